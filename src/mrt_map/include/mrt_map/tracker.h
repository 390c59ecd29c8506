// Tracker (manual chapter 8): one anchor per real object with a stable id,
// a Kalman filter per anchor on the robot's own observations, the anchor
// life cycle (tentative -> confirmed -> coasting -> dropped), global
// nearest neighbour association on gated Mahalanobis costs, and the team
// estimate: the covariance intersection (or, per the class's `fusion`, the
// information fusion) of the own filter and the teammates' anchors linked to it.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mrt_map/conceptual_model.h"
#include "mrt_map/merger.h"
#include "mrt_map/types.h"

namespace mrt::map {

class Tracker {
 public:
  explicit Tracker(const ConceptualModel& model) : model_(model), merger_(model) {}

  /// One cycle at time `now`: predict, associate and update with the own
  /// (already merged) observations, link and fuse the teammates' anchors
  /// (already latency-compensated to `now`), advance the life cycle.
  /// (`remote` by value: the caller moves its compensated tracks in.)
  void cycle(double now, const std::vector<Observation>& observations, std::vector<RemoteTrack> remote);

  /// A teammate's reported pose (world frame): Robot anchors it explains
  /// (Mahalanobis within team.gate) become the class refined_by teammate_pose.
  void set_teammate_pose(const std::string& robot, const Vec2& p, const Mat2& cov, double stamp);

  /// Live anchors (not dropped), ordered by id.
  const std::vector<Anchor>& anchors() const { return anchors_; }
  /// reliability = degree * exp(-(now - last_seen) / tau).
  double reliability(const Anchor& a, double now) const;
  /// How surely the anchor is a real object, by its independent sources:
  /// degree * (1 - prod_i (1 - c * exp(-age_i / tau))) over the own filter
  /// and each teammate's track linked this cycle (age_i: since that
  /// source's last sighting; c = tracker.source_confidence). A clutter
  /// track one camera feeds ranks below the ball three robots report.
  double support(const Anchor& a, double now) const;
  /// Anchors the robot's own sensors confirm (confirm_hits own sightings,
  /// the last within coast_after), for the teammates: their local
  /// estimates only (so a teammate never gets its own data back).
  std::vector<RemoteTrack> local_tracks(const std::string& robot) const;
  std::uint64_t dropped_count() const { return dropped_; }
  /// Time of the last cycle.
  double now() const { return now_; }
  /// Anchors joined into an older one (two symbols for one object).
  std::uint64_t coalesced_count() const { return coalesced_; }

 private:
  void associate_local(double now, const std::vector<Observation>& obs);
  void associate_remote(double now, std::vector<RemoteTrack>& remote);
  void fuse(double now);
  void coalesce();
  void life_cycle(double now);
  void refine_teammates(double now);
  Anchor& create(double now, int class_index, double degree);
  /// Adopts a more specific class (a Robot seen as an Opponent).
  void refine_class(Anchor& a, int c, double degree) const;
  /// The coasting anchor (not supported this cycle, compatible class) nearest
  /// to z within tracker.reid_gate (squared Mahalanobis), or null.
  Anchor* reidentify(int class_index, const Vec2& z, const Mat2& R);
  /// The class with a cardinality (max_count) that `class_index` is or
  /// descends from, if that class is at its cardinality (as many confirmed
  /// or coasting anchors as max_count); else -1.
  int at_cardinality(int class_index) const;
  int cardinality_class(int class_index) const;  // -1: no cardinality
  int live_count(int card) const;                // confirmed or coasting anchors of the class
  /// Observations (z, R) of a class at its cardinality that no live anchor
  /// takes are the class's lost (coasting) anchors coming back: the global
  /// minimum-cost assignment (Hungarian) on the negative log-likelihood
  /// d2 + ln det S with the coasting covariance grown by the motion model,
  /// no gate. Returns an anchor index per observation, or -1 (more
  /// observations than lost anchors).
  std::vector<int> claim_lost(int card_class, const std::vector<std::pair<Vec2, Mat2>>& zs) const;
  void apply_local(double now, Anchor& a, const Observation& o);
  const ConceptualModel& model_;
  Merger merger_;
  std::vector<Anchor> anchors_;
  std::uint32_t next_id_ = 1;
  std::uint64_t dropped_ = 0, coalesced_ = 0, coalesced_cycle_ = 0;
  double now_ = 0.0;  // this cycle's time
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> close_since_;  // coalescence candidates
  struct TeammatePose {
    Vec2 p;
    Mat2 cov;
    double stamp;
  };
  std::map<std::string, TeammatePose> teammates_;
  std::set<std::uint32_t> seen_;  // anchors supported this cycle
  // The frames (sensor, stamp) of the own observations that updated each
  // anchor this cycle.
  std::map<std::uint32_t, std::set<std::pair<std::string, double>>> own_seen_;
  bool seen_in_one_frame(std::uint32_t a, std::uint32_t b) const;
  static bool one_teammate_apart(const Anchor& a, const Anchor& b);
  void keep_lost_off_held(std::vector<std::vector<double>>& cost, double gate) const;
};

}  // namespace mrt::map
