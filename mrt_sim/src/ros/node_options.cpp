#include "node_options.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include <xmlrpcpp/XmlRpcValue.h>

namespace mrt::sim::node {
namespace {

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw ParameterError("~" + name + ": " + what);
}

bool get_raw(const ros::NodeHandle& pnh, const std::string& name, XmlRpc::XmlRpcValue& v) {
  return pnh.hasParam(name) && pnh.getParam(name, v);
}

void get_number(const ros::NodeHandle& pnh, const std::string& name, double& out) {
  XmlRpc::XmlRpcValue v;
  if (!get_raw(pnh, name, v)) return;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble)
    out = static_cast<double>(v);
  else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt)
    out = static_cast<int>(v);
  else
    fail(name, "expected a number");
  if (!std::isfinite(out)) fail(name, "expected a finite number, got " + show(out));
}

void get_int(const ros::NodeHandle& pnh, const std::string& name, int& out) {
  XmlRpc::XmlRpcValue v;
  if (!get_raw(pnh, name, v)) return;
  if (v.getType() != XmlRpc::XmlRpcValue::TypeInt) fail(name, "expected an integer");
  out = static_cast<int>(v);
}

void get_bool(const ros::NodeHandle& pnh, const std::string& name, bool& out) {
  XmlRpc::XmlRpcValue v;
  if (!get_raw(pnh, name, v)) return;
  if (v.getType() != XmlRpc::XmlRpcValue::TypeBoolean) fail(name, "expected true or false");
  out = static_cast<bool>(v);
}

void get_string(const ros::NodeHandle& pnh, const std::string& name, std::string& out) {
  XmlRpc::XmlRpcValue v;
  if (!get_raw(pnh, name, v)) return;
  if (v.getType() != XmlRpc::XmlRpcValue::TypeString) fail(name, "expected a string");
  out = static_cast<std::string>(v);
}

void require_positive(const std::string& name, double v) {
  if (!(v > 0.0)) fail(name, "must be > 0, got " + show(v));
}

bool valid_frame_name(const std::string& s) {
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/')) return false;
  return true;
}

}  // namespace

long NodeOptions::steps_per(double rate) const {
  const long n = std::lround(rate_hz / rate);
  return n < 1 ? 1 : n;
}

NodeOptions load_node_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  get_string(pnh, "world", o.world_file);
  if (o.world_file.empty()) fail("world", "required: path of the world YAML file");

  get_number(pnh, "rate_hz", o.rate_hz);
  require_positive("rate_hz", o.rate_hz);
  if (o.rate_hz > 100000.0) fail("rate_hz", "must be <= 100000, got " + show(o.rate_hz));

  get_number(pnh, "real_time_factor", o.real_time_factor);
  require_positive("real_time_factor", o.real_time_factor);

  get_bool(pnh, "publish_clock", o.publish_clock);
  get_int(pnh, "clock_divider", o.clock_divider);
  if (o.clock_divider < 1) fail("clock_divider", "must be >= 1, got " + show(o.clock_divider));

  get_number(pnh, "ground_truth_rate", o.ground_truth_rate);
  require_positive("ground_truth_rate", o.ground_truth_rate);
  if (o.ground_truth_rate > o.rate_hz)
    fail("ground_truth_rate", "must be <= ~rate_hz (" + show(o.rate_hz) + "), got " +
                                  show(o.ground_truth_rate));
  get_number(pnh, "marker_rate", o.marker_rate);
  require_positive("marker_rate", o.marker_rate);
  get_number(pnh, "path_rate", o.path_rate);
  require_positive("path_rate", o.path_rate);
  get_int(pnh, "path_length", o.path_length);
  if (o.path_length < 0) fail("path_length", "must be >= 0, got " + show(o.path_length));

  get_number(pnh, "cmd_timeout", o.cmd_timeout);
  if (o.cmd_timeout < 0.0) fail("cmd_timeout", "must be >= 0 (0 disables), got " + show(o.cmd_timeout));

  get_string(pnh, "world_frame", o.world_frame);
  if (o.world_frame.empty() || !valid_frame_name(o.world_frame))
    fail("world_frame", "expected a non-empty frame name of [A-Za-z0-9_/]");
  get_string(pnh, "frame_prefix", o.frame_prefix);
  if (!valid_frame_name(o.frame_prefix)) fail("frame_prefix", "expected characters of [A-Za-z0-9_/]");
  if (!o.frame_prefix.empty() && o.frame_prefix.back() != '/') o.frame_prefix += '/';
  get_string(pnh, "sensor_parent", o.sensor_parent);
  if (o.sensor_parent != "base_link_truth" && o.sensor_parent != "base_link")
    fail("sensor_parent", "expected 'base_link_truth' or 'base_link', got '" + o.sensor_parent + "'");
  return o;
}

}  // namespace mrt::sim::node
