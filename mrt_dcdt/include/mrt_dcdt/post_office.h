// The PostOffice (manual §3.1): subscriptions and per-Member mailboxes.
// Three policies with the same delivery semantics (every subscriber whose
// scope matches gets every message, in the order the PostOffice accepted
// them) and different locking / buffering / dispatch strategies:
//   SLWB     Single Lock With Buffer: the publishing thread fans the message
//            out into each subscriber's FIFO buffer under the single lock.
//   SLWDWCV  Single Lock With Dispatcher With Conditional Variable: the
//            publisher appends to one central queue and signals a condition
//            variable; a dispatcher thread (the MsgManager) fans out.
//   SLWSM    Single Lock With Single Message: one message slot; a publisher
//            waits until the slot is free, the dispatcher empties it. At most
//            one message is in flight: back-pressure instead of buffering.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/msg.h"

namespace mrt::dcdt {

using MsgPtr = std::shared_ptr<const Msg>;

enum class PostOfficePolicy { SLWB, SLWDWCV, SLWSM };
const char* policy_name(PostOfficePolicy p);
/// Parses "SLWB" / "SLWDWCV" / "SLWSM"; returns false otherwise.
bool parse_policy(const std::string& s, PostOfficePolicy* out);

/// One Member's queue of received messages (guarded by the PostOffice lock).
struct MailBox {
  int member_id = 0;
  std::deque<MsgPtr> queue;
  std::condition_variable cv;
  uint64_t dropped = 0;  ///< messages discarded because the queue was full
};

class PostOffice {
 public:
  static constexpr size_t kMailBoxCapacity = 100000;

  static std::unique_ptr<PostOffice> create(PostOfficePolicy policy);
  virtual ~PostOffice();

  PostOfficePolicy policy() const { return policy_; }

  void register_mailbox(MailBox* box);
  void unregister_mailbox(MailBox* box);
  void subscribe(int member_id, int type, int scope_mask);
  void unsubscribe(int member_id, int type, int scope_mask);
  void unsubscribe_all(int member_id);
  bool has_subscriptions(int member_id);

  /// Accepts a message for delivery. The producing Member (same agora id and
  /// member id) never receives its own message.
  virtual void post(MsgPtr msg) = 0;

  /// Pops the oldest message of a mailbox (nullptr when empty).
  MsgPtr pop(MailBox* box);
  size_t pending(MailBox* box);
  /// Waits until the mailbox is non-empty, `stop` is set or the timeout
  /// expires; returns the number of queued messages.
  size_t wait_for_mail(MailBox* box, const std::atomic<bool>* stop, std::chrono::milliseconds timeout);
  /// Wakes every waiting Member (used at shutdown).
  void wake_all();
  /// Messages discarded because a mailbox was full, over every mailbox this
  /// PostOffice has held (unregistered ones included).
  uint64_t mailbox_drops();

  int agora_id = 0;  ///< set by the Agora; used to recognise own messages

 protected:
  explicit PostOffice(PostOfficePolicy p) : policy_(p) {}
  /// Fans msg out into the matching mailboxes. Caller holds mutex_.
  void dispatch_locked(const MsgPtr& msg);

  std::mutex mutex_;  // the single lock
  PostOfficePolicy policy_;

 private:
  std::map<int, MailBox*> boxes_;
  uint64_t drops_of_unregistered_ = 0;
  std::map<int, std::map<int, int>> subs_;  // type -> member id -> scope mask
};

}  // namespace mrt::dcdt
