// guide_node: the guide of the distributed FollowMe (launch/followme.launch,
// distributed:=true). Wiring around the ROS-free Guide (guide.h), the same
// guide the in-process loop drives: MUREA's pose and MAP's track of the
// visitor in, and out Mr. BRIAN's path point (goal_crisp, Roby's data:
// Status, HaveGoal, GoalDistance, GoalBearing; plus VisitorDistance and
// VisitorAngle for the KeepVisitor rules, config/brian/README.md), SPIKE's
// legs (make_plan), the call to the visitor, the closed doors' walls as
// Obstacle percepts for SPIKE, the tour dialogue (the ~set_tour service
// and the interactive markers) and the tour's progress.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <mrt_msgs/Tour.h>
#include <mrt_msgs/TourResult.h>
#include <mrt_msgs/TourStatus.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_common/percept.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_followme/SetTour.h"
#include "mrt_followme/guide.h"
#include "mrt_followme/museum.h"
#include "mrt_followme/visitor_tracker.h"
#include "mrt_msgs/CrispDataArray.h"
#include "mrt_msgs/Percept.h"
#include "mrt_roby/crisp_builder.h"
#include "tour_markers.h"

namespace {

using mrt::common::Point2D;
using mrt::common::Pose2D;
using namespace mrt::followme;

struct Options {
  std::string config, frame = "map", plan_service = "make_plan";
  std::vector<std::string> tour;
  double rate = 10.0;
  double door_replan_delay = 0.5;  // s: SPIKE has the door's percepts by then
};

Options read_options(const ros::NodeHandle& pnh) {
  mrt::ros_common::ParamReader p(pnh);
  Options o;
  p.require("config", o.config, "config/followme/followme.yaml")
      .get("tour", o.tour)
      .get("frame", o.frame)
      .get("plan_service", o.plan_service)
      .get_positive("rate", o.rate)
      .get_positive("door_replan_delay", o.door_replan_delay);
  return o;
}

void append(const mrt::brian::CrispDataList& data, mrt_msgs::CrispDataArray& out) {
  for (const auto& c : data) {
    mrt_msgs::CrispData d;
    d.name = c.name;
    d.value = c.value;
    d.reliability = c.reliability;
    out.data.push_back(d);
  }
}

class GuideNode {
 public:
  GuideNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, Options o)
      : opt_(std::move(o)), cfg_(load_followme_config(opt_.config)), guide_(cfg_.guide, {}),
        tracker_(cfg_.visitor.color),
        diag_(nh, "FollowMe guide", "guide", [this](diagnostic_updater::DiagnosticStatusWrapper& st) { diagnose(st); }) {
    diag_.input("pose", 2.0);
    diag_.input("map_crisp", 2.0);
    pose_sub_ = nh.subscribe("pose", 5, &GuideNode::on_pose, this);
    crisp_sub_ = nh.subscribe("map_crisp", 5, &GuideNode::on_crisp, this);
    door_sub_ = nh.subscribe("close_door", 5, &GuideNode::on_close_door, this);
    goal_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("goal_crisp", 5);
    plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    status_pub_ = nh.advertise<mrt_msgs::TourStatus>("tour_status", 5, true);
    result_pub_ = nh.advertise<mrt_msgs::TourResult>("tour_result", 1, true);
    tour_pub_ = nh.advertise<mrt_msgs::Tour>("tour", 1, true);
    call_pub_ = nh.advertise<std_msgs::Empty>("call_visitor", 1);
    door_pub_ = nh.advertise<mrt_msgs::Percept>("door_percepts", 5);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("tour_markers", 1, true);
    // The tour once its topic is advertised: the (simulated) visitor learns
    // it from there; published on a publisher not yet advertised it was lost.
    const std::string bad = set_tour(opt_.tour.empty() ? cfg_.tour : opt_.tour);
    if (!bad.empty())
      throw mrt::ros_common::ParamError("tour", "exhibits of the configuration, each once (" + bad + ")");
    planner_ = nh.serviceClient<nav_msgs::GetPlan>(opt_.plan_service);
    service_ = pnh.advertiseService("set_tour", &GuideNode::on_set_tour, this);
    std::vector<mrt::followme::node::ExhibitRing> rings;
    for (const auto& e : cfg_.exhibits) rings.push_back({e.name, e.spot.x, e.spot.y, 0.4});
    markers_ = std::make_unique<mrt::followme::node::TourMarkers>(
        rings, opt_.frame, [this](const std::vector<std::string>& t) { return set_tour(t); }, "/tour");
    timer_ = nh.createTimer(ros::Duration(1.0 / opt_.rate), &GuideNode::cycle, this);
  }

 private:
  /// The dialogue: "" when taken (the robot starts from where it is).
  std::string set_tour(const std::vector<std::string>& names) {
    const std::string bad = check_tour(cfg_, names);
    if (!bad.empty()) return bad;
    std::vector<Exhibit> tour;
    for (const auto& n : names) tour.push_back(cfg_.exhibits[cfg_.exhibit_index(n)]);
    guide_.set_tour(std::move(tour), ros::Time::now().toSec());
    request_.reset();
    done_ = false;
    started_ = ros::Time::now();
    mrt_msgs::Tour t;
    t.header.stamp = started_;
    t.exhibits = names;
    tour_pub_.publish(t);
    return "";
  }

  bool on_set_tour(mrt_followme::SetTour::Request& req, mrt_followme::SetTour::Response& res) {
    res.message = set_tour(req.exhibits);
    res.accepted = res.message.empty();
    return true;
  }

  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    diag_.received("pose");
    pose_ = mrt::ros_common::to_pose2d(m.pose.pose);
  }

  // The tour's state beside the inputs; WARN while a leg waits for SPIKE.
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const auto& tour = guide_.tour();
    st.add("job", to_string(guide_.job()));
    st.add("next exhibit", guide_.current() < tour.size() ? tour[guide_.current()].name : std::string("-"));
    st.add("visited", std::to_string(guide_.visited().size()) + " of " + std::to_string(tour.size()));
    st.add("wanders", guide_.wanders());
    st.add("tour over", done_);
    if (request_) st.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "waiting for a plan from SPIKE");
    if (!pose_) st.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "no pose yet");
  }

  /// MAP's track of the visitor (VisitorX, VisitorY with MAP's reliability)
  /// feeds the visitor track the guide reads, as the camera's percepts feed
  /// it in process.
  void on_crisp(const mrt_msgs::CrispDataArray& m) {
    diag_.received("map_crisp");
    std::map<std::string, const mrt_msgs::CrispData*> by;
    for (const auto& d : m.data) by[d.name] = &d;
    visitor_reliability_ = 0.0;
    if (!by.count("VisitorX") || !by.count("VisitorY") || by["VisitorX"]->reliability <= 0.05) return;
    const double t = m.header.stamp.isZero() ? ros::Time::now().toSec() : m.header.stamp.toSec();
    tracker_.observe(t, {by["VisitorX"]->value, by["VisitorY"]->value});
    visitor_reliability_ = std::min(by["VisitorX"]->reliability, by["VisitorY"]->reliability);
  }

  /// The museum's door sensor: a door closed now. SPIKE is told (its wall as
  /// Obstacle percepts, every cycle) and the guide re-plans the leg once
  /// SPIKE has it.
  void on_close_door(const std_msgs::String& m) {
    try {
      guide_.close_door(cfg_.door(m.data), ros::Time::now().toSec(), opt_.door_replan_delay);
      ROS_INFO("door %s closed: re-planning", m.data.c_str());
    } catch (const std::exception& e) {
      ROS_WARN("close_door: %s", e.what());
    }
  }

  void publish_doors() {
    if (guide_.closed_doors().empty()) return;
    mrt::common::Percept p;
    p.stamp = ros::Time::now().toSec();
    p.frame = opt_.frame;
    p.sensor = "doors";
    for (const Door& d : guide_.closed_doors())
      for (const DoorDisc& disc : door_discs(d)) {  // SPIKE tracks obstacles by name
        mrt::common::PerceptObject o(disc.name, mrt::common::percept_class::kObstacle);
        o.set_cartesian({disc.center.x, disc.center.y}).set("radius", disc.radius);
        p.objects.push_back(std::move(o));
      }
    door_pub_.publish(mrt::ros_common::to_msg(p));
  }

  /// SPIKE's leg from the pose to `to`; none when it does not answer.
  std::optional<std::vector<Point2D>> plan(const Point2D& to) {
    nav_msgs::GetPlan srv;
    srv.request.start.header.frame_id = srv.request.goal.header.frame_id = opt_.frame;
    srv.request.start.pose = mrt::ros_common::to_pose(*pose_);
    srv.request.goal.pose = mrt::ros_common::to_pose(Pose2D(to.x, to.y, 0.0));
    if (!planner_.call(srv) || srv.response.plan.poses.empty()) return std::nullopt;
    std::vector<Point2D> path;
    for (const auto& p : srv.response.plan.poses) path.push_back({p.pose.position.x, p.pose.position.y});
    srv.response.plan.header.frame_id = opt_.frame;
    plan_pub_.publish(srv.response.plan);
    return path;
  }

  /// The guide's plan request, asked of SPIKE now and, while it does not
  /// answer, again every second (the guide asks once).
  void serve_plan_request(double t) {
    if (!request_ || t < retry_at_) return;
    if (auto path = plan(*request_)) {
      request_.reset();
      guide_.set_plan(std::move(*path), t);
    } else {
      ROS_WARN_THROTTLE(2.0, "no plan to (%.1f, %.1f) yet", request_->x, request_->y);
      diag_.count("plan requests unanswered");
      retry_at_ = t + 1.0;
    }
  }

  void cycle(const ros::TimerEvent&) {
    if (!pose_) return;
    const double t = ros::Time::now().toSec();
    const GuideOutput out = guide_.update({t, *pose_, tracker_.track()});
    if (out.call_visitor) call_pub_.publish(std_msgs::Empty());
    if (out.plan_request) {
      request_ = out.plan_request;
      retry_at_ = t;
    }
    serve_plan_request(t);
    publish_doors();
    publish_goal(out.goal);
    if (guide_.job() == Job::kDone) finish();
    publish_status(t);
  }

  /// Mr. BRIAN's data: the path point (none: stand) and, while MAP tracks
  /// the visitor, where it is (KeepVisitor's data, with MAP's reliability).
  void publish_goal(const std::optional<Point2D>& goal) {
    mrt::brian::CrispDataList d;
    std::optional<mrt::scare::GoalCrisp> g;
    if (goal) g = mrt::scare::goal_crisp(*pose_, *goal);
    mrt::roby::goal_crisp_data(mrt::scare::Mode::kAuto, g, d);
    mrt::roby::remote_crisp_data(std::nullopt, d);
    const auto& v = tracker_.track();
    if (v && visitor_reliability_ > 0.0) {
      const mrt::scare::GoalCrisp c = mrt::scare::goal_crisp(*pose_, v->position);
      d.push_back({"VisitorDistance", c.distance_cm, visitor_reliability_});
      d.push_back({"VisitorAngle", c.bearing_deg, visitor_reliability_});
    }
    mrt_msgs::CrispDataArray m;
    m.header.stamp = ros::Time::now();
    append(d, m);
    goal_pub_.publish(m);
  }

  void finish() {
    if (done_) return;
    done_ = true;
    mrt_msgs::TourResult r;
    r.header.stamp = ros::Time::now();
    r.completed = guide_.visited().size() >= guide_.tour().size();
    r.time = (r.header.stamp - started_).toSec();
    r.wanders = static_cast<std::uint32_t>(guide_.wanders());
    r.visited = guide_.visited();
    result_pub_.publish(r);
    ROS_INFO("tour over: completed %s, %.1f s, %u wanders, %zu exhibits visited", r.completed ? "yes" : "no", r.time,
             r.wanders, r.visited.size());
  }

  void publish_status(double t) {
    const auto& tour = guide_.tour();
    const std::size_t k = guide_.current();
    mrt_msgs::TourStatus st;
    st.header.stamp = ros::Time::now();
    st.time = t;
    st.job = to_string(guide_.job());
    st.next = k < tour.size() ? tour[k].name : "";
    st.visited = guide_.visited();
    st.tour_size = static_cast<std::uint32_t>(tour.size());
    st.wanders = static_cast<std::uint32_t>(guide_.wanders());
    // the rviz line: "t 84 s | WaitVisitor | next pedestal | visited 1 | wanders 0"
    char buf[256];
    std::snprintf(buf, sizeof buf, "t %.0f s | %s | next %s | visited %zu | wanders %zu", t, st.job.c_str(),
                  st.next.empty() ? "-" : st.next.c_str(), st.visited.size(), guide_.wanders());
    const std::string line = buf;
    if (line != last_status_) {
      status_pub_.publish(st);
      publish_progress(line);
    }
    last_status_ = line;
  }

  /// The tour's progress in rviz: the status line above the museum, at each
  /// stop its place in the tour and whether it was visited or is next.
  void publish_progress(const std::string& status) {
    visualization_msgs::MarkerArray a;
    visualization_msgs::Marker del;
    del.action = visualization_msgs::Marker::DELETEALL;
    a.markers.push_back(del);
    auto text = [&](int id, double x, double y, const std::string& t) {
      visualization_msgs::Marker m;
      m.header.frame_id = opt_.frame;
      m.header.stamp = ros::Time::now();
      m.ns = "tour";
      m.id = id;
      m.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
      m.pose.position.x = x;
      m.pose.position.y = y;
      m.pose.position.z = 1.0;
      m.pose.orientation.w = 1.0;
      m.scale.z = 0.4;
      m.color.r = m.color.g = m.color.b = 0.1f;
      m.color.a = 1.0f;
      m.text = t;
      a.markers.push_back(m);
    };
    text(0, 10.0, 12.8, status);
    const auto& tour = guide_.tour();
    const std::size_t current = guide_.current();
    for (std::size_t k = 0; k < tour.size(); ++k)
      text(static_cast<int>(k) + 1, tour[k].stop.x, tour[k].stop.y,
           std::to_string(k + 1) + (k < current ? " visited" : (k == current ? " next" : "")));
    markers_pub_.publish(a);
  }

  Options opt_;
  FollowMeConfig cfg_;
  Guide guide_;
  VisitorTracker tracker_;  // MAP's track of the visitor
  double visitor_reliability_ = 0.0;  // of MAP's last crisp data; 0: no track
  std::optional<Pose2D> pose_;
  std::optional<Point2D> request_;  // the guide's plan request SPIKE has not answered yet
  double retry_at_ = 0.0;
  bool done_ = false;
  std::string last_status_;
  ros::Time started_;
  ros::Subscriber pose_sub_, crisp_sub_, door_sub_;
  ros::Publisher goal_pub_, plan_pub_, status_pub_, result_pub_, tour_pub_, call_pub_, markers_pub_, door_pub_;
  ros::ServiceClient planner_;
  ros::ServiceServer service_;
  ros::Timer timer_;
  mrt::ros_common::NodeDiagnostics diag_;  // last: its callback reads the members above
  std::unique_ptr<mrt::followme::node::TourMarkers> markers_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "guide");
  ros::NodeHandle nh, pnh("~");
  return mrt::ros_common::run_node([&] {
    GuideNode node(nh, pnh, read_options(pnh));
    ros::spin();
    return 0;
  });
}
