// map_eval: runs MAP offline on a bag for a team of robots and writes one
// CSV row per anchor and update:
//   stamp,robot,id,class,x,y,vx,vy,cov_xx,cov_xy,cov_yy,reliability,sources
// Each robot NS reads /NS/percepts (mrt_msgs/Percept); robot poses come from
// the bag's /tf and /tf_static (world frame -> each percept's frame); every
// update of a robot hands its own-sensor anchors to its teammates, as the
// team topic does. Usage errors and bad input files exit 2.
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/buffer_core.h>
#include <tf2/utils.h>
#include <tf2_msgs/TFMessage.h>
#include <mrt_msgs/Percept.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_map/world_model.h"
#include "ros/conversions.h"

namespace {

using mrt::map::WorldModel;

struct Args {
  std::string model, bag, robots, out, world_frame = "map";
  double max_percept_age = 0.5;
  double pose_sigma = 0.02, theta_sigma = 0.01;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> v;
  std::stringstream ss(s);
  for (std::string t; std::getline(ss, t, ',');)
    if (!t.empty()) v.push_back(t);
  return v;
}

void load_tf(rosbag::Bag& bag, tf2::BufferCore& tf) {
  rosbag::View view(bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static"}));
  for (const rosbag::MessageInstance& m : view) {
    auto msg = m.instantiate<tf2_msgs::TFMessage>();
    if (!msg) continue;
    for (const auto& t : msg->transforms) tf.setTransform(t, "bag", m.getTopic() == "/tf_static");
  }
}

void write_rows(std::ostream& out, const WorldModel& w, double now) {
  for (const mrt::map::Anchor& a : w.tracker().anchors()) {
    const auto& x = a.fused.x;
    const auto& P = a.fused.P;
    std::string sources;
    for (const std::string& s : a.sources) sources += (sources.empty() ? "" : ";") + s;
    out << now << ',' << w.options().robot << ',' << a.id << ',' << w.model().at(a.class_index).name << ','
        << x(0) << ',' << x(1) << ',' << x(2) << ',' << x(3) << ',' << P(0, 0) << ',' << P(0, 1) << ','
        << P(1, 1) << ',' << w.tracker().reliability(a, now) << ',' << sources << '\n';
  }
}

int run(const Args& args) {
  const auto model = mrt::map::ConceptualModel::load(args.model);
  const std::vector<std::string> robots = split(args.robots);
  if (robots.empty()) throw std::invalid_argument("--robots: expected NS1,NS2,...");
  rosbag::Bag bag;
  bag.open(args.bag, rosbag::bagmode::Read);
  tf2::BufferCore tf(ros::Duration(1e6));
  load_tf(bag, tf);
  std::map<std::string, std::unique_ptr<WorldModel>> team;
  std::vector<std::string> topics;
  for (const std::string& r : robots) {
    team[r] = std::make_unique<WorldModel>(model, mrt::map::WorldModelOptions{r, args.max_percept_age});
    topics.push_back("/" + r + "/percepts");
  }
  std::ofstream out(args.out);
  if (!out) throw mrt::common::ParseError(args.out, 0, 0, "cannot write file");
  out << "stamp,robot,id,class,x,y,vx,vy,cov_xx,cov_xy,cov_yy,reliability,sources\n" << std::setprecision(9);
  std::size_t updates = 0, no_pose = 0;
  mrt::common::PerceptDrops ontology_drops;
  rosbag::View view(bag, rosbag::TopicQuery(topics));
  mrt::cli::Progress progress("map_eval", view.size());
  double done = 0.0;
  for (const rosbag::MessageInstance& m : view) {
    progress.update(++done);
    auto p = m.instantiate<mrt_msgs::Percept>();
    if (!p) continue;
    const std::string robot = m.getTopic().substr(1, m.getTopic().find('/', 1) - 1);
    WorldModel& w = *team.at(robot);
    const std::string frame = p->header.frame_id.empty() ? robot + "/base_link" : p->header.frame_id;
    mrt::map::RobotPose pose;
    try {
      const auto t = tf.lookupTransform(args.world_frame, frame, p->header.stamp);
      pose.x = t.transform.translation.x;
      pose.y = t.transform.translation.y;
      pose.theta = tf2::getYaw(t.transform.rotation);
      pose.cov = args.pose_sigma * args.pose_sigma * mrt::map::Mat2::Identity();
      pose.theta_sigma = args.theta_sigma;
    } catch (const tf2::TransformException&) {
      ++no_pose;
      continue;
    }
    // The bag's receive time is "now" for the staleness check.
    const double now = m.getTime().toSec();
    w.set_robot_pose(pose, now);
    w.add_percept(mrt::ros_common::accepted_objects(*p, ontology_drops), pose, p->header.stamp.toSec(), now,
                  p->sensor.empty() ? "sensor" : p->sensor);
    w.update(now);
    ++updates;
    for (auto& [name, mate] : team) {
      if (name == robot) continue;
      mate->add_teammate_model(robot, w.local_tracks(), now, &w.robot_pose());
    }
    write_rows(out, w, now);
  }
  std::cerr << "map_eval: " << updates << " updates of " << robots.size() << " robots";
  if (no_pose) std::cerr << ", " << no_pose << " percepts without a pose dropped";
  if (ontology_drops.total()) std::cerr << ", " << ontology_drops.total() << " objects not in the ontology dropped";
  for (const auto& [name, w] : team) {
    const auto& c = w->counters();
    const auto dropped = c.unknown_class + c.non_finite + c.no_position + c.unmatched + c.stale + c.outside_world;
    if (dropped) std::cerr << ", " << name << ": " << dropped << " objects dropped";
  }
  std::cerr << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs MAP on a bag for a team of robots; writes one CSV row per anchor and update."};
  app.name("map_eval");
  Args args;
  app.add_option("--model", args.model, "conceptual model YAML")->required();
  app.add_option("--bag", args.bag, "input bag (/NS/percepts, /tf, /tf_static)")->required();
  app.add_option("--robots", args.robots, "robot namespaces NS1,NS2,...")->required();
  app.add_option("--out", args.out, "output CSV")->required();
  app.add_option("--world-frame", args.world_frame, "world frame (default map)");
  app.add_option("--max-percept-age", args.max_percept_age, "s; older percepts are dropped (default 0.5)")
      ->check(CLI::PositiveNumber);
  if (const int code = mrt::cli::parse_cli(app, argc, argv); code >= 0) return code;
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::cerr << "map_eval: " << e.what() << "\n";
    return mrt::cli::kUsageError;
  }
}
