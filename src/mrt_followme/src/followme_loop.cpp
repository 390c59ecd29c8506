#include "mrt_followme/followme_loop.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "mrt_brian/brian.h"
#include "mrt_common/brian_mapping.h"
#include "mrt_common/package_path.h"
#include "mrt_common/wheel_odometry.h"
#include "mrt_followme/unmapped_echo.h"
#include "mrt_followme/visitor_tracker.h"
#include "mrt_murea/feature_map.h"
#include "mrt_murea/tracker.h"
#include "mrt_roby/crisp_builder.h"
#include "mrt_roby/sonar_sectors.h"
#include "mrt_scare/sequencer.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/simulator.h"
#include "mrt_spike/map_sources.h"
#include "mrt_spike/world_planner.h"

namespace mrt::followme {

namespace {

/// Mr. BRIAN with Roby's rule base: crisp data in (the previous commands fed
/// back), a body twist out through mrt_common's BrianMapping.
class BrianDriver {
 public:
  BrianDriver(const std::string& dir, const std::map<std::string, std::string>& packages)
      : brian_(brian::Brian::from_path(dir, options(packages))) {}

  std::optional<common::Twist2D> run(roby::CrispInputs in) {
    in.last_speed_cm = last_speed_;
    in.last_jog_deg = last_jog_;
    last_speed_ = last_jog_ = 0.0;
    std::vector<std::pair<std::string, double>> commands;
    for (const auto& cmd : brian_->run(roby::build_crisp(in))) {
      if (cmd.name == "Speed") last_speed_ = cmd.value;
      if (cmd.name == "Jog") last_jog_ = cmd.value;
      commands.emplace_back(cmd.name, cmd.value);
    }
    return mapping_.to_twist(commands);
  }

 private:
  static brian::BrianOptions options(const std::map<std::string, std::string>& packages) {
    brian::BrianOptions o;
    o.packages = common::package_finder(packages);
    return o;
  }

  std::unique_ptr<brian::Brian> brian_;
  const common::BrianMapping mapping_{common::BrianMappingParams{}};
  double last_speed_ = 0.0, last_jog_ = 0.0;
};

/// MUREA tracking on the landmark percepts, predicted by the encoders.
class Localization {
 public:
  Localization(const sim::World& world, const Pose2D& initial) : map_(world), tracker_(map_, options()) {
    tracker_.set_pose(initial, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.003});
  }
  void frame(const common::WheelOdometry& odo, const std::vector<sim::SeenObject>& seen) {
    const Pose2D delta = last_odo_.inverse() * odo.pose();
    const double moved = odo.travelled() - last_travelled_;
    last_odo_ = odo.pose();
    last_travelled_ = odo.travelled();
    const double s = 0.02 * moved + 0.002;
    tracker_.predict(delta, {s * s, 0, 0, 0, s * s, 0, 0, 0, 0.25 * s * s + 1e-6});
    std::vector<murea::Percept> percepts;
    for (const auto& o : seen) {
      if (o.membership_class != "Landmark") continue;
      murea::Percept p;
      p.cls = murea::FeatureClass::Landmark;
      p.color = o.color;
      p.distance = o.distance;
      p.bearing = o.bearing;
      percepts.push_back(p);
    }
    tracker_.update(percepts);
  }
  Pose2D pose(const common::WheelOdometry& odo) const { return tracker_.pose() * (last_odo_.inverse() * odo.pose()); }

 private:
  static murea::TrackerOptions options() {
    murea::TrackerOptions o;
    o.search.timeout = 0.05;
    return o;
  }
  murea::FeatureMap map_;
  murea::Tracker tracker_;
  Pose2D last_odo_;
  double last_travelled_ = 0.0;
};

/// SPIKE on the museum's fixed objects (closed doors included).
class LegPlanner {
 public:
  LegPlanner(const sim::World& world, const GuideOptions& g) : g_(g) { rebuild(world); }
  void rebuild(const sim::World& world) {
    spike::WorldPlannerOptions o;
    o.robot_radius = g_.robot_radius;
    o.safety_distance = g_.safety_distance;
    o.spacing = 0.25;
    planner_ = std::make_unique<spike::WorldPlanner>(spike::rasterize_world(world, g_.resolution), o);
  }
  std::vector<Point2D> plan(const Pose2D& from, const Point2D& to) {
    const spike::WorldPlan p = planner_->plan(from.x, from.y, to.x, to.y);
    std::vector<Point2D> out;
    if (!p.solved) return out;
    for (const auto& q : p.poses) out.push_back({q.x, q.y});
    return out;
  }

 private:
  GuideOptions g_;
  std::unique_ptr<spike::WorldPlanner> planner_;
};

/// Which door (if any) the segment a-b crosses.
std::string crossed_door(const std::vector<Door>& doors, const Point2D& a, const Point2D& b) {
  for (const Door& d : doors) {
    const double d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.b.x - d.a.x, d2y = d.b.y - d.a.y;
    const double den = d1x * d2y - d1y * d2x;
    if (std::abs(den) < 1e-12) continue;
    const double s = ((d.a.x - a.x) * d2y - (d.a.y - a.y) * d2x) / den;
    const double u = ((d.a.x - a.x) * d1y - (d.a.y - a.y) * d1x) / den;
    if (s >= 0 && s <= 1 && u >= 0 && u <= 1) return d.name;
  }
  return "";
}

struct Measures {
  FollowMeResult& r;
  void people(const sim::World& w, const Pose2D& p, double body) {
    for (const auto& m : w.movers) {
      const double gap = std::hypot(m.position.x - p.x, m.position.y - p.y) - m.radius - body;
      if (gap < r.min_person_gap) {
        r.min_person_gap = gap;
        r.nearest_person = m.name;
      }
    }
    for (const auto& s : sim::solid_segments(w))
      r.min_clearance = std::min(r.min_clearance, sim::distance_to_segment({p.x, p.y}, s) - body);
    for (const auto& post : w.posts)
      r.min_clearance =
          std::min(r.min_clearance, std::hypot(post.center.x - p.x, post.center.y - p.y) - post.radius - body);
  }
};

}  // namespace

struct FollowMeSession::Impl {
  FollowMeLoopOptions o;
  FollowMeConfig cfg;
  sim::Simulator simulator;
  std::size_t r, guest;
  const sim::RobotConfig rc;
  std::vector<Exhibit> tour;
  Exhibit wander;
  std::unique_ptr<VisitorModel> visitor;
  VisitorTracker tracker;
  std::unique_ptr<Guide> guide;
  LegPlanner planner;
  BrianDriver brian;
  common::WheelOdometry odometry;
  Localization localization;
  roby::SonarSectors sectors;
  std::vector<std::string> sector_names;
  FollowMeResult res;
  std::uint64_t period;
  bool seen_once = false, finished = false;
  double wait_start = -1.0;
  Point2D last_truth;
  Pose2D estimate;
  std::vector<std::string> closed;
  sim::World known;  // what the robot's map holds: walls, closed doors, posts; no people

  static sim::World map_of(const sim::World& w) {
    sim::World m = w;
    m.movers.clear();
    m.ball.enabled = false;
    return m;
  }

  static FollowMeConfig configure(const FollowMeLoopOptions& o) {
    FollowMeConfig c = load_followme_config(o.config);
    if (o.wander_after >= 0) c.visitor.wander_after = o.wander_after;
    if (!o.tour.empty()) {
      const std::string bad = check_tour(c, o.tour);
      if (!bad.empty()) throw std::invalid_argument("tour: " + bad);
      c.tour = o.tour;
    }
    return c;
  }
  static std::vector<double> mounts(const sim::RobotConfig& rc) {
    std::vector<double> m;
    for (const auto& s : rc.sensors.sonars) m.push_back(common::rad_to_deg(s.mount.theta));
    return m;
  }

  explicit Impl(const FollowMeLoopOptions& opt)
      : o(opt),
        cfg(configure(opt)),
        simulator(sim::load_world(opt.world), 0.001),
        r(simulator.robot_index(opt.robot)),
        guest(simulator.mover_index(cfg.visitor.name)),
        rc(simulator.robots()[r].config),
        tracker(cfg.visitor.color),
        planner(simulator.world(), cfg.guide),
        brian(opt.brian, opt.packages),
        odometry(rc.base, rc.sensors.ticks_per_rev),
        localization(simulator.world(), rc.initial_pose),
        sectors(mounts(rc), roby::default_sectors(), rc.sensors.sonars.empty() ? 5.0 : rc.sensors.sonars[0].max_range),
        period(simulator.period(opt.brian_rate)),
        last_truth{rc.initial_pose.x, rc.initial_pose.y},
        estimate(rc.initial_pose),
        known(map_of(simulator.world())) {
    if (!cfg.visitor.wander_to.empty()) wander = cfg.exhibits[cfg.exhibit_index(cfg.visitor.wander_to)];
    for (const auto& s : sectors.sectors()) sector_names.push_back(s.name);
    start_tour(cfg.tour, 0.0);
  }

  void start_tour(const std::vector<std::string>& names, double now) {
    tour.clear();
    for (const auto& n : names) tour.push_back(cfg.exhibits[cfg.exhibit_index(n)]);
    visitor = std::make_unique<VisitorModel>(cfg.visitor, tour, wander);
    if (!guide) {
      guide = std::make_unique<Guide>(cfg.guide, tour);
    } else {
      guide->set_tour(tour, now);
    }
    finished = false;
    res.completed = false;
  }

  void close_door(const std::string& name, double now) {
    const Door& d = cfg.door(name);
    simulator.add_wall({d.a, d.b});
    known.walls.push_back({d.a, d.b});
    planner.rebuild(simulator.world());
    closed.push_back(name);
    guide->close_door(d, now);
  }

  // One simulation step: sensors, localization, the visitor's track, measures.
  void step() {
    simulator.step();
    const sim::RobotState& st = simulator.robots()[r];
    const double now = simulator.time();
    if (st.encoders_ready) odometry.update(st.ticks);
    if (st.sonar_ready) unmapped_echoes(st.sonar, now);
    if (st.vision_ready) {
      localization.frame(odometry, st.vision);
      std::vector<PersonPercept> persons;
      for (const auto& v : st.vision)
        if (v.membership_class == "Person") persons.push_back({v.color, v.distance, v.bearing});
      seen_once = tracker.update(now, localization.pose(odometry), persons) || seen_once;
      if (seen_once) res.max_unseen = std::max(res.max_unseen, tracker.unseen_for(now));
    }
    estimate = o.use_ground_truth ? st.pose : localization.pose(odometry);
    res.max_pose_error = std::max(res.max_pose_error, std::hypot(estimate.x - st.pose.x, estimate.y - st.pose.y));
    if (simulator.steps() % 10 == 0) Measures{res}.people(simulator.world(), st.pose, rc.base.body_radius);
    const Point2D truth{st.pose.x, st.pose.y};
    const std::string door = crossed_door(cfg.doors, last_truth, truth);
    if (!door.empty()) res.doors.push_back({now, door});
    last_truth = truth;
  }

  // Mr. BRIAN's obstacle sectors hold what the map does not explain (people):
  // unmapped_echo.h.
  void unmapped_echoes(const std::vector<double>& ranges, double now) {
    for (std::size_t i = 0; i < ranges.size() && i < rc.sensors.sonars.size(); ++i)
      sectors.set_range(i, unmapped_range(known, estimate, rc.sensors.sonars[i], ranges[i]), now);
  }

  // One guide cycle: the visitor decides, the guide decides, Mr. BRIAN drives.
  void decide() {
    const sim::RobotState& st = simulator.robots()[r];
    const double now = simulator.time();
    const sim::Mover& g = simulator.world().movers[guest];
    const VisitorStep vs = visitor->update(now, g.position, st.pose);
    simulator.steer_mover(guest, vs.target, vs.speed);

    const Job before = guide->job();
    GuideOutput out = guide->update({now, estimate, tracker.track()});
    if (out.call_visitor) visitor->call();
    if (out.plan_request) {
      auto path = planner.plan(estimate, *out.plan_request);
      res.plans.push_back(path);
      guide->set_plan(std::move(path), now);
      if (!o.close_door.empty() && closed.empty() && static_cast<int>(guide->current()) == o.close_at_leg)
        close_door(o.close_door, now);
    }
    if (guide->job() == Job::kWaitVisitor && before != Job::kWaitVisitor) wait_start = now;
    if (before == Job::kWaitVisitor && guide->job() != Job::kWaitVisitor) res.waits.push_back(now - wait_start);
    if (guide->job() == Job::kFollowVisitor && out.goal) ++res.follow_goals;

    roby::CrispInputs in;
    if (out.goal) in.goal = scare::goal_crisp(estimate, *out.goal);
    in.sector_names = sector_names;
    in.sector_distances = sectors.distances(now);
    if (const auto twist = brian.run(in)) simulator.set_twist(r, {twist->vx, twist->vy, twist->omega});
    res.time = now;
    res.visited = guide->visited();
    res.wanders = guide->wanders();
    res.replans = res.plans.size();
    res.events = guide->events();
    res.visitor_state = to_string(visitor->state());
    res.max_wait_at_exhibit = 0.0;
    for (double w : res.waits) res.max_wait_at_exhibit = std::max(res.max_wait_at_exhibit, w);
    if (guide->job() == Job::kDone) {
      res.completed = true;
      finished = true;
    }
  }
};

FollowMeSession::FollowMeSession(const FollowMeLoopOptions& o) : impl_(std::make_unique<Impl>(o)) {}
FollowMeSession::~FollowMeSession() = default;

bool FollowMeSession::cycle() {
  Impl& s = *impl_;
  if (s.finished || s.simulator.time() >= s.o.duration) return false;
  do {
    s.step();
  } while (s.simulator.steps() % s.period != 0);
  s.decide();
  return !s.finished && s.simulator.time() < s.o.duration;
}

std::string FollowMeSession::set_tour(const std::vector<std::string>& names) {
  const std::string bad = check_tour(impl_->cfg, names);
  if (bad.empty()) impl_->start_tour(names, impl_->simulator.time());
  return bad;
}

void FollowMeSession::close_door(const std::string& name) { impl_->close_door(name, impl_->simulator.time()); }

double FollowMeSession::time() const { return impl_->simulator.time(); }

FollowMeTick FollowMeSession::tick() const {
  const Impl& s = *impl_;
  return {s.simulator.time(), s.simulator.robots()[s.r].pose, s.estimate,
          s.simulator.world().movers[s.guest].position, s.guide->job(), s.visitor->state()};
}

FollowMeView FollowMeSession::view() const {
  const Impl& s = *impl_;
  FollowMeView v;
  for (const auto& m : s.simulator.world().movers) v.people.push_back({m.name, m.color, m.position, m.radius});
  v.plan = s.guide->plan();
  v.closed_doors = s.closed;
  if (s.tracker.track()) v.visitor_track = s.tracker.track()->position;
  v.visitor_in_sight = s.tracker.unseen_for(s.simulator.time()) < 0.5;
  return v;
}

const FollowMeResult& FollowMeSession::result() const { return impl_->res; }
const Guide& FollowMeSession::guide() const { return *impl_->guide; }
const FollowMeConfig& FollowMeSession::config() const { return impl_->cfg; }
const sim::World& FollowMeSession::world() const { return impl_->simulator.world(); }

FollowMeResult run_followme_loop(const FollowMeLoopOptions& o, const std::function<void(const FollowMeTick&)>& tick) {
  FollowMeSession session(o);
  while (session.cycle())
    if (tick) tick(session.tick());
  if (tick) tick(session.tick());
  return session.result();
}

}  // namespace mrt::followme
