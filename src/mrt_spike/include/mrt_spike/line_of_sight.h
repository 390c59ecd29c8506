// The validity rule for straight segments between cell centres.
#pragma once

#include <string>
#include <vector>

#include "mrt_spike/grid.h"

namespace mrt::spike {

/// True when the straight segment from the centre of a to the centre of b
/// crosses only free cells and never squeezes between two blocked cells that
/// touch at a corner (where the segment passes exactly through a grid corner,
/// the two cells beside it must not both be blocked). Exact integer
/// arithmetic; cost O(|dx| + |dy|).
bool line_of_sight(const OccupancyGrid& grid, const Cell& a, const Cell& b);

/// Euclidean length of a polyline of cell centres.
double path_length(const std::vector<Cell>& path);

/// Checks a whole path: non-empty, first waypoint `start`, last `goal`, every
/// segment valid by line_of_sight. On failure `why` (if given) says which.
bool path_valid(const OccupancyGrid& grid, const std::vector<Cell>& path, const Cell& start,
                const Cell& goal, std::string* why = nullptr);

}  // namespace mrt::spike
