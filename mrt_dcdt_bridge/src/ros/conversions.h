// mrt_msgs <-> MRT XML message conversions for the bridge node (lossless for
// every field the XML carries; header.seq is not carried).
#pragma once

#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/Percept.h>

#include "mrt_dcdt_bridge/xml_message.h"

namespace mrt::dcdt::ros_conv {

XmlMessage FromPercept(const mrt_msgs::Percept& p);
mrt_msgs::Percept ToPercept(const XmlMessage& x);

/// CrispData -> objects of class "CrispData" with one attribute "value"
/// (value, reliability).
XmlMessage FromCrispData(const mrt_msgs::CrispDataArray& c);
/// Throws XmlError when an object is not of that form.
mrt_msgs::CrispDataArray ToCrispData(const XmlMessage& x);

/// Command -> objects of class "Command" with one attribute "value".
XmlMessage FromCommands(const mrt_msgs::CommandArray& c);
mrt_msgs::CommandArray ToCommands(const XmlMessage& x);

}  // namespace mrt::dcdt::ros_conv
