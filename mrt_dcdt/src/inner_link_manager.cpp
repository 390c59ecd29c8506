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

#include "mrt_dcdt/frame.h"

namespace mrt::dcdt {

namespace {
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
}  // namespace

InnerLinkManager::InnerLinkManager(std::string dir, int agora_id, ReceiveFn rx)
    : dir_(std::move(dir)), agora_id_(agora_id), rx_(std::move(rx)) {}

InnerLinkManager::~InnerLinkManager() { stop(); }

void InnerLinkManager::start() {
  ::mkdir(dir_.c_str(), 0700);
  path_ = dir_ + "/" + std::to_string(agora_id_) + ".sock";
  sockaddr_un a;
  if (!make_unix(path_, &a)) {
    ++errors_;
    return;
  }
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  int buf = 4 << 20;
  setsockopt(fd_, SOL_SOCKET, SO_SNDBUF, &buf, sizeof buf);
  setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buf, sizeof buf);
  ::unlink(path_.c_str());
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ++errors_;
    ::close(fd_);
    fd_ = -1;
    return;
  }
  timeval tv{0, 200000};  // a stuck peer delays a sender at most 200 ms
  setsockopt(fd_, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
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
}

void InnerLinkManager::refresh_peers(bool force) {
  std::lock_guard<std::mutex> l(peers_mutex_);
  const int64_t now = now_ms();
  if (!force && now - peers_time_ < 100) return;
  peers_time_ = now;
  peers_.clear();
  DIR* d = ::opendir(dir_.c_str());
  if (!d) return;
  const std::string self = std::to_string(agora_id_) + ".sock";
  while (dirent* e = ::readdir(d)) {
    std::string n = e->d_name;
    if (n.size() > 5 && n.compare(n.size() - 5, 5, ".sock") == 0 && n != self) peers_.push_back(dir_ + "/" + n);
  }
  ::closedir(d);
}

int InnerLinkManager::peers() {
  refresh_peers(false);
  std::lock_guard<std::mutex> l(peers_mutex_);
  return static_cast<int>(peers_.size());
}

std::vector<int> InnerLinkManager::peer_ids() {
  refresh_peers(false);
  std::lock_guard<std::mutex> l(peers_mutex_);
  std::vector<int> ids;
  for (const auto& p : peers_) {
    const auto slash = p.rfind('/');
    ids.push_back(std::atoi(p.c_str() + slash + 1));
  }
  return ids;
}

void InnerLinkManager::send(const Msg& msg) {
  if (fd_ < 0) return;
  refresh_peers(false);
  std::vector<std::string> peers;
  {
    std::lock_guard<std::mutex> l(peers_mutex_);
    peers = peers_;
  }
  if (peers.empty()) return;
  auto bytes = encode_msg(msg, 0);
  for (const auto& p : peers) {
    sockaddr_un a;
    if (!make_unix(p, &a)) continue;
    if (::sendto(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL, reinterpret_cast<sockaddr*>(&a), sizeof a) < 0) {
      if (errno == ECONNREFUSED) {
        ::unlink(p.c_str());  // a socket file left by a dead Agora
        refresh_peers(true);
      } else if (errno != ENOENT) {
        ++errors_;
      }
    }
  }
}

void InnerLinkManager::loop() {
  std::vector<uint8_t> buf(kMaxBody + kFrameOverhead);
  while (!stop_) {
    pollfd p[2] = {{fd_, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
    ::poll(p, 2, 200);
    if (p[1].revents) waker_.drain();
    if (!(p[0].revents & POLLIN)) continue;
    for (int k = 0; k < 1024; ++k) {
      ssize_t r = ::recv(fd_, buf.data(), buf.size(), MSG_DONTWAIT);
      if (r < 0) break;
      Frame f;
      MsgFrame mf;
      if (!decode_datagram(buf.data(), static_cast<size_t>(r), &f) || f.kind != FrameKind::MSG ||
          !decode_msg_body(f.body, &mf)) {
        ++errors_;
        continue;
      }
      rx_(std::make_shared<Msg>(std::move(mf.msg)));
    }
  }
}

}  // namespace mrt::dcdt
