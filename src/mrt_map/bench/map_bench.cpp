// map_bench: MAP for a team of 5 robots on the MSL field (bench/team_sim.*:
// ball and 5 opponents moving, a camera model per robot), against the
// simulation's ground truth; then the full-cycle time of 50 objects x 5
// robots. Prints `name: value unit` lines (scripts/bench.sh).
//   map_bench [minutes=10] [seed=1] [model=config/robocup.yaml] [--team-rate 10] [--team-latency 0.05]
//             [--scenario team|random|both] [--no-cycle-time]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_map/assignment.h"
#include "mrt_map/team_sender.h"
#include "mrt_map/world_model.h"
#include "bench_diag.h"
#include "team_sim.h"

using namespace mrt::map;
using bench::BallDiag;
using bench::SwitchDiag;
using bench::TeamSim;

namespace {

constexpr double kDt = 1.0 / 30.0;       // camera and MAP rate
double g_team_period = 0.1;      // team exchange, 10 Hz (--team-rate)
double g_team_latency = 0.05;    // s, network delay (--team-latency)

struct Stats {
  double se = 0.0;  // squared errors within 5 m of the nearest teammate
  long n_err = 0;
  double se_obs = 0.0, se_all = 0.0;  // within 5 m of the nearest robot that has it in view; all steps
  long n_obs = 0, n_all = 0;
  long known = 0, steps = 0;
  double rmse() const { return n_err ? std::sqrt(se / static_cast<double>(n_err)) : NAN; }
  double rmse_obs() const { return n_obs ? std::sqrt(se_obs / static_cast<double>(n_obs)) : NAN; }
  double rmse_all() const { return n_all ? std::sqrt(se_all / static_cast<double>(n_all)) : NAN; }
  double availability() const { return steps ? static_cast<double>(known) / static_cast<double>(steps) : NAN; }
};

// The ball anchor MAP would give Mr. BRIAN (config/robocup.yaml's BallDistance,
// `select: best_supported`): the best supported confirmed one (or
// confirmed/coasting with `coasting`).
const Anchor* ball_anchor(const WorldModel& w, int ball_class, double now, bool coasting = false) {
  const Anchor* best = nullptr;
  for (const Anchor& a : w.tracker().anchors())
    if ((a.status == AnchorStatus::kConfirmed || (coasting && a.status == AnchorStatus::kCoasting)) &&
        w.model().is_a(a.class_index, ball_class) &&
        (!best || w.tracker().support(a, now) > w.tracker().support(*best, now)))
      best = &a;
  return best;
}

// What the scoring of one step knows of the truth.
struct BallTruth {
  Vec2 p;
  bool near;         // within 5 m of the nearest teammate
  double nearest;    // m
  bool near_observer;  // within 5 m of the nearest robot that has it in view (range, occlusion)
  int observers;     // robots with the ball in view
  double since_kick;
  Vec2 v;            // the ball's velocity
};

void score_ball(const WorldModel& w, int ball_class, double now, const BallTruth& t, Stats& s,
                BallDiag* diag = nullptr) {
  ++s.steps;
  const Anchor* a = ball_anchor(w, ball_class, now);
  const double e = a ? (a->fused.x.head<2>() - t.p).norm() : INFINITY;
  if (e < 0.5) ++s.known;  // known = a confirmed ball anchor within 0.5 m
  if (a && t.near) {
    s.se += e * e;
    ++s.n_err;
  }
  if (a && t.near_observer) s.se_obs += e * e, ++s.n_obs;
  if (a) s.se_all += e * e, ++s.n_all;
  if (!diag) return;
  ++diag->steps;
  const Anchor* c = ball_anchor(w, ball_class, now, true);
  if (c && (c->fused.x.head<2>() - t.p).norm() < 0.5) ++diag->known_coasting;
  if (t.observers > 0) ++diag->visible;
  if (e < 0.5) diag->known_visible += t.observers > 0;
  else if (t.observers == 0) ++diag->lost_unseen;
  else if (!a) ++diag->lost_no_anchor;
  else ++diag->lost_far;
  if (a && t.near) diag->error(e, t.since_kick, t.nearest, t.observers);
  if (std::getenv("MAP_BENCH_BALLDBG") && a && t.near && e > 0.3)
    std::printf("balldbg obs=%d nearest=%.2f t=%.2f e=%.2f local=%d fresh=%d remotes=%zu truth=(%.2f,%.2f) est=(%.2f,%.2f) v=(%.2f,%.2f) kick=%.2f id=%u\n",
                t.observers, t.nearest, now, e, a->has_local, a->local_last_seen >= now, a->remote.size(), t.p.x(), t.p.y(), a->fused.x(0),
                a->fused.x(1), a->fused.x(2), a->fused.x(3), t.since_kick, a->id);
  if (a && t.near && a->has_local && a->local_last_seen >= now) {
    diag->local_fresh.add((a->local.x.head<2>() - t.p).norm());
    diag->local_fresh_velocity.add((a->local.x.tail<2>() - t.v).norm());
    if (t.since_kick > 0.5) diag->local_fresh_velocity_rolling.add((a->local.x.tail<2>() - t.v).norm());
    diag->fused_when_local_fresh.add(e);
  } else if (a && t.near) {
    diag->fused_from_teammates.add(e);
    // Per source: each teammate's latency-compensated anchor alone, and
    // the most recently seen one (what the fusion could do at best/worst).
    const RemoteTrack* newest = nullptr;
    for (const auto& [robot, r] : a->remote) {
      const double err = (r.estimate.x.head<2>() - t.p).norm(), age = now - r.last_seen;
      diag->teammate_each.add(err);
      diag->teammate_by_age[age < 0.1 ? 0 : age < 0.2 ? 1 : 2].add(err);
      if (t.since_kick > age) diag->teammate_no_kick_since.add(err);
      if (!newest || r.last_seen > newest->last_seen) newest = &r;
    }
    if (newest) diag->teammate_newest.add((newest->estimate.x.head<2>() - t.p).norm());
    if (a->has_local) diag->own_stale.add((a->local.x.head<2>() - t.p).norm());
    diag->teammates_linked.add(static_cast<double>(a->remote.size()));
  }
}

struct Message {
  double deliver;
  std::string robot;
  std::vector<RemoteTrack> tracks;
  double stamp;
  RobotPose pose;
};

struct AnchorCounts {
  double robots = 0.0, balls = 0.0, alone_robots = 0.0;
};

void count_anchors(const WorldModel& team, const WorldModel& alone, int ball_class, int opp_class, AnchorCounts& c) {
  for (const Anchor& a : team.tracker().anchors())
    if (a.status == AnchorStatus::kConfirmed) {
      c.robots += team.model().is_a(a.class_index, opp_class);
      c.balls += team.model().is_a(a.class_index, ball_class);
    }
  for (const Anchor& a : alone.tracker().anchors())
    if (a.status == AnchorStatus::kConfirmed) c.alone_robots += alone.model().is_a(a.class_index, opp_class);
}

std::map<long, std::string>& last_state() {
  static std::map<long, std::string> m;
  return m;
}

// The CLEAR MOT correspondence (Bernardin and Stiefelhagen, 2008), one to
// one: an opponent keeps last step's anchor while that anchor is confirmed
// and within 0.5 m of it (and no other opponent kept it first); the others
// are matched to the remaining confirmed Opponent anchors within 0.5 m by a
// minimum total distance assignment; an opponent matched to a different id
// than its last one is an identity switch. (Until session 19 each opponent
// took its nearest anchor on its own, so two touching opponents could both
// take one anchor: a switch and a switch back within a step or two.)
std::vector<const Anchor*> correspond(const WorldModel& w, int opp_class, const TeamSim& sim,
                                      const std::vector<long>& last_id) {
  constexpr double kRadius = 0.5;
  const std::size_t n = sim.opponents().size();
  std::vector<const Anchor*> anchors, match(n, nullptr);
  for (const Anchor& a : w.tracker().anchors())
    if (a.status == AnchorStatus::kConfirmed && w.model().is_a(a.class_index, opp_class)) anchors.push_back(&a);
  std::vector<bool> used(anchors.size(), false);
  auto dist = [&](std::size_t o, std::size_t k) {
    return (anchors[k]->fused.x.head<2>() - sim.opponents()[o].p).norm();
  };
  for (std::size_t o = 0; o < n; ++o)
    for (std::size_t k = 0; k < anchors.size(); ++k)
      if (!used[k] && static_cast<long>(anchors[k]->id) == last_id[o] && dist(o, k) < kRadius) {
        match[o] = anchors[k];
        used[k] = true;
      }
  std::vector<std::size_t> rows, cols;
  for (std::size_t o = 0; o < n; ++o)
    if (!match[o]) rows.push_back(o);
  for (std::size_t k = 0; k < anchors.size(); ++k)
    if (!used[k]) cols.push_back(k);
  std::vector<std::vector<double>> cost(rows.size(), std::vector<double>(cols.size(), kInfeasible));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < cols.size(); ++c)
      if (dist(rows[r], cols[c]) < kRadius) cost[r][c] = dist(rows[r], cols[c]);
  const std::vector<int> m = assign(cost, kRadius);
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (m[r] >= 0) match[rows[r]] = anchors[cols[static_cast<std::size_t>(m[r])]];
  return match;
}

long identity_switches(const WorldModel& w, int opp_class, const TeamSim& sim, std::vector<long>& last_id,
                       std::vector<bool>& was_matched, SwitchDiag& diag) {
  long switches = 0;
  const std::vector<const Anchor*> match = correspond(w, opp_class, sim, last_id);
  for (std::size_t o = 0; o < sim.opponents().size(); ++o) {
    const Anchor* best = match[o];
    const bool matched_before = was_matched[o];
    was_matched[o] = best != nullptr;
    ++(best ? diag.matched_steps : diag.unmatched_steps);
    if (!best) continue;
    if (last_id[o] >= 0 && last_id[o] != static_cast<long>(best->id)) {
      ++switches;
      diag.count(o);
      ++(matched_before ? diag.while_tracked : diag.at_reacquisition);
      if (std::getenv("MAP_BENCH_DEBUG")) {
        const Anchor* old = nullptr;
        for (const Anchor& a : w.tracker().anchors()) if (static_cast<long>(a.id) == last_id[o]) old = &a;
        std::printf("switch t=%.2f opp %zu: %ld -> %u (new age %.2f s, %s)", w.tracker().now(), o, last_id[o], best->id,
                    w.tracker().now() - best->first_seen, matched_before ? "tracked" : "reacq");
        std::printf(" new: local=%d remotes=%zu", best->has_local, best->remote.size());
        int nc = 0, nco = 0, nt = 0;
        for (const Anchor& a : w.tracker().anchors())
          if (w.model().is_a(a.class_index, opp_class))
            ++(a.status == AnchorStatus::kConfirmed ? nc : a.status == AnchorStatus::kCoasting ? nco : nt);
        std::printf(" [opp conf %d coast %d tent %d]", nc, nco, nt);
        if (old)
          std::printf(" old %s d=%.2f m sigma=%.2f unseen %.2f s", to_string(old->status),
                      (old->fused.x.head<2>() - sim.opponents()[o].p).norm(), std::sqrt(old->fused.P(0, 0)),
                      w.tracker().now() - old->last_seen);
        else
          std::printf(" old gone (last: %s)", last_state()[last_id[o]].c_str());
        std::printf("\n");
      }
    }
    last_id[o] = best->id;
  }
  if (std::getenv("MAP_BENCH_DEBUG"))
    for (const Anchor& a : w.tracker().anchors()) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s %s sigma=%.2f unseen=%.2f", w.model().at(a.class_index).name.c_str(),
                    to_string(a.status), std::sqrt(a.fused.P(0, 0)), w.tracker().now() - a.last_seen);
      last_state()[a.id] = buf;
    }
  return switches;
}

// The team's pooled figures and the best single robot's.
std::tuple<Stats, double, double> summarise(const std::vector<Stats>& team_stats, const std::vector<Stats>& alone_stats) {
  Stats team_all;
  double best_alone_rmse = INFINITY, best_alone_avail = 0.0;
  for (std::size_t i = 0; i < team_stats.size(); ++i) {
    team_all.se += team_stats[i].se;
    team_all.n_err += team_stats[i].n_err;
    team_all.se_obs += team_stats[i].se_obs;
    team_all.n_obs += team_stats[i].n_obs;
    team_all.se_all += team_stats[i].se_all;
    team_all.n_all += team_stats[i].n_all;
    team_all.known += team_stats[i].known;
    team_all.steps += team_stats[i].steps;
    best_alone_rmse = std::min(best_alone_rmse, alone_stats[i].rmse());
    best_alone_avail = std::max(best_alone_avail, alone_stats[i].availability());
  }
  return {team_all, best_alone_rmse, best_alone_avail};
}

// The `map_<tag>...` lines of one scenario.
void print_run(const char* tag, double minutes, const std::vector<Stats>& team_stats,
               const std::vector<Stats>& alone_stats, double in_view, long switches, std::size_t opponents,
               const AnchorCounts& counts, long steps) {
  const auto [team_all, best_alone_rmse, best_alone_avail] = summarise(team_stats, alone_stats);
  const double per10 = static_cast<double>(switches) / static_cast<double>(opponents) /
                       (minutes / 10.0);
  auto line = [tag](const char* name, double value, const char* unit) {
    std::printf("map_%s%s: %.4f %s\n", tag, name, value, unit);
  };
  line("sim_minutes", minutes, "min");
  line("ball_rmse_team_within_5m_of_observer", team_all.rmse_obs(), "m");
  line("ball_rmse_team_within_5m", team_all.rmse(), "m");
  line("ball_rmse_team_all", team_all.rmse_all(), "m");
  line("ball_rmse_best_single_within_5m", best_alone_rmse, "m");
  line("ball_availability_team", 100.0 * team_all.availability(), "%");
  line("ball_availability_best_single", 100.0 * best_alone_avail, "%");
  line("ball_in_view_of_a_robot", 100.0 * in_view, "%");
  line("opponent_id_switches", static_cast<double>(switches), "count");
  line("opponent_id_switches_per_opponent_per_10min", per10, "count");
  line("confirmed_opponent_anchors_team_mean", counts.robots / steps, "count (truth: 5)");
  line("confirmed_opponent_anchors_single_mean", counts.alone_robots / steps, "count");
  line("confirmed_ball_anchors_team_mean", counts.balls / steps, "count (truth: 1)");
}

// The two scenarios. `random` (the first one): every robot on random
// waypoints, 6 m camera range, 90 % detection. `team` (the default since):
// both teams play (team_sim.cpp) and the camera sees as far as the
// simulated omnidirectional camera does: 8 m, detection falling from 98 %
// to 70 % (mrt_sim's realistic model's misses), sigma_d growing with d^2.
bench::CameraModel camera(bool team_play) {
  bench::CameraModel cam;
  if (!team_play) return cam;
  cam.range = 8.0;
  cam.p_detect = 0.98;
  cam.p_detect_far = 0.70;
  cam.sigma_d_quad = 0.001;
  return cam;
}

void team_run(const ConceptualModel& model, double minutes, unsigned seed, bool team_play) {
  TeamSim sim(seed, team_play);
  const bench::CameraModel cam = camera(team_play);
  const char* tag = team_play ? "" : "random_scenario_";
  const int n = static_cast<int>(sim.mates().size());
  std::vector<std::unique_ptr<WorldModel>> team, alone;
  std::vector<TeamSender> senders(static_cast<std::size_t>(n), TeamSender(model, g_team_period, std::min(0.5 * kDt, 0.5 * g_team_period)));
  for (int i = 0; i < n; ++i) {
    team.push_back(std::make_unique<WorldModel>(model, WorldModelOptions{"r" + std::to_string(i), 0.5}));
    alone.push_back(std::make_unique<WorldModel>(model, WorldModelOptions{"r" + std::to_string(i), 0.5}));
  }
  const int ball_class = model.find("Ball"), opp_class = model.find("Opponent");
  std::vector<Stats> team_stats(n), alone_stats(n);
  std::deque<Message> network;
  // Identity switches: for each opponent, the id of robot 0's team anchor on it.
  std::vector<long> last_id(sim.opponents().size(), -1);
  std::vector<bool> was_matched(sim.opponents().size(), false);
  SwitchDiag switch_diag;
  BallDiag ball_diag;
  long switches = 0;
  AnchorCounts counts;
  const long steps = static_cast<long>(minutes * 60.0 / kDt);
  mrt::cli::Progress progress("map_bench", static_cast<double>(steps));
  for (long k = 0; k < steps; ++k) {
    progress.update(static_cast<double>(k));
    const double t = k * kDt;
    sim.step(kDt);
    while (!network.empty() && network.front().deliver <= t) {
      const Message& m = network.front();
      for (int i = 0; i < n; ++i) team[i]->add_teammate_model(m.robot, m.tracks, m.stamp, &m.pose);
      network.pop_front();
    }
    BallTruth truth{sim.ball().p, false, INFINITY, false, 0, sim.since_kick(), sim.ball().v};
    for (const auto& b : sim.mates()) truth.nearest = std::min(truth.nearest, (b.p - sim.ball().p).norm());
    for (int i = 0; i < n; ++i) {
      const bool sees = sim.ball_in_view(i, cam);
      truth.observers += sees;
      if (sees && (sim.mates()[i].p - sim.ball().p).norm() <= 5.0) truth.near_observer = true;
    }
    truth.near = truth.nearest <= 5.0 && k * kDt > 2.0;
    for (int i = 0; i < n; ++i) {
      RobotPose pose;
      const auto objects = sim.see(i, cam, pose);
      for (auto* w : {team[i].get(), alone[i].get()}) {
        w->set_robot_pose(pose, t);
        w->add_percept(objects, pose, t, t, "omnivision");
        w->update(t);
      }
      if (k * kDt > 2.0) {
        score_ball(*team[i], ball_class, t, truth, team_stats[i], &ball_diag);
        score_ball(*alone[i], ball_class, t, truth, alone_stats[i]);
      }
      TeamSender& sender = senders[static_cast<std::size_t>(i)];
      std::vector<RemoteTrack> tracks = team[i]->local_tracks();
      if (sender.due(t, tracks)) {
        sender.sent(t, tracks);
        network.push_back({t + g_team_latency, team[i]->options().robot, std::move(tracks), t, pose});
      }
    }
    count_anchors(*team[0], *alone[0], ball_class, opp_class, counts);
    for (int o = 0; o < static_cast<int>(sim.opponents().size()); ++o) {
      bool in_view = false;
      for (int i = 0; i < n && !in_view; ++i) in_view = sim.opponent_in_view(i, o, cam);
      switch_diag.visibility(static_cast<std::size_t>(o), in_view, kDt);
    }
    switches += identity_switches(*team[0], opp_class, sim, last_id, was_matched, switch_diag);
  }
  progress.finish();
  print_run(tag, minutes, team_stats, alone_stats, ball_diag.in_view_share(), switches, sim.opponents().size(), counts,
            steps);
  double periodic = 0.0, on_deviation = 0.0;
  for (const TeamSender& s : senders) periodic += s.periodic(), on_deviation += s.on_deviation();
  const double robot_seconds = n * minutes * 60.0;
  std::printf("map_%steam_messages_per_robot_per_s: %.2f Hz (periodic %.2f, on deviation %.2f)\n", tag,
              (periodic + on_deviation) / robot_seconds, periodic / robot_seconds, on_deviation / robot_seconds);
  if (!team_play) return;  // the diagnostics of the default scenario only
  ball_diag.print();
  switch_diag.print(sim.opponents().size(), minutes);
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// 50 objects seen by a robot and by each of its 4 teammates: one full
// cycle (classify 50 percept objects, merge, associate, 4 x 50 teammates'
// anchors compensated and fused, life cycle, crisp data).
void cycle_time(const ConceptualModel& model) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-8.5, 8.5), uy(-5.5, 5.5);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<Vec2> objects(50);
  for (Vec2& p : objects) p = Vec2(ux(rng), uy(rng));
  std::vector<std::unique_ptr<WorldModel>> team;
  for (int i = 0; i < 5; ++i) team.push_back(std::make_unique<WorldModel>(model, WorldModelOptions{"r" + std::to_string(i), 0.5}));
  auto percepts = [&](const RobotPose& pose) {
    std::vector<PerceptObject> out;
    for (const Vec2& p : objects) {
      PerceptObject o;
      o.membership_class = "Robot";
      o.attributes.push_back({"color", 0.0, "cyan", 0.0, 1.0});
      const Vec2 d = p - Vec2(pose.x, pose.y);
      o.set("distance", d.norm() + noise(rng), 0.02, 1.0);
      o.set("bearing", std::atan2(d.y(), d.x()), 0.005, 1.0);
      out.push_back(o);
    }
    return out;
  };
  RobotPose pose;
  pose.cov = 1e-4 * Mat2::Identity();
  double t = 0.0, total = 0.0, total_cpu = 0.0;
  int measured = 0;
  for (int k = 0; k < 600; ++k, t += kDt) {
    for (int i = 1; i < 5; ++i) {
      team[i]->add_percept(percepts(pose), pose, t, t, "cam");
      team[i]->update(t);
    }
    const auto objs = percepts(pose);
    const double cpu_start = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 1; i < 5; ++i) team[0]->add_teammate_model(team[i]->options().robot, team[i]->local_tracks(), t);
    team[0]->add_percept(objs, pose, t, t, "cam");
    team[0]->update(t);
    const auto c = team[0]->crisp(t);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = thread_cpu_seconds() - cpu_start;
    if (k >= 100) total += dt, total_cpu += cpu, ++measured;
    if (c.empty()) std::abort();
  }
  const double ms = 1e3 * total / measured;
  std::printf("map_anchors_in_cycle_test: %zu count\n", team[0]->tracker().anchors().size());
  std::printf("map_cycle_50x5: %.4f ms\n", ms);
  std::printf("map_cycle_50x5_vs_1ms_budget: %.3f ratio\n", ms / 1.0);
  // CPU time of this thread: what the cycle costs on one core, whatever
  // else the machine runs (the wall time above includes waiting for a core).
  std::printf("map_cycle_50x5_cpu: %.4f ms\n", 1e3 * total_cpu / measured);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"map_bench: MAP's cycle time (50 objects x 5 robots) and a simulated team run on the MSL field"};
  double minutes = 10.0;
  unsigned seed = 1;
  std::string model_file = MRT_MAP_CONFIG_DIR "/robocup.yaml";
  app.add_option("minutes", minutes, "simulated minutes of the team run")->check(CLI::PositiveNumber);
  app.add_option("seed", seed, "random seed");
  app.add_option("model", model_file, "conceptual model YAML")->check(CLI::ExistingFile);
  double team_rate = 1.0 / g_team_period;
  app.add_option("--team-rate", team_rate, "Hz, team exchange (default 10)")->check(CLI::PositiveNumber);
  app.add_option("--team-latency", g_team_latency, "s, network delay of the team exchange (default 0.05)")
      ->check(CLI::NonNegativeNumber);
  std::string scenario = "both";
  app.add_option("--scenario", scenario, "team (team play), random (the first scenario) or both (default)")
      ->check(CLI::IsMember({"team", "random", "both"}));
  bool no_cycle = false;
  app.add_flag("--no-cycle-time", no_cycle, "skip the 50 x 5 cycle-time measurement");
  const int rc = mrt::cli::parse_cli(app, argc, argv);
  if (rc >= 0) return rc;
  g_team_period = 1.0 / team_rate;
  const ConceptualModel model = ConceptualModel::load(model_file);
  if (!no_cycle) cycle_time(model);
  if (scenario != "random") team_run(model, minutes, seed, true);
  if (scenario != "team") team_run(model, minutes, seed, false);  // the first scenario's figures, for comparison
  return 0;
}
