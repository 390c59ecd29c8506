// sim_run: drives one robot of a world with a constant twist and writes the
// ground truth (and optionally the mice samples) as CSV.
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "mrt_common/csv.h"
#include "mrt_common/parse_error.h"
#include "mrt_common/cli.h"
#include "mrt_sim/camera.h"
#include "mrt_sim/simulator.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace {

int error(const std::string& message) {
  std::cerr << "sim_run: " << message << "\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string world_path, robot, out_path, mice_path, camera_path;
  std::vector<double> twist{0, 0, 0};
  double duration = -1.0, dt = 0.001;
  CLI::App app{
      "Drives robot NAME (default: the first) with the body twist VX VY (m/s) OMEGA (rad/s)\n"
      "for S seconds; writes t,x,y,theta every step to the --out CSV and\n"
      "t,left_dx,left_dy,right_dx,right_dy (counts) at the mice rate to the --mice CSV.",
      "sim_run"};
  app.add_option("--world", world_path, "mrt_sim world file (YAML)")->required();
  app.add_option("--robot", robot, "robot name in the world (default: the first)");
  app.add_option("--twist", twist, "body twist VX VY (m/s) OMEGA (rad/s)")->expected(3)->required();
  app.add_option("--duration", duration, "simulated time (s, >= 0)")
      ->required()->check(CLI::NonNegativeNumber);
  app.add_option("--out", out_path, "ground-truth CSV to write: t,x,y,theta (s, m, m, rad)")->required();
  app.add_option("--mice", mice_path, "mice CSV to write: t,left_dx,left_dy,right_dx,right_dy (s, counts)");
  app.add_option("--camera", camera_path, "image file (PNG, ...) to write the robot's camera frame to at the end");
  app.add_option("--dt", dt, "simulation step (s, > 0), default 0.001")->check(CLI::PositiveNumber);
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;

  std::unique_ptr<mrt::sim::Simulator> sim;
  try {
    sim = std::make_unique<mrt::sim::Simulator>(mrt::sim::load_world(world_path), dt);
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::size_t index = 0;
  try {
    if (!robot.empty()) index = sim->robot_index(robot);
  } catch (const std::out_of_range&) {
    return error("the world has no robot named '" + robot + "'");
  }

  std::ofstream truth_file(out_path);
  if (!truth_file) return error("cannot write '" + out_path + "'");
  std::ofstream mice_file;
  if (!mice_path.empty()) {
    mice_file.open(mice_path);
    if (!mice_file) return error("cannot write '" + mice_path + "'");
  }
  mrt::common::CsvWriter truth(truth_file, {"t", "x", "y", "theta"});
  std::unique_ptr<mrt::common::CsvWriter> mice;
  if (mice_file.is_open())
    mice = std::make_unique<mrt::common::CsvWriter>(
        mice_file, std::vector<std::string>{"t", "left_dx", "left_dy", "right_dx", "right_dy"});

  sim->set_twist(index, {twist[0], twist[1], twist[2]});
  const auto steps = static_cast<long long>(std::llround(duration / dt));
  const mrt::sim::RobotState& r = sim->robots()[index];
  truth.row({0.0, r.pose.x, r.pose.y, r.pose.theta});
  mrt::cli::Progress progress("sim_run", static_cast<double>(steps));
  for (long long k = 0; k < steps; ++k) {
    progress.update(static_cast<double>(k));
    sim->step();
    truth.row({sim->time(), r.pose.x, r.pose.y, r.pose.theta});
    if (mice && r.mice_ready)
      mice->row({sim->time(), double(r.mice.left_dx), double(r.mice.left_dy), double(r.mice.right_dx),
                 double(r.mice.right_dy)});
  }
  if (!camera_path.empty()) {
    if (r.config.sensors.camera.rate <= 0.0) return error("robot '" + r.config.name + "' has no camera");
    mrt::sim::CameraRenderer cam(sim->world(), r.config.sensors.camera.model,
                                 mrt::sim::camera_options(r.config, sim->world().seed));
    cv::Mat rgb, bgr;
    cam.render(r.pose, sim->other_robots(index), sim->time(), rgb, r.twist);
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    try {
      if (!cv::imwrite(camera_path, bgr)) return error("cannot write '" + camera_path + "'");
    } catch (const cv::Exception& e) {
      return error("cannot write '" + camera_path + "': " + e.what());
    }
  }
  return 0;
}
