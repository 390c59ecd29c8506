#include "mrt_scare/coordinator.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace mrt::scare {

double StraightLineCost::time(const RobotSpec& robot, const Pose2D& from, const Point2D& to) const {
  return std::hypot(to.x - from.x, to.y - from.y) / robot.max_speed;
}

RobotView robot_view(const ActivitySet& set, const RobotSpec& robot, const Pose2D& pose, const CrispMap& crisp,
                     const CostModel& cost) {
  RobotView v;
  v.id = robot.id;
  for (const Slot& sl : set.slots()) {
    v.attitude.push_back(set.attitude(robot, sl));
    const Target& t =
        set.activities[static_cast<std::size_t>(sl.activity)].roles[static_cast<std::size_t>(sl.role)].target;
    double time = 0.0;
    if (t.kind == Target::Kind::kFixed) {
      time = cost.time(robot, pose, {t.x, t.y});
    } else if (t.kind == Target::Kind::kCrisp) {
      const auto x = crisp.find(t.x_datum), y = crisp.find(t.y_datum);
      time = x == crisp.end() || y == crisp.end() ? std::numeric_limits<double>::infinity()
                                                  : cost.time(robot, pose, {x->second.first, y->second.first});
    }
    v.time.push_back(time);
  }
  return v;
}

Coordinator::Coordinator(ActivitySet set, RobotSpec self, CoordinatorOptions o, std::shared_ptr<const CostModel> cost)
    : allocator_(set), self_(std::move(self)), options_(o),
      cost_(cost ? std::move(cost) : std::make_shared<StraightLineCost>()), slots_(set.slots()) {}

double age_confidence(double age, const CoordinatorOptions& o) {
  if (age <= o.grace) return 1.0;
  const double span = o.drop_timeout - o.grace;
  const double f = span > 0.0 ? std::min(1.0, (age - o.grace) / span) : 1.0;
  return 1.0 - f * (1.0 - o.min_confidence);
}

CoordinationMessage Coordinator::publish(double now, const Pose2D& pose, const CrispMap& crisp) {
  const ActivitySet& s = set();
  CoordinationMessage m;
  m.robot_id = self_.id;
  m.seq = ++seq_;
  m.stamp = now;
  if (started_ < 0.0) started_ = now;
  m.x = pose.x;
  m.y = pose.y;
  m.intention = own_slot_;
  if (own_slot_ >= 0) m.held = now - since_;
  s.model->evaluate(crisp);
  m.opportunity = s.opportunities();
  RobotView v = robot_view(s, self_, pose, crisp, *cost_);
  m.attitude = std::move(v.attitude);
  m.time = std::move(v.time);
  for (const auto& [id, t] : team_)
    if (id != self_.id) m.heard.emplace_back(id, newest(id, t));
  for (auto it = handed_back_.begin(); it != handed_back_.end();) {
    if (now < it->second) m.attitude[static_cast<std::size_t>(it->first)] = 0.0;
    it = now < it->second ? std::next(it) : handed_back_.erase(it);
  }
  team_[self_.id] = m;
  return m;
}

bool Coordinator::receive(const CoordinationMessage& m) {
  if (m.robot_id.empty() || m.robot_id == self_.id) return m.robot_id == self_.id;
  if (m.leaving) {
    if (team_.count(m.robot_id)) drop(m.robot_id);
    else forget(m.robot_id);
    return true;
  }
  const auto n = slots_.size();
  bool ok = m.attitude.size() == n && m.time.size() == n && m.opportunity.size() == set().activities.size() &&
            m.intention >= -1 && m.intention < static_cast<int>(n) && std::isfinite(m.stamp) &&
            std::isfinite(m.x) && std::isfinite(m.y) && m.held >= 0.0;
  for (std::size_t i = 0; ok && i < n; ++i)
    ok = m.attitude[i] >= 0.0 && m.attitude[i] <= 1.0 && m.time[i] >= 0.0;  // NaN fails too
  for (std::size_t i = 0; ok && i < m.opportunity.size(); ++i) ok = m.opportunity[i] >= 0.0 && m.opportunity[i] <= 1.0;
  if (!ok) return false;
  const auto it = team_.find(m.robot_id);
  if (it == team_.end() || m.seq > it->second.seq || m.stamp > it->second.stamp) {
    if (it != team_.end()) update_rate(it->second, m);
    team_[m.robot_id] = m;
  }
  // Gossip only delays the drop of a teammate still held (never re-adds one).
  for (const auto& [id, stamp] : m.heard)
    if (id != self_.id && std::isfinite(stamp) && team_.count(id) && stamp > heard_[id]) heard_[id] = stamp;
  return true;
}

void Coordinator::update_rate(const CoordinationMessage& before, const CoordinationMessage& m) {
  std::vector<double>& rate = time_rate_[m.robot_id];
  rate.assign(m.time.size(), 0.0);
  const double dt = m.stamp - before.stamp;
  for (std::size_t i = 0; dt > 0.0 && i < m.time.size() && i < before.time.size(); ++i)
    if (std::isfinite(m.time[i]) && std::isfinite(before.time[i]))
      rate[i] = std::clamp((m.time[i] - before.time[i]) / dt, -options_.max_time_rate, options_.max_time_rate);
}

void Coordinator::drop(const std::string& id) {
  const int slot = team_.at(id).intention;
  if (slot >= 0) vacated_.push_back(slot);
  forget(id);
  ++drops_;
}

void Coordinator::forget(const std::string& id) {
  team_.erase(id);
  heard_.erase(id);
  time_rate_.erase(id);
}

double Coordinator::newest(const std::string& id, const CoordinationMessage& m) const {
  const auto h = heard_.find(id);
  return h == heard_.end() ? m.stamp : std::max(m.stamp, h->second);
}

TeamInput Coordinator::team_input(double now) const {
  TeamInput in;
  in.opportunity.assign(set().activities.size(), 0.0);
  for (const auto& [id, m] : team_) {  // by id: the same sum on every robot
    RobotView v;
    v.id = id;
    v.attitude = m.attitude;
    v.time = m.time;
    // A teammate's message is at least one cycle old (this robot's own is
    // of now): its times are brought to now with their rate over the
    // sender's last two messages, so that two robots moving the same way do
    // not each see the other nearer than it is.
    const auto rate = time_rate_.find(id);
    const double ahead = std::min(std::max(0.0, now - m.stamp), options_.grace);
    if (rate != time_rate_.end())
      for (std::size_t i = 0; i < v.time.size(); ++i) v.time[i] = std::max(0.0, v.time[i] + rate->second[i] * ahead);
    v.incumbent = m.intention;
    v.held = m.held + std::max(0.0, now - m.stamp);  // inf stays inf
    v.confidence = id == self_.id ? 1.0 : confidence(std::max(0.0, now - m.stamp));
    in.robots.push_back(std::move(v));
    for (std::size_t a = 0; a < in.opportunity.size(); ++a) in.opportunity[a] += m.opportunity[a];
  }
  if (!team_.empty())
    for (double& o : in.opportunity) o /= static_cast<double>(team_.size());
  return in;
}

Allocation Coordinator::step(double now) {
  for (auto it = team_.begin(); it != team_.end();) {
    // Dropped when neither this robot nor, by their gossip, its teammates
    // have heard it for drop_timeout: survivors whose own copy of its last
    // message was lost drop it with the others, not a cycle earlier.
    if (it->first != self_.id && now - newest(it->first, it->second) > options_.drop_timeout) {
      const std::string id = (it++)->first;
      drop(id);
    } else {
      ++it;
    }
  }
  TeamInput in = team_input(now);
  // A drop-out is re-assigned at once: in that cycle nobody's dwell holds,
  // and its slot carries the hysteresis its holder had (the survivors' own
  // hysteresis alone could outweigh filling it, and leave a free ball to
  // nobody).
  in.vacated = std::move(vacated_);
  vacated_.clear();
  if (drops_ != drops_seen_)
    for (RobotView& v : in.robots) v.held = std::numeric_limits<double>::infinity();
  drops_seen_ = drops_;
  last_ = allocator_.allocate(std::move(in));
  int want = -1;
  for (std::size_t i = 0; i < last_.robots.size(); ++i)
    if (last_.robots[i] == self_.id) want = last_.slot[i];
  // Release before acquire: a slot still claimed by as many teammates as its
  // role holds is taken only once they have announced they left it; until
  // then this robot holds nothing (so that swaps cannot deadlock).
  // A robot that has just started listens first: what it has not yet heard
  // of its teammates could make it take a slot one of them holds.
  waiting_ = want >= 0 && (started_ < 0.0 || now - started_ < options_.listen);
  if (!waiting_ && want >= 0 && want != own_slot_) {
    const Slot& sl = slots_[static_cast<std::size_t>(want)];
    int claims = 0;
    for (const auto& [id, m] : team_) claims += id != self_.id && m.intention == want;
    waiting_ = claims >= set().activities[static_cast<std::size_t>(sl.activity)].roles[static_cast<std::size_t>(sl.role)].max;
  }
  own_slot_ = waiting_ ? -1 : want;
  // The dwell counts from taking a slot other than the last one held (a
  // wait in between does not restart it when the robot comes back).
  if (own_slot_ >= 0 && own_slot_ != last_held_) {
    since_ = now;
    last_held_ = own_slot_;
  }
  return last_;
}

bool Coordinator::hand_back(const std::string& slot, double now) {
  const int s = set().find_slot(slot);
  if (s < 0) return false;
  handed_back_[s] = now + options_.hand_back_penalty;
  if (own_slot_ == s) own_slot_ = -1;
  return true;
}

std::vector<CrispOut> Coordinator::crisp_output() const {
  const ActivitySet& s = set();
  std::vector<CrispOut> out;
  const int own_activity = own_slot_ >= 0 ? slots_[static_cast<std::size_t>(own_slot_)].activity : -1;
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    const ActivitySpec& a = s.activities[static_cast<std::size_t>(slots_[k].activity)];
    if (slots_[k].role == 0) out.push_back({"ScareJob_" + a.name, own_activity == slots_[k].activity ? 1.0 : 0.0, 1.0});
    if (a.schema)
      out.push_back({"ScareRole_" + a.name + "_" + a.roles[static_cast<std::size_t>(slots_[k].role)].name,
                     own_slot_ == static_cast<int>(k) ? 1.0 : 0.0, 1.0});
  }
  if (own_activity >= 0 && s.activities[static_cast<std::size_t>(own_activity)].schema) {
    for (std::size_t i = 0; i < last_.robots.size(); ++i) {
      const int sl = last_.slot[i];
      if (sl < 0 || sl == own_slot_ || slots_[static_cast<std::size_t>(sl)].activity != own_activity) continue;
      const auto it = team_.find(last_.robots[i]);
      if (it == team_.end()) continue;
      const std::string p = "ScareMate_" + s.activities[static_cast<std::size_t>(own_activity)]
                                               .roles[static_cast<std::size_t>(slots_[static_cast<std::size_t>(sl)].role)]
                                               .name;
      out.push_back({p + "_X", it->second.x, 1.0});
      out.push_back({p + "_Y", it->second.y, 1.0});
      out.push_back({p + "_Index", static_cast<double>(i + 1), 1.0});
    }
  }
  out.push_back({"ScareTeamSize", static_cast<double>(last_.robots.size()), 1.0});
  return out;
}

}  // namespace mrt::scare
