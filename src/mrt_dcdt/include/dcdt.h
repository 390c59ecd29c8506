// The legacy DCDT API of the manual (chapter 3), so Agora programs written
// for the original toolkit compile unchanged: DCDT_Agora, DCDT_Member,
// DCDT_Msg with their PascalCase methods (AddMember, LetsWork, DoYourJob,
// ShareMsg, ReadAgoraID ...), DCDT_RequestType, DCDT_LOCAL_MSG /
// DCDT_REMOTE_MSG / DCDT_ALL_MSG, DCDT_TIME, the delivery warranties and the
// MRT message type numbers.
//
// This header is the ONLY place the legacy names live: every method here is a
// thin inline forwarder to the snake_case API of mrt_dcdt (doc/api.md "Naming").
// New code uses mrt::dcdt::Agora / Member / Msg directly.
#pragma once

#include <memory>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/member.h"
#include "mrt_dcdt/msg.h"
#include "mrt_dcdt/types.h"

using DCDT_RequestType = mrt::dcdt::RequestType;
using DCDT_TIME = mrt::dcdt::DCDT_TIME;
using mrt::dcdt::DCDT_ALL_MSG;
using mrt::dcdt::DCDT_LOCAL_MSG;
using mrt::dcdt::DCDT_REMOTE_MSG;
using mrt::dcdt::DCDT_DW_GUARANTEED;
using mrt::dcdt::DCDT_DW_NONE;
using mrt::dcdt::DCDT_DW_RETRANSMIT;
using mrt::dcdt::MSG_FROM_ANCHORER;
using mrt::dcdt::MSG_FROM_BRIAN;
using mrt::dcdt::MSG_FROM_JOYPAD_BRIEF;
using mrt::dcdt::MSG_FROM_MAP;
using mrt::dcdt::MSG_FROM_MONITOR;
using mrt::dcdt::MSG_FROM_MOTION;
using mrt::dcdt::MSG_FROM_REFBOX;
using mrt::dcdt::MSG_FROM_SCARE;
using mrt::dcdt::MSG_FROM_SONAR_QUALITY;
using mrt::dcdt::MSG_FROM_VISION;
using mrt::dcdt::MSG_FROM_VISION_FRONTAL;
using mrt::dcdt::MSG_FROM_VISION_OMNIDIR;
using mrt::dcdt::MSG_TO_ANCHORER;
using mrt::dcdt::MSG_TO_BRIAN;
using mrt::dcdt::MSG_TO_MOTION;

/// DCDT_Agora (manual §3.3.1): an mrt::dcdt::Agora with the legacy names.
class DCDT_Agora : public mrt::dcdt::Agora {
 public:
  DCDT_Agora() = default;  // STANDALONE
  using mrt::dcdt::Agora::Agora;  // DCDT_Agora("dcdt.cfg"): NETWORK; or from AgoraOptions

  void AddMember(mrt::dcdt::Member* m) { add_member(m); }
  void ActivateMember(mrt::dcdt::Member* m) { activate_member(m); }
  void LetsWork() { lets_work(); }
  void Shutdown() { shutdown(); }
  int GetAgoraID() const { return agora_id(); }
};

class DCDT_Member;

/// DCDT_Msg (manual §3.3.3): a handle on an mrt::dcdt::Msg. One made by
/// CreateMsg owns its message until ShareMsg (or delete); the one ReceiveMsg
/// returns views the current message and belongs to the Member. A received
/// message is shared with the other receivers and read-only: the first
/// GetPayload() / SetPayload() / AllocPayload() / SetPriority() through a
/// non-const handle gives this Member its own copy (copy on write), so legacy
/// code that writes into a received payload changes nobody else's message.
class DCDT_Msg {
 public:
  int ReadType() const { return view_->type(); }
  int ReadMemberID() const { return view_->member_id(); }
  int ReadAgoraID() const { return view_->agora_id(); }
  int ReadPriority() const { return view_->priority(); }
  int ReadDeliveryWarranty() const { return view_->delivery_warranty(); }
  DCDT_TIME ReadCreationTime() const { return view_->creation_time(); }
  int ReadPayloadLen() const { return view_->payload_len(); }
  void* GetPayload() { return writable().payload(); }
  const void* GetPayload() const { return view_->payload(); }
  void SetPayload(const void* data, int len) { writable().set_payload(data, len); }
  void* AllocPayload(int len) { return writable().alloc_payload(len); }
  void SetPriority(int p) { writable().set_priority(p); }

  /// The message itself, for code that mixes both APIs (writable: a received
  /// message is copied first).
  mrt::dcdt::Msg& msg() { return writable(); }
  const mrt::dcdt::Msg& msg() const { return *view_; }

 private:
  friend class DCDT_Member;
  explicit DCDT_Msg(mrt::dcdt::Msg* created) : view_(created), owned_(created) {}
  explicit DCDT_Msg(const mrt::dcdt::Msg* received) : view_(received) {}
  mrt::dcdt::Msg& writable() {
    if (!owned_) {
      owned_ = std::make_unique<mrt::dcdt::Msg>(*view_);
      view_ = owned_.get();
    }
    return *owned_;
  }
  const mrt::dcdt::Msg* view_;
  std::unique_ptr<mrt::dcdt::Msg> owned_;  // created, or this Member's copy of a received one
};

/// DCDT_Member (manual §3.3.2): derive from it and override Init, Close and
/// DoYourJob; the snake_case hooks of mrt::dcdt::Member call them.
class DCDT_Member : public mrt::dcdt::Member {
 public:
  /// Cyclic or message-driven Member.
  explicit DCDT_Member(DCDT_Agora* agora) : mrt::dcdt::Member(agora) {}
  /// Periodic Member: DoYourJob every period_ms milliseconds.
  DCDT_Member(DCDT_Agora* agora, int period_ms) : mrt::dcdt::Member(agora, period_ms) {}

  virtual void Init() {}
  virtual void Close() {}
  virtual void DoYourJob(int n) = 0;

  void SubscribeMsgType(int type, DCDT_RequestType req = DCDT_ALL_MSG) { subscribe_msg_type(type, req); }
  void UnSubscribeMsgType(int type, DCDT_RequestType req = DCDT_ALL_MSG) { unsubscribe_msg_type(type, req); }
  void UnSubscribeAll() { unsubscribe_all(); }

  DCDT_Msg* CreateMsg(int type, int delivery_warranty) { return new DCDT_Msg(create_msg(type, delivery_warranty)); }
  DCDT_Msg* CreateMsg(int type) { return new DCDT_Msg(create_msg(type)); }
  /// Shares a message made by CreateMsg (and deletes its handle), or a copy
  /// of the current received message. The manual's ShareMsg returns nothing;
  /// this one returns share_msg's answer (false: a guaranteed message was
  /// refused by a full mailbox or link), which legacy callers may ignore.
  bool ShareMsg(DCDT_Msg* msg) {
    if (!msg) return false;
    if (msg == current_.get()) return share_msg(new mrt::dcdt::Msg(*msg->view_));
    std::unique_ptr<DCDT_Msg> handle(msg);
    return share_msg(handle->owned_ ? handle->owned_.release() : new mrt::dcdt::Msg(*handle->view_));
  }
  DCDT_Msg* ReceiveMsg() {
    const mrt::dcdt::Msg* m = receive_msg();
    current_.reset(m ? new DCDT_Msg(m) : nullptr);
    return current_.get();
  }
  void RemoveCurrMsg() {
    current_.reset();
    remove_curr_msg();
  }

  void Shutdown() { shutdown(); }
  void Terminate() { terminate(); }
  mrt::dcdt::MemberState GetState() const { return state(); }
  int GetMemberID() const { return member_id(); }
  int GetPeriod() const { return period_ms(); }
  /// The Agora this Member was constructed with (always a DCDT_Agora).
  DCDT_Agora* GetAgora() const { return static_cast<DCDT_Agora*>(agora()); }

 protected:
  /// For legacy default constructors; the Agora is set by AddMember.
  DCDT_Member() = default;

 private:
  void init() final { Init(); }
  void close() final {
    Close();
    current_.reset();
  }
  void do_your_job(int n) final { DoYourJob(n); }

  std::unique_ptr<DCDT_Msg> current_;
};
