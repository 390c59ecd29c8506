// The crisp data of one robot's control cycle (manual §2.3.3, ch. 10): from
// its pose, the world model's anchors, SCARE's coordination parameters,
// the referee and the ball possession, the values its Mr. BRIAN rule base
// reads, in the rule base's units (mm, degrees, seconds). ROS-free.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "mrt_brian/types.h"
#include "mrt_common/pose2d.h"

namespace mrt::robocup {

using common::Point2D;
using common::Pose2D;

/// One anchor of the world model (MAP), world frame, metres.
struct AnchorView {
  std::string membership_class;  // "Ball", "Opponent", "Teammate", "Robot", "Obstacle", ...
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
  double reliability = 1.0;      // [0, 1]
};

/// A coordination parameter of SCARE's crisp output (ScareJob_<Activity>,
/// ScareRole_<Activity>_<role>, ScareMate_<role>_X/_Y/_Index, ScareTeamSize).
struct Parameter {
  double value = 0.0;
  double reliability = 1.0;
};
using Parameters = std::map<std::string, Parameter>;

/// The field (MSL, metres): own goal at -goal_x, the opponents' at +goal_x.
struct FieldGeometry {
  double goal_x = 9.0;              // goal lines at x = +-goal_x
  double goal_half_width = 1.0;
  double half_width = 6.0;          // touch lines at y = +-half_width
  double penalty_depth = 2.25;      // penalty areas: depth from the goal line ...
  double penalty_half_width = 3.25; // ... and half width
};

struct SituationOptions {
  FieldGeometry field;
  double body_radius = 0.25;         // m, this robot
  double ball_radius = 0.11;         // m
  std::vector<std::string> obstacle_classes{"Robot", "Opponent", "Teammate", "Obstacle"};
  std::string ball_class = "Ball";
  double min_reliability = 0.05;     // anchors below are ignored
  double possession_gap = 0.08;      // m beyond the body: the ball counts as owned (no kicker sensor)
  double possession_angle = 25.0;    // deg, idem
  double aim_offset = 0.85;          // m from the goal centre towards the open side's post
  double shot_clearance = 0.45;      // m: an obstacle this close to the shot line blocks it
  double shot_range = 6.0;           // m: farther, ShotClear is 0
  double keeper_zone = 2.0;          // m: the obstacle nearest the goal centre within this is the keeper
  /// m: the keeper (mrt_sim's: 0.6 m out, 1.5 m/s) still reaches an 8 m/s
  /// shot whose line passes closer than this from it (doc/shooting.md).
  double keeper_clearance = 0.65;
  double side_hysteresis = 0.25;     // m: the aim changes side once the ball is this far on the other
  double spot_depth = 3.3;           // m: the shooting spot, this far out of the goal line ...
  double spot_offset = 1.3;          // m: ... and this far from the axis, on the open side
  double defense_distance = 1.5;     // m from the own goal centre towards the ball (DefendGoal)
  Point2D home{-3.0, 0.0};           // KeepPosition / Positioning spot
};

/// What one cycle's crisp data are computed from.
struct SituationInput {
  double time = 0.0;                 // s
  Pose2D pose;                       // world frame
  std::vector<AnchorView> anchors;
  Parameters coordination;
  bool possession_known = false;     // the kicker sensor reported
  bool possession = false;
};

/// The geometric facts behind the crisp data (also for tests and debugging).
struct Situation {
  bool ball_seen = false;
  Point2D ball;
  double ball_reliability = 0.0;
  bool owned = false;
  Point2D aim;                       // where a shot goes (a point of the goal mouth)
  Point2D spot;                      // where the carrier takes the ball to shoot from
  bool shot_clear = false;
  double keeper_clearance = 0.0;     // m, the keeper from the shot line (infinite: no keeper)
  bool mate_known = false;
  Point2D mate;                      // the receiver of a pass
  Point2D target;                    // the job's target point
  Point2D defense;                   // DefendGoal's point
  bool obstacle = false;
  Point2D obstacle_at;
  std::string job;                   // the coordination job/role ("BringBall", "PassageToMate.passer", "")
  double area_time = 0.0;            // s in the opponents' penalty area so far
};

/// A shot at the goal's open side (doc/shooting.md), from `from` (the
/// ball): the aim, aim_offset beside the goal centre on the near post's side
/// (the side of `from`, with hysteresis); the shooting spot on that side;
/// whether the line clears the keeper (the obstacle nearest the goal centre)
/// by keeper_clearance and every other obstacle by shot_clearance, within
/// shot_range.
struct Shot {
  double side = 1.0;                 // +1: the +y side of the goal
  Point2D aim, spot;
  double keeper_clearance = 0.0;     // m (infinite: no keeper)
  bool clear = false;
};

/// `obstacles`: the other robots' positions; `side`: the side chosen last
/// (0: none yet, the side of `from`).
Shot plan_shot(const Point2D& from, const std::vector<Point2D>& obstacles, double side, const SituationOptions& o);

/// Turns the inputs into crisp data, keeping the time spent in the
/// opponents' penalty area between cycles.
class SituationAssessor {
 public:
  explicit SituationAssessor(SituationOptions o = {});

  Situation assess(const SituationInput& in);
  /// The crisp data of `s` seen from `pose` (mm, degrees in (-180, 180],
  /// flags 0/1, seconds).
  brian::CrispDataList crisp(const Situation& s, const Pose2D& pose, const Parameters& coordination) const;
  const SituationOptions& options() const { return o_; }

 private:
  void coordination_targets(const SituationInput& in, Situation& s) const;
  void shot(const SituationInput& in, Situation& s);

  SituationOptions o_;
  double area_since_ = -1.0;  // s, -1: not in the area
  double aim_side_ = 0.0;     // +1: aim at the +y side of the goal, 0: not yet chosen
};

/// The job of SCARE's crisp output: "Activity" for a job, "Activity.role"
/// for a schema's role, "" when none is 1.
std::string job_of(const Parameters& p);

/// Distance (m) of `p` from the segment a-b.
double segment_distance(const Point2D& a, const Point2D& b, const Point2D& p);

/// Distance (mm) and bearing (degrees, (-180, 180]) of `p` from `pose`.
double distance_mm(const Pose2D& pose, const Point2D& p);
double bearing_deg(const Pose2D& pose, const Point2D& p);

}  // namespace mrt::robocup
