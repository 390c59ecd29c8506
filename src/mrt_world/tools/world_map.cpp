// world_map: loads a world file or a map_server map, prints what it holds
// and, with --out, writes it as a map_server map (PREFIX.pgm + PREFIX.yaml,
// trinary) that map_server, amcl or SPIKE read.
#include <cstdio>
#include <fstream>
#include <iostream>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_world/occupancy_map.h"
#include "mrt_world/world_loader.h"

using namespace mrt::world;

namespace {

// map_server's trinary grey levels: free 254, occupied 0, unknown 205.
void write_map(const OccupancyMap& m, const std::string& prefix) {
  cv::Mat img(m.height, m.width, CV_8U);
  for (int r = 0; r < m.height; ++r)
    for (int c = 0; c < m.width; ++c)
      img.at<uchar>(m.height - 1 - r, c) = m.occupied(c, r) ? 0 : m.free(c, r) ? 254 : 205;
  const std::string pgm = prefix + ".pgm";
  if (!cv::imwrite(pgm, img)) throw std::runtime_error("cannot write " + pgm);
  std::ofstream y(prefix + ".yaml");
  const auto slash = pgm.rfind('/');
  y << "image: " << (slash == std::string::npos ? pgm : pgm.substr(slash + 1)) << "\nresolution: " << m.resolution
    << "\norigin: [" << m.origin.x << ", " << m.origin.y << ", " << m.origin.theta
    << "]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  if (!y) throw std::runtime_error("cannot write " + prefix + ".yaml");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Load a world file or a map_server map; print a summary; optionally write it as a map_server map.",
               "world_map"};
  std::string file, out;
  double resolution = 0.05;
  app.add_option("file", file, "world YAML or map_server YAML")->required();
  app.add_option("--resolution", resolution, "m per cell when rasterizing a world file")->check(CLI::PositiveNumber);
  app.add_option("--out", out, "write PREFIX.pgm and PREFIX.yaml (map_server, trinary)");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    if (!is_occupancy_map(file)) {
      const World w = load_world(file);
      std::printf("world %s: bounds [%g, %g, %g, %g], %zu walls, %zu field-line segments, %zu posts, %zu goals, "
                  "%zu doors, %zu regions\n",
                  w.name.c_str(), w.min_x, w.min_y, w.max_x, w.max_y, w.walls.size(), w.field_lines.size(),
                  w.posts.size(), w.goals.size(), w.doors.size(), w.regions.size());
    }
    const OccupancyMap m = load_map_grid(file, resolution);
    std::printf("grid %d x %d cells of %g m, origin (%g, %g, %g), %zu occupied\n", m.width, m.height, m.resolution,
                m.origin.x, m.origin.y, m.origin.theta, m.count_occupied());
    if (!out.empty()) write_map(m, out);
  } catch (const mrt::common::ParseError& e) {
    std::cerr << "world_map: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "world_map: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
