// The SCARE sequencer node (wiring only): see include/mrt_scare/ros/sequencer_node.h.
#include "mrt_scare/ros/sequencer_node.h"

#include <cmath>

#include "mrt_common_ros/conversions.h"
#include "mrt_scare/task_config.h"

namespace mrt::scare {

namespace {

uint8_t state_code(SequencerState s) {
  switch (s) {
    case SequencerState::kIdle: return mrt_msgs::TaskStatus::IDLE;
    case SequencerState::kRunning: return mrt_msgs::TaskStatus::RUNNING;
    case SequencerState::kWaitingForPlan: return mrt_msgs::TaskStatus::WAITING_FOR_PLAN;
    case SequencerState::kDone: return mrt_msgs::TaskStatus::DONE;
    case SequencerState::kGaveUp:
    case SequencerState::kAborted:     // no own code in TaskStatus: the event
    case SequencerState::kHandedBack:  // (job_aborted, handed_back) tells which
      return mrt_msgs::TaskStatus::GAVE_UP;
  }
  return 0;
}

/// Distance (m) and bearing (rad) of a path point, for the task status.
void set_goal_geometry(const Pose2D& pose, const Point2D& goal, mrt_msgs::TaskStatus& s) {
  const GoalCrisp g = goal_crisp(pose, goal);
  s.distance = g.distance_cm / 100.0;
  s.bearing = g.bearing_deg * M_PI / 180.0;
}

}  // namespace

std::optional<Mode> parse_mode(const std::string& s) {
  if (s == "auto") return Mode::kAuto;
  if (s == "manual") return Mode::kManual;
  return std::nullopt;
}

SequencerNodeOptions SequencerNodeOptions::read(ros_common::ParamReader& p) {
  SequencerNodeOptions o;
  std::string mode = "auto";
  p.require("tasks", o.tasks, "the task YAML file")
      .get_positive("rate", o.rate)
      .get_non_negative("pose_timeout", o.pose_timeout)
      .get("frame", o.frame)
      .get("mode", mode);
  p.check(o.rate <= 1000, "rate", "a number in (0, 1000]");
  const std::optional<Mode> m = parse_mode(mode);
  p.check(m.has_value(), "mode", "auto or manual");
  o.mode = *m;
  return o;
}

SequencerNode::SequencerNode(ros::NodeHandle& nh, const SequencerNodeOptions& o, CycleHook hook)
    : seq_(load_sequencer_options(o.tasks)),
      pose_timeout_(o.pose_timeout),
      frame_(o.frame),
      hook_(std::move(hook)),
      diag_(nh, "sequencer", "scare", [this](diagnostic_updater::DiagnosticStatusWrapper& st) { diagnose(st); }) {
  diag_.input("pose", pose_timeout_ > 0 ? pose_timeout_ : 2.0);
  for (const char* c : {"path messages", "mode messages", "job messages", "world_crisp messages"})
    diag_.count(c, 0);  // shown from the start
  seq_.set_mode(o.mode, ros::Time::now().toSec());
  status_pub_ = nh.advertise<mrt_msgs::TaskStatus>("task_status", 50);
  replan_pub_ = nh.advertise<mrt_msgs::PlanRequest>("replan_request", 5);
  goal_pub_ = nh.advertise<geometry_msgs::PointStamped>("current_goal", 5, true);
  path_sub_ = nh.subscribe("path", 5, &SequencerNode::on_path, this);
  pose_sub_ = nh.subscribe("pose", 20, &SequencerNode::on_pose, this);
  mode_sub_ = nh.subscribe("mode", 5, &SequencerNode::on_mode, this);
  hand_back_pub_ = nh.advertise<std_msgs::String>("scare/hand_back", 5);
  job_sub_ = nh.subscribe("scare/job", 5, &SequencerNode::on_job, this);
  world_sub_ = nh.subscribe("world_crisp", 5, &SequencerNode::on_world, this);
  timer_ = nh.createTimer(ros::Duration(1.0 / o.rate), &SequencerNode::on_timer, this);
}

void SequencerNode::on_path(const nav_msgs::Path& p) {
  diag_.count("path messages");
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

void SequencerNode::apply_plan() {
  have_pending_ = false;
  ROS_INFO("new plan of %zu path points", pending_.size());
  handle(seq_.set_plan(pending_, ros::Time::now().toSec(), *pose_));
}

void SequencerNode::on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
  diag_.received("pose");
  const Pose2D p = ros_common::to_pose2d(m.pose.pose);
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta)) {
    ++dropped_;
    ROS_WARN_THROTTLE(5, "dropped a non-finite pose");
    return;
  }
  pose_ = p;
  pose_time_ = ros::Time::now();
  if (have_pending_) apply_plan();
  if (have_pending_job_) apply_job();
}

void SequencerNode::on_job(const std_msgs::String& j) {
  diag_.count("job messages");
  if (j.data == seq_.job() && !have_pending_job_ && seq_.state() == SequencerState::kRunning) return;
  // "" (no job, or waiting) stops a job, never a plan from the planner.
  if (j.data.empty() && seq_.job().empty() && !have_pending_job_) return;
  pending_job_ = j.data;
  if (!pending_job_.empty() && !seq_.knows_job(pending_job_)) {
    ++dropped_;
    ROS_WARN("job '%s' is not defined in the task file: stopping", pending_job_.c_str());
    pending_job_.clear();  // the robot must not go on with its previous job
  }
  have_pending_job_ = true;
  if (pose_) apply_job();
}

void SequencerNode::apply_job() {
  have_pending_job_ = false;
  ROS_INFO("job '%s'", pending_job_.c_str());
  handle(seq_.set_job(pending_job_, ros::Time::now().toSec(), *pose_));
}

void SequencerNode::on_world(const mrt_msgs::CrispDataArray& w) {
  diag_.count("world_crisp messages");
  CrispMap world;
  for (const auto& d : w.data) {
    if (d.name.empty() || !std::isfinite(d.value) || !std::isfinite(d.reliability) || d.reliability < 0.0 ||
        d.reliability > 1.0) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "dropped a malformed world crisp datum '%s'", d.name.c_str());
      continue;
    }
    world[d.name] = {d.value, d.reliability};
  }
  seq_.set_world(std::move(world));
}

void SequencerNode::on_mode(const std_msgs::String& m) {
  diag_.count("mode messages");
  const std::optional<Mode> mode = parse_mode(m.data);
  if (!mode) {
    ++dropped_;
    ROS_WARN_THROTTLE(5, "unknown mode '%s' (expected auto or manual)", m.data.c_str());
    return;
  }
  if (*mode != seq_.mode()) ROS_INFO("mode: %s", to_string(*mode));
  handle(seq_.set_mode(*mode, ros::Time::now().toSec()));
}

void SequencerNode::on_timer(const ros::TimerEvent&) {
  const ros::Time now = ros::Time::now();
  const bool pose_fresh = pose_ && (pose_timeout_ <= 0 || (now - pose_time_).toSec() < pose_timeout_);
  if (pose_fresh) handle(seq_.update(now.toSec(), *pose_));
  if (hook_) hook_(now, seq_, pose_fresh ? pose_ : std::nullopt);
  if (++ticks_ % 5 == 0) publish_status("");
}

void SequencerNode::handle(const std::vector<SequencerEvent>& events) {
  for (const auto& e : events) {
    ROS_INFO("%s #%zu (%.2f, %.2f) at (%.2f, %.2f)", to_string(e.type), e.index, e.point.x, e.point.y, e.pose.x,
             e.pose.y);
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
      r.reason = e.task + " " + (e.reason.empty() ? "timeout" : e.reason);
      replan_pub_.publish(r);
    }
    if (e.type == SequencerEvent::Type::kHandedBack) {
      std_msgs::String m;
      m.data = seq_.job().empty() ? e.task : seq_.job();
      hand_back_pub_.publish(m);
    }
    publish_status(to_string(e.type), &e);
  }
  if (!events.empty()) publish_goal();
}

void SequencerNode::publish_goal() {
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

void SequencerNode::publish_status(const std::string& event, const SequencerEvent* e) {
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
    if (pose_) set_goal_geometry(*pose_, t->goal(), s);
    s.elapsed = t->elapsed(now.toSec());
    s.timeout = seq_.active_timeout();
  }
  if (e && !e->task.empty() && e->type != SequencerEvent::Type::kJobAccepted) {
    // The event's own task, which may have ended already.
    s.task = e->task;
    s.index = static_cast<uint32_t>(e->index);
    s.goal_x = e->point.x;
    s.goal_y = e->point.y;
    set_goal_geometry(e->pose, e->point, s);
    s.elapsed = e->elapsed;
    s.timeout = e->timeout;
  }
  s.reached = static_cast<uint32_t>(seq_.reached());
  s.failed = static_cast<uint32_t>(seq_.failed());
  s.replans = static_cast<uint32_t>(seq_.replans());
  status_pub_.publish(s);
}

void SequencerNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
  const bool bad = seq_.state() == SequencerState::kGaveUp || !pose_;
  // After NodeDiagnostics' summary: the state when that is OK; a silent
  // pose (WARN) stays and gets the state's warning appended.
  const std::string what = !pose_ ? "no pose yet" : to_string(seq_.state());
  if (st.level == diagnostic_msgs::DiagnosticStatus::OK)
    st.summary(bad ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK, what);
  else if (bad)
    st.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, what);
  st.add("mode", to_string(seq_.mode()));
  st.add("job", seq_.job());
  st.add("plans", seq_.plans());
  st.add("reached", seq_.reached());
  st.add("failed", seq_.failed());
  st.add("replans", seq_.replans());
  st.add("dropped messages", dropped_);
}

}  // namespace mrt::scare
