#include "markers.h"

#include <algorithm>
#include <cmath>

#include "mrt_common_ros/conversions.h"

namespace mrt::murea::node {
namespace {

using visualization_msgs::Marker;

Marker make(const std::string& frame, const ros::Time& stamp, const char* ns, int type, float r, float g, float b,
            float a = 0.8f) {
  Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = 0;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = a;
  return m;
}

Marker arrow(const std::string& frame, const ros::Time& stamp, const char* ns, const Pose2D& p, double evidence,
             float r, float g, float b) {
  Marker m = make(frame, stamp, ns, Marker::ARROW, r, g, b);
  m.pose = mrt::ros_common::to_pose(p, 0.05);
  m.scale.x = 0.3 + 0.02 * evidence;
  m.scale.y = m.scale.z = 0.06;
  return m;
}

}  // namespace

visualization_msgs::MarkerArray evidence_markers(const TrackResult& r, const Tracker& t, const std::string& frame,
                                                 const ros::Time& stamp) {
  visualization_msgs::MarkerArray out;
  // Covariance ellipse (2 sigma) of x, y from the plateau of most evidence.
  Marker e = make(frame, stamp, "estimate_covariance", Marker::CYLINDER, 0.2f, 0.6f, 1.0f, 0.4f);
  const double a = r.covariance[0], b = r.covariance[1], c = r.covariance[4];
  const double mid = 0.5 * (a + c), rad = std::sqrt(std::max(0.0, 0.25 * (a - c) * (a - c) + b * b));
  const double l1 = std::max(mid + rad, 0.0), l2 = std::max(mid - rad, 0.0);
  e.pose = mrt::ros_common::to_pose(Pose2D(r.pose.x, r.pose.y, 0.5 * std::atan2(2 * b, a - c)), 0.01);
  e.scale.x = std::max(4.0 * std::sqrt(l1), 0.02);
  e.scale.y = std::max(4.0 * std::sqrt(l2), 0.02);
  e.scale.z = 0.01;
  out.markers.push_back(e);
  out.markers.push_back(arrow(frame, stamp, "estimate", r.pose, r.search.best.evidence, 0.2f, 0.6f, 1.0f));
  out.markers.push_back(arrow(frame, stamp, "best_cell", r.search.best.pose, r.search.best.evidence, 0.0f, 1.0f, 0.0f));
  Marker alt = r.search.alternative
                   ? arrow(frame, stamp, "runner_up", r.search.alternative->pose, r.search.alternative->evidence, 1.0f,
                           0.3f, 0.0f)
                   : make(frame, stamp, "runner_up", Marker::ARROW, 1, 0, 0);
  if (!r.search.alternative) alt.action = Marker::DELETE;
  out.markers.push_back(alt);
  // The surviving cells: the lattice poses tied with the best (the plateau).
  Marker cells = make(frame, stamp, "tied_cells", Marker::POINTS, 1.0f, 0.5f, 0.0f, 0.9f);
  cells.scale.x = cells.scale.y = 0.03;
  for (const Pose2D& q : r.search.estimate.tied) {
    geometry_msgs::Point p;
    p.x = q.x;
    p.y = q.y;
    p.z = 0.02;
    cells.points.push_back(p);
  }
  if (cells.points.empty()) cells.action = Marker::DELETE;
  out.markers.push_back(cells);
  // The window the next tracked search will cover.
  Marker w = make(frame, stamp, "search_window", Marker::LINE_STRIP, 1.0f, 1.0f, 0.0f);
  w.scale.x = 0.02;
  if (t.tracking()) {
    const auto box = t.window();
    const double xs[5] = {box[0], box[2], box[2], box[0], box[0]}, ys[5] = {box[1], box[1], box[3], box[3], box[1]};
    for (int i = 0; i < 5; ++i) {
      geometry_msgs::Point p;
      p.x = xs[i];
      p.y = ys[i];
      w.points.push_back(p);
    }
  } else {
    w.action = Marker::DELETE;
  }
  out.markers.push_back(w);
  return out;
}

geometry_msgs::PoseArray particle_cloud(const TrackResult& r, const std::string& frame, const ros::Time& stamp) {
  geometry_msgs::PoseArray out;
  out.header.frame_id = frame;
  out.header.stamp = stamp;
  for (const Pose2D& q : r.search.estimate.tied) out.poses.push_back(mrt::ros_common::to_pose(q));
  if (out.poses.empty()) out.poses.push_back(mrt::ros_common::to_pose(r.search.best.pose));
  if (r.search.alternative) out.poses.push_back(mrt::ros_common::to_pose(r.search.alternative->pose));
  return out;
}

}  // namespace mrt::murea::node
