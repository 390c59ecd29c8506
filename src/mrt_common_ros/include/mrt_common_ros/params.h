// The one node-parameter style of the stack: a node reads its private
// parameters once, at start-up, into its core's options struct through a
// ParamReader, validates them there, and fails fast with an error naming the
// parameter (`~rate: expected a finite number >= 0`). The core never reads
// parameters. run_node() turns any such error into ROS_FATAL and exit 1.
#pragma once

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include <ros/console.h>
#include <ros/node_handle.h>

namespace mrt::ros_common {

/// A missing, mistyped or invalid node parameter; what() names it.
class ParamError : public std::runtime_error {
 public:
  ParamError(const std::string& name, const std::string& expected)
      : std::runtime_error("~" + name + ": expected " + expected), name_(name) {}
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

class ParamReader {
 public:
  explicit ParamReader(ros::NodeHandle private_nh) : nh_(std::move(private_nh)) {}

  /// Sets `value` from ~name when the parameter is set and keeps it (the
  /// default) otherwise; a parameter of the wrong type is an error.
  template <class T>
  ParamReader& get(const std::string& name, T& value) {
    if (nh_.hasParam(name) && !nh_.getParam(name, value)) throw ParamError(name, type_name(value));
    return *this;
  }

  /// Like get(), but the parameter must be set; `what` says what it is.
  template <class T>
  ParamReader& require(const std::string& name, T& value, const std::string& what) {
    if (!nh_.hasParam(name)) throw ParamError(name, what + " (required)");
    return get(name, value);
  }

  /// get() for numbers that must be finite and strictly positive.
  template <class T>
  ParamReader& get_positive(const std::string& name, T& value) {
    get(name, value);
    check(std::isfinite(static_cast<double>(value)) && value > 0, name, "a finite number > 0");
    return *this;
  }

  /// get() for numbers that must be finite and not negative.
  template <class T>
  ParamReader& get_non_negative(const std::string& name, T& value) {
    get(name, value);
    check(std::isfinite(static_cast<double>(value)) && value >= 0, name, "a finite number >= 0");
    return *this;
  }

  /// Throws ParamError(name, expected) unless `ok`.
  static void check(bool ok, const std::string& name, const std::string& expected) {
    if (!ok) throw ParamError(name, expected);
  }

  const ros::NodeHandle& node_handle() const { return nh_; }

 private:
  static std::string type_name(const bool&) { return "a boolean"; }
  static std::string type_name(const int&) { return "an integer"; }
  static std::string type_name(const double&) { return "a number"; }
  static std::string type_name(const std::string&) { return "a string"; }
  template <class T>
  static std::string type_name(const T&) { return "a list or map of the documented form"; }

  ros::NodeHandle nh_;
};

/// Runs a node's body (after ros::init) and returns main()'s exit code: what
/// the body returns, or 1 after ROS_FATAL when it throws (a bad parameter, a
/// configuration file that does not parse, ...).
template <class Body>
int run_node(Body&& body) {
  // The node's NodeHandles die with the body when it throws, and the last
  // one to go shuts the node down, rosconsole with it: this one outlives
  // them, so that ROS_FATAL still prints.
  const ros::NodeHandle keep_alive;
  try {
    return std::forward<Body>(body)();
  } catch (const std::exception& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
}

}  // namespace mrt::ros_common
