#include "net_util.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

namespace mrt::dcdt::net {

bool make_addr(const std::string& ip, int port, sockaddr_in* out) {
  *out = sockaddr_in{};
  out->sin_family = AF_INET;
  out->sin_port = htons(static_cast<uint16_t>(port));
  return inet_pton(AF_INET, ip.c_str(), &out->sin_addr) == 1;
}

std::string addr_to_string(const sockaddr_in& a) {
  char buf[INET_ADDRSTRLEN] = {0};
  inet_ntop(AF_INET, &a.sin_addr, buf, sizeof buf);
  return buf;
}

void set_non_blocking(int fd, bool on) {
  int fl = fcntl(fd, F_GETFL, 0);
  fcntl(fd, F_SETFL, on ? (fl | O_NONBLOCK) : (fl & ~O_NONBLOCK));
}

bool write_all(int fd, const uint8_t* data, size_t n) {
  while (n > 0) {
    ssize_t w = ::send(fd, data, n, MSG_NOSIGNAL);
    if (w < 0 && errno == ENOTSOCK) w = ::write(fd, data, n);  // serial lines
    if (w < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) {
        pollfd p{fd, POLLOUT, 0};
        if (::poll(&p, 1, 1000) <= 0) return false;
        continue;
      }
      return false;
    }
    data += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

int tcp_listen(const std::string& ip, int port) {
  sockaddr_in a;
  if (!make_addr(ip, port, &a)) return -1;
  int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 16) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

int bound_port(int fd) {
  sockaddr_in a{};
  socklen_t l = sizeof a;
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&a), &l) != 0) return 0;
  return ntohs(a.sin_port);
}

void tune_stream(int fd) {
  int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

int tcp_connect(const std::string& local_ip, const std::string& ip, int port, int timeout_ms) {
  sockaddr_in a;
  if (!make_addr(ip, port, &a)) return -1;
  int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  if (!local_ip.empty()) {
    sockaddr_in l;
    if (make_addr(local_ip, 0, &l)) ::bind(fd, reinterpret_cast<sockaddr*>(&l), sizeof l);
  }
  set_non_blocking(fd, true);
  int r = ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  if (r != 0 && errno == EINPROGRESS) {
    pollfd p{fd, POLLOUT, 0};
    if (::poll(&p, 1, timeout_ms) == 1) {
      int err = 0;
      socklen_t el = sizeof err;
      getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &el);
      r = err == 0 ? 0 : -1;
    }
  }
  if (r == 0) {
    // Dialling a free port of the ephemeral range can connect a socket to
    // itself (TCP simultaneous open); that is not a peer.
    sockaddr_in me{}, peer{};
    socklen_t ml = sizeof me, pl = sizeof peer;
    getsockname(fd, reinterpret_cast<sockaddr*>(&me), &ml);
    getpeername(fd, reinterpret_cast<sockaddr*>(&peer), &pl);
    if (me.sin_port == peer.sin_port && me.sin_addr.s_addr == peer.sin_addr.s_addr) r = -1;
  }
  if (r != 0) {
    ::close(fd);
    return -1;
  }
  set_non_blocking(fd, false);
  tune_stream(fd);
  return fd;
}

int tcp_accept(int listen_fd, int timeout_ms, sockaddr_in* peer) {
  pollfd p{listen_fd, POLLIN, 0};
  if (::poll(&p, 1, timeout_ms) != 1) return -1;
  sockaddr_in a{};
  socklen_t l = sizeof a;
  int fd = ::accept4(listen_fd, reinterpret_cast<sockaddr*>(&a), &l, SOCK_CLOEXEC);
  if (fd < 0) return -1;
  if (peer) *peer = a;
  tune_stream(fd);
  return fd;
}

Waker::Waker() { fd_ = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC); }
Waker::~Waker() {
  if (fd_ >= 0) ::close(fd_);
}
void Waker::wake() {
  uint64_t one = 1;
  [[maybe_unused]] ssize_t r = ::write(fd_, &one, sizeof one);
}
void Waker::drain() {
  uint64_t v;
  [[maybe_unused]] ssize_t r = ::read(fd_, &v, sizeof v);
}

}  // namespace mrt::dcdt::net
