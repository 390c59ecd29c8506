#include "mrt_robocup/team_crisp.h"

#include <algorithm>
#include <cmath>

namespace mrt::robocup {

scare::CrispMap team_crisp(const std::vector<AnchorView>& anchors, bool team_owns, const SituationOptions& o) {
  const FieldGeometry& f = o.field;
  scare::CrispMap c;
  const AnchorView* ball = nullptr;
  for (const AnchorView& a : anchors)
    if (a.membership_class == "Ball" && (!ball || a.reliability > ball->reliability)) ball = &a;
  if (!ball) {
    c["BallSeen"] = {0.0, 1.0};
    c["BallOwned"] = {team_owns ? 1.0 : 0.0, 1.0};
    return c;
  }
  const double bx = ball->x, by = ball->y, rel = ball->reliability;
  c["BallX"] = {bx, rel};
  c["BallY"] = {by, rel};
  c["BallSeen"] = {rel, 1.0};
  c["BallOwned"] = {team_owns ? 1.0 : 0.0, 1.0};
  // The carrier's way to goal (situation.h plan_shot, without the
  // player's side hysteresis): from beyond the shooting spot, the line from
  // the ball to the spot on the goal's open side; from nearer, the shot.
  std::vector<Point2D> opponents;
  double threat = 0.0;
  for (const AnchorView& a : anchors) {
    if (a.membership_class != "Opponent") continue;
    opponents.push_back({a.x, a.y});
    if (bx < -f.goal_x / 3.0 && std::hypot(a.x - bx, a.y - by) < 1.5) threat = 1.0;
  }
  // The job follows whether a shot is possible at all (the keeper beyond
  // shot_clearance too); the carrier's kick waits for keeper_clearance.
  SituationOptions team = o;
  team.keeper_clearance = o.shot_clearance;
  const Point2D ball_at{bx, by};
  const Shot shot = plan_shot(ball_at, opponents, 0.0, team);
  const double to_aim = std::hypot(shot.aim.x - bx, shot.aim.y - by);
  bool clear = shot.clear;
  if (to_aim > std::hypot(shot.aim.x - shot.spot.x, shot.aim.y - shot.spot.y) + 0.5) {
    clear = true;
    for (const Point2D& p : opponents)
      if (segment_distance(ball_at, shot.spot, p) < o.shot_clearance) clear = false;
  }
  // Far from the goal the carrier dribbles on (BringBall): a pass is for a
  // blocked way within shot_range.
  if (to_aim > o.shot_range) clear = true;
  c["ShotClear"] = {clear ? 1.0 : 0.0, 1.0};
  c["Threat"] = {threat, 1.0};
  c["ReceiveX"] = {std::clamp(bx + 3.0, -f.goal_x + 3.0, f.goal_x - f.penalty_depth - 0.5), rel};
  c["ReceiveY"] = {by > 0.0 ? -2.0 : 2.0, rel};
  return c;
}

}  // namespace mrt::robocup
