// Team data over DCDT (README "Team data: MAP and SCARE over DCDT"): MAP's
// mrt_msgs/WorldModel and SCARE's mrt_msgs/CoordinationParameters <-> MRT
// XML messages, lossless (numbers bit-exact, every field carried).
#pragma once

#include <mrt_msgs/CoordinationParameters.h>
#include <mrt_msgs/RefereeCommand.h>
#include <mrt_msgs/WorldModel.h>

#include "mrt_dcdt/xml_message.h"

namespace mrt::dcdt::node {

/// One object of class "WorldModel" (the producer: local_only, pose and its
/// covariance), one of class "Anchor" per anchor (name = id), one of class
/// "CrispData" per coordination parameter. Throws XmlError for what XML
/// cannot carry (an empty source, non-finite numbers).
XmlMessage from_world_model(const mrt_msgs::WorldModel& w);
/// Throws XmlError when the document is not of that form (doc/formats.md).
mrt_msgs::WorldModel to_world_model(const XmlMessage& x);

/// One object of class "Coordination" (the sender), then "Slot" (per slot,
/// in order), "Activity" (per activity) and "Heard" (the gossip) objects.
XmlMessage from_coordination(const mrt_msgs::CoordinationParameters& c);
mrt_msgs::CoordinationParameters to_coordination(const XmlMessage& x);

/// The referee box (MSG_FROM_REFBOX, 28): one object of class
/// "RefereeCommand" named after the command (`name`) with `command`, `x`,
/// `y` and the optional symbols `team` and `reason`, then one "Score" object
/// per team (named after it, attribute `goals`), in `teams` order. Throws
/// XmlError for an empty name, a team name XML cannot carry or
/// `teams`/`score` of different lengths.
XmlMessage from_referee(const mrt_msgs::RefereeCommand& r);
mrt_msgs::RefereeCommand to_referee(const XmlMessage& x);

}  // namespace mrt::dcdt::node
