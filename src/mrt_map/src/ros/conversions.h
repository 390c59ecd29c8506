// mrt_msgs <-> mrt_map core types, and the rviz markers of a world model.
// Percepts come in through mrt_common_ros/percept_conversions.h; the team
// exchange is mrt_msgs/WorldModel (over DCDT the bridge's world_model kind
// carries it: the one DCDT encoding of the team world model).
#pragma once

#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/WorldModel.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

#include "mrt_map/world_model.h"

namespace mrt::map::node {

mrt_msgs::Anchor to_msg(const Anchor& a, const ConceptualModel& m, double reliability);
/// The own-sensors track sent to the teammates.
mrt_msgs::Anchor to_msg(const RemoteTrack& t, const ConceptualModel& m);

/// A teammate's anchor; false when its class is unknown here or a value is
/// not finite.
bool from_msg(const mrt_msgs::Anchor& a, const ConceptualModel& m, const ros::Time& stamp, RemoteTrack& out);

/// The team model: every anchor, fused (local_only false).
mrt_msgs::WorldModel to_msg(const WorldModel& w, const std::string& frame, const ros::Time& stamp);
/// The team exchange (local_only true): `tracks`, the caller's w.local_tracks().
mrt_msgs::WorldModel to_msg(const WorldModel& w, const std::vector<RemoteTrack>& tracks, const std::string& frame,
                            const ros::Time& stamp);

mrt_msgs::CrispDataArray to_msg(const std::vector<CrispDatum>& data, const ros::Time& stamp);

/// Ellipses (2 sigma), ids and velocity arrows of the confirmed and
/// coasting anchors; DELETEALL first so dropped anchors disappear.
visualization_msgs::MarkerArray markers(const WorldModel& w, const std::string& frame, const ros::Time& stamp);

}  // namespace mrt::map::node
