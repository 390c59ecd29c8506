// mice_odometry --params P.yaml --in readings.csv --out poses.csv
//
// Runs the two-mouse odometry on recorded raw readings
// (t,left_dx,left_dy,right_dx,right_dy; integer counts in each mouse's
// frame) and writes the integrated poses (t,x,y,theta,flag; m, rad, flag 1
// when the sample was detected as erroneous). Bad input: file:line:column,
// exit 2.
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "mrt_common/csv.h"
#include "mrt_mice/mice_io.h"
#include "mrt_mice/mice_odometry.h"

namespace {
int usage(const char* msg) {
  std::cerr << "mice_odometry: " << msg << "\n"
            << "usage: mice_odometry --params P.yaml --in readings.csv --out poses.csv"
               " [--no-reduction]\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  std::string params_path, in_path, out_path;
  bool reduce = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string* dst) {
      if (i + 1 >= argc) return false;
      *dst = argv[++i];
      return true;
    };
    if (a == "--params") {
      if (!value(&params_path)) return usage("--params needs a file");
    } else if (a == "--in") {
      if (!value(&in_path)) return usage("--in needs a file");
    } else if (a == "--out") {
      if (!value(&out_path)) return usage("--out needs a file");
    } else if (a == "--no-reduction") {
      reduce = false;
    } else if (a == "-h" || a == "--help") {
      usage("help");
      return 0;
    } else {
      return usage(("unknown argument '" + a + "'").c_str());
    }
  }
  if (params_path.empty() || in_path.empty() || out_path.empty())
    return usage("--params, --in and --out are required");
  try {
    const mrt::mice::MiceParams params = mrt::mice::load_params(params_path);
    const auto rows = mrt::mice::read_readings_csv(in_path);
    mrt::mice::OdometryOptions opt;
    opt.reduce_errors = reduce;
    mrt::mice::MiceOdometry odo(params, opt);
    std::ofstream out(out_path);
    if (!out) {
      std::cerr << out_path << ": cannot write\n";
      return 1;
    }
    mrt::common::CsvWriter w(out, {"t", "x", "y", "theta", "flag"});
    for (const auto& r : rows) {
      const auto step = odo.update(r.counts);
      const auto& p = odo.pose();
      w.row({r.t, p.x, p.y, p.theta, step.detection.flagged ? 1.0 : 0.0});
    }
    const auto& s = odo.stats();
    std::cerr << "mice_odometry: " << s.samples << " samples, " << s.flagged << " flagged, "
              << s.corrected << " corrected, distance " << odo.distance() << " m\n";
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
