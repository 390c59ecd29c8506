#include "mrt_robocup/team_session.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "mrt_map/world_model.h"
#include "mrt_robocup/match.h"
#include "mrt_robocup/team_crisp.h"
#include "mrt_robocup/team_percepts.h"
#include "mrt_scare/coordinator.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/simulator.h"

namespace mrt::robocup {

struct Member {
  TeamRobot spec;
  std::size_t index = 0;  // in the simulator
  std::unique_ptr<map::WorldModel> world;
  std::unique_ptr<scare::Coordinator> coordinator;
  std::unique_ptr<Player> player;
  common::Twist2D command;
  std::string job;
  bool had_job = false, active = true;
  Parameters coordination;
  PlayerOutput last;
};

struct TeamSession::Impl {
  TeamSessionOptions o;
  map::ConceptualModel model;
  std::unique_ptr<sim::Simulator> sim;
  std::unique_ptr<Match> match;
  std::vector<Member> team;
  std::vector<scare::CoordinationMessage> leaving;  // delivered at the next cycle
  Referee referee = Referee::kNone;
  std::mt19937_64 rng;
  TeamStats stats;
  std::vector<double> kick_request;  // per robot, < 0 none
  int pass_from = -1;                // robot whose kick may become a pass
  double step_touch_team0 = 0.0;

  explicit Impl(const TeamSessionOptions& opt) : o(opt), model(map::ConceptualModel::load(opt.map_model)), rng(opt.seed) {
    if (!(o.rate > 0.0) || !(o.dt > 0.0) || o.dt * o.rate > 1.0) throw std::invalid_argument("rate and dt: expected 0 < dt <= 1 / rate");
    sim::World w = sim::load_world(o.world);
    MatchConfig mc = load_match_config(o.match);
    if (o.replace_opponents) mc.opponents = o.opponents;
    w.seed = o.seed;
    w.robots.clear();
    const std::vector<TeamRobot> robots = load_team(o.team);
    for (const TeamRobot& r : robots) {
      sim::RobotConfig rc;
      rc.name = r.name;
      rc.color = mc.teams[0];
      rc.base = sim::base_preset(r.base);
      rc.initial_pose = r.pose;
      rc.sensors.rate_mice = rc.sensors.rate_encoders = rc.sensors.rate_sonar = rc.sensors.rate_vision = 0.0;
      rc.sensors.rate_dgps = 0.0;
      w.robots.push_back(rc);
    }
    setup_match_world(mc, w);
    sim = std::make_unique<sim::Simulator>(std::move(w), o.dt);
    match = std::make_unique<Match>(mc, *sim);  // a step hook of sim from now on
    const scare::ActivitySet set = scare::load_activities(o.activities);
    for (std::size_t i = 0; i < robots.size(); ++i) {
      Member m;
      m.spec = robots[i];
      m.index = sim->robot_index(robots[i].name);
      map::WorldModelOptions wo;
      wo.robot = robots[i].name;
      m.world = std::make_unique<map::WorldModel>(model, wo);
      m.coordinator = std::make_unique<scare::Coordinator>(set, set.robot_or_default(robots[i].name));
      const sim::BaseConfig& base = sim->robots()[m.index].config.base;
      PlayerOptions po;
      po.kinematics = base.type == common::BaseType::kOmni ? "omni" : "differential";
      po.rule_base = o.rule_bases + "/" + po.kinematics + "/BrianConfigs.ini";
      po.max_speed = base.type == common::BaseType::kOmni ? 1.5 : 1.2;
      po.situation.body_radius = base.body_radius;
      po.situation.ball_radius = sim->world().ball.radius;
      po.situation.home = robots[i].home;
      po.situation.field.half_width = mc.field_half_width;
      po.carry_max_speed = std::min(po.carry_max_speed, 0.9 * mc.kicker.dribble_max_speed);
      po.carry_max_omega = std::min(po.carry_max_omega, 0.9 * mc.kicker.dribble_max_omega);
      m.player = std::make_unique<Player>(po);
      team.push_back(std::move(m));
    }
    kick_request.assign(team.size(), -1.0);
  }

  double now() const { return sim->time(); }

  void halt_all() {
    for (Member& m : team) {
      m.command = {};
      sim->set_twist(m.index, m.command);
      match->set_dribbler(m.index, false);
    }
    std::fill(kick_request.begin(), kick_request.end(), -1.0);
  }

  void on_event(const RefereeEvent& e) {
    referee = static_cast<Referee>(static_cast<int>(e.command));
    if (e.command == RefereeCommand::kGoal) {
      stats.score = e.score;
      if (e.team == 0 && stats.first_goal_time < 0.0) stats.first_goal_time = e.time;
      pass_from = -1;
    }
    stats.score = e.score;
    if (!Player::playing(referee, false)) halt_all();  // in this very step, whatever the rules
  }

  void perceive(Member& m, double t) {
    const sim::RobotState& rs = sim->robots()[m.index];
    map::RobotPose pose;
    pose.x = rs.pose.x;
    pose.y = rs.pose.y;
    pose.theta = rs.pose.theta;
    pose.cov = map::Mat2::Identity() * 1e-4;
    pose.theta_sigma = 0.005;
    m.world->set_robot_pose(pose, t);
    const auto objects = team_percepts(sim->world(), sim->other_robots(m.index), rs.pose, o.vision_range,
                                       o.distance_noise, o.bearing_noise, rng);
    if (!objects.empty()) m.world->add_percept(objects, pose, t, t, "omnivision");
  }

  void exchange(double t) {
    for (Member& m : team) {
      if (!m.active) continue;
      for (const Member& other : team) {
        if (&other == &m || !other.active) continue;
        const map::RobotPose& p = other.world->robot_pose();
        m.world->add_teammate_model(other.spec.name, other.world->local_tracks(), t, &p);
      }
      m.world->update(t);
    }
  }

  void coordinate(double t);
  void act(double t);
};

void TeamSession::Impl::coordinate(double t) {
  bool owns = false;
  for (const Member& m : team)
    if (m.active && match->in_reach(m.index)) owns = true;
  std::vector<scare::CoordinationMessage> msgs = std::move(leaving);
  leaving.clear();
  for (Member& m : team) {
    if (!m.active) continue;
    const auto crisp = team_crisp(anchor_views(*m.world, t), owns, m.player->options().situation);
    msgs.push_back(m.coordinator->publish(t, sim->robots()[m.index].pose, crisp));
  }
  for (Member& m : team) {
    if (!m.active) continue;
    for (const scare::CoordinationMessage& msg : msgs)
      if (msg.robot_id != m.spec.name) m.coordinator->receive(msg);
    m.coordinator->step(t);
    m.coordination.clear();
    for (const scare::CrispOut& c : m.coordinator->crisp_output()) m.coordination[c.name] = {c.value, c.reliability};
  }
}

void TeamSession::Impl::act(double t) {
  for (std::size_t i = 0; i < team.size(); ++i) {
    Member& m = team[i];
    if (!m.active) continue;
    PlayerInput in;
    in.time = t;
    in.pose_valid = true;
    in.pose = sim->robots()[m.index].pose;
    in.anchors = anchor_views(*m.world, t);
    in.coordination = m.coordination;
    in.referee = referee;
    in.possession_known = true;
    in.possession = match->in_reach(m.index);
    m.last = m.player->cycle(in);
    const PlayerOutput& out = m.last;
    if (out.job != m.job) {
      if (m.had_job) ++stats.role_changes;
      m.had_job = m.had_job || !out.job.empty();
      m.job = out.job;
    }
    m.command = out.twist;
    sim->set_twist(m.index, m.command);
    match->set_dribbler(m.index, out.dribble);
    if (out.kick) {
      match->kick(m.index, out.kick_strength);
      kick_request[i] = out.kick_strength;
    }
  }
}

TeamSession::TeamSession(const TeamSessionOptions& o) : impl_(std::make_unique<Impl>(o)) {}
TeamSession::~TeamSession() = default;

bool TeamSession::cycle() {
  Impl& s = *impl_;
  if (s.now() >= s.o.duration - 1e-9) return false;
  const double t = s.now();
  for (Member& m : s.team)
    if (m.active) s.perceive(m, t);
  s.exchange(t);
  s.coordinate(t);
  s.act(t);
  const long steps = std::max(1L, std::lround(1.0 / (s.o.rate * s.o.dt)));
  for (long k = 0; k < steps; ++k) {
    const int kicks_before = s.match->kicks();
    for (const RefereeEvent& e : s.match->step()) s.on_event(e);
    if (s.match->kicks() > kicks_before) {
      // The kick of this cycle's requester that reached the ball.
      for (std::size_t i = 0; i < s.team.size(); ++i)
        if (s.kick_request[i] >= 0.0) s.pass_from = static_cast<int>(i);
    }
    std::fill(s.kick_request.begin(), s.kick_request.end(), -1.0);
    const bool playing = s.match->state() == Match::State::kPlaying;
    if (playing) {
      s.stats.play_time += s.o.dt;
      if (s.match->last_touch() == 0) s.step_touch_team0 += s.o.dt;
    }
    if (s.pass_from >= 0) {
      if (s.match->last_touch() == 1 || !playing) {
        s.pass_from = -1;
      } else if (s.match->holder() >= 0 && s.match->holder() != static_cast<int>(s.team[s.pass_from].index)) {
        ++s.stats.passes;
        s.pass_from = -1;
      } else if (s.match->holder() == static_cast<int>(s.team[s.pass_from].index)) {
        s.pass_from = -1;
      }
    }
  }
  s.stats.kicks = s.match->kicks();
  s.stats.sim_time = s.now();
  s.stats.possession = s.stats.play_time > 0 ? s.step_touch_team0 / s.stats.play_time : 0.0;
  if (s.o.stop_at_first_goal && s.stats.first_goal_time >= 0.0) return false;
  return s.now() < s.o.duration - 1e-9;
}

void TeamSession::run() {
  while (cycle()) {
  }
}

void TeamSession::referee(Referee command) {
  Impl& s = *impl_;
  if (command == Referee::kNone) return;
  s.match->command(static_cast<RefereeCommand>(static_cast<int>(command)));
  s.referee = command;
  if (!Player::playing(command, false)) s.halt_all();
}

void TeamSession::remove_robot(const std::string& name) {
  Impl& s = *impl_;
  for (std::size_t i = 0; i < s.team.size(); ++i) {
    Member& m = s.team[i];
    if (m.spec.name != name || !m.active) continue;
    m.active = false;
    scare::CoordinationMessage bye = m.coordinator->publish(s.now(), s.sim->robots()[m.index].pose, {});
    bye.leaving = true;
    s.leaving.push_back(bye);
    m.command = {};
    m.job.clear();
    s.sim->set_twist(m.index, m.command);
    s.match->set_dribbler(m.index, false);
    // Carried off the field: beside the own half's touch line.
    sim::RobotState& r = s.sim->robots()[m.index];
    r.pose = Pose2D(-8.0 + 0.7 * static_cast<double>(i), -6.6, 0.0);
    return;
  }
  throw std::out_of_range("remove_robot: no active robot '" + name + "'");
}

double TeamSession::time() const { return impl_->now(); }
const TeamStats& TeamSession::stats() const { return impl_->stats; }
std::size_t TeamSession::robots() const { return impl_->team.size(); }
const std::string& TeamSession::robot_name(std::size_t i) const { return impl_->team.at(i).spec.name; }
const std::string& TeamSession::job(std::size_t i) const { return impl_->team.at(i).job; }
bool TeamSession::active(std::size_t i) const { return impl_->team.at(i).active; }
common::Twist2D TeamSession::command(std::size_t i) const { return impl_->team.at(i).command; }
Pose2D TeamSession::pose(std::size_t i) const { return impl_->sim->robots()[impl_->team.at(i).index].pose; }
Point2D TeamSession::ball() const { return impl_->sim->world().ball.position; }
const PlayerOutput& TeamSession::output(std::size_t i) const { return impl_->team.at(i).last; }
int TeamSession::holder() const {
  for (std::size_t i = 0; i < impl_->team.size(); ++i)
    if (impl_->match->holder() == static_cast<int>(impl_->team[i].index)) return static_cast<int>(i);
  return -1;
}
std::vector<Point2D> TeamSession::opponents() const {
  std::vector<Point2D> out;
  for (const sim::Mover& m : impl_->sim->world().movers) out.push_back(m.position);
  return out;
}
double TeamSession::true_speed(std::size_t i) const {
  const auto& r = impl_->sim->robots()[impl_->team.at(i).index];
  return std::hypot(r.twist.vx, r.twist.vy) + std::abs(r.twist.omega) * r.config.base.body_radius;
}

}  // namespace mrt::robocup
