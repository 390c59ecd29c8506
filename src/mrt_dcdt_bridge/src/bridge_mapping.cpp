#include "mrt_dcdt_bridge/bridge_mapping.h"

#include <set>

#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::dcdt {

using mrt::common::ParseError;
using mrt::common::YamlReader;

const char* kind_name(PayloadKind k) {
  switch (k) {
    case PayloadKind::PERCEPT: return "percept";
    case PayloadKind::CRISP_DATA: return "crisp_data";
    case PayloadKind::COMMANDS: return "commands";
    case PayloadKind::WORLD_MODEL: return "world_model";
    case PayloadKind::COORDINATION: return "coordination";
    case PayloadKind::REFEREE: return "referee";
    case PayloadKind::RAW: return "raw";
  }
  return "?";
}

namespace {

std::string scalar(const YamlReader& r, const YAML::Node& entry, const char* key, bool required,
                   const std::string& def = "") {
  const YAML::Node v = entry[key];
  if (!v) {
    if (required) r.fail(entry, std::string("missing '") + key + "'");
    return def;
  }
  if (!v.IsScalar()) r.fail(v, std::string("'") + key + "' must be a scalar");
  return v.as<std::string>();
}

std::vector<TopicMapping> parse_list(const YamlReader& r, const YAML::Node& list, bool to_ros) {
  std::vector<TopicMapping> out;
  if (!list) return out;
  if (!list.IsSequence()) r.fail(list, std::string(to_ros ? "to_ros" : "to_dcdt") + " must be a list");
  std::set<std::string> topics;
  std::set<int> types;
  for (const auto& e : list) {
    if (!e.IsMap()) r.fail(e, "expected a mapping with type, topic and kind");
    for (const auto& kv : e) {
      const std::string k = kv.first.as<std::string>();
      if (k != "type" && k != "topic" && k != "kind" && k != (to_ros ? "scope" : "warranty"))
        r.fail(kv.first, "unknown key '" + k + "'");
    }
    TopicMapping m;
    m.line = e.Mark().line + 1;
    const std::string type = scalar(r, e, "type", true);
    m.type = msg_type_from_name(type.c_str());
    if (m.type < 0) r.fail(e["type"], "unknown DCDT message type '" + type + "'");
    m.topic = scalar(r, e, "topic", true);
    if (m.topic.empty()) r.fail(e["topic"], "empty topic");
    const std::string kind = scalar(r, e, "kind", false, "percept");
    if (kind == "percept") m.kind = PayloadKind::PERCEPT;
    else if (kind == "crisp_data") m.kind = PayloadKind::CRISP_DATA;
    else if (kind == "commands") m.kind = PayloadKind::COMMANDS;
    else if (kind == "world_model") m.kind = PayloadKind::WORLD_MODEL;
    else if (kind == "coordination") m.kind = PayloadKind::COORDINATION;
    else if (kind == "referee") m.kind = PayloadKind::REFEREE;
    else if (kind == "raw") m.kind = PayloadKind::RAW;
    else
      r.fail(e["kind"], "kind must be percept, crisp_data, commands, world_model, coordination, referee or raw, got '" + kind + "'");
    if (to_ros) {
      const std::string s = scalar(r, e, "scope", false, "all");
      if (s == "local") m.scope = DCDT_LOCAL_MSG;
      else if (s == "remote") m.scope = DCDT_REMOTE_MSG;
      else if (s == "all") m.scope = DCDT_ALL_MSG;
      else r.fail(e["scope"], "scope must be local, remote or all, got '" + s + "'");
      if (!types.insert(m.type).second) r.fail(e["type"], "type " + type + " mapped twice in to_ros");
    } else {
      const std::string w = scalar(r, e, "warranty", false, "guaranteed");
      if (w == "none") m.warranty = DCDT_DW_NONE;
      else if (w == "retransmit") m.warranty = DCDT_DW_RETRANSMIT;
      else if (w == "guaranteed") m.warranty = DCDT_DW_GUARANTEED;
      else r.fail(e["warranty"], "warranty must be none, retransmit or guaranteed, got '" + w + "'");
      if (!topics.insert(m.topic).second) r.fail(e["topic"], "topic " + m.topic + " mapped twice in to_dcdt");
    }
    out.push_back(m);
  }
  return out;
}

}  // namespace

BridgeMapping parse_bridge_mapping(const std::string& text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(text);
  if (!root.IsMap()) throw ParseError(file, 1, 0, "expected a mapping with 'to_ros' and/or 'to_dcdt'");
  for (const auto& kv : root) {
    const std::string k = kv.first.as<std::string>();
    if (k != "to_ros" && k != "to_dcdt") r.fail(kv.first, "unknown key '" + k + "' (expected to_ros, to_dcdt)");
  }
  BridgeMapping m;
  try {
    m.to_ros = parse_list(r, root["to_ros"], true);
    m.to_dcdt = parse_list(r, root["to_dcdt"], false);
  } catch (const YAML::Exception& e) {
    throw r.error(e);
  }
  if (m.to_ros.empty() && m.to_dcdt.empty()) throw ParseError(file, 1, 0, "nothing mapped");
  return m;
}

BridgeMapping load_bridge_mapping(const std::string& path) {
  return parse_bridge_mapping(mrt::common::read_file(path, "cannot read the mapping file"), path);
}

}  // namespace mrt::dcdt
