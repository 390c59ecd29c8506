// MUREA's tracking (ROS-free): odometry predicts the pose between percept
// frames, the search runs in a window around the prediction sized from the
// prediction's uncertainty, and a global search takes over when the
// evidence of the tracked pose collapses (kidnapping).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "mrt_murea/localizer.h"
#include "mrt_murea/refine.h"

namespace mrt::murea {

struct TrackerOptions {
  SearchOptions search;            // global search (and lattice, tolerances) options
  double window_sigmas = 3.0;      // window half-size = this many standard deviations ...
  double min_window_xy = 0.15;     // ... clamped to [min, max] (m)
  double max_window_xy = 1.0;
  double min_window_theta = 0.08726646259971647;  // rad (5 deg)
  double max_window_theta = 0.5235987755982988;   // rad (30 deg)
  /// The tracked pose's evidence is "collapsed" below this fraction of the
  /// evidence the frame's percepts could give (their total reliability) ...
  double collapse_fraction = 0.4;
  /// ... for this many consecutive frames: the next frame is searched globally.
  int collapse_frames = 3;
  /// A global result is accepted (tracking starts) when its evidence is at
  /// least collapse_fraction of the percepts' total and, unless this is
  /// true, it is not ambiguous and the search completed (a timed-out search
  /// does not know its runner-up); else the next frame is searched globally too.
  bool track_ambiguous = false;
  /// A complete but ambiguous global search (the symmetric field's mirror)
  /// is resolved by the prior, the last accepted or set pose carried by
  /// odometry: of the best pose and its runner-up, the one within this
  /// squared Mahalanobis distance of the prior (x, y, theta) is taken when
  /// the other is not. 0: never (no prior: stays ambiguous).
  double prior_gate = 11.34;  // chi^2, 3 dof, 99 %
  /// While lost, each frame whose global search stays ambiguous grows the
  /// prior's standard deviations by these (in quadrature), so a prior gone
  /// wrong before the loss admits the nearer mode first, never both at once
  /// unless they are equally near. 0: the prior stays as odometry left it.
  double lost_growth_xy = 0.1;      // m per frame
  double lost_growth_theta = 0.1;   // rad per frame
  /// While a global search stays ambiguous (two modes, none admitted by
  /// the prior), the modes are carried from frame to frame: odometry moves
  /// each, a windowed search around each follows it, and at the first
  /// frame whose evidence tells them apart by more than the search's
  /// ambiguity_margin (or the prior admits one alone) a global search
  /// decides (it commits when unambiguous). Otherwise a global search runs
  /// only every this many frames (or when both modes collapse), bounding
  /// the cost. 0: a global search at every frame (no modes carried).
  int ambiguous_global_period = 30;
  /// After each accepted search, the pose is fitted to the matched
  /// percepts by least squares, fused with odometry's prediction while
  /// tracking (refine.h); disable to keep the plateau's mean.
  RefineOptions refine;
  /// A global fix rests on one frame's percepts (its error is their noise
  /// over the features seen); it is `settled` once this many tracked
  /// frames with usable percepts have been fused into it. A pose that was
  /// set (set_pose) is settled at once. 0: every fix at once.
  int settle_frames = 0;
};

enum class TrackMode { Global, Tracking };

struct TrackResult {
  Result search;              // the search of this frame (global or windowed)
  TrackMode mode = TrackMode::Global;  // how this frame was searched
  Pose2D pose;                // the estimate after this frame
  Covariance3 covariance{};   // its covariance
  double max_evidence = 0.0;  // total reliability of the usable percepts
  bool collapsed = false;     // this frame's evidence was below the fraction
  bool lost = false;          // no accepted pose after this frame (pose is the last one)
  bool refined = false;       // the pose is the least-squares fit (refine.h)
  bool resolved = false;      // an ambiguous global search resolved by the prior
  bool settled = false;       // tracking, and the last global fix confirmed (settle_frames)
  std::size_t modes = 0;      // modes carried after this frame (0 or 2, while ambiguous)
};

/// A mode of an ambiguous localization, carried by odometry.
struct Mode {
  Pose2D pose;
  Covariance3 covariance{};
};

class Tracker {
 public:
  Tracker(const FeatureMap& map, const TrackerOptions& options);

  /// Applies a relative motion in the robot frame (odometry from the last
  /// call to the next) with its covariance (in the robot frame of the start).
  void predict(const Pose2D& delta, const Covariance3& delta_covariance);

  /// Localizes from one frame of percepts: windowed search while tracking,
  /// global search when lost (at start, after reset(), after a collapse).
  TrackResult update(const std::vector<Percept>& percepts);

  /// Sets the pose (e.g. initialpose) and starts tracking from it.
  void set_pose(const Pose2D& pose, const Covariance3& covariance);
  /// Forgets the pose and the prior: the next update searches globally.
  void reset();
  /// New search options (lattice, timeout, tolerances) from the next
  /// update on; the pose, the prior and the modes are kept. Throws
  /// std::invalid_argument (the options unchanged) when the Localizer
  /// refuses them on this map. Not thread-safe: call between updates.
  void set_search_options(const SearchOptions& search);

  bool tracking() const { return tracking_; }
  /// Tracking from a confirmed fix (TrackerOptions::settle_frames).
  bool settled() const { return tracking_ && unconfirmed_ == 0; }
  /// The modes carried while ambiguous (empty otherwise).
  const std::vector<Mode>& modes() const { return modes_; }
  const Pose2D& pose() const { return pose_; }
  const Covariance3& covariance() const { return cov_; }
  const TrackerOptions& options() const { return opt_; }
  /// The window the next tracked search will use: [min_x, min_y, max_x, max_y].
  std::array<double, 4> window() const;
  std::array<double, 2> heading_window() const;

 private:
  TrackResult global_update(const std::vector<Percept>& percepts, double max_evidence);
  /// While ambiguous: a windowed search around each carried mode; commits
  /// to one when the evidence tells them apart.
  TrackResult modes_update(const std::vector<Percept>& percepts, double max_evidence);
  /// Carries the two modes of an ambiguous complete search `r`.
  void keep_modes(const Localizer& loc, const Result& r, const std::vector<Percept>& percepts);
  /// The search window around a pose of covariance c: [min_x, min_y, max_x, max_y], [min, max] heading.
  std::array<double, 4> window_of(const Pose2D& p, const Covariance3& c) const;
  std::array<double, 2> heading_window_of(const Pose2D& p, const Covariance3& c) const;
  /// Of an ambiguous complete search, the hypothesis the prior admits
  /// alone (prior_gate): &r.best or &*r.alternative; nullptr when both or neither.
  const Hypothesis* resolve_by_prior(const Result& r) const;
  /// Replaces pose_ and cov_ (the search's estimate) by the least-squares
  /// fit, fused with the prediction when with_prior; false if not refined.
  bool refine_pose(const Localizer& loc, const std::vector<Percept>& percepts, bool with_prior,
                   const Pose2D* prior = nullptr, const Covariance3* prior_cov = nullptr);

  const FeatureMap& map_;
  TrackerOptions opt_;
  bool tracking_ = false;
  bool has_prior_ = false;  // pose_ and cov_ come from an accepted or set pose
  int collapsed_frames_ = 0;
  int frames_since_global_ = 0;  // frames with modes carried since the last global search
  int unconfirmed_ = 0;          // tracked frames the last global fix still waits for
  std::vector<Mode> modes_;
  Pose2D pose_;
  Covariance3 cov_{};
};

/// Total reliability of the percepts the localizer would use.
double max_evidence(const Localizer& loc, const std::vector<Percept>& percepts);

/// Covariance of pose * delta from the covariances of pose (world frame) and
/// delta (frame of pose): J1 P J1^T + J2 Q J2^T.
Covariance3 compose_covariance(const Pose2D& pose, const Covariance3& p, const Pose2D& delta,
                               const Covariance3& q);

}  // namespace mrt::murea
