// SerialPort over a pseudo-terminal pair: the line settings both users rely
// on (raw 8N1, no flow control, the speed, VMIN by blocking mode), bytes both
// ways, and the errors naming the device.
#include "mrt_common/serial_port.h"

#include <gtest/gtest.h>
#include <pty.h>

#include <string>

using mrt::common::SerialError;
using mrt::common::SerialOptions;
using mrt::common::SerialPort;

namespace {
struct Pty {
  int master = -1, slave = -1;
  std::string path;
  Pty() {
    char name[256] = {};
    if (openpty(&master, &slave, name, nullptr, nullptr) == 0) path = name;
  }
  ~Pty() {
    if (master >= 0) ::close(master);
    if (slave >= 0) ::close(slave);
  }
};

termios settings(int fd) {
  termios t{};
  EXPECT_EQ(tcgetattr(fd, &t), 0);
  return t;
}
}  // namespace

TEST(SerialPort, ConfiguresARaw8N1LineWithoutFlowControl) {
  Pty pty;
  ASSERT_FALSE(pty.path.empty());
  SerialPort port;
  port.open(pty.path, 57600);
  ASSERT_TRUE(port.is_open());
  const termios t = settings(port.fd());
  EXPECT_EQ(cfgetospeed(&t), B57600);
  EXPECT_EQ(cfgetispeed(&t), B57600);
  EXPECT_EQ(t.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(t.c_cflag & (PARENB | CSTOPB | CRTSCTS), 0u);
  EXPECT_EQ(t.c_iflag & (IXON | IXOFF | ICRNL), 0u);
  EXPECT_EQ(t.c_lflag & (ICANON | ECHO), 0u);
  EXPECT_EQ(t.c_cc[VMIN], 0);  // non-blocking: a read returns what is there
  EXPECT_NE(fcntl(port.fd(), F_GETFL) & O_NONBLOCK, 0);
}

TEST(SerialPort, BlockingModeWaitsForOneByte) {
  Pty pty;
  SerialOptions o;
  o.non_blocking = false;
  SerialPort port;
  port.open(pty.path, o);
  EXPECT_EQ(settings(port.fd()).c_cc[VMIN], 1);
  EXPECT_EQ(fcntl(port.fd(), F_GETFL) & O_NONBLOCK, 0);
}

TEST(SerialPort, CarriesBytesBothWays) {
  Pty pty;
  SerialPort port;
  port.open(pty.path, 115200);
  uint8_t buf[16];
  EXPECT_EQ(port.read(buf, sizeof buf), 0u);  // nothing yet
  const uint8_t out[] = {0xA5, 0x00, 0x0D, 0x0A, 0xFF};
  port.write(out, sizeof out);
  uint8_t got[5] = {};
  ASSERT_EQ(::read(pty.master, got, sizeof got), 5);
  EXPECT_EQ(std::string(got, got + 5), std::string(out, out + 5));  // no CR/LF translation
  const uint8_t in[] = {0x11, 0x13, 0x03};                            // XON, XOFF, ^C: plain bytes
  ASSERT_EQ(::write(pty.master, in, sizeof in), 3);
  ASSERT_TRUE(port.wait_readable(1000));
  ASSERT_EQ(port.read(buf, sizeof buf), 3u);
  EXPECT_EQ(buf[0], 0x11);
  EXPECT_EQ(buf[1], 0x13);
  EXPECT_EQ(buf[2], 0x03);
}

TEST(SerialPort, ReleaseHandsOverTheDescriptor) {
  Pty pty;
  SerialPort port;
  port.open(pty.path, 115200);
  const int fd = port.release();
  EXPECT_GE(fd, 0);
  EXPECT_FALSE(port.is_open());
  EXPECT_EQ(::close(fd), 0);  // still open: the port did not close it
}

TEST(SerialPort, ErrorsNameTheDevice) {
  SerialPort port;
  try {
    port.open("/nonexistent/ttyUSB9", 115200);
    FAIL() << "opened a missing device";
  } catch (const SerialError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot open /nonexistent/ttyUSB9: No such file or directory");
  }
  try {
    port.open("/dev/null", 115200);
    FAIL() << "opened /dev/null as a serial line";
  } catch (const SerialError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("not a serial device: /dev/null: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(port.open("/dev/null", 12345), SerialError);
  EXPECT_FALSE(port.is_open());
  // Not required to be a terminal: used as it is.
  SerialOptions o;
  o.require_tty = false;
  port.open("/dev/null", o);
  EXPECT_TRUE(port.is_open());
  uint8_t buf[4];
  EXPECT_EQ(port.read(buf, sizeof buf), 0u);  // /dev/null: end of file, no hang-up
}
