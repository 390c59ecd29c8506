// sim_run: drives one robot of a world with a constant twist and writes the
// ground truth (and optionally the mice samples) as CSV.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "mrt_common/csv.h"
#include "mrt_common/parse_error.h"
#include "mrt_sim/simulator.h"

namespace {

const char* kUsage =
    "usage: sim_run --world W.yaml [--robot NAME] --twist VX VY OMEGA --duration S\n"
    "               --out truth.csv [--mice mice.csv] [--dt SECONDS]\n"
    "  Drives robot NAME (default: the first) with the body twist VX VY (m/s)\n"
    "  OMEGA (rad/s) for S seconds; writes t,x,y,theta every step to truth.csv\n"
    "  and t,left_dx,left_dy,right_dx,right_dy (counts) at the mice rate.\n";

int usage(const std::string& error) {
  std::cerr << "sim_run: " << error << "\n" << kUsage;
  return 2;
}

bool to_double(const char* s, double& v) {
  char* end = nullptr;
  v = std::strtod(s, &end);
  return *s != '\0' && *end == '\0' && std::isfinite(v);
}

}  // namespace

int main(int argc, char** argv) {
  std::string world_path, robot, out_path, mice_path;
  double twist[3] = {0, 0, 0}, duration = -1.0, dt = 0.001;
  bool have_twist = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](int n) { return i + n < argc; };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--world" && value(1)) {
      world_path = argv[++i];
    } else if (a == "--robot" && value(1)) {
      robot = argv[++i];
    } else if (a == "--out" && value(1)) {
      out_path = argv[++i];
    } else if (a == "--mice" && value(1)) {
      mice_path = argv[++i];
    } else if (a == "--duration" && value(1)) {
      if (!to_double(argv[++i], duration) || duration < 0) return usage("expected a duration >= 0 s");
    } else if (a == "--dt" && value(1)) {
      if (!to_double(argv[++i], dt) || dt <= 0) return usage("expected a step > 0 s after --dt");
    } else if (a == "--twist" && value(3)) {
      for (double& t : twist)
        if (!to_double(argv[++i], t)) return usage("expected three numbers after --twist");
      have_twist = true;
    } else {
      return usage("unexpected or incomplete argument '" + a + "'");
    }
  }
  if (world_path.empty() || out_path.empty() || !have_twist || duration < 0)
    return usage("--world, --twist, --duration and --out are required");

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
    return usage("the world has no robot named '" + robot + "'");
  }

  std::ofstream truth_file(out_path);
  if (!truth_file) return usage("cannot write '" + out_path + "'");
  std::ofstream mice_file;
  if (!mice_path.empty()) {
    mice_file.open(mice_path);
    if (!mice_file) return usage("cannot write '" + mice_path + "'");
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
  for (long long k = 0; k < steps; ++k) {
    sim->step();
    truth.row({sim->time(), r.pose.x, r.pose.y, r.pose.theta});
    if (mice && r.mice_ready)
      mice->row({sim->time(), double(r.mice.left_dx), double(r.mice.left_dy), double(r.mice.right_dx),
                 double(r.mice.right_dy)});
  }
  return 0;
}
