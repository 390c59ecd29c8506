#include "mrt_sim/kinematics.h"

#include <string>

namespace mrt::sim {

BaseGeometry base_preset(const std::string& name) {
  const mrt::common::BasePreset& p = mrt::common::base_preset(name);
  BaseGeometry g;
  g.name = p.name;
  g.type = p.geometry.type;
  g.wheel_radius = p.geometry.wheel_radius;
  g.track = p.geometry.track;
  g.omni_radius = p.geometry.wheel_distance;
  g.wheel_angles = p.geometry.wheel_angles;
  g.max_wheel_speed = p.max_wheel_speed;
  g.body_radius = p.body_radius;
  return g;
}

}  // namespace mrt::sim
