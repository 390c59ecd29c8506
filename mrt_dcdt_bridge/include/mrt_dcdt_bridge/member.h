// DCDT_Member (manual §3.3.2): a thread of an Agora. Periodic (constructed
// with a period in ms), cyclic (no period, no subscriptions after Init) or
// message-driven (no period, subscribed to some type in Init()).
#pragma once

#include <atomic>
#include <memory>
#include <thread>

#include "mrt_dcdt_bridge/msg.h"
#include "mrt_dcdt_bridge/post_office.h"
#include "mrt_dcdt_bridge/types.h"

namespace mrt::dcdt {

class Agora;

enum class MemberState { CREATED, ADDED, ACTIVE, RUNNING, TERMINATING, TERMINATED };

class Member {
 public:
  /// Cyclic or message-driven Member.
  explicit Member(Agora* agora);
  /// Periodic Member: DoYourJob every period_ms milliseconds.
  Member(Agora* agora, int period_ms);
  virtual ~Member();
  Member(const Member&) = delete;
  Member& operator=(const Member&) = delete;

  /// Called once, in the Agora's thread, before any Member runs.
  virtual void Init() {}
  /// Called once, in the Member's thread, after its last DoYourJob.
  virtual void Close() {}
  /// The job. Periodic and cyclic Members: n is the activation number
  /// (0, 1, 2 ...). Message-driven Members: n is the number of messages
  /// waiting in the mailbox.
  virtual void DoYourJob(int n) = 0;

  // --- subscriptions (manual §3.3.2) ---
  void SubscribeMsgType(int type, RequestType req_type = DCDT_ALL_MSG);
  void UnSubscribeMsgType(int type, RequestType req_type = DCDT_ALL_MSG);
  void UnSubscribeAll();

  // --- messages ---
  /// A new message owned by the caller until ShareMsg (or delete).
  Msg* CreateMsg(int type, int delivery_warranty);
  Msg* CreateMsg(int type);
  /// Hands msg to the PostOffice (and the Agora's links); takes ownership.
  void ShareMsg(Msg* msg);
  /// Makes the oldest waiting message the current one and returns it
  /// (nullptr when none). The previous current message is released.
  Msg* ReceiveMsg();
  /// Releases the current message (destroyed when no other Member holds it).
  void RemoveCurrMsg();

  // --- life cycle ---
  /// Asks the whole Agora to stop (LetsWork returns).
  void Shutdown();
  /// This Member stops after the current DoYourJob (state TERMINATING).
  void Terminate();
  MemberState GetState() const { return state_.load(); }
  int GetMemberID() const { return member_id_; }
  int GetPeriod() const { return period_ms_; }
  Agora* GetAgora() const { return agora_; }

 protected:
  /// For legacy default constructors; the Agora is set by AddMember.
  Member();

 private:
  friend class Agora;
  void Run(const std::atomic<bool>* stop);

  Agora* agora_ = nullptr;
  int period_ms_ = 0;
  int member_id_ = 0;
  std::atomic<MemberState> state_{MemberState::CREATED};
  MailBox mailbox_;
  MsgPtr current_;
  std::thread thread_;
  bool registered_ = false;
};

}  // namespace mrt::dcdt
