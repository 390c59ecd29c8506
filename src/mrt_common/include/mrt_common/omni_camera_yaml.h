// Reading the omnidirectional camera model (omni_camera.h) from a YAML map
// (needs yaml-cpp and Eigen). The same block appears in mrt_sim's world
// files (a robot's `camera:`) and in mrt_recvision's calibration files
// (`camera:`), so the simulator and the vision module read one format:
//
//   camera:
//     width: 640            # px
//     height: 480           # px
//     cx: 320               # mirror centre in the image, px
//     cy: 240
//     viewpoint_height: 0.6 # m above the floor
//     roll: 0.0             # tilt of the mirror axis, rad
//     pitch: 0.0
//     mirror:               # one of:
//       {type: hyperbolic, gamma: 200, xi: 0.8, theta_max: 1.9}
//       {type: isometric, metres_per_px: 0.02, inner_range: 4.0, px_per_rad: 120, theta_max: 1.75}
//       {type: table, samples: [[0.0, 0.0], [0.5, 60.0], ...]}   # [theta rad, radius px]
//
// Unknown keys are refused; every error is a ParseError at file:line:column.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "mrt_common/omni_camera.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::common {

/// The `mirror:` map; `height` is the viewpoint height (the isometric
/// profile is defined on the floor).
inline MirrorProfile read_mirror_profile(const YamlReader& r, const YAML::Node& m, double height) {
  r.map(m, "mirror", {"type", "gamma", "xi", "theta_max", "metres_per_px", "inner_range", "px_per_rad", "samples"});
  const std::string type = r.string(m, "type", "", true, "mirror");
  auto num = [&](const char* key) { return r.positive(r.required(m, key, "mirror"), key); };
  try {
    if (type == "hyperbolic") return MirrorProfile::hyperbolic(num("gamma"), num("xi"), num("theta_max"));
    if (type == "isometric")
      return MirrorProfile::isometric(height, num("metres_per_px"), num("inner_range"), num("px_per_rad"),
                                      num("theta_max"));
    if (type == "table") {
      std::vector<std::pair<double, double>> t;
      const YAML::Node samples = r.required(m, "samples", "mirror");  // kept alive for the loop
      for (const YAML::Node& s : r.sequence(samples, "samples")) {
        const auto v = r.numbers(s, "samples", 2);
        t.emplace_back(v[0], v[1]);
      }
      return MirrorProfile(std::move(t));
    }
  } catch (const std::invalid_argument& e) {
    r.fail(m, e.what());
  }
  r.fail(m["type"], "expected mirror type hyperbolic, isometric or table, got '" + type + "'");
}

/// The `camera:` map (see the format above); absent keys keep the
/// defaults of OmniCamera, `mirror` is required.
inline OmniCamera read_omni_camera(const YamlReader& r, const YAML::Node& c) {
  r.map(c, "camera", {"width", "height", "cx", "cy", "viewpoint_height", "roll", "pitch", "mirror", "rate"});
  OmniCamera cam;
  if (c["width"]) cam.width = static_cast<int>(r.integer(c["width"], "width", 16, 8192));
  if (c["height"]) cam.height_px = static_cast<int>(r.integer(c["height"], "height", 16, 8192));
  cam.cx = r.bounded(c, "cx", cam.width / 2.0, 0.0, false, cam.width);
  cam.cy = r.bounded(c, "cy", cam.height_px / 2.0, 0.0, false, cam.height_px);
  cam.height = r.positive(c, "viewpoint_height", cam.height);
  cam.roll = r.bounded(c, "roll", 0.0, -0.5, false, 0.5);
  cam.pitch = r.bounded(c, "pitch", 0.0, -0.5, false, 0.5);
  cam.profile = read_mirror_profile(r, r.required(c, "mirror", "camera"), cam.height);
  return cam;
}

}  // namespace mrt::common
