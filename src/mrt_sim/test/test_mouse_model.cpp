// The physical mouse model (mouse_model.h) against hand-worked figures.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_sim/mouse_model.h"
#include "mrt_sim/simulator.h"

using namespace mrt::sim;

namespace {

constexpr double kCpm = 15748.0;  // 400 cpi
constexpr double kDt = 0.001;

// A mouse at (0, 0.1) in base_link, x forward, physical model with the
// acceleration limit out of the way unless the test sets it.
MouseConfig physical() {
  MouseConfig c;
  c.id = "left";
  c.mount = Pose2D(0.0, 0.1, 0.0);
  c.counts_per_m = kCpm;
  c.physics.enabled = true;
  c.physics.max_accel = 1e9;
  return c;
}

// Drives the body from the origin along +x with twist `t` for `steps` 1 ms
// steps (the pose integrated exactly: straight motion), returns the counts.
struct Drive {
  int dx = 0, dy = 0;
  std::vector<MouseReport> reports;
};
Drive drive(MouseModel& m, const Twist2D& t, int steps, const std::vector<Surface>& floor = {}) {
  std::mt19937_64 rng(7);
  Drive d;
  for (int k = 1; k <= steps; ++k)
    m.step(t, Pose2D(t.vx * k * kDt, 0.0, 0.0), k * kDt, kDt, floor, rng);
  m.read(d.dx, d.dy, &d.reports);
  return d;
}

Surface patch(double x0, double x1, double resolution, double clearance) {
  Surface s;
  s.min_x = x0, s.max_x = x1, s.min_y = -10.0, s.max_y = 10.0;
  s.resolution = resolution;
  s.clearance = clearance;
  return s;
}

}  // namespace

TEST(PhysicalMouse, OffIsTheIdealModelDrawForDraw) {
  // With physics off the new step is the old one: same counts, same random
  // draws (noise and faults on), so existing figures stay comparable.
  MouseConfig c = physical();
  c.physics.enabled = false;
  c.noise = 0.01;
  c.fault_rate = 0.01;
  MouseModel a(c), b(c);
  std::mt19937_64 ra(3), rb(3);
  for (int k = 1; k <= 2000; ++k) {
    const Twist2D t{0.4, 0.1, 0.7};
    EXPECT_EQ(a.step(t, kDt, ra), b.step(t, Pose2D(), k * kDt, kDt, {patch(-9, 9, 0.5, 0.01)}, rb));
  }
  int ax, ay, bx, by;
  a.read(ax, ay);
  b.read(bx, by);
  EXPECT_EQ(ax, bx);
  EXPECT_EQ(ay, by);
}

TEST(PhysicalMouse, CarpetScalesTheResolution) {
  // 0.5 m/s for 1 s on a carpet of resolution 0.9: 0.5 * 15748 * 0.9 =
  // 7086.6 counts -> 7086 (floor); off the carpet 7874.
  MouseModel on(physical()), off(physical());
  EXPECT_EQ(drive(on, {0.5, 0.0, 0.0}, 1000, {patch(-1.0, 10.0, 0.9, 0.0)}).dx, 7086);
  EXPECT_EQ(drive(off, {0.5, 0.0, 0.0}, 1000, {patch(5.0, 10.0, 0.9, 0.0)}).dx, 7874);
}

TEST(PhysicalMouse, HeightScalesAndLiftOffLosesCounts) {
  // 1 mm higher (below the 2 mm lift-off), gain 10 /m: scale 0.99,
  // 7874 * 0.99 = 7795.26 -> 7795.
  MouseModel higher(physical());
  EXPECT_EQ(drive(higher, {0.5, 0.0, 0.0}, 1000, {patch(-1.0, 10.0, 1.0, 0.001)}).dx, 7795);
  // A 3 mm dip from x = 0.2 to 0.3 m: the mouse (x = 0.0005 k after step k)
  // is over it for k = 400..600, 201 steps (borders included; 200 if
  // rounding puts a border outside): 799 counted steps of 0.5 mm, 0.3995 m
  // = 6291.3 counts -> 6291 (6299 with 200).
  MouseModel lifted(physical());
  const Drive d = drive(lifted, {0.5, 0.0, 0.0}, 1000, {patch(0.2, 0.3, 1.0, 0.003)});
  EXPECT_GE(lifted.losses().lifted, 200u);
  EXPECT_LE(lifted.losses().lifted, 201u);
  EXPECT_NEAR(d.dx, 0.5e-3 * (1000 - lifted.losses().lifted) * kCpm, 1.0);
}

TEST(PhysicalMouse, SpeedAndAccelerationLimitsLoseCounts) {
  // max_speed 1 m/s: at 1.2 m/s nothing is counted, at 0.9 m/s all of it
  // (96 ms, up to the 125 Hz report at 96 ms: 0.9 * 0.096 * 15748 = 1360.6
  // -> 1360).
  MouseModel fast(physical()), ok(physical());
  EXPECT_EQ(drive(fast, {1.2, 0.0, 0.0}, 96).dx, 0);
  EXPECT_EQ(fast.losses().too_fast, 96u);
  EXPECT_EQ(drive(ok, {0.9, 0.0, 0.0}, 96).dx, 1360);
  // max_accel 15 g = 147.1 m/s^2: from rest to 0.5 m/s in one 1 ms step is
  // 500 m/s^2, so the first step is lost: 0.199 m -> 1566.9 -> 1566
  // (200 ms, up to the report at 200 ms).
  MouseConfig c = physical();
  c.physics.max_accel = 15.0;
  MouseModel jolt(c);
  EXPECT_EQ(drive(jolt, {0.5, 0.0, 0.0}, 200).dx, 1566);
  EXPECT_EQ(jolt.losses().too_hard, 1u);
}

TEST(PhysicalMouse, ReportsOnItsOwnClock) {
  // 125 Hz, phase 3 ms: reports at 3, 11, ..., 99 ms in 100 ms, 13 of them;
  // the first holds 3 steps of motion, the others 8 (0.5 m/s: 0.5 mm a step
  // = 7.874 counts; cumulative floors at 3, 11, 19 ms: 23, 86, 149).
  MouseConfig c = physical();
  c.physics.phase = 0.003;
  MouseModel m(c);
  const Drive d = drive(m, {0.5, 0.0, 0.0}, 100);
  ASSERT_EQ(d.reports.size(), 13u);
  EXPECT_NEAR(d.reports[0].t, 0.003, 1e-12);
  EXPECT_NEAR(d.reports[12].t, 0.099, 1e-12);
  EXPECT_EQ(d.reports[0].dx, 23);
  EXPECT_EQ(d.reports[1].dx, 86 - 23);
  EXPECT_EQ(d.reports[2].dx, 149 - 86);
  // Counts after the last report (100 ms) wait for the next one.
  EXPECT_EQ(d.dx, static_cast<int>(std::floor(0.099 * 0.5 * kCpm)));
  EXPECT_NEAR(m.last_report_time(), 0.099, 1e-12);
  // A clock 1000 ppm fast: in 10 s its local time reaches 10.01 s, reports
  // k = 0..1251 (k / 125 <= 10.01): 1252, against 1251 on time.
  c.physics.phase = 0.0;
  c.physics.drift_ppm = 1000.0;
  MouseModel drifting(c);
  c.physics.drift_ppm = 0.0;
  MouseModel on_time(c);
  EXPECT_EQ(drive(drifting, {0.1, 0.0, 0.0}, 10000).reports.size(), 1252u);
  EXPECT_EQ(drive(on_time, {0.1, 0.0, 0.0}, 10000).reports.size(), 1251u);
}

TEST(PhysicalMouse, WorldFileAndSimulatorStampEachMouse) {
  const World w = parse_world(R"(name: carpet
bounds: [-5, -5, 5, 5]
surfaces:
  - {name: carpet, min: [1, -5], max: [5, 5], resolution: 0.95}
  - {name: bump, min: [2, -5], max: [2.1, 5], clearance: 0.004}
robots:
  - name: r
    base: ianus3
    pose: [0, 0, 0]
    sensors:
      mice: {rate: 50, model: physical, max_speed: 1.5, max_accel: 20, report_rate: 125,
             left: {x: 0, y: 0.1, phase: 0.001}, right: {x: 0, y: -0.1, phase: 0.005, drift_ppm: 100}}
)", "carpet.yaml", "");
  ASSERT_EQ(w.surfaces.size(), 2u);
  EXPECT_DOUBLE_EQ(w.surfaces[0].resolution, 0.95);
  EXPECT_DOUBLE_EQ(w.surfaces[1].clearance, 0.004);
  const MouseConfig& l = w.robots[0].sensors.mice[0];
  const MouseConfig& r = w.robots[0].sensors.mice[1];
  EXPECT_TRUE(l.physics.enabled && r.physics.enabled);
  EXPECT_DOUBLE_EQ(l.physics.max_speed, 1.5);
  EXPECT_DOUBLE_EQ(r.physics.drift_ppm, 100.0);
  Simulator sim(w);
  sim.set_twist(0, {0.5, 0.0, 0.0});
  while (!sim.robots()[0].mice_ready) sim.step();
  // First sample at 20 ms: left reports at 1, 9, 17 ms, right at 5, 13 ms
  // (drift 100 ppm moves them by under 2 us).
  const MiceSample& s = sim.robots()[0].mice;
  EXPECT_NEAR(s.time, 0.020, 1e-12);
  EXPECT_NEAR(s.left_stamp, 0.017, 1e-12);
  EXPECT_NEAR(s.right_stamp, 0.013, 1e-12);
  ASSERT_EQ(s.left_reports.size(), 3u);
  ASSERT_EQ(s.right_reports.size(), 2u);
  EXPECT_EQ(s.left_dx, s.left_reports[0].dx + s.left_reports[1].dx + s.left_reports[2].dx);
  // The first step (0 -> 0.5 m/s in 1 ms: 51 g) is lost by both mice and
  // flagged as a fault.
  EXPECT_TRUE(s.left_fault && s.right_fault);
  EXPECT_THROW(parse_world("name: x\nbounds: [0, 0, 1, 1]\nrobots:\n  - {name: r, base: ianus3, pose: [0, 0, 0],"
                           " sensors: {mice: {model: real}}}\n", "bad.yaml", ""),
               mrt::common::ParseError);
}
