// sonar_crisp_node: the sonar belt as sector distances, merged with the
// SCARE goal and the previous commands into one Mr. BRIAN cycle's crisp data.
#include <diagnostic_updater/diagnostic_updater.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>
#include <sensor_msgs/Range.h>

#include <cmath>
#include <functional>

#include "mrt_scare/crisp_builder.h"
#include "mrt_scare/sonar_sectors.h"

namespace {

using namespace mrt::scare;

class SonarCrispNode {
 public:
  SonarCrispNode(ros::NodeHandle& nh, std::vector<double> mounts, double max_range, double rate,
                 double input_timeout, double stale_timeout)
      : sectors_(mounts, default_sectors(), max_range, stale_timeout), input_timeout_(input_timeout) {
    for (std::size_t i = 0; i < mounts.size(); ++i)
      subs_.push_back(nh.subscribe<sensor_msgs::Range>(
          "sonar/" + std::to_string(i), 5, std::bind(&SonarCrispNode::on_sonar, this, i, std::placeholders::_1)));
    subs_.push_back(nh.subscribe("goal_crisp", 5, &SonarCrispNode::on_goal, this));
    subs_.push_back(nh.subscribe("commands", 5, &SonarCrispNode::on_commands, this));
    pub_ = nh.advertise<mrt_msgs::CrispDataArray>("crisp_data", 10);
    for (const auto& s : sectors_.sectors()) names_.push_back(s.name);
    timer_ = nh.createTimer(ros::Duration(1.0 / rate), &SonarCrispNode::on_timer, this);
    diag_.setHardwareID("sonar belt");
    diag_.add("sonar sectors", this, &SonarCrispNode::diagnose);
  }

 private:
  void on_sonar(std::size_t i, const sensor_msgs::RangeConstPtr& r) {
    if (!sectors_.set_range(i, r->range, ros::Time::now().toSec())) {
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
    CrispInputs in;
    in.sector_names = names_;
    in.sector_distances = sectors_.distances(now.toSec());
    in.last_speed_cm = last_speed_;
    in.last_jog_deg = last_jog_;
    mrt_msgs::CrispDataArray out;
    out.header.stamp = now;
    for (const auto& c : build_crisp(in)) {
      // The sequencer's data (goal, Status, remote) come from goal_crisp.
      if (c.name.rfind("Obstacle", 0) != 0 && c.name != "FreeSide" && c.name.rfind("Last", 0) != 0) continue;
      mrt_msgs::CrispData d;
      d.name = c.name;
      d.value = c.value;
      d.reliability = c.reliability;
      out.data.push_back(d);
    }
    if ((now - goal_time_).toSec() < input_timeout_) {
      out.data.insert(out.data.end(), goal_.data.begin(), goal_.data.end());
    } else {
      // No sequencer: stand still (HaveGoal 0, Auto).
      mrt_msgs::CrispData d;
      d.name = "HaveGoal";
      d.value = 0.0;
      d.reliability = 1.0;
      out.data.push_back(d);
      d.name = "Status";
      d.value = 1.0;
      out.data.push_back(d);
    }
    pub_.publish(out);
    diag_.update();
  }

  SonarSectors sectors_;
  double input_timeout_;
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
  ros::NodeHandle nh, pnh("~");
  int count;
  double max_range, rate, input_timeout, stale_timeout;
  std::vector<double> mounts;
  pnh.param("sonar_count", count, 16);
  pnh.param("max_range", max_range, 5.0);
  pnh.param("rate", rate, 10.0);
  pnh.param("input_timeout", input_timeout, 0.5);
  pnh.param("stale_timeout", stale_timeout, 1.0);
  if (pnh.getParam("mounts_deg", mounts)) {
    if (mounts.empty()) {
      ROS_FATAL("bad parameter ~mounts_deg: empty list");
      return 1;
    }
  } else {
    if (count < 1 || count > 64) {
      ROS_FATAL("bad parameter ~sonar_count: must be in 1..64, got %d", count);
      return 1;
    }
    mounts = even_mounts_deg(static_cast<std::size_t>(count));
  }
  if (!(max_range > 0)) {
    ROS_FATAL("bad parameter ~max_range: must be > 0, got %g", max_range);
    return 1;
  }
  if (!(rate > 0 && rate <= 1000)) {
    ROS_FATAL("bad parameter ~rate: must be in (0, 1000], got %g", rate);
    return 1;
  }
  if (!(input_timeout > 0)) {
    ROS_FATAL("bad parameter ~input_timeout: must be > 0, got %g", input_timeout);
    return 1;
  }
  if (!(stale_timeout >= 0)) {
    ROS_FATAL("bad parameter ~stale_timeout: must be >= 0, got %g", stale_timeout);
    return 1;
  }
  SonarCrispNode node(nh, mounts, max_range, rate, input_timeout, stale_timeout);
  ros::spin();
  return 0;
}
