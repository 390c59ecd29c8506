// Percepts of the shared ontology (manual §3.2), ROS-free and header-only:
// the one percept type of the stack (what mrt_msgs/Percept and the DCDT XML
// percept carry), the one attribute builder every producer uses and the one
// reader of a position, given in polar (distance, bearing) or Cartesian
// (x, y) form, every consumer uses. The classes and attributes are declared
// in mrt_common/ontology/mrt.yaml (ontology.h checks objects against it);
// their names are the constants below, not literals in each package.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mrt::common {

/// Class names of the ontology (mrt_common/ontology/mrt.yaml).
namespace percept_class {
inline constexpr const char* kBall = "Ball";
inline constexpr const char* kCar = "Car";
inline constexpr const char* kExhibit = "Exhibit";
inline constexpr const char* kGoal = "Goal";
inline constexpr const char* kGoalPost = "GoalPost";
inline constexpr const char* kLandmark = "Landmark";
inline constexpr const char* kLine = "Line";
inline constexpr const char* kObstacle = "Obstacle";
inline constexpr const char* kOpponent = "Opponent";
inline constexpr const char* kPerson = "Person";
inline constexpr const char* kRobot = "Robot";
inline constexpr const char* kTeammate = "Teammate";
inline constexpr const char* kTree = "Tree";
inline constexpr const char* kWall = "Wall";
}  // namespace percept_class

/// One attribute of a perceived object: (name, value, variability,
/// reliability), with `symbol` set instead of `value` for a label (a colour,
/// a team). Variability is one standard deviation in the attribute's unit
/// (0: exact or unknown); reliability is in [0, 1].
struct Attribute {
  std::string name;
  double value = 0.0;
  std::string symbol;
  double variability = 0.0;
  double reliability = 1.0;
  bool is_symbol() const { return !symbol.empty(); }
};

/// A position in polar form (the percept's frame): distance from its origin
/// (m), bearing counter-clockwise from its x axis (rad), each with its
/// standard deviation (0: unknown).
struct Polar {
  double distance = 0.0, bearing = 0.0;
  double sigma_distance = 0.0, sigma_bearing = 0.0;
  double reliability = 1.0;
};

/// A position in Cartesian form (the percept's frame), with the standard
/// deviations of x and y (0: unknown).
struct Cartesian {
  double x = 0.0, y = 0.0;
  double sigma_x = 0.0, sigma_y = 0.0;
  double reliability = 1.0;
};

/// One object of a percept: a name (may be empty), a class of the
/// ontology and attributes.
struct PerceptObject {
  std::string name;
  std::string membership_class;
  std::vector<Attribute> attributes;

  PerceptObject() = default;
  PerceptObject(std::string n, std::string cls, std::vector<Attribute> attrs = {})
      : name(std::move(n)), membership_class(std::move(cls)), attributes(std::move(attrs)) {}

  /// The attribute named `n` (the first), nullptr if none.
  const Attribute* find(std::string_view n) const {
    for (const Attribute& a : attributes)
      if (a.name == n) return &a;
    return nullptr;
  }
  /// The numeric value of attribute `n`; nullopt when absent or a symbol.
  std::optional<double> number(std::string_view n) const {
    const Attribute* a = find(n);
    if (!a || a->is_symbol()) return std::nullopt;
    return a->value;
  }
  /// The symbol of attribute `n`; "" when absent or numeric.
  std::string symbol(std::string_view n) const {
    const Attribute* a = find(n);
    return a ? a->symbol : std::string();
  }

  /// The builder: sets (replaces or appends) a numeric attribute.
  PerceptObject& set(const std::string& n, double value, double variability = 0.0, double reliability = 1.0) {
    put({n, value, "", variability, reliability});
    return *this;
  }
  /// Sets a symbolic attribute (an empty symbol sets nothing).
  PerceptObject& set_symbol(const std::string& n, const std::string& symbol, double reliability = 1.0) {
    if (!symbol.empty()) put({n, 0.0, symbol, 0.0, reliability});
    return *this;
  }
  /// Sets the position in both forms, as every producer writes it: distance
  /// and bearing with their deviations, and x = d cos b, y = d sin b with
  /// the deviation `sigma_xy` (< 0: hypot(sigma_distance, d sigma_bearing),
  /// the larger axis of the propagated error).
  PerceptObject& set_polar(const Polar& p, double sigma_xy = -1.0) {
    const double s = sigma_xy >= 0.0 ? sigma_xy : std::hypot(p.sigma_distance, p.distance * p.sigma_bearing);
    set("distance", p.distance, p.sigma_distance, p.reliability);
    set("bearing", p.bearing, p.sigma_bearing, p.reliability);
    set("x", p.distance * std::cos(p.bearing), s, p.reliability);
    set("y", p.distance * std::sin(p.bearing), s, p.reliability);
    return *this;
  }
  /// Sets the position in Cartesian form only (x, y with their deviations).
  PerceptObject& set_cartesian(const Cartesian& c) {
    set("x", c.x, c.sigma_x, c.reliability);
    set("y", c.y, c.sigma_y, c.reliability);
    return *this;
  }

 private:
  void put(Attribute a) {
    for (Attribute& b : attributes)
      if (b.name == a.name) {
        b = std::move(a);
        return;
      }
    attributes.push_back(std::move(a));
  }
};

/// What one sensor of one robot perceived at one time.
struct Percept {
  double stamp = 0.0;  // s
  std::string frame;   // the frame positions are given in
  std::string sensor, robot;
  std::vector<PerceptObject> objects;
};

/// The object's position in polar form: from distance and bearing when it
/// has both (numbers), else from x and y (distance = hypot(x, y), bearing =
/// atan2(y, x); deviations propagated to first order, sigma_bearing =
/// sigma / distance with sigma the larger of x's and y's); nullopt when it
/// has neither pair. Reliability: the smaller of the pair's.
inline std::optional<Polar> polar(const PerceptObject& o) {
  const Attribute *d = o.find("distance"), *b = o.find("bearing");
  if (d && b && !d->is_symbol() && !b->is_symbol())
    return Polar{d->value, b->value, d->variability, b->variability, std::min(d->reliability, b->reliability)};
  const Attribute *x = o.find("x"), *y = o.find("y");
  if (!x || !y || x->is_symbol() || y->is_symbol()) return std::nullopt;
  const double r = std::hypot(x->value, y->value), s = std::max(x->variability, y->variability);
  return Polar{r, std::atan2(y->value, x->value), s, r > 0.0 ? s / r : 0.0, std::min(x->reliability, y->reliability)};
}

/// The object's position in Cartesian form: from x and y when it has both,
/// else from distance and bearing (x = d cos b, y = d sin b; sigma of each
/// hypot(sigma_distance, d sigma_bearing)); nullopt when it has neither.
inline std::optional<Cartesian> cartesian(const PerceptObject& o) {
  const Attribute *x = o.find("x"), *y = o.find("y");
  if (x && y && !x->is_symbol() && !y->is_symbol())
    return Cartesian{x->value, y->value, x->variability, y->variability, std::min(x->reliability, y->reliability)};
  const std::optional<Polar> p = polar(o);
  if (!p) return std::nullopt;
  const double s = std::hypot(p->sigma_distance, p->distance * p->sigma_bearing);
  return Cartesian{p->distance * std::cos(p->bearing), p->distance * std::sin(p->bearing), s, s, p->reliability};
}

}  // namespace mrt::common
