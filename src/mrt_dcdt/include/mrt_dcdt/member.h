// Member (the manual's DCDT_Member, §3.3.2; its legacy names are in dcdt.h):
// a thread of an Agora. Periodic (constructed with a period in ms), cyclic
// (no period, no subscriptions after init()) or message-driven (no period,
// subscribed to some type in init()).
#pragma once

#include <atomic>
#include <memory>
#include <thread>

#include "mrt_dcdt/msg.h"
#include "mrt_dcdt/post_office.h"
#include "mrt_dcdt/types.h"

namespace mrt::dcdt {

class Agora;

enum class MemberState { CREATED, ADDED, ACTIVE, RUNNING, TERMINATING, TERMINATED };

class Member {
 public:
  /// Cyclic or message-driven Member.
  explicit Member(Agora* agora);
  /// Periodic Member: do_your_job every period_ms milliseconds.
  Member(Agora* agora, int period_ms);
  virtual ~Member();
  Member(const Member&) = delete;
  Member& operator=(const Member&) = delete;

  /// Called once, in the Agora's thread, before any Member runs.
  virtual void init() {}
  /// Called once, in the Member's thread, after its last do_your_job.
  virtual void close() {}
  /// The job. Periodic and cyclic Members: n is the activation number
  /// (0, 1, 2 ...). Message-driven Members: n is the number of messages
  /// waiting in the mailbox.
  virtual void do_your_job(int n) = 0;

  // --- subscriptions (manual §3.3.2) ---
  void subscribe_msg_type(int type, RequestType req_type = DCDT_ALL_MSG);
  void unsubscribe_msg_type(int type, RequestType req_type = DCDT_ALL_MSG);
  void unsubscribe_all();

  // --- messages ---
  /// A new message owned by the caller until share_msg (or delete).
  Msg* create_msg(int type, int delivery_warranty);
  Msg* create_msg(int type);
  /// Hands msg to the PostOffice (and the Agora's links); takes ownership.
  /// False when a guaranteed message was refused by a full mailbox of this
  /// Agora (SLWB; README "PostOffice policies") or by a full link out-queue
  /// (doc/faults.md "Guarantees under faults"); it went to every other destination.
  bool share_msg(Msg* msg);
  /// Makes the oldest waiting message the current one and returns it
  /// (nullptr when none). The previous current message is released. The
  /// message is shared with the other receivers, so it is read-only.
  const Msg* receive_msg();
  /// Releases the current message (destroyed when no other Member holds it).
  void remove_curr_msg();

  // --- life cycle ---
  /// Asks the whole Agora to stop (lets_work returns).
  void shutdown();
  /// This Member stops after the current do_your_job (state TERMINATING).
  /// Called from another thread, returns once the Member has finished
  /// (close() run, state TERMINATED), so the caller may destroy it.
  void terminate();
  MemberState state() const { return state_.load(); }
  int member_id() const { return member_id_; }
  int period_ms() const { return period_ms_; }
  Agora* agora() const { return agora_; }

 protected:
  /// For legacy default constructors; the Agora is set by add_member.
  Member();

 private:
  friend class Agora;
  void run(const std::atomic<bool>* stop);

  Agora* agora_ = nullptr;
  int period_ms_ = 0;
  int member_id_ = 0;
  std::atomic<MemberState> state_{MemberState::CREATED};
  MailBox mailbox_;
  MsgPtr current_;
  std::thread thread_;                       // moved out by its one joiner (Agora::join_members)
  std::atomic<std::thread::id> thread_id_{};  // set when the thread is created
  bool joining_ = false;                      // an Agora joins the thread (guarded by its lock)
  std::atomic<bool> orphaned_{false};         // destructor started: no virtual call any more
  std::atomic<bool> in_job_{false};           // inside do_your_job / close
  bool registered_ = false;
};

}  // namespace mrt::dcdt
