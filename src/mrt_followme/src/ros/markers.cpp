#include "markers.h"

#include <cstdio>

#include "mrt_common_ros/conversions.h"
#include "mrt_sim/world.h"

namespace mrt::followme::node {

namespace {

using visualization_msgs::Marker;

std_msgs::ColorRGBA rgba(float r, float g, float b, float a = 1.0f) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

std_msgs::ColorRGBA named(const std::string& n) {
  if (n == "red") return rgba(0.9f, 0.1f, 0.1f);
  if (n == "green") return rgba(0.1f, 0.7f, 0.2f);
  if (n == "blue") return rgba(0.0f, 0.3f, 1.0f);
  if (n == "yellow") return rgba(1.0f, 0.86f, 0.0f);
  if (n == "magenta") return rgba(0.94f, 0.0f, 0.8f);
  if (n == "cyan") return rgba(0.0f, 0.86f, 1.0f);
  if (n == "orange") return rgba(1.0f, 0.47f, 0.0f);
  if (n == "purple") return rgba(0.5f, 0.16f, 0.7f);
  if (n == "bronze") return rgba(0.8f, 0.5f, 0.2f);
  if (n == "white") return rgba(0.95f, 0.95f, 0.95f);
  return rgba(0.5f, 0.5f, 0.5f);
}

Marker base(const std::string& frame, const std::string& ns, int id, int type) {
  Marker m;
  m.header.frame_id = frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color = rgba(1, 1, 1);
  return m;
}

Marker cylinder(const std::string& frame, const std::string& ns, int id, double x, double y, double r, double h,
                const std_msgs::ColorRGBA& c) {
  Marker m = base(frame, ns, id, Marker::CYLINDER);
  m.pose.position.x = x;
  m.pose.position.y = y;
  m.pose.position.z = h / 2;
  m.scale.x = m.scale.y = 2 * r;
  m.scale.z = h;
  m.color = c;
  return m;
}

Marker text(const std::string& frame, const std::string& ns, int id, double x, double y, double z,
            const std::string& t, double size = 0.35) {
  Marker m = base(frame, ns, id, Marker::TEXT_VIEW_FACING);
  m.pose.position.x = x;
  m.pose.position.y = y;
  m.pose.position.z = z;
  m.scale.z = size;
  m.text = t;
  return m;
}

geometry_msgs::Point pt(double x, double y, double z = 0.05) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

}  // namespace

visualization_msgs::MarkerArray museum_markers(const FollowMeSession& s, const std::string& frame) {
  visualization_msgs::MarkerArray a;
  Marker walls = base(frame, "walls", 0, Marker::LINE_LIST);
  walls.scale.x = 0.1;
  walls.color = rgba(0.3f, 0.3f, 0.3f);
  for (const auto& w : s.world().walls) {
    walls.points.push_back(pt(w.a.x, w.a.y));
    walls.points.push_back(pt(w.b.x, w.b.y));
  }
  a.markers.push_back(walls);
  int id = 0;
  for (const auto& p : s.world().posts) {
    const bool exhibit = p.membership_class == "Exhibit";
    a.markers.push_back(cylinder(frame, exhibit ? "exhibits" : "landmarks", id, p.center.x, p.center.y, p.radius,
                                 exhibit ? 1.0 : 1.5, named(p.color)));
    if (exhibit) a.markers.push_back(text(frame, "exhibit_names", id, p.center.x, p.center.y, 1.4, p.name));
    ++id;
  }
  return a;
}

visualization_msgs::MarkerArray dynamic_markers(const FollowMeSession& s, const std::string& frame) {
  visualization_msgs::MarkerArray a;
  const FollowMeView v = s.view();
  const FollowMeTick k = s.tick();
  int id = 0;
  for (const auto& p : v.people) {
    a.markers.push_back(cylinder(frame, "people", id, p.position.x, p.position.y, p.radius, 1.7, named(p.color)));
    a.markers.push_back(text(frame, "people_names", id++, p.position.x, p.position.y, 2.0, p.name, 0.3));
  }
  a.markers.push_back(cylinder(frame, "robot", 0, k.truth.x, k.truth.y, 0.25, 0.5, rgba(0.1f, 0.1f, 0.1f)));
  Marker est = cylinder(frame, "robot_estimate", 0, k.estimate.x, k.estimate.y, 0.25, 0.02, rgba(0.2f, 0.6f, 1.0f, 0.7f));
  a.markers.push_back(est);
  Marker track = base(frame, "visitor_track", 0, Marker::SPHERE);
  track.action = v.visitor_track ? Marker::ADD : Marker::DELETE;
  if (v.visitor_track) {
    track.pose.position = pt(v.visitor_track->x, v.visitor_track->y, 1.9);
    track.scale.x = track.scale.y = track.scale.z = 0.3;
    track.color = v.visitor_in_sight ? rgba(0.2f, 0.9f, 0.2f) : rgba(0.9f, 0.2f, 0.2f);
  }
  a.markers.push_back(track);
  Marker doors = base(frame, "closed_doors", 0, Marker::LINE_LIST);
  doors.scale.x = 0.15;
  doors.color = rgba(0.9f, 0.1f, 0.1f);
  for (const auto& name : v.closed_doors) {
    const Door& d = s.config().door(name);
    doors.points.push_back(pt(d.a.x, d.a.y, 0.1));
    doors.points.push_back(pt(d.b.x, d.b.y, 0.1));
  }
  if (doors.points.empty()) doors.action = Marker::DELETE;
  a.markers.push_back(doors);
  // The tour's progress: each exhibit of the tour numbered, ticked once
  // visited, the next one marked.
  const Guide& g = s.guide();
  for (std::size_t i = 0; i < g.tour().size(); ++i) {
    const Exhibit& e = g.tour()[i];
    const bool done = i < g.current();
    const std::string t = std::to_string(i + 1) + (done ? " visited" : i == g.current() ? " next" : "");
    Marker m = text(frame, "tour", static_cast<int>(i), e.stop.x, e.stop.y, 0.8, t, 0.4);
    m.color = done ? rgba(0.2f, 0.9f, 0.2f) : i == g.current() ? rgba(1.0f, 0.8f, 0.0f) : rgba(1, 1, 1);
    a.markers.push_back(m);
  }
  a.markers.push_back(text(frame, "status", 0, 10.0, 12.8, 0.5, tour_status(s), 0.45));
  return a;
}

std::string tour_status(const FollowMeSession& s) {
  const Guide& g = s.guide();
  std::string visited;
  for (const auto& n : g.visited()) visited += (visited.empty() ? "" : ", ") + n;
  const std::string next = g.current() < g.tour().size() ? g.tour()[g.current()].name : "-";
  char buf[96];
  std::snprintf(buf, sizeof buf, "t %.0f s | ", s.time());
  return std::string(buf) + to_string(g.job()) + " | next " + next + " | visited " + visited + " | wanders " +
         std::to_string(g.wanders());
}

mrt_msgs::TourStatus tour_status_msg(const FollowMeSession& s, const ros::Time& stamp) {
  const Guide& g = s.guide();
  mrt_msgs::TourStatus m;
  m.header.stamp = stamp;
  m.time = s.time();
  m.job = to_string(g.job());
  m.next = g.current() < g.tour().size() ? g.tour()[g.current()].name : "";
  m.visited = g.visited();
  m.tour_size = static_cast<std::uint32_t>(g.tour().size());
  m.wanders = static_cast<std::uint32_t>(g.wanders());
  return m;
}

std::string summary(const FollowMeResult& r) {
  std::string visited;
  for (const auto& v : r.visited) visited += (visited.empty() ? "" : ", ") + v;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "exhibits visited: %zu (%s)\nwanders handled: %zu\ncompleted: %s\ntime: %.1f s\n"
                "longest time visitor out of sight: %.1f s\nlocalization error (max, vs ground truth): %.3f m\n"
                "closest to a person: %.2f m\n",
                r.visited.size(), visited.c_str(), r.wanders, r.completed ? "yes" : "no", r.time, r.max_unseen,
                r.max_pose_error, r.min_person_gap);
  return buf;
}

}  // namespace mrt::followme::node
