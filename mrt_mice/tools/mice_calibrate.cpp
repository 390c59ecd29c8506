// mice_calibrate --in runs.csv --out params.yaml [--base base.yaml]
//
// The calibration of manual §4.2: from straight pushes and turns in place
// (CSV run,kind,amount,left_dx,left_dy,right_dx,right_dy) estimates D,
// sigma_l, sigma_r, delta, the mouse positions and resolutions, writes the
// YAML parameter file and prints the residuals. Bad input: exit 2.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>

#include "mrt_common/angle.h"
#include "mrt_mice/mice_io.h"

namespace {
int usage(const char* msg) {
  std::cerr << "mice_calibrate: " << msg << "\n"
            << "usage: mice_calibrate --in runs.csv --out params.yaml [--base base.yaml]\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  std::string in_path, out_path, base_path;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--in" || a == "--out" || a == "--base") && i + 1 < argc) {
      (a == "--in" ? in_path : a == "--out" ? out_path : base_path) = argv[++i];
    } else if (a == "-h" || a == "--help") {
      usage("help");
      return 0;
    } else {
      return usage(("unknown or incomplete argument '" + a + "'").c_str());
    }
  }
  if (in_path.empty() || out_path.empty()) return usage("--in and --out are required");
  using mrt::common::rad_to_deg;
  try {
    mrt::mice::MiceParams base;
    if (!base_path.empty()) base = mrt::mice::load_params(base_path);
    const auto runs = mrt::mice::read_calibration_csv(in_path);
    mrt::mice::CalibrationResult res;
    try {
      res = mrt::mice::calibrate(runs, base);
    } catch (const std::invalid_argument& e) {
      throw mrt::common::ParseError(in_path, 0, 0, e.what());
    }
    std::ofstream out(out_path);
    if (!out) {
      std::cerr << out_path << ": cannot write\n";
      return 1;
    }
    mrt::mice::write_params(out, res.params, &res);
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
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
