// world_node: publishes a world file or a map_server map as the
// navigation stack's map (nav_msgs/OccupancyGrid on `map`, latched,
// `map_metadata`, and the `static_map` service), as map_server does.
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_world/occupancy_map.h"
#include "mrt_world/ros/occupancy_grid.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "world_node");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    std::string file, frame = "map";
    double resolution = 0.05;
    mrt::ros_common::ParamReader(pnh)
        .require("map", file, "a world file or map_server YAML")
        .get("frame_id", frame)
        .get_positive("resolution", resolution);
    const nav_msgs::OccupancyGrid grid =
        mrt::world::to_msg(mrt::world::load_map_grid(file, resolution), frame, ros::Time::now());
    ros::Publisher map_pub = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    ros::Publisher meta_pub = nh.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
    map_pub.publish(grid);
    meta_pub.publish(grid.info);
    ros::ServiceServer static_map = nh.advertiseService<nav_msgs::GetMap::Request, nav_msgs::GetMap::Response>(
        "static_map", [&grid](nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
          res.map = grid;
          return true;
        });
    mrt::ros_common::NodeDiagnostics diag(nh, "map server", "world_node", [&](auto& st) {
      st.add("map", file);
      st.add("cells", std::to_string(grid.info.width) + " x " + std::to_string(grid.info.height));
      st.add("resolution (m)", grid.info.resolution);
      st.add("frame", frame);
    });
    ROS_INFO("world_node: %s as a %u x %u map of %.3f m in '%s'", file.c_str(), grid.info.width, grid.info.height,
             grid.info.resolution, frame.c_str());
    ros::spin();
    return 0;
  });
}
