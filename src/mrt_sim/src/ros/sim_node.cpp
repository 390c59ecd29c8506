// sim_node: the ROS layer of the mrt_sim world simulator. Reads its
// parameters once, loads the world, then steps the core Simulator at
// ~rate_hz simulated steps per second, paced on wall time by
// ~real_time_factor, and publishes /clock, ground truth, the simulated
// devices of every robot and rviz markers, all stamped with sim time. The
// plugins of ~plugins (mrt_sim/ros/sim_plugin.h) extend it; it knows none.
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include "mrt_common/parse_error.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_sim/simulator.h"
#include "mrt_sim/world.h"
#include "conversions.h"
#include "markers.h"
#include "node_options.h"
#include "robot_interface.h"
#include "sim_plugins.h"

namespace mrt::sim::node {
namespace {

using SteadyClock = std::chrono::steady_clock;

double seconds_between(SteadyClock::time_point a, SteadyClock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

class SimNode {
 public:
  SimNode(ros::NodeHandle& nh, NodeOptions opt, World world, SimPlugins plugins)
      : opt_(std::move(opt)), sim_(std::move(world), opt_.dt()), plugins_(std::move(plugins)),
        updater_(nh, ros::NodeHandle("~")) {
    plugins_.start(sim_, updater_);  // the world was prepared by their configure()
    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    world_markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("world_markers", 1, true);
    dynamic_markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("dynamic_markers", 5);
    for (std::size_t i = 0; i < sim_.robots().size(); ++i)
      robots_.push_back(std::make_unique<RobotInterface>(nh, sim_, i, opt_));
    // Movers steered from outside (a visitor's behaviour model, FollowMe):
    // <mover>/goal walks it straight to (x, y) at z m/s; <mover>/ground_truth
    // is where it is.
    for (std::size_t i = 0; i < sim_.world().movers.size(); ++i) {
      const std::string name = sim_.world().movers[i].name;
      mover_goal_subs_.push_back(nh.subscribe<geometry_msgs::PointStamped>(
          name + "/goal", 5, [this, i](const geometry_msgs::PointStamped::ConstPtr& m) {
            if (std::isfinite(m->point.x) && std::isfinite(m->point.y) && std::isfinite(m->point.z))
              sim_.steer_mover(i, {m->point.x, m->point.y}, m->point.z);
          }));
      mover_truth_pubs_.push_back(nh.advertise<nav_msgs::Odometry>(name + "/ground_truth", 5));
    }

    std::vector<geometry_msgs::TransformStamped> fixed;
    for (const auto& r : robots_) r->static_transforms(fixed);
    if (!fixed.empty()) static_tf_.sendTransform(fixed);
    world_markers_pub_.publish(world_markers(sim_.world(), opt_.world_frame));

    updater_.setHardwareID("mrt_sim/" + sim_.world().name);
    updater_.add("simulator", this, &SimNode::diagnose);
    for (const auto& r : robots_) {
      RobotInterface* ri = r.get();
      updater_.add("robot " + ri->name(), [ri](diagnostic_updater::DiagnosticStatusWrapper& s) {
        ri->diagnose(s);
      });
    }
    gt_every_ = opt_.steps_per(opt_.ground_truth_rate);
    marker_every_ = opt_.steps_per(opt_.marker_rate);
    path_every_ = opt_.steps_per(opt_.path_rate);
  }

  void run() {
    const double wall_per_step = opt_.dt() / opt_.real_time_factor;
    auto anchor = SteadyClock::now();  // wall time of step 0 of the current pacing run
    std::uint64_t anchor_step = 0;
    window_wall_ = anchor;
    window_sim_ = sim_.time();
    std::vector<geometry_msgs::TransformStamped> tfs;
    while (ros::ok()) {
      ros::spinOnce();  // commands received now act during the next step
      for (auto& r : robots_) r->apply_watchdog();
      sim_.step();  // runs the plugins' step hooks
      ++steps_;
      const ros::Time stamp(sim_.time());
      if (ros::Time::isSimTime()) ros::Time::setNow(stamp);  // our own clock, without a round trip
      plugins_.after_step(stamp);

      if (opt_.publish_clock && steps_ % opt_.clock_divider == 0) {
        rosgraph_msgs::Clock c;
        c.clock = stamp;
        clock_pub_.publish(c);
      }
      const bool gt = steps_ % gt_every_ == 0;
      const bool path = steps_ % path_every_ == 0;
      tfs.clear();
      for (auto& r : robots_) r->publish(stamp, gt, path, tfs);
      if (gt) plugins_.publish_ground_truth(stamp);
      if (gt) publish_movers(stamp);
      if (!tfs.empty()) tf_.sendTransform(tfs);
      if (steps_ % marker_every_ == 0 && dynamic_markers_pub_.getNumSubscribers() > 0)
        dynamic_markers_pub_.publish(
            dynamic_markers(sim_.world(), sim_.robots(), opt_.world_frame, stamp));
      updater_.update();

      // Pace on wall time: step k is due at anchor + k * dt / real_time_factor.
      const auto due = anchor + std::chrono::duration_cast<SteadyClock::duration>(
                                    std::chrono::duration<double>(
                                        static_cast<double>(steps_ - anchor_step) * wall_per_step));
      const auto now = SteadyClock::now();
      if (due > now) {
        std::this_thread::sleep_until(due);
      } else if (seconds_between(due, now) > 0.2) {
        // Too far behind (a stall, or the machine cannot keep up): do not
        // race to catch up, restart pacing from here.
        ++lag_resets_;
        anchor = now;
        anchor_step = steps_;
      }
    }
  }

 private:
  void publish_movers(const ros::Time& stamp) {
    const auto& movers = sim_.world().movers;
    for (std::size_t i = 0; i < movers.size() && i < mover_truth_pubs_.size(); ++i) {
      if (mover_truth_pubs_[i].getNumSubscribers() == 0) continue;
      const Mover& m = movers[i];
      mover_truth_pubs_[i].publish(mrt::ros_common::to_odometry(
          {m.position.x, m.position.y, std::atan2(m.velocity.y, m.velocity.x)}, m.velocity.x, m.velocity.y, 0.0,
          opt_.world_frame, m.name, stamp));
    }
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    const auto now = SteadyClock::now();
    const double wall = seconds_between(window_wall_, now);
    if (wall > 0.0) achieved_rtf_ = (sim_.time() - window_sim_) / wall;
    window_wall_ = now;
    window_sim_ = sim_.time();
    if (achieved_rtf_ < 0.9 * opt_.real_time_factor)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "slower than the requested real-time factor");
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
    s.add("world", sim_.world().file);
    s.add("sim time [s]", sim_.time());
    s.add("steps", steps_);
    s.add("step [s]", sim_.dt());
    s.add("real-time factor requested", opt_.real_time_factor);
    s.add("real-time factor achieved", achieved_rtf_);
    s.add("pacing resets (fell behind)", lag_resets_);
  }

  NodeOptions opt_;
  Simulator sim_;
  SimPlugins plugins_;  // after sim_: destroyed before it (their hooks detach from it)
  std::vector<std::unique_ptr<RobotInterface>> robots_;
  std::vector<ros::Subscriber> mover_goal_subs_;
  std::vector<ros::Publisher> mover_truth_pubs_;
  ros::Publisher clock_pub_, world_markers_pub_, dynamic_markers_pub_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  diagnostic_updater::Updater updater_;
  std::uint64_t steps_ = 0, lag_resets_ = 0;
  long gt_every_ = 1, marker_every_ = 1, path_every_ = 1;
  SteadyClock::time_point window_wall_;
  double window_sim_ = 0.0, achieved_rtf_ = 0.0;
};

}  // namespace
}  // namespace mrt::sim::node

int main(int argc, char** argv) {
  using namespace mrt::sim::node;
  ros::init(argc, argv, "sim_node");
  // A bad parameter: ParamError, ROS_FATAL and exit 1 (run_node); a world
  // file that does not load: exit 2.
  return mrt::ros_common::run_node([]() -> int {
    ros::NodeHandle nh, pnh("~");
    const NodeOptions opt = load_node_options(pnh);
    mrt::sim::World world;
    SimPlugins plugins;
    try {
      world = mrt::sim::load_world(opt.world_file);
      apply_team_options(opt, world);  // ~robots, ~camera_rate, ~seed
      plugins = SimPlugins(opt.plugins, nh, pnh, opt.world_frame, world);  // they may change the world
    } catch (const mrt::ros_common::ParamError&) {
      throw;  // a bad parameter of sim_node or of a plugin: exit 1 (run_node)
    } catch (const mrt::common::ParseError& e) {
      ROS_FATAL("cannot load world: %s", e.what());
      return 2;
    } catch (const std::invalid_argument& e) {
      ROS_FATAL("%s", e.what());
      return 1;
    } catch (const std::exception& e) {
      ROS_FATAL("cannot load world %s: %s", opt.world_file.c_str(), e.what());
      return 2;
    }
    if (opt.publish_clock && !ros::Time::isSimTime())
      ROS_WARN("/use_sim_time is not set: other nodes will not follow the simulated /clock");
    std::unique_ptr<SimNode> node;
    try {
      node = std::make_unique<SimNode>(nh, opt, std::move(world), std::move(plugins));
    } catch (const std::exception& e) {
      throw std::runtime_error("cannot start the simulation of " + opt.world_file + ": " + e.what());
    }
    ROS_INFO("simulating %s at %.0f steps/s, real-time factor %g", opt.world_file.c_str(), opt.rate_hz,
             opt.real_time_factor);
    node->run();
    return 0;
  });
}
