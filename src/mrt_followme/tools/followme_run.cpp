// followme_run: FollowMe in closed loop without ROS (mrt_sim + MUREA + SPIKE
// + the guide + Mr. BRIAN with Roby's rules); prints the tour's summary.
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_followme/followme_loop.h"

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

void print_summary(const mrt::followme::FollowMeResult& r) {
  std::string visited;
  for (const auto& v : r.visited) visited += (visited.empty() ? "" : ", ") + v;
  std::printf("exhibits visited: %zu (%s)\n", r.visited.size(), visited.c_str());
  std::printf("wanders handled: %zu\n", r.wanders);
  std::printf("plans: %zu, completed: %s\n", r.replans, r.completed ? "yes" : "no");
  std::printf("time: %.1f s\n", r.time);
  std::printf("longest time visitor out of sight: %.1f s\n", r.max_unseen);
  std::printf("localization error (max, vs ground truth): %.3f m\n", r.max_pose_error);
  std::printf("closest to a person: %.2f m (%s)\n", r.min_person_gap, r.nearest_person.c_str());
  std::printf("closest to walls and exhibits: %.2f m\n", r.min_clearance);
  std::string doors;
  for (const auto& d : r.doors) doors += (doors.empty() ? "" : ", ") + d.door;
  std::printf("doors: %s\n", doors.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  mrt::followme::FollowMeLoopOptions o;
  std::string tour;
  std::vector<std::string> packages;
  bool trace = false;
  CLI::App app{"FollowMe in closed loop without ROS (mrt_sim + MUREA + SPIKE + Mr. BRIAN); exit 0\n"
               "when the tour was completed, 1 when not, 2 on usage or file errors.",
               "followme_run"};
  app.add_option("--world", o.world, "mrt_sim world file (YAML): the museum")->required();
  app.add_option("--config", o.config, "FollowMe configuration (config/followme/followme.yaml)")->required();
  app.add_option("--brian", o.brian, "Mr. BRIAN rule base (config/followme/brian)")->required();
  app.add_option("--package", packages,
                 "NAME=DIR: the directory of package NAME for the rule base's package:// paths (repeatable; "
                 "default: found on ROS_PACKAGE_PATH)");
  app.add_option("--tour", tour, "exhibits of the tour, comma-separated (default: the configuration's)");
  app.add_option("--robot", o.robot, "robot name in the world")->capture_default_str();
  app.add_option("--duration", o.duration, "simulated time limit (s, > 0)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--close-door", o.close_door, "a door of the configuration closed ...");
  app.add_option("--close-at-leg", o.close_at_leg, "... when the leg to this exhibit (0-based) starts");
  app.add_option("--wander-after", o.wander_after, "the visitor wanders off after this exhibit (0: never; default: the configuration's)");
  app.add_flag("--truth", o.use_ground_truth, "drive on the simulator's ground truth instead of MUREA");
  app.add_flag("--trace", trace, "print every guide event and, each second, the poses and jobs");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  o.tour = split(tour);
  for (const std::string& p : packages) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == p.size()) {
      std::cerr << "followme_run: --package expects NAME=DIR, got '" << p << "'\n";
      return 2;
    }
    o.packages[p.substr(0, eq)] = p.substr(eq + 1);
  }
  try {
    mrt::cli::Progress progress("followme_run", o.duration);
    double next = 0.0;
    const auto res = mrt::followme::run_followme_loop(o, [&](const mrt::followme::FollowMeTick& k) {
      progress.update(k.t);
      if (!trace || k.t < next) return;
      next = k.t + 1.0;
      std::printf("%7.1f robot %5.2f %5.2f est %5.2f %5.2f visitor %5.2f %5.2f %-13s %s\n", k.t, k.truth.x,
                  k.truth.y, k.estimate.x, k.estimate.y, k.visitor.x, k.visitor.y, to_string(k.job),
                  to_string(k.visitor_state));
    });
    progress.finish();
    if (trace)
      for (const auto& e : res.events) std::printf("event %7.1f %-12s %s\n", e.t, e.what.c_str(), e.exhibit.c_str());
    print_summary(res);
    return res.completed ? 0 : 1;
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "followme_run: " << e.what() << "\n";
    return 2;
  }
}
