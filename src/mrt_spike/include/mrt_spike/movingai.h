// Moving AI benchmark files: `.map` grids and `.scen` query lists.
#pragma once

#include <string>
#include <vector>

#include "mrt_spike/grid.h"

namespace mrt::spike {

/// Reads a Moving AI `.map` file (`type octile`, `height H`, `width W`,
/// `map`, then H rows of W characters). Passable: `.` `G` `S`; blocked:
/// `@` `O` `T` `W`. Throws mrt::common::ParseError naming file:line and what
/// was expected.
OccupancyGrid load_movingai_map(const std::string& path);
OccupancyGrid parse_movingai_map(const std::string& text, const std::string& name);

/// One scenario query: x is the column, y the row.
struct ScenarioQuery {
  int bucket = 0;
  std::string map;
  int width = 0;
  int height = 0;
  Cell start;
  Cell goal;
  double optimal_length = 0.0;
};

/// Reads a `.scen` file (`version 1` then one query a line). The index of a
/// query is its 0-based position after the version line.
std::vector<ScenarioQuery> load_scenario(const std::string& path);
std::vector<ScenarioQuery> parse_scenario(const std::string& text, const std::string& name);

/// Reads a list of query indices, one a line (blank lines and `#` comments
/// ignored).
std::vector<int> load_indices(const std::string& path);

}  // namespace mrt::spike
