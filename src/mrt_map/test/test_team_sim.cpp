// map_bench's world (bench/team_sim.*): the team-play scenario's
// goalkeepers, solid robots, and the camera model's detection fall-off and
// noise law.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "team_sim.h"

using namespace mrt::map;
using mrt::map::bench::CameraModel;
using mrt::map::bench::TeamSim;

TEST(TeamSim, GoalkeepersKeepTheirGoals) {
  // set_goals: the first robot of each team aims at x = side * 8.3 + 0.2 *
  // offset (offset in [-1, 1]): [-8.5, -8.1] for the team, [8.1, 8.5] for
  // the opponents, and y = clamp(0.4 * ball y, -1.2, 1.2). Allowed lag
  // 0.15 m in x, 0.3 m in y (the target moves with the ball).
  TeamSim sim(3, true);
  const double dt = 1.0 / 30.0;
  for (int k = 0; k < 600; ++k) sim.step(dt);  // 20 s to take position (up to 17 m at 1.5 m/s)
  for (int k = 0; k < 1500; ++k) {             // then 50 s
    sim.step(dt);
    const Vec2& own = sim.mates()[0].p;
    const Vec2& their = sim.opponents()[0].p;
    ASSERT_GE(own.x(), -8.65) << k;
    ASSERT_LE(own.x(), -7.95) << k;
    ASSERT_GE(their.x(), 7.95) << k;
    ASSERT_LE(their.x(), 8.65) << k;
    ASSERT_LE(std::fabs(own.y()), 1.5) << k;
    ASSERT_LE(std::fabs(their.y()), 1.5) << k;
  }
  // On random waypoints (the first scenario) nobody keeps a goal: over the
  // same minute the first robot leaves the band |x| >= 7.95.
  TeamSim random(3, false);
  bool left = false;
  for (int k = 0; k < 1800; ++k) {
    random.step(dt);
    left = left || std::fabs(random.mates()[0].p.x()) < 7.95;
  }
  EXPECT_TRUE(left);
}

TEST(TeamSim, RobotsDoNotDriveThroughEachOther) {
  // Both teams' chasers drive to the ball (to touch it) and meet there; on
  // random waypoints robots cross. Robots are discs of 0.25 m: after every
  // step no two centres are closer than 0.5 m (a push may leave a third
  // robot a little inside, so 0.45 m); without the separation the closest
  // centres came 0 m (team play) and 0.009 m (random waypoints) apart.
  const double dt = 1.0 / 30.0;
  for (const bool team_play : {true, false}) {
    TeamSim sim(5, team_play);
    double closest = 1e9;
    int contacts = 0;  // steps with two robots touching (within 0.51 m)
    for (int k = 0; k < 9000; ++k) {  // 5 minutes
      sim.step(dt);
      std::vector<Vec2> all;
      for (const auto& b : sim.mates()) all.push_back(b.p);
      for (const auto& b : sim.opponents()) all.push_back(b.p);
      bool touching = false;
      for (std::size_t i = 0; i < all.size(); ++i)
        for (std::size_t j = i + 1; j < all.size(); ++j) {
          const double d = (all[i] - all[j]).norm();
          closest = std::min(closest, d);
          touching = touching || d < 0.51;
        }
      contacts += touching;
    }
    EXPECT_GE(closest, 0.45) << team_play;
    EXPECT_GT(contacts, 10) << team_play;  // the test means something: robots do meet
  }
}

TEST(TeamSim, CameraDetectionFallOffAndNoise) {
  // p_detect 1 at the robot, 0 at range 8: p(d) = 1 - d / 8. sigma_d =
  // 0.005 + 0.01 d + 0.001 d^2 (e.g. d = 4: 0.005 + 0.04 + 0.016 = 0.061).
  // Over many frames, the ball detections of robot 0 (no clutter) number
  // sum over in-view frames of (1 - d / 8), within 4 binomial sigmas.
  CameraModel cam;
  cam.range = 8.0;
  cam.p_detect = 1.0;
  cam.p_detect_far = 0.0;
  cam.sigma_d_quad = 0.001;
  cam.clutter_rate = 0.0;
  TeamSim sim(5, true);
  double expected = 0.0, variance = 0.0;
  long detected = 0;
  for (int k = 0; k < 6000; ++k) {
    sim.step(1.0 / 30.0);
    const double d = (sim.ball().p - sim.mates()[0].p).norm();
    const bool in_view = sim.ball_in_view(0, cam);
    if (in_view) {
      const double p = 1.0 - d / 8.0;
      expected += p;
      variance += p * (1.0 - p);
    }
    RobotPose pose;
    for (const PerceptObject& o : sim.see(0, cam, pose)) {
      if (o.membership_class != "Ball") continue;
      ASSERT_TRUE(in_view);
      ++detected;
      EXPECT_NEAR(o.find("distance")->variability, 0.005 + 0.01 * d + 0.001 * d * d, 1e-12);
    }
  }
  ASSERT_GT(expected, 500.0);  // the test means something
  EXPECT_NEAR(static_cast<double>(detected), expected, 4.0 * std::sqrt(variance));
}
