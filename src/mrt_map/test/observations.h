// The gtests' own-sensor observation: class `cls` seen by robot r1's camera
// at (x, y) with variance `var` on each axis at time t.
#pragma once

#include <string>

#include "mrt_map/tracker.h"

namespace mrt::map::test {

inline Observation obs(int cls, double x, double y, double var, double t, const std::string& sensor = "r1/cam") {
  Observation o;
  o.class_index = cls;
  o.z = Vec2(x, y);
  o.R = var * Mat2::Identity();
  o.stamp = t;
  o.robot = "r1";
  o.sensors = {sensor};
  return o;
}

}  // namespace mrt::map::test
