#include "conversions.h"

#include <algorithm>
#include <cmath>

#include "mrt_common/geodesy.h"
#include "mrt_common_ros/percept_conversions.h"

namespace mrt::sim::node {

RobotFrames make_frames(const std::string& frame_prefix, const std::string& robot,
                        const std::string& sensor_parent_suffix) {
  RobotFrames f;
  f.prefix = frame_prefix + robot + "/";
  f.base_truth = f.prefix + "base_link_truth";
  f.base = f.prefix + "base_link";
  f.sensor_parent = f.prefix + sensor_parent_suffix;
  return f;
}

nav_msgs::Odometry to_odometry(const RobotState& r, const std::string& world_frame,
                               const RobotFrames& f, const ros::Time& stamp) {
  return mrt::ros_common::to_odometry(r.pose, r.twist.vx, r.twist.vy, r.twist.omega, world_frame, f.base_truth,
                                      stamp);
}

mrt_msgs::MiceReading to_mice(const MiceSample& m, const RobotFrames& f, const ros::Time& stamp) {
  mrt_msgs::MiceReading r;
  r.header.stamp = stamp;
  r.header.frame_id = f.sensor_parent;
  // Each mouse stamped with its own last report (physical model: its own
  // clock; ideal: the sample time).
  auto before = [&](double age) { return stamp - ros::Duration(std::min(stamp.toSec(), std::max(0.0, age))); };
  r.left.header.stamp = before(m.time - m.left_stamp);
  r.right.header.stamp = before(m.time - m.right_stamp);
  r.left.header.frame_id = f.mouse(m.left_id);
  r.right.header.frame_id = f.mouse(m.right_id);
  r.left.mouse_id = m.left_id;
  r.right.mouse_id = m.right_id;
  r.left.dx = m.left_dx;
  r.left.dy = m.left_dy;
  r.right.dx = m.right_dx;
  r.right.dy = m.right_dy;
  return r;
}

mrt_msgs::WheelState to_wheel_state(const RobotState& r, bool watchdog, const ros::Time& stamp) {
  mrt_msgs::WheelState w;
  w.header.stamp = stamp;
  const std::size_t n = r.wheel_speed.size();
  w.setpoint = r.wheel_setpoint;
  w.speed = r.wheel_speed;
  w.ticks.assign(r.ticks.begin(), r.ticks.end());
  w.duty.resize(n);
  const double max_speed = r.config.base.max_wheel_speed;
  for (std::size_t i = 0; i < n; ++i)
    w.duty[i] = max_speed > 0.0 ? std::clamp(r.wheel_speed[i] / max_speed, -1.0, 1.0) : 0.0;
  std::uint32_t status = mrt_msgs::WheelState::STATUS_OK;
  if (r.saturated) status |= mrt_msgs::WheelState::STATUS_SATURATED;
  if (watchdog) status |= mrt_msgs::WheelState::STATUS_WATCHDOG;
  w.status.assign(n, status);
  return w;
}

sensor_msgs::JointState to_joint_state(const RobotState& r, const ros::Time& stamp) {
  sensor_msgs::JointState j;
  j.header.stamp = stamp;
  j.name = mrt::common::wheel_joint_names(r.config.base);
  j.velocity = r.wheel_speed;
  for (std::int64_t t : r.ticks) j.position.push_back(mrt::common::encoder_angle(t, r.config.sensors.ticks_per_rev));
  return j;
}

sensor_msgs::Range to_range(const SonarConfig& s, double range, const std::string& frame,
                            const ros::Time& stamp) {
  sensor_msgs::Range m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.radiation_type = sensor_msgs::Range::ULTRASOUND;
  m.field_of_view = static_cast<float>(s.fov);
  m.min_range = static_cast<float>(s.min_range);
  m.max_range = static_cast<float>(s.max_range);
  m.range = static_cast<float>(range);
  return m;
}

mrt_msgs::Percept to_percept(const std::vector<SeenObject>& seen, const SensorsConfig& cfg,
                             const std::string& robot, const std::string& frame,
                             const ros::Time& stamp) {
  mrt_msgs::Percept p;
  p.header.stamp = stamp;
  p.header.frame_id = frame;
  p.sensor = "omnivision";
  p.robot = robot;
  p.objects.reserve(seen.size());
  for (const SeenObject& s : seen) p.objects.push_back(mrt::ros_common::to_msg(to_percept_object(s, cfg)));
  return p;
}

sensor_msgs::NavSatFix to_navsat(const Point2D& p, const SensorsConfig& cfg, const std::string& frame,
                                 const ros::Time& stamp) {
  sensor_msgs::NavSatFix f;
  f.header.stamp = stamp;
  f.header.frame_id = frame;
  f.status.status = sensor_msgs::NavSatStatus::STATUS_GBAS_FIX;
  f.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  const mrt::common::GeoPoint g =
      mrt::common::LocalTangentPlane({cfg.datum_latitude, cfg.datum_longitude}).to_geodetic(p);
  f.latitude = g.latitude;
  f.longitude = g.longitude;
  f.altitude = 0.0;
  const double var = cfg.dgps_noise * cfg.dgps_noise;
  f.position_covariance = {var, 0.0, 0.0, 0.0, var, 0.0, 0.0, 0.0, var};
  f.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  return f;
}

}  // namespace mrt::sim::node
