#include "sim_plugins.h"

#include "mrt_common_ros/params.h"

namespace mrt::sim::node {

using mrt::ros_common::ParamError;

SimPlugins::SimPlugins(const std::vector<PluginSpec>& specs, const ros::NodeHandle& nh, const ros::NodeHandle& pnh,
                       const std::string& world_frame, World& world) {
  if (specs.empty()) return;  // no plugin: no loader (it asks rospack for every export of mrt_sim)
  loader_ = std::make_unique<pluginlib::ClassLoader<SimPlugin>>("mrt_sim", "mrt::sim::SimPlugin");
  for (const PluginSpec& spec : specs) {
    try {
      plugins_.push_back(loader_->createUniqueInstance(spec.type));
    } catch (const pluginlib::PluginlibException& e) {
      throw ParamError("plugins", "pluginlib classes derived from mrt::sim::SimPlugin; '" + spec.type +
                                      "' (plugin '" + spec.name + "') does not load: " + e.what());
    }
    SimPluginContext ctx;
    ctx.name = spec.name;
    ctx.type = spec.type;
    ctx.nh = nh;
    ctx.pnh = ros::NodeHandle(pnh, spec.name);
    ctx.world_frame = world_frame;
    try {
      plugins_.back()->configure(ctx, world);
    } catch (const ParamError& e) {
      // The plugin's parameters are relative to ~<name>/: say so.
      const std::string what = e.what(), marker = ": expected ";
      const std::size_t at = what.find(marker);
      throw ParamError(spec.name + "/" + e.name(), at == std::string::npos ? what : what.substr(at + marker.size()));
    }
    ROS_INFO("plugin '%s' (%s) loaded", spec.name.c_str(), spec.type.c_str());
  }
}

SimPlugins::~SimPlugins() {
  plugins_.clear();  // before the loader unloads their libraries
}

SimPlugins& SimPlugins::operator=(SimPlugins&& other) noexcept {
  plugins_.clear();  // ours go before our loader
  loader_ = std::move(other.loader_);
  plugins_ = std::move(other.plugins_);
  return *this;
}

void SimPlugins::start(Simulator& sim, diagnostic_updater::Updater& diagnostics) {
  for (auto& p : plugins_) p->start(sim, diagnostics);
}

void SimPlugins::after_step(const ros::Time& stamp) {
  for (auto& p : plugins_) p->after_step(stamp);
}

void SimPlugins::publish_ground_truth(const ros::Time& stamp) {
  for (auto& p : plugins_) p->publish_ground_truth(stamp);
}

}  // namespace mrt::sim::node
