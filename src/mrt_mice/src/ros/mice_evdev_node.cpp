// mice_evdev_node: the driver of the two-mouse sensor. Reads two optical
// mice from Linux evdev devices (grabbed, so the desktop cursor does not
// move), and publishes their raw counts as mrt_msgs/MiceReading at a fixed
// rate, exactly as mrt_sim does. Unplugged devices are reopened every
// ~reconnect_period seconds; diagnostics report each device. While either
// device is missing no reading is published (a missing mouse is not a mouse
// standing still): the samples are withheld and counted, and the first
// sample after a reconnection covers only the motion since then. Wiring
// only: the read loop is the ROS-free EvdevReader (evdev_reader.h).
#include <diagnostic_updater/diagnostic_updater.h>
#include <mrt_msgs/MiceReading.h>
#include <ros/ros.h>

#include <atomic>
#include <string>
#include <thread>

#include "mrt_common_ros/params.h"
#include "mrt_mice/evdev_reader.h"

namespace mrt::mice::node {
namespace {

using mrt::ros_common::ParamReader;

struct DriverOptions {
  EvdevReaderOptions reader;  // ~left_device, ~right_device (required), ~grab, ~reconnect_period
  std::string left_id = "left", right_id = "right";
  std::string frame_prefix;  // ~frame_prefix: mouse frames are <prefix><id>_mouse
  double rate = 50.0;        // ~rate: Hz of MiceReading
  bool align = true;         // ~align: both mice interpolated at a common instant (CountAligner)
};

DriverOptions load_options(const ros::NodeHandle& pnh) {
  DriverOptions o;
  ParamReader p(pnh);
  p.require("left_device", o.reader.left_device, "an evdev device path (e.g. /dev/input/by-id/usb-...-event-mouse)")
      .require("right_device", o.reader.right_device, "an evdev device path")
      .get("left_id", o.left_id)
      .get("right_id", o.right_id)
      .get("frame_prefix", o.frame_prefix)
      .get("rate", o.rate)
      .get("grab", o.reader.grab)
      .get("reconnect_period", o.reader.reconnect_period)
      .get("align", o.align)
      .get("align_delay", o.reader.align.delay)
      .get("align_frame", o.reader.align.frame);
  ParamReader::check(o.rate > 0.0 && o.rate <= 1000.0, "rate", "a number in (0, 1000] Hz");
  o.reader.validate();
  try {
    o.reader.align.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("~") + e.what());
  }
  return o;
}

class MiceEvdevNode {
 public:
  MiceEvdevNode(ros::NodeHandle& nh, const ros::NodeHandle& pnh)
      : opt_(load_options(pnh)),
        reader_(opt_.reader, [](EvdevReader::Event e, int, const std::string& text) { log(e, text); }) {
    pub_ = nh.advertise<mrt_msgs::MiceReading>("mice", 100);
    diag_.setHardwareID(opt_.reader.left_device + " " + opt_.reader.right_device);
    diag_.add("left mouse", [this](diagnostic_updater::DiagnosticStatusWrapper& s) { diagnose(s, 0); });
    diag_.add("right mouse", [this](diagnostic_updater::DiagnosticStatusWrapper& s) { diagnose(s, 1); });
    diag_.add("mice readings", this, &MiceEvdevNode::diagnose_readings);
    thread_ = std::thread([this] {
      while (!stop_)
        if (!reader_.step(ros::WallTime::now().toSec(), 50)) ros::WallDuration(0.05).sleep();
    });
    timer_ = nh.createTimer(ros::Duration(1.0 / opt_.rate), &MiceEvdevNode::publish, this);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
  }

  ~MiceEvdevNode() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }

 private:
  static void log(EvdevReader::Event e, const std::string& text) {
    if (e == EvdevReader::Event::kOpened)
      ROS_INFO("mice_evdev: %s", text.c_str());
    else if (e == EvdevReader::Event::kOpenFailed)
      ROS_WARN_THROTTLE(10.0, "mice_evdev: %s", text.c_str());
    else
      ROS_ERROR("mice_evdev: %s", text.c_str());
  }

  void publish(const ros::TimerEvent&) {
    mrt_msgs::MiceReading r;
    r.header.stamp = ros::Time::now();
    r.header.frame_id = opt_.frame_prefix + "base_link";
    // Aligned: the counts up to the common instant, delay before now (on
    // the events' clock, CLOCK_REALTIME: the wall clock).
    const std::optional<MiceCounts> c =
        opt_.align ? reader_.take(ros::WallTime::now().toSec()) : reader_.take();
    if (opt_.align) r.header.stamp -= ros::Duration(opt_.reader.align.delay);
    if (!c) {
      // A sample needs both mice: publishing zeros for the missing one
      // would tell the odometry that it stood still.
      ROS_WARN_THROTTLE(5.0, "mice_evdev: %s missing; no readings published (%llu withheld)",
                        reader_.missing().c_str(), static_cast<unsigned long long>(reader_.withheld()));
      return;
    }
    auto fill = [&](mrt_msgs::MouseReading& m, const std::string& id, std::int64_t dx, std::int64_t dy) {
      m.header.stamp = r.header.stamp;
      m.header.frame_id = opt_.frame_prefix + id + "_mouse";
      m.mouse_id = id;
      m.dx = static_cast<std::int32_t>(dx);
      m.dy = static_cast<std::int32_t>(dy);
    };
    fill(r.left, opt_.left_id, c->left_dx, c->left_dy);
    fill(r.right, opt_.right_id, c->right_dx, c->right_dy);
    pub_.publish(r);
  }

  void diagnose_readings(diagnostic_updater::DiagnosticStatusWrapper& s) {
    const std::string missing = reader_.missing();
    if (!missing.empty())
      s.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "no readings published: missing " + missing);
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "publishing");
    s.add("withheld samples", reader_.withheld());
    const AlignerStats a = reader_.align_stats();
    s.add("aligned", opt_.align ? "yes" : "no");
    s.add("reports out of order (dropped)", a.out_of_order);
    s.add("reports late (deferred)", a.late);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s, int i) {
    const EvdevDeviceStatus d = reader_.status(i);
    if (!d.connected)
      s.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "disconnected: " + d.last_error);
    else if (opt_.reader.grab && !d.grabbed)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "not grabbed: " + d.last_error);
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "connected");
    s.add("device", d.path);
    s.add("connects", d.connects);
    s.add("unplugs", d.unplugs);
    s.add("reports", d.reports);
    s.add("dropped (SYN_DROPPED)", d.dropped);
  }

  DriverOptions opt_;
  EvdevReader reader_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  ros::Publisher pub_;
  ros::Timer timer_, diag_timer_;
  diagnostic_updater::Updater diag_;
};

}  // namespace
}  // namespace mrt::mice::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "mice_evdev");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::mice::node::MiceEvdevNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
