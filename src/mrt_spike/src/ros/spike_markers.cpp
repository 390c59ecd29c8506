#include "spike_markers.h"

#include <geometry_msgs/Point.h>

namespace mrt::spike::node {

namespace {

visualization_msgs::Marker base(const std::string& frame, const std::string& ns, int type, double scale) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.header.stamp = ros::Time::now();
  m.ns = ns;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = scale;
  m.scale.z = 0.02;
  m.color.a = 0.6f;
  return m;
}

geometry_msgs::Point point(const GridFrame& f, double cx, double cy, double z = 0.0) {
  geometry_msgs::Point p;
  p.x = f.origin_x + f.resolution * cx;
  p.y = f.origin_y + f.resolution * cy;
  p.z = z;
  return p;
}

// Cells blocked in `a` but not in `b`, as a CUBE_LIST.
visualization_msgs::Marker cells(const WorldPlanner& p, const OccupancyGrid& a, const OccupancyGrid& b,
                                 const std::string& frame, const std::string& ns) {
  const GridFrame& f = p.map().frame;
  visualization_msgs::Marker m = base(frame, ns, visualization_msgs::Marker::CUBE_LIST, f.resolution);
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (a.blocked(x, y) && !b.blocked(x, y)) m.points.push_back(point(f, x, y, 0.01));
  return m;
}

}  // namespace

visualization_msgs::MarkerArray static_markers(const WorldPlanner& p, const std::string& frame) {
  visualization_msgs::MarkerArray a;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  a.markers.push_back(clear);
  const GridFrame& f = p.map().frame;
  if (const Quadtree* tree = p.quadtree()) {  // SPIKE's; the grid planners have none
    visualization_msgs::Marker d = base(frame, "decomposition", visualization_msgs::Marker::LINE_LIST, f.resolution * 0.2);
    d.color.g = 0.7f, d.color.b = 1.0f, d.color.a = 0.5f;
    for (const QuadLeaf& l : tree->leaves()) {
      if (l.size < 2) continue;  // the finest cells: the inflated marker shows them
      const double x0 = l.x - 0.5, y0 = l.y - 0.5, x1 = l.x + l.size - 0.5, y1 = l.y + l.size - 0.5;
      const geometry_msgs::Point c[4] = {point(f, x0, y0), point(f, x1, y0), point(f, x1, y1), point(f, x0, y1)};
      for (int k = 0; k < 4; ++k) d.points.push_back(c[k]), d.points.push_back(c[(k + 1) % 4]);
    }
    a.markers.push_back(d);
  }
  visualization_msgs::Marker i = cells(p, p.inflated(), p.map().grid, frame, "inflated");
  i.color.r = 1.0f, i.color.g = 0.6f, i.color.a = 0.4f;
  a.markers.push_back(i);
  visualization_msgs::Marker w = cells(p, p.map().grid, OccupancyGrid(p.map().grid.width(), p.map().grid.height()),
                                       frame, "obstacles");
  w.color.r = w.color.g = w.color.b = 0.2f, w.color.a = 0.9f;
  a.markers.push_back(w);
  return a;
}

visualization_msgs::MarkerArray obstacle_markers(const WorldPlanner& p, const std::string& frame) {
  visualization_msgs::MarkerArray a;
  visualization_msgs::Marker m = cells(p, p.with_obstacles(), p.inflated(), frame, "moving_obstacles");
  m.color.r = 1.0f, m.color.a = 0.6f;
  a.markers.push_back(m);
  return a;
}

}  // namespace mrt::spike::node
