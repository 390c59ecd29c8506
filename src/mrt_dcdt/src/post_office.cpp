#include "mrt_dcdt/post_office.h"

namespace mrt::dcdt {

const char* policy_name(PostOfficePolicy p) {
  switch (p) {
    case PostOfficePolicy::SLWB: return "SLWB";
    case PostOfficePolicy::SLWDWCV: return "SLWDWCV";
    case PostOfficePolicy::SLWSM: return "SLWSM";
  }
  return "?";
}

bool parse_policy(const std::string& s, PostOfficePolicy* out) {
  if (s == "SLWB") *out = PostOfficePolicy::SLWB;
  else if (s == "SLWDWCV") *out = PostOfficePolicy::SLWDWCV;
  else if (s == "SLWSM") *out = PostOfficePolicy::SLWSM;
  else return false;
  return true;
}

PostOffice::~PostOffice() = default;

void PostOffice::register_mailbox(MailBox* box) {
  std::lock_guard<std::mutex> l(mutex_);
  boxes_[box->member_id] = box;
}

void PostOffice::unregister_mailbox(MailBox* box) {
  std::lock_guard<std::mutex> l(mutex_);
  auto it = boxes_.find(box->member_id);
  if (it != boxes_.end() && it->second == box) {
    drops_of_unregistered_ += box->dropped;
    refused_of_unregistered_ += box->refused;
    boxes_.erase(it);
  }
  for (auto& [type, m] : subs_) m.erase(box->member_id);
}

uint64_t PostOffice::mailbox_drops() {
  std::lock_guard<std::mutex> l(mutex_);
  uint64_t n = drops_of_unregistered_;
  for (const auto& [id, box] : boxes_) n += box->dropped;
  return n;
}

uint64_t PostOffice::guaranteed_refused() {
  std::lock_guard<std::mutex> l(mutex_);
  uint64_t n = refused_of_unregistered_;
  for (const auto& [id, box] : boxes_) n += box->refused;
  return n;
}

namespace {
// Makes room for `need` bytes by dropping the oldest non-guaranteed
// messages; false when only guaranteed ones are left and it still does not fit.
bool make_room(MailBox* box, size_t need) {
  auto it = box->queue.begin();
  while (box->bytes + need > PostOffice::kMailBoxBytes) {
    while (it != box->queue.end() && (*it)->delivery_warranty() == DCDT_DW_GUARANTEED) ++it;
    if (it == box->queue.end()) return false;
    box->bytes -= PostOffice::cost(**it);
    it = box->queue.erase(it);
    ++box->dropped;
  }
  return true;
}
}  // namespace

void PostOffice::subscribe(int member_id, int type, int scope_mask) {
  std::lock_guard<std::mutex> l(mutex_);
  subs_[type][member_id] |= (scope_mask & DCDT_ALL_MSG);
}

void PostOffice::unsubscribe(int member_id, int type, int scope_mask) {
  std::lock_guard<std::mutex> l(mutex_);
  auto it = subs_.find(type);
  if (it == subs_.end()) return;
  auto jt = it->second.find(member_id);
  if (jt == it->second.end()) return;
  jt->second &= ~scope_mask;
  if (jt->second == 0) it->second.erase(jt);
}

void PostOffice::unsubscribe_all(int member_id) {
  std::lock_guard<std::mutex> l(mutex_);
  for (auto& [type, m] : subs_) m.erase(member_id);
}

bool PostOffice::has_subscriptions(int member_id) {
  std::lock_guard<std::mutex> l(mutex_);
  for (auto& [type, m] : subs_)
    if (m.count(member_id)) return true;
  return false;
}

bool PostOffice::dispatch_locked(const MsgPtr& msg) {
  auto it = subs_.find(msg->type());
  if (it == subs_.end()) return true;
  const size_t need = cost(*msg);
  const bool guaranteed = msg->delivery_warranty() == DCDT_DW_GUARANTEED;
  bool all = true;
  const int scope = msg->header().remote ? DCDT_REMOTE_MSG : DCDT_LOCAL_MSG;
  const bool own_agora = msg->agora_id() == agora_id;
  for (const auto& [member, mask] : it->second) {
    if (!(mask & scope)) continue;
    if (own_agora && member == msg->member_id()) continue;  // never to its producer
    auto b = boxes_.find(member);
    if (b == boxes_.end()) continue;
    MailBox* box = b->second;
    if (!make_room(box, need)) {
      if (guaranteed) {
        ++box->refused;
        all = false;
      } else {
        ++box->dropped;
      }
      continue;
    }
    box->queue.push_back(msg);
    box->bytes += need;
    box->cv.notify_one();
  }
  return all;
}

MsgPtr PostOffice::pop(MailBox* box) {
  std::lock_guard<std::mutex> l(mutex_);
  if (box->queue.empty()) return nullptr;
  MsgPtr m = std::move(box->queue.front());
  box->queue.pop_front();
  box->bytes -= cost(*m);
  return m;
}

size_t PostOffice::pending(MailBox* box) {
  std::lock_guard<std::mutex> l(mutex_);
  return box->queue.size();
}

size_t PostOffice::wait_for_mail(MailBox* box, const std::atomic<bool>* stop, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> l(mutex_);
  box->cv.wait_for(l, timeout, [&] { return !box->queue.empty() || (stop && stop->load()); });
  return box->queue.size();
}

void PostOffice::wake_all() {
  std::lock_guard<std::mutex> l(mutex_);
  for (auto& [id, box] : boxes_) box->cv.notify_all();
}

namespace {

// Single Lock With Buffer: the publisher fans out under the lock.
class SlwbPostOffice : public PostOffice {
 public:
  SlwbPostOffice() : PostOffice(PostOfficePolicy::SLWB) {}
  bool post(MsgPtr msg) override {
    std::lock_guard<std::mutex> l(mutex_);
    return dispatch_locked(msg);
  }
};

// Base of the two dispatcher policies: a MsgManager thread fans out.
class DispatcherPostOffice : public PostOffice {
 public:
  DispatcherPostOffice(PostOfficePolicy p, size_t capacity) : PostOffice(p), capacity_(capacity) {
    thread_ = std::thread([this] { loop(); });
  }
  ~DispatcherPostOffice() override {
    {
      std::lock_guard<std::mutex> l(mutex_);
      stop_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }
  bool post(MsgPtr msg) override {
    std::unique_lock<std::mutex> l(mutex_);
    // SLWSM: wait for the single slot (bounded wait; a stopped office drops).
    space_cv_.wait(l, [&] { return queue_.size() < capacity_ || stop_; });
    if (stop_) return msg->delivery_warranty() != DCDT_DW_GUARANTEED;
    queue_.push_back(std::move(msg));
    cv_.notify_one();
    return true;
  }

 private:
  void loop() {
    std::unique_lock<std::mutex> l(mutex_);
    while (true) {
      cv_.wait(l, [&] { return !queue_.empty() || stop_; });
      if (stop_ && queue_.empty()) return;
      while (!queue_.empty()) {
        MsgPtr m = std::move(queue_.front());
        queue_.pop_front();
        dispatch_locked(m);
      }
      space_cv_.notify_all();
    }
  }
  size_t capacity_;
  std::deque<MsgPtr> queue_;
  std::condition_variable cv_, space_cv_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace

std::unique_ptr<PostOffice> PostOffice::create(PostOfficePolicy policy) {
  switch (policy) {
    case PostOfficePolicy::SLWDWCV:
      return std::make_unique<DispatcherPostOffice>(policy, kMailBoxCapacity);
    case PostOfficePolicy::SLWSM:
      return std::make_unique<DispatcherPostOffice>(policy, 1);
    case PostOfficePolicy::SLWB:
    default:
      return std::make_unique<SlwbPostOffice>();
  }
}

}  // namespace mrt::dcdt
