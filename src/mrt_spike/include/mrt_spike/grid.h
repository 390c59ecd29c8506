// Occupancy grid, cell points and inflation (ROS-free).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mrt::spike {

/// A cell of the grid: column x, row y (0 at the top left, as in Moving AI
/// files). As a point, the centre of cell (x, y) is (x, y).
struct Cell {
  int x = 0;
  int y = 0;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y; }
  bool operator!=(const Cell& o) const { return !(*this == o); }
};

/// A binary occupancy grid: true = blocked. Cells outside are blocked.
class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  OccupancyGrid(int width, int height, bool blocked = false)
      : width_(width), height_(height),
        cells_(static_cast<size_t>(width) * static_cast<size_t>(height), blocked ? 1 : 0) {}

  int width() const { return width_; }
  int height() const { return height_; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool blocked(int x, int y) const { return !inside(x, y) || cells_[index(x, y)] != 0; }
  bool free(int x, int y) const { return !blocked(x, y); }
  bool free(const Cell& c) const { return free(c.x, c.y); }
  void set_blocked(int x, int y, bool b) { cells_[index(x, y)] = b ? 1 : 0; }
  size_t index(int x, int y) const {
    return static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x);
  }
  int count_free() const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> cells_;
};

/// Squared Euclidean distance (in cells) from every cell centre to the
/// nearest blocked cell centre: the exact transform of Felzenszwalb and
/// Huttenlocher (separable, linear time). Blocked cells have 0.
std::vector<double> squared_distance_transform(const OccupancyGrid& grid);

/// The grid with every cell whose centre is within `radius_cells` (robot
/// radius + safety distance, in cells) of a blocked cell centre blocked too.
/// radius_cells <= 0 returns the grid unchanged.
OccupancyGrid inflate(const OccupancyGrid& grid, double radius_cells);

/// Adds (blocked = true) or clears a disc of the given radius around the
/// centre (x, y), in cells: cells whose centre is within radius.
void stamp_disc(OccupancyGrid& grid, double x, double y, double radius, bool blocked);

}  // namespace mrt::spike
