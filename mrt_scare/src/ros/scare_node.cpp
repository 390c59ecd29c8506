// scare_node: the SCARE sequencer as a node (wiring only). Plans in, the
// active path point out as Mr. BRIAN crisp data, task status, re-plan requests.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/PlanRequest.h>
#include <mrt_msgs/TaskStatus.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <cmath>
#include <optional>

#include "mrt_common/parse_error.h"
#include "mrt_scare/crisp_builder.h"
#include "mrt_scare/task_config.h"

namespace {

using namespace mrt::scare;

double yaw(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

std::optional<Mode> parse_mode(const std::string& s) {
  if (s == "auto") return Mode::kAuto;
  if (s == "manual") return Mode::kManual;
  return std::nullopt;
}

uint8_t state_code(SequencerState s) {
  switch (s) {
    case SequencerState::kIdle: return mrt_msgs::TaskStatus::IDLE;
    case SequencerState::kRunning: return mrt_msgs::TaskStatus::RUNNING;
    case SequencerState::kWaitingForPlan: return mrt_msgs::TaskStatus::WAITING_FOR_PLAN;
    case SequencerState::kDone: return mrt_msgs::TaskStatus::DONE;
    case SequencerState::kGaveUp: return mrt_msgs::TaskStatus::GAVE_UP;
  }
  return 0;
}

class ScareNode {
 public:
  ScareNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, SequencerOptions options, Mode mode, double rate,
            double remote_timeout, double pose_timeout, const std::string& frame)
      : seq_(std::move(options)), remote_timeout_(remote_timeout), pose_timeout_(pose_timeout),
        frame_(frame) {
    seq_.set_mode(mode, ros::Time::now().toSec());
    crisp_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("goal_crisp", 10);
    status_pub_ = nh.advertise<mrt_msgs::TaskStatus>("task_status", 50);
    replan_pub_ = nh.advertise<mrt_msgs::PlanRequest>("replan_request", 5);
    goal_pub_ = nh.advertise<geometry_msgs::PointStamped>("current_goal", 5, true);
    path_sub_ = nh.subscribe("path", 5, &ScareNode::on_path, this);
    pose_sub_ = nh.subscribe("pose", 20, &ScareNode::on_pose, this);
    mode_sub_ = nh.subscribe("mode", 5, &ScareNode::on_mode, this);
    remote_sub_ = nh.subscribe("remote_cmd", 10, &ScareNode::on_remote, this);
    timer_ = nh.createTimer(ros::Duration(1.0 / rate), &ScareNode::on_timer, this);
    diag_.setHardwareID("scare");
    diag_.add("sequencer", this, &ScareNode::diagnose);
    (void)pnh;
  }

 private:
  void on_path(const nav_msgs::Path& p) {
    pending_.clear();
    for (const auto& ps : p.poses) {
      if (!std::isfinite(ps.pose.position.x) || !std::isfinite(ps.pose.position.y)) {
        ++dropped_;
        ROS_WARN_THROTTLE(5, "dropped a path with a non-finite point");
        return;
      }
      pending_.push_back({ps.pose.position.x, ps.pose.position.y});
    }
    have_pending_ = true;
    if (pose_) apply_plan();
  }

  void apply_plan() {
    have_pending_ = false;
    ROS_INFO("new plan of %zu path points", pending_.size());
    handle(seq_.set_plan(pending_, ros::Time::now().toSec(), *pose_));
  }

  void on_pose(const nav_msgs::Odometry& o) {
    const auto& p = o.pose.pose;
    if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y) || !std::isfinite(yaw(p.orientation))) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "dropped a non-finite pose");
      return;
    }
    pose_ = Pose2D(p.position.x, p.position.y, yaw(p.orientation));
    pose_time_ = ros::Time::now();
    if (have_pending_) apply_plan();
  }

  void on_mode(const std_msgs::String& m) {
    const std::optional<Mode> mode = parse_mode(m.data);
    if (!mode) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "unknown mode '%s' (expected auto or manual)", m.data.c_str());
      return;
    }
    if (*mode != seq_.mode()) ROS_INFO("mode: %s", to_string(*mode));
    handle(seq_.set_mode(*mode, ros::Time::now().toSec()));
  }

  void on_remote(const geometry_msgs::Twist& t) {
    if (!std::isfinite(t.linear.x) || !std::isfinite(t.angular.z)) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "dropped a non-finite remote command");
      return;
    }
    remote_ = RemoteCommand{t.linear.x, t.angular.z};
    remote_time_ = ros::Time::now();
  }

  void on_timer(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    const bool pose_fresh = pose_ && (pose_timeout_ <= 0 || (now - pose_time_).toSec() < pose_timeout_);
    if (pose_fresh) handle(seq_.update(now.toSec(), *pose_));
    CrispInputs in;
    in.mode = seq_.mode();
    if (pose_fresh && seq_.active()) in.goal = goal_crisp(*pose_, seq_.active()->goal());
    if (remote_ && (now - remote_time_).toSec() < remote_timeout_) in.remote = remote_;
    mrt_msgs::CrispDataArray msg;
    msg.header.stamp = now;
    for (const auto& c : build_crisp(in)) {
      if (c.name.rfind("Last", 0) == 0) continue;  // the sonar adapter adds the feedback
      mrt_msgs::CrispData d;
      d.name = c.name;
      d.value = c.value;
      d.reliability = c.reliability;
      msg.data.push_back(d);
    }
    crisp_pub_.publish(msg);
    if (++ticks_ % 5 == 0) publish_status("");
    diag_.update();
  }

  void handle(const std::vector<SequencerEvent>& events) {
    for (const auto& e : events) {
      ROS_INFO("%s #%zu (%.2f, %.2f) at (%.2f, %.2f)", to_string(e.type), e.index, e.point.x, e.point.y,
               e.pose.x, e.pose.y);
      if (e.type == SequencerEvent::Type::kReplanRequested) {
        mrt_msgs::PlanRequest r;
        r.header.stamp = ros::Time::now();
        r.header.frame_id = frame_;
        r.x = e.pose.x;
        r.y = e.pose.y;
        r.theta = e.pose.theta;
        r.failed_index = static_cast<uint32_t>(e.index);
        r.failed_x = e.point.x;
        r.failed_y = e.point.y;
        r.reason = seq_.options().path_task.name + " timeout";
        replan_pub_.publish(r);
      }
      publish_status(to_string(e.type), &e);
    }
    if (!events.empty()) {
      geometry_msgs::PointStamped g;
      g.header.stamp = ros::Time::now();
      g.header.frame_id = frame_;
      if (seq_.active()) {
        g.point.x = seq_.active()->goal().x;
        g.point.y = seq_.active()->goal().y;
      } else {
        g.point.z = -100.0;  // no active path point: out of sight
      }
      goal_pub_.publish(g);
    }
  }

  void publish_status(const std::string& event, const SequencerEvent* e = nullptr) {
    mrt_msgs::TaskStatus s;
    const ros::Time now = ros::Time::now();
    s.header.stamp = now;
    s.header.frame_id = frame_;
    s.state = state_code(seq_.state());
    s.mode = to_string(seq_.mode());
    s.event = event;
    s.plan_size = static_cast<uint32_t>(seq_.plan().size());
    if (const Task* t = seq_.active()) {
      s.task = t->spec().name;
      s.index = static_cast<uint32_t>(t->index());
      s.goal_x = t->goal().x;
      s.goal_y = t->goal().y;
      if (pose_) {
        const GoalCrisp g = goal_crisp(*pose_, t->goal());
        s.distance = g.distance_cm / 100.0;
        s.bearing = g.bearing_deg * M_PI / 180.0;
      }
      s.elapsed = t->elapsed(now.toSec());
      s.timeout = t->timeout();
    }
    if (e && e->type != SequencerEvent::Type::kPlanAccepted && e->type != SequencerEvent::Type::kModeChanged) {
      // The event's own task, which may have ended already.
      s.task = seq_.options().path_task.name;
      s.index = static_cast<uint32_t>(e->index);
      s.goal_x = e->point.x;
      s.goal_y = e->point.y;
      const GoalCrisp g = goal_crisp(e->pose, e->point);
      s.distance = g.distance_cm / 100.0;
      s.bearing = g.bearing_deg * M_PI / 180.0;
      s.elapsed = e->elapsed;
      s.timeout = e->timeout;
    }
    s.reached = static_cast<uint32_t>(seq_.reached());
    s.failed = static_cast<uint32_t>(seq_.failed());
    s.replans = static_cast<uint32_t>(seq_.replans());
    status_pub_.publish(s);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const bool bad = seq_.state() == SequencerState::kGaveUp || !pose_;
    st.summary(bad ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK,
               !pose_ ? "no pose yet" : to_string(seq_.state()));
    st.add("mode", to_string(seq_.mode()));
    st.add("plans", seq_.plans());
    st.add("reached", seq_.reached());
    st.add("failed", seq_.failed());
    st.add("replans", seq_.replans());
    st.add("dropped messages", dropped_);
  }

  Sequencer seq_;
  double remote_timeout_, pose_timeout_;
  std::string frame_;
  std::optional<Pose2D> pose_;
  ros::Time pose_time_;
  std::optional<RemoteCommand> remote_;
  ros::Time remote_time_;
  std::vector<Point2D> pending_;
  bool have_pending_ = false;
  std::size_t dropped_ = 0;
  unsigned ticks_ = 0;
  ros::Publisher crisp_pub_, status_pub_, replan_pub_, goal_pub_;
  ros::Subscriber path_sub_, pose_sub_, mode_sub_, remote_sub_;
  ros::Timer timer_;
  diagnostic_updater::Updater diag_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "scare");
  ros::NodeHandle nh, pnh("~");
  std::string tasks, frame, mode;
  double rate, remote_timeout, pose_timeout;
  if (!pnh.getParam("tasks", tasks)) {
    ROS_FATAL("missing parameter ~tasks (the task YAML file)");
    return 1;
  }
  pnh.param("rate", rate, 10.0);
  pnh.param("remote_timeout", remote_timeout, 0.5);
  pnh.param("pose_timeout", pose_timeout, 2.0);
  pnh.param<std::string>("frame", frame, "world");
  pnh.param<std::string>("mode", mode, "auto");
  const std::optional<Mode> initial_mode = parse_mode(mode);
  if (!initial_mode) {
    ROS_FATAL("bad parameter ~mode: expected auto or manual, got '%s'", mode.c_str());
    return 1;
  }
  if (!(rate > 0 && rate <= 1000)) {
    ROS_FATAL("bad parameter ~rate: must be in (0, 1000], got %g", rate);
    return 1;
  }
  if (!(remote_timeout > 0)) {
    ROS_FATAL("bad parameter ~remote_timeout: must be > 0, got %g", remote_timeout);
    return 1;
  }
  if (!(pose_timeout >= 0)) {
    ROS_FATAL("bad parameter ~pose_timeout: must be >= 0, got %g", pose_timeout);
    return 1;
  }
  SequencerOptions options;
  try {
    options = load_sequencer_options(tasks);
  } catch (const mrt::common::ParseError& e) {
    ROS_FATAL("%s", e.what());
    return 2;
  }
  ScareNode node(nh, pnh, options, *initial_mode, rate, remote_timeout, pose_timeout, frame);
  ros::spin();
  return 0;
}
