// The evdev reader: event accumulation, frame mapping, unplug and replug
// (a FIFO stands in for the device: same read(2) of struct input_event).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <linux/input.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "mrt_mice/evdev_mouse.h"

using namespace mrt::mice;

namespace {

TEST(EvdevAccumulator, MapsAxesToTheMouseFrameAtSynReport) {
  EvdevAccumulator a;
  // Pushed forward (away from the user: REL_Y < 0) and to the right.
  a.feed(EV_REL, REL_Y, -10);
  a.feed(EV_REL, REL_X, 3);
  std::int64_t dx, dy;
  a.take(&dx, &dy);
  EXPECT_EQ(dx, 0);  // not committed before SYN_REPORT
  a.feed(EV_SYN, SYN_REPORT, 0);
  a.feed(EV_REL, REL_Y, -5);
  a.feed(EV_SYN, SYN_REPORT, 0);
  a.feed(EV_REL, REL_WHEEL, 1);  // ignored
  a.feed(EV_KEY, BTN_LEFT, 1);   // ignored
  a.feed(EV_SYN, SYN_REPORT, 0);
  a.take(&dx, &dy);
  EXPECT_EQ(dx, 15);  // forward
  EXPECT_EQ(dy, -3);  // to the right
  EXPECT_EQ(a.reports(), 3u);
  a.take(&dx, &dy);
  EXPECT_EQ(dx, 0);
  EXPECT_EQ(dy, 0);
}

TEST(EvdevAccumulator, DiscardsAfterSynDropped) {
  EvdevAccumulator a;
  a.feed(EV_REL, REL_X, 7);
  a.feed(EV_SYN, SYN_DROPPED, 0);
  a.feed(EV_REL, REL_X, 9);      // still part of the dropped report
  a.feed(EV_SYN, SYN_REPORT, 0);  // resynchronised
  a.feed(EV_REL, REL_X, -2);
  a.feed(EV_SYN, SYN_REPORT, 0);
  std::int64_t dx, dy;
  a.take(&dx, &dy);
  EXPECT_EQ(dy, 2);
  EXPECT_EQ(a.dropped(), 1u);
}

void write_event(int fd, int type, int code, int value) {
  input_event e{};
  e.type = static_cast<std::uint16_t>(type);
  e.code = static_cast<std::uint16_t>(code);
  e.value = value;
  ASSERT_EQ(::write(fd, &e, sizeof e), static_cast<ssize_t>(sizeof e));
}

// Each committed report keeps its SYN_REPORT's time stamp (for the
// CountAligner); a report without motion is not kept; take() clears them.
TEST(EvdevAccumulator, KeepsEachReportsTimeStamp) {
  EvdevAccumulator a;
  a.feed(EV_REL, REL_Y, -5, 1.000);
  a.feed(EV_SYN, SYN_REPORT, 0, 1.000);
  a.feed(EV_SYN, SYN_REPORT, 0, 1.004);  // no motion
  a.feed(EV_REL, REL_X, 2, 1.008);
  a.feed(EV_SYN, SYN_REPORT, 0, 1.008);
  const auto r = a.take_reports();
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r[0].t, 1.000);
  EXPECT_EQ(r[0].dx, 5);   // x = -REL_Y
  EXPECT_DOUBLE_EQ(r[1].t, 1.008);
  EXPECT_EQ(r[1].dy, -2);  // y = -REL_X
  std::int64_t dx, dy;
  a.take(&dx, &dy);
  EXPECT_EQ(dx, 0);  // take_reports cleared the counts too
  a.feed(EV_REL, REL_Y, -1, 2.0);
  a.feed(EV_SYN, SYN_REPORT, 0, 2.0);
  a.take(&dx, &dy);
  EXPECT_EQ(dx, 1);
  EXPECT_TRUE(a.take_reports().empty());  // and take() the reports
}

TEST(EvdevMouse, ReadsUnplugsAndReconnects) {
  const std::string path = ::testing::TempDir() + "mrt_mice_fake_mouse_" + std::to_string(::getpid());
  ::unlink(path.c_str());
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EvdevMouse m(path, true);
  ASSERT_TRUE(m.open()) << m.last_error();
  EXPECT_FALSE(m.grabbed());  // a FIFO cannot be grabbed; the reader goes on
  int w = ::open(path.c_str(), O_WRONLY);
  ASSERT_GE(w, 0);
  EvdevAccumulator acc;
  write_event(w, EV_REL, REL_Y, -100);
  write_event(w, EV_SYN, SYN_REPORT, 0);
  EXPECT_TRUE(m.poll(acc));
  std::int64_t dx, dy;
  acc.take(&dx, &dy);
  EXPECT_EQ(dx, 100);
  // Unplugged: the writer goes away, the file too.
  ::close(w);
  ::unlink(path.c_str());
  EXPECT_FALSE(m.poll(acc));
  EXPECT_FALSE(m.connected());
  EXPECT_FALSE(m.open());
  EXPECT_NE(m.last_error().find("No such file"), std::string::npos) << m.last_error();
  // Plugged in again.
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  ASSERT_TRUE(m.open());
  EXPECT_EQ(m.connects(), 2u);
  w = ::open(path.c_str(), O_WRONLY);
  write_event(w, EV_REL, REL_X, 4);
  write_event(w, EV_SYN, SYN_REPORT, 0);
  EXPECT_TRUE(m.poll(acc));
  acc.take(&dx, &dy);
  EXPECT_EQ(dy, -4);
  ::close(w);
  m.close();
  ::unlink(path.c_str());
}

}  // namespace
