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
  size_t bytes = 0;      ///< PostOffice::cost of the queued messages
  std::condition_variable cv;
  uint64_t dropped = 0;  ///< non-guaranteed messages discarded because the mailbox was full
  uint64_t refused = 0;  ///< guaranteed messages refused because the mailbox was full of guaranteed ones
};

class PostOffice {
 public:
  static constexpr size_t kMailBoxCapacity = 100000;  ///< dispatcher queue (SLWDWCV), messages
  static constexpr size_t kMailBoxBytes = 64u << 20;  ///< a mailbox's cap, in cost() bytes
  static constexpr size_t kMsgOverhead = 256;         ///< bookkeeping counted per message
  static size_t cost(const Msg& m) { return static_cast<size_t>(m.payload_len()) + kMsgOverhead; }

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
  /// member id) never receives its own message. A full mailbox (kMailBoxBytes)
  /// first loses its oldest non-guaranteed messages (counted as dropped); a
  /// guaranteed message that still does not fit is never dropped silently:
  /// it is refused, counted (guaranteed_refused) and, under SLWB, post
  /// returns false (under the dispatcher policies the refusal happens after
  /// post returned: counted only).
  virtual bool post(MsgPtr msg) = 0;

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
  /// Guaranteed messages refused because a mailbox was full of guaranteed ones.
  uint64_t guaranteed_refused();

  int agora_id = 0;  ///< set by the Agora; used to recognise own messages

 protected:
  explicit PostOffice(PostOfficePolicy p) : policy_(p) {}
  /// Fans msg out into the matching mailboxes; false when a guaranteed
  /// message was refused by a full mailbox. Caller holds mutex_.
  bool dispatch_locked(const MsgPtr& msg);

  std::mutex mutex_;  // the single lock
  PostOfficePolicy policy_;

 private:
  std::map<int, MailBox*> boxes_;
  uint64_t drops_of_unregistered_ = 0, refused_of_unregistered_ = 0;
  std::map<int, std::map<int, int>> subs_;  // type -> member id -> scope mask
};

}  // namespace mrt::dcdt
