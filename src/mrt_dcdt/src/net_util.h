// Small POSIX socket helpers shared by the channels, the InnerLinkManager
// and the Finder (internal header).
#pragma once

#include <netinet/in.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mrt::dcdt::net {

bool make_addr(const std::string& ip, int port, sockaddr_in* out);
std::string addr_to_string(const sockaddr_in& a);
void set_non_blocking(int fd, bool on);
/// Writes all bytes (blocking fd), false on error.
bool write_all(int fd, const uint8_t* data, size_t n);
/// A TCP listening socket bound to ip:port (port 0 = ephemeral); -1 on error.
int tcp_listen(const std::string& ip, int port);
/// Port a socket is bound to.
int bound_port(int fd);
/// Connects to ip:port within timeout_ms (optionally binding the local ip); -1 on error.
int tcp_connect(const std::string& local_ip, const std::string& ip, int port, int timeout_ms);
/// Waits up to timeout_ms for an incoming connection; -1 when none.
int tcp_accept(int listen_fd, int timeout_ms, sockaddr_in* peer);
void tune_stream(int fd);

/// eventfd-based wake-up for poll loops.
class Waker {
 public:
  Waker();
  ~Waker();
  int fd() const { return fd_; }
  void wake();
  void drain();

 private:
  int fd_ = -1;
};

}  // namespace mrt::dcdt::net
