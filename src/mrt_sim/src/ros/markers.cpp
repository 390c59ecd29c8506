#include "markers.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>

#include <geometry_msgs/Point.h>

#include "mrt_common_ros/conversions.h"

namespace mrt::sim::node {
namespace {

using mrt::ros_common::to_pose;
using mrt::ros_common::yaw_to_quaternion;
using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

geometry_msgs::Point point(double x, double y, double z = 0.0) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
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

// A name above an object, in white.
Marker label(const std::string& frame, const ros::Time& stamp, const std::string& ns, int id, double x, double y,
             double z, double size, const std::string& text, float alpha = 0.8f) {
  Marker t = make_marker(frame, stamp, ns, id, Marker::TEXT_VIEW_FACING);
  t.pose.position = point(x, y, z);
  t.scale.z = size;
  t.color = color_of("white", alpha);
  t.text = text;
  return t;
}

// A LINE_LIST of segments at height z.
Marker segments(const std::string& frame, const std::string& ns, const std::vector<Segment>& list, double z,
                double width) {
  Marker m = make_marker(frame, ros::Time(), ns, 0, Marker::LINE_LIST);
  m.scale.x = width;
  for (const Segment& s : list) {
    m.points.push_back(point(s.a.x, s.a.y, z));
    m.points.push_back(point(s.b.x, s.b.y, z));
  }
  return m;
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

// The floor: green when the world has field lines, light grey otherwise.
Marker floor_marker(const World& w, const std::string& frame) {
  Marker floor = make_marker(frame, ros::Time(), "floor", 0, Marker::CUBE);
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
  return floor;
}

void add_posts(const World& w, const std::string& frame, MarkerArray& out) {
  int id = 0;
  for (const Post& p : w.posts) {
    Marker m = make_marker(frame, ros::Time(), "posts", id, Marker::CYLINDER);
    m.pose.position = point(p.center.x, p.center.y, 0.25);
    m.scale.x = m.scale.y = 2.0 * p.radius;
    m.scale.z = 0.5;
    m.color = p.color.empty() ? color_of("black") : color_of(p.color);
    out.markers.push_back(m);
    out.markers.push_back(
        label(frame, ros::Time(), "post_names", id++, p.center.x, p.center.y + p.radius + 0.25, 0.6, 0.35, p.name));
  }
}

void add_goals(const World& w, const std::string& frame, MarkerArray& out) {
  int id = 0;
  for (const Goal& g : w.goals) {
    const double c = std::cos(g.pose.theta), s = std::sin(g.pose.theta);
    Marker fill = make_marker(frame, ros::Time(), "goal_areas", id, Marker::CUBE);
    fill.pose.position = point(g.pose.x + c * g.depth / 2.0, g.pose.y + s * g.depth / 2.0, 0.0);
    fill.pose.orientation = yaw_to_quaternion(g.pose.theta);
    fill.scale.x = g.depth;
    fill.scale.y = g.width;
    fill.scale.z = 0.02;
    fill.color = color_of(g.color, 0.5f);
    out.markers.push_back(fill);
    const auto walls = goal_walls(g);
    const std::vector<Segment> sides(walls.begin(), walls.end());
    Marker frame_m = segments(frame, "goals", sides, 0.1, 0.12);
    frame_m.id = id++;
    frame_m.color = color_of(g.color);
    out.markers.push_back(frame_m);
  }
}

void add_ball(const World& w, const std::string& frame, const ros::Time& stamp, MarkerArray& out) {
  if (!w.ball.enabled) return;
  Marker b = make_marker(frame, stamp, "ball", 0, Marker::SPHERE);
  b.pose.position = point(w.ball.position.x, w.ball.position.y, w.ball.radius);
  b.scale.x = b.scale.y = b.scale.z = 2.0 * w.ball.radius;
  b.color = color_of(w.ball.color.empty() ? "orange" : w.ball.color);
  out.markers.push_back(b);
}

void add_movers(const World& w, const std::string& frame, const ros::Time& stamp, MarkerArray& out) {
  int id = 0;
  for (const Mover& m : w.movers) {
    Marker c = make_marker(frame, stamp, "movers", id, Marker::CYLINDER);
    c.pose.position = point(m.position.x, m.position.y, 0.4);
    c.scale.x = c.scale.y = 2.0 * m.radius;
    c.scale.z = 0.8;
    c.color = m.color.empty() ? color_of(m.membership_class == "Person" ? "pink" : "black")
                              : color_of(m.color);
    out.markers.push_back(c);
    out.markers.push_back(
        label(frame, stamp, "mover_names", id++, m.position.x, m.position.y + m.radius + 0.25, 1.0, 0.35, m.name));
  }
}

// Each robot: footprint, heading arrow (red while bumped) and name.
void add_robots(const std::vector<RobotState>& robots, const std::string& frame, const ros::Time& stamp,
                MarkerArray& out) {
  int id = 0;
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
    out.markers.push_back(
        label(frame, stamp, "robot_names", id++, r.pose.x, r.pose.y + rad + 0.3, 0.8, 0.4, r.config.name, 1.0f));
  }
}

}  // namespace

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
  MarkerArray out;  // stamps zero: always drawn with the latest transform
  out.markers.push_back(floor_marker(w, frame));
  if (!w.field_lines.empty()) {
    Marker lines = segments(frame, "field_lines", w.field_lines, 0.0, 0.08);
    lines.color = color_of("white", 0.9f);
    out.markers.push_back(lines);
  }
  if (!w.walls.empty()) {
    Marker walls = segments(frame, "walls", w.walls, 0.05, 0.1);
    walls.color.r = walls.color.g = walls.color.b = 0.25f;
    walls.color.a = 1.0f;
    out.markers.push_back(walls);
  }
  add_posts(w, frame, out);
  add_goals(w, frame, out);
  return out;
}

MarkerArray dynamic_markers(const World& w, const std::vector<RobotState>& robots,
                            const std::string& frame, const ros::Time& stamp) {
  MarkerArray out;
  add_ball(w, frame, stamp, out);
  add_movers(w, frame, stamp, out);
  add_robots(robots, frame, stamp, out);
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
