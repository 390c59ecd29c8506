// The evidence bound property the exactness of the search rests on: a
// cell's bound is at least the evidence of any of its sub-cells (the most
// evidence of the sub-cell's lattice poses, found here by evaluating them
// all), at least the evidence of any pose of the continuous box spanned by
// its lattice poses, and a leaf's bound is its pose's evidence.
#include <gtest/gtest.h>

#include <random>

#include "mrt_common/angle.h"
#include "mrt_murea/localizer.h"
#include "mrt_sim/sensors.h"

using namespace mrt::murea;

namespace {

// Random percepts: what the simulator sees at `pose` (all classes), with
// noise and random extra percepts of every class, so cells see hits and misses.
std::vector<Percept> percepts_at(const mrt::sim::World& w, const Pose2D& pose, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.05);
  std::uniform_real_distribution<double> r(0.0, 6.0), b(-3.2, 3.2), rel(0.1, 1.0);
  std::vector<Percept> out;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, pose, mrt::sim::SensorsConfig{})) {
    const auto c = parse_feature_class(s.membership_class);
    if (c) out.push_back({*c, s.color, std::max(0.0, s.distance + noise(rng)), s.bearing + noise(rng), rel(rng)});
  }
  for (int i = 0; i < 10; ++i)
    out.push_back({static_cast<FeatureClass>(i % kFeatureClassCount), i % 2 ? "" : "yellow", r(rng), b(rng), rel(rng)});
  return out;
}

std::uint32_t pick(std::mt19937& rng, std::uint32_t lo, std::uint32_t hi) {
  return std::uniform_int_distribution<std::uint32_t>(lo, hi)(rng);
}

// A random non-empty sub-range [a, b) of [lo, hi).
void sub_range(std::mt19937& rng, std::uint32_t lo, std::uint32_t hi, std::uint32_t* a, std::uint32_t* b) {
  *a = pick(rng, lo, hi - 1);
  *b = pick(rng, *a + 1, hi);
}

std::uint64_t volume(const Cell& c) {
  return static_cast<std::uint64_t>(c.x1 - c.x0) * (c.y1 - c.y0) * (c.t1 - c.t0);
}

// The evidence of a cell by brute force: the most of its lattice poses'.
double cell_evidence(const Localizer& loc, const Cell& c, const std::vector<Percept>& ps) {
  double best = 0.0;
  for (std::uint32_t i = c.x0; i < c.x1; ++i)
    for (std::uint32_t j = c.y0; j < c.y1; ++j)
      for (std::uint32_t k = c.t0; k < c.t1; ++k) best = std::max(best, loc.evidence(loc.lattice_pose(i, j, k), ps));
  return best;
}

Cell random_sub_cell(std::mt19937& rng, const Cell& c) {
  Cell s{};
  sub_range(rng, c.x0, c.x1, &s.x0, &s.x1);
  sub_range(rng, c.y0, c.y1, &s.y0, &s.y1);
  sub_range(rng, c.t0, c.t1, &s.t0, &s.t1);
  return s;
}

class BoundProperty : public ::testing::TestWithParam<const char*> {};

}  // namespace

TEST_P(BoundProperty, BoundNeverBelowAnySubCellOrPose) {
  const mrt::sim::World w = mrt::sim::load_world(std::string(MRT_MUREA_DATA "/") + GetParam());
  const FeatureMap map(w);
  SearchOptions opt;
  opt.accuracy_xy = 0.1;
  opt.accuracy_theta = mrt::common::deg_to_rad(2);
  const Localizer loc(map, opt);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(w.min_x, w.max_x), uy(w.min_y, w.max_y), u01(0.0, 1.0);
  int checks = 0, strict = 0;
  for (int frame = 0; frame < 4; ++frame) {
    const std::vector<Percept> ps = percepts_at(w, Pose2D(ux(rng), uy(rng), 6.0 * u01(rng)), rng);
    for (int n = 0; n < 60; ++n) {
      // Cells of all sizes: a random descent from the root.
      Cell cell = loc.root();
      for (int d = pick(rng, 0, 6); d > 0; --d) cell = random_sub_cell(rng, cell);
      const double b = loc.bound(cell, ps);
      for (int k = 0; k < 8; ++k) {
        Cell sub = random_sub_cell(rng, cell);
        while (volume(sub) > 64) sub = random_sub_cell(rng, sub);
        const double se = cell_evidence(loc, sub, ps);
        EXPECT_GE(b, se);
        strict += b > se ? 1 : 0;
        const Cell leaf{pick(rng, cell.x0, cell.x1 - 1), 0, pick(rng, cell.y0, cell.y1 - 1), 0,
                        pick(rng, cell.t0, cell.t1 - 1), 0};
        const Pose2D p = loc.lattice_pose(leaf.x0, leaf.y0, leaf.t0);
        const double e = loc.evidence(p, ps);
        EXPECT_GE(b, e - 1e-12);
        EXPECT_DOUBLE_EQ(loc.bound({leaf.x0, leaf.x0 + 1, leaf.y0, leaf.y0 + 1, leaf.t0, leaf.t0 + 1}, ps), e);
        // Any pose of the cell's box, not only lattice poses.
        double cx, cy, ct, hx, hy, ht;
        loc.cell_geometry(cell, &cx, &cy, &ct, &hx, &hy, &ht);
        const Pose2D q(cx + hx * (2 * u01(rng) - 1), cy + hy * (2 * u01(rng) - 1), ct + ht * (2 * u01(rng) - 1));
        EXPECT_GE(b, loc.evidence(q, ps) - 1e-12);
        checks += 3;
      }
    }
  }
  EXPECT_EQ(checks, 4 * 60 * 8 * 3);
  EXPECT_GT(strict, 100);  // the property is not met trivially by equal values
}

INSTANTIATE_TEST_SUITE_P(Maps, BoundProperty, ::testing::Values("msl_field.yaml", "room.yaml", "corridor.yaml"));
