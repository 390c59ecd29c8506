#include "node_options.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "mrt_common_ros/params.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_murea/scan.h"

namespace mrt::murea::node {

using mrt::ros_common::ParamReader;

namespace {

void read_tolerance(ParamReader& p, const std::string& name, Tolerance& t) {
  std::vector<double> v{t.base, t.per_metre};
  p.get(name, v);
  ParamReader::check(v.size() == 2 && std::isfinite(v[0]) && std::isfinite(v[1]) && v[0] >= 0 && v[1] >= 0, name,
                     "[base_m, per_metre], two finite numbers >= 0");
  t = {v[0], v[1]};
}

// A frame id as tf2 wants it: no leading '/' (amcl strips it too).
std::string strip_slash(std::string f) {
  while (!f.empty() && f.front() == '/') f.erase(f.begin());
  return f;
}

// The frames, tf_broadcast and the scan's beams, by amcl's names and
// MUREA's older ones (aliases); amcl's name wins when both are set.
void read_frames(ParamReader& p, NodeOptions& o) {
  p.get("frame_prefix", o.frame_prefix);
  const char* names[3][2] = {{"map_frame", "global_frame_id"}, {"odom_frame", "odom_frame_id"},
                             {"base_frame", "base_frame_id"}};
  std::string* frames[3] = {&o.map_frame, &o.odom_frame, &o.base_frame};
  for (int i = 0; i < 3; ++i) {
    p.get(names[i][0], *frames[i]).get(names[i][1], *frames[i]);
    *frames[i] = strip_slash(*frames[i]);
    ParamReader::check(!frames[i]->empty(), names[i][1], std::string("a non-empty frame id (alias ~") + names[i][0] + ")");
  }
  p.get("publish_tf", o.publish_tf).get("tf_broadcast", o.publish_tf);
  p.get("scan_max_beams", o.scan_max_beams).get("laser_max_beams", o.scan_max_beams);
  ParamReader::check(o.scan_max_beams >= 1, "laser_max_beams", "an integer >= 1 (alias ~scan_max_beams)");
}

}  // namespace

NodeOptions read_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  ParamReader p(pnh);
  SearchOptions& s = o.tracker.search;
  TrackerOptions& t = o.tracker;
  p.get("use_map_topic", o.use_map_topic);
  if (o.use_map_topic) p.get("map", o.map_file);  // unused: the map comes from the topic
  else p.require("map", o.map_file, "the path of the map (a world file or a map_server map YAML), or ~use_map_topic");
  p.get_positive("accuracy_xy", s.accuracy_xy).get_positive("accuracy_theta", s.accuracy_theta);
  ParamReader::check(s.accuracy_theta <= 1.0, "accuracy_theta", "a number of radians in (0, 1]");
  s.timeout = 0.05;
  p.get_non_negative("timeout", s.timeout);
  s.timeout_cpu = true;  // the node's thread's CPU time: a loaded machine does not cut searches short
  p.get("timeout_cpu", s.timeout_cpu);
  for (int c = 0; c < kFeatureClassCount; ++c) {
    std::string name = std::string("tolerance_") + to_string(static_cast<FeatureClass>(c));
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    read_tolerance(p, name, s.tolerance[c]);
  }
  p.get_positive("window_sigmas", t.window_sigmas)
      .get_positive("min_window_xy", t.min_window_xy)
      .get_positive("max_window_xy", t.max_window_xy)
      .get_positive("min_window_theta", t.min_window_theta)
      .get_positive("max_window_theta", t.max_window_theta)
      .get_non_negative("collapse_fraction", t.collapse_fraction)
      .get_positive("collapse_frames", t.collapse_frames);
  ParamReader::check(t.max_window_xy >= t.min_window_xy, "max_window_xy", "a number >= ~min_window_xy");
  ParamReader::check(t.max_window_theta >= t.min_window_theta && t.max_window_theta < 3.0, "max_window_theta",
                     "a number >= ~min_window_theta and < 3 rad");
  ParamReader::check(t.collapse_fraction <= 1.0, "collapse_fraction", "a number in [0, 1]");
  RefineOptions& f = t.refine;
  std::vector<double> sr{f.sigma_range_base, f.sigma_range_per_metre};
  p.get("refine", f.enabled).get("refine_sigma_range", sr).get_non_negative("refine_sigma_bearing", f.sigma_bearing);
  ParamReader::check(sr.size() == 2 && std::isfinite(sr[0]) && std::isfinite(sr[1]) && sr[0] >= 0 && sr[1] >= 0 &&
                         sr[0] + sr[1] > 0,
                     "refine_sigma_range", "[base_m, per_metre], two finite numbers >= 0, not both 0");
  f.sigma_range_base = sr[0];
  f.sigma_range_per_metre = sr[1];
  read_frames(p, o);
  p.get("odom_topic", o.odom_topic);
  p.get_non_negative("odom_alpha_xy", o.odom_alpha_xy)
      .get_non_negative("odom_alpha_theta", o.odom_alpha_theta)
      .get_non_negative("odom_alpha_theta_xy", o.odom_alpha_theta_xy)
      .get_non_negative("transform_tolerance", o.transform_tolerance)
      .get_positive("tf_rate", o.tf_rate);
  p.get_non_negative("ambiguous_global_period", t.ambiguous_global_period).get_non_negative("settle_frames", t.settle_frames);
  p.get_non_negative("prior_gate", t.prior_gate)
      .get_non_negative("lost_growth_xy", t.lost_growth_xy)
      .get_non_negative("lost_growth_theta", t.lost_growth_theta);
  if (pnh.hasParam("initial_pose_x") || pnh.hasParam("initial_pose_y") || pnh.hasParam("initial_pose_a")) {
    double x = 0.0, y = 0.0, a = 0.0;
    p.get("initial_pose_x", x).get("initial_pose_y", y).get("initial_pose_a", a);
    ParamReader::check(std::isfinite(x) && std::isfinite(y) && std::isfinite(a), "initial_pose_x",
                       "finite ~initial_pose_x, ~initial_pose_y (m) and ~initial_pose_a (rad)");
    o.initial_pose = Pose2D(x, y, a);
  }
  p.get_non_negative("initial_cov_xx", o.initial_cov[0])
      .get_non_negative("initial_cov_yy", o.initial_cov[4])
      .get_non_negative("initial_cov_aa", o.initial_cov[8]);
  return o;
}

std::vector<Percept> to_percepts(const mrt_msgs::Percept& msg, DropCounts& drops) {
  std::vector<Percept> out;
  for (const mrt::common::PerceptObject& obj : mrt::ros_common::accepted_objects(msg, drops.ontology)) {
    const auto cls = parse_feature_class(obj.membership_class);
    if (!cls) {
      ++drops.non_map_class;
      continue;
    }
    const auto pos = mrt::common::polar(obj);  // the ontology check made sure there is one
    const double reliability = pos->reliability > 0.0 ? std::min(pos->reliability, 1.0) : 1.0;
    if (!std::isfinite(pos->distance) || !std::isfinite(pos->bearing) || pos->distance < 0.0 ||
        !std::isfinite(reliability)) {
      ++drops.non_finite;
      continue;
    }
    Percept p;
    p.cls = *cls;
    p.color = obj.symbol("color");
    p.distance = pos->distance;
    p.bearing = pos->bearing;
    p.reliability = std::clamp(reliability, 1e-6, 1.0);
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<Percept> scan_to_percepts(const sensor_msgs::LaserScan& scan, int max_beams, ScanCounts& counts) {
  ++counts.scans;
  const ScanGeometry g{scan.angle_min, scan.angle_increment, scan.range_min, scan.range_max};
  return scan_percepts(scan.ranges, g, max_beams, &counts.invalid);
}

Covariance3 odometry_covariance(const Pose2D& d, const NodeOptions& o) {
  const double dist = std::hypot(d.x, d.y), turn = std::abs(d.theta);
  const double sxy = o.odom_alpha_xy * dist;
  const double st = o.odom_alpha_theta * turn + o.odom_alpha_theta_xy * dist;
  return {sxy * sxy, 0, 0, 0, sxy * sxy, 0, 0, 0, st * st};
}

void to_base_frame(std::vector<Percept>& percepts, const Pose2D& mount) {
  for (Percept& p : percepts) {
    const Pose2D q = mount * Pose2D(p.distance * std::cos(p.bearing), p.distance * std::sin(p.bearing), 0.0);
    p.distance = std::hypot(q.x, q.y);
    p.bearing = std::atan2(q.y, q.x);
  }
}

TrackResult track_frame(Tracker& tracker, std::optional<Pose2D>* last_odom, const Pose2D& odom,
                        const std::vector<Percept>& percepts, const NodeOptions& o) {
  if (*last_odom) {
    const Pose2D delta = (*last_odom)->inverse() * odom;
    tracker.predict(delta, odometry_covariance(delta, o));
  }
  *last_odom = odom;
  return tracker.update(percepts);
}

}  // namespace mrt::murea::node
