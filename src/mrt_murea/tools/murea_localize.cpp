// murea_localize: global localization of each frame of a percept CSV in an
// world file or map_server map (see README, "Command-line tool").
#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <iostream>

#include "mrt_common/angle.h"
#include "mrt_common/parse_error.h"
#include "mrt_murea/percept_csv.h"
#include "mrt_common/cli.h"
#include "mrt_world/occupancy_map.h"

int main(int argc, char** argv) {
  CLI::App app{"MUREA global localization: one pose per percept frame", "murea_localize"};
  std::string map_file, percept_file;
  std::vector<double> accuracy{0.05, mrt::common::deg_to_rad(1.0)};
  double timeout = 1.0;
  app.add_option("--map", map_file, "world file or map_server map (YAML)")->required();
  app.add_option("--percepts", percept_file, "CSV: frame,class,color,distance,bearing,reliability")->required();
  app.add_option("--accuracy", accuracy, "lattice spacing: XY (m) THETA (rad), default 0.05 0.0174533 (1 deg)")->expected(2);
  app.add_option("--timeout", timeout, "seconds per frame (0 = no limit), default 1");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    const mrt::world::World world = mrt::world::load_map_world(map_file);
    const auto frames = mrt::murea::load_percept_csv(percept_file);
    mrt::murea::SearchOptions opt;
    opt.accuracy_xy = accuracy[0];
    opt.accuracy_theta = accuracy[1];
    opt.timeout = timeout;
    const mrt::murea::FeatureMap map(world);
    const mrt::murea::Localizer localizer(map, opt);
    mrt::murea::write_result_header(std::cout);
    for (const auto& f : frames) {
      const mrt::murea::Result r = localizer.localize(f.percepts);
      mrt::murea::write_result_row(std::cout, f.id, r);
      if (f.dropped.total() > 0)
        std::cerr << "murea_localize: frame " << f.id << ": dropped " << f.dropped.total() << " percepts ("
                  << f.dropped.unknown_class << " unknown class, " << f.dropped.non_finite << " non-finite, "
                  << f.dropped.out_of_range << " out of range)\n";
      if (!r.complete) std::cerr << "murea_localize: frame " << f.id << ": timeout, best so far\n";
    }
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "murea_localize: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
