#include "mrt_followme/visitor_model.h"

#include <cmath>
#include <utility>

namespace mrt::followme {

namespace {

double dist(const Point2D& a, const Point2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

constexpr double kTrailStep = 0.1;   // m between trail points
constexpr double kAtTarget = 0.05;   // m: arrived
constexpr double kRobotStill = 0.6;  // m from the stop: the robot waits there

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

// The trail point about `comfortable` metres behind the robot along its
// path; straight towards the robot when the trail is shorter (or the
// visitor nearer to the robot than that point).
VisitorStep VisitorModel::follow(const Point2D& self, const Pose2D& robot) const {
  const Point2D r{robot.x, robot.y};
  const double d = dist(self, r);
  if (d <= opt_.comfortable + 0.25) return {self, 0.0};
  Point2D target{r.x + (self.x - r.x) * opt_.comfortable / d, r.y + (self.y - r.y) * opt_.comfortable / d};
  double along = 0.0;
  for (std::size_t i = trail_.size(); i-- > 1;) {
    along += dist(trail_[i], trail_[i - 1]);
    if (along >= opt_.comfortable) {
      if (dist(self, trail_[i - 1]) < d) target = trail_[i - 1];
      break;
    }
  }
  return {target, opt_.walk_speed};
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
        return {next->spot, opt_.walk_speed};
      }
      return follow(self, robot);
    case VisitorState::kGoToExhibit:
      if (dist(self, next->spot) < kAtTarget) enter(VisitorState::kLook, t);
      return {next->spot, opt_.walk_speed};
    case VisitorState::kLook:
      if (t - since_ < opt_.look_time) return {self, 0.0};
      ++looked_;
      if (!wandered_ && opt_.wander_after > 0 && looked_ == static_cast<std::size_t>(opt_.wander_after)) {
        wandered_ = true;
        called_ = false;
        enter(VisitorState::kWander, t);
        return {wander_.spot, opt_.walk_speed};
      }
      enter(VisitorState::kReturn, t);
      return {r, opt_.walk_speed};
    case VisitorState::kWander:
      if (dist(self, wander_.spot) < kAtTarget) enter(VisitorState::kStay, t);
      return {wander_.spot, opt_.walk_speed};
    case VisitorState::kStay:
      if (called_ || t - since_ >= opt_.wander_stay) {
        came_back_called_ = called_;
        enter(VisitorState::kReturn, t);
        return {r, opt_.walk_speed};
      }
      return {self, 0.0};
    case VisitorState::kReturn:
      if (dist(self, r) <= opt_.comfortable + 0.1) {
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
