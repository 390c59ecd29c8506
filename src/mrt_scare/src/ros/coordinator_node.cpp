// scare_coordinator: SCARE's coordination sub-module on one robot (wiring
// only; the protocol and the allocation are mrt_scare's Coordinator). Every
// 1 / ~rate s it publishes its parameters and intention on the team topic,
// allocates the team from what it heard, and publishes its job (to the
// sequencer) and the coordination crisp data (to Mr. BRIAN / MAP).
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <mrt_msgs/CoordinationParameters.h>
#include <mrt_msgs/CrispDataArray.h>
#include <nav_msgs/GetPlan.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>

#include <ros/callback_queue.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_scare/coordinator.h"
#include "mrt_scare/path_cost.h"

namespace mrt::scare::node {

struct CoordinatorNodeOptions {
  std::string activities;           // ~activities (required)
  std::string robot_id;             // ~robot_id (required)
  double rate = 10.0;               // ~rate, Hz
  std::string frame = "map";        // ~frame of the poses and targets (REP-105)
  std::string team_topic = "/scare/team";
  CoordinatorOptions coordination;  // ~grace, ~drop_timeout, ~min_confidence, ~listen, ~max_time_rate
  std::string cost = "straight_line";  // ~cost: straight_line | planner
  std::string plan_service = "make_plan";  // ~plan_service (nav_msgs/GetPlan, SPIKE's)
  PlannerCostOptions planner;       // ~plan_resolution, ~plan_max_age

  static CoordinatorNodeOptions read(ros_common::ParamReader& p) {
    CoordinatorNodeOptions o;
    p.require("activities", o.activities, "the activity YAML file")
        .require("robot_id", o.robot_id, "this robot's id")
        .get_positive("rate", o.rate)
        .get("frame", o.frame)
        .get("team_topic", o.team_topic)
        .get_non_negative("grace", o.coordination.grace)
        .get_positive("drop_timeout", o.coordination.drop_timeout)
        .get_positive("min_confidence", o.coordination.min_confidence)
        .get_non_negative("listen", o.coordination.listen)
        .get_non_negative("hand_back_penalty", o.coordination.hand_back_penalty)
        .get_non_negative("max_time_rate", o.coordination.max_time_rate)
        .get("cost", o.cost)
        .get("plan_service", o.plan_service)
        .get_positive("plan_resolution", o.planner.resolution)
        .get_positive("plan_max_age", o.planner.max_age);
    p.check(o.cost == "straight_line" || o.cost == "planner", "cost", "straight_line or planner");
    p.check(!o.plan_service.empty(), "plan_service", "a non-empty service name");
    p.check(!o.robot_id.empty(), "robot_id", "a non-empty string");
    p.check(o.rate <= 1000, "rate", "a number in (0, 1000]");
    p.check(o.coordination.grace < o.coordination.drop_timeout, "grace", "a number < ~drop_timeout");
    p.check(o.coordination.min_confidence <= 1.0, "min_confidence", "a number in (0, 1]");
    return o;
  }
};

class CoordinatorNode {
 public:
  CoordinatorNode(ros::NodeHandle& nh, const CoordinatorNodeOptions& o)
      : frame_(o.frame),
        planner_(o.cost == "planner" ? std::make_shared<PlannerCost>(o.planner) : nullptr),
        coord_(make(o, planner_)),
        slots_(coord_.set().slots()) {
    team_pub_ = nh.advertise<mrt_msgs::CoordinationParameters>(o.team_topic, 20);
    crisp_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("scare/crisp", 5);
    job_pub_ = nh.advertise<std_msgs::String>("scare/job", 5, true);
    team_sub_ = nh.subscribe(o.team_topic, 50, &CoordinatorNode::on_team, this);
    pose_sub_ = nh.subscribe("pose", 10, &CoordinatorNode::on_pose, this);
    world_sub_ = nh.subscribe("world_crisp", 10, &CoordinatorNode::on_world, this);
    enable_sub_ = nh.subscribe("scare/enable", 5, &CoordinatorNode::on_enable, this);
    hand_back_sub_ = nh.subscribe("scare/hand_back", 5, &CoordinatorNode::on_hand_back, this);
    timer_ = nh.createTimer(ros::Duration(1.0 / o.rate), &CoordinatorNode::on_timer, this);
    diag_.setHardwareID("scare_coordinator/" + o.robot_id);
    diag_.add("coordination", this, &CoordinatorNode::diagnose);
    if (planner_) {
      plan_client_ = nh.serviceClient<nav_msgs::GetPlan>(o.plan_service);
      plan_thread_ = std::thread([this] { plan_loop(); });
    }
  }

  ~CoordinatorNode() {
    stop_ = true;
    if (plan_thread_.joinable()) plan_thread_.join();
  }

  /// The leaving message, so teammates re-assign at once.
  void leave() {
    mrt_msgs::CoordinationParameters m;
    m.header.stamp = ros::Time::now();
    m.robot_id = coord_.id();
    m.leaving = true;
    team_pub_.publish(m);
  }

 private:
  static Coordinator make(const CoordinatorNodeOptions& o, std::shared_ptr<const CostModel> cost) {
    ActivitySet set = load_activities(o.activities);
    RobotSpec self = set.robot_or_default(o.robot_id);
    return Coordinator(std::move(set), std::move(self), o.coordination, std::move(cost));
  }

  // ~cost planner: asks the planner's GetPlan service (SPIKE's make_plan)
  // for the targets PlannerCost queues, one at a time, off the cycle.
  void plan_loop() {
    while (!stop_ && ros::ok()) {
      const double now = ros::Time::now().toSec();
      const auto q = planner_->next_query(now);
      if (!q) {
        ros::WallDuration(0.02).sleep();
        continue;
      }
      nav_msgs::GetPlan srv;
      srv.request.start.header.frame_id = srv.request.goal.header.frame_id = frame_;
      srv.request.start.header.stamp = srv.request.goal.header.stamp = ros::Time(now);
      srv.request.start.pose = ros_common::to_pose(q->first);
      srv.request.goal.pose.position.x = q->second.x;
      srv.request.goal.pose.position.y = q->second.y;
      srv.request.goal.pose.orientation.w = 1.0;
      if (!plan_client_.call(srv)) {  // no planner (yet): straight lines meanwhile
        ++plan_failures_;
        ROS_WARN_THROTTLE(10, "scare_coordinator: planner service %s did not answer; straight-line times",
                          plan_client_.getService().c_str());
        ros::WallDuration(0.5).sleep();
        continue;
      }
      std::optional<double> length;
      const auto& poses = srv.response.plan.poses;
      if (!poses.empty()) {
        double len = 0.0, x = q->first.x, y = q->first.y;
        for (const auto& p : poses) {
          len += std::hypot(p.pose.position.x - x, p.pose.position.y - y);
          x = p.pose.position.x;
          y = p.pose.position.y;
        }
        length = len;
      }
      planner_->record(q->first, q->second, length, now);
      ++plans_;
    }
  }

  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const Pose2D p = ros_common::to_pose2d(m.pose.pose);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return drop("a pose with non-finite values");
    pose_ = p;
  }

  void on_world(const mrt_msgs::CrispDataArray& m) {
    CrispMap c;
    for (const auto& d : m.data) {
      if (!std::isfinite(d.value) || !(d.reliability >= 0.0 && d.reliability <= 1.0))
        return drop("crisp data with a non-finite value or a reliability outside [0, 1]");
      c[d.name] = {d.value, d.reliability};
    }
    world_ = std::move(c);
  }

  void on_enable(const std_msgs::Bool& m) { enabled_ = m.data; }

  /// The sequencer could not carry the job out: re-allocate it.
  void on_hand_back(const std_msgs::String& m) {
    if (!coord_.hand_back(m.data, ros::Time::now().toSec())) return drop("a hand-back of an unknown slot");
    ROS_INFO("scare_coordinator: job '%s' handed back", m.data.c_str());
    ++hand_backs_;
  }

  void on_team(const mrt_msgs::CoordinationParameters& m) {
    if (!enabled_) return;
    if (m.robot_id == coord_.id()) return;  // our own message, looped back
    CoordinationMessage c;
    c.robot_id = m.robot_id;
    c.seq = m.seq;
    c.stamp = m.header.stamp.toSec();
    c.leaving = m.leaving;
    c.x = m.x;
    c.y = m.y;
    c.intention = m.intention.empty() ? -1 : coord_.set().find_slot(m.intention);
    // Unknown (0, e.g. from a relay that does not carry it): no dwell.
    c.held = m.intention_since > 0.0 ? std::max(0.0, c.stamp - m.intention_since)
                                     : std::numeric_limits<double>::infinity();
    bool ok = c.leaving || ((m.intention.empty() || c.intention >= 0) && m.slots.size() == slots_.size() &&
                            m.activities.size() == coord_.set().activities.size());
    for (std::size_t i = 0; ok && !c.leaving && i < slots_.size(); ++i)
      ok = m.slots[i] == coord_.set().slot_name(slots_[i]);
    for (std::size_t a = 0; ok && !c.leaving && a < m.activities.size(); ++a)
      ok = m.activities[a] == coord_.set().activities[a].name;
    c.attitude = m.attitude;
    c.opportunity = m.opportunity;
    for (double t : m.time) c.time.push_back(t < 0.0 ? std::numeric_limits<double>::infinity() : t);
    ok = ok && m.heard_ids.size() == m.heard_stamps.size();
    for (std::size_t i = 0; ok && i < m.heard_ids.size(); ++i) c.heard.emplace_back(m.heard_ids[i], m.heard_stamps[i]);
    if (!ok || !coord_.receive(c)) drop("a team message that does not match the activity file");
  }

  void on_timer(const ros::TimerEvent&) {
    if (!enabled_ || !pose_) return;
    const ros::Time now = ros::Time::now();
    if (planner_) planner_->set_time(now.toSec());
    const CoordinationMessage c = coord_.publish(now.toSec(), *pose_, world_);
    mrt_msgs::CoordinationParameters m;
    m.header.stamp = now;
    m.header.frame_id = frame_;
    m.robot_id = c.robot_id;
    m.seq = c.seq;
    m.x = c.x;
    m.y = c.y;
    m.intention = c.intention >= 0 ? coord_.set().slot_name(slots_[static_cast<std::size_t>(c.intention)]) : "";
    m.intention_since = std::isfinite(c.held) ? now.toSec() - c.held : 0.0;
    for (const Slot& s : slots_) m.slots.push_back(coord_.set().slot_name(s));
    for (const auto& a : coord_.set().activities) m.activities.push_back(a.name);
    m.attitude = c.attitude;
    for (double t : c.time) m.time.push_back(std::isfinite(t) ? t : -1.0);
    m.opportunity = c.opportunity;
    for (const auto& [id, stamp] : c.heard) {
      m.heard_ids.push_back(id);
      m.heard_stamps.push_back(stamp);
    }
    team_pub_.publish(m);
    coord_.step(now.toSec());
    publish_outputs(now);
    diag_.update();
  }

  void publish_outputs(const ros::Time& now) {
    mrt_msgs::CrispDataArray crisp;
    crisp.header.stamp = now;
    for (const CrispOut& o : coord_.crisp_output()) {
      mrt_msgs::CrispData d;
      d.name = o.name;
      d.value = o.value;
      d.reliability = o.reliability;
      crisp.data.push_back(d);
    }
    crisp_pub_.publish(crisp);
    const int s = coord_.own_slot();
    const std::string job = s >= 0 ? coord_.set().slot_name(slots_[static_cast<std::size_t>(s)]) : "";
    if (job != job_ || !job_published_) {
      std_msgs::String j;
      j.data = job;
      job_pub_.publish(j);
      job_ = job;
      job_published_ = true;
      ++changes_;
    }
  }

  void drop(const char* what) {
    ++dropped_;
    ROS_WARN_THROTTLE(5, "scare_coordinator: dropped %s", what);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    st.summary(enabled_ ? diagnostic_msgs::DiagnosticStatus::OK : diagnostic_msgs::DiagnosticStatus::WARN,
               enabled_ ? "coordinating" : "disabled");
    st.add("job", job_);
    st.add("team size", coord_.team_size());
    st.add("teammates dropped", coord_.drops());
    st.add("job changes", changes_);
    st.add("hand-backs", hand_backs_);
    st.add("dropped messages", dropped_);
    if (planner_) {
      st.add("plans", plans_.load());
      st.add("planner failures", plan_failures_.load());
    }
  }

  std::string frame_;
  std::shared_ptr<PlannerCost> planner_;  // ~cost planner, else null
  Coordinator coord_;
  std::vector<Slot> slots_;
  std::optional<Pose2D> pose_;
  CrispMap world_;
  bool enabled_ = true;
  std::string job_;
  bool job_published_ = false;
  std::size_t dropped_ = 0, changes_ = 0, hand_backs_ = 0;
  ros::Publisher team_pub_, crisp_pub_, job_pub_;
  ros::Subscriber team_sub_, pose_sub_, world_sub_, enable_sub_, hand_back_sub_;
  ros::Timer timer_;
  diagnostic_updater::Updater diag_;
  ros::ServiceClient plan_client_;
  std::thread plan_thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> plans_{0}, plan_failures_{0};
};

}  // namespace mrt::scare::node

namespace {
volatile std::sig_atomic_t g_stop = 0;
}  // namespace

int main(int argc, char** argv) {
  // Our own SIGINT handler: the leaving message goes out before shutdown.
  ros::init(argc, argv, "scare_coordinator", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, [](int) { g_stop = 1; });
  std::signal(SIGTERM, [](int) { g_stop = 1; });
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader params(pnh);
    mrt::scare::node::CoordinatorNode node(nh, mrt::scare::node::CoordinatorNodeOptions::read(params));
    while (ros::ok() && !g_stop) ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
    node.leave();
    ros::WallDuration(0.1).sleep();
    ros::shutdown();
    return 0;
  });
}
