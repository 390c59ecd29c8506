// Small POSIX socket helpers shared by the channels, the InnerLinkManager
// and the Finder (internal header).
#pragma once

#include <netinet/in.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mrt::dcdt::net {

bool MakeAddr(const std::string& ip, int port, sockaddr_in* out);
std::string AddrToString(const sockaddr_in& a);
void SetNonBlocking(int fd, bool on);
/// Writes all bytes (blocking fd), false on error.
bool WriteAll(int fd, const uint8_t* data, size_t n);
/// A TCP listening socket bound to ip:port (port 0 = ephemeral); -1 on error.
int TcpListen(const std::string& ip, int port);
/// Port a socket is bound to.
int BoundPort(int fd);
/// Connects to ip:port within timeout_ms (optionally binding the local ip); -1 on error.
int TcpConnect(const std::string& local_ip, const std::string& ip, int port, int timeout_ms);
/// Waits up to timeout_ms for an incoming connection; -1 when none.
int TcpAccept(int listen_fd, int timeout_ms, sockaddr_in* peer);
void TuneStream(int fd);

/// eventfd-based wake-up for poll loops.
class Waker {
 public:
  Waker();
  ~Waker();
  int fd() const { return fd_; }
  void Wake();
  void Drain();

 private:
  int fd_ = -1;
};

}  // namespace mrt::dcdt::net
