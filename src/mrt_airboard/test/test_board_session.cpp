// BoardSession against the firmware model, in simulated time: the board is
// stepped every 1 ms, the session reads every 2 ms and runs its control
// period every 20 ms (50 Hz), as airboard_node's timers do.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mrt_airboard/board_session.h"
#include "mrt_airboard/firmware.h"

namespace mrt::airboard {
namespace {

// The cable and the board: what the fake link reads and writes.
struct Bench {
  explicit Bench(FirmwareConfig c = {}) : fw(c) {}
  Firmware fw;
  double now = 0.0;
  bool present = true;      // the device exists (open succeeds)
  bool unplugged = false;   // an open link fails on its next read
  bool mute = false;        // the board's output is lost
  double corrupt = 0.0;     // probability that a board -> PC byte gets one bit flipped
  std::mt19937 rng{7};
  std::deque<uint8_t> to_pc;
  std::vector<double> open_attempts;
  std::vector<Frame> sent;  // frames the session wrote
  FrameDecoder sent_dec;
};

class FakeLink : public BoardLink {
 public:
  explicit FakeLink(Bench* b) : b_(b) {}
  void open() override {
    b_->open_attempts.push_back(b_->now);
    if (!b_->present) throw SerialError("/dev/fake: No such file or directory");
    b_->to_pc.clear();
    open_ = true;
  }
  void close() override { open_ = false; }
  bool is_open() const override { return open_; }
  std::size_t read(uint8_t* buf, std::size_t cap) override {
    if (b_->unplugged) {
      open_ = false;
      throw SerialError("/dev/fake: Input/output error");
    }
    std::size_t n = 0;
    while (n < cap && !b_->to_pc.empty()) {
      buf[n++] = b_->to_pc.front();
      b_->to_pc.pop_front();
    }
    return n;
  }
  void write(const uint8_t* data, std::size_t n) override {
    b_->sent_dec.feed(data, n, [this](const Frame& f) { b_->sent.push_back(f); });
    b_->fw.receive(data, n);
  }
  std::string name() const override { return "/dev/fake"; }

 private:
  Bench* b_;
  bool open_ = false;
};

struct Recorder : SessionListener {
  int states = 0, lost = 0, errors = 0;
  void on_state(const BoardState&) override { ++states; }
  void on_link_lost() override { ++lost; }
  void log(Level level, const std::string&, const std::string&) override { errors += level == Level::kError; }
};

SessionOptions options() {
  SessionOptions o;
  o.base = base_preset("ianus3");  // r 0.05 m, track 0.38 m, max 24 rad/s, 8192 counts/rev
  o.brian = BrianMappingParams::for_base(o.base.type);
  o.cmd_timeout = 100.0;  // commands stay in force unless a test says otherwise
  return o;
}

struct Fixture {
  explicit Fixture(SessionOptions o = options(), FirmwareConfig c = {})
      : bench(c), session(o, std::make_unique<FakeLink>(&bench), &rec) {}

  // Runs `ms` milliseconds; `control` false stalls the control period (the
  // node's process starved) while reads go on; `reads` false stalls those.
  void run(int ms, bool control = true, bool reads = true) {
    for (int i = 0; i < ms; ++i) {
      ++t_ms;
      bench.now = t_ms * 1e-3;
      bench.fw.step();
      std::vector<uint8_t> out = bench.fw.take_output();
      if (session.link_open() && !bench.mute) {
        std::bernoulli_distribution flip(bench.corrupt);
        std::uniform_int_distribution<int> bit(0, 7);
        for (uint8_t b : out) bench.to_pc.push_back(flip(bench.rng) ? static_cast<uint8_t>(b ^ (1u << bit(bench.rng))) : b);
      }
      if (reads && t_ms % 2 == 0) session.read(bench.now);
      if (control && t_ms % 20 == 0) session.control(bench.now);
    }
  }
  double now() const { return t_ms * 1e-3; }
  int count_sent(uint8_t type) const {
    int n = 0;
    for (const Frame& f : bench.sent) n += f.type == type;
    return n;
  }

  Bench bench;
  Recorder rec;
  BoardSession session;
  long t_ms = 0;
};

TEST(BoardSession, ConnectsIdentifiesTheBoardAndDrives) {
  Fixture f;
  ASSERT_TRUE(f.session.command_twist(Twist2D{0.5, 0.0, 0.0}, f.now()));
  f.run(1000);
  EXPECT_TRUE(f.session.link_up());
  EXPECT_TRUE(f.session.info_ok());
  EXPECT_EQ(f.session.stats().port_opens, 1u);
  EXPECT_EQ(f.session.stats().reconnects, 0u);
  // vx 0.5 m/s on wheels of 0.05 m: 0.5 / 0.05 = 10 rad/s on both wheels.
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 10.0);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(1), 10.0);
  // A STATE every 10 ms over about 1 s: some 90 to 100 of them.
  EXPECT_GT(f.rec.states, 80);
  EXPECT_FALSE(f.session.compact());
  EXPECT_EQ(f.bench.fw.stream_format(), proto::kFormatState);
}

TEST(BoardSession, ReconnectsWithExponentialBackOff) {
  Fixture f;
  f.bench.present = false;
  f.run(2000);
  // Attempts at the control periods (every 20 ms) once the delay is over:
  // the first at 0.02 s, then after 0.1, 0.2, 0.4, 0.8 s (doubling, max
  // 2 s): 0.02, 0.12, 0.32, 0.72, 1.52; each may slip by one period (the
  // delay runs from the actual attempt), so attempt k is within k x 0.02 s.
  const std::vector<double> nominal = {0.02, 0.12, 0.32, 0.72, 1.52};
  ASSERT_EQ(f.bench.open_attempts.size(), nominal.size());
  for (std::size_t k = 0; k < nominal.size(); ++k)
    EXPECT_NEAR(f.bench.open_attempts[k], nominal[k], 0.02 * k + 1e-9) << "attempt " << k;
  // The delay after the fifth failure was 1.6 s (next attempt 3.12 s); the
  // one after a sixth would be 3.2 s, capped at reconnect_max 2 s.
  EXPECT_DOUBLE_EQ(f.session.next_reconnect_delay(), 2.0);
  EXPECT_EQ(f.session.stats().port_opens, 0u);

  // The device appears: the next attempt (1.52 + 1.6 = 3.12 s) opens it and
  // the board's first frame resets the back-off to its minimum.
  f.bench.present = true;
  f.run(1500);
  EXPECT_EQ(f.bench.open_attempts.size(), 6u);
  EXPECT_NEAR(f.bench.open_attempts.back(), 3.12, 0.1 + 1e-9);
  EXPECT_TRUE(f.session.link_up());
  EXPECT_DOUBLE_EQ(f.session.next_reconnect_delay(), 0.1);
  EXPECT_EQ(f.session.stats().reconnects, 0u);

  // Unplugged: the read fails, the motors are considered stopped, and the
  // link comes back 0.1 s later (one reconnection).
  f.bench.unplugged = true;
  f.run(10);
  EXPECT_FALSE(f.session.link_up());
  EXPECT_EQ(f.rec.lost, 1);
  f.bench.unplugged = false;
  f.run(500);
  EXPECT_TRUE(f.session.link_up());
  EXPECT_EQ(f.session.stats().port_opens, 2u);
  EXPECT_EQ(f.session.stats().reconnects, 1u);
}

TEST(BoardSession, SilentBoardTimesOutAndKeepsBackingOff) {
  Fixture f;
  f.bench.mute = true;
  f.run(2000);
  // Open at 0.02 s; no frame for > 0.5 s: lost at 0.54, retry after 0.1 s
  // (0.64), lost at 1.16, retry after 0.2 s (1.36), lost at 1.88; the delay
  // is not reset (no frame ever arrived): next 0.8 s.
  EXPECT_EQ(f.session.stats().port_opens, 3u);
  EXPECT_EQ(f.rec.lost, 3);
  EXPECT_DOUBLE_EQ(f.session.next_reconnect_delay(), 0.8);
  EXPECT_FALSE(f.session.link_up());
  EXPECT_EQ(f.rec.states, 0);
}

// The node's process starved for 0.7 s (longer than link_timeout 0.5 s)
// while the board went on streaming; when it runs again its control
// callback comes first: the frames waiting in the line are taken before
// the link is judged, so it is not lost.
TEST(BoardSession, StarvedNodeReadsWaitingFramesBeforeJudgingTheLink) {
  Fixture f;
  f.run(1000);
  ASSERT_TRUE(f.session.link_up());
  const int states = f.rec.states;
  f.run(700, false, false);
  f.session.control(f.now());
  EXPECT_TRUE(f.session.link_up());
  EXPECT_EQ(f.rec.lost, 0);
  EXPECT_GT(f.rec.states, states + 60);  // about 70 STATEs were waiting
}

// A simulated clock that jumps 0.8 s (the simulator stalled, then caught
// up; the board, on the same clock, sent nothing meanwhile): the time the
// session did not run is not the board's silence, the link stays up. A
// silent board still times out: 0.5 s of control periods after the jump.
TEST(BoardSession, ClockJumpIsNotSilence) {
  Fixture f;
  f.run(1000);
  ASSERT_TRUE(f.session.link_up());
  f.t_ms += 800;
  f.run(100);
  EXPECT_TRUE(f.session.link_up());
  EXPECT_EQ(f.rec.lost, 0);
  f.t_ms += 800;
  f.bench.mute = true;
  f.run(480);
  EXPECT_EQ(f.rec.lost, 0);
  f.run(60);
  EXPECT_EQ(f.rec.lost, 1);
}

TEST(BoardSession, WatchdogTripRestartsTheRampFromRest) {
  SessionOptions o = options();
  o.base.max_wheel_accel = 100.0;  // rad/s^2: 100 x 0.02 s = 2 rad/s per control period
  Fixture f(o);
  ASSERT_TRUE(f.session.command_twist(Twist2D{0.5, 0.0, 0.0}, f.now()));  // 10 rad/s per wheel
  f.run(1000);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 10.0);
  // The node stalls 200 ms: the board stops the motors 100 ms after the
  // last command and reports it (WATCHDOG bit) in its STATEs.
  f.run(200, false);
  EXPECT_EQ(f.bench.fw.watchdog_trips(), 1u);
  EXPECT_EQ(f.bench.fw.setpoint(0), 0.0);
  // Control resumes at t = 1.22 s: the first command is one step from rest
  // (2 rad/s), not the old target 10.
  f.run(19, false);
  f.run(2);  // the control period at 1.22 s, and the board acts on it
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 2.0);
  // The board applied it (a STATE without the bit arrives): the ramp goes
  // on from 2: 4, 6, 8, 10.
  f.run(20);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 4.0);
  f.run(60);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 10.0);
}

TEST(BoardSession, SwitchesToCompactFramesOnANoisyLineAndBack) {
  Fixture f;
  f.run(500);
  ASSERT_TRUE(f.session.link_up());
  // 10 % of the board's bytes get a bit flipped: a 49-byte STATE survives
  // with probability 0.9^49 = 0.6 %, so within a second more than 8 frames
  // are bad and more bad than good: the session asks for SHORT_STATE.
  f.bench.corrupt = 0.1;
  f.run(2000);
  EXPECT_TRUE(f.session.compact());
  EXPECT_EQ(f.bench.fw.stream_format(), proto::kFormatCompact);
  // A clean line again: over the next 2 s window fewer than one frame in
  // six is bad, so back to the full STATE.
  f.bench.corrupt = 0.0;
  f.run(3000);
  EXPECT_FALSE(f.session.compact());
  EXPECT_EQ(f.bench.fw.stream_format(), proto::kFormatState);
}

TEST(BoardSession, FixedStateFormatNeverSwitches) {
  SessionOptions o = options();
  o.state_format = SessionOptions::StateFormat::kState;
  Fixture f(o);
  f.bench.corrupt = 0.1;
  f.run(3000);
  EXPECT_FALSE(f.session.compact());
  EXPECT_EQ(f.bench.fw.stream_format(), proto::kFormatState);
}

TEST(BoardSession, CompactStreamEstimatesTheWheelSpeeds) {
  SessionOptions o = options();
  o.state_format = SessionOptions::StateFormat::kCompact;
  Fixture f(o);
  ASSERT_TRUE(f.session.command_wheels(BoardSession::WheelMode::kSpeed, {10.0, -5.0}, f.now()));
  f.run(1500);
  EXPECT_EQ(f.bench.fw.stream_format(), proto::kFormatCompact);
  ASSERT_TRUE(f.session.have_state());
  const BoardState& s = f.session.last_state();
  // Count differences over >= 10 ms: one count is 2 pi / 8192 / 0.01 s =
  // 0.077 rad/s; the PI loop holds the set-points within 0.1 rad/s.
  EXPECT_NEAR(s.motors[0].speed, 10.0, 0.2);
  EXPECT_NEAR(s.motors[1].speed, -5.0, 0.2);
  EXPECT_DOUBLE_EQ(s.motors[0].setpoint, 10.0);
  EXPECT_TRUE(std::isnan(s.motors[0].duty));  // not carried by SHORT_STATE
}

TEST(BoardSession, ArbitratesBetweenTheCommandSources) {
  SessionOptions o = options();
  o.cmd_timeout = 0.5;
  Fixture f(o);
  f.run(300);
  // Twist: vx 0.5 m/s -> 10 rad/s per wheel.
  f.session.command_twist(Twist2D{0.5, 0.0, 0.0}, f.now());
  f.run(100);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 10.0);
  // Wheel speeds: the latest command wins.
  f.session.command_wheels(BoardSession::WheelMode::kSpeed, {3.0, -3.0}, f.now());
  f.run(100);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 3.0);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(1), -3.0);
  // Wheel speeds beyond 24 rad/s are scaled together: [40, 20] x 24/40 =
  // [24, 12], and counted.
  f.session.command_wheels(BoardSession::WheelMode::kSpeed, {40.0, 20.0}, f.now());
  f.run(100);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 24.0);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(1), 12.0);
  EXPECT_GE(f.session.stats().commands_saturated, 1u);
  // PWM duties go out as SET_PWM, clamped to +-1.
  const uint64_t saturated = f.session.stats().commands_saturated;
  f.session.command_wheels(BoardSession::WheelMode::kPwm, {1.5, -0.25}, f.now());
  f.run(100);
  std::vector<double> duty;
  ASSERT_TRUE(parse_set_pwm(f.bench.sent.back(), &duty));
  EXPECT_DOUBLE_EQ(duty[0], 1.0);
  EXPECT_DOUBLE_EQ(duty[1], -0.25);
  EXPECT_EQ(f.session.stats().commands_saturated, saturated + 5);  // 5 control periods in 100 ms
  EXPECT_TRUE(f.bench.fw.state().status & proto::kStatusPwmMode);
  // Mr. BRIAN (differential base: unicycle, Speed in cm/s, Jog in deg/s):
  // Speed 25 -> vx 0.25 m/s -> 5 rad/s per wheel.
  ASSERT_TRUE(f.session.command_brian({{"Speed", 25.0}, {"Jog", 0.0}}, f.now()));
  f.run(100);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 5.0);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(1), 5.0);
  // No command for longer than cmd_timeout (0.5 s): stop.
  f.run(600);
  EXPECT_EQ(f.bench.fw.setpoint(0), 0.0);
  EXPECT_EQ(f.bench.fw.setpoint(1), 0.0);
}

TEST(BoardSession, TwistAfterPwmRampsFromTheMeasuredSpeeds) {
  SessionOptions o = options();
  o.base.max_wheel_accel = 100.0;  // rad/s^2: 2 rad/s per 20 ms control period
  Fixture f(o);
  f.run(300);
  ASSERT_TRUE(f.session.command_wheels(BoardSession::WheelMode::kPwm, {0.5, 0.5}, f.now()));
  f.run(700);  // ends on the control period at 1.0 s, after that ms's read
  // Half duty: about 0.5 x 38 = 19 rad/s measured on each wheel.
  const double m0 = f.session.last_state().motors[0].speed, m1 = f.session.last_state().motors[1].speed;
  ASSERT_GT(m0, 10.0);
  ASSERT_GT(m1, 10.0);
  // Stop by twist: the ramp starts from the speeds measured at the last PWM
  // period, one step (2 rad/s on the faster wheel, the change vector
  // scaled as a whole) per period: w_i = m_i (1 - 2 / max(m0, m1)).
  ASSERT_TRUE(f.session.command_twist(Twist2D{}, f.now()));
  f.run(20);
  const double k = 1.0 - 2.0 / std::max(m0, m1);
  EXPECT_NEAR(f.bench.fw.setpoint(0), m0 * k, 1e-3);  // the wire's quantum: 1 mrad/s
  EXPECT_NEAR(f.bench.fw.setpoint(1), m1 * k, 1e-3);
}

TEST(BoardSession, NonFiniteAndMalformedInputsAreDroppedAndCounted) {
  Fixture f;
  ASSERT_TRUE(f.session.command_twist(Twist2D{0.5, 0.0, 0.0}, f.now()));
  const double nan = std::nan("");
  EXPECT_FALSE(f.session.command_twist(Twist2D{nan, 0.0, 0.0}, f.now()));
  EXPECT_FALSE(f.session.command_twist(Twist2D{0.0, 0.0, INFINITY}, f.now()));
  EXPECT_FALSE(f.session.command_brian({{"Speed", INFINITY}}, f.now()));
  EXPECT_FALSE(f.session.command_wheels(BoardSession::WheelMode::kSpeed, {1.0, nan}, f.now()));
  EXPECT_FALSE(f.session.command_wheels(BoardSession::WheelMode::kPwm, {0.1, 0.1, 0.1}, f.now()));
  f.session.drop_input("a wheel_cmd of unknown mode 7");
  EXPECT_EQ(f.session.stats().dropped_inputs, 6u);
  // The command in force is still the first twist.
  f.run(500);
  EXPECT_DOUBLE_EQ(f.bench.fw.setpoint(0), 10.0);
  EXPECT_EQ(f.count_sent(proto::kSetPwm), 0);
}

TEST(BoardSession, BoardOfAnotherBaseIsNotDriven) {
  FirmwareConfig c;
  c.motors = 3;  // the ianus3 base has 2
  Fixture f(options(), c);
  ASSERT_TRUE(f.session.command_twist(Twist2D{0.5, 0.0, 0.0}, f.now()));
  f.run(1000);
  EXPECT_TRUE(f.session.link_up());
  EXPECT_FALSE(f.session.info_ok());
  EXPECT_GT(f.rec.errors, 0);
  EXPECT_EQ(f.count_sent(proto::kSetSpeed), 0);
  EXPECT_GT(f.count_sent(proto::kHeartbeat), 40);  // one per control period: about 50 in 1 s
}

TEST(BoardSession, InvalidOptionsNameTheParameter) {
  SessionOptions o = options();
  o.rate = 0.0;
  try {
    BoardSession s(o, nullptr, nullptr);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "~rate: expected a number in (0, 1000] Hz");
  }
  EXPECT_THROW(SessionOptions::parse_state_format("short"), std::invalid_argument);
}

}  // namespace
}  // namespace mrt::airboard
