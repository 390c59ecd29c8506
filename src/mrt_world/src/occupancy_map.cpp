// map_server maps, rasterized worlds and walls from occupied cells.
#include "mrt_world/occupancy_map.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"
#include "mrt_world/world_loader.h"

namespace mrt::world {

using mrt::common::ParseError;
using mrt::common::YamlReader;

std::int8_t OccupancyMap::value(int col, int row) const {
  const float p = at(col, row);
  if (p < 0.0f) return -1;
  if (mode == Mode::kRaw) return static_cast<std::int8_t>(std::lround(100.0 * p));
  if (p > occupied_thresh) return 100;
  if (p < free_thresh) return 0;
  if (mode == Mode::kTrinary) return -1;
  return static_cast<std::int8_t>(1 + std::lround(98.0 * (p - free_thresh) / (occupied_thresh - free_thresh)));
}

std::vector<std::int8_t> OccupancyMap::values() const {
  std::vector<std::int8_t> out(occupancy.size());
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) out[static_cast<std::size_t>(r) * width + c] = value(c, r);
  return out;
}

Point2D OccupancyMap::cell_center(int col, int row) const {
  if (origin.theta == 0.0)  // the rasterizer's arithmetic, to the last bit
    return {origin.x + 0.5 * resolution + resolution * col, origin.y + 0.5 * resolution + resolution * row};
  return origin.transform({(col + 0.5) * resolution, (row + 0.5) * resolution});
}

std::size_t OccupancyMap::count_occupied() const {
  return static_cast<std::size_t>(
      std::count_if(occupancy.begin(), occupancy.end(), [&](float p) { return p > occupied_thresh; }));
}

namespace {

constexpr int kMaxSide = 20000;

// The YAML keys of a map_server map (see the header).
OccupancyMap read_info(const YamlReader& r, const YAML::Node& root, YAML::Node& image_node) {
  if (!root.IsMap()) r.fail(root, "expected a map at the top level (map_server map YAML)");
  r.map(root, "map", {"image", "resolution", "origin", "occupied_thresh", "free_thresh", "negate", "mode"});
  OccupancyMap m;
  m.file = r.file();
  image_node = r.required(root, "image", "map");
  m.image = r.string(image_node, "image");
  namespace fs = std::filesystem;
  if (!m.image.empty() && fs::path(m.image).is_relative())
    m.image = (fs::path(r.file()).parent_path() / m.image).string();
  m.resolution = r.positive(r.required(root, "resolution", "map"), "resolution");
  const auto o = r.numbers(r.required(root, "origin", "map"), "origin", 3);
  m.origin = Pose2D(o[0], o[1], o[2]);
  m.occupied_thresh = r.number(r.required(root, "occupied_thresh", "map"), "occupied_thresh");
  m.free_thresh = r.number(r.required(root, "free_thresh", "map"), "free_thresh");
  if (!(0.0 <= m.free_thresh && m.free_thresh <= m.occupied_thresh && m.occupied_thresh <= 1.0))
    r.fail(root["occupied_thresh"], "expected 0 <= free_thresh <= occupied_thresh <= 1");
  if (const YAML::Node n = root["negate"]) {
    bool b = false;
    if (YAML::convert<bool>::decode(n, b) && n.Scalar() != "0" && n.Scalar() != "1") m.negate = b;
    else m.negate = r.integer(n, "negate", 0, 1) == 1;
  }
  if (const YAML::Node n = root["mode"]) {
    const std::string s = r.string(n, "mode");
    if (s == "trinary") m.mode = OccupancyMap::Mode::kTrinary;
    else if (s == "scale") m.mode = OccupancyMap::Mode::kScale;
    else if (s == "raw") m.mode = OccupancyMap::Mode::kRaw;
    else r.fail(n, "expected 'mode' trinary, scale or raw, got '" + s + "'");
  }
  return m;
}

// Blocks the cells whose centre is within `d` of segment s.
void block_near(OccupancyMap& m, const Segment& s, double d) {
  const double res = m.resolution;
  auto cell = [&](double v, double o) { return static_cast<int>(std::floor((v - o) / res)); };
  const int c0 = std::max(0, cell(std::min(s.a.x, s.b.x) - d, m.origin.x) - 1);
  const int c1 = std::min(m.width - 1, cell(std::max(s.a.x, s.b.x) + d, m.origin.x) + 1);
  const int r0 = std::max(0, cell(std::min(s.a.y, s.b.y) - d, m.origin.y) - 1);
  const int r1 = std::min(m.height - 1, cell(std::max(s.a.y, s.b.y) + d, m.origin.y) + 1);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c)
      if (distance_to_segment(m.cell_center(c, r), s) <= d) m.occupancy[static_cast<std::size_t>(r) * m.width + c] = 1.0f;
}

}  // namespace

OccupancyMap load_occupancy_map(const std::string& path) {
  const YamlReader r(path);
  const YAML::Node root = r.load(mrt::common::read_file(path, "cannot open file", 1u << 20));
  YAML::Node image_node;
  OccupancyMap m = read_info(r, root, image_node);
  const cv::Mat img = cv::imread(m.image, cv::IMREAD_GRAYSCALE);
  if (img.empty()) r.fail(image_node, "cannot read image '" + m.image + "' (PNG, PGM, ...)");
  if (img.cols > kMaxSide || img.rows > kMaxSide) r.fail(image_node, "image larger than 20000 x 20000 pixels");
  m.width = img.cols;
  m.height = img.rows;
  m.occupancy.resize(static_cast<std::size_t>(m.width) * m.height);
  for (int row = 0; row < img.rows; ++row)
    for (int c = 0; c < img.cols; ++c) {
      const int v = img.at<uchar>(row, c);
      float p;
      if (m.mode == OccupancyMap::Mode::kRaw) p = v > 100 ? -1.0f : v / 100.0f;
      else p = static_cast<float>(m.negate ? v / 255.0 : (255 - v) / 255.0);
      m.occupancy[static_cast<std::size_t>(img.rows - 1 - row) * m.width + c] = p;
    }
  return m;
}

bool is_occupancy_map(const std::string& path) {
  const YamlReader r(path);
  const YAML::Node root = r.load(mrt::common::read_file(path, "cannot open map file", 1u << 20));
  return root.IsMap() && root["image"];
}

OccupancyMap rasterize(const World& w, double resolution) {
  OccupancyMap m;
  m.file = w.file;
  m.resolution = resolution;
  m.origin = Pose2D(w.min_x, w.min_y, 0.0);
  m.width = std::max(1, static_cast<int>(std::ceil((w.max_x - w.min_x) / resolution - 1e-9)));
  m.height = std::max(1, static_cast<int>(std::ceil((w.max_y - w.min_y) / resolution - 1e-9)));
  m.occupancy.assign(static_cast<std::size_t>(m.width) * m.height, 0.0f);
  const double half_diag = resolution / std::sqrt(2.0);
  for (const Segment& s : solid_segments(w)) block_near(m, s, half_diag);
  for (const Post& p : w.posts) block_near(m, {p.center, p.center}, p.radius + half_diag);
  return m;
}

World occupied_walls(const OccupancyMap& m) {
  World w;
  w.name = w.file = m.file;
  std::vector<bool> left(m.occupancy.size());  // occupied cells not yet in a horizontal run
  for (int r = 0; r < m.height; ++r)
    for (int c = 0; c < m.width; ++c) left[static_cast<std::size_t>(r) * m.width + c] = m.occupied(c, r);
  // Rows from the top, as the image is read (the order of the walls).
  for (int r = m.height - 1; r >= 0; --r)
    for (int a = 0; a < m.width;) {
      int b = a;
      while (b < m.width && m.occupied(b, r)) ++b;
      if (b - a >= 2) {
        w.walls.push_back({m.cell_center(a, r), m.cell_center(b - 1, r)});
        for (int k = a; k < b; ++k) left[static_cast<std::size_t>(r) * m.width + k] = false;
      }
      a = b > a ? b : a + 1;
    }
  for (int c = 0; c < m.width; ++c)
    for (int a = m.height - 1; a >= 0;) {
      int b = a;
      while (b >= 0 && left[static_cast<std::size_t>(b) * m.width + c]) --b;
      if (b < a) w.walls.push_back({m.cell_center(c, a), m.cell_center(c, b + 1)});
      a = b < a ? b : a - 1;
    }
  // Bounds: the grid's corners (rotated by the origin's yaw).
  w.min_x = w.min_y = INFINITY;
  w.max_x = w.max_y = -INFINITY;
  const double ex = m.width * m.resolution, ey = m.height * m.resolution;
  for (const auto& [lx, ly] : {std::pair{0.0, 0.0}, {ex, 0.0}, {0.0, ey}, {ex, ey}}) {
    const Point2D p = m.origin.transform({lx, ly});
    w.min_x = std::min(w.min_x, p.x);
    w.max_x = std::max(w.max_x, p.x);
    w.min_y = std::min(w.min_y, p.y);
    w.max_y = std::max(w.max_y, p.y);
  }
  return w;
}

World load_map_world(const std::string& path) {
  return is_occupancy_map(path) ? occupied_walls(load_occupancy_map(path)) : load_world(path);
}

OccupancyMap load_map_grid(const std::string& path, double resolution) {
  return is_occupancy_map(path) ? load_occupancy_map(path) : rasterize(load_world(path), resolution);
}

}  // namespace mrt::world
