#include "mrt_airboard/pty_emulator.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <stdexcept>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

namespace mrt::airboard {

PtyEmulator::PtyEmulator(const FirmwareConfig& fw, const LineFaults& faults, std::string link_path)
    : fw_(fw), faults_(faults), link_path_(std::move(link_path)), rng_(faults.seed) {
  if (faults_.baud < 0) throw std::runtime_error("baud must be >= 0");
  if (faults_.baud > 0)
    byte_time_ = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(10.0 / faults_.baud));
  char name[256] = {0};
  termios t{};
  cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  cfsetispeed(&t, B115200);
  cfsetospeed(&t, B115200);
  if (openpty(&master_, &slave_, name, &t, nullptr) != 0)
    throw std::runtime_error(std::string("openpty failed: ") + std::strerror(errno));
  slave_path_ = name;
  fcntl(master_, F_SETFL, fcntl(master_, F_GETFL) | O_NONBLOCK);
  fcntl(master_, F_SETFD, FD_CLOEXEC);
  fcntl(slave_, F_SETFD, FD_CLOEXEC);
  if (!link_path_.empty()) {
    struct stat st{};
    if (lstat(link_path_.c_str(), &st) == 0) {
      if (!S_ISLNK(st.st_mode)) {
        ::close(master_);
        ::close(slave_);
        throw std::runtime_error("refusing to replace " + link_path_ + ": not a symlink");
      }
      ::unlink(link_path_.c_str());
    }
    if (::symlink(slave_path_.c_str(), link_path_.c_str()) != 0) {
      const std::string e = std::strerror(errno);
      ::close(master_);
      ::close(slave_);
      throw std::runtime_error("cannot create symlink " + link_path_ + ": " + e);
    }
  }
}

PtyEmulator::~PtyEmulator() {
  if (!link_path_.empty()) {
    // Remove the link only if it still points at our slave.
    char buf[256];
    const ssize_t n = ::readlink(link_path_.c_str(), buf, sizeof(buf) - 1);
    if (n > 0 && std::string(buf, static_cast<std::size_t>(n)) == slave_path_) ::unlink(link_path_.c_str());
  }
  if (master_ >= 0) ::close(master_);
  if (slave_ >= 0) ::close(slave_);
}

void PtyEmulator::corrupt(uint8_t* d, std::size_t n, double p, uint64_t* count) {
  if (p <= 0.0) return;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> bit(0, 7);
  for (std::size_t i = 0; i < n; ++i)
    if (u(rng_) < p) {
      d[i] ^= static_cast<uint8_t>(1u << bit(rng_));
      ++*count;
    }
}

void PtyEmulator::write_out(const uint8_t* d, std::size_t n) {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t k = ::write(master_, d + done, n - done);
    if (k > 0) {
      done += static_cast<std::size_t>(k);
    } else if (k < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // nobody reads the line: the bytes are lost, as on a UART
    }
  }
  stats_.bytes_out += done;
  stats_.bytes_dropped_out += n - done;
}

void PtyEmulator::observe(const std::vector<uint8_t>& out) {
  out_dec_.feed(out.data(), out.size(), [this](const Frame& f) {
    BoardState s;
    ShortState ss;
    std::vector<double> speeds;
    uint32_t ms = 0;
    if (parse_state(f, &s)) {
      ms = s.time_ms;
      for (const MotorState& m : s.motors) speeds.push_back(m.speed);
    } else if (parse_short_state(f, &ss)) {
      ms = ss.time_ms;
      for (int i = 0; i < fw_.motors(); ++i) speeds.push_back(to_mrad(fw_.measured_speed(i)) / 1000.0);
    } else {
      return;
    }
    if (observed_ && ms == observed_ms_) return;
    observed_ = true;
    observed_ms_ = ms;
    observer_(ms, speeds);
  });
}

void PtyEmulator::flush() {
  std::vector<uint8_t> out = fw_.take_output();
  if (out.empty()) return;
  if (observer_) observe(out);
  corrupt(out.data(), out.size(), faults_.corrupt_tx, &stats_.bytes_corrupted_out);
  if (byte_time_.count() == 0) return write_out(out.data(), out.size());
  const auto now = Clock::now();
  for (uint8_t b : out) {
    tx_free_ = std::max(tx_free_, now) + byte_time_;
    tx_q_.emplace_back(b, tx_free_);
  }
}

void PtyEmulator::deliver(uint8_t* d, std::size_t n) {
  const bool cut = faults_.cut_rx_after >= 0.0 && fw_.time_ms() >= faults_.cut_rx_after * 1000.0;
  if (cut) {
    stats_.bytes_cut_in += n;
    return;
  }
  corrupt(d, n, faults_.corrupt_rx, &stats_.bytes_corrupted_in);
  fw_.receive(d, n);
  flush();
}

bool PtyEmulator::handle_input() {
  uint8_t buf[4096];
  const ssize_t n = ::read(master_, buf, sizeof(buf));
  if (n <= 0) return false;
  stats_.bytes_in += static_cast<uint64_t>(n);
  if (byte_time_.count() == 0) {
    deliver(buf, static_cast<std::size_t>(n));
    return true;
  }
  // The PC's UART sends the bytes one after the other at the line rate.
  const auto now = Clock::now();
  for (ssize_t i = 0; i < n; ++i) {
    rx_free_ = std::max(rx_free_, now) + byte_time_;
    rx_q_.emplace_back(buf[i], rx_free_);
  }
  return true;
}

void PtyEmulator::service_line(Clock::time_point now) {
  uint8_t buf[512];
  std::size_t k = 0;
  while (!rx_q_.empty() && rx_q_.front().second <= now) {
    buf[k++] = rx_q_.front().first;
    rx_q_.pop_front();
    if (k == sizeof(buf)) {
      deliver(buf, k);
      k = 0;
    }
  }
  if (k) deliver(buf, k);
  k = 0;
  while (!tx_q_.empty() && tx_q_.front().second <= now) {
    buf[k++] = tx_q_.front().first;
    tx_q_.pop_front();
    if (k == sizeof(buf)) {
      write_out(buf, k);
      k = 0;
    }
  }
  if (k) write_out(buf, k);
}

void PtyEmulator::run_on_source(const std::atomic<bool>& stop) {
  const double hz = fw_.config().control_hz;
  constexpr std::uint64_t kMaxSteps = 1000;
  double start = 0.0;
  std::uint64_t done = 0;
  bool started = false;
  // The cable runs at its baud rate in the source's time too: a byte takes
  // 10 / baud s of source time, converted to wall time by the source's rate
  // over the last 100 ms of wall time (at a real-time factor of 2 the line
  // carries twice the bytes per wall second, as the board sends them), but
  // never slower than the real cable: a stalled source would otherwise
  // choke the line (a factor of 0.01) and the frames of its catch-up
  // would queue behind it until the PC declared the link lost.
  const Clock::duration byte_time = byte_time_;
  auto rate_since = Clock::now();
  double rate_source = time_source_();
  while (!stop.load(std::memory_order_relaxed)) {
    if (byte_time.count() > 0 && Clock::now() - rate_since >= std::chrono::milliseconds(100)) {
      const double wall = std::chrono::duration<double>(Clock::now() - rate_since).count(), src = time_source_();
      const double factor = std::min(100.0, std::max(1.0, (src - rate_source) / wall));
      if (src > rate_source) byte_time_ = std::chrono::duration_cast<Clock::duration>(byte_time / factor);
      rate_since = Clock::now();
      rate_source = src;
    }
    service_line(Clock::now());
    // Input as soon as it comes; the source is looked at every 0.2 ms of
    // wall time (a simulator's /clock moves in steps of its own).
    pollfd p{master_, POLLIN, 0};
    timespec ts{0, 200000};
    if (::ppoll(&p, 1, &ts, nullptr) > 0 && (p.revents & POLLIN)) {
      while (handle_input()) {
      }
    }
    const double now = time_source_();
    if (!started) {
      if (!(now > 0.0)) continue;
      started = true;
      start = now;
    }
    const double elapsed = (now - start) * hz;
    const std::uint64_t due = elapsed > 0.0 ? static_cast<std::uint64_t>(std::floor(elapsed + 1e-9)) : 0;
    if (now < start || due - done > kMaxSteps) {  // back in time or a long jump: pause
      if (due > done) stats_.paused_ticks += due - done;
      start = now;
      done = 0;
      continue;
    }
    const std::uint64_t steps = due - done;
    for (std::uint64_t k = 0; k < steps; ++k) fw_.step();
    if (steps > 1) stats_.late_ticks += steps - 1;
    done = due;
    flush();
  }
}

void PtyEmulator::run(const std::atomic<bool>& stop) {
  if (time_source_) {
    run_on_source(stop);
    return;
  }
  const auto period = std::chrono::microseconds(1000000 / fw_.config().control_hz);
  // A real board never stalls; this process can (a loaded machine). Up to
  // kMaxCatchUp late periods are caught up; beyond that board time pauses,
  // so a stall of the emulator is not seen by the firmware as a silent PC.
  constexpr int kMaxCatchUp = 20;
  auto next = Clock::now() + period;
  while (!stop.load(std::memory_order_relaxed)) {
    auto now = Clock::now();
    service_line(now);
    if (now < next) {
      auto wake = next;
      if (!rx_q_.empty()) wake = std::min(wake, rx_q_.front().second);
      if (!tx_q_.empty()) wake = std::min(wake, tx_q_.front().second);
      const auto wait = std::chrono::duration_cast<std::chrono::nanoseconds>(std::max(wake - now, Clock::duration(0)));
      timespec ts{static_cast<time_t>(wait.count() / 1000000000), static_cast<long>(wait.count() % 1000000000)};
      pollfd p{master_, POLLIN, 0};
      if (::ppoll(&p, 1, &ts, nullptr) > 0 && (p.revents & POLLIN)) handle_input();
      continue;
    }
    // Control periods are due: first take what the PC sent meanwhile.
    while (handle_input()) {
    }
    service_line(Clock::now());
    int steps = 0;
    while (Clock::now() >= next && steps < kMaxCatchUp) {
      fw_.step();
      next += period;
      if (++steps > 1) ++stats_.late_ticks;
    }
    if (Clock::now() >= next) {
      stats_.paused_ticks += static_cast<uint64_t>((Clock::now() - next) / period);
      next = Clock::now() + period;
    }
    flush();
  }
}

}  // namespace mrt::airboard
