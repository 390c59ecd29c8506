#include "mrt_spike/map_sources.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"
#include "mrt_sim/world.h"

namespace mrt::spike {

using mrt::common::ParseError;

Cell WorldGrid::cell_at(double x, double y) const {
  return {static_cast<int>(std::lround((x - frame.origin_x) / frame.resolution)),
          static_cast<int>(std::lround((y - frame.origin_y) / frame.resolution))};
}

namespace {

// Blocks the cells whose centre is within `r` of segment ab (world metres).
void block_near_segment(WorldGrid& m, mrt::sim::Point2D a, mrt::sim::Point2D b, double r) {
  const double res = m.frame.resolution;
  const Cell lo = m.cell_at(std::min(a.x, b.x) - r, std::min(a.y, b.y) - r);
  const Cell hi = m.cell_at(std::max(a.x, b.x) + r, std::max(a.y, b.y) + r);
  const mrt::sim::Segment s{a, b};
  for (int y = std::max(0, lo.y - 1); y <= std::min(m.grid.height() - 1, hi.y + 1); ++y)
    for (int x = std::max(0, lo.x - 1); x <= std::min(m.grid.width() - 1, hi.x + 1); ++x) {
      const mrt::sim::Point2D p{m.frame.origin_x + res * x, m.frame.origin_y + res * y};
      if (mrt::sim::distance_to_segment(p, s) <= r) m.grid.set_blocked(x, y, true);
    }
}

}  // namespace

WorldGrid rasterize_world(const mrt::sim::World& w, double resolution) {
  WorldGrid m;
  m.frame.resolution = resolution;
  m.frame.origin_x = w.min_x + resolution / 2;
  m.frame.origin_y = w.min_y + resolution / 2;
  const int width = static_cast<int>(std::ceil((w.max_x - w.min_x) / resolution - 1e-9));
  const int height = static_cast<int>(std::ceil((w.max_y - w.min_y) / resolution - 1e-9));
  m.grid = OccupancyGrid(std::max(width, 1), std::max(height, 1));
  const double half_diag = resolution / std::sqrt(2.0);
  for (const auto& s : mrt::sim::solid_segments(w)) block_near_segment(m, s.a, s.b, half_diag);
  for (const auto& p : w.posts) block_near_segment(m, p.center, p.center, p.radius + half_diag);
  return m;
}

WorldGrid load_world_map(const std::string& path, double resolution) {
  return rasterize_world(mrt::sim::load_world(path), resolution);
}

WorldGrid load_occupancy_map(const std::string& yaml_path) {
  const mrt::common::YamlReader yr(yaml_path);
  const YAML::Node root = yr.load(mrt::common::read_file(yaml_path, "cannot open file", 1 << 20));
  yr.map(root, "map", {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"});
  const std::string image = yr.string(root, "image", "", true, "map");
  WorldGrid m;
  m.frame.resolution = yr.positive(yr.required(root, "resolution", "map"), "resolution");
  const std::vector<double> origin = yr.numbers(yr.required(root, "origin", "map"), "origin", 3);
  const bool negate = yr.number(root, "negate", 0.0) != 0.0;
  const double occupied = yr.fraction(root, "occupied_thresh", 0.65);
  const double free_t = yr.fraction(root, "free_thresh", 0.196);
  const std::string mode = yr.string(root, "mode", "trinary", false, "map");
  if (mode != "trinary" && mode != "scale" && mode != "raw")
    throw yr.error(root["mode"], "expected trinary, scale or raw for 'mode', got '" + mode + "'");
  if (!(free_t < occupied)) throw yr.error(root["free_thresh"], "expected free_thresh < occupied_thresh");
  namespace fs = std::filesystem;
  const fs::path img = fs::path(image).is_absolute() ? fs::path(image) : fs::path(yaml_path).parent_path() / image;
  const cv::Mat px = cv::imread(img.string(), cv::IMREAD_GRAYSCALE);
  if (px.empty()) throw yr.error(root["image"], "cannot read image '" + img.string() + "'");
  m.frame.origin_x = origin[0] + m.frame.resolution / 2;
  m.frame.origin_y = origin[1] + m.frame.resolution / 2;
  m.grid = OccupancyGrid(px.cols, px.rows);
  for (int r = 0; r < px.rows; ++r)
    for (int c = 0; c < px.cols; ++c) {
      const int v = px.at<unsigned char>(r, c);
      // raw mode: the value is the occupancy in percent (0 free, 100 occupied)
      const double p = mode == "raw" ? v / 100.0 : (negate ? v : 255 - v) / 255.0;
      m.grid.set_blocked(c, px.rows - 1 - r, !(p < free_t));
    }
  return m;
}

}  // namespace mrt::spike
