// A null-modem cable between two pseudo-terminals, with optional bit flips
// and a plug that a test can pull.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace dcdt_test {

// Copies bytes between two pty masters: a null-modem cable. With `one_in`
// > 0 it flips a bit of each byte, in either direction, with probability
// 1/`one_in` (a fixed seed, so a run is reproducible). Masters are
// non-blocking and each direction is buffered, so neither side can stall
// the other.
class NullModem {
 public:
  explicit NullModem(int one_in = 0) : one_in_(one_in) {
    char n1[64], n2[64];
    termios t{};
    cfmakeraw(&t);
    ok = openpty(&m_[0], &s1_, n1, &t, nullptr) == 0 && openpty(&m_[1], &s2_, n2, &t, nullptr) == 0;
    if (ok) {
      for (int fd : m_) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
      dev1 = n1;
      dev2 = n2;
      thread_ = std::thread([this] { loop(); });
    }
  }
  ~NullModem() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    for (int fd : {m_[0], s1_, m_[1], s2_})
      if (fd >= 0) ::close(fd);
  }
  /// Unplugs (true) or plugs back (false) the cable: while unplugged every
  /// byte is lost, and so is what was on its way.
  void cut(bool unplugged) { cut_ = unplugged; }
  bool ok = false;
  std::string dev1, dev2;
  std::atomic<uint64_t> flipped{0}, relayed{0};

 private:
  void loop() {
    std::mt19937 rng(12345);
    std::uniform_int_distribution<int> hit(0, one_in_ > 0 ? one_in_ - 1 : 0), bit(0, 7);
    std::vector<uint8_t> pend[2];  // bytes read from m_[k], to be written to m_[1-k]
    uint8_t buf[4096];
    while (!stop_) {
      pollfd p[2];
      for (int k = 0; k < 2; ++k) {
        p[k] = {m_[k], static_cast<short>(POLLIN | (pend[1 - k].empty() ? 0 : POLLOUT)), 0};
      }
      if (::poll(p, 2, 20) <= 0) continue;
      for (int k = 0; k < 2; ++k) {
        if (p[k].revents & POLLIN) {
          ssize_t r = ::read(m_[k], buf, sizeof buf);
          if (cut_) {
            pend[0].clear();
            pend[1].clear();
            continue;
          }
          for (ssize_t i = 0; i < r; ++i) {
            uint8_t b = buf[i];
            if (one_in_ > 0 && hit(rng) == 0) {
              b ^= static_cast<uint8_t>(1u << bit(rng));
              ++flipped;
            }
            pend[k].push_back(b);
          }
          if (r > 0) relayed += static_cast<uint64_t>(r);
        }
        if ((p[k].revents & POLLOUT) && !pend[1 - k].empty()) {
          auto& q = pend[1 - k];
          ssize_t w = ::write(m_[k], q.data(), q.size());
          if (w > 0) q.erase(q.begin(), q.begin() + w);
        }
      }
    }
  }
  int one_in_;
  int m_[2] = {-1, -1}, s1_ = -1, s2_ = -1;
  std::atomic<bool> stop_{false}, cut_{false};
  std::thread thread_;
};

}  // namespace dcdt_test
