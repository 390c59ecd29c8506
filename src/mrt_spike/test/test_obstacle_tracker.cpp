// spike_node's obstacle tracker, without ROS: tracks from percepts (ids,
// positions through the frame's pose, velocities between sightings,
// timeouts) and from MAP's world model (radius from the covariance,
// rotation, completeness), values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "mrt_spike/obstacle_tracker.h"

using namespace mrt::spike;
using mrt::common::PerceptObject;
using mrt::common::Pose2D;
namespace pc = mrt::common::percept_class;

namespace {

struct Call {
  int id;
  bool removed;
  double x, y, r, vx, vy;
};

// What the tracker writes, in order, and the obstacles as they stand.
struct RecordingSink : ObstacleSink {
  std::vector<Call> calls;
  std::map<int, Call> now;
  void set_obstacle(int id, double x, double y, double r, double vx, double vy) override {
    calls.push_back({id, false, x, y, r, vx, vy});
    now[id] = calls.back();
  }
  void remove_obstacle(int id) override {
    calls.push_back({id, true, 0, 0, 0, 0, 0});
    now.erase(id);
  }
};

PerceptObject at(const std::string& name, const std::string& cls, double x, double y) {
  PerceptObject o(name, cls);
  o.set_cartesian({x, y});
  return o;
}

WorldModelAnchor anchor(unsigned id, const std::string& cls, double x, double y, double vx = 0, double vy = 0,
                        double var = 0.01) {
  WorldModelAnchor a;
  a.id = id, a.membership_class = cls, a.x = x, a.y = y, a.vx = vx, a.vy = vy, a.var_x = a.var_y = var;
  return a;
}

const Pose2D kMap;  // the percept's frame is the map frame
const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(ObstacleTracker, VelocityBetweenTwoSightings) {
  RecordingSink sink;
  ObstacleTracker t({}, sink);
  // first sighting: default radius 0.25, no velocity yet
  EXPECT_EQ(t.add_percept("robot1", {at("visitor", pc::kPerson, 1.0, 2.0)}, kMap, 10.0), 0u);
  ASSERT_EQ(sink.calls.size(), 1u);
  EXPECT_EQ(sink.calls[0].id, 0);
  EXPECT_DOUBLE_EQ(sink.calls[0].x, 1.0);
  EXPECT_DOUBLE_EQ(sink.calls[0].y, 2.0);
  EXPECT_DOUBLE_EQ(sink.calls[0].r, 0.25);
  EXPECT_DOUBLE_EQ(sink.calls[0].vx, 0.0);
  // 0.5 s later 0.2 m further along x: 0.4 m/s; 0.3 m back along y: -0.6 m/s
  t.add_percept("robot1", {at("visitor", pc::kPerson, 1.2, 1.7)}, kMap, 10.5);
  ASSERT_EQ(sink.calls.size(), 2u);
  EXPECT_EQ(sink.calls[1].id, 0);  // the same track
  EXPECT_NEAR(sink.calls[1].vx, 0.4, 1e-12);
  EXPECT_NEAR(sink.calls[1].vy, -0.6, 1e-12);
  EXPECT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t.tracks().at("robot1/visitor").seen, 10.5);
  // 0.5 ms later (not more than 1 ms): no estimate, velocity 0
  t.add_percept("robot1", {at("visitor", pc::kPerson, 1.3, 1.7)}, kMap, 10.5005);
  EXPECT_DOUBLE_EQ(sink.calls[2].vx, 0.0);
  EXPECT_DOUBLE_EQ(sink.calls[2].vy, 0.0);
}

TEST(ObstacleTracker, GivenVelocityAndRadiusAreTakenAsTheyAre) {
  RecordingSink sink;
  ObstacleTracker t({}, sink);
  t.add_percept("robot1", {at("r2", pc::kOpponent, 0.0, 0.0)}, kMap, 1.0);
  PerceptObject o = at("r2", pc::kOpponent, 1.0, 0.0);
  o.set("vx", 0.3).set("vy", -0.1).set("radius", 0.4);
  t.add_percept("robot1", {o}, kMap, 2.0);  // moved 1 m in 1 s, but says 0.3, -0.1
  EXPECT_DOUBLE_EQ(sink.calls[1].vx, 0.3);
  EXPECT_DOUBLE_EQ(sink.calls[1].vy, -0.1);
  EXPECT_DOUBLE_EQ(sink.calls[1].r, 0.4);
  // only vx: both estimated from the sightings, (2 - 1) / 0.5 = 2 m/s and 0
  PerceptObject p = at("r2", pc::kOpponent, 2.0, 0.0);
  p.set("vx", 5.0);
  t.add_percept("robot1", {p}, kMap, 2.5);
  EXPECT_NEAR(sink.calls[2].vx, 2.0, 1e-12);
  EXPECT_NEAR(sink.calls[2].vy, 0.0, 1e-12);
}

TEST(ObstacleTracker, PositionsThroughTheFramesPoseInEitherForm) {
  RecordingSink sink;
  ObstacleTracker t({}, sink);
  // the percept's frame at (2, 1) in the map, turned 90 degrees: its x axis
  // is the map's y axis. Polar (2 m, bearing 0) is (2, 0) there: (2, 3) in
  // the map. Cartesian (1, 0.5) there: (2 - 0.5, 1 + 1) = (1.5, 2).
  const Pose2D frame(2.0, 1.0, M_PI / 2);
  PerceptObject polar("p", pc::kPerson);
  polar.set("distance", 2.0).set("bearing", 0.0);
  EXPECT_EQ(t.add_percept("robot1", {polar, at("q", pc::kPerson, 1.0, 0.5)}, frame, 1.0), 0u);
  ASSERT_EQ(sink.calls.size(), 2u);
  EXPECT_NEAR(sink.calls[0].x, 2.0, 1e-12);
  EXPECT_NEAR(sink.calls[0].y, 3.0, 1e-12);
  EXPECT_NEAR(sink.calls[1].x, 1.5, 1e-12);
  EXPECT_NEAR(sink.calls[1].y, 2.0, 1e-12);
  EXPECT_EQ(sink.calls[1].id, 1);  // a second name: a second track
}

TEST(ObstacleTracker, ClassesAndDroppedObjects) {
  RecordingSink sink;
  ObstacleTracker t({}, sink);
  // a ball is not an obstacle class by default: ignored, not dropped; a
  // person with a non-finite or no position: dropped
  PerceptObject nopos("n", pc::kPerson);
  EXPECT_EQ(t.add_percept("robot1", {at("ball", pc::kBall, 1, 1), at("x", pc::kPerson, kNaN, 1), nopos}, kMap, 1.0),
            2u);
  EXPECT_TRUE(sink.calls.empty());
  EXPECT_EQ(t.dropped(), 2u);
  EXPECT_FALSE(t.take_changed());
  // with Ball among the classes, the ball is one
  ObstacleTrackerOptions o;
  o.classes = {pc::kBall};
  ObstacleTracker balls(o, sink);
  balls.add_percept("robot1", {at("ball", pc::kBall, 1, 1), at("v", pc::kPerson, 2, 2)}, kMap, 1.0);
  EXPECT_EQ(balls.size(), 1u);
  EXPECT_EQ(balls.tracks().count("robot1/ball"), 1u);
}

TEST(ObstacleTracker, ForgottenAfterTheTimeoutIdsNotReused) {
  RecordingSink sink;
  ObstacleTrackerOptions o;
  o.timeout = 1.0;
  ObstacleTracker t(o, sink);
  t.add_percept("robot1", {at("a", pc::kPerson, 1, 1)}, kMap, 10.0);
  t.add_percept("robot2", {at("a", pc::kPerson, 5, 5)}, kMap, 10.5);  // another robot's "a": another track
  EXPECT_EQ(t.size(), 2u);
  EXPECT_TRUE(t.take_changed());
  EXPECT_FALSE(t.take_changed());
  EXPECT_EQ(t.expire(11.0), 0u);  // 1.0 s after: not more than the timeout
  EXPECT_FALSE(t.take_changed());
  EXPECT_EQ(t.expire(11.2), 1u);  // robot1/a, 1.2 s: removed; robot2/a, 0.7 s: kept
  EXPECT_TRUE(t.take_changed());
  ASSERT_EQ(sink.calls.back().id, 0);
  EXPECT_TRUE(sink.calls.back().removed);
  EXPECT_EQ(t.tracks().count("robot2/a"), 1u);
  // seen again: a new track with a new id (2), no velocity from the old one
  t.add_percept("robot1", {at("a", pc::kPerson, 3, 1)}, kMap, 12.0);
  EXPECT_EQ(sink.calls.back().id, 2);
  EXPECT_DOUBLE_EQ(sink.calls.back().vx, 0.0);
  EXPECT_EQ(t.expire(20.0), 2u);
  EXPECT_TRUE(sink.now.empty());
}

TEST(ObstacleTracker, WorldModelAnchors) {
  RecordingSink sink;
  ObstacleTracker t({}, sink);
  // (rostest's opponent) at (23, 12) coming at 2 m/s, variance 0.01 m^2:
  // radius 0.25 + 1 x 0.1 = 0.35; a tentative anchor and a ball are ignored
  WorldModelAnchor tentative = anchor(2, pc::kOpponent, 25.5, 10.5);
  tentative.tentative = true;
  EXPECT_EQ(t.add_world_model("robot1", {anchor(1, pc::kOpponent, 23, 12, 0, -2), tentative,
                                         anchor(3, pc::kBall, 20.5, 10.5)},
                              kMap, 5.0),
            0u);
  ASSERT_EQ(sink.calls.size(), 1u);
  EXPECT_DOUBLE_EQ(sink.calls[0].x, 23.0);
  EXPECT_DOUBLE_EQ(sink.calls[0].y, 12.0);
  EXPECT_NEAR(sink.calls[0].r, 0.35, 1e-12);
  EXPECT_DOUBLE_EQ(sink.calls[0].vx, 0.0);
  EXPECT_DOUBLE_EQ(sink.calls[0].vy, -2.0);
  EXPECT_EQ(t.tracks().count("world_model:robot1/1"), 1u);
}

TEST(ObstacleTracker, WorldModelRotationRadiusAndVelocity) {
  RecordingSink sink;
  ObstacleTrackerOptions o;
  o.anchor_sigmas = 2.0;
  ObstacleTracker t(o, sink);
  // the model's frame at (1, 0) turned 90 degrees: (1, 0) there is (1, 1)
  // in the map, velocity (1, 0) is (0, 1). Variances 0.04 and 0.09: the
  // larger, sigma 0.3, twice: radius 0.25 + 0.6 = 0.85.
  WorldModelAnchor a = anchor(4, pc::kRobot, 1, 0, 1, 0);
  a.var_x = 0.04, a.var_y = 0.09;
  t.add_world_model("robot2", {a}, Pose2D(1.0, 0.0, M_PI / 2), 1.0);
  EXPECT_NEAR(sink.calls[0].x, 1.0, 1e-12);
  EXPECT_NEAR(sink.calls[0].y, 1.0, 1e-12);
  EXPECT_NEAR(sink.calls[0].vx, 0.0, 1e-12);
  EXPECT_NEAR(sink.calls[0].vy, 1.0, 1e-12);
  EXPECT_NEAR(sink.calls[0].r, 0.85, 1e-12);
  // moved 1 m in 1 s with no finite velocity and no variance: velocity 0
  // (an anchor's velocity is never estimated), radius the default
  WorldModelAnchor b = anchor(4, pc::kRobot, 2, 0, kNaN, kNaN, kNaN);
  t.add_world_model("robot2", {b}, kMap, 2.0);
  EXPECT_DOUBLE_EQ(sink.calls[1].vx, 0.0);
  EXPECT_DOUBLE_EQ(sink.calls[1].vy, 0.0);
  EXPECT_DOUBLE_EQ(sink.calls[1].r, 0.25);
  EXPECT_EQ(sink.calls[1].id, sink.calls[0].id);
  // without a finite position: dropped, the track removed (the model is complete)
  EXPECT_EQ(t.add_world_model("robot2", {anchor(4, pc::kRobot, kNaN, 0)}, kMap, 3.0), 1u);
  EXPECT_EQ(t.dropped(), 1u);
  EXPECT_EQ(t.size(), 0u);
}

TEST(ObstacleTracker, WorldModelIsCompleteAndCoexistsWithPercepts) {
  RecordingSink sink;
  ObstacleTracker t({}, sink);
  // the same person seen by the camera and in two producers' models: three
  // obstacles (ids 0, 1, 2)
  t.add_percept("robot1", {at("visitor", pc::kPerson, 4, 4)}, kMap, 1.0);
  t.add_world_model("robot1", {anchor(7, pc::kPerson, 4.1, 4)}, kMap, 1.0);
  t.add_world_model("robot10", {anchor(7, pc::kPerson, 4.2, 4)}, kMap, 1.0);
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(sink.now.size(), 3u);
  // robot1's next model without anchor 7: only that track goes (not the
  // percept's, not robot10's, whose key shares the prefix "world_model:robot1")
  t.take_changed();
  t.add_world_model("robot1", {}, kMap, 1.5);
  EXPECT_TRUE(t.take_changed());
  EXPECT_EQ(t.size(), 2u);
  EXPECT_TRUE(sink.calls.back().removed);
  EXPECT_EQ(sink.calls.back().id, 1);
  EXPECT_EQ(t.tracks().count("robot1/visitor"), 1u);
  EXPECT_EQ(t.tracks().count("world_model:robot10/7"), 1u);
  // anchors time out like percepts (their model's stamp is their sighting)
  EXPECT_EQ(t.expire(2.01), 2u);
}
