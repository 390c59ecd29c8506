#include "mrt_followme/visitor_model.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

namespace mrt::followme {

namespace {

double dist(const Point2D& a, const Point2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

constexpr double kTrailStep = 0.1;   // m between trail points
constexpr double kAtTarget = 0.05;   // m: arrived
constexpr double kRobotStill = 0.6;  // m from the stop: the robot waits there
constexpr double kPassRobot = 1.0;   // m: a visitor walking by passes the robot's centre no closer

// Where to walk to reach `target` without brushing past the robot: the
// target itself, or first a point beside the robot when the straight way
// passes closer than kPassRobot to it.
Point2D around_robot(const Point2D& self, const Point2D& target, const Point2D& r) {
  const double dx = target.x - self.x, dy = target.y - self.y, l2 = dx * dx + dy * dy;
  if (l2 < 1e-12) return target;
  const double t = std::clamp(((r.x - self.x) * dx + (r.y - self.y) * dy) / l2, 0.0, 1.0);
  const Point2D c{self.x + t * dx, self.y + t * dy};
  if (dist(c, r) >= kPassRobot || t >= 1.0) return target;
  const double l = std::sqrt(l2), nx = -dy / l, ny = dx / l;
  const double side = (c.x - r.x) * nx + (c.y - r.y) * ny >= 0.0 ? 1.0 : -1.0;
  return {r.x + side * nx * (kPassRobot + 0.2), r.y + side * ny * (kPassRobot + 0.2)};
}

// The visitor's place on the trail: its nearest trail point, unless the
// robot came by the same place again later (it turned back: out to an
// exhibit and back, a re-planned leg): then its nearest point of that later
// pass. A trail point within kSamePlace of the nearest distance whose way
// to the robot is shorter by more than kOtherPass belongs to a later pass;
// points of one pass that near the visitor differ by less along the trail.
// Without this the visitor, standing where the trail crosses itself, could
// take the earlier pass and walk the robot's old way back and forth.
std::size_t place_on_trail(const std::deque<Point2D>& trail, const std::vector<double>& rest, const Point2D& self) {
  constexpr double kSamePlace = 0.3;  // m
  constexpr double kOtherPass = 1.5;  // m along the trail
  std::size_t j = 0;
  for (std::size_t k = 1; k < trail.size(); ++k)
    if (dist(self, trail[k]) < dist(self, trail[j])) j = k;
  if (trail.empty()) return j;
  const double near = dist(self, trail[j]) + kSamePlace;
  double latest = rest[j];  // the shortest way to the robot from a point that near
  for (std::size_t k = 0; k < trail.size(); ++k)
    if (dist(self, trail[k]) <= near) latest = std::min(latest, rest[k]);
  if (latest >= rest[j] - kOtherPass) return j;
  std::size_t best = trail.size();
  for (std::size_t k = 0; k < trail.size(); ++k)
    if (dist(self, trail[k]) <= near && rest[k] <= latest + kOtherPass &&
        (best == trail.size() || dist(self, trail[k]) < dist(self, trail[best])))
      best = k;
  return best;
}

}  // namespace

const char* to_string(VisitorState s) {
  switch (s) {
    case VisitorState::kFollow: return "follow";
    case VisitorState::kGoToExhibit: return "go_to_exhibit";
    case VisitorState::kLook: return "look";
    case VisitorState::kWander: return "wander";
    case VisitorState::kStay: return "stay";
    case VisitorState::kReturn: return "return";
  }
  return "?";
}

VisitorModel::VisitorModel(VisitorOptions options, std::vector<Exhibit> tour, Exhibit wander)
    : opt_(std::move(options)), tour_(std::move(tour)), wander_(std::move(wander)) {}

void VisitorModel::enter(VisitorState s, double t) {
  state_ = s;
  since_ = t;
}

// Follows the robot along its trail: the distance that counts is the way
// along the trail (through the door the robot took, not through the wall).
// It stands once within comfortable + 0.25 m that way; else it walks to the
// trail point at most 0.5 m ahead of its nearest one, and never past the
// point `comfortable` metres behind the robot. With no trail to speak of,
// straight to the point `comfortable` metres from the robot.
VisitorStep VisitorModel::follow(const Point2D& self, const Pose2D& robot) const {
  const Point2D r{robot.x, robot.y};
  // rest[k]: the way from trail point k to the robot
  std::vector<double> rest(trail_.size(), 0.0);
  for (std::size_t k = trail_.size(); k-- > 0;)
    rest[k] = k + 1 < trail_.size() ? rest[k + 1] + dist(trail_[k], trail_[k + 1]) : dist(trail_[k], r);
  const std::size_t j = place_on_trail(trail_, rest, self);
  const double way = trail_.empty() ? dist(self, r) : std::min(dist(self, r) < 0.5 ? dist(self, r) : 1e9,
                                                                 dist(self, trail_[j]) + rest[j]);
  if (way <= opt_.comfortable + 0.25) return {self, 0.0};
  std::size_t last = trail_.size();  // the last trail point still `comfortable` from the robot
  for (std::size_t k = 0; k < trail_.size(); ++k)
    if (rest[k] >= opt_.comfortable) last = k;
  if (last == trail_.size() || last < j) {
    const double d = dist(self, r);
    return {{r.x + (self.x - r.x) * opt_.comfortable / d, r.y + (self.y - r.y) * opt_.comfortable / d},
            opt_.walk_speed};
  }
  std::size_t k = j;
  while (k < last && dist(trail_[j], trail_[k + 1]) <= 0.5) ++k;
  if (k == j && k < last) ++k;
  return {trail_[k], opt_.walk_speed};
}

VisitorStep VisitorModel::update(double t, const Point2D& self, const Pose2D& robot) {
  const Point2D r{robot.x, robot.y};
  if (trail_.empty() || dist(trail_.back(), r) >= kTrailStep) trail_.push_back(r);
  while (trail_.size() > 400) trail_.pop_front();
  const Exhibit* next = looked_ < tour_.size() ? &tour_[looked_] : nullptr;
  switch (state_) {
    case VisitorState::kFollow:
      if (next && dist(r, next->stop) < kRobotStill) {
        enter(VisitorState::kGoToExhibit, t);
        return {around_robot(self, next->spot, r), opt_.walk_speed};
      }
      return follow(self, robot);
    case VisitorState::kGoToExhibit:
      if (dist(self, next->spot) < kAtTarget) enter(VisitorState::kLook, t);
      return {around_robot(self, next->spot, r), opt_.walk_speed};
    case VisitorState::kLook:
      if (t - since_ < opt_.look_time) return {self, 0.0};
      ++looked_;
      if (!wandered_ && opt_.wander_after > 0 && looked_ == static_cast<std::size_t>(opt_.wander_after)) {
        wandered_ = true;
        called_ = false;
        enter(VisitorState::kWander, t);
        return {around_robot(self, wander_.spot, r), opt_.walk_speed};
      }
      enter(VisitorState::kReturn, t);
      return {r, opt_.walk_speed};
    case VisitorState::kWander:
      if (dist(self, wander_.spot) < kAtTarget) enter(VisitorState::kStay, t);
      return {around_robot(self, wander_.spot, r), opt_.walk_speed};
    case VisitorState::kStay:
      if (called_ || t - since_ >= opt_.wander_stay) {
        came_back_called_ = called_;
        enter(VisitorState::kReturn, t);
        return {r, opt_.walk_speed};
      }
      return {self, 0.0};
    case VisitorState::kReturn:
      if (dist(self, r) <= opt_.return_distance) {
        enter(VisitorState::kFollow, t);
        trail_.clear();
        trail_.push_back(r);
        return {self, 0.0};
      }
      return {r, opt_.walk_speed};
  }
  return {self, 0.0};
}

}  // namespace mrt::followme
