// The plugin interface of sim_node (pluginlib, base class
// "mrt::sim::SimPlugin" of package mrt_sim): code that extends the
// simulation without sim_node knowing it, e.g. a game's rules with their
// topics. sim_node loads the plugins named in its
// ~plugins parameter ([{name: N, type: PACKAGE/CLASS}, ...]), in that
// order, and calls, for each:
//
//   configure()  once, after the world is loaded and before the Simulator
//                exists: read the parameters under ~N/, prepare the world;
//   start()      once, with the Simulator built on that world: attach its
//                StepHooks (mrt_sim/step_hook.h), advertise, subscribe, add
//                diagnostic tasks;
//   after_step() after every step (the step ran the hooks), before /clock
//                and the robots' topics;
//   publish_ground_truth()  at ~ground_truth_rate, after the robots'
//                ground truth.
//
// Callbacks run in sim_node's one thread between two steps (ros::spinOnce),
// so a plugin needs no locking. The Simulator outlives every plugin.
// This is the one ROS header mrt_sim exports (under include/mrt_sim/ros/,
// so the core headers stay ROS-free): a plugin's package needs roscpp,
// diagnostic_updater and pluginlib itself.
#pragma once

#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/node_handle.h>
#include <ros/time.h>

#include "mrt_sim/simulator.h"
#include "mrt_sim/world.h"

namespace mrt::sim {

/// What sim_node gives a plugin.
struct SimPluginContext {
  std::string name;          // the plugin's `name` in ~plugins
  std::string type;          // its `type` (the pluginlib class name)
  ros::NodeHandle nh;        // sim_node's namespace: topics beside the robots' (`<robot>/...`)
  ros::NodeHandle pnh;       // the plugin's parameters: sim_node's ~<name>/
  std::string world_frame;   // sim_node's ~world_frame (frame of everything in the world)
};

class SimPlugin {
 public:
  virtual ~SimPlugin() = default;
  SimPlugin(const SimPlugin&) = delete;
  SimPlugin& operator=(const SimPlugin&) = delete;

  /// Reads the plugin's parameters (ctx.pnh) and prepares `world` before the
  /// simulator is built on it (movers added, the ball enabled ...).
  /// sim_node stops at start-up when it throws: exit 1 for
  /// mrt::ros_common::ParamError (a bad parameter; sim_node names it
  /// ~<name>/<param>) and std::invalid_argument, exit 2 for
  /// mrt::common::ParseError (a file that does not parse) and other errors.
  virtual void configure(const SimPluginContext& ctx, World& world) = 0;
  /// The simulator is built on the world configure() prepared: attach the
  /// plugin's StepHooks to `sim` (detach them in the destructor), advertise,
  /// subscribe (on ctx.nh), add diagnostic tasks to `diagnostics`.
  virtual void start(Simulator& sim, diagnostic_updater::Updater& diagnostics) = 0;
  /// After every step; `stamp` is the sim time after it.
  virtual void after_step(const ros::Time& stamp) { (void)stamp; }
  /// With the robots' ground truth (sim_node's ~ground_truth_rate).
  virtual void publish_ground_truth(const ros::Time& stamp) { (void)stamp; }

 protected:
  SimPlugin() = default;  // pluginlib creates plugins with their default constructor
};

}  // namespace mrt::sim
