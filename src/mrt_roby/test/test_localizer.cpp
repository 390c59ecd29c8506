// The DGPS localizer's projection and wheel kinematics, and who owns which
// crisp datum, with numbers worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "mrt_roby/crisp_builder.h"
#include "mrt_roby/dgps_localizer.h"

using namespace mrt::roby;
using mrt::common::GeoPoint;
using mrt::common::Pose2D;

TEST(DgpsLocalizer, ProjectsTheFixOnThePlaneAroundTheDatum) {
  // Datum (45, 9) deg, fix 0.001 deg north and east of it:
  //   y = 0.001 * pi / 180 * 6378137          = 111.319491 m
  //   x = y * cos(45 deg) = 111.319491 * 0.7071068 = 78.714767 m
  // With position_gain 1 the pose moves onto the fix.
  DgpsLocalizerOptions o;
  o.datum = {45.0, 9.0};
  o.position_gain = 1.0;
  DgpsLocalizer l(Pose2D(0, 0, 0), o);
  l.correct(GeoPoint{45.001, 9.001});
  EXPECT_NEAR(l.pose().x, 78.714767, 1e-6);
  EXPECT_NEAR(l.pose().y, 111.319491, 1e-6);
  // The datum itself is the origin; with the default gain 0.5 the pose
  // goes half way back from (78.71, 111.32) to it.
  l = DgpsLocalizer(Pose2D(78.714767, 111.319491, 0), DgpsLocalizerOptions{0.5, 0.3, 0.4, 0.1, {45.0, 9.0}});
  l.correct(GeoPoint{45.0, 9.0});
  EXPECT_NEAR(l.pose().x, 39.357383, 1e-6);
  EXPECT_NEAR(l.pose().y, 55.659746, 1e-6);
  EXPECT_EQ(l.fixes(), 1);
}

TEST(DgpsLocalizer, IntegratesWheelSpeedsBetweenStamps) {
  // r = 0.1 m, track 0.5 m; left 2 rad/s, right 4 rad/s:
  //   vx = 0.1 * (2 + 4) / 2 = 0.3 m/s, omega = 0.1 * (4 - 2) / 0.5 = 0.4 rad/s.
  // Over 0.5 s on the exact arc (radius vx / omega = 0.75 m, turn 0.2 rad):
  //   x = 0.75 sin 0.2 = 0.149002, y = 0.75 (1 - cos 0.2) = 0.014950.
  DgpsLocalizerOptions o;
  o.wheel_radius = 0.1;
  o.track = 0.5;
  DgpsLocalizer l(Pose2D(0, 0, 0), o);
  l.wheel_state(2.0, 4.0, 10.0);  // the first only starts the clock
  EXPECT_EQ(l.pose().x, 0.0);
  EXPECT_EQ(l.twist().vx, 0.0);
  l.wheel_state(2.0, 4.0, 10.5);
  EXPECT_NEAR(l.twist().vx, 0.3, 1e-12);
  EXPECT_NEAR(l.twist().omega, 0.4, 1e-12);
  EXPECT_NEAR(l.pose().x, 0.149002, 1e-6);
  EXPECT_NEAR(l.pose().y, 0.014950, 1e-6);
  EXPECT_NEAR(l.pose().theta, 0.2, 1e-12);
  // An older stamp integrates nothing.
  l.wheel_state(5.0, 5.0, 10.4);
  EXPECT_NEAR(l.pose().x, 0.149002, 1e-6);
  EXPECT_NEAR(l.twist().vx, 0.3, 1e-12);
  // Straight on at 0.1 * 5 = 0.5 m/s for 1 s from 10.4: 0.5 m along 0.2 rad
  //   dx = 0.5 cos 0.2 = 0.490033, dy = 0.5 sin 0.2 = 0.099335.
  l.wheel_state(5.0, 5.0, 11.4);
  EXPECT_NEAR(l.pose().x, 0.149002 + 0.490033, 1e-6);
  EXPECT_NEAR(l.pose().y, 0.014950 + 0.099335, 1e-6);
}

// The pose covariance reflects the fix quality. Gain g = 0.5, fixes of
// variance R: var' = 0.25 var + 0.25 R. From the initial 1 m^2:
//   DGPS (GBAS, no covariance given: sigma 0.3 m, R = 0.09):
//     0.25 + 0.0225 = 0.2725, then 0.068125 + 0.0225 = 0.090625;
//     the fixed point is R / 3 = 0.03.
//   an autonomous fix (sigma 3 m, R = 9) from 0.03: 0.0075 + 2.25 = 2.2575.
//   a fix with its own covariance (east 4, north 1): R = max = 4.
// Driving 2 m straight adds 0.01 m^2 per m: + 0.02.
TEST(DgpsLocalizer, CovarianceReflectsTheFixQuality) {
  DgpsLocalizer l(Pose2D(0, 0, 0));
  EXPECT_DOUBLE_EQ(l.covariance()[0], 1.0);
  const double gbas = l.fix_variance(2, false, 0, 0);
  EXPECT_DOUBLE_EQ(gbas, 0.09);
  l.correct(0, 0, gbas);
  EXPECT_NEAR(l.covariance()[0], 0.2725, 1e-12);
  l.correct(0, 0, gbas);
  EXPECT_NEAR(l.covariance()[0], 0.090625, 1e-12);
  EXPECT_EQ(l.covariance()[4], l.covariance()[0]);
  for (int i = 0; i < 40; ++i) l.correct(0, 0, gbas);
  EXPECT_NEAR(l.covariance()[0], 0.03, 1e-9);
  l.correct(0, 0, l.fix_variance(0, false, 0, 0));
  EXPECT_NEAR(l.covariance()[0], 0.0075 + 2.25, 1e-9);
  EXPECT_DOUBLE_EQ(l.fix_variance(1, false, 0, 0), 1.0);
  EXPECT_DOUBLE_EQ(l.fix_variance(2, true, 4.0, 1.0), 4.0);
  EXPECT_LT(l.fix_variance(-1, false, 0, 0), 0.0);
  const double before = l.covariance()[0];
  l.predict(1.0, 0.0, 2.0);
  EXPECT_NEAR(l.covariance()[0], before + 0.02, 1e-12);
  EXPECT_GT(l.covariance()[8], 0.0);
}

TEST(DgpsLocalizer, OptionsValidate) {
  DgpsLocalizerOptions o;
  EXPECT_NO_THROW(o.validate());
  o.datum.latitude = 90.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.track = 0.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.wheel_radius = NAN;
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

TEST(CrispBuilder, EachDatumHasOneOwner) {
  // The four owners' data are disjoint and together make build_crisp().
  CrispInputs in;
  in.goal = GoalCrisp{100.0, 10.0};
  in.sector_names = {"ObstacleFront", "ObstacleFrontLeft", "ObstacleFrontRight", "ObstacleLeft", "ObstacleRight",
                     "ObstacleBack"};
  in.sector_distances = {1, 2, 3, 4, 5, 6};
  in.remote = RemoteCommand{0.2, 0.0};
  CrispDataList goal, remote, sonar, feedback;
  goal_crisp_data(in.mode, in.goal, goal);
  remote_crisp_data(in.remote, remote);
  sonar_crisp_data(in.sector_names, in.sector_distances, sonar);
  feedback_crisp_data(20.0, -5.0, feedback);
  EXPECT_EQ(goal.size(), 4u);      // Status, HaveGoal, GoalDistance, GoalBearing
  EXPECT_EQ(remote.size(), 2u);    // RemoteSpeed, RemoteTurn
  EXPECT_EQ(sonar.size(), 7u);     // six sectors, FreeSide
  EXPECT_EQ(feedback.size(), 2u);  // LastSpeed, LastJog
  std::set<std::string> names;
  for (const auto* part : {&goal, &remote, &sonar, &feedback})
    for (const auto& c : *part) EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
  in.last_speed_cm = 20.0;
  in.last_jog_deg = -5.0;
  const CrispDataList all = build_crisp(in);
  ASSERT_EQ(all.size(), names.size());
  for (const auto& c : all) EXPECT_EQ(names.count(c.name), 1u) << c.name;
  // Without a goal the sequencer's part is Status and HaveGoal 0 only.
  goal.clear();
  goal_crisp_data(Mode::kAuto, std::nullopt, goal);
  ASSERT_EQ(goal.size(), 2u);
  EXPECT_EQ(goal[0].name, "Status");
  EXPECT_EQ(goal[0].value, 1.0);
  EXPECT_EQ(goal[1].name, "HaveGoal");
  EXPECT_EQ(goal[1].value, 0.0);
}
