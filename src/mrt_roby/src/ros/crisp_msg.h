// Crisp data <-> mrt_msgs/CrispDataArray for the Roby nodes (private header).
#pragma once

#include <mrt_msgs/CrispDataArray.h>
#include <ros/time.h>

#include "mrt_brian/types.h"

namespace mrt::roby::node {

inline void append(const brian::CrispDataList& data, mrt_msgs::CrispDataArray& out) {
  for (const auto& c : data) {
    mrt_msgs::CrispData d;
    d.name = c.name;
    d.value = c.value;
    d.reliability = c.reliability;
    out.data.push_back(d);
  }
}

inline mrt_msgs::CrispDataArray to_msg(const brian::CrispDataList& data, const ros::Time& stamp) {
  mrt_msgs::CrispDataArray out;
  out.header.stamp = stamp;
  append(data, out);
  return out;
}

}  // namespace mrt::roby::node
