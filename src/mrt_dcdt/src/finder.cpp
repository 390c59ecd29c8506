#include "finder.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "mrt_dcdt/agora.h"

namespace mrt::dcdt {

namespace {
constexpr auto kHelloWait = std::chrono::seconds(2);  // an accepted connection must say HELLO within this
}  // namespace

FinderSlot::~FinderSlot() {
  if (fd >= 0) ::close(fd);
}

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
  listen_fd_ = net::tcp_listen(cfg_.local_addr, agora_->options().finder_tcp_port);
  thread_ = std::thread([this] { loop(); });
}

void Finder::stop() {
  stop_ = true;
  waker_.wake();
  if (thread_.joinable()) thread_.join();
  if (mcast_fd_ >= 0) ::close(mcast_fd_);
  if (listen_fd_ >= 0) ::close(listen_fd_);
  mcast_fd_ = listen_fd_ = -1;
  for (auto& a : accepted_) ::close(a->fd);
  accepted_.clear();
}

int Finder::peers() { return static_cast<int>(peer_ids().size()); }

std::vector<int> Finder::peer_ids() {
  std::lock_guard<std::mutex> l(mutex_);
  std::vector<int> ids;
  const auto now = Clock::now();
  for (auto& [id, t] : seen_)
    if (now - t < std::chrono::seconds(3)) ids.push_back(id);
  return ids;
}

Finder::Link& Finder::link_of(int peer, bool dialling, const std::string& name) {
  Link& k = links_[peer];
  if (!k.slot) {
    k.slot = std::make_shared<FinderSlot>();
    k.dialling = dialling;
    auto rx = [a = agora_](std::shared_ptr<Msg> m, Channel* ch) { a->route(std::move(m), Source{Source::CHANNEL, ch}); };
    new_channels_.push_back(make_finder_channel(name, dialling, k.slot, agora_->options().channel, rx));
  }
  return k;
}

void Finder::on_beacon(const Beacon& b) {
  // The Agora with the smaller id dials; the other accepts. The dialling
  // side dials again whenever it hears the peer while not connected.
  const bool connected = agora_->has_connected_peer(b.agora_id);
  std::lock_guard<std::mutex> l(mutex_);
  const auto now = Clock::now();
  seen_[b.agora_id] = now;
  if (agora_->agora_id() < b.agora_id && b.tcp_port != 0) {
    Link& k = link_of(b.agora_id, true,
                      "finder -> " + b.tcp_addr + ":" + std::to_string(b.tcp_port) + " (agora " +
                          std::to_string(b.agora_id) + ")");
    k.seen = now;
    std::lock_guard<std::mutex> sl(k.slot->mu);
    k.slot->addr = b.tcp_addr;
    k.slot->port = b.tcp_port;
    if (!connected) k.slot->dial = true;
  } else if (auto it = links_.find(b.agora_id); it != links_.end()) {
    it->second.seen = now;
  }
}

bool Finder::on_accepted_readable(Accepted& a) {
  uint8_t buf[4096];
  const ssize_t r = ::recv(a.fd, buf, sizeof buf, MSG_DONTWAIT);
  const bool expired = Clock::now() > a.deadline;
  if (r < 0 && (errno == EAGAIN || errno == EINTR) && !expired) return false;
  if (r <= 0) {
    ::close(a.fd);
    return true;
  }
  a.bytes.insert(a.bytes.end(), buf, buf + r);
  a.dec.feed(buf, static_cast<size_t>(r));
  while (auto f = a.dec.next()) {
    Hello h;
    if (f->kind != FrameKind::HELLO || !decode_hello_body(f->body, &h)) continue;
    std::lock_guard<std::mutex> l(mutex_);
    if (h.agora_id == agora_->agora_id() || (links_.count(h.agora_id) && links_[h.agora_id].dialling)) break;
    Link& k = link_of(h.agora_id, false, "finder <- agora " + std::to_string(h.agora_id));
    k.seen = Clock::now();
    std::lock_guard<std::mutex> sl(k.slot->mu);
    if (k.slot->fd >= 0) ::close(k.slot->fd);  // an older connection nobody took yet
    k.slot->fd = a.fd;
    k.slot->prefix = std::move(a.bytes);  // the channel's session reads the HELLO again
    k.slot->fd_waiting = true;
    return true;
  }
  if (a.bytes.size() > 4096 || expired) {
    ::close(a.fd);  // not a DCDT peer
    return true;
  }
  return false;
}

void Finder::forget_silent_peers() {
  const auto now = Clock::now();
  std::vector<int> silent;
  {
    std::lock_guard<std::mutex> l(mutex_);
    for (auto& [id, k] : links_)
      if (now - k.seen > std::chrono::milliseconds(agora_->options().finder_forget_ms)) silent.push_back(id);
  }
  for (int id : silent) {
    if (agora_->has_connected_peer(id)) continue;
    std::lock_guard<std::mutex> l(mutex_);
    auto it = links_.find(id);
    if (it == links_.end()) continue;
    it->second.slot->forget = true;  // the channel ends; the Agora collects it and counts what it held
    links_.erase(it);
  }
}

void Finder::loop() {
  sockaddr_in group;
  net::make_addr(cfg_.multicast_addr, cfg_.port, &group);
  const int announce = agora_->options().finder_announce_port;
  Beacon me{agora_->agora_id(), host_key_, cfg_.local_addr,
            static_cast<uint16_t>(announce > 0 ? announce : listen_fd_ >= 0 ? net::bound_port(listen_fd_) : 0)};
  const auto beacon = encode_beacon(me);
  auto next_beacon = Clock::now();
  std::vector<uint8_t> buf(2048);
  while (!stop_) {
    if (Clock::now() >= next_beacon && mcast_fd_ >= 0) {
      ::sendto(mcast_fd_, beacon.data(), beacon.size(), 0, reinterpret_cast<sockaddr*>(&group), sizeof group);
      next_beacon = Clock::now() + std::chrono::milliseconds(period_ms_);
      forget_silent_peers();
      agora_->add_channel(nullptr);  // collects channels that ended
    }
    std::vector<pollfd> p = {{mcast_fd_, POLLIN, 0}, {listen_fd_, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
    for (auto& a : accepted_) p.push_back({a->fd, POLLIN, 0});
    ::poll(p.data(), p.size(), 50);
    if (p[2].revents) waker_.drain();
    if (mcast_fd_ >= 0 && (p[0].revents & POLLIN)) {
      ssize_t r = ::recv(mcast_fd_, buf.data(), buf.size(), MSG_DONTWAIT);
      Frame f;
      Beacon b;
      if (r > 0 && decode_datagram(buf.data(), static_cast<size_t>(r), &f) && f.kind == FrameKind::BEACON &&
          decode_beacon_body(f.body, &b) && b.agora_id != me.agora_id && b.host_key != host_key_)
        on_beacon(b);
    }
    for (size_t i = 0, n = accepted_.size(); i < n; ++i) {
      const bool ready = p[3 + i].revents != 0;
      if ((ready || Clock::now() > accepted_[i]->deadline) && on_accepted_readable(*accepted_[i]))
        accepted_[i].reset();
    }
    accepted_.erase(std::remove(accepted_.begin(), accepted_.end(), nullptr), accepted_.end());
    if (listen_fd_ >= 0 && (p[1].revents & POLLIN)) {
      int fd = net::tcp_accept(listen_fd_, 0, nullptr);
      if (fd >= 0) accepted_.push_back(std::make_unique<Accepted>(Accepted{fd, {}, {}, Clock::now() + kHelloWait}));
    }
    std::vector<std::unique_ptr<Channel>> fresh;
    {
      std::lock_guard<std::mutex> l(mutex_);
      fresh.swap(new_channels_);
    }
    for (auto& c : fresh) agora_->add_channel(std::move(c));
  }
}

}  // namespace mrt::dcdt
