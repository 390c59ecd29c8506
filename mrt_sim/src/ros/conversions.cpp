#include "conversions.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>

#include <geometry_msgs/Point.h>

#include "mrt_common/angle.h"

namespace mrt::sim::node {
namespace {

using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

geometry_msgs::Point point(double x, double y, double z = 0.0) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

geometry_msgs::Quaternion yaw_quaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.w = std::cos(yaw / 2.0);
  q.z = std::sin(yaw / 2.0);
  return q;
}

Marker make_marker(const std::string& frame, const ros::Time& stamp, const std::string& ns, int id,
                   int type) {
  Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color = color_of("");
  return m;
}

mrt_msgs::Attribute numeric(const std::string& name, double value, double variability) {
  mrt_msgs::Attribute a;
  a.name = name;
  a.value = value;
  a.variability = variability;
  a.reliability = 1.0;
  return a;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// Colour of an object in a percept: its own colour, else one per class.
std_msgs::ColorRGBA object_color(const SeenObject& o, float alpha) {
  if (!o.color.empty()) return color_of(o.color, alpha);
  static const std::map<std::string, std::string> by_class = {
      {"Ball", "orange"}, {"Person", "pink"}, {"Robot", "black"}, {"Obstacle", "black"},
      {"Line", "white"},  {"Goal", "gray"},   {"GoalPost", "white"}, {"Landmark", "gray"}};
  const auto it = by_class.find(o.membership_class);
  return color_of(it == by_class.end() ? "" : it->second, alpha);
}

}  // namespace

RobotFrames make_frames(const std::string& frame_prefix, const std::string& robot,
                        const std::string& sensor_parent_suffix) {
  RobotFrames f;
  f.prefix = frame_prefix + robot + "/";
  f.base_truth = f.prefix + "base_link_truth";
  f.base = f.prefix + "base_link";
  f.sensor_parent = f.prefix + sensor_parent_suffix;
  return f;
}

geometry_msgs::Pose to_pose(const Pose2D& p, double z) {
  geometry_msgs::Pose m;
  m.position = point(p.x, p.y, z);
  m.orientation = yaw_quaternion(p.theta);
  return m;
}

geometry_msgs::TransformStamped to_transform(const Pose2D& p, const std::string& parent,
                                             const std::string& child, const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = p.x;
  t.transform.translation.y = p.y;
  t.transform.rotation = yaw_quaternion(p.theta);
  return t;
}

nav_msgs::Odometry to_odometry(const RobotState& r, const std::string& world_frame,
                               const RobotFrames& f, const ros::Time& stamp) {
  nav_msgs::Odometry o;
  o.header.stamp = stamp;
  o.header.frame_id = world_frame;
  o.child_frame_id = f.base_truth;
  o.pose.pose = to_pose(r.pose);
  o.twist.twist.linear.x = r.twist.vx;
  o.twist.twist.linear.y = r.twist.vy;
  o.twist.twist.angular.z = r.twist.omega;
  return o;
}

mrt_msgs::MiceReading to_mice(const MiceSample& m, const RobotFrames& f, const ros::Time& stamp) {
  mrt_msgs::MiceReading r;
  r.header.stamp = stamp;
  r.header.frame_id = f.sensor_parent;
  r.left.header.stamp = r.right.header.stamp = stamp;
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
  for (const SeenObject& s : seen) {
    mrt_msgs::PerceptObject o;
    o.name = s.name;
    o.membership_class = s.membership_class;
    const double sd = cfg.vision_distance_noise * s.distance;
    const double sb = cfg.vision_bearing_noise;
    o.attributes.push_back(numeric("distance", s.distance, sd));
    o.attributes.push_back(numeric("bearing", s.bearing, sb));
    o.attributes.push_back(numeric("x", s.distance * std::cos(s.bearing), std::hypot(sd, s.distance * sb)));
    o.attributes.push_back(numeric("y", s.distance * std::sin(s.bearing), std::hypot(sd, s.distance * sb)));
    if (!s.color.empty()) {
      mrt_msgs::Attribute c;
      c.name = "color";
      c.symbol = s.color;
      c.reliability = 1.0;
      o.attributes.push_back(c);
    }
    p.objects.push_back(std::move(o));
  }
  return p;
}

void world_to_geodetic(double lat0_deg, double lon0_deg, const Point2D& p, double& lat_deg,
                       double& lon_deg) {
  const double lat0 = mrt::common::deg_to_rad(lat0_deg);
  lat_deg = lat0_deg + mrt::common::rad_to_deg(p.y / kEarthRadius);
  lon_deg = lon0_deg + mrt::common::rad_to_deg(p.x / (kEarthRadius * std::cos(lat0)));
}

sensor_msgs::NavSatFix to_navsat(const Point2D& p, const SensorsConfig& cfg, const std::string& frame,
                                 const ros::Time& stamp) {
  sensor_msgs::NavSatFix f;
  f.header.stamp = stamp;
  f.header.frame_id = frame;
  f.status.status = sensor_msgs::NavSatStatus::STATUS_GBAS_FIX;
  f.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  world_to_geodetic(cfg.datum_latitude, cfg.datum_longitude, p, f.latitude, f.longitude);
  f.altitude = 0.0;
  const double var = cfg.dgps_noise * cfg.dgps_noise;
  f.position_covariance = {var, 0.0, 0.0, 0.0, var, 0.0, 0.0, 0.0, var};
  f.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  return f;
}

std_msgs::ColorRGBA color_of(const std::string& name, float alpha) {
  static const std::map<std::string, std::array<float, 3>> table = {
      {"yellow", {1.0f, 0.9f, 0.0f}},   {"blue", {0.1f, 0.3f, 1.0f}},
      {"sky_blue", {0.4f, 0.75f, 1.0f}}, {"skyblue", {0.4f, 0.75f, 1.0f}},
      {"cyan", {0.0f, 0.9f, 0.9f}},     {"magenta", {0.9f, 0.0f, 0.9f}},
      {"red", {0.9f, 0.1f, 0.1f}},      {"green", {0.1f, 0.8f, 0.2f}},
      {"orange", {1.0f, 0.5f, 0.0f}},   {"white", {1.0f, 1.0f, 1.0f}},
      {"black", {0.1f, 0.1f, 0.1f}},    {"gray", {0.5f, 0.5f, 0.5f}},
      {"grey", {0.5f, 0.5f, 0.5f}},     {"pink", {1.0f, 0.5f, 0.7f}},
      {"purple", {0.5f, 0.1f, 0.7f}},   {"brown", {0.55f, 0.35f, 0.15f}}};
  std_msgs::ColorRGBA c;
  c.r = c.g = c.b = 0.5f;
  c.a = alpha;
  const std::string n = lower(name);
  if (n.size() == 7 && n[0] == '#') {
    char* end = nullptr;
    const unsigned long v = std::strtoul(n.c_str() + 1, &end, 16);
    if (end && *end == '\0') {
      c.r = static_cast<float>((v >> 16) & 0xff) / 255.0f;
      c.g = static_cast<float>((v >> 8) & 0xff) / 255.0f;
      c.b = static_cast<float>(v & 0xff) / 255.0f;
    }
    return c;
  }
  const auto it = table.find(n);
  if (it != table.end()) {
    c.r = it->second[0];
    c.g = it->second[1];
    c.b = it->second[2];
  }
  return c;
}

MarkerArray world_markers(const World& w, const std::string& frame) {
  MarkerArray out;
  const ros::Time stamp;  // zero: always drawn with the latest transform

  Marker floor = make_marker(frame, stamp, "floor", 0, Marker::CUBE);
  floor.pose.position = point((w.min_x + w.max_x) / 2.0, (w.min_y + w.max_y) / 2.0, -0.02);
  floor.scale.x = w.max_x - w.min_x;
  floor.scale.y = w.max_y - w.min_y;
  floor.scale.z = 0.01;
  if (w.field_lines.empty()) {
    floor.color.r = 0.82f;
    floor.color.g = 0.80f;
    floor.color.b = 0.75f;
  } else {
    floor.color.r = 0.10f;
    floor.color.g = 0.45f;
    floor.color.b = 0.15f;
  }
  floor.color.a = 1.0f;
  out.markers.push_back(floor);

  if (!w.field_lines.empty()) {
    Marker lines = make_marker(frame, stamp, "field_lines", 0, Marker::LINE_LIST);
    lines.scale.x = 0.08;
    lines.color = color_of("white", 0.9f);
    for (const Segment& s : w.field_lines) {
      lines.points.push_back(point(s.a.x, s.a.y, 0.0));
      lines.points.push_back(point(s.b.x, s.b.y, 0.0));
    }
    out.markers.push_back(lines);
  }

  if (!w.walls.empty()) {
    Marker walls = make_marker(frame, stamp, "walls", 0, Marker::LINE_LIST);
    walls.scale.x = 0.1;
    walls.color.r = walls.color.g = walls.color.b = 0.25f;
    walls.color.a = 1.0f;
    for (const Segment& s : w.walls) {
      walls.points.push_back(point(s.a.x, s.a.y, 0.05));
      walls.points.push_back(point(s.b.x, s.b.y, 0.05));
    }
    out.markers.push_back(walls);
  }

  int id = 0;
  for (const Post& p : w.posts) {
    Marker m = make_marker(frame, stamp, "posts", id, Marker::CYLINDER);
    m.pose.position = point(p.center.x, p.center.y, 0.25);
    m.scale.x = m.scale.y = 2.0 * p.radius;
    m.scale.z = 0.5;
    m.color = p.color.empty() ? color_of("black") : color_of(p.color);
    out.markers.push_back(m);
    Marker t = make_marker(frame, stamp, "post_names", id++, Marker::TEXT_VIEW_FACING);
    t.pose.position = point(p.center.x, p.center.y + p.radius + 0.25, 0.6);
    t.scale.z = 0.35;
    t.color = color_of("white", 0.8f);
    t.text = p.name;
    out.markers.push_back(t);
  }

  id = 0;
  for (const Goal& g : w.goals) {
    const double c = std::cos(g.pose.theta), s = std::sin(g.pose.theta);
    Marker fill = make_marker(frame, stamp, "goal_areas", id, Marker::CUBE);
    fill.pose.position = point(g.pose.x + c * g.depth / 2.0, g.pose.y + s * g.depth / 2.0, 0.0);
    fill.pose.orientation = yaw_quaternion(g.pose.theta);
    fill.scale.x = g.depth;
    fill.scale.y = g.width;
    fill.scale.z = 0.02;
    fill.color = color_of(g.color, 0.5f);
    out.markers.push_back(fill);
    Marker frame_m = make_marker(frame, stamp, "goals", id++, Marker::LINE_LIST);
    frame_m.scale.x = 0.12;
    frame_m.color = color_of(g.color);
    for (const Segment& side : goal_walls(g)) {
      frame_m.points.push_back(point(side.a.x, side.a.y, 0.1));
      frame_m.points.push_back(point(side.b.x, side.b.y, 0.1));
    }
    out.markers.push_back(frame_m);
  }
  return out;
}

MarkerArray dynamic_markers(const World& w, const std::vector<RobotState>& robots,
                            const std::string& frame, const ros::Time& stamp) {
  MarkerArray out;
  if (w.ball.enabled) {
    Marker b = make_marker(frame, stamp, "ball", 0, Marker::SPHERE);
    b.pose.position = point(w.ball.position.x, w.ball.position.y, w.ball.radius);
    b.scale.x = b.scale.y = b.scale.z = 2.0 * w.ball.radius;
    b.color = color_of(w.ball.color.empty() ? "orange" : w.ball.color);
    out.markers.push_back(b);
  }
  int id = 0;
  for (const Mover& m : w.movers) {
    Marker c = make_marker(frame, stamp, "movers", id, Marker::CYLINDER);
    c.pose.position = point(m.position.x, m.position.y, 0.4);
    c.scale.x = c.scale.y = 2.0 * m.radius;
    c.scale.z = 0.8;
    c.color = m.color.empty() ? color_of(m.membership_class == "Person" ? "pink" : "black")
                              : color_of(m.color);
    out.markers.push_back(c);
    Marker t = make_marker(frame, stamp, "mover_names", id++, Marker::TEXT_VIEW_FACING);
    t.pose.position = point(m.position.x, m.position.y + m.radius + 0.25, 1.0);
    t.scale.z = 0.35;
    t.color = color_of("white", 0.8f);
    t.text = m.name;
    out.markers.push_back(t);
  }
  id = 0;
  for (const RobotState& r : robots) {
    const double rad = r.config.base.body_radius;
    Marker body = make_marker(frame, stamp, "robots", id, Marker::CYLINDER);
    body.pose = to_pose(r.pose, 0.15);
    body.scale.x = body.scale.y = 2.0 * rad;
    body.scale.z = 0.3;
    body.color = color_of(r.config.color, 0.95f);
    out.markers.push_back(body);
    Marker head = make_marker(frame, stamp, "robot_headings", id, Marker::ARROW);
    head.pose = to_pose(r.pose, 0.32);
    head.scale.x = 1.6 * rad;  // arrow length
    head.scale.y = 0.08;
    head.scale.z = 0.08;
    head.color = color_of(r.bumped ? "red" : "white");
    out.markers.push_back(head);
    Marker name = make_marker(frame, stamp, "robot_names", id++, Marker::TEXT_VIEW_FACING);
    name.pose.position = point(r.pose.x, r.pose.y + rad + 0.3, 0.8);
    name.scale.z = 0.4;
    name.color = color_of("white");
    name.text = r.config.name;
    out.markers.push_back(name);
  }
  return out;
}

MarkerArray percept_markers(const std::vector<SeenObject>& seen, const Pose2D& robot_pose,
                            const std::string& frame, const ros::Time& stamp) {
  MarkerArray out;
  Marker clear;
  clear.header.frame_id = frame;
  clear.header.stamp = stamp;
  clear.action = Marker::DELETEALL;
  out.markers.push_back(clear);

  Marker rays = make_marker(frame, stamp, "rays", 0, Marker::LINE_LIST);
  rays.scale.x = 0.05;
  Marker line_points = make_marker(frame, stamp, "line_points", 0, Marker::POINTS);
  line_points.scale.x = line_points.scale.y = 0.12;
  line_points.color = color_of("magenta");
  int id = 0;
  for (const SeenObject& o : seen) {
    const Point2D p = robot_pose.transform(
        {o.distance * std::cos(o.bearing), o.distance * std::sin(o.bearing)});
    if (o.membership_class == "Line") {
      line_points.points.push_back(point(p.x, p.y, 0.05));
      continue;
    }
    Marker s = make_marker(frame, stamp, "objects", id, Marker::SPHERE);
    s.pose.position = point(p.x, p.y, 0.3);
    s.scale.x = s.scale.y = s.scale.z = 0.3;
    s.color = object_color(o, 0.9f);
    out.markers.push_back(s);
    Marker t = make_marker(frame, stamp, "labels", id++, Marker::TEXT_VIEW_FACING);
    t.pose.position = point(p.x, p.y - 0.35, 0.7);
    t.scale.z = 0.35;
    t.color = color_of("yellow");
    t.text = o.membership_class;
    out.markers.push_back(t);
    rays.points.push_back(point(robot_pose.x, robot_pose.y, 0.3));
    rays.points.push_back(point(p.x, p.y, 0.3));
    std_msgs::ColorRGBA c = object_color(o, 0.9f);
    rays.colors.push_back(c);
    rays.colors.push_back(c);
  }
  if (!rays.points.empty()) out.markers.push_back(rays);
  if (!line_points.points.empty()) out.markers.push_back(line_points);
  return out;
}

}  // namespace mrt::sim::node
