// roby_run: Roby in closed loop without ROS (mrt_sim + SCARE + Mr. BRIAN).
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_roby/roby_loop.h"

namespace {
int usage() {
  std::cerr << "usage: roby_run --world W.yaml --map MAP.yaml --tasks TASKS.yaml --brian DIR\n"
               "                [--robot NAME] [--duration S] [--truth] [--trace]\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  mrt::roby::RobyLoopOptions o;
  bool trace = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    const char* v = nullptr;
    if (a == "--truth") o.use_ground_truth = true;
    else if (a == "--trace") trace = true;
    else if ((a == "--world" || a == "--map" || a == "--tasks" || a == "--brian" || a == "--robot" ||
              a == "--duration") && (v = next())) {
      if (a == "--world") o.world = v;
      else if (a == "--map") o.map = v;
      else if (a == "--tasks") o.tasks = v;
      else if (a == "--brian") o.brian = v;
      else if (a == "--robot") o.robot = v;
      else {
        char* end = nullptr;
        o.duration = std::strtod(v, &end);
        if (*end || !(o.duration > 0)) return usage();
      }
    } else return usage();
  }
  if (o.world.empty() || o.map.empty() || o.tasks.empty() || o.brian.empty()) return usage();
  try {
    std::size_t shown = 0;
    const auto res = mrt::roby::run_roby_loop(o, [&](double, const mrt::roby::RobyLoopResult& r) {
      for (; trace && shown < r.events.size(); ++shown) {
        const auto& e = r.events[shown];
        std::printf("%8.2f %-16s #%zu (%.2f, %.2f) at (%.2f, %.2f)\n", e.time, to_string(e.type),
                    e.index, e.point.x, e.point.y, e.pose.x, e.pose.y);
      }
    });
    std::printf("path points reached: %zu of %zu\n", res.reached, res.route_points);
    std::printf("failed: %zu, re-plans: %zu, completed: %s\n", res.failed, res.replans,
                res.completed ? "yes" : "no");
    std::printf("time: %.2f s\n", res.time);
    std::printf("minimum clearance: %.3f m (%s)\n", res.min_clearance, res.nearest.c_str());
    std::printf("max localization error: %.3f m\n", res.max_pose_error);
    return res.completed ? 0 : 1;
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
