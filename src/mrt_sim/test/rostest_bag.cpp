// rostest of sim_node: records the mice and vision topics of a robot driven
// straight with the real `rosbag record`, replays the bag with `rosbag play`
// (remapped to /replay/...) and checks that the replay delivers exactly the
// messages seen live, then checks counts (rate x duration, +-1) and contents:
// the summed mouse counts equal the ground-truth displacement seen in each
// mouse's frame (mounts from the static tf), and the percepts name their
// producer and hold the expected classes with distances that match the
// ground truth.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <mrt_msgs/MiceReading.h>
#include <mrt_msgs/Percept.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "mrt_common_ros/rostest_helpers.h"

extern char** environ;

namespace {

using mrt::ros_common::wait_for;

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

const mrt_msgs::Attribute* attribute(const mrt_msgs::PerceptObject& o, const std::string& name) {
  for (const auto& a : o.attributes)
    if (a.name == name) return &a;
  return nullptr;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

// Starts a program found on PATH; returns its pid (0 on failure).
pid_t spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  return posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) == 0 ? pid : 0;
}

// Waits up to `seconds` of wall time for a child, spinning meanwhile;
// returns its exit status, or -1 if it is still running.
int wait_child(pid_t pid, double seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  int status = 0;
  while (ros::WallTime::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  return -1;
}

// How many nodes other than this one subscribe to `topic` (from the master).
int other_subscribers(const std::string& topic) {
  XmlRpc::XmlRpcValue req, res, payload;
  req[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", req, res, payload, false)) return 0;
  XmlRpc::XmlRpcValue& subs = payload[1];
  for (int i = 0; i < subs.size(); ++i) {
    if (static_cast<std::string>(subs[i][0]) != topic) continue;
    int n = 0;
    for (int j = 0; j < subs[i][1].size(); ++j)
      if (static_cast<std::string>(subs[i][1][j]) != ros::this_node::getName()) ++n;
    return n;
  }
  return 0;
}

bool same(const mrt_msgs::MiceReading& a, const mrt_msgs::MiceReading& b) {
  return a.header.stamp == b.header.stamp && a.left.dx == b.left.dx && a.left.dy == b.left.dy &&
         a.right.dx == b.right.dx && a.right.dy == b.right.dy && a.left.mouse_id == b.left.mouse_id &&
         a.right.mouse_id == b.right.mouse_id;
}

bool same(const mrt_msgs::Percept& a, const mrt_msgs::Percept& b) {
  if (a.header.stamp != b.header.stamp || a.objects.size() != b.objects.size()) return false;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const auto &x = a.objects[i], &y = b.objects[i];
    if (x.name != y.name || x.attributes.size() != y.attributes.size()) return false;
    for (std::size_t j = 0; j < x.attributes.size(); ++j)
      if (x.attributes[j].value != y.attributes[j].value || x.attributes[j].symbol != y.attributes[j].symbol)
        return false;
  }
  return true;
}

class BagTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::NodeHandle pnh("~");
    pnh.param("robot", robot_, std::string("robot1"));
    // Unique per run so parallel test runs do not share a file.
    pnh.param("bag", bag_path_, "/tmp/mrt_sim_bag_test_" + std::to_string(::getpid()) + ".bag");
    pnh.param("duration", duration_, 3.0);
    pnh.param("speed", speed_, 0.3);
    pnh.param("rate_mice", rate_mice_, 50.0);
    pnh.param("rate_vision", rate_vision_, 10.0);
    pnh.param("counts_per_m", counts_per_m_, 15748.0);
    std::string classes;
    pnh.param("expected_classes", classes, std::string("Ball"));
    expected_classes_ = split(classes);
    pnh.param("ball_x", ball_x_, 0.0);
    pnh.param("ball_y", ball_y_, 0.0);
    ns_ = "/" + robot_ + "/";
  }

  // Subscribes to the live topics, the replayed ones and the ground truth.
  void subscribe() {
    subs_.push_back(nh_.subscribe<mrt_msgs::MiceReading>(ns_ + "mice", 1000, [this](const mrt_msgs::MiceReading::ConstPtr& m) {
      live_mice_[m->header.stamp.toNSec()] = *m;
    }));
    subs_.push_back(nh_.subscribe<mrt_msgs::Percept>(ns_ + "percepts", 1000, [this](const mrt_msgs::Percept::ConstPtr& m) {
      live_percepts_[m->header.stamp.toNSec()] = *m;
    }));
    subs_.push_back(nh_.subscribe<nav_msgs::Odometry>(
        ns_ + "ground_truth", 20000, [this](const nav_msgs::Odometry::ConstPtr& m) { gt_.push_back(*m); },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay()));
    subs_.push_back(nh_.subscribe<mrt_msgs::MiceReading>(
        "/replay/mice", 1000, [this](const mrt_msgs::MiceReading::ConstPtr& m) { replay_mice_.push_back(*m); }));
    subs_.push_back(nh_.subscribe<mrt_msgs::Percept>(
        "/replay/percepts", 1000, [this](const mrt_msgs::Percept::ConstPtr& m) { replay_percepts_.push_back(*m); }));
    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(ns_ + "cmd_vel", 10);
  }

  // Waits for the simulator, records mice and percepts with rosbag while
  // driving straight, and stops the recorder.
  void record_while_driving() {
    wait_for([&] {
      return !gt_.empty() && cmd_pub_.getNumSubscribers() > 0 && subs_[0].getNumPublishers() > 0 &&
             subs_[1].getNumPublishers() > 0;
    }, 30.0);
    ASSERT_FALSE(gt_.empty()) << "no ground truth from sim_node";
    ASSERT_GT(cmd_pub_.getNumSubscribers(), 0u);

    // Record with rosbag, from when it has subscribed to both topics.
    const pid_t rec = spawn({"rosbag", "record", "--quiet", "-O", bag_path_, ns_ + "mice", ns_ + "percepts"});
    ASSERT_GT(rec, 0) << "cannot start rosbag record";
    wait_for([&] { return other_subscribers(ns_ + "mice") > 0 && other_subscribers(ns_ + "percepts") > 0; }, 30.0,
             0.05);
    ASSERT_GT(other_subscribers(ns_ + "percepts"), 0) << "rosbag record did not subscribe";
    ros::WallDuration(0.5).sleep();  // let its connections come up

    // Drive straight; stop after the recording window plus a margin.
    geometry_msgs::Twist cmd;
    cmd.linear.x = speed_;
    const double t_begin = gt_.back().header.stamp.toSec();
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(60.0);
    ros::WallTime next_cmd = ros::WallTime::now();
    while (ros::ok() && ros::WallTime::now() < give_up &&
           gt_.back().header.stamp.toSec() < t_begin + duration_ + 1.0) {
      if (ros::WallTime::now() >= next_cmd) {
        cmd_pub_.publish(cmd);
        next_cmd += ros::WallDuration(0.02);
      }
      ros::spinOnce();
      ros::WallDuration(0.001).sleep();
    }
    cmd_pub_.publish(geometry_msgs::Twist());
    kill(rec, SIGINT);
    ASSERT_GE(wait_child(rec, 30.0), 0) << "rosbag record did not stop";
  }

  // Ground truth by stamp (every step is published); straight motion: the
  // heading never changes.
  void index_ground_truth() {
    bool moving_seen = false;
    for (const auto& m : gt_) {
      gt_at_[m.header.stamp.toNSec()] = m;
      if (m.twist.twist.linear.x != 0.0) {
        if (moving_seen) {
          ASSERT_NEAR(yaw_of(m.pose.pose.orientation), heading_, 1e-9);
        }
        heading_ = yaw_of(m.pose.pose.orientation);
        moving_seen = true;
      }
    }
    ASSERT_TRUE(moving_seen) << "the robot never moved";
  }

  // The bag holds what was published live, unchanged.
  void read_bag() {
    // `rosbag record` may exit before its recorder child has renamed the
    // .bag.active file: wait for the bag itself.
    wait_for([&] { return ::access(bag_path_.c_str(), F_OK) == 0; }, 10.0, 0.05);
    rosbag::Bag in(bag_path_, rosbag::bagmode::Read);
    rosbag::View view(in, rosbag::TopicQuery({ns_ + "mice", ns_ + "percepts"}));
    for (const rosbag::MessageInstance& mi : view) {
      if (auto m = mi.instantiate<mrt_msgs::MiceReading>()) {
        ASSERT_TRUE(live_mice_.count(m->header.stamp.toNSec())) << "recorded a mice message never published";
        EXPECT_TRUE(same(*m, live_mice_[m->header.stamp.toNSec()]));
        mice_.push_back(*m);
      } else if (auto p = mi.instantiate<mrt_msgs::Percept>()) {
        ASSERT_TRUE(live_percepts_.count(p->header.stamp.toNSec())) << "recorded a percept never published";
        EXPECT_TRUE(same(*p, live_percepts_[p->header.stamp.toNSec()]));
        percepts_.push_back(*p);
      } else {
        ADD_FAILURE() << "unexpected type " << mi.getDataType() << " on " << mi.getTopic();
      }
    }
    in.close();
    ASSERT_GT(mice_.size(), 0u) << "no mice messages recorded";
    ASSERT_GT(percepts_.size(), 0u) << "no percepts recorded";
  }

  // Replay it (4x, remapped) and receive exactly the recorded messages, in order.
  void replay() {
    const pid_t play = spawn({"rosbag", "play", "--quiet", "--wait-for-subscribers", "-r", "4", bag_path_,
                              ns_ + "mice:=/replay/mice", ns_ + "percepts:=/replay/percepts"});
    ASSERT_GT(play, 0) << "cannot start rosbag play";
    ASSERT_EQ(wait_child(play, 60.0), 0) << "rosbag play failed or did not finish";
    wait_for([&] { return replay_mice_.size() >= mice_.size() && replay_percepts_.size() >= percepts_.size(); }, 2.0);
    ASSERT_EQ(replay_mice_.size(), mice_.size());
    ASSERT_EQ(replay_percepts_.size(), percepts_.size());
    for (std::size_t i = 0; i < mice_.size(); ++i) EXPECT_TRUE(same(replay_mice_[i], mice_[i])) << "mice #" << i;
    for (std::size_t i = 0; i < percepts_.size(); ++i)
      EXPECT_TRUE(same(replay_percepts_[i], percepts_[i])) << "percept #" << i;
  }

  // Window: from the first mouse sample after motion started, for
  // `duration`; counts: rate x duration within one (by header stamp, in
  // (ta, tb]).
  void select_window() {
    std::size_t first = 0;
    while (first < mice_.size() && gt_at_.count(mice_[first].header.stamp.toNSec()) &&
           gt_at_[mice_[first].header.stamp.toNSec()].twist.twist.linear.x == 0.0)
      ++first;
    ASSERT_LT(first, mice_.size());
    ta_ = mice_[first].header.stamp;
    const ros::Time tb = ta_ + ros::Duration(duration_);
    for (const auto& m : mice_)
      if (m.header.stamp > ta_ && m.header.stamp <= tb) mice_window_.push_back(m);
    for (const auto& p : percepts_)
      if (p.header.stamp > ta_ && p.header.stamp <= tb) vision_window_.push_back(p);
    EXPECT_NEAR(static_cast<double>(mice_window_.size()), rate_mice_ * duration_, 1.0);
    EXPECT_NEAR(static_cast<double>(vision_window_.size()), rate_vision_ * duration_, 1.0);
  }

  // Summed mouse counts over (ta, tlast] against the ground-truth displacement.
  void check_mouse_counts() {
    std::map<std::string, std::pair<long, long>> sum;
    ros::Time tlast = ta_;
    std::string left_frame, right_frame, left_id, right_id;
    for (const auto& m : mice_window_) {
      EXPECT_EQ(m.header.frame_id, robot_ + "/base_link_truth");
      sum[m.left.mouse_id].first += m.left.dx;
      sum[m.left.mouse_id].second += m.left.dy;
      sum[m.right.mouse_id].first += m.right.dx;
      sum[m.right.mouse_id].second += m.right.dy;
      left_frame = m.left.header.frame_id;
      right_frame = m.right.header.frame_id;
      left_id = m.left.mouse_id;
      right_id = m.right.mouse_id;
      tlast = m.header.stamp;
    }
    ASSERT_TRUE(gt_at_.count(ta_.toNSec()) && gt_at_.count(tlast.toNSec()));
    const auto& pa = gt_at_[ta_.toNSec()].pose.pose.position;
    const auto& pb = gt_at_[tlast.toNSec()].pose.pose.position;
    // Body-frame displacement (pure translation at constant heading).
    const double dxw = pb.x - pa.x, dyw = pb.y - pa.y;
    const double bx = std::cos(heading_) * dxw + std::sin(heading_) * dyw;
    const double by = -std::sin(heading_) * dxw + std::cos(heading_) * dyw;
    EXPECT_NEAR(bx, speed_ * (tlast - ta_).toSec(), 1e-6);
    for (const auto& [frame, id] : {std::make_pair(left_frame, left_id), std::make_pair(right_frame, right_id)}) {
      geometry_msgs::TransformStamped mount;
      try {
        mount = tf_buffer_.lookupTransform(robot_ + "/base_link_truth", frame, ros::Time(0), ros::Duration(5.0));
      } catch (const tf2::TransformException& e) {
        FAIL() << "no static transform of " << frame << ": " << e.what();
      }
      const double phi = yaw_of(mount.transform.rotation);
      const double ex = counts_per_m_ * (std::cos(phi) * bx + std::sin(phi) * by);
      const double ey = counts_per_m_ * (-std::sin(phi) * bx + std::cos(phi) * by);
      std::printf("mouse %s: counts (%ld, %ld), expected (%.1f, %.1f)\n", id.c_str(), sum[id].first,
                  sum[id].second, ex, ey);
      EXPECT_NEAR(static_cast<double>(sum[id].first), ex, 2.0) << "mouse " << id;
      EXPECT_NEAR(static_cast<double>(sum[id].second), ey, 2.0) << "mouse " << id;
    }
  }

  // Percept contents; the ball within five standard deviations of the
  // vision noise of its true distance and bearing.
  void check_percepts() {
    std::set<std::string> classes;
    for (const auto& percept : vision_window_) {
      const mrt_msgs::Percept* p = &percept;
      EXPECT_EQ(p->sensor, "omnivision");
      EXPECT_EQ(p->robot, robot_);
      EXPECT_EQ(p->header.frame_id, robot_ + "/base_link_truth");
      EXPECT_FALSE(p->objects.empty());
      ASSERT_TRUE(gt_at_.count(p->header.stamp.toNSec())) << "percept stamp is not a step's stamp";
      const auto& pose = gt_at_[p->header.stamp.toNSec()].pose.pose;
      for (const auto& o : p->objects) {
        classes.insert(o.membership_class);
        const mrt_msgs::Attribute* d = attribute(o, "distance");
        const mrt_msgs::Attribute* b = attribute(o, "bearing");
        ASSERT_TRUE(d && b) << o.name << " lacks distance or bearing";
        EXPECT_TRUE(d->symbol.empty());
        EXPECT_GE(d->value, 0.0);
        EXPECT_LE(std::fabs(b->value), M_PI + 1e-9);
        if (o.membership_class == "Ball") {
          const mrt_msgs::Attribute* c = attribute(o, "color");
          ASSERT_TRUE(c) << "the ball has no color";
          EXPECT_FALSE(c->symbol.empty());
          const double true_d = std::hypot(ball_x_ - pose.position.x, ball_y_ - pose.position.y);
          const double true_b = std::remainder(
              std::atan2(ball_y_ - pose.position.y, ball_x_ - pose.position.x) - yaw_of(pose.orientation), 2 * M_PI);
          EXPECT_NEAR(d->value, true_d, 5.0 * d->variability + 1e-6);
          EXPECT_NEAR(std::remainder(b->value - true_b, 2 * M_PI), 0.0, 5.0 * b->variability + 1e-6);
        }
      }
    }
    for (const auto& c : expected_classes_) EXPECT_TRUE(classes.count(c)) << "no object of class " << c;
  }

  std::string robot_, bag_path_, ns_;
  double duration_ = 3.0, speed_ = 0.3, rate_mice_ = 50.0, rate_vision_ = 10.0,
         counts_per_m_ = 15748.0, ball_x_ = 0.0, ball_y_ = 0.0;
  std::vector<std::string> expected_classes_;

  ros::NodeHandle nh_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_{tf_buffer_};
  std::vector<ros::Subscriber> subs_;  // live mice, live percepts, ground truth, replayed mice and percepts
  ros::Publisher cmd_pub_;
  // Everything seen live, by stamp, and everything the replay delivers.
  std::map<std::int64_t, mrt_msgs::MiceReading> live_mice_;
  std::map<std::int64_t, mrt_msgs::Percept> live_percepts_;
  std::vector<mrt_msgs::MiceReading> replay_mice_;
  std::vector<mrt_msgs::Percept> replay_percepts_;
  std::vector<nav_msgs::Odometry> gt_;  // every step, kept in memory for the checks
  std::map<std::int64_t, nav_msgs::Odometry> gt_at_;
  double heading_ = 0.0;
  std::vector<mrt_msgs::MiceReading> mice_, mice_window_;  // recorded; in the window
  std::vector<mrt_msgs::Percept> percepts_, vision_window_;
  ros::Time ta_;
};

TEST_F(BagTest, RecordReplayAndCheck) {
  subscribe();
  ASSERT_NO_FATAL_FAILURE(record_while_driving());
  ASSERT_NO_FATAL_FAILURE(index_ground_truth());
  ASSERT_NO_FATAL_FAILURE(read_bag());
  ASSERT_NO_FATAL_FAILURE(replay());
  ASSERT_NO_FATAL_FAILURE(select_window());
  check_mouse_counts();
  check_percepts();
  if (!HasFailure()) std::remove(bag_path_.c_str());
  std::printf("bag: %zu mice and %zu percepts recorded and replayed; %zu and %zu in %.1f s\n", mice_.size(),
              percepts_.size(), mice_window_.size(), vision_window_.size(), duration_);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "bag_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
