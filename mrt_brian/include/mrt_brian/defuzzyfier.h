// Defuzzyfier (manual §10.3.9, §10.4.6): composed actions -> commands,
// through the output shapes (s_shape.txt) associated with each action
// (s_ftoc.txt). Singleton: sum(s * mu) / sum(mu); barycenter: centre of area
// of the polygon sets clipped at their membership. Actions whose name
// contains "Angle" are angles in degrees and use a circular mean.
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
  bool is_angle(int action) const { return is_angle_[static_cast<std::size_t>(action)] != 0; }

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
  std::vector<Shape> shapes_;
  // [shape][label]: the outlines barycenter defuzzification clips, built
  // once (FuzzySet::polygons() allocates).
  std::vector<std::vector<std::vector<Polygon>>> polygons_;
  SymbolTable actions_;
  std::vector<int> shape_of_;
  std::vector<std::uint8_t> is_angle_;
  DefuzzMethod method_ = DefuzzMethod::kSingleton;
  Profile profile_ = Profile::kManual;
};

}  // namespace mrt::brian
