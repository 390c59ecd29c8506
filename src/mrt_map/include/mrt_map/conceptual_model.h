// The conceptual model of MAP (manual chapter 8): an application's classes
// of perceivable objects in a hierarchy, how a percept's attributes match
// them (mrt_brian fuzzy sets or symbol degrees), per-class motion model and
// noise, and the tracker, team and crisp-data settings. Loaded from YAML;
// every error is a mrt::common::ParseError naming file:line:column.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mrt_brian/fuzzy_set.h"

namespace mrt::map {

enum class MotionModel { kStatic, kConstantVelocity };

/// How one attribute of a percept matches a class: a numeric attribute
/// through a fuzzy set, a symbolic one through a table of degrees (a symbol
/// not in the table matches with 0).
struct AttributeMatcher {
  std::string attribute;
  std::shared_ptr<const mrt::brian::FuzzySet> set;  // numeric when set
  std::map<std::string, double> symbols;            // symbolic otherwise
  /// Degree of a numeric value or of a symbol.
  double match(double value, const std::string& symbol) const;
};

/// The interacting multiple model of a constant-velocity class (imm.h):
/// two CV models on the own observations, mixed by a Markov chain whose
/// switching probabilities apply per prediction (per MAP cycle).
struct ImmDef {
  bool on = false;
  double quiet_accel_noise = 0.5;   // m/s^2, the quiet model (rolling)
  double kicked_accel_noise = 0.0;  // m/s^2, the kicked model (0 = the class's accel_noise)
  double p_quiet_to_kicked = 0.02;  // per cycle
  double p_kicked_to_quiet = 0.1;   // per cycle
};

struct ClassDef {
  std::string name;
  int parent = -1;
  int depth = 0;
  std::vector<int> children;
  std::vector<AttributeMatcher> matchers;  // own, not inherited
  MotionModel motion = MotionModel::kConstantVelocity;
  double accel_noise = 1.0;      // m/s^2 (white acceleration, CV) or m/sqrt(s) drift (static)
  double init_speed_sigma = 2.0; // m/s, velocity prior of a new anchor (CV)
  double default_sigma = 0.1;    // m, position sigma when a percept gives none
  double velocity_tau = 0.0;     // s, CV only: velocity decays as exp(-dt/tau) (integrated
                                 // Ornstein-Uhlenbeck); 0 = constant velocity, no decay
  double drop_after = 0.0;       // s, per-class tracker.drop_after (0 = the tracker's)
  double max_sigma = 0.0;        // m, per-class tracker.max_sigma (0 = the tracker's)
  ImmDef imm;                    // CV only: the own filter is an IMM of two CV models (class `imm:`)
  /// Team fusion of the class's anchors (`fusion:`): team.fusion's rule, or its own.
  enum class Fusion { kTeam, kCovarianceIntersection, kIndependent };
  Fusion fusion = Fusion::kTeam;
  bool impulse_maneuver = false; // `maneuver: impulse`: a manoeuvre is a velocity jump (a kick)
                                 // at the start of the last interval (kalman.h, maneuver)
  double keep_link = 0.0;        // m, `keep_teammate_link`: a teammate's track stays on the
                                 // anchor it was linked to beyond the gate, up to this far
  bool refined_by_teammate_pose = false;  // a Robot becomes this class near a teammate
  int max_count = 0;             // cardinality: at most this many objects of the class
                                 // (and its subclasses) exist; 0 = unknown. Not inherited.
};

struct ClassifierOptions {
  double threshold = 0.5;         // minimal matching degree to accept a class
  double ambiguity_margin = 0.1;  // best child must beat the next by this much
};

struct TrackerOptions {
  double gate = 9.21;            // chi-square 2 dof, 99 %
  double merge_gate = 9.21;      // Merger: same object from two sensors
  int confirm_hits = 3;
  double tentative_timeout = 0.5;  // s unseen before a tentative anchor is dropped
  double coast_after = 0.3;      // s unseen before confirmed -> coasting
  double drop_after = 3.0;       // s unseen before coasting -> dropped
  double max_sigma = 3.0;        // m, dropped when the position sigma grows beyond
  double reliability_tau = 1.0;  // s, reliability decay after last seen
  double coalesce_gate = 9.49;   // chi-square 4 dof, 95 %: two anchors this close in state ...
  double maneuver_radius = 0.5;  // m: an observation outside the gate but this close to the
                                // only anchor near it is a manoeuvre (kick): velocity reset
  double coalesce_after = 0.5;   // s ... for this long are one object (not a crossing): joined
  double source_confidence = 0.5;  // in (0, 1]: how surely one fresh sighting (own or a teammate's
                                   // track) is of a real object (select: best_supported)
  double reid_gate = 0.0;        // chi-square: an observation (or a teammate's track) no anchor
                                 // takes, within this of a coasting anchor, re-identifies it
                                 // (nearest first) instead of creating a symbol; 0 = off
};

struct TeamOptions {
  double max_latency = 1.0;  // s, older teammate models are stale
  double gate = 13.82;       // chi-square 2 dof, 99.9 %
  double extra_sigma = 0.05; // m, added to a teammate's position sigma (its localisation bias)
  bool covariance_intersection = true;  // false: independent (Kalman) fusion
  double send_threshold = 0.0;  // m, TeamSender: send when a teammate's prediction is this far off (0: periodic only)
};

/// The extent of the world (e.g. the field with its run-off area): no
/// object is outside it. Observations and teammates' anchors outside are
/// dropped (counted), an anchor predicted outside is dropped.
struct WorldBounds {
  bool set = false;
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
  bool contains(double x, double y) const { return !set || (x >= x_min && x <= x_max && y >= y_min && y <= y_max); }
};

/// One crisp datum for Mr. BRIAN: either a quantity of the selected anchor
/// of a class, or a coordination parameter written by SCARE.
struct CrispEntry {
  enum class Quantity { kDistance, kBearing, kX, kY, kVx, kVy, kSpeed, kParameter };
  enum class Select { kNearest, kMostReliable, kBestSupported };
  std::string name;
  int class_index = -1;
  std::string parameter;
  Quantity quantity = Quantity::kDistance;
  Select select = Select::kNearest;
  double scale = 1.0;        // to the rule base's unit (e.g. 1000 for mm)
  double missing = 0.0;      // value when nothing is known (reliability 0)
  double min_reliability = 0.0;
};

/// What map_node's dynamic_reconfigure tunes at run time (the model file's
/// tracker.gate, tracker.merge_gate, team.gate, team.extra_sigma).
struct ModelTuning {
  double gate = 9.21;         // squared Mahalanobis, > 0
  double merge_gate = 9.21;   // squared Mahalanobis, > 0
  double team_gate = 13.82;   // squared Mahalanobis, > 0
  double team_extra_sigma = 0.05;  // m, >= 0
};

class ConceptualModel {
 public:
  /// Loads a model file; throws mrt::common::ParseError.
  static ConceptualModel load(const std::string& path);
  /// Parses YAML text; `file` names it in errors.
  static ConceptualModel parse(const std::string& text, const std::string& file);

  int size() const { return static_cast<int>(classes_.size()); }
  const ClassDef& at(int i) const { return classes_.at(static_cast<std::size_t>(i)); }
  /// Index of a class, or -1.
  int find(const std::string& name) const;
  /// True when `a` is `b` or one of its descendants.
  bool is_a(int a, int b) const;
  /// True when one class is the other or an ancestor of it.
  bool compatible(int a, int b) const { return is_a(a, b) || is_a(b, a); }

  const ClassifierOptions& classifier() const { return classifier_; }
  const TrackerOptions& tracker() const { return tracker_; }
  const TeamOptions& team() const { return team_; }
  const WorldBounds& world() const { return world_; }
  const std::vector<CrispEntry>& crisp() const { return crisp_; }

  ModelTuning tuning() const;
  /// Replaces the tuned values; the Merger, Tracker and team fusion holding
  /// this model read them from their next call. Throws
  /// std::invalid_argument naming the key (as in the file) with nothing
  /// changed when one is out of range or not finite.
  void set_tuning(const ModelTuning& t);

 private:
  friend class ModelLoader;
  std::vector<ClassDef> classes_;
  std::map<std::string, int> index_;
  ClassifierOptions classifier_;
  TrackerOptions tracker_;
  TeamOptions team_;
  WorldBounds world_;
  std::vector<CrispEntry> crisp_;
};

}  // namespace mrt::map
