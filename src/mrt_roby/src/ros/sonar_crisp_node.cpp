// sonar_crisp_node: the sonar belt as sector distances and the previous
// commands, appended to the sequencer's crisp data (goal_crisp, as it comes)
// into one Mr. BRIAN cycle's crisp data. Wiring only.
#include <diagnostic_updater/diagnostic_updater.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>
#include <sensor_msgs/Range.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <functional>
#include <limits>

#include "crisp_msg.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common/angle.h"
#include "mrt_common_ros/params.h"
#include "mrt_roby/crisp_builder.h"
#include "mrt_roby/sonar_sectors.h"

namespace {

using namespace mrt::roby;
using namespace mrt::roby::node;

struct SonarCrispOptions {
  std::vector<double> mounts_deg;
  double max_range = 5.0, rate = 10.0, input_timeout = 0.5, stale_timeout = 1.0;
  std::string base_frame = "base_link";  // beam axes from tf: each Range's frame in this one

  static SonarCrispOptions read(mrt::ros_common::ParamReader& p) {
    SonarCrispOptions o;
    int count = 16;
    std::vector<double> mounts;  // rad (REP-103); the sectors' core takes degrees
    p.get("sonar_count", count)
        .get("mounts", mounts)
        .get_positive("max_range", o.max_range)
        .get_positive("rate", o.rate)
        .get_positive("input_timeout", o.input_timeout)
        .get_non_negative("stale_timeout", o.stale_timeout)
        .get("base_frame", o.base_frame);
    p.check(o.rate <= 1000, "rate", "a number in (0, 1000]");
    if (p.node_handle().hasParam("mounts")) {
      p.check(!mounts.empty(), "mounts", "a non-empty list of beam directions (rad)");
      for (double m : mounts) o.mounts_deg.push_back(mrt::common::rad_to_deg(m));
    } else {
      p.check(count >= 1 && count <= 64, "sonar_count", "an integer in 1..64");
      o.mounts_deg = even_mounts_deg(static_cast<std::size_t>(count));
    }
    return o;
  }
};

class SonarCrispNode {
 public:
  SonarCrispNode(ros::NodeHandle& nh, const SonarCrispOptions& o)
      : sectors_(o.mounts_deg, default_sectors(), o.max_range, o.stale_timeout),
        input_timeout_(o.input_timeout),
        base_frame_(o.base_frame),
        mount_frames_(o.mounts_deg.size()),
        tf_listener_(tf_buffer_) {
    for (std::size_t i = 0; i < o.mounts_deg.size(); ++i)
      subs_.push_back(nh.subscribe<sensor_msgs::Range>(
          "sonar/" + std::to_string(i), 5, std::bind(&SonarCrispNode::on_sonar, this, i, std::placeholders::_1)));
    subs_.push_back(nh.subscribe("goal_crisp", 5, &SonarCrispNode::on_goal, this));
    subs_.push_back(nh.subscribe("commands", 5, &SonarCrispNode::on_commands, this));
    pub_ = nh.advertise<mrt_msgs::CrispDataArray>("crisp_data", 10);
    for (const auto& s : sectors_.sectors()) names_.push_back(s.name);
    timer_ = nh.createTimer(ros::Duration(1.0 / o.rate), &SonarCrispNode::on_timer, this);
    diag_.setHardwareID("sonar belt");
    diag_.add("sonar sectors", this, &SonarCrispNode::diagnose);
  }

 private:
  // The beam axis of sonar i from tf (its Range's frame_id in ~base_frame:
  // the frame's x axis is the beam), looked up once per frame name; until
  // tf has it, the configured mount stays in force.
  void update_mount(std::size_t i, const std::string& frame) {
    if (frame.empty() || frame == mount_frames_[i]) return;
    try {
      const auto t = tf_buffer_.lookupTransform(base_frame_, frame, ros::Time(0));
      const double yaw = mrt::ros_common::quaternion_to_yaw(t.transform.rotation);
      if (sectors_.set_mount(i, yaw * 180.0 / M_PI)) {
        mount_frames_[i] = frame;
        ++mounts_from_tf_;
      }
    } catch (const tf2::TransformException& e) {
      ROS_DEBUG_THROTTLE(5, "no tf yet for sonar %zu's frame %s: %s", i, frame.c_str(), e.what());
    }
  }

  void on_sonar(std::size_t i, const sensor_msgs::RangeConstPtr& r) {
    update_mount(i, r->header.frame_id);
    const double sensor_max = r->max_range > 0.0 ? r->max_range : std::numeric_limits<double>::infinity();
    if (!sectors_.set_range(i, r->range, ros::Time::now().toSec(), sensor_max)) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "dropped a bad reading of sonar %zu (%d dropped)", i, dropped_);
      return;
    }
    have_sonar_ = true;
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const std::vector<std::size_t> stale = sectors_.stale(ros::Time::now().toSec());
    std::string which;
    for (std::size_t i : stale) which += (which.empty() ? "" : " ") + std::to_string(i);
    if (!have_sonar_)
      st.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "no sonar reading yet");
    else if (!stale.empty())
      st.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "silent sonars (their sectors read 0 m): " + which);
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "all sonars reporting");
    st.add("sonars", sectors_.sonar_count());
    st.add("stale sonars", stale.size());
    st.add("dropped readings", dropped_);
    st.add("beam axes from tf", mounts_from_tf_);
    const std::vector<double> d = sectors_.distances(ros::Time::now().toSec());
    for (std::size_t s = 0; s < d.size(); ++s) st.add(sectors_.sectors()[s].name + " (m)", d[s]);
  }

  void on_goal(const mrt_msgs::CrispDataArray& m) {
    goal_ = m;
    goal_time_ = ros::Time::now();
  }

  void on_commands(const mrt_msgs::CommandArray& m) {
    last_speed_ = last_jog_ = 0.0;  // an absent command is 0
    for (const auto& c : m.commands) {
      if (!std::isfinite(c.value)) continue;
      if (c.name == "Speed") last_speed_ = c.value;
      if (c.name == "Jog") last_jog_ = c.value;
    }
  }

  void on_timer(const ros::TimerEvent&) {
    if (!have_sonar_) return;
    const ros::Time now = ros::Time::now();
    // This node's data, then the sequencer's as they come; without a
    // sequencer, stand still (HaveGoal 0, Auto).
    CrispDataList own;
    sonar_crisp_data(names_, sectors_.distances(now.toSec()), own);
    feedback_crisp_data(last_speed_, last_jog_, own);
    const bool sequencer = (now - goal_time_).toSec() < input_timeout_;
    if (!sequencer) goal_crisp_data(Mode::kAuto, std::nullopt, own);
    mrt_msgs::CrispDataArray out = to_msg(own, now);
    if (sequencer) out.data.insert(out.data.end(), goal_.data.begin(), goal_.data.end());
    pub_.publish(out);
    diag_.update();
  }

  SonarSectors sectors_;
  double input_timeout_;
  std::string base_frame_;
  std::vector<std::string> mount_frames_;  // frame each sonar's axis was taken from ("" = configured)
  int mounts_from_tf_ = 0;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  std::vector<std::string> names_;
  mrt_msgs::CrispDataArray goal_;
  ros::Time goal_time_;
  double last_speed_ = 0.0, last_jog_ = 0.0;
  bool have_sonar_ = false;
  int dropped_ = 0;
  std::vector<ros::Subscriber> subs_;
  ros::Publisher pub_;
  ros::Timer timer_;
  diagnostic_updater::Updater diag_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sonar_crisp");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader params(pnh);
    SonarCrispNode node(nh, SonarCrispOptions::read(params));
    ros::spin();
    return 0;
  });
}
