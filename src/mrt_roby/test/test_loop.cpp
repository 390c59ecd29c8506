// Roby in closed loop without ROS: the rule base, the sequencer, the sonar
// adapter and the localizer on the simulator's core, in simulated time.
#include <gtest/gtest.h>

#include "mrt_brian/brian.h"
#include "mrt_brian/checker.h"
#include "mrt_roby/roby_loop.h"

using namespace mrt::roby;

namespace {
const std::string kRoot = MRT_ROBY_ROOT;

RobyLoopOptions route_options() {
  RobyLoopOptions o;
  o.world = kRoot + "/test/data/roby_route.yaml";
  o.map = kRoot + "/test/data/roby_route_map.yaml";
  o.tasks = kRoot + "/config/tasks.yaml";
  o.brian = kRoot + "/config/brian";
  o.duration = 400.0;
  return o;
}

double command(mrt::brian::Brian& b, const mrt::brian::CrispDataList& in, const std::string& name) {
  for (const auto& c : b.run(in))
    if (c.name == name) return c.value;
  return 0.0;  // absent = 0, as the AIRBoard mapping reads it
}
}  // namespace

TEST(RuleBase, CheckerClean) {
  const auto d = mrt::brian::Checker().check_path(kRoot + "/config/brian");
  for (const auto& x : d) ADD_FAILURE() << x.file << ":" << x.line << ": " << x.message;
}

TEST(RuleBase, HandWorkedCycles) {
  auto b = mrt::brian::Brian::from_path(kRoot + "/config/brian");
  const mrt::brian::CrispDataList free = {
      {"ObstacleFront", 500}, {"ObstacleFrontLeft", 500}, {"ObstacleFrontRight", 500},
      {"ObstacleLeft", 500},  {"ObstacleRight", 500},     {"ObstacleBack", 500},
      {"FreeSide", 0}};
  auto with = [&](mrt::brian::CrispDataList extra) {
    auto v = free;
    for (auto& x : extra) {
      bool replaced = false;
      for (auto& y : v)
        if (y.name == x.name) y = x, replaced = true;
      if (!replaced) v.push_back(x);
    }
    return v;
  };
  // Auto, path point 5 m straight ahead: FAST (55 cm/s), no turn.
  auto in = with({{"Status", 1}, {"HaveGoal", 1}, {"GoalDistance", 500}, {"GoalBearing", 0}});
  EXPECT_NEAR(command(*b, in, "Speed"), 55.0, 1e-9);
  EXPECT_NEAR(command(*b, in, "Jog"), 0.0, 1e-9);
  // 20 deg to the left: LEFT = 1, SLOW and turn LEFT (20 deg/s).
  in = with({{"Status", 1}, {"HaveGoal", 1}, {"GoalDistance", 500}, {"GoalBearing", 20}});
  EXPECT_NEAR(command(*b, in, "Speed"), 20.0, 1e-9);
  EXPECT_NEAR(command(*b, in, "Jog"), 20.0, 1e-9);
  // Behind on the right: stop and turn right fast.
  in = with({{"Status", 1}, {"HaveGoal", 1}, {"GoalDistance", 500}, {"GoalBearing", -120}});
  EXPECT_NEAR(command(*b, in, "Speed"), 0.0, 1e-9);
  EXPECT_NEAR(command(*b, in, "Jog"), -50.0, 1e-9);
  // No path point: nothing moves.
  in = with({{"Status", 1}, {"HaveGoal", 0}});
  EXPECT_NEAR(command(*b, in, "Speed"), 0.0, 1e-9);
  // Obstacle 30 cm ahead (DANGER 1) and the path point ahead: AvoidObstacle
  // deletes FAST and proposes STOP; the right side is freer: turn right fast.
  in = with({{"Status", 1}, {"HaveGoal", 1}, {"GoalDistance", 500}, {"GoalBearing", 0},
             {"ObstacleFront", 30}, {"FreeSide", -100}});
  EXPECT_NEAR(command(*b, in, "Speed"), 0.0, 1e-9);
  EXPECT_NEAR(command(*b, in, "Jog"), -50.0, 1e-9);
  // Manual: the remote's 50 cm/s forward becomes FAST, its 30 deg/s LEFT.
  in = with({{"Status", 0}, {"HaveGoal", 1}, {"GoalDistance", 500}, {"GoalBearing", 90},
             {"RemoteSpeed", 50}, {"RemoteTurn", 30}});
  EXPECT_NEAR(command(*b, in, "Speed"), 55.0, 1e-9);
  EXPECT_NEAR(command(*b, in, "Jog"), 20.0, 1e-9);
  // Manual towards an obstacle 30 cm ahead: refused (STOP), no autonomous turn.
  in = with({{"Status", 0}, {"RemoteSpeed", 50}, {"RemoteTurn", 0}, {"ObstacleFront", 30}});
  EXPECT_NEAR(command(*b, in, "Speed"), 0.0, 1e-9);
  EXPECT_NEAR(command(*b, in, "Jog"), 0.0, 1e-9);
  // Manual backing away from it is allowed.
  in = with({{"Status", 0}, {"RemoteSpeed", -20}, {"RemoteTurn", 0}, {"ObstacleFront", 30}});
  EXPECT_NEAR(command(*b, in, "Speed"), -20.0, 1e-9);
  // ... but not into something 30 cm behind (REAR DANGER 1): STOP.
  in = with({{"Status", 0}, {"RemoteSpeed", -20}, {"RemoteTurn", 0}, {"ObstacleBack", 30}});
  EXPECT_NEAR(command(*b, in, "Speed"), 0.0, 1e-9);
  // 60 cm behind is past the danger shape (TOL 30 50 reads 0): back up.
  in = with({{"Status", 0}, {"RemoteSpeed", -20}, {"RemoteTurn", 0}, {"ObstacleBack", 60}});
  EXPECT_NEAR(command(*b, in, "Speed"), -20.0, 1e-9);
  // Forward with something close behind: unaffected.
  in = with({{"Status", 0}, {"RemoteSpeed", 50}, {"RemoteTurn", 0}, {"ObstacleBack", 30}});
  EXPECT_NEAR(command(*b, in, "Speed"), 55.0, 1e-9);
}

TEST(RobyLoop, SixPointRouteWithTwoUnmappedObstacles) {
  const auto r = run_roby_loop(route_options());
  EXPECT_EQ(r.route_points, 6u);
  EXPECT_TRUE(r.completed);
  EXPECT_EQ(r.reached, 6u);
  EXPECT_EQ(r.failed, 0u);
  EXPECT_GE(r.min_clearance, 0.3) << "nearest: " << r.nearest;
  EXPECT_LT(r.time, 200.0);
  EXPECT_LT(r.max_pose_error, 0.5);
  RecordProperty("sim_time", std::to_string(r.time));
  RecordProperty("min_clearance", std::to_string(r.min_clearance));
}
