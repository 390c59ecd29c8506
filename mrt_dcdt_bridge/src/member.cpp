#include "mrt_dcdt_bridge/member.h"

#include <chrono>

#include "mrt_dcdt_bridge/agora.h"

namespace mrt::dcdt {

Member::Member() = default;

Member::Member(Agora* agora) : agora_(agora) {}

Member::Member(Agora* agora, int period_ms) : agora_(agora), period_ms_(period_ms > 0 ? period_ms : 0) {}

Member::~Member() {
  if (thread_.joinable()) {
    // The Agora normally joins its Members; a Member destroyed first must not
    // leave a running thread behind.
    state_ = MemberState::TERMINATING;
    thread_.join();
  }
  if (agora_) agora_->RemoveMember(this);
}

void Member::SubscribeMsgType(int type, RequestType req_type) {
  if (agora_ && registered_) agora_->GetPostOffice().Subscribe(member_id_, type, req_type);
}

void Member::UnSubscribeMsgType(int type, RequestType req_type) {
  if (agora_ && registered_) agora_->GetPostOffice().Unsubscribe(member_id_, type, req_type);
}

void Member::UnSubscribeAll() {
  if (agora_ && registered_) agora_->GetPostOffice().UnsubscribeAll(member_id_);
}

Msg* Member::CreateMsg(int type, int delivery_warranty) {
  return new Msg(type, member_id_, agora_ ? agora_->GetAgoraID() : 0, delivery_warranty);
}

Msg* Member::CreateMsg(int type) { return CreateMsg(type, DCDT_DW_GUARANTEED); }

void Member::ShareMsg(Msg* msg) {
  if (!msg) return;
  std::shared_ptr<Msg> owned(msg);
  if (!agora_) return;
  auto& h = owned->mutable_header();
  h.member_id = member_id_;
  h.agora_id = agora_->GetAgoraID();
  h.hops = 0;
  h.remote = false;
  h.incarnation = agora_->Incarnation();
  h.seq = agora_->NextSeq();
  agora_->Route(std::move(owned), Source{Source::MEMBER, nullptr});
}

Msg* Member::ReceiveMsg() {
  current_.reset();
  if (!agora_ || !registered_) return nullptr;
  current_ = agora_->GetPostOffice().Pop(&mailbox_);
  // Receivers get a read-only view in spirit; the legacy API returns a
  // non-const pointer, and each message is shared, so do not modify it.
  return const_cast<Msg*>(current_.get());
}

void Member::RemoveCurrMsg() { current_.reset(); }

void Member::Shutdown() {
  if (agora_) agora_->Shutdown();
}

void Member::Terminate() {
  state_ = MemberState::TERMINATING;
  if (agora_) agora_->NotifyStateChange();
}

void Member::Run(const std::atomic<bool>* stop) {
  using Clock = std::chrono::steady_clock;
  auto& po = agora_->GetPostOffice();
  const bool message_driven = period_ms_ == 0 && po.HasSubscriptions(member_id_);
  auto running = [&] { return !stop->load() && state_.load() == MemberState::RUNNING; };
  int n = 0;
  auto next = Clock::now();
  while (running()) {
    if (message_driven) {
      size_t pending = po.WaitForMail(&mailbox_, stop, std::chrono::milliseconds(50));
      if (pending == 0) continue;
      DoYourJob(static_cast<int>(pending));
    } else if (period_ms_ > 0) {
      DoYourJob(n++);
      next += std::chrono::milliseconds(period_ms_);
      auto now = Clock::now();
      if (next < now) next = now;  // overrun: do not try to catch up
      // Sleep in short slices so Shutdown is seen within ~10 ms.
      while (running() && Clock::now() < next) {
        auto slice = std::min<Clock::duration>(next - Clock::now(), std::chrono::milliseconds(10));
        std::this_thread::sleep_for(slice);
      }
    } else {
      DoYourJob(n++);
      std::this_thread::yield();
    }
  }
  Close();
  current_.reset();
  state_ = MemberState::TERMINATED;
  agora_->NotifyStateChange();
}

}  // namespace mrt::dcdt
