// sim_node's plugins (mrt_sim/ros/sim_plugin.h): loaded with pluginlib
// from ~plugins, configured on the world before the Simulator is built,
// then started and called after every step. sim_node itself knows none of
// them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pluginlib/class_loader.hpp>

#include "mrt_sim/ros/sim_plugin.h"
#include "node_options.h"

namespace mrt::sim::node {

class SimPlugins {
 public:
  SimPlugins() = default;
  /// Loads the plugins of `specs` in their order and configures each on
  /// `world` (SimPlugin::configure). Throws mrt::ros_common::ParamError
  /// naming ~plugins when a class cannot be loaded, and naming
  /// ~<name>/<param> for a plugin's bad parameter; a plugin's other errors
  /// pass through.
  SimPlugins(const std::vector<PluginSpec>& specs, const ros::NodeHandle& nh, const ros::NodeHandle& pnh,
             const std::string& world_frame, World& world);
  SimPlugins(SimPlugins&&) = default;
  SimPlugins& operator=(SimPlugins&& other) noexcept;
  ~SimPlugins();

  void start(Simulator& sim, diagnostic_updater::Updater& diagnostics);
  void after_step(const ros::Time& stamp);
  void publish_ground_truth(const ros::Time& stamp);
  std::size_t size() const { return plugins_.size(); }

 private:
  // The loader holds the plugins' libraries: it is destroyed after them
  // (members go in reverse order).
  std::unique_ptr<pluginlib::ClassLoader<SimPlugin>> loader_;
  std::vector<pluginlib::UniquePtr<SimPlugin>> plugins_;
};

}  // namespace mrt::sim::node
