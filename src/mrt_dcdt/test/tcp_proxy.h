// A TCP relay on loopback that a test can kill (both connections closed,
// the listening port closed: connections are refused) and restart.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace dcdt_test {

class TcpProxy {
 public:
  TcpProxy(int listen_port, int target_port) : listen_port_(listen_port), target_port_(target_port) {
    thread_ = std::thread([this] { loop(); });
  }
  ~TcpProxy() {
    stop_ = true;
    thread_.join();
  }
  void kill() { down_ = true; }
  void Restart() { down_ = false; }
  std::atomic<uint64_t> relayed{0};
  std::atomic<int> sessions{0}, accepts{0};

 private:
  void loop() {
    while (!stop_) {
      if (down_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        continue;
      }
      int l = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
      int one = 1;
      setsockopt(l, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
      sockaddr_in a{};
      a.sin_family = AF_INET;
      a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      a.sin_port = htons(static_cast<uint16_t>(listen_port_));
      if (::bind(l, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(l, 4) != 0) {
        ::close(l);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      while (!stop_ && !down_) {
        pollfd p{l, POLLIN, 0};
        if (::poll(&p, 1, 20) != 1) continue;
        int in = ::accept4(l, nullptr, nullptr, SOCK_CLOEXEC);
        if (in < 0) continue;
        ++accepts;
        int out = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in t = a;
        t.sin_port = htons(static_cast<uint16_t>(target_port_));
        if (::connect(out, reinterpret_cast<sockaddr*>(&t), sizeof t) != 0) {
          ::close(in);
          ::close(out);
          continue;
        }
        ++sessions;
        Relay(in, out);
        ::close(in);
        ::close(out);
      }
      ::close(l);
    }
  }
  void Relay(int x, int y) {
    char buf[16384];
    while (!stop_ && !down_) {
      pollfd p[2] = {{x, POLLIN, 0}, {y, POLLIN, 0}};
      if (::poll(p, 2, 20) <= 0) continue;
      for (int k = 0; k < 2; ++k) {
        if (!(p[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
        ssize_t r = ::read(p[k].fd, buf, sizeof buf);
        if (r <= 0) return;
        if (::send(k == 0 ? y : x, buf, static_cast<size_t>(r), MSG_NOSIGNAL) != r) return;
        relayed += static_cast<uint64_t>(r);
      }
    }
  }
  int listen_port_, target_port_;
  std::atomic<bool> stop_{false}, down_{false};
  std::thread thread_;
};

}  // namespace dcdt_test
