// A Monte Carlo localization baseline with amcl's algorithm (ROS-free,
// written for murea_bench): amcl's omni odometry motion model, its
// likelihood-field sensor model on MUREA's map (each percept class against
// the distance function of its layer, like amcl's beam end points against
// the obstacle distance map), KLD-sampling resampling, amcl's update
// thresholds and its best-cluster estimate; all defaults are amcl's.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "mrt_murea/localizer.h"

namespace mrt::murea::bench {

struct MclOptions {        // amcl's parameter and default
  int min_particles = 100;  // ~min_particles
  int max_particles = 5000; // ~max_particles
  double kld_err = 0.01;    // ~kld_err
  double kld_z = 0.99;      // ~kld_z (amcl uses it as the quantile itself)
  double update_min_d = 0.2;             // ~update_min_d (m)
  double update_min_a = 0.5235987755982988;  // ~update_min_a (pi / 6)
  int resample_interval = 2;             // ~resample_interval
  double alpha[5] = {0.2, 0.2, 0.2, 0.2, 0.2};  // ~odom_alpha1..5 (omni model)
  double z_hit = 0.95, z_rand = 0.05;    // ~laser_z_hit, ~laser_z_rand
  double sigma_hit = 0.2;                // ~laser_sigma_hit (m)
  double max_dist = 2.0;                 // ~laser_likelihood_max_dist (m)
  int max_beams = 30;                    // ~laser_max_beams (percepts used per update)
  double range_max = 6.0;                // the sensor's range (amcl: the laser's)
  double init_cov[3] = {0.25, 0.25, 0.06853891945200942};  // ~initial_cov_xx, _yy, _aa ((pi/12)^2)
};

struct Particle {
  Pose2D pose;
  double weight;
};

class Mcl {
 public:
  Mcl(const FeatureMap& map, const MclOptions& options, std::uint64_t seed);
  /// amcl's global_localization: max_particles uniform over the map's bounds.
  void global_init();
  /// amcl's initialpose: a Gaussian with the initial covariance.
  void set_pose(const Pose2D& pose);
  /// One percept frame with odometry's motion since the last frame (robot
  /// frame). The filter runs (motion, sensor, maybe resampling) when the
  /// accumulated motion passes update_min_d or update_min_a, or the first
  /// time after an init; returns true if it ran.
  bool frame(const Pose2D& odom_delta, const std::vector<Percept>& percepts);
  /// The mean of the heaviest cluster, moved by odometry since the last filter update.
  Pose2D estimate() const { return estimate_ * pending_; }
  std::size_t particles() const { return set_.size(); }

 private:
  void motion(const Pose2D& delta);
  void sensor(const std::vector<Percept>& percepts);
  void resample();
  void cluster();

  const FeatureMap& map_;
  MclOptions opt_;
  std::mt19937_64 rng_;
  std::vector<Particle> set_;
  Pose2D pending_;     // odometry accumulated since the last filter update
  Pose2D estimate_;
  bool force_ = true;  // update on the next frame whatever the motion
  int updates_ = 0;
};

}  // namespace mrt::murea::bench
