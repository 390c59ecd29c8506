// The benchmark's own little world (ROS-free, not mrt_sim): an MSL field
// with 5 teammates, 5 opponents (solid: they push each other apart, never
// drive through each other) and a ball moving, and a camera model per
// robot (range limit, occlusion by robots, distance-dependent noise,
// missed detections, clutter) producing mrt_map percept objects.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "mrt_map/types.h"

namespace mrt::map::bench {

struct Body {
  Vec2 p = Vec2::Zero();
  Vec2 v = Vec2::Zero();
  Vec2 goal = Vec2::Zero();
  double speed = 1.0;
  double radius = 0.25;
};

struct CameraModel {
  double range = 6.0;           // m
  double sigma_d0 = 0.005;      // m
  double sigma_d_rel = 0.01;    // fraction of the distance
  double sigma_d_quad = 0.0;    // m per m^2: sigma_d = d0 + rel d + quad d^2
  double sigma_bearing = 0.005; // rad
  double p_detect = 0.9;        // at the robot
  double p_detect_far = 0.9;    // at `range` (linear in between)
  double clutter_rate = 0.03;   // false balls per frame
  double pose_sigma = 0.02;     // m, self-localisation error
  double theta_sigma = 0.005;   // rad
};

class TeamSim {
 public:
  /// `team_play` false: every robot on random waypoints (the first
  /// scenario). True: both teams play (see team_sim.cpp, set_goals).
  explicit TeamSim(unsigned seed, bool team_play = false, int teammates = 5, int opponents = 5);
  void step(double dt);
  const std::vector<Body>& mates() const { return mates_; }
  const std::vector<Body>& opponents() const { return opps_; }
  const Body& ball() const { return ball_; }
  /// What robot i's camera sees now, and the pose it believes it has.
  std::vector<PerceptObject> see(int i, const CameraModel& cam, RobotPose& believed);
  /// True when the segment a-b passes through a robot other than `skip_mate`/`skip_opp`.
  bool occluded(const Vec2& a, const Vec2& b, int skip_mate, int skip_opp) const;
  /// True when robot i's camera could see the ball now (range, occlusion;
  /// detection misses aside): the ground truth of "the ball is visible".
  bool ball_in_view(int i, const CameraModel& cam) const;
  /// True when robot i's camera could see opponent k now (range, occlusion).
  bool opponent_in_view(int i, int k, const CameraModel& cam) const;
  /// Time since the ball was last kicked (s).
  double since_kick() const { return since_kick_; }

 private:
  void move(Body& b, double dt);
  void separate();
  void set_goals(std::vector<Body>& team, std::vector<Vec2>& offsets, int& chaser, double side);
  Vec2 random_point();
  bool team_play_ = false;  // (declared before rng_: initialised first)
  std::vector<Vec2> offset_mates_, offset_opps_;  // each player's wandering around its slot
  double offset_timer_ = 0.0;
  int chaser_mates_ = -1, chaser_opps_ = -1;
  std::mt19937 rng_;
  std::vector<Body> mates_, opps_;
  Body ball_;
  double kick_timer_ = 0.0;
  double since_kick_ = 0.0;
};

}  // namespace mrt::map::bench
