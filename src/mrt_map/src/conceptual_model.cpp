#include "mrt_map/conceptual_model.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "mrt_common/angle.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::map {

using mrt::common::YamlReader;

double AttributeMatcher::match(double value, const std::string& symbol) const {
  if (set) return set->membership(value);
  const auto it = symbols.find(symbol);
  return it == symbols.end() ? 0.0 : it->second;
}

ModelTuning ConceptualModel::tuning() const {
  return {tracker_.gate, tracker_.merge_gate, team_.gate, team_.extra_sigma};
}

void ConceptualModel::set_tuning(const ModelTuning& t) {
  const auto require = [](bool ok, const char* key, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("'") + key + "': expected " + what);
  };
  require(std::isfinite(t.gate) && t.gate > 0.0, "tracker.gate", "a finite number > 0");
  require(std::isfinite(t.merge_gate) && t.merge_gate > 0.0, "tracker.merge_gate", "a finite number > 0");
  require(std::isfinite(t.team_gate) && t.team_gate > 0.0, "team.gate", "a finite number > 0");
  require(std::isfinite(t.team_extra_sigma) && t.team_extra_sigma >= 0.0, "team.extra_sigma",
          "a finite number >= 0 (m)");
  tracker_.gate = t.gate;
  tracker_.merge_gate = t.merge_gate;
  team_.gate = t.team_gate;
  team_.extra_sigma = t.team_extra_sigma;
}

int ConceptualModel::find(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? -1 : it->second;
}

bool ConceptualModel::is_a(int a, int b) const {
  if (a < 0 || b < 0) return false;
  for (int c = a; c >= 0; c = at(c).parent)
    if (c == b) return true;
  return false;
}

class ModelLoader {
 public:
  ModelLoader(ConceptualModel& m, const std::string& file) : m_(m), r_(file) {}

  void load(const std::string& text) {
    const YAML::Node root = r_.load(text);
    r_.map(root, "model", {"classes", "classifier", "tracker", "team", "crisp", "world"});
    classes(r_.required(root, "classes", "model"));
    if (root["classifier"]) classifier(root["classifier"]);
    if (root["tracker"]) tracker(root["tracker"]);
    if (root["team"]) team(root["team"]);
    if (root["crisp"]) crisp(root["crisp"]);
    if (root["world"]) world(root["world"]);
  }

  void world(const YAML::Node& n) {
    r_.map(n, "world", {"x_min", "x_max", "y_min", "y_max"});
    WorldBounds& w = m_.world_;
    for (const char* k : {"x_min", "x_max", "y_min", "y_max"})
      if (!n[k]) r_.fail(n, std::string("missing '") + k + "' in 'world'");
    w.x_min = r_.number(n, "x_min", 0.0);
    w.x_max = r_.number(n, "x_max", 0.0);
    w.y_min = r_.number(n, "y_min", 0.0);
    w.y_max = r_.number(n, "y_max", 0.0);
    if (!(w.x_min < w.x_max)) r_.fail(n["x_max"], "expected 'x_max' > 'x_min' in 'world'");
    if (!(w.y_min < w.y_max)) r_.fail(n["y_max"], "expected 'y_max' > 'y_min' in 'world'");
    w.set = true;
  }

 private:
  void classes(const YAML::Node& n) {
    if (!n.IsMap() || n.size() == 0) r_.fail(n, "expected a non-empty map of classes for 'classes'");
    std::vector<YAML::Node> bodies;
    std::vector<YAML::Node> parents;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node k = it->first;
      const std::string name = r_.string(k, "class name");
      if (m_.index_.count(name)) r_.fail(k, "duplicate class '" + name + "'");
      m_.index_[name] = static_cast<int>(m_.classes_.size());
      ClassDef c;
      c.name = name;
      m_.classes_.push_back(c);
      bodies.push_back(it->second);
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const YAML::Node& b = bodies[i];
      const std::string what = m_.classes_[i].name;
      if (b.IsNull()) continue;
      r_.map(b, what, {"parent", "attributes", "motion", "accel_noise", "init_speed_sigma", "default_sigma",
                       "refined_by", "velocity_tau", "drop_after", "max_sigma", "max_count",
                       "imm", "fusion", "maneuver", "keep_teammate_link"});
      if (const YAML::Node p = b["parent"]) {
        const int pi = m_.find(r_.string(p, "parent"));
        if (pi < 0) r_.fail(p, "unknown parent class '" + p.Scalar() + "' of '" + what + "'");
        m_.classes_[i].parent = pi;
      }
    }
    // Depths, rejecting cycles, then inheritance parents first.
    for (std::size_t i = 0; i < m_.classes_.size(); ++i) {
      int d = 0;
      for (int c = m_.classes_[i].parent; c >= 0; c = m_.classes_[static_cast<std::size_t>(c)].parent)
        if (++d > static_cast<int>(m_.classes_.size())) r_.fail(bodies[i]["parent"], "cycle in the class hierarchy at '" + m_.classes_[i].name + "'");
      m_.classes_[i].depth = d;
      if (m_.classes_[i].parent >= 0)
        m_.classes_[static_cast<std::size_t>(m_.classes_[i].parent)].children.push_back(static_cast<int>(i));
    }
    std::vector<std::size_t> order(m_.classes_.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return m_.classes_[a].depth < m_.classes_[b].depth; });
    for (std::size_t i : order) body(m_.classes_[i], bodies[i]);
  }

  void imm(ClassDef& c, const YAML::Node& n) {
    const std::string what = c.name + ".imm";
    r_.map(n, what, {"quiet_accel_noise", "kicked_accel_noise", "p_quiet_to_kicked", "p_kicked_to_quiet"});
    if (c.motion != MotionModel::kConstantVelocity) r_.fail(n, "'imm' needs motion 'constant_velocity' in '" + c.name + "'");
    ImmDef& d = c.imm;
    d.on = true;
    d.quiet_accel_noise = r_.non_negative(n, "quiet_accel_noise", d.quiet_accel_noise);
    d.kicked_accel_noise = r_.non_negative(n, "kicked_accel_noise", d.kicked_accel_noise);
    for (auto [key, v] : {std::make_pair("p_quiet_to_kicked", &d.p_quiet_to_kicked),
                          std::make_pair("p_kicked_to_quiet", &d.p_kicked_to_quiet)}) {
      *v = r_.non_negative(n, key, *v);
      if (*v > 1.0) r_.fail(n[key], std::string("expected a probability in [0, 1] for '") + key + "' in '" + what + "'");
    }
  }

  void body(ClassDef& c, const YAML::Node& b) {
    if (c.parent >= 0) {  // inherit tracking settings
      const ClassDef& p = m_.at(c.parent);
      c.motion = p.motion;
      c.accel_noise = p.accel_noise;
      c.init_speed_sigma = p.init_speed_sigma;
      c.default_sigma = p.default_sigma;
      c.velocity_tau = p.velocity_tau;
      c.drop_after = p.drop_after;
      c.max_sigma = p.max_sigma;
      c.imm = p.imm;
      c.fusion = p.fusion;
      c.impulse_maneuver = p.impulse_maneuver;
      c.keep_link = p.keep_link;
    }
    if (b.IsNull()) return;
    if (const YAML::Node mo = b["motion"]) {
      const std::string s = r_.string(mo, "motion");
      if (s == "static") c.motion = MotionModel::kStatic;
      else if (s == "constant_velocity") c.motion = MotionModel::kConstantVelocity;
      else r_.fail(mo, "expected 'static' or 'constant_velocity' for 'motion', got '" + s + "'");
    }
    c.accel_noise = r_.non_negative(b, "accel_noise", c.accel_noise);
    c.init_speed_sigma = r_.non_negative(b, "init_speed_sigma", c.init_speed_sigma);
    c.default_sigma = r_.positive(b, "default_sigma", c.default_sigma);
    c.velocity_tau = r_.non_negative(b, "velocity_tau", c.velocity_tau);
    c.drop_after = r_.non_negative(b, "drop_after", c.drop_after);
    c.max_sigma = r_.non_negative(b, "max_sigma", c.max_sigma);
    if (const YAML::Node im = b["imm"]) imm(c, im);
    if (const YAML::Node f = b["fusion"]) {
      const std::string s = r_.string(f, "fusion");
      if (s == "team") c.fusion = ClassDef::Fusion::kTeam;
      else if (s == "covariance_intersection") c.fusion = ClassDef::Fusion::kCovarianceIntersection;
      else if (s == "independent") c.fusion = ClassDef::Fusion::kIndependent;
      else r_.fail(f, "expected 'team', 'covariance_intersection' or 'independent' for 'fusion' of '" + c.name + "'");
    }
    if (const YAML::Node mv = b["maneuver"]) {
      const std::string s = r_.string(mv, "maneuver");
      if (s != "reset" && s != "impulse") r_.fail(mv, "expected 'reset' or 'impulse' for 'maneuver' of '" + c.name + "'");
      c.impulse_maneuver = s == "impulse";
    }
    c.keep_link = r_.non_negative(b, "keep_teammate_link", c.keep_link);
    if (const YAML::Node mc = b["max_count"]) {
      const double v = r_.non_negative(b, "max_count", 0.0);
      if (v != std::floor(v) || v > 1000.0) r_.fail(mc, "expected a whole number <= 1000 for 'max_count'");
      c.max_count = static_cast<int>(v);
    }
    if (const YAML::Node rb = b["refined_by"]) {
      if (r_.string(rb, "refined_by") != "teammate_pose") r_.fail(rb, "expected 'teammate_pose' for 'refined_by'");
      c.refined_by_teammate_pose = true;
    }
    if (const YAML::Node a = b["attributes"]) attributes(c, a);
  }

  void attributes(ClassDef& c, const YAML::Node& n) {
    if (!n.IsMap()) r_.fail(n, "expected a map of attributes for '" + c.name + ".attributes'");
    for (auto it = n.begin(); it != n.end(); ++it) {
      AttributeMatcher m;
      m.attribute = r_.string(it->first, "attribute name");
      const YAML::Node v = it->second;
      const std::string what = c.name + "." + m.attribute;
      r_.map(v, what, {"set", "symbols"});
      if (static_cast<bool>(v["set"]) == static_cast<bool>(v["symbols"]))
        r_.fail(v, "expected exactly one of 'set' or 'symbols' in '" + what + "'");
      if (const YAML::Node s = v["set"]) {
        r_.sequence(s, "set");
        if (s.size() < 2) r_.fail(s, "expected [TYPE, parameters...] for 'set' of '" + what + "'");
        const std::string type = r_.string(s[0], "set type");
        std::vector<double> params;
        for (std::size_t i = 1; i < s.size(); ++i) params.push_back(r_.number(s[i], "set parameter"));
        try {
          m.set = mrt::brian::make_fuzzy_set(type, m.attribute, params);
        } catch (const std::invalid_argument& e) {
          r_.fail(s, std::string("bad fuzzy set in '") + what + "': " + e.what());
        }
      } else {
        const YAML::Node sy = v["symbols"];
        if (!sy.IsMap()) r_.fail(sy, "expected a map symbol: degree for 'symbols' of '" + what + "'");
        for (auto jt = sy.begin(); jt != sy.end(); ++jt) {
          const double d = r_.number(jt->second, "degree");
          if (d < 0.0 || d > 1.0) r_.fail(jt->second, "expected a degree in [0, 1] in '" + what + "'");
          m.symbols[r_.string(jt->first, "symbol")] = d;
        }
      }
      c.matchers.push_back(std::move(m));
    }
  }

  void classifier(const YAML::Node& n) {
    r_.map(n, "classifier", {"threshold", "ambiguity_margin"});
    m_.classifier_.threshold = r_.fraction(n, "threshold", m_.classifier_.threshold);
    m_.classifier_.ambiguity_margin = r_.fraction(n, "ambiguity_margin", m_.classifier_.ambiguity_margin);
  }

  void tracker(const YAML::Node& n) {
    TrackerOptions& t = m_.tracker_;
    r_.map(n, "tracker", {"gate", "merge_gate", "confirm_hits", "tentative_timeout", "coast_after", "drop_after",
                          "max_sigma", "reliability_tau", "coalesce_gate",
                          "coalesce_after", "maneuver_radius", "reid_gate", "source_confidence"});
    t.gate = r_.positive(n, "gate", t.gate);
    t.merge_gate = r_.positive(n, "merge_gate", t.merge_gate);
    if (n["confirm_hits"]) t.confirm_hits = static_cast<int>(r_.integer(n["confirm_hits"], "confirm_hits", 1, 1000));
    t.tentative_timeout = r_.positive(n, "tentative_timeout", t.tentative_timeout);
    t.coast_after = r_.positive(n, "coast_after", t.coast_after);
    t.drop_after = r_.positive(n, "drop_after", t.drop_after);
    if (t.drop_after < t.coast_after) r_.fail(n["drop_after"] ? n["drop_after"] : n, "expected 'drop_after' >= 'coast_after'");
    t.max_sigma = r_.positive(n, "max_sigma", t.max_sigma);
    t.reliability_tau = r_.positive(n, "reliability_tau", t.reliability_tau);
    t.coalesce_gate = r_.non_negative(n, "coalesce_gate", t.coalesce_gate);
    t.coalesce_after = r_.non_negative(n, "coalesce_after", t.coalesce_after);
    t.maneuver_radius = r_.non_negative(n, "maneuver_radius", t.maneuver_radius);
    t.reid_gate = r_.non_negative(n, "reid_gate", t.reid_gate);
    t.source_confidence = r_.positive(n, "source_confidence", t.source_confidence);
    if (t.source_confidence > 1.0) r_.fail(n["source_confidence"], "expected a value in (0, 1] for 'source_confidence'");
  }

  void team(const YAML::Node& n) {
    r_.map(n, "team", {"max_latency", "gate", "fusion", "extra_sigma", "send_threshold"});
    m_.team_.send_threshold = r_.non_negative(n, "send_threshold", m_.team_.send_threshold);
    m_.team_.extra_sigma = r_.non_negative(n, "extra_sigma", m_.team_.extra_sigma);
    m_.team_.max_latency = r_.positive(n, "max_latency", m_.team_.max_latency);
    m_.team_.gate = r_.positive(n, "gate", m_.team_.gate);
    if (const YAML::Node f = n["fusion"]) {
      const std::string s = r_.string(f, "fusion");
      if (s != "covariance_intersection" && s != "independent")
        r_.fail(f, "expected 'covariance_intersection' or 'independent' for 'fusion'");
      m_.team_.covariance_intersection = s == "covariance_intersection";
    }
  }

  void crisp(const YAML::Node& n) {
    r_.sequence(n, "crisp");
    for (const YAML::Node& e : n) {
      r_.map(e, "crisp", {"name", "class", "quantity", "select", "parameter", "scale", "missing", "min_reliability"});
      CrispEntry c;
      c.name = r_.string(e, "name", "", true, "crisp");
      c.scale = r_.number(e, "scale", 1.0);
      c.missing = r_.number(e, "missing", 0.0);
      c.min_reliability = r_.fraction(e, "min_reliability", 0.0);
      if (e["parameter"]) {
        if (e["class"] || e["quantity"] || e["select"]) r_.fail(e, "expected either 'parameter' or 'class' in crisp '" + c.name + "'");
        c.parameter = r_.string(e["parameter"], "parameter");
        c.quantity = CrispEntry::Quantity::kParameter;
      } else {
        const YAML::Node cl = r_.required(e, "class", "crisp " + c.name);
        c.class_index = m_.find(r_.string(cl, "class"));
        if (c.class_index < 0) r_.fail(cl, "unknown class '" + cl.Scalar() + "' in crisp '" + c.name + "'");
        quantity(c, e);
      }
      m_.crisp_.push_back(c);
    }
  }

  void quantity(CrispEntry& c, const YAML::Node& e) {
    using Q = CrispEntry::Quantity;
    static const std::map<std::string, Q> quantities = {{"distance", Q::kDistance}, {"bearing", Q::kBearing},
                                                        {"x", Q::kX}, {"y", Q::kY}, {"vx", Q::kVx},
                                                        {"vy", Q::kVy}, {"speed", Q::kSpeed}};
    const YAML::Node q = r_.required(e, "quantity", "crisp " + c.name);
    const auto it = quantities.find(r_.string(q, "quantity"));
    if (it == quantities.end())
      r_.fail(q, "expected one of distance, bearing, x, y, vx, vy, speed for 'quantity', got '" + q.Scalar() + "'");
    c.quantity = it->second;
    if (const YAML::Node s = e["select"]) {
      const std::string v = r_.string(s, "select");
      if (v == "nearest") c.select = CrispEntry::Select::kNearest;
      else if (v == "most_reliable") c.select = CrispEntry::Select::kMostReliable;
      else if (v == "best_supported") c.select = CrispEntry::Select::kBestSupported;
      else r_.fail(s, "expected 'nearest', 'most_reliable' or 'best_supported' for 'select', got '" + v + "'");
    }
  }

  ConceptualModel& m_;
  YamlReader r_;
};

ConceptualModel ConceptualModel::parse(const std::string& text, const std::string& file) {
  ConceptualModel m;
  ModelLoader(m, file).load(text);
  return m;
}

ConceptualModel ConceptualModel::load(const std::string& path) {
  return parse(mrt::common::read_file(path, "cannot open model file", 1u << 20), path);
}

}  // namespace mrt::map
