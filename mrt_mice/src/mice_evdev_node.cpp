// mice_evdev_node: the driver of the two-mouse sensor. Reads two optical
// mice from Linux evdev devices (grabbed, so the desktop cursor does not
// move), and publishes their raw counts as mrt_msgs/MiceReading at a fixed
// rate, exactly as mrt_sim does. Unplugged devices are reopened every
// ~reconnect_period seconds; diagnostics report each device. While either
// device is missing no reading is published (a missing mouse is not a mouse
// standing still): the samples are withheld and counted, and the first
// sample after a reconnection covers only the motion since then.
#include <diagnostic_updater/diagnostic_updater.h>
#include <mrt_msgs/MiceReading.h>
#include <poll.h>
#include <ros/ros.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "mrt_mice/evdev_mouse.h"

namespace mrt::mice {
namespace {

struct DriverOptions {
  std::string left_device, right_device;  // ~left_device, ~right_device (required)
  std::string left_id = "left", right_id = "right";
  std::string frame_prefix;  // ~frame_prefix: mouse frames are <prefix><id>_mouse
  double rate = 50.0;        // ~rate: Hz of MiceReading
  bool grab = true;          // ~grab: exclusive access (EVIOCGRAB)
  double reconnect_period = 1.0;  // ~reconnect_period: s between reopen attempts
};

DriverOptions load_options(const ros::NodeHandle& pnh) {
  DriverOptions o;
  if (!pnh.getParam("left_device", o.left_device) || o.left_device.empty())
    throw std::invalid_argument("~left_device: required (e.g. /dev/input/by-id/usb-...-event-mouse)");
  if (!pnh.getParam("right_device", o.right_device) || o.right_device.empty())
    throw std::invalid_argument("~right_device: required");
  pnh.param("left_id", o.left_id, o.left_id);
  pnh.param("right_id", o.right_id, o.right_id);
  pnh.param("frame_prefix", o.frame_prefix, o.frame_prefix);
  pnh.param("rate", o.rate, o.rate);
  pnh.param("grab", o.grab, o.grab);
  pnh.param("reconnect_period", o.reconnect_period, o.reconnect_period);
  if (!(o.rate > 0.0 && o.rate <= 1000.0)) throw std::invalid_argument("~rate: must be in (0, 1000] Hz");
  if (!(o.reconnect_period > 0.0)) throw std::invalid_argument("~reconnect_period: must be > 0");
  if (o.left_device == o.right_device)
    throw std::invalid_argument("~right_device: must differ from ~left_device");
  return o;
}

class MiceEvdevNode {
 public:
  MiceEvdevNode(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : opt_(load_options(pnh)), left_(opt_.left_device, opt_.grab), right_(opt_.right_device, opt_.grab) {
    pub_ = nh.advertise<mrt_msgs::MiceReading>("mice", 100);
    diag_.setHardwareID(opt_.left_device + " " + opt_.right_device);
    diag_.add("left mouse", [this](diagnostic_updater::DiagnosticStatusWrapper& s) { diagnose(s, 0); });
    diag_.add("right mouse", [this](diagnostic_updater::DiagnosticStatusWrapper& s) { diagnose(s, 1); });
    diag_.add("mice readings", this, &MiceEvdevNode::diagnose_readings);
    reader_ = std::thread([this] { read_loop(); });
    timer_ = nh.createTimer(ros::Duration(1.0 / opt_.rate), &MiceEvdevNode::publish, this);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
  }

  ~MiceEvdevNode() {
    stop_ = true;
    if (reader_.joinable()) reader_.join();
  }

 private:
  // Reads both devices continuously (the kernel buffer of a 1 kHz mouse
  // would overflow between two publications) and reopens missing ones.
  void read_loop() {
    ros::WallTime next_try;
    while (!stop_) {
      const ros::WallTime now = ros::WallTime::now();
      if (now >= next_try) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (int i = 0; i < 2; ++i) {
          EvdevMouse& m = i ? right_ : left_;
          if (!m.connected()) {
            if (m.open()) {
              ROS_INFO("mice_evdev: opened %s%s", m.path().c_str(), m.grabbed() ? " (grabbed)" : "");
              // Both mice start afresh: what the other one counted while this
              // one was away has no partner and is dropped.
              discard_counts();
            } else
              ROS_WARN_THROTTLE(10.0, "mice_evdev: %s", m.last_error().c_str());
          }
        }
        next_try = now + ros::WallDuration(opt_.reconnect_period);
      }
      pollfd fds[2];
      int n = 0;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (left_.connected()) fds[n++] = {left_.fd(), POLLIN, 0};
        if (right_.connected()) fds[n++] = {right_.fd(), POLLIN, 0};
      }
      if (n == 0) {
        ros::WallDuration(0.05).sleep();
        continue;
      }
      ::poll(fds, static_cast<nfds_t>(n), 50);
      std::lock_guard<std::mutex> lock(mutex_);
      for (int i = 0; i < 2; ++i) {
        EvdevMouse& m = i ? right_ : left_;
        if (m.connected() && !m.poll(i ? right_acc_ : left_acc_)) {
          ++unplugs_[i];
          ROS_ERROR("mice_evdev: lost %s; reconnecting", m.last_error().c_str());
        }
      }
    }
  }

  // Drops the counts accumulated so far (mutex_ held).
  void discard_counts() {
    std::int64_t dx, dy;
    left_acc_.take(&dx, &dy);
    right_acc_.take(&dx, &dy);
  }

  void publish(const ros::TimerEvent&) {
    mrt_msgs::MiceReading r;
    r.header.stamp = ros::Time::now();
    r.header.frame_id = opt_.frame_prefix + "base_link";
    std::int64_t ldx, ldy, rdx, rdy;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!left_.connected() || !right_.connected()) {
        // A sample needs both mice: publishing zeros for the missing one
        // would tell the odometry that it stood still.
        discard_counts();
        ++withheld_;
        ROS_WARN_THROTTLE(5.0, "mice_evdev: %s missing; no readings published (%llu withheld)",
                          missing().c_str(), static_cast<unsigned long long>(withheld_));
        return;
      }
      left_acc_.take(&ldx, &ldy);
      right_acc_.take(&rdx, &rdy);
    }
    auto fill = [&](mrt_msgs::MouseReading& m, const std::string& id, std::int64_t dx, std::int64_t dy) {
      m.header.stamp = r.header.stamp;
      m.header.frame_id = opt_.frame_prefix + id + "_mouse";
      m.mouse_id = id;
      m.dx = static_cast<std::int32_t>(dx);
      m.dy = static_cast<std::int32_t>(dy);
    };
    fill(r.left, opt_.left_id, ldx, ldy);
    fill(r.right, opt_.right_id, rdx, rdy);
    pub_.publish(r);
  }

  // The missing devices, e.g. "right mouse /dev/input/..." (mutex_ held).
  std::string missing() const {
    std::string out;
    for (int i = 0; i < 2; ++i) {
      const EvdevMouse& m = i ? right_ : left_;
      if (m.connected()) continue;
      if (!out.empty()) out += " and ";
      out += std::string(i ? "right" : "left") + " mouse " + m.path();
    }
    return out;
  }

  void diagnose_readings(diagnostic_updater::DiagnosticStatusWrapper& s) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!left_.connected() || !right_.connected())
      s.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "no readings published: missing " + missing());
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "publishing");
    s.add("withheld samples", withheld_);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s, int i) {
    std::lock_guard<std::mutex> lock(mutex_);
    const EvdevMouse& m = i ? right_ : left_;
    const EvdevAccumulator& a = i ? right_acc_ : left_acc_;
    if (!m.connected())
      s.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "disconnected: " + m.last_error());
    else if (opt_.grab && !m.grabbed())
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "not grabbed: " + m.last_error());
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "connected");
    s.add("device", m.path());
    s.add("connects", m.connects());
    s.add("unplugs", unplugs_[i]);
    s.add("reports", a.reports());
    s.add("dropped (SYN_DROPPED)", a.dropped());
  }

  DriverOptions opt_;
  EvdevMouse left_, right_;
  EvdevAccumulator left_acc_, right_acc_;
  std::uint64_t unplugs_[2] = {0, 0};
  std::uint64_t withheld_ = 0;  // samples not published because a mouse was missing
  std::mutex mutex_;
  std::atomic<bool> stop_{false};
  std::thread reader_;
  ros::Publisher pub_;
  ros::Timer timer_, diag_timer_;
  diagnostic_updater::Updater diag_;
};

}  // namespace
}  // namespace mrt::mice

int main(int argc, char** argv) {
  ros::init(argc, argv, "mice_evdev");
  ros::NodeHandle nh, pnh("~");
  std::unique_ptr<mrt::mice::MiceEvdevNode> node;
  try {
    node = std::make_unique<mrt::mice::MiceEvdevNode>(nh, pnh);
  } catch (const std::exception& e) {
    ROS_FATAL("mice_evdev: %s", e.what());
    return 1;
  }
  ros::spin();
  return 0;
}
