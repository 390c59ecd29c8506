// A simulated game for scare_bench: five Coordinators, each on its own
// 100 ms cycle (phases spread over the period), exchanging messages with
// 20 % loss and a uniform 0-100 ms delay; each sees the ball and itself
// with its own 5 cm noise. The ball and the needs drift smoothly; robots
// drive to their roles' targets. Measured: cycles in which two robots hold
// the same exclusive role (role max 1), re-assignments per robot per 10 s,
// and, after a robot drops out, cycles from the first survivor dropping it
// until every survivor holds a slot, no slot is over-full and every schema
// one of them holds is covered.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

#include "mrt_scare/coordinator.h"

namespace mrt::scare::bench {

namespace {

constexpr double kDt = 0.001, kPeriod = 0.1;
constexpr long kTicks = 100;  // ticks of kDt per cycle

struct Pending {
  double at;
  int to;
  CoordinationMessage m;
};

struct Game {
  const ActivitySet& set;
  std::vector<Coordinator> c;
  std::vector<Pose2D> pose;
  std::vector<long> phase;  // ticks
  std::vector<bool> alive;
  std::vector<Pending> queue;
  std::mt19937 rng{9};
  std::uniform_real_distribution<double> uni{0.0, 1.0};
  std::normal_distribution<double> noise{0.0, 0.05};
  std::size_t checks = 0, conflicts = 0, changes = 0;
  std::vector<std::vector<double>> change_times = std::vector<std::vector<double>>(5);  // per robot, s
  std::vector<int> last_held = std::vector<int>(5, -1);  // per robot, the last slot it held
  std::vector<int> left = std::vector<int>(5, -1);       // per robot, the slot its last change left
  std::size_t flips = 0;

  explicit Game(const ActivitySet& s) : set(s) {
    for (int r = 0; r < 5; ++r) {
      c.emplace_back(s, s.robot_or_default("robot" + std::to_string(r)));
      pose.emplace_back(-6.0 + 3.0 * r, r % 2 ? 2.0 : -2.0, 0.0);
      phase.push_back(17 * r);
      alive.push_back(true);
    }
  }

  CrispMap world(double t) {
    CrispMap w{{"BallX", {6.0 * std::sin(0.1 * t) + noise(rng), 1}}, {"BallY", {4.0 * std::sin(0.13 * t) + noise(rng), 1}}};
    for (int k = 0; k < 4; ++k) w["N" + std::to_string(k)] = {0.5 + 0.5 * std::sin(0.05 * t + 1.7 * k), 1};
    return w;
  }

  void drive(int r, const CrispMap& w) {
    const int s = c[static_cast<std::size_t>(r)].own_slot();
    if (s < 0) return;
    const Slot sl = set.slots()[static_cast<std::size_t>(s)];
    const Target& tg = set.activities[static_cast<std::size_t>(sl.activity)].roles[static_cast<std::size_t>(sl.role)].target;
    Point2D goal{tg.x, tg.y};
    if (tg.kind == Target::Kind::kNone) return;
    if (tg.kind == Target::Kind::kCrisp) goal = {w.at(tg.x_datum).first, w.at(tg.y_datum).first};
    Pose2D& p = pose[static_cast<std::size_t>(r)];
    const double dx = goal.x - p.x, dy = goal.y - p.y, d = std::hypot(dx, dy);
    const double step = std::min(d, 0.5 * set.robot_or_default(c[static_cast<std::size_t>(r)].id()).max_speed * kPeriod);
    if (d > 1e-9) p = Pose2D(p.x + dx / d * step, p.y + dy / d * step, 0);
  }

  /// Robot r's cycle at time t: publish, deliver with loss and delay, step.
  void cycle(int r, double t) {
    const CrispMap w = world(t);
    const Pose2D& p = pose[static_cast<std::size_t>(r)];
    const CoordinationMessage m = c[static_cast<std::size_t>(r)].publish(t, Pose2D(p.x + noise(rng), p.y + noise(rng), 0), w);
    for (int j = 0; j < 5; ++j)
      if (j != r && uni(rng) >= 0.2) queue.push_back({t + 0.1 * uni(rng), j, m});
    c[static_cast<std::size_t>(r)].step(t);
    // A re-assignment: the robot takes a slot other than the last one it
    // held, directly or after waiting (release before acquire) in between.
    const int after = c[static_cast<std::size_t>(r)].own_slot();
    int& held = last_held[static_cast<std::size_t>(r)];
    if (after >= 0 && held >= 0 && after != held) {
      ++changes;
      auto& times = change_times[static_cast<std::size_t>(r)];
      // A flip-flop: back to the slot it left less than 1 s ago.
      flips += !times.empty() && t - times.back() < 1.0 && after == left[static_cast<std::size_t>(r)];
      times.push_back(t);
      left[static_cast<std::size_t>(r)] = held;
    }
    if (after >= 0) held = after;
    drive(r, w);
    check();
  }

  void check() {
    std::vector<int> held(set.slots().size(), 0);
    for (std::size_t r = 0; r < c.size(); ++r)
      if (alive[r] && c[r].own_slot() >= 0) ++held[static_cast<std::size_t>(c[r].own_slot())];
    bool conflict = false;
    for (std::size_t s = 0; s < held.size(); ++s) {
      const Slot sl = set.slots()[s];
      conflict = conflict ||
                 held[s] > set.activities[static_cast<std::size_t>(sl.activity)].roles[static_cast<std::size_t>(sl.role)].max;
    }
    ++checks;
    conflicts += conflict;
  }

  void deliver(double t) {
    auto due = std::partition(queue.begin(), queue.end(), [t](const Pending& p) { return p.at > t; });
    for (auto it = due; it != queue.end(); ++it)
      if (alive[static_cast<std::size_t>(it->to)]) c[static_cast<std::size_t>(it->to)].receive(it->m);
    queue.erase(due, queue.end());
  }

  /// Runs [t0, t1); robot cycles at their phases.
  void run(long k0, long k1, const std::function<void(double)>& after_tick = {}) {
    for (long k = k0; k < k1; ++k) {
      const double t = kDt * static_cast<double>(k);
      deliver(t);
      for (int r = 0; r < 5; ++r)
        if (alive[static_cast<std::size_t>(r)] && (k - phase[static_cast<std::size_t>(r)]) % kTicks == 0) cycle(r, t);
      if (after_tick) after_tick(t);
    }
  }

  /// Every survivor holds a slot, no slot holds more robots than its role
  /// allows, and every schema a survivor holds has all its roles filled.
  bool covered() const {
    std::vector<int> held(set.slots().size(), 0);
    for (std::size_t r = 0; r < c.size(); ++r) {
      if (!alive[r]) continue;
      if (c[r].own_slot() < 0) return false;
      ++held[static_cast<std::size_t>(c[r].own_slot())];
    }
    const auto slots = set.slots();
    for (std::size_t s = 0; s < slots.size(); ++s) {
      const RoleSpec& role = set.activities[static_cast<std::size_t>(slots[s].activity)].roles[static_cast<std::size_t>(slots[s].role)];
      int total = 0;
      for (std::size_t k = 0; k < slots.size(); ++k) total += slots[k].activity == slots[s].activity ? held[k] : 0;
      if (held[s] > role.max || (total > 0 && held[s] < role.min)) return false;
    }
    return true;
  }
};

/// Per robot, the most re-assignments in any 10 s window (sliding), and
/// the fixed 10 s windows [10k, 10k + 10) of any robot with more than one.
void print_windows(const Game& g, double duration, const char* name) {
  std::size_t worst = 0, over = 0, windows = 0;
  for (const auto& times : g.change_times) {
    for (std::size_t i = 0, j = 0; i < times.size(); ++i) {
      while (j < times.size() && times[j] < times[i] + 10.0) ++j;
      worst = std::max(worst, j - i);
    }
    for (double w = 0.0; w + 10.0 <= duration + 1e-9; w += 10.0, ++windows)
      over += std::count_if(times.begin(), times.end(), [w](double t) { return t >= w && t < w + 10.0; }) > 1;
  }
  std::size_t busiest = 0;
  for (const auto& times : g.change_times) busiest = std::max(busiest, times.size());
  std::printf("%s_reassignments_busiest_robot_per_10s: %.3f count\n",
              name, static_cast<double>(busiest) / (duration / 10.0));
  std::printf("%s_reassignments_max_in_any_10s_window: %zu count\n", name, worst);
  std::printf("%s_robot_10s_windows_over_one: %zu of %zu count\n", name, over, windows);
  std::printf("%s_flip_flops_within_1s: %zu count\n", name, g.flips);
}

}  // namespace

void run_game(const ActivitySet& set, const char* name, bool dropouts) {
  const double duration = 600.0;  // s of game
  Game g(set);
  g.run(0, static_cast<long>(duration / kDt));
  std::printf("%s_cycles_checked: %zu count\n", name, g.checks);
  std::printf("%s_consistent_cycles: %.3f %%\n", name, 100.0 * (1.0 - double(g.conflicts) / double(g.checks)));
  std::printf("%s_reassignments_per_robot_per_10s: %.3f count\n", name, g.changes / 5.0 / (duration / 10.0));
  print_windows(g, duration, name);
  if (!dropouts) return;
  // Drop-outs: 50 trials, each from a game settled for 20 s; the robot
  // holding a schema role if any, else robot4, falls silent.
  int worst = 0, worst_all = 0, failed = 0;
  double sum = 0.0, sum_all = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    Game d(set);
    d.rng.seed(100 + trial);
    const long k_stop = 20000 + 370 * trial;
    d.run(0, k_stop);
    int victim = 4;
    for (int r = 0; r < 5; ++r)
      if (d.c[r].own_slot() >= 0 &&
          set.activities[static_cast<std::size_t>(set.slots()[static_cast<std::size_t>(d.c[r].own_slot())].activity)].schema)
        victim = r;
    d.alive[static_cast<std::size_t>(victim)] = false;
    double detected = -1.0, all_detected = -1.0, restored = -1.0;
    d.run(k_stop, k_stop + 3000, [&](double t) {
      bool any = false, all = true;  // the first / every survivor dropped the silent robot
      for (int r = 0; r < 5; ++r) {
        if (!d.alive[static_cast<std::size_t>(r)]) continue;
        any = any || d.c[r].team_size() == 4;
        all = all && d.c[r].team_size() == 4;
      }
      if (any && detected < 0) detected = t;
      if (all && all_detected < 0) all_detected = t;
      if (detected >= 0 && restored < 0 && d.covered()) restored = t;
    });
    if (restored < 0) {
      ++failed;
      continue;
    }
    const int cycles = static_cast<int>(std::ceil((restored - detected) / kPeriod - 1e-9));
    const int cycles_all = static_cast<int>(std::ceil(std::max(0.0, restored - all_detected) / kPeriod - 1e-9));
    worst = std::max(worst, cycles);
    sum += cycles;
    worst_all = std::max(worst_all, cycles_all);
    sum_all += cycles_all;
  }
  std::printf("coordination_dropout_restore_cycles_mean: %.2f cycles\n", sum / std::max(1, 50 - failed));
  std::printf("coordination_dropout_restore_cycles_max: %d cycles\n", worst);
  std::printf("coordination_dropout_restore_after_all_detected_mean: %.2f cycles\n", sum_all / std::max(1, 50 - failed));
  std::printf("coordination_dropout_restore_after_all_detected_max: %d cycles\n", worst_all);
  std::printf("coordination_dropout_not_restored_in_3s: %d count\n", failed);
}

}  // namespace mrt::scare::bench
