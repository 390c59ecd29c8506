// EvdevReader, the driver's read loop, on FIFOs standing in for the two
// devices (same read(2) of struct input_event; a FIFO cannot be grabbed,
// the reader goes on without). Time is given to step(), so the reconnect
// period is exercised without sleeping.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <linux/input.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "mrt_mice/evdev_reader.h"

using namespace mrt::mice;

namespace {

// A FIFO held open read-write by the test: the reader never sees end of
// file while it is "plugged", and writes never block.
struct FakeDevice {
  explicit FakeDevice(std::string p) : path(std::move(p)) { ::unlink(path.c_str()); }
  ~FakeDevice() { unplug(); }
  void plug() {
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    fd = ::open(path.c_str(), O_RDWR | O_NONBLOCK);
    ASSERT_GE(fd, 0);
  }
  void unplug() {
    if (fd >= 0) ::close(fd);
    fd = -1;
    ::unlink(path.c_str());
  }
  void event(int type, int code, int value) {
    input_event e{};
    e.type = static_cast<std::uint16_t>(type);
    e.code = static_cast<std::uint16_t>(code);
    e.value = value;
    ASSERT_EQ(::write(fd, &e, sizeof e), static_cast<ssize_t>(sizeof e));
  }
  // One report: motion (REL_X right, REL_Y towards the user) then SYN_REPORT.
  void motion(int rel_x, int rel_y) {
    if (rel_x) event(EV_REL, REL_X, rel_x);
    if (rel_y) event(EV_REL, REL_Y, rel_y);
    event(EV_SYN, SYN_REPORT, 0);
  }
  std::string path;
  int fd = -1;
};

struct Bench {
  Bench()
      : left(::testing::TempDir() + "mrt_mice_reader_left_" + std::to_string(::getpid())),
        right(::testing::TempDir() + "mrt_mice_reader_right_" + std::to_string(::getpid())) {
    o.left_device = left.path;
    o.right_device = right.path;
    o.reconnect_period = 1.0;
  }
  FakeDevice left, right;
  EvdevReaderOptions o;
  std::vector<std::pair<EvdevReader::Event, int>> events;
  EvdevReader::Listener listener() {
    return [this](EvdevReader::Event e, int i, const std::string&) { events.emplace_back(e, i); };
  }
};

TEST(EvdevReader, ReadsBothMiceIntoOneSample) {
  Bench b;
  b.left.plug();
  b.right.plug();
  EvdevReader r(b.o, b.listener());
  ASSERT_TRUE(r.step(0.0, 0));
  EXPECT_TRUE(r.both_connected());
  ASSERT_EQ(b.events.size(), 2u);
  EXPECT_EQ(b.events[0].first, EvdevReader::Event::kOpened);
  // Left pushed forward 120 counts in two reports (REL_Y -100, -20): x =
  // -REL_Y = 120; right moved to its right by 7 (REL_X 7): y = -7.
  b.left.motion(0, -100);
  b.left.motion(0, -20);
  b.right.motion(7, 0);
  r.step(0.01, 10);
  const auto c = r.take();
  ASSERT_TRUE(c);
  EXPECT_EQ(c->left_dx, 120);
  EXPECT_EQ(c->left_dy, 0);
  EXPECT_EQ(c->right_dx, 0);
  EXPECT_EQ(c->right_dy, -7);
  EXPECT_EQ(r.status(0).reports, 2u);
  // The next sample holds only what came since.
  const auto d = r.take();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->left_dx, 0);
  EXPECT_EQ(r.withheld(), 0u);
  EXPECT_TRUE(r.missing().empty());
}

TEST(EvdevReader, WithholdsSamplesWhileAMouseIsMissingAndReconnects) {
  Bench b;
  b.left.plug();
  EvdevReader r(b.o, b.listener());
  r.step(0.0, 0);
  EXPECT_TRUE(r.status(0).connected);
  EXPECT_FALSE(r.status(1).connected);
  EXPECT_EQ(r.missing(), "right mouse " + b.right.path);
  // Motion of the left mouse alone has no partner: the sample is withheld
  // and its counts dropped.
  b.left.motion(0, -50);
  r.step(0.1, 10);
  EXPECT_FALSE(r.take());
  EXPECT_EQ(r.withheld(), 1u);
  // The right mouse appears at 0.2 s, but the next attempt is 1 s after the
  // first (0.0 + reconnect_period): nothing before 1.0 s.
  b.right.plug();
  r.step(0.5, 0);
  EXPECT_FALSE(r.status(1).connected);
  b.left.motion(0, -3);  // read before the reconnection: dropped by it
  r.step(0.6, 10);
  r.step(1.0, 10);
  EXPECT_TRUE(r.status(1).connected);
  EXPECT_EQ(r.status(1).connects, 1u);
  b.left.motion(0, -4);
  b.right.motion(0, -6);
  r.step(1.01, 10);
  const auto c = r.take();
  ASSERT_TRUE(c);
  EXPECT_EQ(c->left_dx, 4);  // only the motion since the reconnection
  EXPECT_EQ(c->right_dx, 6);
  // Open failures were reported for the right mouse at 0.0 s (and only then
  // before 1.0 s).
  int failures = 0;
  for (const auto& e : b.events) failures += e.first == EvdevReader::Event::kOpenFailed && e.second == 1;
  EXPECT_EQ(failures, 1);
}

TEST(EvdevReader, UnplugIsDetectedAndCounted) {
  Bench b;
  b.left.plug();
  b.right.plug();
  EvdevReader r(b.o, b.listener());
  r.step(0.0, 0);
  b.right.unplug();  // the writer goes away: end of file for the reader
  r.step(0.02, 10);
  EXPECT_FALSE(r.status(1).connected);
  EXPECT_EQ(r.status(1).unplugs, 1u);
  EXPECT_NE(r.status(1).last_error.find("end of file"), std::string::npos) << r.status(1).last_error;
  EXPECT_EQ(b.events.back().first, EvdevReader::Event::kLost);
  EXPECT_EQ(b.events.back().second, 1);
  EXPECT_FALSE(r.take());
  // Both gone: step() says there is nothing to wait on.
  b.left.unplug();
  r.step(0.04, 10);
  EXPECT_FALSE(r.step(0.05, 0));
}

TEST(EvdevReader, InvalidOptionsNameTheParameter) {
  EvdevReaderOptions o;
  o.left_device = o.right_device = "/dev/input/event3";
  try {
    EvdevReader r(o);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "~right_device: must differ from ~left_device");
  }
  o.right_device.clear();
  EXPECT_THROW(EvdevReader{o}, std::invalid_argument);
}

}  // namespace
