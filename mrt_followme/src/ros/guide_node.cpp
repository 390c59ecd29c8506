// guide_node: the tour of the distributed FollowMe (launch/followme.launch,
// distributed:=true). It holds the tour dialogue (the ~set_tour service and
// the interactive markers), gives SCARE's scare_node one job per exhibit
// (Visit.<n>: Replan, Guide, WaitVisitor; FollowVisitor.<n> after a
// hand-back), supplies the facts its task machines read (world_crisp: MAP's
// crisp data and TourFacts), asks SPIKE's spike_node for each leg when the
// Replan task starts, and gives Mr. BRIAN the path point of the active task
// (goal_crisp, Roby's data: Status, HaveGoal, GoalDistance, GoalBearing)
// and the visitor's place for the KeepVisitor rules (VisitorDistance,
// VisitorAngle; config/brian/README.md), which keep the visitor.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_followme/SetTour.h"
#include "mrt_followme/museum.h"
#include "mrt_followme/tour_facts.h"
#include "mrt_msgs/CrispDataArray.h"
#include "mrt_msgs/Percept.h"
#include "mrt_msgs/TaskStatus.h"
#include "tour_markers.h"

namespace {

using mrt::common::Point2D;
using mrt::common::Pose2D;
using namespace mrt::followme;

struct Options {
  std::string config, frame = "map", plan_service = "make_plan";
  std::vector<std::string> tour;
  double rate = 10.0;
};

Options read_options(const ros::NodeHandle& pnh) {
  mrt::ros_common::ParamReader p(pnh);
  Options o;
  p.require("config", o.config, "config/followme/followme.yaml")
      .get("tour", o.tour)
      .get("frame", o.frame)
      .get("plan_service", o.plan_service)
      .get_positive("rate", o.rate);
  return o;
}

void add(mrt_msgs::CrispDataArray& a, const std::string& name, double value, double reliability = 1.0) {
  mrt_msgs::CrispData d;
  d.name = name;
  d.value = value;
  d.reliability = reliability;
  a.data.push_back(d);
}

class GuideNode {
 public:
  GuideNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, Options o)
      : opt_(std::move(o)), cfg_(load_followme_config(opt_.config)), facts_(cfg_.guide) {
    pose_sub_ = nh.subscribe("pose", 5, &GuideNode::on_pose, this);
    crisp_sub_ = nh.subscribe("map_crisp", 5, &GuideNode::on_crisp, this);
    status_sub_ = nh.subscribe("task_status", 50, &GuideNode::on_status, this);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("pose_odom", 5);
    world_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("world_crisp", 5);
    goal_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("goal_crisp", 5);
    job_pub_ = nh.advertise<std_msgs::String>("scare/job", 1, true);
    plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    status_pub_ = nh.advertise<std_msgs::String>("tour_status", 5, true);
    result_pub_ = nh.advertise<std_msgs::String>("tour_result", 1, true);
    tour_pub_ = nh.advertise<std_msgs::String>("tour", 1, true);
    call_pub_ = nh.advertise<std_msgs::Empty>("call_visitor", 1);
    door_pub_ = nh.advertise<mrt_msgs::Percept>("door_percepts", 5);
    door_sub_ = nh.subscribe("close_door", 5, &GuideNode::on_close_door, this);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("tour_markers", 1, true);
    // The tour once its topic is advertised: the (simulated) visitor learns
    // it from there; published on a publisher not yet advertised it was lost.
    const std::string bad = set_tour(opt_.tour.empty() ? cfg_.tour : opt_.tour);
    if (!bad.empty())
      throw mrt::ros_common::ParamError("tour", "exhibits of the configuration, each once (" + bad + ")");
    planner_ = nh.serviceClient<nav_msgs::GetPlan>(opt_.plan_service);
    service_ = pnh.advertiseService("set_tour", &GuideNode::on_set_tour, this);
    std::vector<mrt::followme::ros_glue::ExhibitRing> rings;
    for (const auto& e : cfg_.exhibits) rings.push_back({e.name, e.spot.x, e.spot.y, 0.4});
    markers_ = std::make_unique<mrt::followme::ros_glue::TourMarkers>(
        rings, opt_.frame, [this](const std::vector<std::string>& t) { return set_tour(t); }, "/tour");
    timer_ = nh.createTimer(ros::Duration(1.0 / opt_.rate), &GuideNode::cycle, this);
  }

 private:
  /// The dialogue: "" when taken (the robot starts from where it is).
  std::string set_tour(const std::vector<std::string>& names) {
    const std::string bad = check_tour(cfg_, names);
    if (!bad.empty()) return bad;
    tour_.clear();
    for (const auto& n : names) tour_.push_back(cfg_.exhibits[cfg_.exhibit_index(n)]);
    current_ = 0;
    visited_.clear();
    wanders_ = 0;
    done_ = false;
    started_ = ros::Time::now();
    std_msgs::String t;
    for (const auto& n : names) t.data += (t.data.empty() ? "" : ",") + n;
    tour_pub_.publish(t);
    if (pose_) give_visit();
    return "";
  }

  bool on_set_tour(mrt_followme::SetTour::Request& req, mrt_followme::SetTour::Response& res) {
    res.message = set_tour(req.exhibits);
    res.accepted = res.message.empty();
    return true;
  }

  /// The job goes to SCARE two cycles later, after the facts of the new
  /// leg (PlanReady 0, the new stop's distance, nothing looked at): SCARE
  /// must not judge the new job on the old leg's facts.
  void give_job(const std::string& job) {
    pending_job_ = job + "." + std::to_string(++jobs_);  // a new name: SCARE starts it afresh
    job_delay_ = 2;
    task_.clear();
  }

  void send_pending_job() {
    if (pending_job_.empty() || --job_delay_ > 0) return;
    std_msgs::String j;
    j.data = pending_job_;
    job_pub_.publish(j);
    pending_job_.clear();
  }

  void give_visit() {
    if (current_ >= tour_.size()) return finish();
    facts_.set_exhibit(tour_[current_]);
    plan_.clear();
    plan_ready_ = false;
    give_job("Visit");
  }

  void finish() {
    if (done_) return;
    done_ = true;
    std_msgs::String none;  // no job: SCARE stops
    job_pub_.publish(none);
    pending_job_.clear();
    task_.clear();
    std_msgs::String r;
    char buf[256];
    std::snprintf(buf, sizeof buf, "completed %s | time %.1f | wanders %zu | visited ",
                  visited_.size() == tour_.size() ? "yes" : "no", (ros::Time::now() - started_).toSec(), wanders_);
    r.data = buf;
    for (std::size_t i = 0; i < visited_.size(); ++i) r.data += (i ? "," : "") + visited_[i];
    result_pub_.publish(r);
    ROS_INFO("tour over: %s", r.data.c_str());
  }

  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const bool first = !pose_;
    pose_ = mrt::ros_common::to_pose2d(m.pose.pose);
    nav_msgs::Odometry od;
    od.header = m.header;
    od.child_frame_id = "base_link";
    od.pose = m.pose;
    odom_pub_.publish(od);
    if (first && !tour_.empty()) give_visit();
  }

  void on_crisp(const mrt_msgs::CrispDataArray& m) {
    map_crisp_ = m;
    std::map<std::string, const mrt_msgs::CrispData*> by;
    for (const auto& d : m.data) by[d.name] = &d;
    visitor_.reset();
    if (by.count("VisitorX") && by.count("VisitorY") && by["VisitorX"]->reliability > 0.05) {
      visitor_ = Point2D{by["VisitorX"]->value, by["VisitorY"]->value};
      visitor_reliability_ = std::min(by["VisitorX"]->reliability, by["VisitorY"]->reliability);
    }
    // Its speed: the track's displacement over the last second (MAP's
    // filtered velocity jitters by 0.1-0.2 m/s around a standing person).
    const double t = m.header.stamp.isZero() ? ros::Time::now().toSec() : m.header.stamp.toSec();
    if (!visitor_) {
      track_.clear();
      return;
    }
    track_.push_back({t, *visitor_});
    while (track_.size() > 2 && t - track_[1].first >= 1.0) track_.pop_front();
    const auto& [t0, p0] = track_.front();
    visitor_speed_ = t - t0 >= 0.5 ? std::hypot(visitor_->x - p0.x, visitor_->y - p0.y) / (t - t0) : 0.0;
  }

  /// The museum's door sensor: a door closed now. SPIKE is told (its wall as
  /// Obstacle percepts, every cycle) and the current leg re-planned.
  void on_close_door(const std_msgs::String& m) {
    try {
      closed_.push_back(cfg_.door(m.data));
      ROS_INFO("door %s closed: re-planning", m.data.c_str());
      replan_at_ = ros::Time::now() + ros::Duration(0.5);  // once SPIKE has the door
    } catch (const std::exception& e) {
      ROS_WARN("close_door: %s", e.what());
    }
  }

  void publish_doors() {
    if (closed_.empty()) return;
    mrt_msgs::Percept p;
    p.header.stamp = ros::Time::now();
    p.header.frame_id = opt_.frame;
    p.sensor = "doors";
    auto attr = [](const std::string& n, double v) {
      mrt_msgs::Attribute a;
      a.name = n;
      a.value = v;
      a.reliability = 1.0;
      return a;
    };
    for (const auto& d : closed_) {
      const double len = std::hypot(d.b.x - d.a.x, d.b.y - d.a.y);
      const int n = std::max(2, static_cast<int>(std::ceil(len / 0.25)) + 1);  // discs 0.25 m apart
      for (int i = 0; i < n; ++i) {
        const double k = static_cast<double>(i) / (n - 1);
        mrt_msgs::PerceptObject o;
        o.name = d.name + "_" + std::to_string(i);  // SPIKE tracks obstacles by name
        o.membership_class = "Obstacle";
        o.attributes = {attr("x", d.a.x + k * (d.b.x - d.a.x)), attr("y", d.a.y + k * (d.b.y - d.a.y)),
                        attr("radius", 0.2)};
        p.objects.push_back(o);
      }
    }
    door_pub_.publish(p);
  }

  void on_status(const mrt_msgs::TaskStatus& s) {
    if (s.event == "task_started") {
      task_ = s.task;
      if (task_ == "Replan") request_plan();
      if (task_ == "FollowVisitor") called_ = false;
    } else if (s.event == "handed_back") {
      // The visitor wandered off (Guide or WaitVisitor): follow it. An
      // exhibit it had looked at counts as visited.
      ++wanders_;
      if (s.task == "WaitVisitor" && last_.looked) visited_.push_back(tour_[current_++].name);
      give_job("FollowVisitor");
    } else if (s.event == "job_done") {
      if (task_ == "WaitVisitor") visited_.push_back(tour_[current_++].name);
      give_visit();  // after FollowVisitor: the same exhibit or the next, re-planned
    } else if (s.event == "job_aborted" || s.event == "gave_up") {
      ROS_WARN("job aborted (%s): the leg again", s.task.c_str());
      give_visit();
    }
  }

  void request_plan() {
    if (!pose_ || current_ >= tour_.size()) return;
    nav_msgs::GetPlan srv;
    srv.request.start.header.frame_id = srv.request.goal.header.frame_id = opt_.frame;
    srv.request.start.pose = mrt::ros_common::to_pose(*pose_);
    const Point2D g = tour_[current_].stop;
    srv.request.goal.pose = mrt::ros_common::to_pose(Pose2D(g.x, g.y, 0.0));
    if (!planner_.call(srv) || srv.response.plan.poses.empty()) {
      ROS_WARN_THROTTLE(2.0, "no plan to %s yet", tour_[current_].name.c_str());
      return;  // Replan's timeout retries
    }
    plan_.clear();
    for (const auto& p : srv.response.plan.poses) plan_.push_back({p.pose.position.x, p.pose.position.y});
    index_ = 0;
    plan_ready_ = true;
    srv.response.plan.header.frame_id = opt_.frame;
    plan_pub_.publish(srv.response.plan);
  }

  /// The path point of the active task, if any.
  std::optional<Point2D> goal(const TourFacts& f) {
    if (!pose_) return std::nullopt;
    const Pose2D& p = *pose_;
    if (task_ == "Guide" && !plan_.empty()) {  // a lagging visitor: KeepVisitor's rules
      while (index_ + 1 < plan_.size() &&
             std::hypot(plan_[index_].x - p.x, plan_[index_].y - p.y) < cfg_.guide.lookahead)
        ++index_;
      return plan_[index_];
    }
    if (task_ == "FollowVisitor" && visitor_) {
      if (f.still && !called_) {
        call_pub_.publish(std_msgs::Empty());
        called_ = true;
      }
      const double d = f.visitor_distance;
      if (d <= cfg_.guide.follow_distance) return std::nullopt;
      const double k = (d - cfg_.guide.follow_distance) / d;
      return Point2D{p.x + k * (visitor_->x - p.x), p.y + k * (visitor_->y - p.y)};
    }
    return std::nullopt;
  }

  void cycle(const ros::TimerEvent&) {
    if (!pose_) return;
    const double t = ros::Time::now().toSec();
    const TourFacts f = facts_.update(t, *pose_, visitor_, visitor_speed_);
    last_ = f;
    mrt_msgs::CrispDataArray w = map_crisp_;
    w.header.stamp = ros::Time::now();
    add(w, "PlanReady", plan_ready_ ? 1 : 0);
    add(w, "ExhibitDistance", f.exhibit_distance * 100.0);
    add(w, "VisitorLooked", f.looked);
    add(w, "VisitorReady", f.ready);
    add(w, "VisitorWandered", f.wandered);
    add(w, "VisitorBack", f.back);
    add(w, "VisitorLost", f.lost);
    world_pub_.publish(w);
    send_pending_job();
    publish_doors();
    if (!replan_at_.isZero() && ros::Time::now() >= replan_at_) {
      replan_at_ = ros::Time();
      if (task_ == "Guide") request_plan();  // a later leg is planned by its Replan task
    }

    mrt_msgs::CrispDataArray g;
    g.header.stamp = w.header.stamp;
    const auto point = done_ ? std::nullopt : goal(f);
    add(g, "Status", 1);
    add(g, "HaveGoal", point ? 1 : 0);
    if (point) {
      const double dx = point->x - pose_->x, dy = point->y - pose_->y;
      add(g, "GoalDistance", std::hypot(dx, dy) * 100.0);
      add(g, "GoalBearing", mrt::common::normalize_angle(std::atan2(dy, dx) - pose_->theta) * 180.0 / M_PI);
    }
    add(g, "RemoteSpeed", 0);
    add(g, "RemoteTurn", 0);
    if (f.visitor_seen) {  // MAP's track, with MAP's reliability; none: KeepVisitor stays out
      add(g, "VisitorDistance", f.visitor_distance * 100.0, visitor_reliability_);
      add(g, "VisitorAngle", f.visitor_bearing * 180.0 / M_PI, visitor_reliability_);
    }
    goal_pub_.publish(g);

    std_msgs::String st;
    char buf[256];
    std::snprintf(buf, sizeof buf, "t %.0f s | %s | next %s | visited %zu | wanders %zu", t,
                  done_ ? "Done" : (task_.empty() ? "-" : task_.c_str()),
                  current_ < tour_.size() ? tour_[current_].name.c_str() : "-", visited_.size(), wanders_);
    st.data = buf;
    if (st.data != last_status_) {
      status_pub_.publish(st);
      publish_progress(st.data);
    }
    last_status_ = st.data;
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
    for (std::size_t k = 0; k < tour_.size(); ++k) {
      const bool seen = k < visited_.size();
      text(static_cast<int>(k) + 1, tour_[k].stop.x, tour_[k].stop.y,
           std::to_string(k + 1) + (seen ? " visited" : (k == current_ ? " next" : "")));
    }
    markers_pub_.publish(a);
  }

  Options opt_;
  FollowMeConfig cfg_;
  TourFactsTracker facts_;
  TourFacts last_;
  std::vector<Exhibit> tour_;
  std::size_t current_ = 0, wanders_ = 0, index_ = 0, jobs_ = 0;
  std::vector<std::string> visited_;
  std::vector<Point2D> plan_;
  bool plan_ready_ = false, done_ = false, called_ = false;
  std::string task_, last_status_, pending_job_;
  int job_delay_ = 0;
  std::optional<Pose2D> pose_;
  std::optional<Point2D> visitor_;
  double visitor_speed_ = 0.0, visitor_reliability_ = 1.0;
  std::deque<std::pair<double, Point2D>> track_;
  mrt_msgs::CrispDataArray map_crisp_;
  ros::Time started_, replan_at_;
  std::vector<Door> closed_;
  ros::Subscriber pose_sub_, crisp_sub_, status_sub_, door_sub_;
  ros::Publisher odom_pub_, world_pub_, goal_pub_, job_pub_, plan_pub_, status_pub_, result_pub_, tour_pub_,
      call_pub_, markers_pub_, door_pub_;
  ros::ServiceClient planner_;
  ros::ServiceServer service_;
  ros::Timer timer_;
  std::unique_ptr<mrt::followme::ros_glue::TourMarkers> markers_;
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
