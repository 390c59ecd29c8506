#include "ros/conversions.h"

#include <cstdint>

#include "mrt_common_ros/percept_conversions.h"

namespace mrt::dcdt::node {

void stamp_to(const std_msgs::Header& h, XmlMessage* x) {
  x->sec = h.stamp.sec;
  x->nsec = h.stamp.nsec;
  x->frame = h.frame_id;
}

void stamp_from(const XmlMessage& x, std_msgs::Header* h) {
  if (x.sec < 0 || x.sec > static_cast<int64_t>(UINT32_MAX))
    throw XmlError(0, "time stamp " + std::to_string(x.sec) + " s is outside the ROS time range [0, 4294967295] s");
  h->stamp.sec = static_cast<uint32_t>(x.sec);
  h->stamp.nsec = x.nsec;
  h->frame_id = x.frame;
}

namespace {
const XmlAttribute& value_of(const XmlObject& o, const char* cls) {
  if (o.membership_class != cls || o.attributes.size() != 1 || o.attributes[0].name != "value" ||
      !o.attributes[0].symbol.empty())
    throw XmlError(0, "object '" + o.name + "' is not a " + cls + " (class " + cls +
                          ", one numeric attribute 'value')");
  return o.attributes[0];
}
}  // namespace

XmlMessage from_percept(const mrt_msgs::Percept& p) {
  XmlMessage x;
  stamp_to(p.header, &x);
  x.sensor = p.sensor;
  x.robot = p.robot;
  for (const auto& o : p.objects) x.objects.push_back(mrt::ros_common::from_msg(o));
  return x;
}

mrt_msgs::Percept to_percept(const XmlMessage& x) {
  mrt_msgs::Percept p;
  stamp_from(x, &p.header);
  p.sensor = x.sensor;
  p.robot = x.robot;
  for (const auto& o : x.objects) p.objects.push_back(mrt::ros_common::to_msg(o));
  return p;
}

XmlMessage from_crisp_data(const mrt_msgs::CrispDataArray& c) {
  XmlMessage x;
  stamp_to(c.header, &x);
  for (const auto& d : c.data) x.objects.push_back({d.name, "CrispData", {{"value", d.value, "", 0.0, d.reliability}}});
  return x;
}

mrt_msgs::CrispDataArray to_crisp_data(const XmlMessage& x) {
  mrt_msgs::CrispDataArray c;
  stamp_from(x, &c.header);
  for (const auto& o : x.objects) {
    const auto& a = value_of(o, "CrispData");
    mrt_msgs::CrispData d;
    d.name = o.name;
    d.value = a.value;
    d.reliability = a.reliability;
    c.data.push_back(d);
  }
  return c;
}

XmlMessage from_commands(const mrt_msgs::CommandArray& c) {
  XmlMessage x;
  stamp_to(c.header, &x);
  for (const auto& d : c.commands) x.objects.push_back({d.name, "Command", {{"value", d.value, "", 0.0, 1.0}}});
  return x;
}

mrt_msgs::CommandArray to_commands(const XmlMessage& x) {
  mrt_msgs::CommandArray c;
  stamp_from(x, &c.header);
  for (const auto& o : x.objects) {
    mrt_msgs::Command d;
    d.name = o.name;
    d.value = value_of(o, "Command").value;
    c.commands.push_back(d);
  }
  return c;
}

}  // namespace mrt::dcdt::node
