#include "ros/team_conversions.h"

#include "ros/conversions.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mrt::dcdt::node {

namespace {

const char* const kCov4[4] = {"0", "1", "2", "3"};
const char* const kCov2[4] = {"cov_xx", "cov_xy", "cov_yx", "cov_yy"};

XmlAttribute num(const std::string& name, double v, double reliability = 1.0) {
  return {name, v, "", 0.0, reliability};
}
XmlAttribute sym(const std::string& name, const std::string& s) { return {name, 0.0, s, 0.0, 1.0}; }

// Reads the attributes of one object: every numeric attribute asked for must
// be there exactly once; symbols are optional; anything left over is an error
// (a typo in a legacy producer must not pass as a default).
class Attributes {
 public:
  explicit Attributes(const XmlObject& o) : o_(o), used_(o.attributes.size(), false) {}

  double number(const std::string& name) {
    const XmlAttribute* a = find(name);
    if (!a) fail("has no numeric attribute '" + name + "'");
    if (!a->symbol.empty()) fail("attribute '" + name + "' must be numeric");
    return a->value;
  }
  double reliability(const std::string& name) { return find_used(name)->reliability; }
  uint32_t uint(const std::string& name) {
    const double v = number(name);
    if (!(v >= 0.0 && v <= static_cast<double>(UINT32_MAX) && v == std::floor(v)))
      fail("attribute '" + name + "' must be an integer in [0, 4294967295]");
    return static_cast<uint32_t>(v);
  }
  bool flag(const std::string& name) {
    const double v = number(name);
    if (v != 0.0 && v != 1.0) fail("attribute '" + name + "' must be 0 or 1");
    return v == 1.0;
  }
  /// Optional number (`fallback` when absent).
  double number_or(const std::string& name, double fallback) {
    const XmlAttribute* a = find(name);  // marks it used
    if (!a) return fallback;
    if (!a->symbol.empty()) fail("attribute '" + name + "' must be numeric");
    return a->value;
  }
  /// Optional symbol ("" when absent).
  std::string symbol(const std::string& name) {
    const XmlAttribute* a = find(name);
    if (!a) return "";
    if (a->symbol.empty()) fail("attribute '" + name + "' must be a symbol");
    return a->symbol;
  }
  /// Every symbol of that name, in order.
  std::vector<std::string> symbols(const std::string& name) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < o_.attributes.size(); ++i) {
      if (o_.attributes[i].name != name) continue;
      if (o_.attributes[i].symbol.empty()) fail("attribute '" + name + "' must be a symbol");
      used_[i] = true;
      out.push_back(o_.attributes[i].symbol);
    }
    return out;
  }
  void finish() const {
    for (std::size_t i = 0; i < used_.size(); ++i)
      if (!used_[i]) fail("has an unknown or repeated attribute '" + o_.attributes[i].name + "'");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw XmlError(0, o_.membership_class + " object '" + o_.name + "' " + what);
  }

 private:
  const XmlAttribute* find(const std::string& name) {
    for (std::size_t i = 0; i < o_.attributes.size(); ++i)
      if (!used_[i] && o_.attributes[i].name == name) {
        used_[i] = true;
        return &o_.attributes[i];
      }
    return nullptr;
  }
  const XmlAttribute* find_used(const std::string& name) {
    for (std::size_t i = 0; i < o_.attributes.size(); ++i)
      if (used_[i] && o_.attributes[i].name == name) return &o_.attributes[i];
    fail("has no attribute '" + name + "'");
  }
  const XmlObject& o_;
  std::vector<bool> used_;
};

uint32_t parse_id(const XmlObject& o) {
  const std::string& s = o.name;
  if (s.empty() || s.size() > 10 || s.find_first_not_of("0123456789") != std::string::npos ||
      std::stoull(s) > UINT32_MAX)
    throw XmlError(0, "Anchor object '" + s + "': the name must be the anchor id, an integer in [0, 4294967295]");
  return static_cast<uint32_t>(std::stoull(s));
}

std::string cov_name(int r, int c) { return std::string("cov_") + kCov4[r] + kCov4[c]; }

XmlObject anchor_object(const mrt_msgs::Anchor& a) {
  XmlObject o{std::to_string(a.id), "Anchor", {}};
  if (!a.membership_class.empty()) o.attributes.push_back(sym("class", a.membership_class));
  o.attributes.push_back(num("matching_degree", a.matching_degree));
  o.attributes.push_back(num("status", a.status));
  o.attributes.push_back(num("x", a.x));
  o.attributes.push_back(num("y", a.y));
  o.attributes.push_back(num("vx", a.vx));
  o.attributes.push_back(num("vy", a.vy));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) o.attributes.push_back(num(cov_name(r, c), a.covariance[static_cast<std::size_t>(4 * r + c)]));
  o.attributes.push_back(num("reliability", a.reliability));
  o.attributes.push_back(num("last_seen_sec", a.last_seen.sec));
  o.attributes.push_back(num("last_seen_nsec", a.last_seen.nsec));
  for (const auto& s : a.sources) {
    if (s.empty()) throw XmlError(0, "anchor " + std::to_string(a.id) + ": an empty source cannot be carried");
    o.attributes.push_back(sym("source", s));
  }
  return o;
}

mrt_msgs::Anchor anchor_from(const XmlObject& o) {
  mrt_msgs::Anchor a;
  a.id = parse_id(o);
  Attributes at(o);
  a.membership_class = at.symbol("class");
  a.matching_degree = at.number("matching_degree");
  const uint32_t status = at.uint("status");
  if (status > mrt_msgs::Anchor::COASTING) at.fail("attribute 'status' must be 0, 1 or 2");
  a.status = static_cast<uint8_t>(status);
  a.x = at.number("x");
  a.y = at.number("y");
  a.vx = at.number("vx");
  a.vy = at.number("vy");
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a.covariance[static_cast<std::size_t>(4 * r + c)] = at.number(cov_name(r, c));
  a.reliability = at.number("reliability");
  a.last_seen.sec = at.uint("last_seen_sec");
  a.last_seen.nsec = at.uint("last_seen_nsec");
  if (a.last_seen.nsec >= 1000000000u) at.fail("attribute 'last_seen_nsec' must be < 1000000000");
  a.sources = at.symbols("source");
  at.finish();
  return a;
}

}  // namespace

XmlMessage from_world_model(const mrt_msgs::WorldModel& w) {
  XmlMessage x;
  stamp_to(w.header, &x);
  x.sensor = "map";
  x.robot = w.robot;
  XmlObject self{w.robot, "WorldModel", {}};
  self.attributes.push_back(num("local_only", w.local_only ? 1.0 : 0.0));
  self.attributes.push_back(num("x", w.robot_x));
  self.attributes.push_back(num("y", w.robot_y));
  self.attributes.push_back(num("theta", w.robot_theta));
  for (int i = 0; i < 4; ++i) self.attributes.push_back(num(kCov2[i], w.robot_covariance[static_cast<std::size_t>(i)]));
  x.objects.push_back(std::move(self));
  for (const auto& a : w.anchors) x.objects.push_back(anchor_object(a));
  for (const auto& p : w.parameters) x.objects.push_back({p.name, "CrispData", {num("value", p.value, p.reliability)}});
  return x;
}

mrt_msgs::WorldModel to_world_model(const XmlMessage& x) {
  mrt_msgs::WorldModel w;
  stamp_from(x, &w.header);
  w.robot = x.robot;
  bool have_self = false;
  for (const auto& o : x.objects) {
    if (o.membership_class == "WorldModel") {
      if (have_self) throw XmlError(0, "more than one WorldModel object");
      have_self = true;
      Attributes at(o);
      w.local_only = at.flag("local_only");
      w.robot_x = at.number("x");
      w.robot_y = at.number("y");
      w.robot_theta = at.number("theta");
      for (int i = 0; i < 4; ++i) w.robot_covariance[static_cast<std::size_t>(i)] = at.number(kCov2[i]);
      at.finish();
      if (o.name != x.robot) at.fail("must be named after the message's robot '" + x.robot + "'");
    } else if (o.membership_class == "Anchor") {
      w.anchors.push_back(anchor_from(o));
    } else if (o.membership_class == "CrispData") {
      Attributes at(o);
      mrt_msgs::CrispData d;
      d.name = o.name;
      d.value = at.number("value");
      d.reliability = at.reliability("value");
      at.finish();
      w.parameters.push_back(d);
    } else {
      throw XmlError(0, "object '" + o.name + "' of class '" + o.membership_class +
                            "' in a world model (expected WorldModel, Anchor or CrispData)");
    }
  }
  if (!have_self) throw XmlError(0, "a world model needs one WorldModel object (the producer)");
  return w;
}

XmlMessage from_coordination(const mrt_msgs::CoordinationParameters& c) {
  if (c.attitude.size() != c.slots.size() || c.time.size() != c.slots.size() ||
      c.opportunity.size() != c.activities.size() || c.heard_stamps.size() != c.heard_ids.size())
    throw XmlError(0, "coordination message of " + c.robot_id + ": per-slot, per-activity or heard vectors of different lengths");
  XmlMessage x;
  stamp_to(c.header, &x);
  x.sensor = "scare";
  x.robot = c.robot_id;
  XmlObject self{c.robot_id, "Coordination", {}};
  self.attributes.push_back(num("seq", c.seq));
  self.attributes.push_back(num("leaving", c.leaving ? 1.0 : 0.0));
  self.attributes.push_back(num("x", c.x));
  self.attributes.push_back(num("y", c.y));
  if (!c.intention.empty()) self.attributes.push_back(sym("intention", c.intention));
  if (c.intention_since != 0.0) self.attributes.push_back(num("intention_since", c.intention_since));
  x.objects.push_back(std::move(self));
  for (std::size_t i = 0; i < c.slots.size(); ++i)
    x.objects.push_back({c.slots[i], "Slot", {num("attitude", c.attitude[i]), num("time", c.time[i])}});
  for (std::size_t i = 0; i < c.activities.size(); ++i)
    x.objects.push_back({c.activities[i], "Activity", {num("opportunity", c.opportunity[i])}});
  for (std::size_t i = 0; i < c.heard_ids.size(); ++i)
    x.objects.push_back({c.heard_ids[i], "Heard", {num("stamp", c.heard_stamps[i])}});
  return x;
}

mrt_msgs::CoordinationParameters to_coordination(const XmlMessage& x) {
  mrt_msgs::CoordinationParameters c;
  stamp_from(x, &c.header);
  c.robot_id = x.robot;
  bool have_self = false;
  for (const auto& o : x.objects) {
    Attributes at(o);
    if (o.membership_class == "Coordination") {
      if (have_self) throw XmlError(0, "more than one Coordination object");
      if (o.name != x.robot) at.fail("must be named after the message's robot '" + x.robot + "'");
      have_self = true;
      c.seq = at.uint("seq");
      c.leaving = at.flag("leaving");
      c.x = at.number("x");
      c.y = at.number("y");
      c.intention = at.symbol("intention");
      c.intention_since = at.number_or("intention_since", 0.0);  // 0: unknown (legacy senders)
    } else if (o.membership_class == "Slot") {
      c.slots.push_back(o.name);
      c.attitude.push_back(at.number("attitude"));
      c.time.push_back(at.number("time"));
    } else if (o.membership_class == "Activity") {
      c.activities.push_back(o.name);
      c.opportunity.push_back(at.number("opportunity"));
    } else if (o.membership_class == "Heard") {
      c.heard_ids.push_back(o.name);
      c.heard_stamps.push_back(at.number("stamp"));
    } else {
      throw XmlError(0, "object '" + o.name + "' of class '" + o.membership_class +
                            "' in a coordination message (expected Coordination, Slot, Activity or Heard)");
    }
    at.finish();
  }
  if (!have_self) throw XmlError(0, "a coordination message needs one Coordination object (the sender)");
  return c;
}

XmlMessage from_referee(const mrt_msgs::RefereeCommand& r) {
  if (r.name.empty()) throw XmlError(0, "referee command " + std::to_string(r.command) + ": an empty name cannot be carried");
  if (r.teams.size() != r.score.size())
    throw XmlError(0, "referee command " + r.name + ": teams and score of different lengths");
  XmlMessage x;
  stamp_to(r.header, &x);
  x.sensor = "refbox";
  x.robot = "referee";
  XmlObject self{r.name, "RefereeCommand", {num("command", r.command)}};
  if (!r.team.empty()) self.attributes.push_back(sym("team", r.team));
  self.attributes.push_back(num("x", r.x));
  self.attributes.push_back(num("y", r.y));
  if (!r.reason.empty()) self.attributes.push_back(sym("reason", r.reason));
  x.objects.push_back(std::move(self));
  for (std::size_t i = 0; i < r.teams.size(); ++i) {
    if (r.teams[i].empty()) throw XmlError(0, "referee command " + r.name + ": an empty team name cannot be carried");
    x.objects.push_back({r.teams[i], "Score", {num("goals", r.score[i])}});
  }
  return x;
}

mrt_msgs::RefereeCommand to_referee(const XmlMessage& x) {
  mrt_msgs::RefereeCommand r;
  stamp_from(x, &r.header);
  bool have_command = false;
  for (const auto& o : x.objects) {
    Attributes at(o);
    if (o.membership_class == "RefereeCommand") {
      if (have_command) throw XmlError(0, "more than one RefereeCommand object");
      have_command = true;
      const uint32_t c = at.uint("command");
      if (c > 255) at.fail("attribute 'command' must be in [0, 255]");
      if (o.name.empty()) at.fail("must be named after the command");
      r.command = static_cast<uint8_t>(c);
      r.name = o.name;
      r.team = at.symbol("team");
      r.x = at.number("x");
      r.y = at.number("y");
      r.reason = at.symbol("reason");
    } else if (o.membership_class == "Score") {
      r.teams.push_back(o.name);
      r.score.push_back(at.uint("goals"));
    } else {
      throw XmlError(0, "object '" + o.name + "' of class '" + o.membership_class +
                            "' in a referee message (expected RefereeCommand or Score)");
    }
    at.finish();
  }
  if (!have_command) throw XmlError(0, "a referee message needs one RefereeCommand object");
  return r;
}

}  // namespace mrt::dcdt::node
