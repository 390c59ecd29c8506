// The UMBmark protocol (Borenstein & Feng) of the two-mouse odometry in
// mrt_sim, shared by umbmark_bench and its reduced gtest (test_umbmark.cpp):
// a 4 m square driven open loop (the odometry is not used to steer), the
// odometry's error measured at the end against the simulator's ground
// truth; an IANUS3 whose mice have realistic systematic errors. Tests and
// benchmarks only.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_mice/calibrator.h"
#include "mrt_mice/mice_odometry.h"
#include "sim_protocol.h"

namespace mrt::mice::umbmark {

using mrt::common::deg_to_rad;

constexpr double kSide = 4.0;      // m
constexpr double kSpeed = 0.5;     // m/s
constexpr double kTurnRate = 1.0;  // rad/s

// The drawing: mice 12 cm ahead of and behind the wheel axle, on the left
// of the centre line, x axes forward, 400 cpi.
inline MiceParams nominal() {
  MiceParams p;
  p.left.mount = Pose2D(0.12, 0.10, 0.0);
  p.right.mount = Pose2D(-0.12, 0.06, 0.0);
  p.left.counts_per_m = p.right.counts_per_m = 15748.0;
  return p;
}

// The robot as built.
inline sim::SimMice as_built(double noise) {
  sim::SimMice m;
  m.truth.left.mount = Pose2D(0.124, 0.097, deg_to_rad(2.0));
  m.truth.left.counts_per_m = 15748.0 * 1.015;
  m.truth.right.mount = Pose2D(-0.117, 0.064, deg_to_rad(-3.0));
  m.truth.right.counts_per_m = 15748.0 * 0.982;
  m.noise = noise;
  return m;
}

struct Slips {
  double rate = 0.0;  // per moving sample, one mouse loses a fraction in [min, 1] of it
  double min_fraction = 0.2;
  std::mt19937_64 rng{123};
  long injected = 0, detected = 0;
  long clean = 0, false_alarms = 0;
};

// One UMBmark run; returns the final error (odometry - truth) of each
// odometry in `odos`, in the frame of the start pose.
inline std::vector<Pose2D> run_square(std::uint64_t seed, bool clockwise, const sim::SimMice& mice,
                               std::vector<MiceOdometry*> odos, Slips* slips) {
  mrt::sim::Simulator s(sim::make_world(mice, seed));
  for (auto* o : odos) o->reset();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  bool moving = false;
  int moving_samples = 0;
  sim::AlignedMice aligned(mice.physical());
  auto on = [&](const mrt::sim::RobotState& r) {
    MiceCounts c = aligned(r.mice);
    bool slip = false;
    // A slip (manual §4.2): for part of the sample one mouse sees nothing.
    if (slips && moving && moving_samples > 0 && slips->rate > 0 && u(slips->rng) < slips->rate) {
      const double keep = 1.0 - (slips->min_fraction + (1.0 - slips->min_fraction) * u(slips->rng));
      if (u(slips->rng) < 0.5) {
        c.left_dx = std::llround(c.left_dx * keep);
        c.left_dy = std::llround(c.left_dy * keep);
      } else {
        c.right_dx = std::llround(c.right_dx * keep);
        c.right_dy = std::llround(c.right_dy * keep);
      }
      slip = true;
    }
    ++moving_samples;
    bool flagged = false;
    for (std::size_t i = 0; i < odos.size(); ++i) {
      const bool f = odos[i]->update(c).detection.flagged;
      if (i == 0) flagged = f;
    }
    if (slips) {
      if (slip) {
        ++slips->injected;
        slips->detected += flagged;
      } else if (!r.mice.left_fault && !r.mice.right_fault) {
        ++slips->clean;
        slips->false_alarms += flagged;
      }
    }
  };
  const long steps_per_s = std::lround(1.0 / s.dt());
  sim::settle(s, on);
  const Pose2D start = s.robots()[0].pose;
  for (int side = 0; side < 4; ++side) {
    moving = true;
    moving_samples = 0;
    sim::drive(s, {kSpeed, 0.0, 0.0}, std::lround(kSide / kSpeed * steps_per_s), on);
    moving = false;
    sim::settle(s, on);
    moving = true;
    moving_samples = 0;
    sim::drive(s, {0.0, 0.0, clockwise ? -kTurnRate : kTurnRate},
               std::lround(M_PI / 2 / kTurnRate * steps_per_s), on);
    moving = false;
    sim::settle(s, on);
  }
  const Pose2D truth = start.inverse() * s.robots()[0].pose;
  std::vector<Pose2D> errors;
  for (auto* o : odos)
    errors.emplace_back(o->pose().x - truth.x, o->pose().y - truth.y,
                        mrt::common::angle_diff(o->pose().theta, truth.theta));
  return errors;
}

// E_max,syst = max over the two directions of the distance of the centre of
// gravity of the five final errors from the origin.
inline double e_max_syst(const std::vector<Pose2D>& cw, const std::vector<Pose2D>& ccw) {
  auto cg = [](const std::vector<Pose2D>& e) {
    double x = 0, y = 0;
    for (const auto& p : e) {
      x += p.x;
      y += p.y;
    }
    return std::hypot(x / e.size(), y / e.size());
  };
  return std::max(cg(cw), cg(ccw));
}

/// The calibration of manual §4.2 in the same simulator, by a careful
/// person (pushes within +-2 mm, turns within +-0.3 degrees, 1 sigma).
inline CalibrationResult calibrate_as_operator(const sim::SimMice& mice, std::uint64_t world_seed,
                                               const MiceParams& start) {
  mrt::sim::Simulator calib_sim(sim::make_world(mice, world_seed));
  sim::Operator op;
  op.push_sigma = 0.002;
  op.turn_sigma = deg_to_rad(0.3);
  op.seed = 17;
  return calibrate(sim::calibration_runs(calib_sim, 10, 5, op), start);
}

}  // namespace mrt::mice::umbmark
