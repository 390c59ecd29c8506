#include "mrt_murea/occupancy_map.h"

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <vector>

#include "mrt_common/yaml_reader.h"

namespace mrt::murea {

namespace {

using mrt::common::ParseError;
using mrt::sim::Segment;

class OccupancyLoader : private mrt::common::YamlReader {
 public:
  using YamlReader::load;
  using YamlReader::YamlReader;

  OccupancyInfo info(const YAML::Node& root) const {
    if (!root.IsMap()) fail(root, "expected a map at the top level (map_server map YAML)");
    map(root, "map", {"image", "resolution", "origin", "occupied_thresh", "free_thresh", "negate", "mode"});
    OccupancyInfo i;
    const YAML::Node image = required(root, "image", "map");
    i.image = string(image, "image");
    if (!i.image.empty() && i.image[0] != '/') {
      const auto slash = file().rfind('/');
      if (slash != std::string::npos) i.image = file().substr(0, slash + 1) + i.image;
    }
    i.resolution = positive(required(root, "resolution", "map"), "resolution");
    const auto o = numbers(required(root, "origin", "map"), "origin", 3);
    std::copy(o.begin(), o.end(), i.origin);
    i.occupied_thresh = number(required(root, "occupied_thresh", "map"), "occupied_thresh");
    i.free_thresh = number(required(root, "free_thresh", "map"), "free_thresh");
    if (!(0.0 <= i.free_thresh && i.free_thresh <= i.occupied_thresh && i.occupied_thresh <= 1.0))
      fail(root["occupied_thresh"], "expected 0 <= free_thresh <= occupied_thresh <= 1");
    if (const YAML::Node n = root["negate"]) i.negate = integer(n, "negate", 0, 1) == 1;
    if (const YAML::Node n = root["mode"]) {
      const std::string m = string(n, "mode");
      if (m != "trinary" && m != "scale") fail(n, "expected 'mode' trinary or scale");
    }
    image_node_ = image;
    return i;
  }

  ParseError image_error(const std::string& msg) const { return error(image_node_, msg); }

 private:
  mutable YAML::Node image_node_;
};

// Walls through the centres of the occupied pixels (see the header).
std::vector<Segment> walls(const cv::Mat& occ, const OccupancyInfo& i) {
  const double c = std::cos(i.origin[2]), s = std::sin(i.origin[2]);
  auto at = [&](double col, double row) {  // pixel centre in the world (row 0 is the image's top)
    const double lx = (col + 0.5) * i.resolution, ly = (i.height - 1 - row + 0.5) * i.resolution;
    return mrt::common::Point2D{i.origin[0] + c * lx - s * ly, i.origin[1] + s * lx + c * ly};
  };
  std::vector<Segment> out;
  cv::Mat left = occ.clone();  // occupied pixels not yet in a horizontal run
  for (int r = 0; r < occ.rows; ++r)
    for (int a = 0; a < occ.cols;) {
      int b = a;
      while (b < occ.cols && occ.at<uchar>(r, b)) ++b;
      if (b - a >= 2) {
        out.push_back({at(a, r), at(b - 1, r)});
        for (int k = a; k < b; ++k) left.at<uchar>(r, k) = 0;
      }
      a = b > a ? b : a + 1;
    }
  for (int col = 0; col < occ.cols; ++col)
    for (int a = 0; a < occ.rows;) {
      int b = a;
      while (b < occ.rows && left.at<uchar>(b, col)) ++b;
      if (b > a) out.push_back({at(col, a), at(col, b - 1)});
      a = b > a ? b : a + 1;
    }
  return out;
}

}  // namespace

mrt::sim::World load_occupancy_map(const std::string& path, OccupancyInfo* info_out) {
  const OccupancyLoader loader(path);
  const YAML::Node root = loader.load(mrt::common::read_file(path, "cannot open file", 1u << 20));
  OccupancyInfo i = loader.info(root);
  const cv::Mat img = cv::imread(i.image, cv::IMREAD_GRAYSCALE);
  if (img.empty()) throw loader.image_error("cannot read image '" + i.image + "' (PNG, PGM, ...)");
  if (img.cols > 20000 || img.rows > 20000) throw loader.image_error("image larger than 20000 x 20000 pixels");
  i.width = img.cols;
  i.height = img.rows;
  cv::Mat occ(img.rows, img.cols, CV_8U, cv::Scalar(0));
  for (int r = 0; r < img.rows; ++r)
    for (int col = 0; col < img.cols; ++col) {
      const double v = img.at<uchar>(r, col) / 255.0, p = i.negate ? v : 1.0 - v;
      if (p > i.occupied_thresh) {
        occ.at<uchar>(r, col) = 1;
        ++i.occupied;
      }
    }
  mrt::sim::World w;
  w.name = path;
  w.file = path;
  w.walls = walls(occ, i);
  i.segments = w.walls.size();
  // Bounds: the image's corners (rotated by the origin's yaw).
  const double c = std::cos(i.origin[2]), s = std::sin(i.origin[2]);
  const double ex = img.cols * i.resolution, ey = img.rows * i.resolution;
  w.min_x = w.min_y = INFINITY;
  w.max_x = w.max_y = -INFINITY;
  for (const auto& [lx, ly] : {std::pair{0.0, 0.0}, {ex, 0.0}, {0.0, ey}, {ex, ey}}) {
    const double x = i.origin[0] + c * lx - s * ly, y = i.origin[1] + s * lx + c * ly;
    w.min_x = std::min(w.min_x, x);
    w.max_x = std::max(w.max_x, x);
    w.min_y = std::min(w.min_y, y);
    w.max_y = std::max(w.max_y, y);
  }
  w.ball.enabled = false;
  if (info_out) *info_out = i;
  return w;
}

mrt::sim::World load_map(const std::string& path) {
  const mrt::common::YamlReader reader(path);
  const YAML::Node root = reader.load(mrt::common::read_file(path, "cannot open map file"));
  if (root.IsMap() && root["image"]) return load_occupancy_map(path);
  return mrt::sim::load_world(path);
}

}  // namespace mrt::murea
