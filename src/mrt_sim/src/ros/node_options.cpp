#include "node_options.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "mrt_common_ros/params.h"
#include "mrt_sim/camera.h"

namespace mrt::sim::node {
namespace {

using mrt::ros_common::ParamReader;

bool valid_frame_name(const std::string& s) {
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/')) return false;
  return true;
}

bool valid_plugin_name(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// ~plugins: a list of {name: N, type: PACKAGE/CLASS} (as costmap_2d's
// layers), names unique; absent = none.
std::vector<PluginSpec> load_plugins(const ros::NodeHandle& pnh) {
  std::vector<PluginSpec> out;
  XmlRpc::XmlRpcValue v;
  if (!pnh.getParam("plugins", v)) return out;
  const std::string form = "a list of {name: NAME, type: PACKAGE/CLASS}, names of [A-Za-z0-9_] and unique";
  ParamReader::check(v.getType() == XmlRpc::XmlRpcValue::TypeArray, "plugins", form);
  for (int i = 0; i < v.size(); ++i) {
    XmlRpc::XmlRpcValue& e = v[i];
    const bool ok = e.getType() == XmlRpc::XmlRpcValue::TypeStruct && e.size() == 2 && e.hasMember("name") &&
                    e.hasMember("type") && e["name"].getType() == XmlRpc::XmlRpcValue::TypeString &&
                    e["type"].getType() == XmlRpc::XmlRpcValue::TypeString;
    ParamReader::check(ok, "plugins", form);
    PluginSpec p{static_cast<std::string>(e["name"]), static_cast<std::string>(e["type"])};
    const bool unique = std::none_of(out.begin(), out.end(), [&](const PluginSpec& q) { return q.name == p.name; });
    ParamReader::check(valid_plugin_name(p.name) && unique && !p.type.empty(), "plugins", form);
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

long NodeOptions::steps_per(double rate) const {
  const long n = std::lround(rate_hz / rate);
  return n < 1 ? 1 : n;
}

bool NodeOptions::joint_states_for(const std::string& robot) const {
  return std::find(joint_state_robots.begin(), joint_state_robots.end(), robot) != joint_state_robots.end();
}

bool NodeOptions::described(const std::string& robot) const {
  return std::find(description_robots.begin(), description_robots.end(), robot) != description_robots.end();
}

NodeOptions load_node_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  ParamReader p(pnh);
  p.require("world", o.world_file, "the path of the world YAML file");
  ParamReader::check(!o.world_file.empty(), "world", "the path of the world YAML file (required)");
  o.plugins = load_plugins(pnh);
  p.get_positive("rate_hz", o.rate_hz);
  ParamReader::check(o.rate_hz <= 100000.0, "rate_hz", "a number <= 100000");
  p.get_positive("real_time_factor", o.real_time_factor)
      .get("publish_clock", o.publish_clock)
      .get("clock_divider", o.clock_divider);
  ParamReader::check(o.clock_divider >= 1, "clock_divider", "an integer >= 1");
  p.get_positive("ground_truth_rate", o.ground_truth_rate);
  ParamReader::check(o.ground_truth_rate <= o.rate_hz, "ground_truth_rate", "a number <= ~rate_hz");
  p.get_positive("marker_rate", o.marker_rate)
      .get_positive("path_rate", o.path_rate)
      .get_non_negative("path_length", o.path_length)
      .get_non_negative("cmd_timeout", o.cmd_timeout)  // 0 disables the watchdog
      .get("world_frame", o.world_frame)
      .get("frame_prefix", o.frame_prefix)
      .get("sensor_parent", o.sensor_parent)
      .get("joint_state_robots", o.joint_state_robots)
      .get("description_robots", o.description_robots)
      .get("robots", o.robots)
      .get_non_negative("camera_rate", o.camera_rate)
      .get_positive("camera_scale", o.camera_scale)
      .get("seed", o.seed);
  ParamReader::check(o.camera_scale <= 4.0, "camera_scale", "a number in (0, 4]");
  ParamReader::check(o.seed >= -1, "seed", "an integer >= 0, or -1 for the world file's");
  ParamReader::check(!o.world_frame.empty() && valid_frame_name(o.world_frame), "world_frame",
                     "a non-empty frame name of [A-Za-z0-9_/]");
  ParamReader::check(valid_frame_name(o.frame_prefix), "frame_prefix", "characters of [A-Za-z0-9_/]");
  if (!o.frame_prefix.empty() && o.frame_prefix.back() != '/') o.frame_prefix += '/';
  ParamReader::check(o.sensor_parent == "base_link_truth" || o.sensor_parent == "base_link", "sensor_parent",
                     "'base_link_truth' or 'base_link'");
  return o;
}

void apply_team_options(const NodeOptions& o, World& world) {
  if (!o.robots.empty()) {
    for (const std::string& name : o.robots) {
      const bool known = std::any_of(world.robots.begin(), world.robots.end(),
                                     [&](const RobotConfig& r) { return r.name == name; });
      if (!known) throw std::invalid_argument("~robots: the world has no robot '" + name + "'");
    }
    std::vector<RobotConfig> kept;
    for (RobotConfig& r : world.robots)
      if (std::find(o.robots.begin(), o.robots.end(), r.name) != o.robots.end()) kept.push_back(std::move(r));
    world.robots = std::move(kept);
  }
  if (o.camera_rate > 0.0)
    for (RobotConfig& r : world.robots)
      if (r.sensors.camera.rate > 0.0) r.sensors.camera.rate = o.camera_rate;
  if (o.camera_scale != 1.0)
    for (RobotConfig& r : world.robots)
      if (r.sensors.camera.rate > 0.0) r.sensors.camera.model = r.sensors.camera.model.scaled(o.camera_scale);
  if (o.seed >= 0) world.seed = static_cast<std::uint64_t>(o.seed);
}

}  // namespace mrt::sim::node
