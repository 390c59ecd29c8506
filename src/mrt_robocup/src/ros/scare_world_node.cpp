// scare_world_node: SCARE's world data from the robot's MAP world model, for
// the distributed team (robot.launch). The activity file
// (config/scare/robocup_team.yaml) reads BallX, BallY, BallSeen, BallOwned,
// ShotClear, Threat, ReceiveX, ReceiveY; the in-process team session computes
// them with team_crisp() (team_crisp.h), and this node does the same on
// `world_model` (mrt_msgs/WorldModel), publishing `world_crisp`
// (mrt_msgs/CrispDataArray) for scare_coordinator at every model. BallOwned:
// the ball within ~own_reach of the robot's own pose or of a Teammate
// anchor (a teammate's kicker holds it). Diagnostics "SCARE world data":
// world_model expected every second, the arrays published, the anchors
// skipped (non-finite), the last BallOwned. The bringup's node: README "The
// RoboCup bringup".
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/WorldModel.h>
#include <ros/ros.h>

#include <cmath>

#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_robocup/team_crisp.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "scare_world");
  return mrt::ros_common::run_node([]() -> int {
    ros::NodeHandle nh, pnh("~");
    double reach = 0.25 + 0.11 + 0.08;  // body + ball + the Player's 8 cm (README "Crisp data")
    mrt::ros_common::ParamReader(pnh).get_positive("own_reach", reach);
    const mrt::robocup::SituationOptions situation;
    bool last_owned = false;
    mrt::ros_common::NodeDiagnostics diag(nh, "SCARE world data", "scare", [&](auto& st) {
      st.add("own reach (m)", reach);
      st.add("BallOwned (last)", last_owned);
    });
    diag.input("world_model", 1.0);  // MAP's model, ~rate 30 Hz
    diag.count("crisp arrays published", 0);
    diag.count("anchors skipped (non-finite)", 0);
    ros::Publisher pub = nh.advertise<mrt_msgs::CrispDataArray>("world_crisp", 5);
    ros::Subscriber sub = nh.subscribe<mrt_msgs::WorldModel>("world_model", 5, [&](const mrt_msgs::WorldModel::ConstPtr& m) {
      diag.received("world_model");
      std::vector<mrt::robocup::AnchorView> anchors;
      for (const mrt_msgs::Anchor& a : m->anchors) {
        if (std::isfinite(a.x) && std::isfinite(a.y))
          anchors.push_back({a.membership_class, a.x, a.y, a.vx, a.vy, a.reliability});
        else
          diag.count("anchors skipped (non-finite)");
      }
      bool owns = false;
      for (const auto& b : anchors) {
        if (b.membership_class != "Ball") continue;
        if (std::hypot(b.x - m->robot_x, b.y - m->robot_y) <= reach) owns = true;
        for (const auto& t : anchors)
          if (t.membership_class == "Teammate" && std::hypot(b.x - t.x, b.y - t.y) <= reach) owns = true;
      }
      mrt_msgs::CrispDataArray out;
      out.header = m->header;
      for (const auto& [name, v] : mrt::robocup::team_crisp(anchors, owns, situation)) {
        mrt_msgs::CrispData d;
        d.name = name;
        d.value = v.first;
        d.reliability = v.second;
        out.data.push_back(d);
      }
      pub.publish(out);
      last_owned = owns;
      diag.count("crisp arrays published");
    });
    ros::spin();
    return 0;
  });
}
