// MUREA's global localization: best-first branch and bound over the pose
// space (x, y, theta) with a conservative evidence bound (ROS-free).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mrt_murea/feature_map.h"

namespace mrt::murea {

/// One perception in the robot frame (metres, radians; bearing
/// counter-clockwise from the robot's forward axis). `color` is ignored for
/// Line and Wall; empty means "any colour" for point classes.
struct Percept {
  FeatureClass cls = FeatureClass::Line;
  std::string color;
  double distance = 0.0;
  double bearing = 0.0;
  double reliability = 1.0;
};

/// Tolerance of a percept of a class: base + per_metre * distance (m).
struct Tolerance {
  double base = 0.05;
  double per_metre = 0.03;
};

struct SearchOptions {
  double accuracy_xy = 0.05;                 // m, lattice spacing in x and y
  double accuracy_theta = 0.017453292519943295;  // rad (1 degree)
  double timeout = 0.0;                      // s; 0 = no limit
  /// The timeout counts the calling thread's CPU time instead of wall-clock
  /// time (benchmarks: the search's budget on one core, whatever else the
  /// machine runs). A node keeps wall-clock time (a real deadline).
  bool timeout_cpu = false;
  double alt_distance = 0.5;                 // m: a runner-up is farther than this ...
  double alt_angle = 0.5235987755982988;     // rad: ... or turned more than this (30 deg)
  double ambiguity_margin = 0.5;             // runner-up within this of the best -> ambiguous
  std::array<Tolerance, kFeatureClassCount> tolerance{
      Tolerance{0.05, 0.03}, Tolerance{0.3, 0.03}, Tolerance{0.2, 0.03}, Tolerance{0.2, 0.03},
      Tolerance{0.05, 0.03}};                // Line, Goal, GoalPost, Landmark, Wall
  double plateau_xy = 0.3;                   // m, half-size of the plateau box
  double plateau_theta = 0.17453292519943295;  // rad (10 deg)
  /// Region searched [min_x, min_y, max_x, max_y]; empty = the map's bounds.
  std::optional<std::array<double, 4>> region;
  /// Headings searched [min, max] (rad, both included, max - min < 2 pi,
  /// max may exceed pi); empty = all headings. With `region`, this bounds
  /// the search around a predicted pose (tracking).
  std::optional<std::array<double, 2>> heading_range;
};

struct Hypothesis {
  Pose2D pose;
  double evidence = 0.0;
};

/// The plateau of most evidence around the best pose: the lattice poses
/// within plateau_xy and plateau_theta of it (a box) whose evidence equals
/// the best's; their mean (circular in theta) and covariance (row-major
/// x, y, theta; plus the lattice's quantisation variance d^2 / 12).
struct Estimate {
  Pose2D mean;
  std::array<double, 9> covariance{};
  std::size_t poses = 0;   // lattice poses of the plateau
  bool truncated = false;  // the plateau reaches the box's faces
  /// The plateau's lattice poses (the cells tied with the best), evenly
  /// subsampled to at most kMaxTied (for display).
  std::vector<Pose2D> tied;
  static constexpr std::size_t kMaxTied = 500;
};

struct Result {
  Hypothesis best;
  Estimate estimate;         // filled in when the search completed
  /// The best lattice pose outside the exclusion zone of `best` (farther
  /// than alt_distance or turned more than alt_angle) whose evidence is at
  /// least best - ambiguity_margin; nullopt when there is none.
  std::optional<Hypothesis> alternative;
  bool ambiguous = false;    // == alternative.has_value()
  bool complete = false;     // false when the timeout cut the search short
  std::size_t cells = 0;     // cells whose bound or evidence was evaluated
  std::size_t percepts = 0;  // percepts used
  double time_ms = 0.0;      // wall-clock time of the search
  double cpu_ms = 0.0;       // CPU time of the calling thread during the search
};

/// A box of lattice poses: indices [x0, x1) x [y0, y1) x [t0, t1).
struct Cell {
  std::uint32_t x0, x1, y0, y1, t0, t1;
  bool leaf() const { return x1 - x0 == 1 && y1 - y0 == 1 && t1 - t0 == 1; }
};

class Localizer {
 public:
  Localizer(const FeatureMap& map, const SearchOptions& options);

  /// Global localization: the lattice pose of maximum evidence (exact when
  /// result.complete), its runner-up and the ambiguity flag.
  Result localize(const std::vector<Percept>& percepts) const;

  /// The same maximum by evaluating every lattice pose (for verification;
  /// slow). Only `best` and `cells` (= lattice poses) are filled in.
  Result exhaustive(const std::vector<Percept>& percepts) const;

  /// The plateau of `best` (a lattice pose and its evidence); see Estimate.
  Estimate plateau(const Hypothesis& best, const std::vector<Percept>& percepts) const;

  /// Evidence of any pose: sum of reliabilities of the percepts that land
  /// within their tolerance of a matching feature (map distance function).
  double evidence(const Pose2D& pose, const std::vector<Percept>& percepts) const;

  /// The conservative bound of a cell (== evidence of its pose for a leaf).
  double bound(const Cell& cell, const std::vector<Percept>& percepts) const;

  // The lattice: x_i = min_x + i dx (i < nx), y_j likewise,
  // theta_k = -pi + k dtheta (k < nt), or min + k dtheta with a heading range.
  std::uint32_t nx() const { return nx_; }
  std::uint32_t ny() const { return ny_; }
  std::uint32_t nt() const { return nt_; }
  Pose2D lattice_pose(std::uint32_t i, std::uint32_t j, std::uint32_t k) const;
  Cell root() const { return {0, nx_, 0, ny_, 0, nt_}; }
  /// Centre pose and half-sizes (m, m, rad) of the lattice poses' box.
  void cell_geometry(const Cell& c, double* cx, double* cy, double* ct, double* hx, double* hy,
                     double* ht) const;

  /// What a percept becomes once matched to its layer (public for tests).
  struct Prepared {
    double lx, ly, r, w, tol, slack;
    Layer layer;
  };
  std::vector<Prepared> prepare(const std::vector<Percept>& percepts) const;

 private:
  friend class Search;
  double score(const std::vector<Prepared>& ps, const Cell& c, double floor) const;
  std::vector<std::array<double, 3>> plateau_box(const std::vector<Prepared>& ps, double evidence, const long c[3],
                                                 const long h[3], bool* face) const;
  double x_at(std::uint32_t i) const { return min_x_ + i * dx_; }
  double y_at(std::uint32_t j) const { return min_y_ + j * dy_; }
  double t_at(std::uint32_t k) const;

  const FeatureMap& map_;
  SearchOptions opt_;
  double min_x_, min_y_, dx_, dy_, dt_, t0_;
  bool wrap_;  // all headings: theta indices wrap around
  std::uint32_t nx_, ny_, nt_;
};

}  // namespace mrt::murea
