// The percept and result CSV formats of murea_localize (ROS-free).
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "mrt_murea/localizer.h"

namespace mrt::murea {

/// Percepts dropped while reading, by reason.
struct DropCounts {
  std::size_t unknown_class = 0;  // class not one of Line, Goal, GoalPost, Landmark, Wall
  std::size_t non_finite = 0;     // nan or inf in distance, bearing or reliability
  std::size_t out_of_range = 0;   // negative distance or reliability outside (0, 1]
  std::size_t total() const { return unknown_class + non_finite + out_of_range; }
};

/// The percepts of one frame, in file order.
struct PerceptFrame {
  std::string id;
  int line = 0;  // line of the frame's first row
  std::vector<Percept> percepts;
  DropCounts dropped;
};

/// Reads the stack's percept CSV (mrt_common/percept_csv.h: rows
/// `frame,class,color,distance,bearing,reliability`, exactly these
/// columns, a header row optional, its first column `frame` or `stamp`:
/// what recvision_run writes). Rows of a frame need not be adjacent;
/// frames come out in order of first appearance. Throws
/// mrt::common::ParseError (file:line:column) on a malformed row: wrong
/// field count, empty frame, a field that is not a number. Percepts that
/// are well-formed but unusable are dropped and counted in their frame.
std::vector<PerceptFrame> read_percept_csv(std::istream& in, const std::string& file);
std::vector<PerceptFrame> load_percept_csv(const std::string& path);

/// Output: `frame,x,y,theta,evidence,ambiguous,alt_x,alt_y,alt_theta,alt_evidence,time_ms`;
/// x, y, theta are the estimate (the plateau's mean, see Estimate),
/// evidence the best's; the alt_ fields are empty when there is no runner-up.
void write_result_header(std::ostream& out);
void write_result_row(std::ostream& out, const std::string& frame, const Result& r);

}  // namespace mrt::murea
