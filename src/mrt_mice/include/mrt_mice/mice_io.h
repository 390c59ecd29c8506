// File formats of the mice tools (ROS-free): the YAML parameter file, the
// readings CSV and the calibration CSV. Every reader throws
// mrt::common::ParseError naming file, line and column.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "mrt_common/parse_error.h"
#include "mrt_mice/calibrator.h"
#include "mrt_mice/mice_odometry.h"

namespace mrt::mice {

/// Parameter file (metres, radians, counts per metre):
///   left:  {x: 0.0, y: 0.10, yaw: 0.0, counts_per_m: 15748}
///   right: {x: 0.0, y: -0.10, yaw: 0.0, counts_per_m: 15748}
///   detection_factor: 1.0        # optional
///   detection_relative: 0.0      # optional
/// Any other top-level key (derived:, calibration:) is ignored.
MiceParams load_params(const std::string& path);
MiceParams parse_params(const std::string& yaml_text, const std::string& file);

/// Writes a parameter file, with the manual's derived parameters (D, sigma,
/// delta, in metres and degrees, for the reader) and, when given, the
/// calibration report.
void write_params(std::ostream& out, const MiceParams& p, const CalibrationResult* calib = nullptr);

/// One row of the readings CSV `t,left_dx,left_dy,right_dx,right_dy`.
struct ReadingRow {
  double t = 0.0;
  MiceCounts counts;
  int line = 0;
};
/// Reads the readings CSV; t must not decrease.
std::vector<ReadingRow> read_readings_csv(const std::string& path);
std::vector<ReadingRow> parse_readings_csv(std::istream& in, const std::string& file);

/// Calibration CSV `run,kind,amount,left_dx,left_dy,right_dx,right_dy`:
/// kind is `push` (amount in metres) or `turn` (amount in radians, ccw
/// positive); rows with the same run number are the samples of one run and
/// are summed (a run may be one row of totals).
std::vector<CalibrationRun> read_calibration_csv(const std::string& path);
std::vector<CalibrationRun> parse_calibration_csv(std::istream& in, const std::string& file);

}  // namespace mrt::mice
