// followme_node: FollowMe's simulation bringup in one process — the closed
// loop of mrt_followme (mrt_sim museum, visitor model, MUREA, SPIKE, the
// guide, Mr. BRIAN with Roby's rules) paced against the wall clock, with
// /clock, tf, rviz markers, the tour dialogue (service and interactive
// markers on the exhibits) and the tour's progress.
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <mrt_msgs/TourResult.h>
#include <mrt_msgs/TourStatus.h>
#include <std_msgs/String.h>
#include <tf2_ros/transform_broadcaster.h>

#include <memory>
#include <string>
#include <vector>

#include "markers.h"
#include "tour_markers.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_followme/SetTour.h"
#include "mrt_followme/followme_loop.h"
#include "mrt_sim/world.h"

namespace {

using mrt::followme::FollowMeLoopOptions;
using mrt::followme::FollowMeResult;
using mrt::followme::FollowMeSession;
namespace glue = mrt::followme::node;

struct NodeOptions {
  FollowMeLoopOptions loop;
  double real_time_factor = 1.0;
  std::string frame = "map";
};

NodeOptions read_options(const ros::NodeHandle& pnh) {
  mrt::ros_common::ParamReader p(pnh);
  NodeOptions n;
  p.require("world", n.loop.world, "the museum's mrt_sim world file")
      .require("config", n.loop.config, "config/followme/followme.yaml")
      .require("brian", n.loop.brian, "the rule base (config/followme/brian)")
      .get("robot", n.loop.robot)
      .get("tour", n.loop.tour)
      .get_positive("duration", n.loop.duration)
      .get_positive("real_time_factor", n.real_time_factor)
      .get("close_door", n.loop.close_door)
      .get("close_at_leg", n.loop.close_at_leg)
      .get("wander_after", n.loop.wander_after)
      .get("frame", n.frame);
  return n;
}

/// What the node publishes every cycle: clock, poses, markers, status, plans.
class Outputs {
 public:
  Outputs(ros::NodeHandle& nh, const std::string& robot, const std::string& frame) : robot_(robot), frame_(frame) {
    clock_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    museum_ = nh.advertise<visualization_msgs::MarkerArray>("world_markers", 1, true);
    dynamic_ = nh.advertise<visualization_msgs::MarkerArray>("dynamic_markers", 5);
    plan_ = nh.advertise<nav_msgs::Path>(robot + "/plan", 1, true);
    status_ = nh.advertise<mrt_msgs::TourStatus>(robot + "/tour_status", 5, true);
    result_ = nh.advertise<mrt_msgs::TourResult>(robot + "/tour_result", 1, true);
    summary_ = nh.advertise<std_msgs::String>(robot + "/tour_summary", 1, true);
    truth_ = nh.advertise<nav_msgs::Odometry>(robot + "/ground_truth", 10);
    estimate_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>(robot + "/pose", 10);
  }

  void museum(const FollowMeSession& s) { museum_.publish(glue::museum_markers(s, frame_)); }

  void cycle(const FollowMeSession& s) {
    ros::Time now;
    now.fromSec(s.time());
    rosgraph_msgs::Clock c;
    c.clock = now;
    clock_.publish(c);
    const auto k = s.tick();
    pose(truth_, k.truth, "/base_link_truth", now);
    tf_.sendTransform(mrt::ros_common::to_transform(k.estimate, frame_, robot_ + "/base_link", now));
    geometry_msgs::PoseWithCovarianceStamped est;  // as MUREA's, in the distributed bringup
    est.header.frame_id = frame_;
    est.header.stamp = now;
    est.pose.pose = mrt::ros_common::to_pose(k.estimate);
    estimate_.publish(est);
    auto markers = glue::dynamic_markers(s, frame_);
    for (auto& m : markers.markers) m.header.stamp = now;
    dynamic_.publish(markers);
    status_.publish(glue::tour_status_msg(s, now));
    if (s.result().plans.size() != plans_) {
      plans_ = s.result().plans.size();
      nav_msgs::Path p;
      p.header.frame_id = frame_;
      p.header.stamp = now;
      for (const auto& q : s.result().plans.back()) {
        geometry_msgs::PoseStamped ps;
        ps.header = p.header;
        ps.pose = mrt::ros_common::to_pose(mrt::common::Pose2D(q.x, q.y, 0.0));
        p.poses.push_back(ps);
      }
      plan_.publish(p);
    }
  }

  void summary(const FollowMeSession& s) {
    const FollowMeResult& r = s.result();
    mrt_msgs::TourResult res;
    res.header.stamp.fromSec(s.time());
    res.completed = r.completed;
    res.time = r.time;
    res.wanders = static_cast<std::uint32_t>(r.wanders);
    res.visited = r.visited;
    result_.publish(res);
    std_msgs::String m;
    m.data = glue::summary(s.result());
    summary_.publish(m);
    ROS_INFO("tour %s:\n%s", s.result().completed ? "completed" : "ended", m.data.c_str());
  }

 private:
  void pose(ros::Publisher& pub, const mrt::common::Pose2D& p, const std::string& child, const ros::Time& now) {
    tf_.sendTransform(mrt::ros_common::to_transform(p, frame_, robot_ + child, now));
    nav_msgs::Odometry od;
    od.header.frame_id = frame_;
    od.header.stamp = now;
    od.child_frame_id = robot_ + child;
    od.pose.pose = mrt::ros_common::to_pose(p);
    pub.publish(od);
  }

  std::string robot_, frame_;
  ros::Publisher clock_, museum_, dynamic_, plan_, status_, result_, summary_, truth_, estimate_;
  tf2_ros::TransformBroadcaster tf_;
  std::size_t plans_ = 0;
};

int run(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
  const NodeOptions opt = read_options(pnh);
  FollowMeSession session(opt.loop);
  Outputs out(nh, opt.loop.robot, opt.frame);
  auto set_tour = pnh.advertiseService<mrt_followme::SetTour::Request, mrt_followme::SetTour::Response>(
      "set_tour", [&](auto& req, auto& res) {
        res.message = session.set_tour(req.exhibits);
        res.accepted = res.message.empty();
        return true;
      });
  auto close = nh.subscribe<std_msgs::String>(opt.loop.robot + "/close_door", 5,
                                              [&](const std_msgs::String::ConstPtr& m) {
                                                try {
                                                  session.close_door(m->data);
                                                } catch (const std::exception& e) {
                                                  ROS_WARN("close_door: %s", e.what());
                                                }
                                              });
  std::vector<glue::ExhibitRing> rings;
  for (const auto& p : session.world().posts)
    if (p.membership_class == "Exhibit") rings.push_back({p.name, p.center.x, p.center.y, p.radius});
  glue::TourMarkers tour(rings, opt.frame, [&](const std::vector<std::string>& t) { return session.set_tour(t); });
  out.museum(session);
  ros::WallTime start = ros::WallTime::now();
  bool done = false;
  mrt::ros_common::NodeDiagnostics diag(nh, "FollowMe (in process)", "followme",
                                        [&](diagnostic_updater::DiagnosticStatusWrapper& st) {
                                          const auto m = glue::tour_status_msg(session, ros::Time::now());
                                          st.add("simulated time (s)", m.time);
                                          st.add("job", m.job);
                                          st.add("next exhibit", m.next.empty() ? std::string("-") : m.next);
                                          st.add("visited", std::to_string(m.visited.size()) + " of " +
                                                                std::to_string(m.tour_size));
                                          st.add("wanders", m.wanders);
                                          st.add("tour over", done);
                                        });
  while (ros::ok()) {
    ros::spinOnce();
    const bool more = session.cycle();  // false at once when the tour is over
    out.cycle(session);
    if (!more && !done) out.summary(session);
    done = !more;  // a new tour through the dialogue starts it again
    // Pace: simulated time runs real_time_factor times the wall clock; more
    // than 0.2 s behind (a slow machine, a pause after the tour), pacing
    // restarts from now rather than racing to catch up.
    const double ahead = session.time() / opt.real_time_factor - (ros::WallTime::now() - start).toSec();
    if (ahead > 0) ros::WallDuration(ahead).sleep();
    if (ahead < -0.2) start = ros::WallTime::now() - ros::WallDuration(session.time() / opt.real_time_factor);
    if (done) ros::WallDuration(0.1).sleep();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "followme");
  ros::NodeHandle nh, pnh("~");
  return mrt::ros_common::run_node([&] { return run(nh, pnh); });
}
