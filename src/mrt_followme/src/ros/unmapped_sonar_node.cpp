// unmapped_sonar_node: the sonar belt as FollowMe's Mr. BRIAN needs it in
// the museum (unmapped_echo.h): every reading the map explains from
// MUREA's pose becomes "no echo" (max_range), the rest (people, anything
// nearer than 0.3 m) passes. Subscribes sonar/<i> and pose, publishes
// unmapped/sonar/<i>, which Roby's sonar_crisp_node (started in the
// namespace unmapped) turns into sector distances.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/Range.h>

#include <optional>
#include <string>
#include <vector>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_followme/unmapped_echo.h"
#include "mrt_sim/world.h"

namespace {

class UnmappedSonar {
 public:
  UnmappedSonar(ros::NodeHandle& nh, ros::NodeHandle& pnh) : diag_(nh, "unmapped sonar", "sonar belt") {
    mrt::ros_common::ParamReader p(pnh);
    std::string world, robot = "robot1";
    p.require("world", world, "the museum's mrt_sim world file (its walls and posts: the map)").get("robot", robot);
    known_ = mrt::sim::load_world(world);
    known_.movers.clear();
    known_.ball.enabled = false;
    for (const auto& rc : known_.robots)
      if (rc.name == robot) sonars_ = rc.sensors.sonars;
    if (sonars_.empty()) throw mrt::ros_common::ParamError("robot", "a robot of ~world with sonars");
    pose_sub_ = nh.subscribe("pose", 5, &UnmappedSonar::on_pose, this);
    diag_.input("pose", 2.0);
    diag_.input("sonar", 1.0);
    for (std::size_t i = 0; i < sonars_.size(); ++i) {
      pubs_.push_back(nh.advertise<sensor_msgs::Range>("unmapped/sonar/" + std::to_string(i), 5));
      subs_.push_back(nh.subscribe<sensor_msgs::Range>(
          "sonar/" + std::to_string(i), 5, [this, i](const sensor_msgs::Range::ConstPtr& m) { on_range(i, *m); }));
    }
  }

 private:
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    pose_ = mrt::ros_common::to_pose2d(m.pose.pose);
    diag_.received("pose");
  }

  void on_range(std::size_t i, const sensor_msgs::Range& m) {
    diag_.received("sonar");
    sensor_msgs::Range out = m;
    if (!pose_) diag_.count("ranges passed on unfiltered (no pose yet)");
    if (pose_) out.range = static_cast<float>(mrt::followme::unmapped_range(known_, *pose_, sonars_[i], m.range));
    pubs_[i].publish(out);
  }

  mrt::sim::World known_;
  std::vector<mrt::sim::SonarConfig> sonars_;
  std::optional<mrt::common::Pose2D> pose_;
  ros::Subscriber pose_sub_;
  std::vector<ros::Subscriber> subs_;
  std::vector<ros::Publisher> pubs_;
  mrt::ros_common::NodeDiagnostics diag_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "unmapped_sonar");
  ros::NodeHandle nh, pnh("~");
  return mrt::ros_common::run_node([&] {
    UnmappedSonar node(nh, pnh);
    ros::spin();
    return 0;
  });
}
