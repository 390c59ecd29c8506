#include "finder.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/frame.h"

namespace mrt::dcdt {

using Clock = std::chrono::steady_clock;

Finder::Finder(Agora* agora, const AgoraConfig& cfg, const std::string& inner_dir, int period_ms)
    : agora_(agora), cfg_(cfg), period_ms_(period_ms > 0 ? period_ms : 200) {
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  // Agoras sharing host and inner-link directory already talk through inner links.
  host_key_ = std::string(host) + ":" +
              (agora->options().inner_links ? inner_dir : "agora" + std::to_string(agora->agora_id()));
}

Finder::~Finder() { stop(); }

void Finder::start() {
  sockaddr_in group;
  net::make_addr(cfg_.multicast_addr, cfg_.port, &group);
  in_addr local{};
  inet_pton(AF_INET, cfg_.local_addr.c_str(), &local);
  mcast_fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  int one = 1;
  setsockopt(mcast_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  setsockopt(mcast_fd_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
  if (::bind(mcast_fd_, reinterpret_cast<sockaddr*>(&group), sizeof group) != 0) {
    ::close(mcast_fd_);
    mcast_fd_ = -1;
  } else {
    ip_mreq mreq{};
    mreq.imr_multiaddr = group.sin_addr;
    mreq.imr_interface = local;
    setsockopt(mcast_fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &mreq, sizeof mreq);
    setsockopt(mcast_fd_, IPPROTO_IP, IP_MULTICAST_IF, &local, sizeof local);
    unsigned char loop = 1;
    // A loopback Agora keeps its announcements on this host (TTL 0).
    unsigned char ttl = (ntohl(local.s_addr) >> 24) == 127 ? 0 : 1;
    setsockopt(mcast_fd_, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop);
    setsockopt(mcast_fd_, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
  }
  listen_fd_ = net::tcp_listen(cfg_.local_addr, 0);
  thread_ = std::thread([this] { loop(); });
}

void Finder::stop() {
  stop_ = true;
  waker_.wake();
  if (thread_.joinable()) thread_.join();
  if (mcast_fd_ >= 0) ::close(mcast_fd_);
  if (listen_fd_ >= 0) ::close(listen_fd_);
  mcast_fd_ = listen_fd_ = -1;
}

int Finder::peers() {
  std::lock_guard<std::mutex> l(mutex_);
  int n = 0;
  const auto now = Clock::now();
  for (auto& [id, t] : seen_)
    if (now - t < std::chrono::seconds(3)) ++n;
  return n;
}

std::vector<int> Finder::peer_ids() {
  std::lock_guard<std::mutex> l(mutex_);
  std::vector<int> ids;
  const auto now = Clock::now();
  for (auto& [id, t] : seen_)
    if (now - t < std::chrono::seconds(3)) ids.push_back(id);
  return ids;
}

void Finder::loop() {
  sockaddr_in group;
  net::make_addr(cfg_.multicast_addr, cfg_.port, &group);
  Beacon me{agora_->agora_id(), host_key_, cfg_.local_addr,
            static_cast<uint16_t>(listen_fd_ >= 0 ? net::bound_port(listen_fd_) : 0)};
  const auto beacon = encode_beacon(me);
  auto next_beacon = Clock::now();
  auto rx = [a = agora_](std::shared_ptr<Msg> m, Channel* ch) { a->route(std::move(m), Source{Source::CHANNEL, ch}); };
  std::vector<uint8_t> buf(2048);
  while (!stop_) {
    if (Clock::now() >= next_beacon && mcast_fd_ >= 0) {
      ::sendto(mcast_fd_, beacon.data(), beacon.size(), 0, reinterpret_cast<sockaddr*>(&group), sizeof group);
      next_beacon = Clock::now() + std::chrono::milliseconds(period_ms_);
      agora_->add_channel(nullptr);  // collects channels whose connection ended
    }
    pollfd p[3] = {{mcast_fd_, POLLIN, 0}, {listen_fd_, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
    ::poll(p, 3, 50);
    if (p[2].revents) waker_.drain();
    if (mcast_fd_ >= 0 && (p[0].revents & POLLIN)) {
      ssize_t r = ::recv(mcast_fd_, buf.data(), buf.size(), MSG_DONTWAIT);
      Frame f;
      Beacon b;
      if (r > 0 && decode_datagram(buf.data(), static_cast<size_t>(r), &f) && f.kind == FrameKind::BEACON &&
          decode_beacon_body(f.body, &b) && b.agora_id != me.agora_id && b.host_key != host_key_) {
        bool dial = false;
        const auto now = Clock::now();
        {
          std::lock_guard<std::mutex> l(mutex_);
          seen_[b.agora_id] = now;
          // The Agora with the smaller id dials; the other accepts. It dials
          // again when the connection is gone (the peer restarted), at most
          // once a second.
          auto it = last_dial_.find(b.agora_id);
          if (me.agora_id < b.agora_id && b.tcp_port != 0 &&
              (it == last_dial_.end() || now - it->second > std::chrono::seconds(1)) &&
              !agora_->has_connected_peer(b.agora_id)) {
            last_dial_[b.agora_id] = now;
            dial = true;
          }
        }
        if (dial) {
          auto ch = make_dialled_tcp_channel(b.tcp_addr, b.tcp_port, agora_->options().channel, rx);
          agora_->add_channel(std::move(ch));
        }
      }
    }
    if (listen_fd_ >= 0 && (p[1].revents & POLLIN)) {
      int fd = net::tcp_accept(listen_fd_, 0, nullptr);
      if (fd >= 0) agora_->add_channel(make_accepted_tcp_channel(fd, agora_->options().channel, rx));
    }
  }
}

}  // namespace mrt::dcdt
