#include "inner_link_manager.h"

#include <dirent.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "mrt_dcdt/frame.h"

namespace mrt::dcdt {

namespace {
constexpr uint8_t kMagic[4] = {'D', 'C', 'I', 'F'};
constexpr uint32_t kMaxFragments = (kMaxBody + kFrameOverhead) / kInnerFragmentData + 1;

int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
bool make_unix(const std::string& path, sockaddr_un* a) {
  *a = sockaddr_un{};
  a->sun_family = AF_UNIX;
  if (path.size() >= sizeof(a->sun_path)) return false;
  std::memcpy(a->sun_path, path.c_str(), path.size() + 1);
  return true;
}
void put_be(uint8_t* p, uint64_t v, int n) {
  for (int i = n - 1; i >= 0; --i, v >>= 8) p[i] = static_cast<uint8_t>(v);
}
uint64_t get_be(const uint8_t* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | p[i];
  return v;
}
}  // namespace

void check_inner_dir(const std::string& dir) {
  if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST)
    throw std::runtime_error(dir + ": cannot create the inner-link directory: " + std::strerror(errno));
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0)
    throw std::runtime_error(dir + ": " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode)) throw std::runtime_error(dir + ": the inner-link directory is not a directory");
  if (st.st_uid != ::geteuid())
    throw std::runtime_error(dir + ": the inner-link directory belongs to uid " + std::to_string(st.st_uid) +
                             ", not to this user (uid " + std::to_string(::geteuid()) + ")");
  if (st.st_mode & (S_IWGRP | S_IWOTH))
    throw std::runtime_error(dir + ": the inner-link directory is writable by group or others (chmod 700 it)");
}

InnerLinkManager::Peer::~Peer() {
  if (fd >= 0) ::close(fd);
}

InnerLinkManager::InnerLinkManager(InnerLinkOptions options, ReceiveFn rx)
    : options_(std::move(options)), rx_(std::move(rx)) {}

InnerLinkManager::~InnerLinkManager() { stop(); }

void InnerLinkManager::start() {
  check_inner_dir(options_.dir);
  path_ = options_.dir + "/" + std::to_string(options_.agora_id) + ".sock";
  sockaddr_un a;
  if (!make_unix(path_, &a)) {
    ++errors_;
    return;
  }
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  int buf = options_.socket_buffer;
  setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buf, sizeof buf);
  ::unlink(path_.c_str());
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ++errors_;
    ::close(fd_);
    fd_ = -1;
    return;
  }
  refresh_peers(true);
  thread_ = std::thread([this] { loop(); });
}

void InnerLinkManager::stop() {
  stop_ = true;
  waker_.wake();
  if (thread_.joinable()) thread_.join();
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(path_.c_str());
    fd_ = -1;
  }
  std::lock_guard<std::mutex> l(mutex_);
  peers_.clear();
}

bool InnerLinkManager::connect_peer(Peer& p) {
  sockaddr_un a;
  if (!make_unix(p.path, &a)) return false;
  p.fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  int buf = options_.socket_buffer;
  setsockopt(p.fd, SOL_SOCKET, SO_SNDBUF, &buf, sizeof buf);
  if (::connect(p.fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) return true;
  if (errno == ECONNREFUSED) ::unlink(p.path.c_str());  // a socket file left by a dead Agora
  ::close(p.fd);
  p.fd = -1;
  return false;
}

void InnerLinkManager::refresh_peers(bool force) {
  std::lock_guard<std::mutex> l(mutex_);
  const int64_t now = now_ms();
  if (!force && now - peers_time_ < 100) return;
  peers_time_ = now;
  DIR* d = ::opendir(options_.dir.c_str());
  if (!d) return;
  const std::string self = std::to_string(options_.agora_id) + ".sock";
  std::map<std::string, std::shared_ptr<Peer>> next;
  while (dirent* e = ::readdir(d)) {
    std::string n = e->d_name;
    if (n.size() <= 5 || n.compare(n.size() - 5, 5, ".sock") != 0 || n == self) continue;
    const std::string path = options_.dir + "/" + n;
    auto it = peers_.find(path);
    if (it != peers_.end() && !it->second->dead) {
      next[path] = it->second;
      continue;
    }
    auto p = std::make_shared<Peer>();
    p->path = path;
    p->id = std::atoi(n.c_str());
    if (connect_peer(*p)) next[path] = p;
  }
  ::closedir(d);
  peers_.swap(next);
}

int InnerLinkManager::peers() {
  refresh_peers(false);
  std::lock_guard<std::mutex> l(mutex_);
  return static_cast<int>(peers_.size());
}

std::vector<int> InnerLinkManager::peer_ids() {
  refresh_peers(false);
  std::lock_guard<std::mutex> l(mutex_);
  std::vector<int> ids;
  for (const auto& [path, p] : peers_) ids.push_back(p->id);
  return ids;
}

std::vector<int> InnerLinkManager::stalled_peers() {
  std::lock_guard<std::mutex> l(mutex_);
  std::vector<int> ids;
  for (const auto& [path, p] : peers_)
    if (p->stalled) ids.push_back(p->id);
  return ids;
}

void InnerLinkManager::send(const Msg& msg) {
  if (fd_ < 0) return;
  refresh_peers(false);
  const auto bytes = encode_msg(msg, 0);
  auto dgrams = std::make_shared<Datagrams>();
  size_t total = 0;
  {
    std::lock_guard<std::mutex> l(mutex_);
    if (peers_.empty()) return;
    const uint64_t number = ++next_number_;
    const uint32_t count = static_cast<uint32_t>((bytes.size() + kInnerFragmentData - 1) / kInnerFragmentData);
    for (uint32_t i = 0; i < count; ++i) {
      const size_t off = i * kInnerFragmentData, n = std::min(kInnerFragmentData, bytes.size() - off);
      std::vector<uint8_t> d(kInnerFragmentHeader + n);
      std::memcpy(d.data(), kMagic, 4);
      put_be(d.data() + 4, static_cast<uint32_t>(options_.agora_id), 4);
      put_be(d.data() + 8, options_.incarnation, 8);
      put_be(d.data() + 16, number, 8);
      put_be(d.data() + 24, i, 4);
      put_be(d.data() + 28, count, 4);
      std::memcpy(d.data() + kInnerFragmentHeader, bytes.data() + off, n);
      total += d.size();
      dgrams->push_back(std::move(d));
    }
    bool wake = false;
    for (auto& [path, p] : peers_) {
      if (p->dead) continue;
      // An empty queue always takes the next message (even one over the cap).
      if (!p->queue.empty() && (p->stalled || p->bytes + total > options_.queue_bytes)) {
        p->stalled = true;  // dropped from delivery until it has read its queue
        ++dropped_;
        continue;
      }
      p->queue.push_back(dgrams);
      p->bytes += total;
      flush_locked(*p);
      wake = wake || !p->queue.empty();
    }
    if (!wake) return;
  }
  waker_.wake();
}

void InnerLinkManager::flush_locked(Peer& p) {
  while (!p.queue.empty() && !p.dead) {
    const auto& msg = *p.queue.front();
    const auto& d = msg[p.next_fragment];
    if (::send(p.fd, d.data(), d.size(), MSG_DONTWAIT | MSG_NOSIGNAL) < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK) return;  // the loop polls for POLLOUT
      if (errno == ECONNREFUSED || errno == ENOTCONN) {
        p.dead = true;  // the peer went away; refresh_peers reconnects a new one
      } else {
        ++errors_;
      }
      p.queue.clear();
      p.bytes = 0;
      p.next_fragment = 0;
      return;
    }
    if (++p.next_fragment < msg.size()) continue;
    size_t sent = 0;
    for (const auto& x : msg) sent += x.size();
    p.bytes -= sent;
    p.next_fragment = 0;
    p.queue.pop_front();
  }
  if (p.queue.empty()) p.stalled = false;  // caught up: back in delivery
}

void InnerLinkManager::loop() {
  std::vector<uint8_t> buf(kInnerFragmentHeader + kInnerFragmentData + 64);
  while (!stop_) {
    std::vector<pollfd> fds = {{fd_, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
    std::vector<std::shared_ptr<Peer>> waiting;  // keeps their fds open during poll
    {
      std::lock_guard<std::mutex> l(mutex_);
      for (auto& [path, p] : peers_) {
        if (p->queue.empty() || p->dead) continue;
        waiting.push_back(p);
        fds.push_back({p->fd, POLLOUT, 0});
      }
    }
    ::poll(fds.data(), fds.size(), 100);
    if (fds[1].revents) waker_.drain();
    {
      std::lock_guard<std::mutex> l(mutex_);
      for (auto& p : waiting) flush_locked(*p);
    }
    refresh_peers(false);
    if (!(fds[0].revents & POLLIN)) continue;
    for (int k = 0; k < 1024; ++k) {
      ssize_t r = ::recv(fd_, buf.data(), buf.size(), MSG_DONTWAIT);
      if (r < 0) break;
      receive_datagram(buf.data(), static_cast<size_t>(r));
    }
  }
}

void InnerLinkManager::receive_datagram(const uint8_t* data, size_t len) {
  if (len < kInnerFragmentHeader || std::memcmp(data, kMagic, 4) != 0) {
    ++errors_;
    return;
  }
  const auto key = std::make_pair(static_cast<int>(get_be(data + 4, 4)), get_be(data + 8, 8));
  const uint64_t number = get_be(data + 16, 8);
  const auto index = static_cast<uint32_t>(get_be(data + 24, 4)), count = static_cast<uint32_t>(get_be(data + 28, 4));
  const uint8_t* body = data + kInnerFragmentHeader;
  const size_t n = len - kInnerFragmentHeader;
  if (count == 0 || count > kMaxFragments || index >= count) {
    ++errors_;
    return;
  }
  if (count == 1) {
    partials_.erase(key);
    deliver(body, n);
    return;
  }
  if (partials_.size() >= 64 && !partials_.count(key)) partials_.erase(partials_.begin());  // bounded memory
  Partial& p = partials_[key];
  if (index == 0) {
    p = Partial{number, 0, count, {}};
  } else if (p.number != number || p.next != index || p.count != count) {
    ++errors_;  // a fragment out of sequence: the message is incomplete
    partials_.erase(key);
    return;
  }
  p.bytes.insert(p.bytes.end(), body, body + n);
  if (++p.next < count) return;
  std::vector<uint8_t> whole = std::move(p.bytes);
  partials_.erase(key);
  deliver(whole.data(), whole.size());
}

void InnerLinkManager::deliver(const uint8_t* data, size_t len) {
  Frame f;
  MsgFrame mf;
  if (!decode_datagram(data, len, &f) || f.kind != FrameKind::MSG || !decode_msg_body(f.body, &mf)) {
    ++errors_;
    return;
  }
  rx_(std::make_shared<Msg>(std::move(mf.msg)));
}

}  // namespace mrt::dcdt
