// Channels in-process: UDP delivery warranties through a lossy relay, a
// serial (RS-232) link over a pair of pseudo-terminals, and guaranteed
// messages over a serial line that corrupts bytes.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>

#include <atomic>
#include <map>
#include <random>
#include <set>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/frame.h"
#include "mrt_dcdt/testing/process.h"
#include "null_modem.h"
#include "test_util.h"

using namespace mrt::dcdt;
using namespace dcdt_test;

namespace {

// A Member used from the test thread to share messages.
class Sender : public Member {
 public:
  explicit Sender(Agora* a) : Member(a) {}
  void do_your_job(int) override {}
  void send(int type, int warranty, int i) {
    Msg* m = create_msg(type, warranty);
    m->set_payload(std::to_string(i));
    share_msg(m);
  }
};

AgoraOptions NetOptions(const std::string& channel_line) {
  AgoraOptions o;
  o.network = true;
  o.inner_links = false;
  o.finder = false;
  o.config = parse_agora_config("127.0.0.1 239.255.0.1 9\nPostOffice: SLWB\n" + channel_line, "test.cfg");
  return o;
}

// Relays datagrams between two ports; in the a->b direction drops the first
// copy of every acknowledged message and every second unacknowledged one.
class LossyUdpRelay {
 public:
  LossyUdpRelay(int port, int pa, int pb) : pa_(pa), pb_(pb) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<uint16_t>(port));
    ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a);
    thread_ = std::thread([this] { loop(); });
  }
  ~LossyUdpRelay() {
    stop_ = true;
    thread_.join();
    ::close(fd_);
  }

 private:
  void loop() {
    std::vector<uint8_t> buf(65536);
    std::set<uint64_t> seen;
    int unacked = 0;
    while (!stop_) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 20) != 1) continue;
      sockaddr_in from{};
      socklen_t fl = sizeof from;
      ssize_t r = ::recvfrom(fd_, buf.data(), buf.size(), 0, reinterpret_cast<sockaddr*>(&from), &fl);
      if (r <= 0) continue;
      const bool from_a = ntohs(from.sin_port) == pa_;
      if (from_a) {
        Frame f;
        MsgFrame mf;
        if (decode_datagram(buf.data(), static_cast<size_t>(r), &f) && f.kind == FrameKind::MSG &&
            decode_msg_body(f.body, &mf)) {
          if (mf.link_seq != 0 ? seen.insert(mf.link_seq).second : (++unacked % 2 == 0)) continue;  // lost
        }
      }
      sockaddr_in to = from;
      to.sin_port = htons(static_cast<uint16_t>(from_a ? pb_ : pa_));
      ::sendto(fd_, buf.data(), static_cast<size_t>(r), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
    }
  }
  int fd_;
  int pa_, pb_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

TEST(Links, UdpWarrantiesNoneLosesRetransmitRecovers) {
  const int pa = free_port(), pb = free_port(), pr = free_port();
  LossyUdpRelay relay(pr, pa, pb);
  auto line = [](int l, int r) {
    return "ip link 0 127.0.0.1 " + std::to_string(l) + " 127.0.0.1 " + std::to_string(r) + "\n";
  };
  Agora a(NetOptions(line(pa, pr)));
  Agora b(NetOptions(line(pb, pr)));
  Sender s(&a);
  a.add_member(&s);
  MailBox box;
  box.member_id = 500;
  b.post_office().register_mailbox(&box);
  b.post_office().subscribe(500, 40, DCDT_ALL_MSG);
  b.post_office().subscribe(500, 41, DCDT_ALL_MSG);
  // Both UDP sockets bound and the path working: a retransmitted probe arrives.
  b.post_office().subscribe(500, 99, DCDT_ALL_MSG);
  bool probed = false;
  for (int i = 0; i < 20 && !probed; ++i) {
    s.send(99, DCDT_DW_RETRANSMIT, -1);
    probed = WaitFor([&] { return b.post_office().pending(&box) > 0; }, 300);
  }
  ASSERT_TRUE(probed);
  while (b.post_office().pop(&box)) {
  }
  b.post_office().unsubscribe(500, 99, DCDT_ALL_MSG);
  for (int i = 0; i < 20; ++i) s.send(40, DCDT_DW_NONE, i);
  for (int i = 0; i < 20; ++i) s.send(41, DCDT_DW_RETRANSMIT, i);
  std::map<int, std::set<std::string>> got;
  int total = 0;
  WaitFor([&] {
    while (auto m = b.post_office().pop(&box)) {
      got[m->type()].insert(m->payload_string());
      ++total;
    }
    return got[41].size() == 20;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // late copies would show up now
  while (auto m = b.post_office().pop(&box)) {
    got[m->type()].insert(m->payload_string());
    ++total;
  }
  EXPECT_EQ(got[40].size(), 10u);  // no warranty: every second datagram lost for good
  EXPECT_EQ(got[41].size(), 20u);  // retransmission recovers all
  EXPECT_EQ(total, 30);            // and duplicates never reach Members
  auto st = a.stats();
  ASSERT_EQ(st.channels.size(), 1u);
  EXPECT_GE(st.channels[0].resent, 20u);
  b.post_office().unregister_mailbox(&box);
}

TEST(Links, SerialLinkOverPseudoTerminals) {
  NullModem cable;
  if (!cable.ok) GTEST_SKIP() << "no pseudo-terminals available";
  Agora a(NetOptions("ser link 0 " + cable.dev1 + "\n"));
  Agora b(NetOptions("ser bridge 0 " + cable.dev2 + "\n"));
  Sender s(&a);
  a.add_member(&s);
  MailBox box;
  box.member_id = 600;
  b.post_office().register_mailbox(&box);
  b.post_office().subscribe(600, 32, DCDT_ALL_MSG);
  ASSERT_TRUE(WaitFor([&] {
    auto sa = a.stats(), sb = b.stats();
    return sa.channels[0].peer_agora == b.agora_id() && sb.channels[0].peer_agora == a.agora_id();
  }, 5000));
  for (int i = 0; i < 50; ++i) s.send(32, i % 3, i);  // every warranty
  std::vector<std::string> got;
  WaitFor([&] {
    while (auto m = b.post_office().pop(&box)) {
      got.push_back(m->payload_string());
      EXPECT_FALSE(m->header().remote);  // arrived by a bridge channel: LOCAL
    }
    return got.size() == 50;
  });
  ASSERT_EQ(got.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(got[i], std::to_string(i));
  b.post_office().unregister_mailbox(&box);
}

TEST(Links, GuaranteedOverACorruptingSerialLineArriveOnceInOrder) {
  // ~1 byte in 1500 flipped both ways: with 70-byte frames about one MSG in
  // 20 and some HELLO/ACK/NACK frames are hit (CRC errors, lengths too).
  NullModem cable(1500);
  if (!cable.ok) GTEST_SKIP() << "no pseudo-terminals available";
  AgoraOptions oa = NetOptions("ser link 0 " + cable.dev1 + "\n"), ob = NetOptions("ser link 0 " + cable.dev2 + "\n");
  oa.channel.stream_resend_ms = ob.channel.stream_resend_ms = 100;
  Agora a(oa);
  Agora b(ob);
  Sender s(&a);
  a.add_member(&s);
  MailBox box;
  box.member_id = 700;
  b.post_office().register_mailbox(&box);
  b.post_office().subscribe(700, 32, DCDT_ALL_MSG);
  const int kCount = 400;
  for (int i = 0; i < kCount; ++i) {
    s.send(32, DCDT_DW_GUARANTEED, i);
    if (i % 50 == 49) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::vector<std::string> got;
  auto drain = [&] {
    while (auto m = b.post_office().pop(&box)) got.push_back(m->payload_string());
  };
  WaitFor([&] {
    drain();
    return got.size() >= static_cast<size_t>(kCount);
  }, 30000);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // late copies would show up now
  drain();
  ASSERT_EQ(got.size(), static_cast<size_t>(kCount)) << "flipped " << cable.flipped;
  for (int i = 0; i < kCount; ++i) ASSERT_EQ(got[i], std::to_string(i)) << "at " << i;
  // The line really was noisy and the link really recovered.
  const auto sa = a.stats().channels.at(0), sb = b.stats().channels.at(0);
  RecordProperty("bytes_flipped", static_cast<int>(cable.flipped));
  RecordProperty("receiver_errors", static_cast<int>(sb.errors));
  RecordProperty("receiver_gaps", static_cast<int>(sb.gaps));
  RecordProperty("sender_resent", static_cast<int>(sa.resent));
  EXPECT_GT(cable.flipped.load(), 10u);
  EXPECT_GT(sb.errors, 0u);  // CRC / header errors seen by the receiver
  EXPECT_GT(sa.resent, 0u);
  EXPECT_TRUE(WaitFor([&] { return a.stats().channels.at(0).pending == 0; }, 5000));  // all acknowledged
  b.post_office().unregister_mailbox(&box);
}

}  // namespace
