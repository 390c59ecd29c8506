// murea_eval: runs murea_node's pipeline (percepts into base_link, odometry
// prediction, the Tracker's update) over a recorded bag and writes one row
// per estimate; with the robot's ground truth in the bag, prints the RMSE
// and the worst error (see README, "murea_eval"). With --initial-pose it
// tracks from a known start (amcl's initial pose); ambiguous global
// searches give rows too (mode `ambiguous`, with the runner-up).
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>

#include "mrt_common/angle.h"
#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_world/occupancy_map.h"
#include "ros/node_options.h"

namespace {

using mrt::murea::Pose2D;
namespace rc = mrt::ros_common;
namespace mn = mrt::murea::node;

// The first eight columns are a contract other tools read; new ones go at the end.
const char* const kHeader = "stamp,x,y,theta,cov_xx,cov_yy,cov_tt,mode,evidence,alt_x,alt_y,alt_theta,alt_evidence";

struct Stamped {
  ros::Time stamp;
  Pose2D pose;
};

// Reads the bag in time order and runs each percept frame through the pipeline.
class Evaluator {
 public:
  Evaluator(const mn::NodeOptions& o, const std::string& robot, std::ostream& out)
      : opt_(o), map_(mrt::world::load_map_world(o.map_file)), tracker_(map_, o.tracker), ns_("/" + robot), out_(out) {
    if (o.initial_pose) tracker_.set_pose(*o.initial_pose, o.initial_cov);
  }

  void run(rosbag::Bag& bag) {
    const std::vector<std::string> topics{ns_ + "/percepts", ns_ + "/odom", ns_ + "/ground_truth", "/tf", "/tf_static"};
    rosbag::View view(bag, rosbag::TopicQuery(topics));
    for (const rosbag::ConnectionInfo* c : view.getConnections()) odom_topic_ = odom_topic_ || c->topic == ns_ + "/odom";
    const ros::Time begin = view.getBeginTime();
    mrt::cli::Progress progress("murea_eval", (view.getEndTime() - begin).toSec());
    out_ << kHeader << '\n';
    for (const rosbag::MessageInstance& m : view) {
      progress.update((m.getTime() - begin).toSec());
      if (const auto tf = m.instantiate<tf2_msgs::TFMessage>()) {
        for (const auto& t : tf->transforms) {
          buffer_.setTransform(t, "bag", m.getTopic() == "/tf_static");
          if (t.child_frame_id == opt_.frame_prefix + opt_.base_frame) odom_stamp_ = std::max(odom_stamp_, t.header.stamp);
        }
      } else if (const auto od = m.instantiate<nav_msgs::Odometry>()) {
        const Stamped s{od->header.stamp, rc::to_pose2d(od->pose.pose)};
        if (m.getTopic() != ns_ + "/odom") {
          truth_.push_back(s);
          continue;
        }
        odom_prev_ = odom_msg_;
        odom_msg_ = s;
        odom_stamp_ = std::max(odom_stamp_, s.stamp);
      } else if (const auto p = m.instantiate<mrt_msgs::Percept>()) {
        pending_.push_back(*p);
      }
      // A frame waits until odometry at or after its stamp has been read
      // (odometry is then interpolated at the stamp, not the latest one).
      while (!pending_.empty() && pending_.front().header.stamp <= odom_stamp_) {
        frame(pending_.front());
        pending_.pop_front();
      }
    }
    for (; !pending_.empty(); pending_.pop_front()) frame(pending_.front());
    progress.finish();
  }

  void summary() const {
    std::cout << "frames: " << frames_ << "\nestimates: " << estimates_.size() << " (" << globals_
              << " global)\nambiguous: " << ambiguous_ << "\nskipped: " << no_odom_ << " without odometry, " << unknown_frame_
              << " in an unknown frame\ndropped percepts: " << drops_.non_finite << " non-finite, "
              << drops_.non_map_class << " not a map class, " << drops_.ontology.total() << " not in the ontology\n";
    if (truth_.empty()) return;
    double d2 = 0, t2 = 0, worst = 0;
    std::size_t n = 0;
    for (const Stamped& e : estimates_) {
      const std::optional<Pose2D> t = truth_at(e.stamp);
      if (!t) continue;
      const double d = std::hypot(e.pose.x - t->x, e.pose.y - t->y), a = mrt::common::angle_diff(e.pose.theta, t->theta);
      d2 += d * d;
      t2 += a * a;
      worst = std::max(worst, d);
      ++n;
    }
    std::printf("compared with ground truth: %zu\n", n);
    if (n == 0) return;
    std::printf("rmse_xy: %.4f m\nrmse_theta: %.3f deg\nworst_xy: %.4f m\n", std::sqrt(d2 / n),
                mrt::common::rad_to_deg(std::sqrt(t2 / n)), worst);
  }

 private:
  std::optional<Pose2D> lookup(const std::string& target, const std::string& source, const ros::Time& stamp) const {
    for (const ros::Time& t : {stamp, ros::Time(0)}) {
      try {
        return rc::to_pose2d(to_pose(buffer_.lookupTransform(target, source, t)));
      } catch (const tf2::TransformException&) {
      }
    }
    return std::nullopt;
  }

  static geometry_msgs::Pose to_pose(const geometry_msgs::TransformStamped& t) {
    geometry_msgs::Pose p;
    p.position.x = t.transform.translation.x;
    p.position.y = t.transform.translation.y;
    p.orientation = t.transform.rotation;
    return p;
  }

  void frame(const mrt_msgs::Percept& msg) {
    ++frames_;
    const std::string base = opt_.frame_prefix + opt_.base_frame;
    const std::optional<Pose2D> mount =
        msg.header.frame_id.empty() || msg.header.frame_id == base ? Pose2D() : lookup(base, msg.header.frame_id, msg.header.stamp);
    const std::optional<Pose2D> odom =
        odom_topic_ ? odom_at(msg.header.stamp) : lookup(opt_.frame_prefix + opt_.odom_frame, base, msg.header.stamp);
    if (!mount) ++unknown_frame_;
    if (!odom) ++no_odom_;
    if (!mount || !odom) return;
    std::vector<mrt::murea::Percept> ps = mn::to_percepts(msg, drops_);
    mn::to_base_frame(ps, *mount);
    const mrt::murea::TrackResult r = mn::track_frame(tracker_, &last_odom_, *odom, ps, opt_);
    const bool ambiguous = r.lost && r.search.ambiguous;
    if (r.lost && !ambiguous) return;
    const bool global = r.mode == mrt::murea::TrackMode::Global;
    // An ambiguous search's row: its best pose (the plateau's mean when
    // the search completed) with the plateau's covariance.
    const bool plateau = r.search.estimate.poses > 0;
    const Pose2D pose = !ambiguous ? r.pose : plateau ? r.search.estimate.mean : r.search.best.pose;
    const mrt::murea::Covariance3 cov = !ambiguous ? r.covariance : r.search.estimate.covariance;
    if (ambiguous) {
      ++ambiguous_;
    } else {
      globals_ += global ? 1 : 0;
      estimates_.push_back({msg.header.stamp, r.pose});
    }
    char row[384];
    int n = std::snprintf(row, sizeof row, "%u.%09u,%.4f,%.4f,%.5f,%.6g,%.6g,%.6g,%s,%.4f", msg.header.stamp.sec,
                          msg.header.stamp.nsec, pose.x, pose.y, pose.theta, cov[0], cov[4], cov[8],
                          ambiguous ? "ambiguous" : global ? "global" : "tracking", r.search.best.evidence);
    if (const auto& alt = r.search.alternative)
      std::snprintf(row + n, sizeof row - n, ",%.4f,%.4f,%.5f,%.4f\n", alt->pose.x, alt->pose.y, alt->pose.theta,
                    alt->evidence);
    else
      std::snprintf(row + n, sizeof row - n, ",,,,\n");
    out_ << row;
  }

  static Pose2D interpolate(const Stamped& a, const Stamped& b, const ros::Time& stamp) {
    const double span = (b.stamp - a.stamp).toSec(), f = span > 0.0 ? (stamp - a.stamp).toSec() / span : 1.0;
    return Pose2D(a.pose.x + f * (b.pose.x - a.pose.x), a.pose.y + f * (b.pose.y - a.pose.y),
                  a.pose.theta + f * mrt::common::angle_diff(b.pose.theta, a.pose.theta));
  }

  // The odometry topic's pose at `stamp`: interpolated between the last two
  // messages when they bracket it, else the last one.
  std::optional<Pose2D> odom_at(const ros::Time& stamp) const {
    if (!odom_msg_) return std::nullopt;
    if (odom_prev_ && odom_prev_->stamp <= stamp && stamp <= odom_msg_->stamp) return interpolate(*odom_prev_, *odom_msg_, stamp);
    return odom_msg_->pose;
  }

  // The ground truth at `stamp`, interpolated between the two nearest
  // messages (none when `stamp` is outside their span by more than 0.1 s).
  std::optional<Pose2D> truth_at(const ros::Time& stamp) const {
    auto it = std::lower_bound(truth_.begin(), truth_.end(), stamp,
                               [](const Stamped& s, const ros::Time& t) { return s.stamp < t; });
    if (it == truth_.end()) return (stamp - truth_.back().stamp).toSec() <= 0.1 ? std::optional(truth_.back().pose) : std::nullopt;
    if (it == truth_.begin() || it->stamp == stamp)
      return (it->stamp - stamp).toSec() <= 0.1 ? std::optional(it->pose) : std::nullopt;
    return interpolate(*(it - 1), *it, stamp);
  }

  mn::NodeOptions opt_;
  mrt::murea::FeatureMap map_;
  mrt::murea::Tracker tracker_;
  std::string ns_;
  std::ostream& out_;
  tf2::BufferCore buffer_;
  bool odom_topic_ = false;
  std::optional<Stamped> odom_msg_, odom_prev_;  // the last two odometry messages
  ros::Time odom_stamp_;                         // latest odometry stamp read (topic or tf)
  std::deque<mrt_msgs::Percept> pending_;        // frames waiting for their odometry
  std::optional<Pose2D> last_odom_;
  std::vector<Stamped> truth_, estimates_;
  mn::DropCounts drops_;
  std::size_t frames_ = 0, globals_ = 0, ambiguous_ = 0, no_odom_ = 0, unknown_frame_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs murea_node's pipeline over a bag: one row per estimate", "murea_eval"};
  std::string bag_file, robot, out_file;
  mn::NodeOptions o;
  std::vector<double> accuracy{0.05, mrt::common::deg_to_rad(1.0)}, initial;
  o.tracker.search.timeout = 0.05;
  o.tracker.search.timeout_cpu = true;  // as murea_node: CPU time of this thread
  app.add_option("--map", o.map_file, "world file or map_server map (YAML)")->required();
  app.add_option("--bag", bag_file, "bag with /NS/percepts and /NS/odom or tf (/NS/ground_truth optional)")->required();
  app.add_option("--robot", robot, "the robot's namespace NS (frames NS/odom, NS/base_link)")->required();
  app.add_option("--out", out_file, std::string("CSV: ") + kHeader)->required();
  app.add_option("--accuracy", accuracy, "lattice spacing: XY (m) THETA (rad), default 0.05 0.0174533 (1 deg)")->expected(2);
  app.add_option("--timeout", o.tracker.search.timeout, "seconds of CPU time per search (0 = no limit), default 0.05");
  app.add_option("--initial-pose", initial,
                 "X Y A: track from this pose at the first frame (m, m, rad; amcl's initial pose, covariance "
                 "0.25 m^2, 0.25 m^2, 0.0685 rad^2); default: a global search")
      ->expected(3);
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  if (!initial.empty()) {
    if (!std::isfinite(initial[0]) || !std::isfinite(initial[1]) || !std::isfinite(initial[2])) {
      std::cerr << "murea_eval: --initial-pose: expected three finite numbers X Y A\n";
      return 2;
    }
    o.initial_pose = Pose2D(initial[0], initial[1], initial[2]);
  }
  o.tracker.search.accuracy_xy = accuracy[0];
  o.tracker.search.accuracy_theta = accuracy[1];
  o.frame_prefix = robot + "/";
  try {
    std::ofstream out(out_file);
    if (!out) throw std::runtime_error(out_file + ": cannot write");
    Evaluator eval(o, robot, out);
    rosbag::Bag bag(bag_file, rosbag::bagmode::Read);
    eval.run(bag);
    eval.summary();
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "murea_eval: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
