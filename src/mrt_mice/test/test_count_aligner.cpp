// The two mice on their own USB clocks: 125 Hz polling (8 ms frames) with a
// phase skew of up to one frame and 100 ppm of drift between the two. The
// robot drives with a varying twist (vx = 0.4 + 0.2 sin 1.3t m/s,
// omega = 0.8 sin 0.5t rad/s) for 10 s; each mouse reports, at its polls,
// the whole counts it has gathered (nothing when it has none). The node
// samples at 50 Hz.
//
// Summing "the reports since the last sample" gives windows of 2 or 3
// reports (16 or 24 ms) for one mouse while the other has 3 or 2: at
// 0.4 m/s that is 3.2 mm = 50 counts of mismatch along the joining line
// (the staggered mice: it runs mostly forward), far above the detector's
// threshold (sqrt 2 (1/c + 1/c) = 0.18 mm): false alarms whenever the skew
// is not 0. Aligned (both interpolated at sample time - 10 ms): none.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mrt_mice/count_aligner.h"
#include "mrt_mice/mice_odometry.h"

using namespace mrt::mice;

namespace {
struct DriveResult {
  std::uint64_t samples = 0, flagged = 0;
  double pos_err = 0.0, heading_err = 0.0;
};

DriveResult drive(double skew, bool aligned) {
  // The staggered placement of config/ianus3_staggered.yaml: the joining
  // line runs mostly forward, so forward motion must read the same on both.
  MiceParams p;
  p.left.mount = Pose2D(0.12, 0.10, 0.0);
  p.right.mount = Pose2D(-0.12, 0.06, 0.0);
  MiceOdometry odo(p);
  CountAligner al;
  const MouseParams* m[2] = {&p.left, &p.right};
  double cum[2][2] = {{0, 0}, {0, 0}};        // true counts, fractional
  std::int64_t sent[2][2] = {{0, 0}, {0, 0}};  // reported
  MiceCounts raw;                               // unaligned: reports since the last sample
  double next_poll[2] = {0.0005, 0.0005 + skew};
  const double period[2] = {0.008, 0.008 * (1 + 100e-6)};
  double next_pub = 0.0213;
  double x = 0, y = 0, th = 0;  // true pose
  struct Truth { double t, x, y, th; };
  std::vector<Truth> hist;
  const double dt = 1e-4;
  double last_take = 0.0;
  for (int k = 1; k <= 100000; ++k) {
    const double t = k * dt;
    const double vx = 0.4 + 0.2 * std::sin(1.3 * t), w = 0.8 * std::sin(0.5 * t);
    for (int i = 0; i < 2; ++i) {
      const auto& mt = m[i]->mount;
      const double bx = vx - w * mt.y, by = w * mt.x;  // the mouse point's velocity, body frame
      const double c = std::cos(mt.theta), s = std::sin(mt.theta);
      cum[i][0] += m[i]->counts_per_m * (c * bx + s * by) * dt;
      cum[i][1] += m[i]->counts_per_m * (-s * bx + c * by) * dt;
    }
    x += vx * std::cos(th) * dt;
    y += vx * std::sin(th) * dt;
    th += w * dt;
    hist.push_back({t, x, y, th});
    for (int i = 0; i < 2; ++i) {
      if (t < next_poll[i]) continue;
      next_poll[i] += period[i];
      const std::int64_t dx = static_cast<std::int64_t>(std::floor(cum[i][0])) - sent[i][0];
      const std::int64_t dy = static_cast<std::int64_t>(std::floor(cum[i][1])) - sent[i][1];
      if (dx == 0 && dy == 0) continue;  // a USB mouse sends nothing without motion
      sent[i][0] += dx;
      sent[i][1] += dy;
      al.add(i, t, dx, dy);
      (i ? raw.right_dx : raw.left_dx) += dx;
      (i ? raw.right_dy : raw.left_dy) += dy;
    }
    if (t >= next_pub) {
      next_pub += 0.020;
      odo.update(aligned ? al.take(t) : raw);
      raw = MiceCounts{};
      last_take = t - 0.010;
    }
  }
  DriveResult r;
  r.samples = odo.stats().samples;
  r.flagged = odo.stats().flagged;
  // Truth at the last common instant (aligned) / the last sample (not).
  const double at = aligned ? last_take : last_take + 0.010;
  const Truth& tr = hist[static_cast<std::size_t>(std::lround(at / dt)) - 1];
  r.pos_err = std::hypot(odo.pose().x - tr.x, odo.pose().y - tr.y);
  r.heading_err = std::fabs(std::remainder(odo.pose().theta - tr.th, 2 * M_PI));
  return r;
}
}  // namespace

TEST(CountAligner, OneUsbFrameOfSkewGivesNoFalseAlarms) {
  for (double skew : {0.0, 0.002, 0.004, 0.006, 0.008}) {
    const DriveResult a = drive(skew, true);
    EXPECT_GT(a.samples, 490u);
    EXPECT_EQ(a.flagged, 0u) << "skew " << skew;
    // 4 m driven: the aligned estimate within 1 cm and 0.5 deg of the truth.
    EXPECT_LT(a.pos_err, 0.01) << "skew " << skew;
    EXPECT_LT(a.heading_err, 0.5 * M_PI / 180) << "skew " << skew;
  }
  // Without the alignment: false alarms wherever a sample ends between the
  // two mice's polls at one end of its window and not at the other. With
  // 20 ms samples at 5.3 and 1.3 ms past an 8 ms frame (mod 8) that is
  // every other sample at skews of 2 and 4 ms; at 6 ms both ends of every
  // window fall between the polls, the windows are shifted alike and only
  // the acceleration shows (1 flag in this run).
  for (double skew : {0.002, 0.004}) {
    const DriveResult u = drive(skew, false);
    EXPECT_GT(u.flagged, u.samples / 10) << "skew " << skew;
  }
}

// Gaps, duplicated and out-of-order stamps: dropped or deferred and
// counted, never a crash, never counts lost.
TEST(CountAligner, DisorderedStampsAreCountedAndNoCountIsLost) {
  CountAligner al;
  EXPECT_TRUE(al.add(0, 1.000, 10, 0));
  EXPECT_TRUE(al.add(0, 1.000, 5, 0));    // duplicated stamp: kept (same instant)
  EXPECT_FALSE(al.add(0, 0.990, 7, 0));   // out of order: dropped
  EXPECT_TRUE(al.add(1, 1.004, 0, 20));
  MiceCounts c = al.take(1.100);          // common instant 1.090: everything
  EXPECT_EQ(c.left_dx, 15);
  EXPECT_EQ(c.right_dy, 20);
  EXPECT_TRUE(al.add(1, 1.050, 0, 4));    // late (before 1.090): deferred to the next sample
  EXPECT_TRUE(al.add(1, 1.050, 0, 2));    // late again, same stamp: deferred too, not dropped
  c = al.take(1.120);
  EXPECT_EQ(c.right_dy, 6);
  EXPECT_EQ(al.stats().out_of_order, 1u);
  EXPECT_EQ(al.stats().late, 2u);
  // A gap of 5 s: no interpolation across it beyond one frame.
  EXPECT_TRUE(al.add(0, 6.000, 8, 0));
  c = al.take(5.996 + 0.010);             // instant 5.996: half of the 8 ms frame before 6.000
  EXPECT_EQ(c.left_dx, 4);
  c = al.take(7.0);
  EXPECT_EQ(c.left_dx, 4);
  EXPECT_FALSE(al.add(2, 1.0, 1, 1));
  AlignerOptions bad;
  bad.delay = -1;
  EXPECT_THROW(CountAligner{bad}, std::invalid_argument);
}
