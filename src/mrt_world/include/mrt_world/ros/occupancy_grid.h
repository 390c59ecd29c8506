// OccupancyMap <-> nav_msgs/OccupancyGrid (header-only, the ROS side of
// mrt_world): what world_node publishes, and the map a node takes from the
// `map` topic (use_map_topic, as amcl). The core's exports stay ROS-free:
// a node including this finds nav_msgs and mrt_common_ros itself.
#pragma once

#include <nav_msgs/OccupancyGrid.h>
#include <ros/time.h>

#include <cmath>
#include <string>

#include "mrt_common_ros/conversions.h"
#include "mrt_world/occupancy_map.h"

namespace mrt::world {

inline nav_msgs::OccupancyGrid to_msg(const OccupancyMap& m, const std::string& frame, const ros::Time& stamp) {
  nav_msgs::OccupancyGrid g;
  g.header.frame_id = frame;
  g.header.stamp = stamp;
  g.info.map_load_time = stamp;
  g.info.resolution = static_cast<float>(m.resolution);
  g.info.width = static_cast<std::uint32_t>(m.width);
  g.info.height = static_cast<std::uint32_t>(m.height);
  g.info.origin = mrt::ros_common::to_pose(m.origin);
  g.data = m.values();
  return g;
}

/// A map received on a topic: each value v in 0..100 is the occupancy v/100,
/// anything else unknown; map_server's default thresholds (occupied above
/// 0.65, free below 0.196) and the raw mode, so that to_msg() gives the same
/// values back. `name` stands for the file in error messages.
inline OccupancyMap from_msg(const nav_msgs::OccupancyGrid& g, const std::string& name) {
  OccupancyMap m;
  m.file = name;
  m.resolution = g.info.resolution;
  m.origin = mrt::ros_common::to_pose2d(g.info.origin);
  m.width = static_cast<int>(g.info.width);
  m.height = static_cast<int>(g.info.height);
  m.mode = OccupancyMap::Mode::kRaw;
  m.occupancy.resize(g.data.size());
  for (std::size_t i = 0; i < g.data.size(); ++i)
    m.occupancy[i] = g.data[i] >= 0 && g.data[i] <= 100 ? static_cast<float>(g.data[i]) / 100.0f : -1.0f;
  return m;
}

}  // namespace mrt::world
