// mrt_msgs <-> MRT XML message conversions for the bridge node (lossless for
// every field the XML carries; header.seq is not carried).
#pragma once

#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/Percept.h>

#include "mrt_dcdt/xml_message.h"

namespace mrt::dcdt::node {

/// The header's stamp and frame into the XML message's time and frame.
void stamp_to(const std_msgs::Header& h, XmlMessage* x);
/// Back; ROS time is unsigned 32-bit seconds: anything else throws
/// XmlError, it is not wrapped.
void stamp_from(const XmlMessage& x, std_msgs::Header* h);

XmlMessage from_percept(const mrt_msgs::Percept& p);
mrt_msgs::Percept to_percept(const XmlMessage& x);

/// CrispData -> objects of class "CrispData" with one attribute "value"
/// (value, reliability).
XmlMessage from_crisp_data(const mrt_msgs::CrispDataArray& c);
/// Throws XmlError when an object is not of that form.
mrt_msgs::CrispDataArray to_crisp_data(const XmlMessage& x);

/// Command -> objects of class "Command" with one attribute "value".
XmlMessage from_commands(const mrt_msgs::CommandArray& c);
mrt_msgs::CommandArray to_commands(const XmlMessage& x);

}  // namespace mrt::dcdt::node
