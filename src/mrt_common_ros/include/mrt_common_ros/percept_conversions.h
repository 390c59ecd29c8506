// Percepts between mrt_common's percept type (mrt_common/percept.h) and
// mrt_msgs (header-only): the one conversion every node uses, and the
// ontology check a consuming node applies to what it receives (drop and
// count; report() puts the counts in its diagnostics).
#pragma once

#include <string>
#include <vector>

#include <mrt_msgs/Percept.h>

#include "mrt_common/ontology.h"
#include "mrt_common/percept.h"

namespace mrt::ros_common {

inline mrt_msgs::Attribute to_msg(const mrt::common::Attribute& a) {
  mrt_msgs::Attribute m;
  m.name = a.name;
  m.value = a.value;
  m.symbol = a.symbol;
  m.variability = a.variability;
  m.reliability = a.reliability;
  return m;
}

inline mrt::common::Attribute from_msg(const mrt_msgs::Attribute& m) {
  return {m.name, m.symbol.empty() ? m.value : 0.0, m.symbol, m.variability, m.reliability};
}

inline mrt_msgs::PerceptObject to_msg(const mrt::common::PerceptObject& o) {
  mrt_msgs::PerceptObject m;
  m.name = o.name;
  m.membership_class = o.membership_class;
  m.attributes.reserve(o.attributes.size());
  for (const auto& a : o.attributes) m.attributes.push_back(to_msg(a));
  return m;
}

inline mrt::common::PerceptObject from_msg(const mrt_msgs::PerceptObject& m) {
  mrt::common::PerceptObject o(m.name, m.membership_class);
  o.attributes.reserve(m.attributes.size());
  for (const auto& a : m.attributes) o.attributes.push_back(from_msg(a));
  return o;
}

/// The message of a percept (header stamp and frame from it).
inline mrt_msgs::Percept to_msg(const mrt::common::Percept& p) {
  mrt_msgs::Percept m;
  m.header.stamp.fromSec(p.stamp);
  m.header.frame_id = p.frame;
  m.sensor = p.sensor;
  m.robot = p.robot;
  m.objects.reserve(p.objects.size());
  for (const auto& o : p.objects) m.objects.push_back(to_msg(o));
  return m;
}

inline mrt::common::Percept from_msg(const mrt_msgs::Percept& m) {
  mrt::common::Percept p;
  p.stamp = m.header.stamp.toSec();
  p.frame = m.header.frame_id;
  p.sensor = m.sensor;
  p.robot = m.robot;
  p.objects.reserve(m.objects.size());
  for (const auto& o : m.objects) p.objects.push_back(from_msg(o));
  return p;
}

/// The objects of a received percept that pass the ontology; the others are
/// counted in `drops`.
inline std::vector<mrt::common::PerceptObject> accepted_objects(
    const mrt_msgs::Percept& m, mrt::common::PerceptDrops& drops,
    const mrt::common::Ontology& ontology = mrt::common::Ontology::standard()) {
  std::vector<mrt::common::PerceptObject> out;
  out.reserve(m.objects.size());
  for (const auto& o : m.objects) out.push_back(from_msg(o));
  ontology.filter(out, drops);
  return out;
}

/// Adds the drop counts to a diagnostic status (diagnostic_updater's
/// DiagnosticStatusWrapper or anything with add(key, value)).
template <class Status>
void report(Status& s, const mrt::common::PerceptDrops& d) {
  s.add("percept objects dropped: unknown class", d.unknown_class);
  s.add("percept objects dropped: missing attribute", d.missing_attribute);
  s.add("percept objects dropped: wrong attribute kind", d.wrong_kind);
}

}  // namespace mrt::ros_common
