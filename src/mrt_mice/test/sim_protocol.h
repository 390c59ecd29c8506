// Runs the calibration protocol and test drives in mrt_sim (tests and
// benchmarks only; the core does not depend on the simulator).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "mrt_mice/calibrator.h"
#include "mrt_mice/count_aligner.h"
#include "mrt_mice/mice_params.h"
#include "mrt_sim/simulator.h"

namespace mrt::mice::sim {

/// The mice of a simulated robot, as the simulator models them.
struct SimMice {
  MiceParams truth;         // real mounts and resolutions
  double noise = 0.0;       // multiplicative length noise per step
  double fault_rate = 0.0;  // per step
  double fault_max_fraction = 0.5;
  /// The physical model (mrt_sim/mouse_model.h), per mouse (left, right);
  /// off (the ideal model, the estimator's exact inverse) by default.
  mrt::sim::MousePhysics physics[2];
  std::vector<mrt::sim::Surface> surfaces;  // the floor under the physical mice
  bool physical() const { return physics[0].enabled || physics[1].enabled; }
};

/// A world with one IANUS3 robot (differential drive: it turns in place
/// about base_link) at the origin carrying only the two mice (50 Hz).
inline mrt::sim::World make_world(const SimMice& m, std::uint64_t seed = 1) {
  mrt::sim::World w;
  w.name = "mice_test";
  w.min_x = w.min_y = -100;
  w.max_x = w.max_y = 100;
  w.seed = seed;
  mrt::sim::RobotConfig r;
  r.name = "robot1";
  r.base = mrt::sim::base_preset("ianus3");
  mrt::sim::SensorsConfig s;
  s.rate_mice = 50.0;
  s.rate_encoders = s.rate_sonar = s.rate_vision = s.rate_dgps = 0.0;
  for (int i = 0; i < 2; ++i) {
    const MouseParams& p = i == 0 ? m.truth.left : m.truth.right;
    mrt::sim::MouseConfig c;
    c.id = i == 0 ? "left" : "right";
    c.mount = p.mount;
    c.counts_per_m = p.counts_per_m;
    c.noise = m.noise;
    c.fault_rate = m.fault_rate;
    c.fault_max_fraction = m.fault_max_fraction;
    c.physics = m.physics[i];
    s.mice.push_back(c);
  }
  r.sensors = s;
  w.robots.push_back(r);
  w.surfaces = m.surfaces;
  return w;
}

inline MiceCounts to_counts(const mrt::sim::MiceSample& s) {
  MiceCounts c;
  c.left_dx = s.left_dx;
  c.left_dy = s.left_dy;
  c.right_dx = s.right_dx;
  c.right_dy = s.right_dy;
  return c;
}

/// What the driver does on a robot (mice_evdev_node): each physical
/// mouse's reports, stamped on its own clock, go to a CountAligner, and the
/// sample is taken at the sample's time. The ideal model's sample as is.
class AlignedMice {
 public:
  explicit AlignedMice(bool physical, AlignerOptions o = {}) : physical_(physical), aligner_(o) {}
  MiceCounts operator()(const mrt::sim::MiceSample& s) {
    if (!physical_) return to_counts(s);  // the ideal model: both read at the sample's instant
    for (const auto& r : s.left_reports) aligner_.add(0, r.t, r.dx, r.dy);
    for (const auto& r : s.right_reports) aligner_.add(1, r.t, r.dx, r.dy);
    return aligner_.take(s.time);
  }
  const CountAligner& aligner() const { return aligner_; }

 private:
  bool physical_;
  CountAligner aligner_;
};

using SampleFn = std::function<void(const mrt::sim::RobotState&)>;

/// Drives robot 0 with a constant twist for `steps` steps, calling `on` at
/// every mice sample.
inline void drive(mrt::sim::Simulator& sim, const mrt::sim::Twist2D& t, long steps,
                  const SampleFn& on) {
  sim.set_twist(0, t);
  for (long i = 0; i < steps; ++i) {
    sim.step();
    const auto& r = sim.robots()[0];
    if (r.mice_ready && on) on(r);
  }
}

/// Stops and waits for the next sample, so that a run's counts are all read.
inline void settle(mrt::sim::Simulator& sim, const SampleFn& on) {
  sim.set_twist(0, mrt::sim::Twist2D{});
  for (int i = 0; i < 1000; ++i) {
    sim.step();
    const auto& r = sim.robots()[0];
    if (r.mice_ready) {
      if (on) on(r);
      return;
    }
  }
}

/// How well the person doing the calibration pushes and turns the robot:
/// each push really covers 0.5 m + N(0, push_sigma), each turn 2 pi +
/// N(0, turn_sigma), but the calibration is told the nominal values.
struct Operator {
  double push_sigma = 0.0;  // m
  double turn_sigma = 0.0;  // rad
  std::uint64_t seed = 1;
};

/// The manual's protocol: ten straight 500 mm pushes (0.25 m/s for 2 s) and
/// five counter-clockwise 360 degree turns in place (pi/2 rad/s for 4 s).
/// The calibration is told the nominal 0.5 m and 2 pi, as a person pushing
/// the robot would.
inline std::vector<CalibrationRun> calibration_runs(mrt::sim::Simulator& sim, int pushes = 10,
                                                    int turns = 5, const Operator& op = Operator()) {
  std::vector<CalibrationRun> runs;
  std::mt19937_64 rng(op.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const long steps_per_s = std::lround(1.0 / sim.dt());
  settle(sim, nullptr);
  for (int k = 0; k < pushes + turns; ++k) {
    CalibrationRun run;
    const bool push = k < pushes;
    run.kind = push ? CalibrationRun::Kind::kPush : CalibrationRun::Kind::kTurn;
    run.amount = push ? 0.5 : 2.0 * M_PI;
    run.source = (push ? "push " : "turn ") + std::to_string(push ? k + 1 : k - pushes + 1);
    auto add = [&](const mrt::sim::RobotState& r) {
      const MiceCounts c = to_counts(r.mice);
      run.counts.left_dx += c.left_dx;
      run.counts.left_dy += c.left_dy;
      run.counts.right_dx += c.right_dx;
      run.counts.right_dy += c.right_dy;
    };
    mrt::sim::Twist2D t;
    if (push)
      t.vx = 0.25;
    else
      t.omega = M_PI / 2.0;
    const double real = push ? (0.5 + op.push_sigma * gauss(rng)) / t.vx
                             : (2.0 * M_PI + op.turn_sigma * gauss(rng)) / t.omega;
    drive(sim, t, std::lround(real * steps_per_s), add);
    settle(sim, add);
    runs.push_back(run);
  }
  return runs;
}

}  // namespace mrt::mice::sim
