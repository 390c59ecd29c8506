// recvision_museum_bench [--frames N] [--calib FILE] [--world FILE] [--list]
// FollowMe's museum through the rendered camera: the robot drives a loop
// through the south-west room (up to 0.5 m/s, turning), the guest follows
// 1.5-2.5 m behind, the other visitors walk in the east rooms. Per frame:
// mrt_sim's render time and RecVision's processing time (CPU time of one
// core, OpenCV on one thread; medians), and the detections against the
// world (test/museum_scene.h: objects in full sight, distance and bearing
// errors, objects reported that are not there).
// Prints `name: value unit` lines.
#include <opencv2/core/utility.hpp>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_recvision/detector.h"
#include "mrt_sim/camera.h"
#include "museum_scene.h"

using namespace mrt::recvision;
namespace sim = mrt::sim;

namespace {

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The robot's pose at time t on a loop in the south-west room (centre
// (5.5, 3), 3.5 x 1.8 m), heading along the path and swinging +-0.5 rad.
sim::Pose2D robot_at(double t) {
  const double w = 0.12;
  const double x = 5.5 + 3.5 * std::sin(w * t), y = 3.0 + 1.8 * std::sin(2 * w * t);
  const double heading = std::atan2(3.6 * w * std::cos(2 * w * t), 3.5 * w * std::cos(w * t));
  return {x, y, heading + 0.5 * std::sin(0.3 * t)};
}

void report(const char* name, const museum::Tally& t) {
  std::printf("%s_in_sight: %d objects\n", name, t.required);
  std::printf("%s_found: %.2f %%\n", name, t.required ? 100.0 * t.found / t.required : 100.0);
  std::printf("%s_distance_error_median: %.3f m\n", name, median(t.distance_error));
  std::printf("%s_distance_error_max: %.3f m\n", name, museum::max_of(t.distance_error));
  std::printf("%s_relative_error_max: %.2f %%\n", name, 100.0 * museum::max_of(t.relative_error));
  std::printf("%s_bearing_error_median: %.2f deg\n", name, median(t.bearing_error) * 180.0 / M_PI);
  std::printf("%s_bearing_error_max: %.2f deg\n", name, museum::max_of(t.bearing_error) * 180.0 / M_PI);
  std::printf("%s_reported_not_there: %d of %d\n", name, t.false_positives, t.reported);
}

void list(const char* name, const museum::Tally& t) {
  for (const std::string& m : t.missed) std::fprintf(stderr, "%s missed: %s\n", name, m.c_str());
  for (const std::string& m : t.spurious) std::fprintf(stderr, "%s not there: %s\n", name, m.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 600;
  bool verbose = false;
  std::string calib = MRT_RECVISION_CONFIG_DIR "/museum.yaml", world = MRT_SIM_MUSEUM;
  CLI::App app{"recvision_museum_bench: RecVision's time per frame and accuracy in FollowMe's rendered museum"};
  app.add_option("--frames", frames, "rendered frames (10 Hz)")->check(CLI::PositiveNumber);
  app.add_option("--calib", calib, "calibration file")->check(CLI::ExistingFile);
  app.add_option("--world", world, "mrt_sim world file (the museum)");
  app.add_flag("--list", verbose, "list the objects missed and those reported that are not there (stderr)");
  if (const int code = mrt::cli::parse_cli(app, argc, argv); code >= 0) return code;
  if (world.empty()) {
    std::fprintf(stderr, "recvision_museum_bench: give --world (mrt_sim's worlds/museum.yaml)\n");
    return 2;
  }
  sim::World w = sim::load_world(world);
  const sim::RobotConfig rc = w.robots.at(0);
  w.robots.clear();
  const Calibration cal = load_calibration(calib);
  Detector det(cal);
  sim::CameraRenderer renderer(w, rc.sensors.camera.model, sim::camera_options(rc, 1));
  cv::setNumThreads(1);
  museum::Tally landmarks, persons, exhibits;
  std::vector<double> t_render, t_vision;
  Frame f;
  for (int i = 0; i < frames; ++i) {
    const double t = i / 10.0;
    const sim::Pose2D robot = robot_at(t), behind = robot_at(t - 4.0 - 1.5 * std::sin(0.05 * t));
    for (auto& m : w.movers) {
      if (m.name == "guest") m.position = {behind.x, behind.y};
      if (m.name == "visitor1") m.position = {15.0 + 3.8 * std::sin(0.09 * t), 0.8};
      if (m.name == "visitor2") m.position = {15.0 + 3.8 * std::cos(0.11 * t), 11.2};
    }
    const double c0 = cpu_ms();
    renderer.render(robot, {}, t, f.rgb);
    const double c1 = cpu_ms();
    const auto dets = det.process(f);
    const double c2 = cpu_ms();
    t_render.push_back(c1 - c0);
    t_vision.push_back(c2 - c1);
    const auto truth = museum::truth(w, robot, cal.detector.min_distance);
    const std::string at = " (frame " + std::to_string(i) + ", robot " + std::to_string(robot.x) + " " +
                           std::to_string(robot.y) + " " + std::to_string(robot.theta) + ")";
    for (auto [cls, tally] : {std::make_pair("Landmark", &landmarks), std::make_pair("Person", &persons),
                              std::make_pair("Exhibit", &exhibits)}) {
      const std::size_t missed = tally->missed.size(), spurious = tally->spurious.size();
      museum::evaluate(dets, truth, cls, cal.camera, *tally);
      for (std::size_t k = missed; k < tally->missed.size(); ++k) tally->missed[k] += at;
      for (std::size_t k = spurious; k < tally->spurious.size(); ++k) tally->spurious[k] += at;
    }
  }
  std::printf("frames: %d frames\n", frames);
  std::printf("image: %dx%d px\n", cal.camera.width, cal.camera.height_px);
  std::printf("render_cpu_median: %.2f ms\n", median(t_render));
  std::printf("recvision_cpu_median: %.2f ms\n", median(t_vision));
  std::printf("recvision_cpu_max: %.2f ms\n", museum::max_of(t_vision));
  report("landmarks", landmarks);
  report("persons", persons);
  report("exhibits", exhibits);
  if (verbose) {
    list("landmarks", landmarks);
    list("persons", persons);
    list("exhibits", exhibits);
  }
  return 0;
}
