#include "ros/conversions.h"

#include <cmath>

#include "mrt_map/kalman.h"

namespace mrt::map::node {

namespace {
void fill(mrt_msgs::Anchor& m, const Estimate& e) {
  m.x = e.x(0);
  m.y = e.x(1);
  m.vx = e.x(2);
  m.vy = e.x(3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m.covariance[static_cast<std::size_t>(4 * i + j)] = e.P(i, j);
}
}  // namespace

mrt_msgs::Anchor to_msg(const Anchor& a, const ConceptualModel& m, double reliability) {
  mrt_msgs::Anchor out;
  out.id = a.id;
  out.membership_class = m.at(a.class_index).name;
  out.matching_degree = a.degree;
  out.status = static_cast<std::uint8_t>(a.status);
  fill(out, a.fused);
  out.reliability = reliability;
  out.last_seen = ros::Time(std::max(0.0, a.last_seen));
  out.sources.assign(a.sources.begin(), a.sources.end());
  return out;
}

mrt_msgs::Anchor to_msg(const RemoteTrack& t, const ConceptualModel& m) {
  mrt_msgs::Anchor out;
  out.id = t.id;
  out.membership_class = m.at(t.class_index).name;
  out.matching_degree = t.degree;
  out.status = mrt_msgs::Anchor::CONFIRMED;
  fill(out, t.estimate);
  out.reliability = t.degree;
  out.last_seen = ros::Time(std::max(0.0, t.last_seen));
  out.sources.assign(t.sensors.begin(), t.sensors.end());
  return out;
}

bool from_msg(const mrt_msgs::Anchor& a, const ConceptualModel& m, const ros::Time& stamp, RemoteTrack& out) {
  out.class_index = m.find(a.membership_class);
  if (out.class_index < 0) return false;
  out.id = a.id;
  out.degree = a.matching_degree;
  out.estimate.x << a.x, a.y, a.vx, a.vy;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out.estimate.P(i, j) = a.covariance[static_cast<std::size_t>(4 * i + j)];
  out.estimate.stamp = stamp.toSec();
  out.last_seen = a.last_seen.toSec();
  out.sensors.clear();
  out.sensors.insert(a.sources.begin(), a.sources.end());
  // A covariance must be finite, symmetric and positive definite.
  const Mat4& P = out.estimate.P;
  if (!out.estimate.x.allFinite() || !P.allFinite() || !std::isfinite(out.degree)) return false;
  if ((P - P.transpose()).cwiseAbs().maxCoeff() > 1e-9 * (1.0 + P.cwiseAbs().maxCoeff())) return false;
  return Eigen::LLT<Mat4>(P).info() == Eigen::Success;
}

namespace {
// The message without anchors: robot, pose, SCARE's parameters.
mrt_msgs::WorldModel model_msg(const WorldModel& w, const std::string& frame, const ros::Time& stamp, bool local_only) {
  mrt_msgs::WorldModel out;
  out.header.stamp = stamp;
  out.header.frame_id = frame;
  out.robot = w.options().robot;
  out.local_only = local_only;
  const RobotPose& p = w.robot_pose();
  out.robot_x = p.x;
  out.robot_y = p.y;
  out.robot_theta = p.theta;
  out.robot_covariance = {p.cov(0, 0), p.cov(0, 1), p.cov(1, 0), p.cov(1, 1)};
  for (const auto& [name, d] : w.parameters()) {
    mrt_msgs::CrispData c;
    c.name = name;
    c.value = d.value;
    c.reliability = d.reliability;
    out.parameters.push_back(c);
  }
  return out;
}
}  // namespace

mrt_msgs::WorldModel to_msg(const WorldModel& w, const std::string& frame, const ros::Time& stamp) {
  mrt_msgs::WorldModel out = model_msg(w, frame, stamp, false);
  const double now = stamp.toSec();
  for (const Anchor& a : w.tracker().anchors()) out.anchors.push_back(to_msg(a, w.model(), w.tracker().reliability(a, now)));
  return out;
}

mrt_msgs::WorldModel to_msg(const WorldModel& w, const std::vector<RemoteTrack>& tracks, const std::string& frame,
                            const ros::Time& stamp) {
  mrt_msgs::WorldModel out = model_msg(w, frame, stamp, true);
  for (const RemoteTrack& t : tracks) out.anchors.push_back(to_msg(t, w.model()));
  return out;
}

mrt_msgs::CrispDataArray to_msg(const std::vector<CrispDatum>& data, const ros::Time& stamp) {
  mrt_msgs::CrispDataArray out;
  out.header.stamp = stamp;
  for (const CrispDatum& d : data) {
    mrt_msgs::CrispData c;
    c.name = d.name;
    c.value = d.value;
    c.reliability = d.reliability;
    out.data.push_back(c);
  }
  return out;
}

namespace {
std_msgs::ColorRGBA color(const std::string& cls) {
  std_msgs::ColorRGBA c;
  c.a = 0.8f;
  if (cls == "Ball") c.r = 1.0f, c.g = 0.5f;
  else if (cls == "Teammate") c.r = 1.0f, c.b = 1.0f;
  else if (cls == "Opponent") c.g = 1.0f, c.b = 1.0f;
  else c.r = c.g = c.b = 0.6f;
  return c;
}
}  // namespace

visualization_msgs::MarkerArray markers(const WorldModel& w, const std::string& frame, const ros::Time& stamp) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.header.frame_id = frame;
  clear.header.stamp = stamp;
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  for (const Anchor& a : w.tracker().anchors()) {
    if (a.status != AnchorStatus::kConfirmed && a.status != AnchorStatus::kCoasting) continue;
    const std::string cls = w.model().at(a.class_index).name;
    visualization_msgs::Marker m;
    m.header = clear.header;
    m.ns = "map_ellipses";
    m.id = static_cast<int>(a.id);
    m.type = visualization_msgs::Marker::CYLINDER;
    m.action = visualization_msgs::Marker::ADD;
    // 2-sigma ellipse from the eigen decomposition of the position block.
    const Ellipse el = principal_axes(a.fused.P.topLeftCorner<2, 2>());
    const double yaw = el.angle;
    m.pose.position.x = a.fused.x(0);
    m.pose.position.y = a.fused.x(1);
    m.pose.orientation.z = std::sin(yaw / 2);
    m.pose.orientation.w = std::cos(yaw / 2);
    m.scale.x = std::max(0.01, 4 * std::sqrt(el.major));
    m.scale.y = std::max(0.01, 4 * std::sqrt(el.minor));
    m.scale.z = 0.02;
    m.color = color(cls);
    if (a.status == AnchorStatus::kCoasting) m.color.a = 0.3f;
    out.markers.push_back(m);
    visualization_msgs::Marker t = m;
    t.ns = "map_ids";
    t.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    t.pose.orientation = geometry_msgs::Quaternion();
    t.pose.orientation.w = 1;
    t.pose.position.z = 0.4;
    t.scale.x = t.scale.y = t.scale.z = 0.25;
    t.color.r = t.color.g = t.color.b = t.color.a = 1.0f;
    t.text = cls + " " + std::to_string(a.id);
    out.markers.push_back(t);
    visualization_msgs::Marker v = t;
    v.ns = "map_velocities";
    v.type = visualization_msgs::Marker::ARROW;
    v.text.clear();
    v.pose = geometry_msgs::Pose();
    v.pose.orientation.w = 1;
    geometry_msgs::Point p0, p1;
    p0.x = a.fused.x(0);
    p0.y = a.fused.x(1);
    p1.x = p0.x + a.fused.x(2);
    p1.y = p0.y + a.fused.x(3);
    v.points = {p0, p1};
    v.scale.x = 0.04;
    v.scale.y = 0.08;
    v.scale.z = 0.0;
    v.color = m.color;
    out.markers.push_back(v);
  }
  return out;
}

}  // namespace mrt::map::node
