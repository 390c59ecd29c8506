// mice_odometry --params P.yaml --in readings.csv --out poses.csv
//
// Runs the two-mouse odometry on recorded raw readings
// (t,left_dx,left_dy,right_dx,right_dy; integer counts in each mouse's
// frame) and writes the integrated poses (t,x,y,theta,flag; m, rad, flag 1
// when the sample was detected as erroneous). Bad input: file:line:column,
// exit 2.
#include <fstream>
#include <iostream>
#include <string>

#include "mrt_common/csv.h"
#include "mrt_mice/mice_io.h"
#include "mrt_mice/mice_odometry.h"
#include "mrt_common/cli.h"

int main(int argc, char** argv) {
  std::string params_path, in_path, out_path;
  bool no_reduction = false;
  CLI::App app{"Two-mouse odometry on recorded raw readings (t,left_dx,left_dy,right_dx,right_dy;\n"
               "s, counts) -> poses t,x,y,theta,flag (s, m, m, rad, 1 when the sample was erroneous).",
               "mice_odometry"};
  app.add_option("--params", params_path, "mice parameter file (YAML, e.g. from mice_calibrate)")->required();
  app.add_option("--in", in_path, "readings CSV: t,left_dx,left_dy,right_dx,right_dy (s, counts)")->required();
  app.add_option("--out", out_path, "poses CSV to write: t,x,y,theta,flag (s, m, m, rad, 0/1)")->required();
  app.add_flag("--no-reduction", no_reduction, "do not correct the samples detected as erroneous");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  const bool reduce = !no_reduction;
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
    mrt::cli::Progress progress("mice_odometry", static_cast<double>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& r = rows[i];
      progress.update(static_cast<double>(i));
      const auto step = odo.update(r.counts);
      const auto& p = odo.pose();
      w.row({r.t, p.x, p.y, p.theta, step.detection.flagged ? 1.0 : 0.0});
    }
    progress.finish();
    const auto& s = odo.stats();
    std::cerr << "mice_odometry: " << s.samples << " samples, " << s.flagged << " flagged, "
              << s.corrected << " corrected, distance " << odo.distance() << " m\n";
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
