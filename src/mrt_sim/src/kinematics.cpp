#include "mrt_sim/kinematics.h"

#include <string>

namespace mrt::sim {

BaseConfig base_preset(const std::string& name) {
  const mrt::common::BasePreset& p = mrt::common::base_preset(name);
  BaseConfig g;
  static_cast<BaseGeometry&>(g) = p.geometry;
  g.name = p.name;
  g.max_wheel_speed = p.max_wheel_speed;
  g.body_radius = p.body_radius;
  return g;
}

}  // namespace mrt::sim
