// The search on hand-made maps: exact answers worked out by hand, the
// ambiguity report, agreement with exhaustive evaluation, the timeout.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_murea/localizer.h"
#include "mrt_sim/sensors.h"

using namespace mrt::murea;
using mrt::common::angle_diff;
using mrt::common::kPi;

namespace {

const double kHalfPi = kPi / 2;

FeatureMap load(const char* name) { return FeatureMap(mrt::sim::load_world(std::string(MRT_MUREA_DATA "/") + name)); }

Percept wall(double d, double b) { return {FeatureClass::Wall, "", d, b, 1.0}; }

// Within the plateau of maximal evidence around `p`: with the default
// tolerances (0.05 m + 3 % of the range for walls) every percept of the
// tests below still matches within 0.15 m and 6 degrees of the true pose.
void expect_near(const Pose2D& got, double x, double y, double theta) {
  EXPECT_NEAR(got.x, x, 0.15);
  EXPECT_NEAR(got.y, y, 0.15);
  EXPECT_NEAR(angle_diff(got.theta, theta), 0.0, mrt::common::deg_to_rad(6));
}

}  // namespace

// Corridor y in [-1, 1], closed by the wall x = 5. A robot at (3, 0)
// facing +x sees the end wall 2 m ahead, the side walls 1 m to its left
// and right, and the wall points (4, +-1) at sqrt(2) m, bearings +-45 deg:
// 5 percepts, all matched only near (3, 0, 0) -> evidence 5, unambiguous.
TEST(Search, CorridorWithItsEndIsUnique) {
  const FeatureMap map = load("corridor.yaml");
  const Localizer loc(map, SearchOptions{});
  const std::vector<Percept> ps{wall(2, 0), wall(1, kHalfPi), wall(1, -kHalfPi), wall(std::sqrt(2.0), kPi / 4),
                                wall(std::sqrt(2.0), -kPi / 4)};
  EXPECT_DOUBLE_EQ(loc.evidence(Pose2D(3, 0, 0), ps), 5.0);
  const Result r = loc.localize(ps);
  EXPECT_TRUE(r.complete);
  EXPECT_DOUBLE_EQ(r.best.evidence, 5.0);
  expect_near(r.best.pose, 3, 0, 0);
  EXPECT_FALSE(r.ambiguous);
  EXPECT_EQ(r.percepts, 5u);
  // The plateau of evidence 5: the end wall allows |x - 3| <= 0.11 (its
  // tolerance at 2 m) whatever y and theta; the side walls and the points
  // (4, +-1) are symmetric about y = 0 and theta = 0, so is the lattice:
  // the plateau's mean is (3, 0, 0) in y and theta. In x it is pushed up
  // by 2 (1 - cos theta) averaged over the plateau's headings (about
  // 0.005) and by where the 2.5 cm pixels' edges fall: within 3 cm.
  const Estimate& e = r.estimate;
  EXPECT_GT(e.poses, 10u);
  EXPECT_FALSE(e.truncated);
  EXPECT_NEAR(e.mean.x, 3.0, 0.03);
  EXPECT_NEAR(e.mean.y, 0.0, 0.01);
  EXPECT_NEAR(e.mean.theta, 0.0, mrt::common::deg_to_rad(0.5));
  // x spreads over about +-0.11 m: a variance near 0.11^2 / 3 = 0.004.
  EXPECT_GT(e.covariance[0], 0.002);
  EXPECT_LT(e.covariance[0], 0.006);
  EXPECT_DOUBLE_EQ(e.covariance[1], e.covariance[3]);  // symmetric
}

// Seeing only the side walls, every x along the corridor (facing +x or -x)
// has evidence 2: the result must say ambiguous, the runner-up more than
// 0.5 m away or turned more than 30 degrees, with the same evidence.
TEST(Search, CorridorWithoutItsEndIsAmbiguous) {
  const FeatureMap map = load("corridor.yaml");
  const Localizer loc(map, SearchOptions{});
  const Result r = loc.localize({wall(1, kHalfPi), wall(1, -kHalfPi)});
  EXPECT_DOUBLE_EQ(r.best.evidence, 2.0);
  EXPECT_NEAR(r.best.pose.y, 0.0, 0.1);
  ASSERT_TRUE(r.ambiguous);
  ASSERT_TRUE(r.alternative);
  EXPECT_DOUBLE_EQ(r.alternative->evidence, 2.0);
  const double dist = std::hypot(r.alternative->pose.x - r.best.pose.x, r.alternative->pose.y - r.best.pose.y);
  const double turn = std::abs(angle_diff(r.alternative->pose.theta, r.best.pose.theta));
  EXPECT_TRUE(dist > 0.5 || turn > mrt::common::deg_to_rad(30));
}

// Square room [-2, 2]^2, red landmark at (1.5, 1.5). Robot at (-1, 0)
// facing +y (theta = 90 deg): wall y = 2 ahead at 2 m, wall x = -2 on the
// left at 1 m, x = 2 on the right at 3 m, y = -2 behind at 2 m. The post,
// (2.5, 1.5) away in the world, is (1.5 forward, -2.5 left) in the robot
// frame: distance sqrt(8.5) = 2.91548, bearing atan2(-2.5, 1.5) = -1.03038.
// The walls alone fit the room turned by 90, 180, 270 degrees as well
// ((0, -1, 180), (1, 0, -90), (0, 1, 0)): ambiguous. The post breaks the
// tie: those three poses score 4, the true one 5.
TEST(Search, SquareRoomNeedsItsColouredPost) {
  const FeatureMap map = load("room.yaml");
  const Localizer loc(map, SearchOptions{});
  std::vector<Percept> ps{wall(2, 0), wall(1, kHalfPi), wall(3, -kHalfPi), wall(2, kPi)};
  const Result walls = loc.localize(ps);
  EXPECT_DOUBLE_EQ(walls.best.evidence, 4.0);
  EXPECT_TRUE(walls.ambiguous);
  ASSERT_TRUE(walls.alternative);
  EXPECT_DOUBLE_EQ(walls.alternative->evidence, 4.0);
  const Pose2D rotations[4] = {Pose2D(-1, 0, kHalfPi), Pose2D(0, -1, kPi), Pose2D(1, 0, -kHalfPi), Pose2D(0, 1, 0)};
  for (const Pose2D& p : rotations) EXPECT_DOUBLE_EQ(loc.evidence(p, ps), 4.0);

  ps.push_back({FeatureClass::Landmark, "red", std::sqrt(8.5), std::atan2(-2.5, 1.5), 1.0});
  const Result r = loc.localize(ps);
  EXPECT_DOUBLE_EQ(r.best.evidence, 5.0);
  expect_near(r.best.pose, -1, 0, kHalfPi);
  EXPECT_FALSE(r.ambiguous);
  for (int i = 1; i < 4; ++i) EXPECT_DOUBLE_EQ(loc.evidence(rotations[i], ps), 4.0);
  // A post of a colour the map lacks matches nothing: back to ambiguous.
  ps.back().color = "green";
  EXPECT_TRUE(loc.localize(ps).ambiguous);
}

// The MSL field is symmetric under the half turn about its centre: with
// line points and unnamed goals, the pose (x, y, theta) and its mirror
// (-x, -y, theta + 180) have the same evidence; the result must report
// both. Robot at (-3, 1.5, 0.4 rad); its mirror is (3, -1.5, 0.4 - pi).
// Naming the goal it sees (blue at (-9, 0): distance hypot(6, 1.5) =
// 6.18466, bearing atan2(-1.5, -6) - 0.4 + 2 pi = 2.98658) breaks the tie.
TEST(Search, SymmetricFieldIsAmbiguousUntilAGoalIsNamed) {
  mrt::sim::World w = mrt::sim::load_world(MRT_MUREA_DATA "/msl_field.yaml");
  w.movers.clear();
  const FeatureMap map(w);
  const Localizer loc(map, SearchOptions{});
  std::vector<Percept> ps;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, Pose2D(-3, 1.5, 0.4), mrt::sim::SensorsConfig{}))
    if (s.membership_class == "Line") ps.push_back({FeatureClass::Line, "", s.distance, s.bearing, 1.0});
  ASSERT_GT(ps.size(), 30u);
  const Result r = loc.localize(ps);
  ASSERT_TRUE(r.ambiguous);
  ASSERT_TRUE(r.alternative);
  EXPECT_DOUBLE_EQ(r.alternative->evidence, r.best.evidence);
  EXPECT_DOUBLE_EQ(r.best.evidence, static_cast<double>(ps.size()));
  const bool best_is_truth = std::abs(r.best.pose.x + 3) < 0.15;
  const Pose2D& truth = best_is_truth ? r.best.pose : r.alternative->pose;
  const Pose2D& mirror = best_is_truth ? r.alternative->pose : r.best.pose;
  expect_near(truth, -3, 1.5, 0.4);
  expect_near(mirror, 3, -1.5, 0.4 - kPi);

  ps.push_back({FeatureClass::Goal, "blue", std::hypot(6.0, 1.5), std::atan2(-1.5, -6.0) - 0.4 + 2 * kPi, 1.0});
  EXPECT_NEAR(ps.back().bearing, 2.98658, 1e-5);
  const Result named = loc.localize(ps);
  EXPECT_FALSE(named.ambiguous);
  expect_near(named.best.pose, -3, 1.5, 0.4);
}

// Tracking: a window around a predicted pose picks one of the room's four
// wall-only modes (see SquareRoomNeedsItsColouredPost): around (-1, 0, 90)
// +-0.5 m +-20 deg the answer is (-1, 0, 90), unambiguous (no other mode in
// the window); around (0, -1, 180) with headings 160 ... 200 deg (across
// +-180) it is (0, -1, 180). Exhaustive evaluation of the window agrees.
TEST(Search, WindowAroundAPredictedPose) {
  const FeatureMap map = load("room.yaml");
  const std::vector<Percept> ps{wall(2, 0), wall(1, kHalfPi), wall(3, -kHalfPi), wall(2, kPi),
                                wall(2.309401076758503, -kPi / 6), wall(1.1547005383792515, kPi / 3)};
  SearchOptions opt;
  opt.region = std::array<double, 4>{-1.5, -0.5, -0.5, 0.5};
  opt.heading_range = std::array<double, 2>{mrt::common::deg_to_rad(70), mrt::common::deg_to_rad(110)};
  const Localizer a(map, opt);
  EXPECT_EQ(a.nx() * a.ny() * a.nt(), 21u * 21u * 41u);
  const Result ra = a.localize(ps);
  EXPECT_DOUBLE_EQ(ra.best.evidence, 6.0);
  EXPECT_FALSE(ra.ambiguous);
  expect_near(ra.estimate.mean, -1, 0, kHalfPi);
  EXPECT_DOUBLE_EQ(a.exhaustive(ps).best.evidence, ra.best.evidence);

  opt.region = std::array<double, 4>{-0.5, -1.5, 0.5, -0.5};
  opt.heading_range = std::array<double, 2>{mrt::common::deg_to_rad(160), mrt::common::deg_to_rad(200)};
  const Localizer b(map, opt);
  const Result rb = b.localize(ps);
  EXPECT_DOUBLE_EQ(rb.best.evidence, 6.0);
  expect_near(rb.estimate.mean, 0, -1, kPi);
  EXPECT_LE(std::abs(rb.best.pose.theta), kPi);  // reported normalized
  EXPECT_DOUBLE_EQ(b.exhaustive(ps).best.evidence, rb.best.evidence);
}

// Exact: the search's best evidence equals the exhaustive maximum over the
// lattice (room at 10 cm / 3 degrees: 41 x 41 x 120 poses), noisy percepts.
TEST(Search, EqualsExhaustiveEvaluation) {
  const FeatureMap map = load("room.yaml");
  SearchOptions opt;
  opt.accuracy_xy = 0.1;
  opt.accuracy_theta = mrt::common::deg_to_rad(3);
  const Localizer loc(map, opt);
  EXPECT_EQ(loc.nx() * loc.ny() * loc.nt(), 41u * 41u * 120u);
  const std::vector<Percept> ps{wall(2.03, 0.02), wall(0.97, kHalfPi), wall(3.1, -kHalfPi - 0.03),
                                wall(1.95, kPi), wall(1.2, 0.7), {FeatureClass::Landmark, "", 2.9, -1.0, 0.5},
                                {FeatureClass::Wall, "", 0.7, 2.0, 0.3}};
  const Result s = loc.localize(ps), e = loc.exhaustive(ps);
  EXPECT_TRUE(s.complete);
  EXPECT_DOUBLE_EQ(s.best.evidence, e.best.evidence);
  EXPECT_DOUBLE_EQ(loc.evidence(s.best.pose, ps), s.best.evidence);
  EXPECT_LT(s.cells, e.cells / 10);  // and it is much cheaper
}

// Anytime: a timeout too short to finish still returns a pose, its true
// evidence, and says the search was cut short.
TEST(Search, TimeoutReturnsTheBestSoFar) {
  mrt::sim::World w = mrt::sim::load_world(MRT_MUREA_DATA "/msl_field.yaml");
  const FeatureMap map(w);
  SearchOptions opt;
  opt.timeout = 1e-7;
  const Localizer loc(map, opt);
  std::vector<Percept> ps;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, Pose2D(1, 2, 3), mrt::sim::SensorsConfig{}))
    if (s.membership_class == "Line") ps.push_back({FeatureClass::Line, "", s.distance, s.bearing, 1.0});
  const Result r = loc.localize(ps);
  EXPECT_FALSE(r.complete);
  EXPECT_DOUBLE_EQ(loc.evidence(r.best.pose, ps), r.best.evidence);
  EXPECT_LE(r.best.evidence, static_cast<double>(ps.size()));
}

// The same with the deadline in the thread's CPU time (timeout_cpu): cut
// short as well; a complete search reports its CPU time, which a single
// thread cannot spend faster than wall-clock time passes.
TEST(Search, CpuTimeoutReturnsTheBestSoFar) {
  mrt::sim::World w = mrt::sim::load_world(MRT_MUREA_DATA "/msl_field.yaml");
  const FeatureMap map(w);
  SearchOptions opt;
  opt.timeout = 1e-7;
  opt.timeout_cpu = true;
  std::vector<Percept> ps;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, Pose2D(1, 2, 3), mrt::sim::SensorsConfig{}))
    if (s.membership_class == "Line") ps.push_back({FeatureClass::Line, "", s.distance, s.bearing, 1.0});
  const Result r = Localizer(map, opt).localize(ps);
  EXPECT_FALSE(r.complete);
  EXPECT_DOUBLE_EQ(Localizer(map, opt).evidence(r.best.pose, ps), r.best.evidence);
  opt.timeout = 0.0;  // no deadline: complete
  const Result full = Localizer(map, opt).localize(ps);
  EXPECT_TRUE(full.complete);
  EXPECT_GT(full.cpu_ms, 0.0);
  EXPECT_LE(full.cpu_ms, full.time_ms + 0.01);
}

// Without usable percepts every pose has evidence 0: ambiguous; unusable
// percepts (non-finite, negative range, zero reliability) are ignored.
TEST(Search, NoUsablePercepts) {
  const FeatureMap map = load("room.yaml");
  const Localizer loc(map, SearchOptions{});
  const Result r = loc.localize({wall(NAN, 0), wall(-1, 0), {FeatureClass::Wall, "", 1, 0, 0.0}});
  EXPECT_EQ(r.percepts, 0u);
  EXPECT_DOUBLE_EQ(r.best.evidence, 0.0);
  EXPECT_TRUE(r.ambiguous);
}

TEST(Search, RejectsBadOptions) {
  const FeatureMap map = load("room.yaml");
  SearchOptions opt;
  opt.accuracy_xy = 0.0;
  EXPECT_THROW(Localizer(map, opt), std::invalid_argument);
  opt = SearchOptions{};
  opt.accuracy_theta = -1;
  EXPECT_THROW(Localizer(map, opt), std::invalid_argument);
  opt = SearchOptions{};
  opt.heading_range = std::array<double, 2>{0.0, 7.0};  // more than a turn
  EXPECT_THROW(Localizer(map, opt), std::invalid_argument);
  opt = SearchOptions{};
  opt.tolerance[0].base = -0.1;
  EXPECT_THROW(Localizer(map, opt), std::invalid_argument);
}
