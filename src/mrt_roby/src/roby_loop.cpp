#include "mrt_roby/roby_loop.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "mrt_brian/brian.h"
#include "mrt_common/brian_mapping.h"
#include "mrt_roby/crisp_builder.h"
#include "mrt_roby/dgps_localizer.h"
#include "mrt_roby/sonar_sectors.h"
#include "mrt_scare/task_config.h"
#include "mrt_sim/simulator.h"

namespace mrt::roby {

using scare::Sequencer;
using scare::SequencerState;
using scare::goal_crisp;
using scare::load_sequencer_options;

double world_clearance(const void* world_ptr, double x, double y, double radius, std::string* what) {
  const auto& w = *static_cast<const sim::World*>(world_ptr);
  double best = std::numeric_limits<double>::infinity();
  const Point2D p{x, y};
  for (const auto& s : sim::solid_segments(w)) {
    const double d = sim::distance_to_segment(p, s) - radius;
    if (d < best) {
      best = d;
      if (what) *what = "wall";
    }
  }
  for (const auto& post : w.posts) {
    const double d = std::hypot(post.center.x - x, post.center.y - y) - post.radius - radius;
    if (d < best) {
      best = d;
      if (what) *what = post.name;
    }
  }
  for (const auto& m : w.movers) {
    const double d = std::hypot(m.position.x - x, m.position.y - y) - m.radius - radius;
    if (d < best) {
      best = d;
      if (what) *what = m.name;
    }
  }
  return best;
}

namespace {

/// Mr. BRIAN's side of one cycle: the crisp data in, the previous commands
/// fed back (LastSpeed, LastJog), the commands mapped to a body twist as the
/// AIRBoard maps them (unicycle: Speed cm/s, Jog deg/s).
class BrianCycle {
 public:
  explicit BrianCycle(const std::string& dir) : brian_(brian::Brian::from_path(dir)) {}

  std::optional<common::Twist2D> run(CrispInputs in) {
    in.last_speed_cm = last_speed_;
    in.last_jog_deg = last_jog_;
    crisp_ = build_crisp(in);
    last_speed_ = last_jog_ = 0.0;
    commands_.clear();
    for (const auto& cmd : brian_->run(crisp_)) {
      if (cmd.name == "Speed") last_speed_ = cmd.value;
      if (cmd.name == "Jog") last_jog_ = cmd.value;
      commands_.emplace_back(cmd.name, cmd.value);
    }
    return mapping_.to_twist(commands_);
  }

  void print(double now, const Pose2D& truth) const {
    std::printf("%7.2f pose %6.2f %6.2f %6.1f |", now, truth.x, truth.y, common::rad_to_deg(truth.theta));
    for (const auto& x : crisp_) std::printf(" %s=%.0f", x.name.c_str(), x.value);
    std::printf(" | Speed %.1f Jog %.1f\n", last_speed_, last_jog_);
  }

 private:
  std::unique_ptr<brian::Brian> brian_;
  const common::BrianMapping mapping_{common::BrianMappingParams{}};
  CrispDataList crisp_;
  std::vector<std::pair<std::string, double>> commands_;
  double last_speed_ = 0.0, last_jog_ = 0.0;
};

}  // namespace

RobyLoopResult run_roby_loop(const RobyLoopOptions& o,
                             const std::function<void(double, const RobyLoopResult&)>& tick) {
  sim::Simulator simulator(sim::load_world(o.world), 0.001);
  const std::size_t r = simulator.robot_index(o.robot);
  const sim::RobotConfig& rc = simulator.robots()[r].config;
  RoutePlanner planner(load_road_map(o.map));
  Sequencer seq(load_sequencer_options(o.tasks));
  BrianCycle brian(o.brian);
  std::vector<double> mounts;
  for (const auto& s : rc.sensors.sonars) mounts.push_back(common::rad_to_deg(s.mount.theta));
  const double max_range = rc.sensors.sonars.empty() ? 5.0 : rc.sensors.sonars[0].max_range;
  SonarSectors sectors(mounts, default_sectors(), max_range);
  DgpsLocalizer loc(rc.initial_pose);

  RobyLoopResult res;
  const auto first = planner.plan({rc.initial_pose.x, rc.initial_pose.y});
  res.route_points = first.size();
  auto record = [&](std::vector<SequencerEvent> ev) {
    for (const auto& e : ev) {
      res.events.push_back(e);
      if (e.type == SequencerEvent::Type::kReplanRequested) {
        auto next = planner.replan({e.pose.x, e.pose.y}, e.point);
        auto more = seq.set_plan(next, e.time, e.pose);
        res.events.insert(res.events.end(), more.begin(), more.end());
      }
    }
  };
  record(seq.set_plan(first, 0.0, loc.pose()));

  const bool debug = std::getenv("ROBY_DEBUG") != nullptr;
  const std::uint64_t brian_period = simulator.period(o.brian_rate);
  std::vector<std::string> names;
  for (const auto& s : sectors.sectors()) names.push_back(s.name);
  while (simulator.time() < o.duration) {
    simulator.step();
    const sim::RobotState& st = simulator.robots()[r];
    loc.predict(st.twist.vx, st.twist.omega, simulator.dt());
    if (st.dgps_ready) loc.correct(st.dgps.x, st.dgps.y);
    if (st.sonar_ready)
      for (std::size_t i = 0; i < st.sonar.size(); ++i) sectors.set_range(i, st.sonar[i]);
    std::string what;
    const double c = world_clearance(&simulator.world(), st.pose.x, st.pose.y, rc.base.body_radius, &what);
    if (c < res.min_clearance) {
      res.min_clearance = c;
      res.nearest = what;
    }
    const Pose2D pose = o.use_ground_truth ? st.pose : loc.pose();
    res.max_pose_error = std::max(res.max_pose_error, std::hypot(pose.x - st.pose.x, pose.y - st.pose.y));
    if (simulator.steps() % brian_period != 0) continue;
    const double now = simulator.time();
    record(seq.update(now, pose));
    CrispInputs in;
    if (seq.active()) in.goal = goal_crisp(pose, seq.active()->goal());
    in.mode = seq.mode();
    in.sector_names = names;
    in.sector_distances = sectors.distances();
    if (const auto twist = brian.run(in)) simulator.set_twist(r, {twist->vx, twist->vy, twist->omega});
    if (debug) brian.print(now, st.pose);
    res.reached = seq.reached();
    res.failed = seq.failed();
    res.replans = seq.replans();
    res.time = now;
    if (tick) tick(now, res);
    if (seq.state() == SequencerState::kDone) {
      res.completed = true;
      break;
    }
    if (seq.state() == SequencerState::kGaveUp || seq.state() == SequencerState::kIdle) break;
  }
  return res;
}

}  // namespace mrt::roby
