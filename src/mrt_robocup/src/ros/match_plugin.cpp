// mrt_robocup/MatchPlugin: the RoboCup match (match.h) in mrt_sim's
// sim_node, as a sim_node plugin (mrt_sim/ros/sim_plugin.h). Its
// parameters are sim_node's ~<name>/match (the match file, required) and
// ~<name>/dribble_timeout; it prepares the world (opponents, ball), attaches
// the Match to the simulator as a step hook and publishes through
// MatchInterface: `referee`, `ball/ground_truth`, and takes
// `referee/operator`, `<robot>/kick`, `<robot>/dribble` (README "The match
// plugin").
#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "match_interface.h"
#include "mrt_common_ros/params.h"
#include "mrt_robocup/match.h"
#include "mrt_sim/ros/sim_plugin.h"

namespace mrt::robocup::node {

class MatchPlugin : public sim::SimPlugin {
 public:
  void configure(const sim::SimPluginContext& ctx, sim::World& world) override {
    nh_ = ctx.nh;
    frame_ = ctx.world_frame;
    using mrt::ros_common::ParamReader;
    std::string file;
    double dribble_timeout = 0.5;  // s a `dribble` true holds; 0: until a false
    ParamReader p(ctx.pnh);
    p.require("match", file, "the path of the match file (mrt_robocup/doc/match.md)");
    ParamReader::check(!file.empty(), "match", "the path of the match file (required)");
    p.get_non_negative("dribble_timeout", dribble_timeout);
    cfg_ = load_match_config(file);  // mrt::common::ParseError: sim_node exits 2
    cfg_.kicker.dribble_timeout = dribble_timeout;
    setup_match_world(cfg_, world);  // std::invalid_argument without the two goals
  }

  void start(sim::Simulator& sim, diagnostic_updater::Updater& diagnostics) override {
    match_ = std::make_unique<Match>(cfg_, sim);
    interface_ = std::make_unique<MatchInterface>(nh_, *match_, frame_);
    diagnostics.add("match", [this](diagnostic_updater::DiagnosticStatusWrapper& s) { interface_->diagnose(s); });
  }

  void after_step(const ros::Time& stamp) override { interface_->publish_events(stamp); }
  void publish_ground_truth(const ros::Time& stamp) override { interface_->publish_ball(stamp); }

 private:
  ros::NodeHandle nh_;
  std::string frame_;
  MatchConfig cfg_;
  std::unique_ptr<Match> match_;               // detaches from the simulator when destroyed ...
  std::unique_ptr<MatchInterface> interface_;  // ... after its interface
};

}  // namespace mrt::robocup::node

PLUGINLIB_EXPORT_CLASS(mrt::robocup::node::MatchPlugin, mrt::sim::SimPlugin)
