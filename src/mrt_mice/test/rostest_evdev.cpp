// rostest of mice_evdev_node: events written to FIFOs (the node reads them
// as it reads /dev/input/event*) come out as MiceReading counts in the
// mouse frame; while a device is unplugged no reading is published (and the
// diagnostics name it); it is reconnected, and the first reading after that
// holds only the motion since the reconnection.
#include <fcntl.h>
#include <linux/input.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <mrt_msgs/MiceReading.h>
#include <ros/ros.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

std::string dir;
long long sum_ldx = 0, sum_ldy = 0, sum_rdx = 0, sum_rdy = 0;
int readings = 0;
std::string right_status, readings_status;

void on_mice(const mrt_msgs::MiceReading::ConstPtr& m) {
  sum_ldx += m->left.dx;
  sum_ldy += m->left.dy;
  sum_rdx += m->right.dx;
  sum_rdy += m->right.dy;
  ++readings;
}

void on_diag(const diagnostic_msgs::DiagnosticArray::ConstPtr& d) {
  for (const auto& s : d->status) {
    if (s.name.find("right mouse") != std::string::npos) right_status = s.message;
    if (s.name.find("mice readings") != std::string::npos)
      readings_status = std::to_string(s.level) + " " + s.message;
  }
}

// Plugs a "device" in: a FIFO held open read-write by the test, so that the
// node never sees end of file while it is plugged and writes never block.
int plug(const std::string& path) {
  ::unlink(path.c_str());
  if (::mkfifo(path.c_str(), 0600) != 0) return -1;
  return ::open(path.c_str(), O_RDWR | O_NONBLOCK);
}

void event(int fd, int type, int code, int value) {
  input_event e{};
  e.type = static_cast<std::uint16_t>(type);
  e.code = static_cast<std::uint16_t>(code);
  e.value = value;
  ASSERT_EQ(::write(fd, &e, sizeof e), static_cast<ssize_t>(sizeof e));
}

using mrt::ros_common::spin_for;
using mrt::ros_common::wait_for;

TEST(MiceEvdevNode, PublishesCountsAndReconnects) {
  ros::NodeHandle nh;
  auto sub = nh.subscribe("/mice", 1000, on_mice);
  auto dsub = nh.subscribe("/diagnostics", 100, on_diag);
  const std::string left = dir + "/left", right = dir + "/right";
  const int lw = plug(left), rw = plug(right);
  ASSERT_GE(lw, 0) << left;
  ASSERT_GE(rw, 0) << right;
  ASSERT_TRUE(wait_for([] { return right_status == "connected"; }, 10.0))
      << "the node did not open the devices: " << right_status;
  ASSERT_TRUE(wait_for([] { return readings > 3; }, 10.0)) << "no MiceReading";
  // Left mouse pushed forward 120 counts in 12 reports; right mouse to its
  // left (REL_X < 0) by 30.
  for (int i = 0; i < 12; ++i) {
    event(lw, EV_REL, REL_Y, -10);
    event(lw, EV_SYN, SYN_REPORT, 0);
  }
  event(rw, EV_REL, REL_X, -30);
  event(rw, EV_REL, REL_X, 0);
  event(rw, EV_SYN, SYN_REPORT, 0);
  event(rw, EV_REL, REL_X, 99);  // never committed: no SYN_REPORT follows
  EXPECT_TRUE(wait_for([] { return sum_ldx == 120 && sum_rdy == 30; }, 5.0))
      << sum_ldx << " " << sum_rdy;
  spin_for(0.2);
  EXPECT_EQ(sum_ldy, 0);
  EXPECT_EQ(sum_rdx, 0);
  EXPECT_EQ(sum_rdy, 30);

  // Unplug the right mouse: diagnostics say so (ERROR naming the device),
  // and no reading is published while it is away, although the left mouse
  // moves: it is not a mouse standing still.
  ::close(rw);
  ::unlink(right.c_str());
  EXPECT_TRUE(wait_for([] { return right_status.find("disconnected") == 0; }, 5.0)) << right_status;
  const std::string error = std::to_string(diagnostic_msgs::DiagnosticStatus::ERROR) +
                            " no readings published: missing right mouse " + right;
  EXPECT_TRUE(wait_for([&] { return readings_status == error; }, 5.0)) << readings_status;
  const int before = readings;
  for (int i = 0; i < 5; ++i) {
    event(lw, EV_REL, REL_Y, -100);  // left pushed 500 counts during the outage
    event(lw, EV_SYN, SYN_REPORT, 0);
  }
  spin_for(1.0);  // 50 publication periods
  EXPECT_EQ(readings, before) << "readings published while the right mouse was unplugged";
  EXPECT_EQ(sum_ldx, 120) << "the outage's left counts were published";
  // Plug it back: the node reopens it and publishes again; the first
  // readings hold only what both mice did after the reconnection.
  const int rw2 = plug(right);
  ASSERT_GE(rw2, 0);
  event(rw2, EV_REL, REL_Y, 7);  // pulled backwards
  event(rw2, EV_SYN, SYN_REPORT, 0);
  EXPECT_TRUE(wait_for([] { return sum_rdx == -7; }, 5.0)) << sum_rdx;
  EXPECT_GT(readings, before);
  event(lw, EV_REL, REL_Y, -3);
  event(lw, EV_SYN, SYN_REPORT, 0);
  EXPECT_TRUE(wait_for([] { return sum_ldx == 123; }, 5.0)) << sum_ldx << " (120 + 3 expected)";
  spin_for(0.2);
  EXPECT_EQ(sum_ldx, 123);
  EXPECT_TRUE(wait_for([] { return right_status.find("disconnected") != 0; }, 5.0)) << right_status;
  EXPECT_TRUE(wait_for([] { return readings_status == "0 publishing"; }, 5.0)) << readings_status;
  ::close(rw2);
  ::close(lw);
  ::unlink(left.c_str());
  ::unlink(right.c_str());
  ::rmdir(dir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mice_evdev_rostest");
  ros::NodeHandle pnh("~");
  pnh.param("dir", dir, std::string("/tmp/mrt_mice_evdev_rostest"));
  ::mkdir(dir.c_str(), 0700);
  return RUN_ALL_TESTS();
}
