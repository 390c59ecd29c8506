// map_bench's error analysis: where the fused ball error, the lost ball
// and the identity switches come from (printed as `diag_*` lines).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace mrt::map::bench {

struct ErrorBin {
  double se = 0.0;
  long n = 0;
  void add(double e) { se += e * e, ++n; }
  double rmse() const { return n ? std::sqrt(se / static_cast<double>(n)) : NAN; }
};

struct BallDiag {
  // Error within 5 m of the nearest observer, split three ways.
  ErrorBin just_kicked, rolling;            // < 0.5 s after a kick / later
  std::array<ErrorBin, 3> by_distance;      // nearest observer 0-2, 2-4, 4-5 m
  std::array<ErrorBin, 3> by_observers;     // robots with the ball in view: 0, 1, >= 2
  // Availability: steps with the ball in view of at least one robot (range,
  // occlusion), and why the ball is not known.
  long steps = 0, visible = 0, known_visible = 0, known_coasting = 0;
  long lost_unseen = 0;        // nobody has it in view and no confirmed anchor within 0.5 m
  long lost_no_anchor = 0;     // in view, but no confirmed ball anchor (tentative, coasting or none)
  long lost_far = 0;           // in view, a confirmed anchor more than 0.5 m off

  std::vector<double> errors;
  ErrorBin local_fresh, fused_when_local_fresh;  // the robot sees it itself this step
  ErrorBin fused_from_teammates;                 // it does not: its teammates' anchors only
  ErrorBin teammate_each, teammate_newest, own_stale;  // ... per source
  std::array<ErrorBin, 3> teammate_by_age;       // its own sighting 0-0.1, 0.1-0.2, >= 0.2 s old
  ErrorBin teammate_no_kick_since;               // no kick since its sighting
  ErrorBin teammates_linked;
  ErrorBin local_fresh_velocity, local_fresh_velocity_rolling;  // own filter's velocity error (m/s)                     // (rmse of the count: sqrt(mean n^2))
  void error(double e, double since_kick, double nearest, int observers) {
    errors.push_back(e);
    (since_kick < 0.5 ? just_kicked : rolling).add(e);
    by_distance[nearest < 2.0 ? 0 : nearest < 4.0 ? 1 : 2].add(e);
    by_observers[observers >= 2 ? 2 : observers].add(e);
  }
  double in_view_share() const { return steps ? static_cast<double>(visible) / static_cast<double>(steps) : NAN; }
  void print() {
    std::sort(errors.begin(), errors.end());
    double big = 0.0, all = 0.0;
    for (double e : errors) all += e * e, big += e > 0.2 ? e * e : 0.0;
    auto q = [&](double f) { return errors.empty() ? NAN : errors[static_cast<std::size_t>(f * static_cast<double>(errors.size() - 1))]; };
    std::printf("diag_ball_error_p50_p90_p99: %.4f %.4f %.4f m\n", q(0.5), q(0.9), q(0.99));
    std::printf("diag_ball_squared_error_share_above_20cm: %.1f %%\n", all > 0 ? 100.0 * big / all : NAN);
    std::printf("map_ball_rmse_team_robot_sees_it_within_5m: %.4f m (own filter %.4f m, %ld samples)\n",
                fused_when_local_fresh.rmse(), local_fresh.rmse(), local_fresh.n);
    std::printf("map_ball_rmse_team_from_teammates_only_within_5m: %.4f m (%ld samples)\n",
                fused_from_teammates.rmse(), fused_from_teammates.n);
    std::printf("diag_ball_teammates_only_per_source: each teammate's anchor %.4f m, the newest %.4f m, "
                "own stale filter %.4f m (%ld samples), linked teammates %.2f\n",
                teammate_each.rmse(), teammate_newest.rmse(), own_stale.rmse(), own_stale.n, teammates_linked.rmse());
    std::printf("diag_ball_teammate_anchor_by_age: 0-0.1 s %.4f m (%ld), 0.1-0.2 s %.4f m (%ld), >= 0.2 s %.4f m (%ld); "
                "no kick since its sighting %.4f m\n",
                teammate_by_age[0].rmse(), teammate_by_age[0].n, teammate_by_age[1].rmse(), teammate_by_age[1].n,
                teammate_by_age[2].rmse(), teammate_by_age[2].n, teammate_no_kick_since.rmse());
    std::printf("diag_ball_own_filter_velocity_rmse_robot_sees_it: %.4f m/s (> 0.5 s after a kick %.4f m/s)\n",
                local_fresh_velocity.rmse(), local_fresh_velocity_rolling.rmse());
    std::printf("diag_ball_rmse_just_kicked: %.4f m (%ld samples)\n", just_kicked.rmse(), just_kicked.n);
    std::printf("diag_ball_rmse_rolling: %.4f m (%ld samples)\n", rolling.rmse(), rolling.n);
    const char* d[] = {"0_2m", "2_4m", "4_5m"};
    for (int i = 0; i < 3; ++i)
      std::printf("diag_ball_rmse_nearest_%s: %.4f m (%ld samples)\n", d[i], by_distance[i].rmse(), by_distance[i].n);
    const char* o[] = {"0", "1", "2plus"};
    for (int i = 0; i < 3; ++i)
      std::printf("diag_ball_rmse_observers_%s: %.4f m (%ld samples)\n", o[i], by_observers[i].rmse(),
                  by_observers[i].n);
    auto pct = [](long a, long b) { return b ? 100.0 * static_cast<double>(a) / static_cast<double>(b) : NAN; };
    std::printf("diag_ball_in_view_of_a_robot: %.2f %%\n", pct(visible, steps));
    std::printf("map_ball_availability_team_when_in_view: %.2f %%\n", pct(known_visible, visible));
    std::printf("diag_ball_known_incl_coasting: %.2f %%\n", pct(known_coasting, steps));
    std::printf("diag_ball_lost_nobody_sees: %.2f %% of steps\n", pct(lost_unseen, steps));
    std::printf("diag_ball_lost_in_view_no_confirmed_anchor: %.2f %% of steps\n", pct(lost_no_anchor, steps));
    std::printf("diag_ball_lost_in_view_anchor_off: %.2f %% of steps\n", pct(lost_far, steps));
  }
};

struct SwitchDiag {
  long at_reacquisition = 0;  // the opponent had no anchor within 0.5 m the step before
  long while_tracked = 0;     // it had one (a swap: crossing, or a duplicate taking over)
  long unmatched_steps = 0, matched_steps = 0;
  std::vector<long> per_opponent;  // switches of each opponent (index 0: their goalkeeper in team play)
  void count(std::size_t o) {
    if (per_opponent.size() <= o) per_opponent.resize(o + 1, 0);
    ++per_opponent[o];
  }
  // Episodes in which an opponent is in no robot's view (range, occlusion)
  // for longer than 1 s: indistinguishable opponents, so each is a chance
  // for a re-identification to pick the wrong one.
  std::vector<double> unseen_for;
  std::vector<long> episodes_by_opponent;
  long unseen_episodes = 0;
  void visibility(std::size_t o, bool in_view, double dt) {
    if (unseen_for.size() <= o) unseen_for.resize(o + 1, 0.0);
    if (episodes_by_opponent.size() <= o) episodes_by_opponent.resize(o + 1, 0);
    if (in_view) {
      unseen_episodes += unseen_for[o] > 1.0;
      episodes_by_opponent[o] += unseen_for[o] > 1.0;
      unseen_for[o] = 0.0;
    } else {
      unseen_for[o] += dt;
    }
  }
  void print(std::size_t opponents, double minutes) const {
    const double k = 1.0 / static_cast<double>(opponents) / (minutes / 10.0);
    std::printf("diag_id_switches_at_reacquisition_per_opp_10min: %.2f count\n", k * static_cast<double>(at_reacquisition));
    std::printf("diag_id_switches_while_tracked_per_opp_10min: %.2f count\n", k * static_cast<double>(while_tracked));
    std::printf("diag_opponent_unseen_by_all_over_1s_per_opp_10min: %.2f count\n", k * static_cast<double>(unseen_episodes));
    std::string each;
    for (std::size_t o = 0; o < opponents; ++o) each += " " + std::to_string(o < per_opponent.size() ? per_opponent[o] : 0);
    std::printf("diag_id_switches_by_opponent:%s count\n", each.c_str());
    each.clear();
    for (long c : episodes_by_opponent) each += " " + std::to_string(c);
    std::printf("diag_opponent_unseen_by_all_over_1s_by_opponent:%s count\n", each.c_str());
    std::printf("diag_opponent_tracked: %.2f %% of steps\n",
                100.0 * static_cast<double>(matched_steps) / static_cast<double>(matched_steps + unmatched_steps));
  }
};

}  // namespace mrt::map::bench
