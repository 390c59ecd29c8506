// Model of the AIRBoard firmware (PIC18F252 at 40 MHz) and of the motors it
// drives, used by the emulator and the tests. ROS-free, single-threaded,
// stepped in simulated time: one step() is one 1 ms control period.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_airboard/protocol.h"

namespace mrt::airboard {

struct FirmwareConfig {
  int motors = 2;                   // 1..4
  uint32_t counts_per_rev = 8192;   // encoder counts per wheel revolution (x4 quadrature, after the gear)
  int control_hz = 1000;            // PI loop rate
  // PWM: Fosc 40 MHz (10 MHz crystal, HS/PLL), Timer2 prescaler 4, PR2 = 124:
  // f = Fosc / (4 * 4 * (PR2 + 1)) = 20 kHz; duty resolution 4 * (PR2 + 1) = 500 steps.
  uint32_t pwm_hz = 20000;
  int pwm_steps = 500;
  double max_speed = 30.0;          // rad/s: set-points are clamped to +-max_speed
  uint16_t watchdog_ms = 100;       // motors stopped this long after the last valid command
  // PI gains (duty per rad/s, duty per rad) and the feed-forward the firmware
  // assumes (duty per rad/s = 1 / nominal no-load speed).
  double kp = 0.05;
  double ki = 1.0;
  double kff = 1.0 / 40.0;
  int speed_window_ms = 10;         // measured speed = counts over this window
  // Motor + gear + wheel, first order: tau dw/dt = u * no_load_speed - w.
  double no_load_speed = 38.0;      // rad/s at the wheel with 100 % duty (5 % below nominal)
  double tau = 0.02;                // s, mechanical time constant
  double stall_current = 10.0;      // A at 100 % duty, standstill
  double current_limit = 8.0;       // A: the firmware limits the duty above it
  bool require_checked = false;     // refuse plain SET_SPEED / SET_PWM from power-up
};

class Firmware {
 public:
  explicit Firmware(const FirmwareConfig& c);

  /// Bytes from the PC (any chunking). Valid frames are acted on at once;
  /// replies are queued for take_output().
  void receive(const uint8_t* data, std::size_t n);
  /// One control period: watchdog, PI loops, motor and encoder models,
  /// streamed STATE frames.
  void step();
  /// Bytes for the PC produced since the last call.
  std::vector<uint8_t> take_output();

  // Inspection (tests, emulator statistics).
  uint32_t time_ms() const { return time_ms_; }
  int motors() const { return static_cast<int>(m_.size()); }
  double setpoint(int i) const { return m_[i].setpoint; }
  double speed(int i) const { return m_[i].w; }          // true wheel speed
  double measured_speed(int i) const { return m_[i].meas; }
  double duty(int i) const { return m_[i].duty; }
  int64_t ticks(int i) const { return m_[i].ticks; }
  bool watchdog_tripped() const { return tripped_; }
  uint32_t watchdog_trips() const { return trips_; }
  uint64_t commands_applied() const { return applied_; }
  uint64_t commands_rejected() const { return rejected_; }
  /// Checked set commands refused because their CRC-32 failed (damage that
  /// passed the CRC-16).
  uint64_t check_failures() const { return check_failures_; }
  bool strict() const { return strict_ || c_.require_checked; }
  const FrameDecoder::Stats& rx_stats() const { return dec_.stats(); }
  BoardState state() const;
  BoardInfo info() const;
  const FirmwareConfig& config() const { return c_; }
  uint8_t stream_format() const { return format_; }

 private:
  enum class Mode { kSpeed, kPwm, kBrake };
  struct Motor {
    double setpoint = 0.0;   // rad/s (speed mode)
    double duty_cmd = 0.0;   // PWM mode
    double integ = 0.0;      // PI integral of the error, rad
    double duty = 0.0;       // applied
    double w = 0.0;          // true wheel speed, rad/s
    double angle = 0.0;      // true wheel angle, rad
    int64_t ticks = 0;
    double meas = 0.0;       // measured speed, rad/s
    std::vector<int64_t> hist;  // ring of past tick counts for the speed window
    uint8_t status = 0;
    bool clamped = false;
    double kp = 0.0, ki = 0.0;
  };

  void handle(const Frame& f);
  void reply_state(uint8_t seq);
  void reply_set(uint8_t seq);  // STATE, or SHORT_STATE in the compact format
  void command_received(uint8_t seq);
  bool accept_check(bool checked);
  template <class Nack>
  void refuse_set(const Frame& f, const Nack& nack);
  void control(Motor& m);

  FirmwareConfig c_;
  double dt_;
  std::vector<Motor> m_;
  FrameDecoder dec_;
  std::vector<uint8_t> out_;
  Mode mode_ = Mode::kBrake;
  uint32_t time_ms_ = 0;
  uint32_t since_cmd_ = 0;
  bool armed_ = false;     // a set command is in force
  bool tripped_ = false;
  uint32_t trips_ = 0;
  uint8_t last_seq_ = 0;
  uint16_t stream_ms_ = 0;
  uint8_t format_ = proto::kFormatState;
  uint32_t streamed_ = 0;
  uint64_t applied_ = 0, rejected_ = 0, check_failures_ = 0;
  bool strict_ = false;
  std::size_t hist_at_ = 0;
};

}  // namespace mrt::airboard
