// mice_calibrate --in runs.csv --out params.yaml [--base base.yaml]
// mice_calibrate --push-bag p1.bag ... --turn-bag t1.bag ... --out params.yaml
//
// The calibration of manual §4.2: from straight pushes and turns in place
// (CSV run,kind,amount,left_dx,left_dy,right_dx,right_dy, or one bag of
// mrt_msgs/MiceReading per run) estimates D, sigma_l, sigma_r, delta, the
// mouse positions and resolutions, writes the YAML parameter file and
// prints the residuals. Bad input: exit 2.
#include <mrt_msgs/MiceReading.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>
#include <cstdlib>

#include "mrt_common/angle.h"
#include "mrt_mice/mice_io.h"
#include "mrt_common/cli.h"

namespace {
// One run from a bag: the sum of every mrt_msgs/MiceReading in it (on
// `topic` if not empty).
mrt::mice::CalibrationRun run_from_bag(const std::string& path, bool push, double amount,
                                       const std::string& topic) {
  mrt::mice::CalibrationRun run;
  run.kind = push ? mrt::mice::CalibrationRun::Kind::kPush : mrt::mice::CalibrationRun::Kind::kTurn;
  run.amount = amount;
  run.source = path;
  int n = 0;
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    rosbag::View view(bag, rosbag::TypeQuery("mrt_msgs/MiceReading"));
    for (const rosbag::MessageInstance& m : view) {
      if (!topic.empty() && m.getTopic() != topic && m.getTopic() != "/" + topic) continue;
      const auto r = m.instantiate<mrt_msgs::MiceReading>();
      if (!r) continue;
      run.counts.left_dx += r->left.dx;
      run.counts.left_dy += r->left.dy;
      run.counts.right_dx += r->right.dx;
      run.counts.right_dy += r->right.dy;
      ++n;
    }
  } catch (const rosbag::BagException& e) {
    throw mrt::common::ParseError(path, 0, 0, std::string("cannot read the bag: ") + e.what());
  }
  if (n == 0)
    throw mrt::common::ParseError(path, 0, 0, "expected mrt_msgs/MiceReading messages" +
                                                  (topic.empty() ? std::string() : " on '" + topic + "'"));
  return run;
}

// Prints the estimated geometry, mouse placements and residuals.
void print_result(const mrt::mice::CalibrationResult& res) {
  using mrt::common::rad_to_deg;
  const auto& g = res.geometry;
  std::cout << std::fixed << std::setprecision(4) << "runs: " << res.pushes << " pushes, "
            << res.turns << " turns\n"
            << "D: " << g.D * 1000.0 << " mm\n"
            << "sigma_l: " << rad_to_deg(g.sigma_l) << " deg\n"
            << "sigma_r: " << rad_to_deg(g.sigma_r) << " deg\n"
            << "delta: " << rad_to_deg(g.delta) << " deg\n"
            << "left: x " << res.params.left.mount.x * 1000.0 << " mm, y "
            << res.params.left.mount.y * 1000.0 << " mm, " << res.params.left.counts_per_m
            << " counts/m\n"
            << "right: x " << res.params.right.mount.x * 1000.0 << " mm, y "
            << res.params.right.mount.y * 1000.0 << " mm, " << res.params.right.counts_per_m
            << " counts/m\n";
  for (const auto& r : res.residuals)
    std::cout << "residual " << r.source << " "
              << (r.kind == mrt::mice::CalibrationRun::Kind::kPush ? "push" : "turn")
              << ": left " << r.left << " counts, right " << r.right << " counts\n";
  std::cout << "rms residual: " << res.rms_residual << " counts\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string in_path, out_path, base_path, topic;
  std::vector<std::string> push_bags, turn_bags;
  double push_distance = 0.5, turn_angle_deg = 360.0;
  CLI::App app{"Mice calibration (manual 4.2): from straight pushes and turns in place estimates\n"
               "D, sigma_l, sigma_r, delta, the mouse positions and resolutions, writes the YAML\n"
               "parameter file and prints the residuals.",
               "mice_calibrate"};
  const CLI::Validator non_zero(
      [](std::string& v) {
        const double x = std::strtod(v.c_str(), nullptr);
        return x != 0.0 && std::isfinite(x) ? std::string() : std::string("needs a non-zero number");
      },
      "NONZERO");
  app.add_option("--in", in_path, "runs CSV: run,kind,amount,left_dx,left_dy,right_dx,right_dy");
  app.add_option("--push-bag", push_bags, "bag of mrt_msgs/MiceReading of one straight push (repeatable)");
  app.add_option("--turn-bag", turn_bags, "bag of mrt_msgs/MiceReading of one turn in place (repeatable)");
  app.add_option("--push-distance", push_distance, "distance of each bag push (m), default 0.5")
      ->check(non_zero);
  app.add_option("--turn-angle-deg", turn_angle_deg, "angle of each bag turn (deg), default 360")
      ->check(non_zero);
  app.add_option("--topic", topic, "topic of the readings in the bags (default: any)");
  app.add_option("--out", out_path, "parameter file to write (YAML)")->required();
  app.add_option("--base", base_path, "parameter file (YAML) whose other values are kept");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  if (in_path.empty() && push_bags.empty() && turn_bags.empty()) {
    std::cerr << "mice_calibrate: give the runs with --in or --push-bag/--turn-bag\n";
    return 2;
  }
  try {
    mrt::mice::MiceParams base;
    if (!base_path.empty()) base = mrt::mice::load_params(base_path);
    std::vector<mrt::mice::CalibrationRun> runs;
    if (!in_path.empty()) runs = mrt::mice::read_calibration_csv(in_path);
    mrt::cli::Progress progress("mice_calibrate", static_cast<double>(push_bags.size() + turn_bags.size()));
    double bags_read = 0;
    for (const auto& b : push_bags) {
      progress.update(bags_read++);
      runs.push_back(run_from_bag(b, true, push_distance, topic));
    }
    for (const auto& b : turn_bags) {
      progress.update(bags_read++);
      runs.push_back(run_from_bag(b, false, mrt::common::deg_to_rad(turn_angle_deg), topic));
    }
    progress.finish();
    mrt::mice::CalibrationResult res;
    try {
      res = mrt::mice::calibrate(runs, base);
    } catch (const std::invalid_argument& e) {
      throw mrt::common::ParseError(in_path.empty() ? "runs" : in_path, 0, 0, e.what());
    }
    std::ofstream out(out_path);
    if (!out) {
      std::cerr << out_path << ": cannot write\n";
      return 1;
    }
    mrt::mice::write_params(out, res.params, &res);
    print_result(res);
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
