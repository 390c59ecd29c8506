// The aggregator's core: see include/mrt_common_ros/diagnostic_aggregator.h.
#include "mrt_common_ros/diagnostic_aggregator.h"

#include <algorithm>
#include <set>

#include "mrt_common/yaml_reader.h"

namespace mrt::ros_common {

namespace {

using mrt::common::YamlReader;

constexpr const char* kGeneric = "diagnostic_aggregator/GenericAnalyzer";

/// "a/b/" -> "a/b" (no leading or trailing '/').
std::string trim_slashes(const std::string& s) {
  const auto b = s.find_first_not_of('/');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of('/') - b + 1);
}

/// A string or a list of strings.
std::vector<std::string> strings(const YamlReader& r, const YAML::Node& m, const char* key, const std::string& what) {
  const YAML::Node n = m[key];
  std::vector<std::string> out;
  if (!n) return out;
  const std::string expected = "expected a string or a list of strings for '" + what + "/" + key + "'";
  if (n.IsScalar()) {
    out.push_back(n.Scalar());
  } else if (n.IsSequence()) {
    for (const YAML::Node& e : n) {
      if (!e.IsScalar()) r.fail(e, expected);
      out.push_back(e.Scalar());
    }
  } else {
    r.fail(n, expected);
  }
  for (const auto& s : out)
    if (s.empty()) r.fail(n, "expected non-empty strings in '" + what + "/" + key + "'");
  return out;
}

AnalyzerSpec analyzer(const YamlReader& r, const std::string& key, const YAML::Node& n, const std::string& base) {
  const std::string what = "analyzers/" + key;
  r.map(n, what, {"type", "path", "startswith", "contains", "name", "expected", "remove_prefix", "timeout"});
  const YAML::Node type = r.required(n, "type", what);
  if (r.string(type, what + "/type") != kGeneric)
    r.fail(type, "unknown analyzer type '" + type.Scalar() + "' in '" + what + "/type' (expected " + kGeneric +
                     ", the only type this aggregator implements)");
  AnalyzerSpec a;
  a.key = key;
  const YAML::Node path = r.required(n, "path", what);
  const std::string p = trim_slashes(r.string(path, what + "/path"));
  if (p.empty()) r.fail(path, "expected a non-empty name for '" + what + "/path'");
  a.path = base + "/" + p;
  a.startswith = strings(r, n, "startswith", what);
  a.contains = strings(r, n, "contains", what);
  a.name = strings(r, n, "name", what);
  a.expected = strings(r, n, "expected", what);
  a.remove_prefix = strings(r, n, "remove_prefix", what);
  if (a.startswith.empty() && a.contains.empty() && a.name.empty() && a.expected.empty())
    r.fail(n, "expected at least one of startswith, contains, name, expected in '" + what + "'");
  if (n["timeout"]) a.timeout = r.number(n["timeout"], what + "/timeout");
  return a;
}

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

}  // namespace

AggregatorConfig parse_aggregator_config(const std::string& text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(text);
  r.map(root, "(top level)", {"analyzers", "pub_rate", "base_path"});
  AggregatorConfig c;
  c.pub_rate = r.bounded(root, "pub_rate", c.pub_rate, 0.0, true, 100.0);
  if (root["base_path"]) {
    const std::string b = trim_slashes(r.string(root["base_path"], "base_path"));
    c.base_path = b.empty() ? "" : "/" + b;
  }
  const YAML::Node list = r.required(root, "analyzers", "(top level)");
  if (!list.IsMap() || list.size() == 0) r.fail(list, "expected a non-empty map of analyzers for 'analyzers'");
  std::set<std::string> keys, paths;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const YAML::Node k = it->first;
    const std::string key = r.string(k, "analyzers");
    if (!keys.insert(key).second) r.fail(k, "duplicate key '" + key + "' in 'analyzers'");
    AnalyzerSpec a = analyzer(r, key, it->second, c.base_path);
    if (!paths.insert(a.path).second || a.path == c.base_path + "/Other")
      r.fail(it->second, "expected a path of its own for 'analyzers/" + key + "/path' (" + a.path +
                             " is taken; /Other holds the unmatched statuses)");
    c.analyzers.push_back(std::move(a));
  }
  return c;
}

AggregatorConfig load_aggregator_config(const std::string& file) {
  return parse_aggregator_config(mrt::common::read_file(file, "cannot open the aggregator configuration", 1u << 20),
                                 file);
}

bool analyzer_matches(const AnalyzerSpec& a, const std::string& name) {
  const auto eq = [&](const std::string& s) { return s == name; };
  return std::any_of(a.name.begin(), a.name.end(), eq) || std::any_of(a.expected.begin(), a.expected.end(), eq) ||
         std::any_of(a.startswith.begin(), a.startswith.end(), [&](const std::string& s) { return starts_with(name, s); }) ||
         std::any_of(a.contains.begin(), a.contains.end(),
                     [&](const std::string& s) { return name.find(s) != std::string::npos; });
}

std::string item_name(const AnalyzerSpec& a, const std::string& name) {
  std::string s = name;
  for (const auto& p : a.remove_prefix)
    if (starts_with(s, p)) {
      s = s.substr(p.size());
      break;
    }
  s.erase(0, std::min(s.size(), s.find_first_not_of(" :/")));
  std::replace(s.begin(), s.end(), '/', ' ');
  return s.empty() ? name : s;
}

const char* level_word(std::uint8_t level) {
  switch (level) {
    case kAggOk: return "OK";
    case kAggWarn: return "Warning";
    case kAggError: return "Error";
    default: return "Stale";
  }
}

Aggregator::Aggregator(AggregatorConfig config, double other_timeout)
    : config_(std::move(config)), other_timeout_(other_timeout), items_(config_.analyzers.size()) {}

void Aggregator::add(const AggStatus& s, double now) {
  bool matched = false;
  for (std::size_t i = 0; i < config_.analyzers.size(); ++i) {
    if (!analyzer_matches(config_.analyzers[i], s.name)) continue;
    items_[i][s.name] = Item{s, now};
    matched = true;
  }
  if (!matched) other_[s.name] = Item{s, now};
}

AggStatus Aggregator::parent(const std::string& path, const std::vector<AggStatus>& items) const {
  AggStatus p;
  p.name = path;
  if (items.empty()) {
    p.level = kAggStale;
    p.message = "no item yet";
    return p;
  }
  for (const auto& it : items) p.level = std::max(p.level, std::min(it.level, kAggStale));
  std::string worst;
  for (const auto& it : items) {
    p.values.emplace_back(it.name.substr(path.size() + 1), std::string(level_word(it.level)) + ": " + it.message);
    if (p.level != kAggOk && std::min(it.level, kAggStale) == p.level)
      worst += (worst.empty() ? "" : ", ") + it.name.substr(path.size() + 1);
  }
  p.message = p.level == kAggOk ? "OK" : std::string(level_word(p.level)) + ": " + worst;
  return p;
}

AggOutput Aggregator::aggregate(double now) {
  AggOutput out;
  std::string worst;  // the parents at the top level
  const auto emit = [&](const std::string& path, std::vector<AggStatus> items) {
    std::sort(items.begin(), items.end(), [](const AggStatus& a, const AggStatus& b) { return a.name < b.name; });
    out.statuses.push_back(parent(path, items));
    const AggStatus& p = out.statuses.back();
    if (p.level > out.toplevel.level) worst.clear();
    out.toplevel.level = std::max(out.toplevel.level, p.level);
    if (p.level == out.toplevel.level && p.level != kAggOk) worst += (worst.empty() ? "" : ", ") + p.name;
    out.statuses.insert(out.statuses.end(), items.begin(), items.end());
  };
  for (std::size_t i = 0; i < config_.analyzers.size(); ++i) {
    const AnalyzerSpec& a = config_.analyzers[i];
    std::vector<AggStatus> items;
    for (const auto& [name, it] : items_[i]) {
      AggStatus s = it.status;
      s.name = a.path + "/" + item_name(a, name);
      if (a.timeout > 0 && now - it.time > a.timeout) {
        s.level = kAggStale;
        s.message = "stale (" + std::to_string(static_cast<long>(now - it.time)) + " s silent): " + s.message;
      }
      items.push_back(std::move(s));
    }
    for (const auto& e : a.expected)
      if (!items_[i].count(e)) {
        AggStatus s;
        s.name = a.path + "/" + item_name(a, e);
        s.level = kAggStale;
        s.message = "expected, never received";
        items.push_back(std::move(s));
      }
    emit(a.path, std::move(items));
  }
  for (auto it = other_.begin(); it != other_.end();)
    it = now - it->second.time > other_timeout_ ? other_.erase(it) : std::next(it);
  if (!other_.empty()) {
    AnalyzerSpec other;
    other.path = config_.base_path + "/Other";
    std::vector<AggStatus> items;
    for (const auto& [name, it] : other_) {
      items.push_back(it.status);
      items.back().name = other.path + "/" + item_name(other, name);
    }
    emit(other.path, std::move(items));
  }
  out.toplevel.name = config_.base_path.empty() ? "toplevel_state" : config_.base_path;
  out.toplevel.message = worst.empty() ? "OK" : std::string(level_word(out.toplevel.level)) + ": " + worst;
  return out;
}

}  // namespace mrt::ros_common
