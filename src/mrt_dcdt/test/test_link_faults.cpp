// Link faults of issue 19, in-process on loopback: a link's out-queue capped
// in bytes (a guaranteed message refused and reported, never dropped), a
// Finder link cut and restored under load, a serial line unplugged and its
// far end closed and reopened, and a peer Agora destroyed and re-created
// (on a Finder link with the same id, on static ip and serial links). Every guaranteed message must arrive once and in order
// (across a restart: none lost). Every wait is bounded.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/agora.h"
#include "null_modem.h"
#include "tcp_proxy.h"
#include "test_util.h"

using namespace mrt::dcdt;
using namespace dcdt_test;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kType = 33;

// A Member used from the test thread to share messages; the payload starts
// with the message's number.
class Sender : public Member {
 public:
  explicit Sender(Agora* a) : Member(a) {}
  void do_your_job(int) override {}
  bool send(int warranty, int i, const std::string& pad = "") {
    Msg* m = create_msg(kType, warranty);
    m->set_payload(std::to_string(i) + pad);
    return share_msg(m);
  }
};

// A mailbox of the test in an Agora's PostOffice, subscribed to kType.
class Collector {
 public:
  explicit Collector(Agora& a) : a_(&a) {
    box_.member_id = 900;
    a_->post_office().register_mailbox(&box_);
    a_->post_office().subscribe(900, kType, DCDT_ALL_MSG);
  }
  ~Collector() {
    if (a_) a_->post_office().unregister_mailbox(&box_);
  }
  void drain() {
    if (!a_) return;
    while (auto m = a_->post_office().pop(&box_)) got.push_back(std::stoi(m->payload_string()));
  }
  /// After the Agora was destroyed: what reached the mailbox until then.
  void agora_destroyed() {
    a_ = nullptr;
    for (auto& m : box_.queue) got.push_back(std::stoi(m->payload_string()));
    box_.queue.clear();
  }
  /// Drains until n numbers arrived (at most timeout_ms), then 300 ms more:
  /// late copies would show up then.
  void wait_for(size_t n, int timeout_ms) {
    WaitFor([&] {
      drain();
      return got.size() >= n;
    }, timeout_ms);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    drain();
  }
  std::vector<int> got;

 private:
  Agora* a_;
  MailBox box_;
};

std::vector<int> Range(int from, int to) {  // from, from + 1, ..., to - 1
  std::vector<int> v;
  for (int i = from; i < to; ++i) v.push_back(i);
  return v;
}

AgoraOptions NetOptions(const std::string& channel_lines) {
  AgoraOptions o;
  o.network = true;
  o.inner_links = false;
  o.finder = false;
  o.config = parse_agora_config("127.0.0.1 239.255.0.1 9\nPostOffice: SLWB\n" + channel_lines, "test.cfg");
  return o;
}

std::string IpLine(int local, int remote) {
  return "ip link 0 127.0.0.1 " + std::to_string(local) + " 127.0.0.1 " + std::to_string(remote) + "\n";
}

// Two Agoras that find each other by multicast on loopback (no inner links,
// so the Finder joins them); this program's own group and port.
AgoraOptions FinderOptions(int mcast_port, int id) {
  AgoraOptions o;
  o.network = true;
  o.inner_links = false;
  o.agora_id = id;
  o.finder_period_ms = 100;
  o.config = parse_agora_config("127.0.0.1 239.255." + std::to_string(::getpid() % 250 + 1) + ".9 " +
                                    std::to_string(mcast_port) + "\nPostOffice: SLWB\n",
                                "finder.cfg");
  return o;
}

bool ConnectedTo(Agora& a, int peer) {
  for (const auto& c : a.stats().channels)
    if (c.connected && c.peer_agora == peer) return true;
  return false;
}

// Sends 1 guaranteed message per iteration, pausing 2 ms every 10: a steady
// load of a few thousand messages a second.
void Pace(int i) {
  if (i % 10 == 9) std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

TEST(LinkQueues, CappedInBytesAGuaranteedMessageIsRefusedNeverDropped) {
  // A's ip link leads to B, which is not started yet: everything waits in
  // A's out-queue, capped at 1 MiB = 1 048 576 bytes.
  const int pa = free_port(), pb = free_port();
  AgoraOptions oa = NetOptions(IpLine(pa, pb));
  oa.channel.max_queue_bytes = 1u << 20;
  Agora a(oa);
  Sender s(&a);
  a.add_member(&s);
  const std::string pad(100000 - 8, 'x');  // payload 100 000 bytes (with the number): cost 100 256
  auto send = [&](int warranty, int i) {
    std::string n = std::to_string(i);
    return s.send(warranty, i, pad + std::string(8 - n.size(), 'x'));
  };
  // 3 without warranty (too big for a datagram: they wait on the stream too).
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(send(DCDT_DW_NONE, 1000 + i));
  // 10 guaranteed fit: 10 x 100 256 = 1 002 560 <= 1 048 576. From the 8th on
  // (7 G + 3 N + 1 G = 1 102 816 > cap) the oldest without warranty make room.
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(send(DCDT_DW_GUARANTEED, i)) << i;
  // 11 x 100 256 = 1 102 816 > cap with nothing left to evict: refused, and
  // the sender is told (share_msg returns false).
  for (int i = 10; i < 15; ++i) EXPECT_FALSE(send(DCDT_DW_GUARANTEED, i)) << i;
  // One more without warranty: dropped (nothing promised), share_msg true.
  EXPECT_TRUE(send(DCDT_DW_NONE, 1003));
  auto st = a.stats();
  ASSERT_EQ(st.channels.size(), 1u);
  EXPECT_EQ(st.channels[0].refused, 5u);
  EXPECT_EQ(st.channels[0].dropped, 4u);  // the 3 evicted + the last one
  EXPECT_EQ(st.channels[0].pending, 10u);
  EXPECT_EQ(st.channel_refused, 5u);
  // B comes up: exactly the 10 accepted guaranteed messages arrive, in order.
  Agora b(NetOptions(IpLine(pb, pa)));
  Collector c(b);
  c.wait_for(10, 10000);
  EXPECT_EQ(c.got, Range(0, 10));
  EXPECT_TRUE(WaitFor([&] { return a.stats().channels.at(0).pending == 0; }, 5000));  // all acknowledged
}

TEST(FinderLinks, CutAndRestoredUnderLoadEveryGuaranteedMessageArrivesOnceInOrder) {
  // B (the larger id: it accepts) listens on pb and announces pproxy; the
  // proxy forwards pproxy -> pb, so killing it cuts the Finder's TCP link.
  const int mport = free_port(), pb = free_port(), pproxy = free_port();
  const int id_a = 3000000 + (::getpid() % 100000) * 2;
  TcpProxy proxy(pproxy, pb);
  AgoraOptions ob = FinderOptions(mport, id_a + 1);
  ob.finder_tcp_port = pb;
  ob.finder_announce_port = pproxy;
  Agora a(FinderOptions(mport, id_a));
  Agora b(ob);
  Sender s(&a);
  a.add_member(&s);
  Collector c(b);
  ASSERT_TRUE(WaitFor([&] { return ConnectedTo(a, id_a + 1) && ConnectedTo(b, id_a); }, 8000));
  const int kCount = 3000;
  auto cut_at = Clock::now();
  for (int i = 0; i < kCount; ++i) {
    if (i == 800 || i == 2000) {
      proxy.kill();  // both connections closed, the port refuses connections
      cut_at = Clock::now();
    }
    if (i == 1300 || i == 2500) {
      std::this_thread::sleep_until(cut_at + std::chrono::milliseconds(300));  // down at least 300 ms
      proxy.Restart();
    }
    EXPECT_TRUE(s.send(DCDT_DW_GUARANTEED, i)) << i;
    Pace(i);
  }
  c.wait_for(kCount, 15000);
  ASSERT_EQ(c.got.size(), static_cast<size_t>(kCount)) << "proxy sessions " << proxy.sessions;
  EXPECT_EQ(c.got, Range(0, kCount));  // once each, in order
  EXPECT_GE(proxy.sessions.load(), 3);  // connected, cut, reconnected, cut, reconnected
  const auto st = a.stats();
  ASSERT_EQ(st.channels.size(), 1u);  // one channel per peer, kept across the cuts
  EXPECT_GE(st.channels[0].reconnects, 3u);
  EXPECT_TRUE(WaitFor([&] { return a.stats().channels.at(0).pending == 0; }, 5000));
}

// `a` sends 1500 guaranteed messages under a steady load to the peer that
// make_b makes; after message 900 the peer is destroyed (its channels,
// sockets, PostOffice), 200 ms later, after message 1100, it is made again
// (a new incarnation: the same id or not, see the callers). `step(i)` runs
// before message i (other faults). Checks: B's first run got 0, 1, ...
// once each, in order; the second run gets first ... 1499 once each, in
// order, and `first` is at most one past what the first run had: nothing
// in between was lost. A message the first run received but had not yet
// acknowledged when it was destroyed is sent to the second run again
// (recorded as received_again). Returns what B's first run received.
// settle: before B's first run ends (message 900), wait up to 10 s until it
// has got that many (a starved machine, e.g. the sanitizer stage at nice 19
// beside the RoboCup rostests, had resent only 411 of the 600 by then).
std::vector<int> RestartPeerUnderLoad(Agora& a, const std::function<std::unique_ptr<Agora>()>& make_b,
                                      const std::function<void(int)>& step = nullptr, size_t settle = 0) {
  Sender s(&a);
  a.add_member(&s);
  auto b = make_b();
  auto c = std::make_unique<Collector>(*b);
  EXPECT_TRUE(WaitFor([&] { return ConnectedTo(a, b->agora_id()) && ConnectedTo(*b, a.agora_id()); }, 8000));
  std::vector<int> before;
  const int kCount = 1500;
  for (int i = 0; i < kCount; ++i) {
    if (step) step(i);
    if (i == 900) {
      if (settle > 0) c->wait_for(settle, 10000);
      c->drain();
      b.reset();
      c->agora_destroyed();
      before = c->got;
    }
    if (i == 1100) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      // Subscribed before anything can arrive (that needs at least a
      // connection and a HELLO round trip).
      b = make_b();
      c = std::make_unique<Collector>(*b);
    }
    EXPECT_TRUE(s.send(DCDT_DW_GUARANTEED, i)) << i;
    Pace(i);
  }
  c->wait_for(1, 10000);
  EXPECT_FALSE(c->got.empty());
  if (c->got.empty()) return before;
  const int first = c->got.front();
  c->wait_for(static_cast<size_t>(kCount - first), 15000);
  EXPECT_EQ(before, Range(0, static_cast<int>(before.size())));
  EXPECT_LE(first, static_cast<int>(before.size()));
  EXPECT_EQ(c->got, Range(first, kCount));
  ::testing::Test::RecordProperty("first_run_received", static_cast<int>(before.size()));
  ::testing::Test::RecordProperty("received_again", static_cast<int>(before.size()) - first);
  return before;
}

TEST(FinderLinks, PeerAgoraDestroyedAndRecreatedWithTheSameIdLosesNothing) {
  const int mport = free_port();
  const int id_a = 3000000 + (::getpid() % 100000) * 2;
  Agora a(FinderOptions(mport, id_a));
  // Same id, new incarnation, new Finder port (announced by its beacons).
  RestartPeerUnderLoad(a, [&] { return std::make_unique<Agora>(FinderOptions(mport, id_a + 1)); });
  ASSERT_EQ(a.stats().channels.size(), 1u);  // one channel per peer id, kept across the restart
}

TEST(IpLinks, PeerAgoraDestroyedAndRecreatedLosesNothing) {
  const int pa = free_port(), pb = free_port();
  Agora a(NetOptions(IpLine(pa, pb)));
  // The same static channel, a new random agora id each time.
  RestartPeerUnderLoad(a, [&] { return std::make_unique<Agora>(NetOptions(IpLine(pb, pa))); });
}

TEST(SerialLinks, LineUnpluggedThenFarEndClosedAndReopenedUnderLoadLosesNothing) {
  NullModem cable;
  if (!cable.ok) GTEST_SKIP() << "no pseudo-terminals available";
  AgoraOptions oa = NetOptions("ser link 0 " + cable.dev1 + "\n"), ob = NetOptions("ser link 0 " + cable.dev2 + "\n");
  oa.channel.stream_resend_ms = ob.channel.stream_resend_ms = 100;
  Agora a(oa);
  // The cable is unplugged before message 300 (every byte lost, both ways)
  // and plugged back at 600, at least 300 ms later; the far Agora then
  // closes its end of the line and reopens the same device (the pty stays:
  // the cable holds it), with a new id.
  auto cut_at = Clock::now();
  const auto before = RestartPeerUnderLoad(a, [&] { return std::make_unique<Agora>(ob); }, [&](int i) {
    if (i == 300) {
      cable.cut(true);
      cut_at = Clock::now();
    }
    if (i == 600) {
      std::this_thread::sleep_until(cut_at + std::chrono::milliseconds(300));
      cable.cut(false);
    }
  }, 600);
  // Across the unplugged line B's first run got 0, 1, ... once each, in
  // order: at least the 600 sent before the line came back.
  EXPECT_GE(before.size(), 600u);
  EXPECT_GT(a.stats().channels.at(0).resent, 0u);  // the cut really lost frames
}

}  // namespace
