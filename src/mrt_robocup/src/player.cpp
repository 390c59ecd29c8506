#include "mrt_robocup/player.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace mrt::robocup {

common::BrianMappingParams mapping_for(const std::string& kinematics) {
  if (kinematics == "differential") return common::BrianMappingParams::for_base(common::BaseType::kDifferential);
  if (kinematics == "omni") return common::BrianMappingParams::for_base(common::BaseType::kOmni);
  throw std::invalid_argument("kinematics: expected 'differential' or 'omni', got '" + kinematics + "'");
}

Player::Player(PlayerOptions o)
    : o_(std::move(o)), mapping_(mapping_for(o_.kinematics)), assessor_(o_.situation) {
  if (!(o_.max_speed > 0.0) || !(o_.max_omega > 0.0) || !(o_.carry_max_speed > 0.0) || !(o_.carry_max_omega > 0.0))
    throw std::invalid_argument("speed limits must be positive");
  brian_ = brian::Brian::from_path(o_.rule_base);
}

Player::~Player() = default;

bool Player::playing(Referee r, bool play_without_referee) {
  return r == Referee::kStart || (r == Referee::kNone && play_without_referee);
}

PlayerOutput Player::cycle(const PlayerInput& in) {
  PlayerOutput out;
  SituationInput si;
  si.time = in.time;
  si.pose = in.pose;
  si.anchors = in.anchors;
  si.coordination = in.coordination;
  if (!job_of(in.coordination).empty()) {
    held_ = in.coordination;
    held_since_ = in.time;
  } else if (in.time - held_since_ <= o_.job_hold) {
    si.coordination = held_;  // waiting for a slot: keep the last job a little
  }
  si.possession_known = in.possession_known;
  si.possession = in.possession;
  out.situation = assessor_.assess(si);
  out.job = out.situation.job;
  out.crisp = assessor_.crisp(out.situation, in.pose, si.coordination);
  out.halted = !in.pose_valid || !playing(in.referee, o_.play_without_referee);
  if (out.halted) return out;  // zero twist, no kick, ball handler off: before the rules

  out.commands = brian_->run(out.crisp);
  const brian::BehaviorEngine& engine = brian_->engine();
  for (int b = 0; b < engine.size(); ++b) {
    if (!brian_->active()[static_cast<std::size_t>(b)]) continue;
    char w[32];
    std::snprintf(w, sizeof w, " %.2f ", brian_->weights()[static_cast<std::size_t>(b)]);
    out.behaviors += engine.behavior(b).name() + w;
  }
  std::vector<std::pair<std::string, double>> named;
  named.reserve(out.commands.size());
  for (const brian::Command& c : out.commands) {
    named.emplace_back(c.name, c.value);
    if (c.name == o_.kick_name && std::isfinite(c.value) && c.value > 0.0 && in.time - last_kick_ >= o_.kick_cooldown) {
      if (std::abs(in.omega) > o_.kick_max_omega) {  // NaN: unknown, not held
        out.kick_held = true;
        continue;
      }
      out.kick = true;
      out.kick_strength = std::clamp(c.value, 0.0, 1.0);
    }
  }
  if (const auto t = mapping_.to_twist(named)) out.twist = *t;
  // The boundary's safety limits (the ball handler loses the ball beyond them).
  const bool owned = out.situation.owned;
  const double vmax = owned ? std::min(o_.max_speed, o_.carry_max_speed) : o_.max_speed;
  const double wmax = owned ? std::min(o_.max_omega, o_.carry_max_omega) : o_.max_omega;
  const double v = std::hypot(out.twist.vx, out.twist.vy);
  if (v > vmax) {
    out.twist.vx *= vmax / v;
    out.twist.vy *= vmax / v;
  }
  out.twist.omega = std::clamp(out.twist.omega, -wmax, wmax);
  if (out.kick_held) out.twist.omega = 0.0;  // settle the aim: the rules kick next cycle if it still holds
  if (out.kick) last_kick_ = in.time;
  const Situation& s = out.situation;
  out.dribble = !out.kick && s.ball_seen &&
                std::hypot(s.ball.x - in.pose.x, s.ball.y - in.pose.y) <=
                    o_.situation.body_radius + o_.situation.ball_radius + o_.dribble_distance;
  return out;
}

}  // namespace mrt::robocup
