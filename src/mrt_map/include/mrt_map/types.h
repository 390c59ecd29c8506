// Core value types of MAP (manual chapter 8): percepts in, perceived
// objects, estimates and anchors. ROS-free; world frame, metres, seconds.
#pragma once

#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "mrt_common/percept.h"

namespace mrt::map {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
using Vec4 = Eigen::Vector4d;  // x, y, vx, vy
using Mat4 = Eigen::Matrix4d;

/// A percept object (mrt_common/percept.h: the stack's one percept type),
/// relative to the observing robot: a position as `distance`/`bearing` or
/// `x`/`y` in the robot frame, plus any other attributes of the ontology.
using PerceptObject = mrt::common::PerceptObject;
using PerceptAttribute = mrt::common::Attribute;

/// A robot's planar pose in the world frame with the covariance of x, y and
/// the standard deviation of theta.
struct RobotPose {
  double x = 0.0, y = 0.0, theta = 0.0;
  Mat2 cov = Mat2::Zero();
  double theta_sigma = 0.0;
};

/// A perceived object: a classified percept object placed in the world
/// frame (position z, covariance R).
struct Observation {
  int class_index = -1;
  double degree = 1.0;  // matching degree of the class, in [0, 1]
  Vec2 z = Vec2::Zero();
  Mat2 R = Mat2::Identity();
  double stamp = 0.0;
  std::string robot;
  std::set<std::string> sensors;  // "robot/sensor"
};

/// A state estimate at time `stamp`.
struct Estimate {
  Vec4 x = Vec4::Zero();
  Mat4 P = Mat4::Identity();
  double stamp = 0.0;
};

/// The two-model (quiet, kicked) IMM state of an own filter (imm.h).
struct ImmState {
  std::array<Estimate, 2> model;       // 0 quiet, 1 kicked
  std::array<double, 2> mu{0.5, 0.5};  // mode probabilities
};

enum class AnchorStatus : std::uint8_t { kTentative = 0, kConfirmed = 1, kCoasting = 2, kDropped = 3 };
const char* to_string(AnchorStatus s);

/// A teammate's anchor as received (its own sensors only, see README):
/// latency-compensated by the Merger before fusion.
struct RemoteTrack {
  std::string robot;
  std::uint32_t id = 0;
  int class_index = -1;
  double degree = 1.0;
  Estimate estimate;
  double last_seen = 0.0;
  std::set<std::string> sensors;
};

/// One anchor: a symbol (id) bound to one real object.
struct Anchor {
  std::uint32_t id = 0;
  int class_index = -1;
  double degree = 1.0;
  AnchorStatus status = AnchorStatus::kTentative;
  Estimate fused;            // the team estimate (output)
  bool has_local = false;    // own sensors' Kalman filter
  Estimate local;
  int local_hits = 0;
  double local_last_seen = 0.0;
  bool has_imm = false;      // the own filter is an IMM (class `imm:`); `local` is then
  ImmState imm;              // its combined estimate
  int hits = 0;              // cycles with support (own or teammates')
  double first_seen = 0.0;
  double last_seen = 0.0;    // own or teammates'
  std::map<std::string, RemoteTrack> remote;        // by teammate, this cycle's
  std::map<std::string, std::uint32_t> remote_ids;  // sticky association
  std::set<std::string> sources;                    // robots/sensors supporting it
};

}  // namespace mrt::map
