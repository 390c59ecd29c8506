#include "mrt_robocup/situation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrt::robocup {
namespace {

constexpr double kMissing = 99999.0;  // mm: "far away", with reliability 0

double dist(const Point2D& a, const Point2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

double param(const Parameters& p, const std::string& name) {
  const auto it = p.find(name);
  return it == p.end() ? 0.0 : it->second.value * it->second.reliability;
}

}  // namespace

double segment_distance(const Point2D& a, const Point2D& b, const Point2D& p) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return dist({a.x + t * dx, a.y + t * dy}, p);
}

double distance_mm(const Pose2D& pose, const Point2D& p) { return 1000.0 * std::hypot(p.x - pose.x, p.y - pose.y); }

double bearing_deg(const Pose2D& pose, const Point2D& p) {
  return common::rad_to_deg(common::normalize_angle(std::atan2(p.y - pose.y, p.x - pose.x) - pose.theta));
}

std::string job_of(const Parameters& p) {
  // ScareJob_<Activity> names a job; a schema's role is ScareRole_<Activity>_<role>.
  for (const auto& [name, v] : p) {
    if (v.value < 0.5) continue;
    if (name.rfind("ScareRole_", 0) == 0) {
      const std::string rest = name.substr(10);
      const auto us = rest.rfind('_');
      if (us != std::string::npos) return rest.substr(0, us) + "." + rest.substr(us + 1);
    }
  }
  for (const auto& [name, v] : p)
    if (v.value >= 0.5 && name.rfind("ScareJob_", 0) == 0) return name.substr(9);
  return "";
}

SituationAssessor::SituationAssessor(SituationOptions o) : o_(std::move(o)) {}

Situation SituationAssessor::assess(const SituationInput& in) {
  Situation s;
  const Point2D me{in.pose.x, in.pose.y};
  double nearest = std::numeric_limits<double>::infinity();
  for (const AnchorView& a : in.anchors) {
    if (a.reliability < o_.min_reliability) continue;
    const Point2D p{a.x, a.y};
    if (a.membership_class == o_.ball_class) {
      if (a.reliability > s.ball_reliability) {
        s.ball_seen = true;
        s.ball = p;
        s.ball_reliability = a.reliability;
      }
    } else if (std::find(o_.obstacle_classes.begin(), o_.obstacle_classes.end(), a.membership_class) !=
               o_.obstacle_classes.end()) {
      const double d = dist(me, p);
      // Closer than a body radius + 0.15 m: the robot itself (its teammates'
      // sightings of it), nothing else fits there.
      if (d > o_.body_radius + 0.15 && d < nearest) {
        nearest = d;
        s.obstacle = true;
        s.obstacle_at = p;
      }
    }
  }
  if (in.possession_known) {
    s.owned = in.possession;
  } else if (s.ball_seen) {
    s.owned = dist(me, s.ball) <= o_.body_radius + o_.ball_radius + o_.possession_gap &&
              std::abs(bearing_deg(in.pose, s.ball)) <= o_.possession_angle;
  }
  s.job = job_of(in.coordination);
  coordination_targets(in, s);
  shot(in, s);
  // Time in the opponents' penalty area (MSL: a robot may not stay there).
  const FieldGeometry& f = o_.field;
  const bool in_area = in.pose.x >= f.goal_x - f.penalty_depth && std::abs(in.pose.y) <= f.penalty_half_width;
  if (!in_area) area_since_ = -1.0;
  else if (area_since_ < 0.0) area_since_ = in.time;
  s.area_time = in_area ? in.time - area_since_ : 0.0;
  return s;
}

void SituationAssessor::coordination_targets(const SituationInput& in, Situation& s) const {
  const FieldGeometry& f = o_.field;
  const Point2D own_goal{-f.goal_x, 0.0};
  // DefendGoal's point: on the line from the own goal centre to the ball.
  if (s.ball_seen) {
    // Never onto the ball: at least 1 m short of it, at least 0.5 m out of the goal.
    const double d = std::max(dist(own_goal, s.ball), 1e-6);
    const double k = std::max(0.5, std::min(o_.defense_distance, d - 1.0)) / d;
    s.defense = {own_goal.x + k * (s.ball.x - own_goal.x), own_goal.y + k * (s.ball.y - own_goal.y)};
  } else {
    s.defense = {own_goal.x + o_.defense_distance, 0.0};
  }
  const double mx = param(in.coordination, "ScareMate_receiver_X"),
               my = param(in.coordination, "ScareMate_receiver_Y");
  const auto rx = in.coordination.find("ScareMate_receiver_X");
  s.mate_known = rx != in.coordination.end() && rx->second.reliability > 0.0;
  s.mate = {mx, my};
  // The job's target point (where GoToTarget/KeepPosition take the robot).
  if (s.job == "Defense") {
    s.target = s.defense;
  } else if (s.job == "PassageToMate.receiver") {
    const double bx = s.ball_seen ? s.ball.x : 0.0, by = s.ball_seen ? s.ball.y : 0.0;
    // 3 m ahead of the ball, on the receiver's own side of the field.
    (void)by;
    s.target = {std::clamp(bx + 3.0, -f.goal_x + 3.0, f.goal_x - f.penalty_depth - 0.5), in.pose.y >= 0.0 ? 2.5 : -2.5};
  } else if (s.job == "DefensiveDoubling.cover") {
    s.target = {-f.goal_x + 2.5, 0.0};
  } else if (s.job == "Blocking.blocker" && s.ball_seen) {
    // Between the ball and the own goal, 1.5 m from the ball.
    const double d = std::max(dist(own_goal, s.ball), 1e-6), k = std::min(1.5, d) / d;
    s.target = {s.ball.x + k * (own_goal.x - s.ball.x), s.ball.y + k * (own_goal.y - s.ball.y)};
  } else if (s.job == "Blocking.cover") {
    s.target = {-2.0, 0.0};
  } else if (s.ball_seen && s.job != "Positioning" && !s.job.empty()) {
    s.target = s.ball;
  } else {
    s.target = o_.home;
  }
}

Shot plan_shot(const Point2D& from, const std::vector<Point2D>& obstacles, double side, const SituationOptions& o) {
  const FieldGeometry& f = o.field;
  const Point2D centre{f.goal_x, 0.0};
  // The keeper: the obstacle nearest the goal centre, within keeper_zone.
  const Point2D* keeper = nullptr;
  double best = o.keeper_zone;
  for (const Point2D& p : obstacles)
    if (dist(p, centre) < best) {
      best = dist(p, centre);
      keeper = &p;
    }
  const double aim_y = std::min(o.aim_offset, f.goal_half_width - o.ball_radius);
  const auto aim_at = [&](double sd) { return Point2D{f.goal_x, sd * aim_y}; };
  // The open side: the near post's, the side the ball is on. The keeper
  // stands on the line goal centre - ball: a shot to the near post moves
  // away from it faster than it follows (1.5 against 8 m/s), one across
  // that line draws it into the ball's path (doc/shooting.md). Near the
  // axis the side chosen last stays (hysteresis).
  Shot s;
  s.side = side != 0.0 ? (side > 0.0 ? 1.0 : -1.0) : (from.y >= 0.0 ? 1.0 : -1.0);
  if (from.y * s.side < -o.side_hysteresis) s.side = -s.side;
  s.aim = aim_at(s.side);
  s.spot = {f.goal_x - o.spot_depth, s.side * o.spot_offset};
  s.keeper_clearance = keeper ? segment_distance(from, s.aim, *keeper) : std::numeric_limits<double>::infinity();
  s.clear = dist(from, s.aim) <= o.shot_range && s.keeper_clearance >= o.keeper_clearance;
  for (const Point2D& p : obstacles)
    if (segment_distance(from, s.aim, p) < o.shot_clearance) s.clear = false;
  return s;
}

void SituationAssessor::shot(const SituationInput& in, Situation& s) {
  const Point2D me{in.pose.x, in.pose.y};
  std::vector<Point2D> obstacles;
  for (const AnchorView& a : in.anchors) {
    if (a.reliability < o_.min_reliability || a.membership_class == o_.ball_class) continue;
    if (std::find(o_.obstacle_classes.begin(), o_.obstacle_classes.end(), a.membership_class) ==
        o_.obstacle_classes.end())
      continue;
    const Point2D p{a.x, a.y};
    if (dist(p, me) > o_.body_radius + 0.15) obstacles.push_back(p);  // nearer: itself
  }
  // The shot leaves from the ball when it is held (it sits at the kicker).
  const Shot shot = plan_shot(s.owned && s.ball_seen ? s.ball : me, obstacles, aim_side_, o_);
  aim_side_ = shot.side;
  s.aim = shot.aim;
  s.spot = shot.spot;
  s.shot_clear = shot.clear;
  s.keeper_clearance = shot.keeper_clearance;
}

brian::CrispDataList SituationAssessor::crisp(const Situation& s, const Pose2D& pose,
                                              const Parameters& coordination) const {
  brian::CrispDataList c;
  auto add = [&c](const char* name, double v, double r = 1.0) { c.push_back({name, v, r}); };
  auto place = [&](const char* d, const char* a, bool known, const Point2D& p, double r = 1.0) {
    add(d, known ? distance_mm(pose, p) : kMissing, known ? r : 0.0);
    add(a, known ? bearing_deg(pose, p) : 0.0, known ? r : 0.0);
  };
  place("BallDistance", "BallAngle", s.ball_seen, s.ball, s.ball_reliability);
  add("BallSeen", s.ball_reliability);
  add("BallOwned", s.owned ? 1.0 : 0.0);
  place("GoalDistance", "GoalAngle", true, s.aim);
  place("SpotDistance", "SpotAngle", true, s.spot);
  add("ShotClear", s.shot_clear ? 1.0 : 0.0);
  place("OwnGoalDistance", "OwnGoalAngle", true, Point2D{-o_.field.goal_x, 0.0});
  place("MateDistance", "MateAngle", s.mate_known, s.mate);
  add("MateKnown", s.mate_known ? 1.0 : 0.0);
  place("TargetDistance", "TargetAngle", true, s.target);
  // The gap between the bodies (obstacles taken as robots of this size).
  const double gap = s.obstacle ? std::max(0.0, distance_mm(pose, s.obstacle_at) - 2000.0 * o_.body_radius) : kMissing;
  add("ObstacleDistance", gap, s.obstacle ? 1.0 : 0.0);
  add("ObstacleAngle", s.obstacle ? bearing_deg(pose, s.obstacle_at) : 0.0, s.obstacle ? 1.0 : 0.0);
  const bool ball_first = s.ball_seen && !s.owned && (!s.obstacle || distance_mm(pose, s.ball) < distance_mm(pose, s.obstacle_at));
  add("BallBeforeObstacle", ball_first ? 1.0 : 0.0);
  add("AreaTime", s.area_time);
  // Coordination information (SCARE's crisp output) under the rule base's names.
  const auto flag = [&](const char* name, std::initializer_list<const char*> sources) {
    double v = 0.0;
    for (const char* src : sources) v = std::max(v, param(coordination, src));
    add(name, v);
  };
  flag("JobBringBall", {"ScareJob_BringBall"});
  flag("JobRecoverBall", {"ScareJob_RecoverWanderingBall"});
  flag("JobDefense", {"ScareJob_Defense"});
  flag("JobPositioning", {"ScareJob_Positioning"});
  flag("RolePasser", {"ScareRole_PassageToMate_passer"});
  flag("RoleReceiver", {"ScareRole_PassageToMate_receiver"});
  flag("RoleTackler", {"ScareRole_DefensiveDoubling_tackler"});
  flag("RoleBlocker", {"ScareRole_Blocking_blocker"});
  flag("RoleCover", {"ScareRole_DefensiveDoubling_cover", "ScareRole_Blocking_cover"});
  return c;
}

}  // namespace mrt::robocup
