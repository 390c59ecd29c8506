// recvision_mirror_calib --calib FILE --image IMG --ray BEARING_DEG:D1,D2,... [--ray ...]
//                        [--degree N] [--theta-max RAD]
// Fits the mirror's radial profile from field marks at known distances:
// the robot stands where white lines cross the given rays (bearing in
// degrees, counter-clockwise from forward) at the given floor distances
// (m, from the point under the viewpoint, increasing). Along each ray the
// centres of the green-white-green runs are matched in order to those
// distances. Prints every mark with its residuals (px and m), the RMS, and
// the fitted `camera:` block (a `table` mirror) to paste into the file.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_recvision/calibration.h"
#include "mrt_recvision/mirror_fit.h"

using namespace mrt::recvision;

namespace {

struct Ray {
  double bearing = 0;
  std::vector<double> distances;
};

Ray parse_ray(const std::string& spec) {
  Ray r;
  const auto colon = spec.find(':');
  try {
    if (colon == std::string::npos) throw std::invalid_argument("");
    r.bearing = std::stod(spec.substr(0, colon)) * M_PI / 180.0;
    std::stringstream s(spec.substr(colon + 1));
    for (std::string d; std::getline(s, d, ',');) r.distances.push_back(std::stod(d));
  } catch (const std::exception&) {
    throw std::invalid_argument("--ray '" + spec + "': expected BEARING_DEG:D1,D2,...");
  }
  for (std::size_t i = 0; i < r.distances.size(); ++i)
    if (!(r.distances[i] > 0) || (i > 0 && !(r.distances[i] > r.distances[i - 1])))
      throw std::invalid_argument("--ray '" + spec + "': distances must be positive and increasing");
  if (r.distances.empty()) throw std::invalid_argument("--ray '" + spec + "': no distances");
  return r;
}

void print_camera(const mrt::common::OmniCamera& cam, const MirrorFit& fit) {
  std::printf("camera:\n  width: %d\n  height: %d\n  cx: %g\n  cy: %g\n  viewpoint_height: %g\n  roll: %g\n  pitch: %g\n",
              cam.width, cam.height_px, cam.cx, cam.cy, cam.height, cam.roll, cam.pitch);
  std::printf("  mirror:\n    type: table\n    samples: [");
  const auto& t = fit.profile.table();
  for (std::size_t i = 0; i < t.size(); i = (i + 8 < t.size() || i + 1 == t.size()) ? i + 8 : t.size() - 1)
    std::printf("%s[%.5f, %.3f]", i ? ", " : "", t[i].first, t[i].second);
  std::printf("]\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fits RecVision's mirror profile from field marks at known distances", "recvision_mirror_calib"};
  std::string calib, image;
  std::vector<std::string> ray_specs;
  int degree = 3;
  double theta_max = 0;
  app.add_option("--calib", calib, "calibration file (image centre, viewpoint height, colours)")->required();
  app.add_option("--image", image, "image taken at the known place")->required();
  app.add_option("--ray", ray_specs, "BEARING_DEG:D1,D2,... marks along one ray, repeatable")->required();
  app.add_option("--degree", degree, "polynomial degree of r(theta)")->check(CLI::Range(1, 6));
  app.add_option("--theta-max", theta_max, "fit up to this ray angle (rad; default: the file's mirror)");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    const Calibration cal = load_calibration(calib);
    const auto& cam = cal.camera;
    ImageFileSource src({image});
    Frame f;
    src.next(f);
    std::vector<MirrorMark> marks;
    std::vector<double> bearings;
    const double r_max = std::hypot(std::max(cam.cx, cam.width - cam.cx), std::max(cam.cy, cam.height_px - cam.cy));
    for (const std::string& spec : ray_specs) {
      const Ray ray = parse_ray(spec);
      const auto radii = white_runs_along_ray(f, cal.colors, cam.cx, cam.cy, ray.bearing, 3.0, r_max);
      if (radii.size() != ray.distances.size()) {
        std::ostringstream os;
        os << "--ray '" << spec << "': found " << radii.size() << " line(s) at radii";
        for (double r : radii) os << " " << r;
        os << " px, expected " << ray.distances.size();
        throw std::runtime_error(os.str());
      }
      for (std::size_t i = 0; i < radii.size(); ++i) {
        marks.push_back({radii[i], ray.distances[i]});
        bearings.push_back(ray.bearing);
      }
    }
    const MirrorFit fit = fit_mirror(marks, cam.height, theta_max > 0 ? theta_max : cam.profile.max_theta(), degree);
    std::printf("# bearing_deg,distance_m,radius_px,residual_px,residual_m\n");
    for (std::size_t i = 0; i < marks.size(); ++i)
      std::printf("# %.1f,%.3f,%.2f,%.3f,%.4f\n", bearings[i] * 180.0 / M_PI, marks[i].distance, marks[i].radius,
                  fit.residual_px[i], fit.residual_m[i]);
    std::printf("# rms: %.3f px, %.4f m over %zu marks\n", fit.rms_px, fit.rms_m, marks.size());
    print_camera(cam, fit);
  } catch (const mrt::common::ParseError& e) {
    std::cerr << "recvision_mirror_calib: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "recvision_mirror_calib: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "recvision_mirror_calib: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
