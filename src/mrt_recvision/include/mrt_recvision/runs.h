// Colour runs along the radial scan lines (ROS-free), grouped over
// neighbouring bearings into objects: goals (yellow, blue) and robots
// (black bodies with cyan or magenta markers).
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_recvision/color_table.h"
#include "mrt_recvision/scan_lines.h"

namespace mrt::recvision {

/// The innermost run of one colour on one radial line.
struct Hit {
  bool hit = false;
  int index = 0;          // first point of the run on the line
  int length = 0;         // points in the run
  float x = 0, y = 0;     // floor point of its first point (viewpoint frame)
  double distance = 0;    // hypot(x, y)
  int cyan = 0, magenta = 0;  // marker points just beyond the run's start
};

/// Neighbouring radial lines whose hits belong together; first and last
/// are line indices (the group may wrap through line 0).
struct Segment {
  int first = 0, last = 0;
  int lines = 0;
  int pixels = 0;             // sum of the runs' lengths
  double middle_bearing = 0;  // rad, half-way from first to last line
};

/// For every line the first run of `color` at least `min_length` long; with
/// `skip_at_start` a run beginning at the line's first point (touching the
/// robot's own body) is skipped.
std::vector<Hit> first_runs(const std::vector<ScanLine>& lines, const std::vector<std::vector<std::uint8_t>>& cls,
                            std::uint8_t color, int min_length, bool skip_at_start);

/// Groups consecutive lines with hits whose distances differ by at most
/// `max_jump` metres (cyclically: the last line neighbours the first).
std::vector<Segment> group_hits(const std::vector<Hit>& hits, double max_jump);

/// The marker colour of a robot segment: cyan or magenta when at least 3
/// marker points were seen, the more frequent one; otherwise black.
ColorClass marker_color(const Segment& s, const std::vector<Hit>& hits);

}  // namespace mrt::recvision
