// The match: kickers, ball handling, scripted opponents and the automatic
// referee, as a step hook of the simulator (see match.h and doc/match.md).
#include "mrt_robocup/match.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::robocup {

using common::Point2D;
using mrt::common::normalize_angle;
using sim::Ball;
using sim::Goal;
using sim::Mover;
using sim::RobotState;
using sim::Simulator;
using sim::World;

namespace {

double dist(const Point2D& a, const Point2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
Point2D sub(const Point2D& a, const Point2D& b) { return {a.x - b.x, a.y - b.y}; }
Point2D add(const Point2D& a, const Point2D& b, double k = 1.0) { return {a.x + k * b.x, a.y + k * b.y}; }
double dot(const Point2D& a, const Point2D& b) { return a.x * b.x + a.y * b.y; }
Point2D unit(const Point2D& v, const Point2D& fallback = {1.0, 0.0}) {
  const double n = std::hypot(v.x, v.y);
  return n > 1e-12 ? Point2D{v.x / n, v.y / n} : fallback;
}
Point2D mouth(const Goal& g) { return {g.pose.x, g.pose.y}; }
Point2D into(const Goal& g) { return {std::cos(g.pose.theta), std::sin(g.pose.theta)}; }
Point2D across(const Goal& g) { return {-std::sin(g.pose.theta), std::cos(g.pose.theta)}; }

// The field's frame: the centre between the goal mouths, the axis towards
// the other goal, the normal to the left of it, half the mouths' distance.
struct FieldFrame {
  Point2D centre, axis, normal;
  double half_length;
};
FieldFrame field_frame(const Goal& own, const Goal& other) {
  const Point2D c0 = mouth(own), c1 = mouth(other), axis = unit(sub(c1, c0));
  return {add(c0, sub(c1, c0), 0.5), axis, {-axis.y, axis.x}, dist(c0, c1) / 2};
}

const Goal& find_goal(const World& w, const std::string& name) {
  for (const Goal& g : w.goals)
    if (g.name == name) return g;
  throw std::invalid_argument("match: the world has no goal named '" + name + "'");
}

const Goal& other_goal(const World& w, const std::string& own) {
  if (w.goals.size() != 2) throw std::invalid_argument("match: the world must have exactly two goals");
  return w.goals[0].name == own ? w.goals[1] : w.goals[0];
}

}  // namespace

const char* to_string(RefereeCommand c) {
  switch (c) {
    case RefereeCommand::kStart: return "start";
    case RefereeCommand::kStop: return "stop";
    case RefereeCommand::kKickOff: return "kick_off";
    case RefereeCommand::kGoal: return "goal";
    case RefereeCommand::kThrowIn: return "throw_in";
    case RefereeCommand::kGoalKick: return "goal_kick";
    case RefereeCommand::kCorner: return "corner";
    case RefereeCommand::kDropBall: return "drop_ball";
  }
  return "?";
}

RefereeCommand referee_command_from_string(const std::string& name) {
  for (int i = 0; i <= static_cast<int>(RefereeCommand::kDropBall); ++i)
    if (name == to_string(static_cast<RefereeCommand>(i))) return static_cast<RefereeCommand>(i);
  throw std::invalid_argument("unknown referee command '" + name +
                              "' (expected start, stop, kick_off, goal, throw_in, goal_kick, corner or drop_ball)");
}

void setup_match_world(const MatchConfig& cfg, World& world) {
  find_goal(world, cfg.own_goal);
  other_goal(world, cfg.own_goal);
  if (cfg.clear_movers) world.movers.clear();
  for (const OpponentConfig& o : cfg.opponents) {
    Mover m;
    m.name = o.name;
    m.membership_class = "Robot";
    m.color = cfg.teams[1];
    m.radius = o.radius;
    m.speed = o.speed;
    m.loop = false;
    m.waypoints = {o.home, o.home};
    m.position = o.home;
    m.done = true;
    world.movers.push_back(m);
  }
  world.ball.enabled = true;
  world.ball.robot_restitution = cfg.ball_robot_restitution;
}

Match::Match(MatchConfig cfg, Simulator& sim)
    : cfg_(std::move(cfg)), sim_(sim), own_goal_(find_goal(sim.world(), cfg_.own_goal)),
      other_goal_(other_goal(sim.world(), cfg_.own_goal)) {
  for (const OpponentConfig& o : cfg_.opponents) {
    std::size_t k = 0;
    while (k < sim_.movers().size() && sim_.movers()[k].name != o.name) ++k;
    if (k == sim_.movers().size())
      throw std::invalid_argument("match: opponent '" + o.name + "' is not in the world (call setup_match_world)");
    opponent_movers_.push_back(k);
  }
  pending_kick_.assign(sim_.robots().size(), -1.0);
  dribbler_.assign(sim_.robots().size(), false);
  dribbler_since_.assign(sim_.robots().size(), 0.0);
  opponent_cooldown_.assign(cfg_.opponents.size(), 0.0);
  if (cfg_.referee.auto_start) {
    restart_pending_ = true;
    restart_ = RefereeCommand::kKickOff;
    restart_team_ = cfg_.referee.kickoff_team;
    restart_position_ = {(own_goal_.pose.x + other_goal_.pose.x) / 2, (own_goal_.pose.y + other_goal_.pose.y) / 2};
    restart_time_ = sim_.time();
  }
  sim_.add_hook(*this);
}

Match::~Match() { sim_.remove_hook(*this); }

void Match::kick(std::size_t robot, double strength) {
  pending_kick_.at(robot) = std::clamp(strength, 0.0, 1.0);
}

void Match::set_dribbler(std::size_t robot, bool on) {
  dribbler_.at(robot) = on;
  dribbler_since_.at(robot) = sim_.time();
}

bool Match::in_reach(std::size_t robot) const {
  const RobotState& r = sim_.robots().at(robot);
  const Ball& b = sim_.world().ball;
  const Point2D c{r.pose.x, r.pose.y};
  if (dist(c, b.position) > r.config.base.body_radius + b.radius + cfg_.kicker.reach) return false;
  const double bearing = std::atan2(b.position.y - c.y, b.position.x - c.x);
  return std::abs(normalize_angle(bearing - r.pose.theta)) <= cfg_.kicker.half_angle;
}

void Match::before_step(Simulator&) { steer_opponents(); }

void Match::after_step(Simulator&) {
  robot_kicks();
  ball_handling();
  opponent_kicks();
  track_touch();
  referee();
}

std::vector<RefereeEvent> Match::take_events() {
  std::vector<RefereeEvent> out;
  out.swap(events_);
  return out;
}

std::vector<RefereeEvent> Match::step() {
  sim_.step();
  return take_events();
}

Point2D Match::opponent_target(std::size_t k) const {
  const OpponentConfig& o = cfg_.opponents[k];
  const Mover& m = sim_.world().movers[opponent_movers_[k]];
  const Ball& b = sim_.world().ball;
  if (state_ != State::kPlaying) return m.position;
  if (o.role == "goalkeeper") {
    // On the segment from the mouth centre of its goal to the ball,
    // keeper_distance from the mouth, laterally within the posts.
    const Point2D g = mouth(other_goal_);
    Point2D t = add(g, unit(sub(b.position, g), {-into(other_goal_).x, -into(other_goal_).y}), cfg_.keeper_distance);
    const Point2D lat = across(other_goal_);
    const double l = dot(sub(t, g), lat), half = other_goal_.width / 2;
    if (std::abs(l) > half) t = add(t, lat, std::clamp(l, -half, half) - l);
    return t;
  }
  if (o.role == "defender") {
    // Between the ball and its own goal, defender_distance from the ball
    // (half way when closer than twice that).
    const Point2D g = mouth(other_goal_);
    const double d = std::min(cfg_.defender_distance, dist(g, b.position) / 2);
    return add(b.position, unit(sub(g, b.position)), d);
  }
  if (o.role == "attacker") {
    if (opponents_wait()) return m.position;
    // Behind the ball on the line from the goal it attacks; then through it.
    const Point2D target = mouth(own_goal_);
    const Point2D behind = add(b.position, unit(sub(b.position, target)), o.radius + b.radius + 0.02);
    return dist(m.position, behind) > 0.1 ? behind : b.position;
  }
  return o.home;  // static
}

// Team 0's restart (kick-off, throw-in, ...): the opponents leave the ball
// to them until it has moved 0.3 m or restart_wait has passed.
bool Match::opponents_wait() const {
  return restart_for_ == 0 && sim_.time() - play_since_ < cfg_.referee.restart_wait &&
         dist(sim_.world().ball.position, restart_spot_) < 0.3;
}

void Match::steer_opponents() {
  for (std::size_t k = 0; k < opponent_movers_.size(); ++k) {
    Mover& m = sim_.movers()[opponent_movers_[k]];
    m.waypoints = {m.position, opponent_target(k)};
    m.next = 1;
    m.loop = false;
    m.done = false;
    m.speed = cfg_.opponents[k].speed;
    opponent_cooldown_[k] = std::max(0.0, opponent_cooldown_[k] - sim_.dt());
  }
}

void Match::robot_kicks() {
  Ball& b = sim_.ball();
  for (std::size_t i = 0; i < pending_kick_.size(); ++i) {
    if (pending_kick_[i] < 0.0) continue;
    const double strength = pending_kick_[i];
    pending_kick_[i] = -1.0;
    if (!in_reach(i)) continue;
    const double th = sim_.robots()[i].pose.theta, v = strength * cfg_.kicker.max_speed;
    b.velocity = {v * std::cos(th), v * std::sin(th)};
    ++kicks_;
    last_touch_ = 0;
    if (holder_ == static_cast<int>(i)) holder_ = -1;
    pending_kick_[i] = -2.0;  // marks "kicked this step" for ball_handling
  }
}

void Match::ball_handling() {
  Ball& b = sim_.ball();
  holder_ = -1;
  const double timeout = cfg_.kicker.dribble_timeout;
  for (std::size_t i = 0; i < dribbler_.size(); ++i)
    if (dribbler_[i] && timeout > 0.0 && sim_.time() - dribbler_since_[i] > timeout + 1e-9) {
      dribbler_[i] = false;
      ++dribble_timeouts_;
    }
  for (std::size_t i = 0; i < dribbler_.size(); ++i) {
    const bool kicked = pending_kick_[i] == -2.0;
    pending_kick_[i] = std::max(pending_kick_[i], -1.0);
    if (!dribbler_[i] || kicked || holder_ >= 0 || !in_reach(i)) continue;
    const RobotState& r = sim_.robots()[i];
    if (std::hypot(r.twist.vx, r.twist.vy) > cfg_.kicker.dribble_max_speed ||
        std::abs(r.twist.omega) > cfg_.kicker.dribble_max_omega)
      continue;  // too fast: the ball is lost and keeps its own motion
    // Held at the kicker: in front of the body, moving with that point.
    const double c = std::cos(r.pose.theta), s = std::sin(r.pose.theta);
    const double reach = r.config.base.body_radius + b.radius;
    b.position = {r.pose.x + reach * c, r.pose.y + reach * s};
    const Point2D v{c * r.twist.vx - s * r.twist.vy, s * r.twist.vx + c * r.twist.vy};
    b.velocity = {v.x - r.twist.omega * reach * s, v.y + r.twist.omega * reach * c};
    holder_ = static_cast<int>(i);
    last_touch_ = 0;
  }
}

void Match::opponent_kicks() {
  if (state_ != State::kPlaying) return;
  Ball& b = sim_.ball();
  for (std::size_t k = 0; k < opponent_movers_.size(); ++k) {
    const OpponentConfig& o = cfg_.opponents[k];
    const Mover& m = sim_.world().movers[opponent_movers_[k]];
    if (o.role == "static" || opponent_cooldown_[k] > 0.0 || holder_ >= 0 || opponents_wait()) continue;
    if (dist(m.position, b.position) > o.radius + b.radius + cfg_.kicker.reach) continue;
    // The keeper clears towards the other goal, the others shoot at it.
    const Point2D dir = o.role == "goalkeeper" ? unit(sub(mouth(own_goal_), mouth(other_goal_)))
                                               : unit(sub(mouth(own_goal_), b.position));
    if (dot(unit(sub(b.position, m.position)), dir) < 0.5) continue;  // ball not on the kicking side
    b.velocity = {dir.x * cfg_.opponent_kick_speed, dir.y * cfg_.opponent_kick_speed};
    opponent_cooldown_[k] = 1.0;
    last_touch_ = 1;
  }
}

void Match::track_touch() {
  const Ball& b = sim_.world().ball;
  const double eps = 0.01;
  for (const RobotState& r : sim_.robots())
    if (dist({r.pose.x, r.pose.y}, b.position) <= r.config.base.body_radius + b.radius + eps) last_touch_ = 0;
  for (std::size_t idx : opponent_movers_) {
    const Mover& m = sim_.world().movers[idx];
    if (dist(m.position, b.position) <= m.radius + b.radius + eps) last_touch_ = 1;
  }
}

void Match::emit(RefereeCommand c, int team, const Point2D& p, const std::string& reason) {
  RefereeEvent e;
  e.command = c;
  e.team = team;
  e.position = p;
  e.score = score_;
  e.time = sim_.time();
  e.reason = reason;
  events_.push_back(e);
}

void Match::place_ball(const Point2D& p) {
  Ball& b = sim_.ball();
  b.position = p;
  b.velocity = {0.0, 0.0};
}

Point2D Match::free_spot(const Point2D& p) const {
  const Ball& b = sim_.world().ball;
  const double margin = 0.05;  // m of air between the ball and a body
  auto free = [&](const Point2D& q) {
    for (const RobotState& r : sim_.robots())
      if (dist({r.pose.x, r.pose.y}, q) < r.config.base.body_radius + b.radius + margin) return false;
    for (std::size_t idx : opponent_movers_) {
      const Mover& m = sim_.world().movers[idx];
      if (dist(m.position, q) < m.radius + b.radius + margin) return false;
    }
    return true;
  };
  if (free(p)) return p;
  // On the field (lines included): within the touch lines and goal lines.
  const FieldFrame f = field_frame(own_goal_, other_goal_);
  auto on_field = [&](const Point2D& q) {
    const Point2D d = sub(q, f.centre);
    return std::abs(dot(d, f.axis)) <= f.half_length + 1e-9 &&
           std::abs(dot(d, f.normal)) <= cfg_.field_half_width + 1e-9;
  };
  // The nearest free point: rings 5 cm apart, 32 directions each.
  constexpr int kDirections = 32;
  for (int ring = 1; ring <= 100; ++ring)
    for (int k = 0; k < kDirections; ++k) {
      const double a = 2.0 * M_PI * k / kDirections, r = 0.05 * ring;
      const Point2D q{p.x + r * std::cos(a), p.y + r * std::sin(a)};
      if (on_field(q) && free(q)) return q;
    }
  return p;  // crowded for 5 m around: leave it where it was
}

void Match::stoppage(RefereeCommand restart, int team, const Point2D& p, const std::string& reason) {
  state_ = State::kStopped;
  emit(RefereeCommand::kStop, -1, sim_.world().ball.position, reason);
  restart_pending_ = true;
  start_pending_ = false;
  restart_ = restart;
  restart_team_ = team;
  restart_position_ = p;
  restart_time_ = sim_.time() + cfg_.referee.restart_delay;
}

void Match::command(RefereeCommand c, int team) {
  const Point2D centre{(own_goal_.pose.x + other_goal_.pose.x) / 2, (own_goal_.pose.y + other_goal_.pose.y) / 2};
  restart_pending_ = start_pending_ = false;
  switch (c) {
    case RefereeCommand::kStop:
      state_ = State::kStopped;
      emit(c, team, sim_.world().ball.position, "operator");
      return;
    case RefereeCommand::kStart:
      state_ = State::kPlaying;
      restart_for_ = -1;
      stuck_anchor_ = sim_.world().ball.position;
      stuck_since_ = sim_.time();
      emit(c, team, sim_.world().ball.position, "operator");
      return;
    case RefereeCommand::kGoal:
      if (team != 0 && team != 1) throw std::invalid_argument("match: a goal needs the scoring team (0 or 1)");
      ++score_[static_cast<std::size_t>(team)];
      emit(c, team, sim_.world().ball.position, "operator");
      stoppage(RefereeCommand::kKickOff, 1 - team, centre, "goal");
      return;
    default:
      break;
  }
  // A restart: stop, place the ball (kick-off: the centre; otherwise where
  // it is), announce it, and start after restart_delay.
  state_ = State::kStopped;
  const Point2D p = c == RefereeCommand::kKickOff ? centre : sim_.world().ball.position;
  restart_pending_ = true;
  restart_ = c;
  restart_team_ = team;
  restart_position_ = p;
  restart_time_ = sim_.time();
}

void Match::referee() {
  const double now = sim_.time();
  Ball& b = sim_.ball();
  if (restart_pending_ && now >= restart_time_ - 1e-9) {
    restart_pending_ = false;
    if (restart_ == RefereeCommand::kKickOff)
      for (std::size_t k = 0; k < opponent_movers_.size(); ++k) {
        Mover& m = sim_.movers()[opponent_movers_[k]];
        m.position = cfg_.opponents[k].home;
        m.velocity = {0.0, 0.0};
      }
    restart_position_ = free_spot(restart_position_);
    place_ball(restart_position_);
    emit(restart_, restart_team_, restart_position_, "restart");
    start_pending_ = true;
    restart_time_ = now + cfg_.referee.restart_delay;
    return;
  }
  if (start_pending_ && now >= restart_time_ - 1e-9) {
    start_pending_ = false;
    state_ = State::kPlaying;
    stuck_anchor_ = restart_spot_ = b.position;
    stuck_since_ = play_since_ = now;
    restart_for_ = restart_team_;
    emit(RefereeCommand::kStart, -1, b.position, "restart");
    return;
  }
  if (state_ != State::kPlaying) return;

  // Over a goal line: a goal between the posts, else a goal kick or corner.
  for (int defender = 0; defender < 2; ++defender) {
    const Goal& g = goal_of(defender);
    const Point2D rel = sub(b.position, mouth(g));
    const double depth = dot(rel, into(g)), lateral = dot(rel, across(g));
    if (depth <= b.radius) continue;  // the whole ball must be over the line
    const int attacker = 1 - defender;
    if (std::abs(lateral) < g.width / 2) {
      ++score_[static_cast<std::size_t>(attacker)];
      emit(RefereeCommand::kGoal, attacker, b.position, "goal for " + cfg_.teams[static_cast<std::size_t>(attacker)]);
      stoppage(RefereeCommand::kKickOff, defender, field_frame(own_goal_, other_goal_).centre, "goal");
      return;
    }
    const double side = lateral > 0 ? 1.0 : -1.0;
    if (last_touch_ == defender) {
      // Corner: at the corner of the field on that side, inside by a radius.
      const Point2D p = add(add(mouth(g), across(g), side * (cfg_.field_half_width - b.radius)), into(g), -b.radius);
      stoppage(RefereeCommand::kCorner, attacker, p, "ball over the goal line");
    } else {
      const Point2D p = add(add(mouth(g), across(g), side * 1.0), into(g), -1.0);
      stoppage(RefereeCommand::kGoalKick, defender, p, "ball over the goal line");
    }
    return;
  }
  // Over a touch line: throw-in for the team that did not touch it last.
  const FieldFrame f = field_frame(own_goal_, other_goal_);
  const Point2D centre = f.centre, axis = f.axis, normal = f.normal;
  const double along = dot(sub(b.position, centre), axis), lateral = dot(sub(b.position, centre), normal);
  if (std::abs(lateral) > cfg_.field_half_width + b.radius) {
    const Point2D p = add(add(centre, axis, along), normal, lateral > 0 ? cfg_.field_half_width : -cfg_.field_half_width);
    stoppage(last_touch_ < 0 ? RefereeCommand::kDropBall : RefereeCommand::kThrowIn,
             last_touch_ < 0 ? -1 : 1 - last_touch_, p, "ball over the touch line");
    return;
  }
  // No progress: drop ball where it is.
  if (dist(b.position, stuck_anchor_) > 0.2) {
    stuck_anchor_ = b.position;
    stuck_since_ = now;
  } else if (cfg_.referee.stuck_timeout > 0.0 && now - stuck_since_ > cfg_.referee.stuck_timeout) {
    stoppage(RefereeCommand::kDropBall, -1, b.position, "ball stuck");
  }
}

}  // namespace mrt::robocup
