#include "mrt_dcdt/member.h"

#include <chrono>

#include "mrt_dcdt/agora.h"

namespace mrt::dcdt {

Member::Member() = default;

Member::Member(Agora* agora) : agora_(agora) {}

Member::Member(Agora* agora, int period_ms) : agora_(agora), period_ms_(period_ms > 0 ? period_ms : 0) {}

Member::~Member() {
  // Stops and joins this Member's thread if it still runs (without calling
  // any virtual function: the derived part is already gone), then leaves
  // the Agora. See Agora::detach_member.
  if (agora_) agora_->detach_member(this);
}

void Member::subscribe_msg_type(int type, RequestType req_type) {
  if (agora_ && registered_) agora_->post_office().subscribe(member_id_, type, req_type);
}

void Member::unsubscribe_msg_type(int type, RequestType req_type) {
  if (agora_ && registered_) agora_->post_office().unsubscribe(member_id_, type, req_type);
}

void Member::unsubscribe_all() {
  if (agora_ && registered_) agora_->post_office().unsubscribe_all(member_id_);
}

Msg* Member::create_msg(int type, int delivery_warranty) {
  return new Msg(type, member_id_, agora_ ? agora_->agora_id() : 0, delivery_warranty);
}

Msg* Member::create_msg(int type) { return create_msg(type, DCDT_DW_GUARANTEED); }

bool Member::share_msg(Msg* msg) {
  if (!msg) return false;
  std::shared_ptr<Msg> owned(msg);
  if (!agora_) return false;
  auto& h = owned->mutable_header();
  h.member_id = member_id_;
  h.agora_id = agora_->agora_id();
  h.hops = 0;
  h.remote = false;
  h.incarnation = agora_->incarnation();
  h.seq = agora_->next_seq();
  return agora_->route(std::move(owned), Source{Source::MEMBER, nullptr});
}

const Msg* Member::receive_msg() {
  current_.reset();
  if (!agora_ || !registered_) return nullptr;
  current_ = agora_->post_office().pop(&mailbox_);
  return current_.get();  // shared with the other receivers: read-only
}

void Member::remove_curr_msg() { current_.reset(); }

void Member::shutdown() {
  if (agora_) agora_->shutdown();
}

void Member::terminate() {
  if (!agora_) {
    state_ = MemberState::TERMINATING;
    return;
  }
  agora_->terminate_member(this);
}

void Member::run(const std::atomic<bool>* stop) {
  using Clock = std::chrono::steady_clock;
  Agora* agora = agora_;  // the Member may be gone once TERMINATED is set
  auto& po = agora->post_office();
  const bool message_driven = period_ms_ == 0 && po.has_subscriptions(member_id_);
  auto running = [&] { return !stop->load() && state_.load() == MemberState::RUNNING && !orphaned_.load(); };
  // Every virtual call is bracketed by in_job_ and skipped once the Member is
  // orphaned (its destructor started): see Agora::detach_member.
  auto job = [&](auto&& f) {
    in_job_ = true;
    if (!orphaned_) f();
    in_job_ = false;
  };
  int n = 0;
  auto next = Clock::now();
  while (running()) {
    if (message_driven) {
      size_t pending = po.wait_for_mail(&mailbox_, stop, std::chrono::milliseconds(50));
      if (pending == 0 || !running()) continue;
      job([&] { do_your_job(static_cast<int>(pending)); });
    } else if (period_ms_ > 0) {
      job([&] { do_your_job(n++); });
      next += std::chrono::milliseconds(period_ms_);
      auto now = Clock::now();
      if (next < now) next = now;  // overrun: do not try to catch up
      // Sleep in short slices so shutdown() is seen within ~10 ms.
      while (running() && Clock::now() < next) {
        auto slice = std::min<Clock::duration>(next - Clock::now(), std::chrono::milliseconds(10));
        std::this_thread::sleep_for(slice);
      }
    } else {
      job([&] { do_your_job(n++); });
      std::this_thread::yield();
    }
  }
  job([&] { close(); });
  current_.reset();
  {
    std::lock_guard<std::mutex> l(agora->members_mutex_);
    state_ = MemberState::TERMINATED;
    agora->members_cv_.notify_all();
  }
}

}  // namespace mrt::dcdt
