#include "mrt_dcdt/agora.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "finder.h"
#include "inner_link_manager.h"

namespace mrt::dcdt {

namespace {
std::atomic<unsigned> g_signals{0};  // lock-free: safe in a signal handler
extern "C" void count_signal(int) { g_signals.fetch_add(1); }

int random_agora_id() {
  std::random_device rd;
  uint32_t v = rd() ^ (static_cast<uint32_t>(::getpid()) << 16) ^
               static_cast<uint32_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  v &= 0x7fffffff;
  return v == 0 ? 1 : static_cast<int>(v);
}

uint64_t random_incarnation() {
  std::random_device rd;
  uint64_t v = (static_cast<uint64_t>(rd()) << 32) ^ rd() ^
               static_cast<uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
  return v == 0 ? 1 : v;
}

AgoraOptions NetworkOptions(const std::string& file) {
  AgoraOptions o;
  o.network = true;
  o.config = load_agora_config(file);
  return o;
}
}  // namespace

Agora::Agora() : Agora(AgoraOptions{}) {}
Agora::Agora(const char* config_file) : Agora(NetworkOptions(config_file ? config_file : "")) {}
Agora::Agora(const std::string& config_file) : Agora(NetworkOptions(config_file)) {}
Agora::Agora(AgoraOptions options) : options_(std::move(options)) { setup(); }

std::string default_inner_dir() {
  if (const char* d = std::getenv("DCDT_INNER_DIR"); d && *d) return d;
  return "/tmp/dcdt-" + std::to_string(::getuid());
}

void Agora::setup() {
  agora_id_ = options_.agora_id > 0 ? options_.agora_id : random_agora_id();
  incarnation_ = random_incarnation();
  signal_base_ = g_signals.load();
  options_.channel.agora_id = agora_id_;
  options_.channel.incarnation = incarnation_;
  post_office_ = PostOffice::create(options_.config.policy);
  post_office_->agora_id = agora_id_;
  if (options_.inner_links) {
    if (options_.inner_dir.empty()) options_.inner_dir = default_inner_dir();
    InnerLinkOptions io;
    io.dir = options_.inner_dir;
    io.agora_id = agora_id_;
    io.incarnation = incarnation_;
    io.socket_buffer = options_.inner_socket_buffer;
    io.queue_bytes = options_.inner_queue_bytes;
    inner_ = std::make_unique<InnerLinkManager>(
        std::move(io), [this](std::shared_ptr<Msg> m) { route(std::move(m), Source{Source::INNER, nullptr}); });
    inner_->start();
  }
  if (!options_.network) return;
  auto rx = [this](std::shared_ptr<Msg> m, Channel* ch) { route(std::move(m), Source{Source::CHANNEL, ch}); };
  for (const auto& c : options_.config.channels) {
    auto ch = c.kind == ChannelConfig::IP ? make_ip_channel(c, options_.channel, rx)
                                          : make_serial_channel(c, options_.channel, rx);
    ch->start();
    std::lock_guard<std::mutex> l(channels_mutex_);
    channels_.push_back(std::move(ch));
  }
  if (options_.finder && options_.config.port > 0) {
    finder_ = std::make_unique<Finder>(this, options_.config, options_.inner_dir, options_.finder_period_ms);
    finder_->start();
  }
}

Agora::~Agora() {
  shutdown();
  {
    std::unique_lock<std::mutex> l(members_mutex_);
    for (Member* m : members_) {
      if (m->thread_id_.load() == std::this_thread::get_id()) {
        std::fprintf(stderr, "mrt_dcdt: an Agora destroyed from inside its Member %d; call shutdown() there and "
                             "destroy the Agora after lets_work returns\n", m->member_id_);
        std::abort();
      }
    }
    // lets_work running in another thread: it joins every Member, then returns.
    members_cv_.wait(l, [&] { return !running_; });
  }
  join_members();  // Members started by activate_member and never joined (none normally)
  stop_network();
  std::lock_guard<std::mutex> l(members_mutex_);
  for (Member* m : members_) {
    if (m->registered_) post_office_->unregister_mailbox(&m->mailbox_);
    m->registered_ = false;
    m->agora_ = nullptr;  // the Member may outlive its Agora
  }
  members_.clear();
}

void Agora::join_members() {
  // Each thread is moved out under the lock by exactly one joiner and joined
  // without the lock (the Member's last step takes it).
  for (;;) {
    std::thread t;
    Member* m = nullptr;
    {
      std::lock_guard<std::mutex> l(members_mutex_);
      for (Member* x : members_) {
        if (!x->thread_.joinable()) continue;
        t = std::move(x->thread_);
        x->joining_ = true;
        m = x;
        break;
      }
    }
    if (!m) return;
    t.join();
    std::lock_guard<std::mutex> l(members_mutex_);
    m->joining_ = false;  // m is alive: its destructor waits for this
    members_cv_.notify_all();
  }
}

void Agora::detach_member(Member* m) {
  std::thread t;
  {
    std::unique_lock<std::mutex> l(members_mutex_);
    if (m->thread_id_.load() != std::thread::id() && m->state_.load() != MemberState::TERMINATED) {
      // Destroyed while its thread runs: the derived part is gone, so no
      // virtual function may run any more.
      m->orphaned_ = true;
      if (m->in_job_) {
        std::fprintf(stderr, "mrt_dcdt: Member %d destroyed during its own job; terminate() it (or end lets_work) "
                             "before destroying it\n", m->member_id_);
        std::abort();
      }
      m->state_ = MemberState::TERMINATING;
    }
    if (m->thread_.joinable()) t = std::move(m->thread_);
    members_cv_.wait(l, [&] { return !m->joining_; });
    auto it = std::find(members_.begin(), members_.end(), m);
    if (it != members_.end()) members_.erase(it);
    if (m->registered_) post_office_->unregister_mailbox(&m->mailbox_);
    m->registered_ = false;
  }
  post_office_->wake_all();
  if (t.joinable()) t.join();
  m->agora_ = nullptr;
  notify_state_change();
}

void Agora::terminate_member(Member* m) {
  std::unique_lock<std::mutex> l(members_mutex_);
  if (m->state_.load() != MemberState::TERMINATED) m->state_ = MemberState::TERMINATING;
  members_cv_.notify_all();
  const auto id = m->thread_id_.load();
  l.unlock();
  post_office_->wake_all();
  if (id == std::thread::id() || id == std::this_thread::get_id()) return;
  // From another thread: return once the Member has finished (close() run),
  // so the caller may destroy it.
  l.lock();
  members_cv_.wait(l, [&] { return m->state_.load() == MemberState::TERMINATED; });
}

void Agora::stop_network() {
  if (finder_) finder_->stop();
  std::vector<std::unique_ptr<Channel>> chans;
  {
    std::lock_guard<std::mutex> l(channels_mutex_);
    chans.swap(channels_);
  }
  for (auto& c : chans) c->stop();
  chans.clear();
  if (inner_) inner_->stop();
  finder_.reset();
  inner_.reset();
}

void Agora::add_member(Member* m) {
  if (!m) return;
  std::lock_guard<std::mutex> l(members_mutex_);
  for (Member* x : members_)
    if (x == m) return;
  m->agora_ = this;
  m->member_id_ = next_member_id();
  m->mailbox_.member_id = m->member_id_;
  post_office_->register_mailbox(&m->mailbox_);
  m->registered_ = true;
  m->state_ = MemberState::ADDED;
  members_.push_back(m);
}

void Agora::start_thread_locked(Member* m) {
  m->state_ = MemberState::RUNNING;
  m->thread_ = std::thread([this, m] { m->run(&stop_); });
  m->thread_id_ = m->thread_.get_id();
}

void Agora::activate_member(Member* m) {
  bool start_now = false;
  {
    std::lock_guard<std::mutex> l(members_mutex_);
    if (!m || m->agora_ != this || m->state_ != MemberState::ADDED) return;
    m->state_ = MemberState::ACTIVE;
    start_now = running_ && !stop_;
  }
  if (!start_now) return;
  m->init();
  std::lock_guard<std::mutex> l(members_mutex_);
  if (running_ && !stop_ && m->state_ == MemberState::ACTIVE) start_thread_locked(m);
}

void Agora::lets_work() {
  std::vector<Member*> to_start;
  {
    std::lock_guard<std::mutex> l(members_mutex_);
    if (running_) return;
    running_ = true;
    for (Member* m : members_)
      if (m->state_ == MemberState::ACTIVE) to_start.push_back(m);
  }
  // init() of every Member first, so subscriptions exist before anyone shares.
  for (Member* m : to_start) m->init();
  {
    std::lock_guard<std::mutex> l(members_mutex_);
    for (Member* m : to_start)
      if (std::find(members_.begin(), members_.end(), m) != members_.end() && m->state_ == MemberState::ACTIVE &&
          !stop_)
        start_thread_locked(m);
  }
  {
    std::unique_lock<std::mutex> l(members_mutex_);
    auto done = [&] {
      if (shutdown_ || g_signals.load() != signal_base_) return true;
      for (Member* m : members_) {
        auto s = m->state_.load();
        if (s == MemberState::RUNNING || s == MemberState::ACTIVE) return false;
      }
      return true;
    };
    while (!done()) members_cv_.wait_for(l, std::chrono::milliseconds(10));
  }
  stop_ = true;
  post_office_->wake_all();
  join_members();
  std::lock_guard<std::mutex> l(members_mutex_);
  running_ = false;
  members_cv_.notify_all();  // under the lock: ~Agora may be waiting for this
}

void Agora::shutdown_on_signal(int signum) {
  struct sigaction sa {};
  sa.sa_handler = count_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  ::sigaction(signum, &sa, nullptr);
}

void Agora::shutdown() {
  shutdown_ = true;
  stop_ = true;
  notify_state_change();
  if (post_office_) post_office_->wake_all();
}

void Agora::notify_state_change() {
  std::lock_guard<std::mutex> l(members_mutex_);
  members_cv_.notify_all();
}

bool Agora::seen_before(const MsgHeader& h) {
  const Origin key{h.agora_id, h.incarnation, h.seq};
  std::lock_guard<std::mutex> l(seen_mutex_);
  if (!seen_.insert(key).second) return true;
  seen_order_.push_back(key);
  if (seen_order_.size() > 200000) {
    seen_.erase(seen_order_.front());
    seen_order_.pop_front();
  }
  return false;
}

bool Agora::route(std::shared_ptr<Msg> msg, const Source& src) {
  auto& h = msg->mutable_header();
  if (src.kind != Source::MEMBER) {
    if (h.agora_id == agora_id_ || seen_before(h)) {
      ++duplicates_;  // our own message came back, or a copy by another path
      return true;
    }
    if (src.kind == Source::CHANNEL) {
      h.hops = static_cast<uint8_t>(h.hops + 1);
      h.remote = src.channel->mode == ChannelMode::LINK;
    }
    if (h.hops > kMaxHops) {
      ++hop_limited_;
      return true;
    }
  }
  ++routed_;
  MsgPtr m = std::move(msg);
  bool delivered = post_office_->post(m);
  if (inner_ && src.kind != Source::INNER) inner_->send(*m);
  std::lock_guard<std::mutex> l(channels_mutex_);
  for (auto& ch : channels_) {
    if (ch.get() == src.channel || ch->dead()) continue;
    if ((src.kind == Source::MEMBER || (ch->mode == ChannelMode::BRIDGE && m->header().hops <= ch->level)) &&
        !ch->send(m)) {
      ++channel_refused_;
      delivered = false;
    }
  }
  return delivered;
}

void Agora::add_channel(std::unique_ptr<Channel> c) {
  std::vector<std::unique_ptr<Channel>> dead;
  {
    std::lock_guard<std::mutex> l(channels_mutex_);
    for (auto it = channels_.begin(); it != channels_.end();) {
      if ((*it)->dead()) {
        dead.push_back(std::move(*it));
        it = channels_.erase(it);
      } else {
        ++it;
      }
    }
    if (c) {
      c->start();
      channels_.push_back(std::move(c));
    }
  }
  for (auto& d : dead) {
    d->stop();
    channels_lost_ += d->stats().pending;  // a forgotten Finder peer's messages
  }
}

bool Agora::has_connected_peer(int id) {
  std::lock_guard<std::mutex> l(channels_mutex_);
  for (auto& c : channels_) {
    if (c->dead()) continue;
    auto s = c->stats();
    if (s.connected && s.peer_agora == id) return true;
  }
  return false;
}

AgoraStats Agora::stats() {
  AgoraStats s;
  s.routed = routed_;
  s.duplicates = duplicates_;
  s.hop_limited = hop_limited_;
  s.channel_refused = channel_refused_;
  s.channels_lost = channels_lost_;
  s.mailbox_dropped = post_office_->mailbox_drops();
  s.guaranteed_refused = post_office_->guaranteed_refused();
  if (inner_) {
    s.peer_ids = inner_->peer_ids();
    s.inner_peers = static_cast<int>(s.peer_ids.size());
    s.inner_errors = inner_->errors();
    s.inner_dropped = inner_->dropped();
    s.inner_stalled_peers = inner_->stalled_peers();
  }
  if (finder_) {
    auto f = finder_->peer_ids();
    s.finder_peers = static_cast<int>(f.size());
    s.peer_ids.insert(s.peer_ids.end(), f.begin(), f.end());
  }
  {
    std::lock_guard<std::mutex> l(channels_mutex_);
    for (auto& c : channels_) {
      s.channels.push_back(c->stats());
      if (s.channels.back().peer_agora) s.peer_ids.push_back(s.channels.back().peer_agora);
    }
  }
  std::sort(s.peer_ids.begin(), s.peer_ids.end());
  s.peer_ids.erase(std::unique(s.peer_ids.begin(), s.peer_ids.end()), s.peer_ids.end());
  return s;
}

}  // namespace mrt::dcdt
