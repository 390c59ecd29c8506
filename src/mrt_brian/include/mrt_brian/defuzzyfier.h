// Defuzzyfier (manual §10.3.9, §10.4.6): composed actions -> commands,
// through the output shapes (s_shape.txt) associated with each action
// (s_ftoc.txt). Singleton: sum(s * mu) / sum(mu); barycenter: centre of area
// of the polygon sets clipped at their membership. Actions whose output
// shape is declared `(CIRCULAR lo hi)` use a circular mean over [lo, hi)
// (both methods); in the legacy profile an action whose name contains
// "Angle" is a 2009 angle (degrees, constant 0.01745).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_brian/composer.h"
#include "mrt_brian/config_ast.h"
#include "mrt_brian/shape.h"
#include "mrt_brian/symbol_table.h"
#include "mrt_brian/types.h"

namespace mrt::brian {

enum class DefuzzMethod { kSingleton, kBarycenter };

class Defuzzyfier {
 public:
  Defuzzyfier() = default;
  /// Throws mrt::common::ParseError on an association to an unknown shape,
  /// and in barycenter mode on a set without area (SNG, TOL, TOR).
  Defuzzyfier(const std::vector<ShapeDef>& shapes, const std::vector<AssociationDef>& assocs,
              DefuzzMethod method = DefuzzMethod::kSingleton, Profile profile = Profile::kManual,
              const std::string& shapes_file = "s_shape", const std::string& assoc_file = "s_ftoc");

  int action_id(const std::string& name) const { return actions_.find(name); }
  const std::string& action_name(int id) const { return actions_.name(id); }
  int action_count() const { return actions_.size(); }
  /// Label id of `label` in the action's output shape, or -1.
  int label_id(int action, const std::string& label) const { return shape(action).find(label); }
  const std::string& label_name(int action, int label) const { return shape(action).set(label).label(); }
  int label_count(int action) const { return shape(action).size(); }
  std::vector<int> labels_per_action() const;
  const Shape& shape(int action) const { return shapes_[static_cast<std::size_t>(shape_of_[static_cast<std::size_t>(action)])]; }
  /// How an action's value wraps around.
  enum class Wrap : std::uint8_t { kLinear, kCircular, kLegacyAngle };
  Wrap wrap(int action) const { return wrap_[static_cast<std::size_t>(action)]; }
  bool is_angle(int action) const { return wrap(action) != Wrap::kLinear; }

  /// One value per action; has[a] == 0 when no command (sum of weights 0).
  void defuzzify(const ComposedActions& in, std::vector<double>& value, std::vector<std::uint8_t>& has) const;

  /// Convenience for module-level use: <action, label, mu> -> commands.
  struct Action {
    std::string name, label;
    double value;
  };
  CommandList defuzzify(const std::vector<Action>& actions) const;

 private:
  double singleton_point(int action, int label) const;
  bool barycenter(int action, const ComposedActions& in, double* out) const;
  bool singleton_linear(int action, const ComposedActions& in, double* out) const;
  bool singleton_circular(int action, const ComposedActions& in, double* out) const;
  bool singleton_legacy_angle(int action, const ComposedActions& in, double* out) const;
  /// [lo, lo + period) of a circular action, and the angle of x in it.
  /// (A legacy angle: [0, 360).)
  double range_lo(int action) const { return wrap(action) == Wrap::kCircular ? shape(action).range_lo() : 0.0; }
  double period(int action) const {
    return wrap(action) == Wrap::kCircular ? shape(action).range_hi() - shape(action).range_lo() : 360.0;
  }
  /// A circular mean (sum mu cos, sum mu sin) back to [lo, hi); false when
  /// the vectors cancel out (|sum| <= 1e-12 sum mu).
  bool from_circle(int action, double c, double s, double w, double* out) const;
  std::vector<Shape> shapes_;
  // [shape][label]: the outlines barycenter defuzzification clips, built
  // once (FuzzySet::polygons() allocates).
  std::vector<std::vector<std::vector<Polygon>>> polygons_;
  SymbolTable actions_;
  std::vector<int> shape_of_;
  std::vector<Wrap> wrap_;
  // Singleton points by action, flat (points_[point_first_[a] + label]).
  std::vector<double> points_;
  std::vector<int> point_first_;
  DefuzzMethod method_ = DefuzzMethod::kSingleton;
  Profile profile_ = Profile::kManual;
};

}  // namespace mrt::brian
