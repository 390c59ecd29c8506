// Realistic percepts: statistics of misses, false positives and
// distance-dependent noise against the numbers they are configured with.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

using namespace mrt::sim;

namespace {

SensorsConfig config() {
  SensorsConfig c;
  c.vision_realistic = true;
  c.vision_range = 6.0;
  c.vision_distance_noise = 0.02;
  c.vision_bearing_noise = 0.01;
  c.vision_miss_near = 0.1;
  c.vision_miss_far = 0.5;
  c.vision_false_positives = 0.0;
  return c;
}

}  // namespace

TEST(RealisticPercepts, MissesAndNoiseGrowWithDistance) {
  const SensorsConfig c = config();
  const std::vector<SeenObject> ideal = {{"ball", "Ball", "orange", 3.0, 0.5}};
  std::mt19937_64 rng(11);
  const int frames = 4000;
  int seen = 0;
  double sum = 0, sum2 = 0, bsum2 = 0;
  for (int k = 0; k < frames; ++k) {
    for (const SeenObject& o : realistic_percepts(ideal, c, rng)) {
      ASSERT_EQ(o.name, "");  // class and colour only
      ASSERT_EQ(o.membership_class, "Ball");
      ASSERT_EQ(o.color, "orange");
      ++seen;
      sum += o.distance;
      sum2 += (o.distance - 3.0) * (o.distance - 3.0);
      bsum2 += (o.bearing - 0.5) * (o.bearing - 0.5);
    }
  }
  // Miss probability at 3 m of a 6 m range: 0.1 + 0.4 * 0.5 = 0.3, so 2800
  // of 4000 seen (binomial sigma 29; bound 100 = 3.4 sigma).
  EXPECT_NEAR(seen, 2800, 100);
  // Distance sigma 0.02 * 3 * (1 + 0.5) = 0.09 m, unbiased; bearing 0.01.
  EXPECT_NEAR(sum / seen, 3.0, 0.01);
  EXPECT_NEAR(std::sqrt(sum2 / seen), 0.09, 0.009);
  EXPECT_NEAR(std::sqrt(bsum2 / seen), 0.01, 0.001);
  // Near the robot almost nothing is missed (0.1 + 0.4 * 0.5 / 6 = 0.133).
  const std::vector<SeenObject> near = {{"p", "GoalPost", "yellow", 0.5, 0.0}};
  int seen_near = 0;
  for (int k = 0; k < frames; ++k) seen_near += static_cast<int>(realistic_percepts(near, c, rng).size());
  EXPECT_NEAR(seen_near, 4000 * (1 - 0.1 - 0.4 * 0.5 / 6), 100);
}

TEST(RealisticPercepts, FalsePositivesArePoisson) {
  SensorsConfig c = config();
  c.vision_false_positives = 0.5;
  std::mt19937_64 rng(5);
  const int frames = 4000;
  int total = 0, empty = 0;
  for (int k = 0; k < frames; ++k) {
    const auto v = realistic_percepts({}, c, rng);
    total += static_cast<int>(v.size());
    empty += v.empty();
    for (const SeenObject& o : v) {
      EXPECT_EQ(o.name, "");
      EXPECT_GE(o.distance, 0.5);
      EXPECT_LE(o.distance, 6.0);
    }
  }
  // Poisson mean 0.5: 2000 in total (sigma sqrt(2000) = 45), and
  // P(none) = exp(-0.5) = 0.6065 of the frames (sigma 31).
  EXPECT_NEAR(total, 2000, 150);
  EXPECT_NEAR(empty, 4000 * std::exp(-0.5), 100);
}

TEST(RealisticPercepts, WorldFileSelectsTheModel) {
  const std::string head =
      "name: t\nbounds: [-5, -5, 5, 5]\nrobots:\n  - name: r\n    base: ianus3\n    pose: [0, 0, 0]\n"
      "    sensors:\n      vision: ";
  EXPECT_FALSE(parse_world(head + "{rate: 10}\n", "v.yaml", "").robots[0].sensors.vision_realistic);
  const World w = parse_world(head + "{model: realistic, miss_far: 0.4, false_positives: 1}\n", "v.yaml", "");
  EXPECT_TRUE(w.robots[0].sensors.vision_realistic);
  EXPECT_EQ(w.robots[0].sensors.vision_miss_far, 0.4);
  EXPECT_EQ(w.robots[0].sensors.vision_false_positives, 1.0);
  try {
    parse_world(head + "{model: perfect}\n", "v.yaml", "");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    // line 8, column 23: "      vision: {model: " is 22 characters
    EXPECT_STREQ(e.what(), "v.yaml:8:23: expected 'model' ideal or realistic, got 'perfect'");
  }
}
