// Integration tests with separate dcdt_agora processes on loopback: inner
// links, link vs bridge between two communities, a cycle that must not loop,
// a guaranteed TCP link killed and restarted mid-stream, Finder discovery on
// loopback and across two network namespaces joined by a veth pair.
#include <gtest/gtest.h>

#include <poll.h>

#include <atomic>
#include <set>

#include "mrt_dcdt/testing/process.h"
#include "tcp_proxy.h"
#include "test_util.h"

using namespace dcdt_test;

namespace {

const std::string kAgora = DCDT_AGORA;

std::unique_ptr<Process> Agora(std::vector<std::string> args) {
  args.insert(args.begin(), kAgora);
  return std::make_unique<Process>(args);
}

bool WaitReady(const std::string& out, int timeout_ms = 5000) {
  return WaitFor([&] { return slurp(out).find("ready agora=") != std::string::npos; }, timeout_ms);
}

std::string AgoraIdOf(const std::string& out) {
  auto l = lines(out, "ready agora=");
  return l.empty() ? "" : l[0].substr(12);
}

std::string Group() { return "239.255." + std::to_string(::getpid() % 250 + 1) + ".7"; }

std::string NetLine(int port) { return "127.0.0.1 " + Group() + " " + std::to_string(port) + "\nPostOffice: SLWB\n"; }

std::string IpLine(const char* mode, int level, int local, int remote) {
  return std::string("ip ") + mode + " " + std::to_string(level) + " 127.0.0.1 " + std::to_string(local) +
         " 127.0.0.1 " + std::to_string(remote) + "\n";
}

TEST(Integration, ThreeAgorasOnOneMachineThroughInnerLinks) {
  const std::string d = TempDir("three");
  auto b = Agora({"--inner-dir", d, "--subscribe", "MSG_FROM_VISION:local", "--expect", "10", "--duration", "15",
                  "--out", d + "/b.txt"});
  auto c = Agora({"--inner-dir", d, "--subscribe", "MSG_FROM_VISION", "--expect", "10", "--duration", "15", "--out",
                  d + "/c.txt"});
  ASSERT_TRUE(WaitReady(d + "/b.txt"));
  ASSERT_TRUE(WaitReady(d + "/c.txt"));
  auto a = Agora({"--inner-dir", d, "--publish", "MSG_FROM_VISION", "--count", "10", "--rate", "200", "--wait-peers",
                  "2", "--duration", "15", "--out", d + "/a.txt"});
  EXPECT_EQ(a->wait(15000), 0);
  EXPECT_EQ(b->wait(15000), 0);
  EXPECT_EQ(c->wait(15000), 0);
  const std::string id = AgoraIdOf(d + "/a.txt");
  for (const char* f : {"/b.txt", "/c.txt"}) {
    auto recv = lines(d + f, "recv ");
    ASSERT_EQ(recv.size(), 10u) << slurp(d + f);
    for (size_t i = 0; i < recv.size(); ++i) {
      EXPECT_EQ(field(recv[i], "agora"), id);
      EXPECT_EQ(field(recv[i], "seq"), std::to_string(i + 1));
      EXPECT_EQ(field(recv[i], "scope"), "local");
      EXPECT_EQ(field(recv[i], "payload"), "message " + std::to_string(i));
    }
  }
}

// Community 1 = {A1 (network), B1}, community 2 = {A2 (network), B2}; A1 and
// A2 are joined by one ip channel. B1 publishes type 22, A1 type 21; B2
// listens to both.
void RunTwoCommunities(const char* mode, size_t expect21, size_t expect22, const char* scope21) {
  const std::string d1 = TempDir("c1"), d2 = TempDir("c2");
  int p1 = free_port(), p2 = free_port();
  if (p1 > p2) std::swap(p1, p2);
  write_file(d1 + "/a1.cfg", NetLine(free_port()) + IpLine(mode, 0, p1, p2));
  write_file(d2 + "/a2.cfg", NetLine(free_port()) + IpLine(mode, 0, p2, p1));
  // B2 stops 700 ms after the expected messages: anything else would show up.
  auto b2 = Agora({"--inner-dir", d2, "--subscribe", "21", "--subscribe", "22", "--expect",
                   std::to_string(expect21 + expect22), "--linger", "700", "--duration", "20", "--out",
                   d2 + "/b2.txt"});
  ASSERT_TRUE(WaitReady(d2 + "/b2.txt"));
  auto a2 = Agora({"--config", d2 + "/a2.cfg", "--inner-dir", d2, "--no-finder", "--subscribe", "99", "--duration",
                   "30", "--out", d2 + "/a2.txt"});
  ASSERT_TRUE(WaitReady(d2 + "/a2.txt"));
  auto a1 = Agora({"--config", d1 + "/a1.cfg", "--inner-dir", d1, "--no-finder", "--publish", "21", "--count", "10",
                   "--rate", "100", "--wait-peers", "2", "--subscribe", "99", "--duration", "30", "--out",
                   d1 + "/a1.txt"});
  ASSERT_TRUE(WaitReady(d1 + "/a1.txt"));
  auto b1 = Agora({"--inner-dir", d1, "--publish", "22", "--count", "10", "--rate", "100", "--wait-peers", "1",
                   "--duration", "20", "--out", d1 + "/b1.txt"});
  EXPECT_EQ(b1->wait(20000), 0);
  EXPECT_EQ(b2->wait(20000), 0) << slurp(d2 + "/b2.txt");
  a1->kill();
  a2->kill();
  size_t n21 = 0, n22 = 0;
  for (const auto& l : lines(d2 + "/b2.txt", "recv ")) {
    if (field(l, "type") == "21") {
      ++n21;
      EXPECT_EQ(field(l, "scope"), scope21) << l;
      EXPECT_EQ(field(l, "hops"), "1") << l;
    } else {
      ++n22;
    }
  }
  EXPECT_EQ(n21, expect21) << slurp(d2 + "/b2.txt") << slurp(d1 + "/a1.txt");
  EXPECT_EQ(n22, expect22) << slurp(d2 + "/b2.txt") << slurp(d1 + "/a1.txt");
}

TEST(Integration, TcpLinkForwardsOnlyMessagesOfTheLinkedAgora) {
  // link: only A1's own messages cross; B2 sees them as REMOTE.
  RunTwoCommunities("link", 10, 0, "remote");
}

TEST(Integration, BridgeForwardsTheWholeCommunity) {
  // bridge: B1's messages cross too; B2 sees them as LOCAL.
  RunTwoCommunities("bridge", 10, 10, "local");
}

TEST(Integration, BridgesInACycleDoNotLoop) {
  const std::string d = TempDir("cycle");
  const int ab = free_port(), ba = free_port(), ac = free_port(), ca = free_port(), bc = free_port(), cb = free_port();
  const char* br = "bridge";
  write_file(d + "/a.cfg", NetLine(free_port()) + IpLine(br, 15, ab, ba) + IpLine(br, 15, ac, ca));
  write_file(d + "/b.cfg", NetLine(free_port()) + IpLine(br, 15, ba, ab) + IpLine(br, 15, bc, cb));
  write_file(d + "/c.cfg", NetLine(free_port()) + IpLine(br, 15, ca, ac) + IpLine(br, 15, cb, bc));
  std::vector<std::unique_ptr<Process>> ps;
  // Each Agora stops 700 ms after its 20 messages: copies would show up.
  for (const char* n : {"b", "c"})
    ps.push_back(Agora({"--config", d + "/" + n + ".cfg", "--no-inner", "--no-finder", "--subscribe", "18",
                        "--expect", "20", "--linger", "700", "--duration", "20", "--out", d + "/" + n + ".txt"}));
  ASSERT_TRUE(WaitReady(d + "/b.txt"));
  ASSERT_TRUE(WaitReady(d + "/c.txt"));
  auto a = Agora({"--config", d + "/a.cfg", "--no-inner", "--no-finder", "--subscribe", "18", "--publish", "18",
                  "--count", "20", "--rate", "200", "--wait-peers", "2", "--expect", "20", "--linger", "700",
                  "--duration", "20", "--out", d + "/a.txt"});
  EXPECT_EQ(a->wait(25000), 0);
  for (auto& p : ps) EXPECT_EQ(p->wait(25000), 0);
  // A's subscriber gets A's messages once, from its own PostOffice (hops 0),
  // never again after a trip round the triangle.
  auto own = lines(d + "/a.txt", "recv ");
  EXPECT_EQ(own.size(), 20u) << slurp(d + "/a.txt");
  for (auto& l : own) EXPECT_EQ(field(l, "hops"), "0") << l;
  uint64_t dups = 0;
  for (const char* n : {"/b.txt", "/c.txt"}) {
    auto recv = lines(d + n, "recv ");
    std::set<std::string> seqs;
    for (auto& l : recv) seqs.insert(field(l, "seq"));
    EXPECT_EQ(recv.size(), 20u) << slurp(d + n);
    EXPECT_EQ(seqs.size(), 20u);
    auto st = lines(d + n, "stats ");
    if (!st.empty()) dups += std::stoull(field(st[0], "duplicates"));
  }
  // Each copy that came round the triangle was recognised and dropped.
  EXPECT_GT(dups, 0u);
}

TEST(Integration, GuaranteedTcpLinkKilledAndRestartedLosesNothing) {
  const std::string d = TempDir("kill");
  std::vector<int> p = {free_port(), free_port(), free_port()};
  std::sort(p.begin(), p.end());
  const int pa = p[0], pproxy = p[1], pb = p[2];  // A dials (pa < pproxy), B accepts (pb > pa)
  write_file(d + "/a.cfg", NetLine(free_port()) + IpLine("link", 0, pa, pproxy));
  write_file(d + "/b.cfg", NetLine(free_port()) + IpLine("link", 0, pb, pa));
  TcpProxy proxy(pproxy, pb);
  const int kCount = 3000;
  auto b = Agora({"--config", d + "/b.cfg", "--no-inner", "--no-finder", "--subscribe", "21", "--expect",
                  std::to_string(kCount), "--duration", "20", "--out", d + "/b.txt"});
  ASSERT_TRUE(WaitReady(d + "/b.txt"));
  auto a = Agora({"--config", d + "/a.cfg", "--no-inner", "--no-finder", "--publish", "21", "--warranty",
                  "guaranteed", "--count", std::to_string(kCount), "--rate", "1000", "--wait-peers", "1",
                  "--duration", "20", "--out", d + "/a.txt"});
  // Kill the link mid-stream, keep it down a while, restart it.
  ASSERT_TRUE(WaitFor([&] { return lines(d + "/b.txt", "recv ").size() >= 300; }, 10000));
  proxy.kill();
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const size_t during = lines(d + "/b.txt", "recv ").size();
  proxy.Restart();
  EXPECT_EQ(b->wait(20000), 0) << slurp(d + "/b.txt").substr(0, 2000);
  a->wait(20000);
  auto recv = lines(d + "/b.txt", "recv ");
  ASSERT_EQ(recv.size(), static_cast<size_t>(kCount)) << slurp(d + "/a.txt") << "proxy sessions " << proxy.sessions << " accepts " << proxy.accepts;
  for (int i = 0; i < kCount; ++i) ASSERT_EQ(field(recv[i], "seq"), std::to_string(i + 1));
  EXPECT_LT(during, static_cast<size_t>(kCount)) << "the kill happened after the stream ended";
  EXPECT_GE(proxy.sessions.load(), 2);
}

// A publisher with a fixed agora id on a static ip link is killed and
// started again with the same id: its second run's link and origin sequence
// numbers restart at 1, and the subscriber must still get every message
// (neither taken for a resend of the first run nor for a duplicate).
TEST(Integration, RestartedAgoraWithFixedIdLosesNothing) {
  const std::string d = TempDir("reinc");
  int pa = free_port(), pb = free_port();
  write_file(d + "/a.cfg", NetLine(free_port()) + IpLine("link", 0, pa, pb));
  write_file(d + "/b.cfg", NetLine(free_port()) + IpLine("link", 0, pb, pa));
  const int kCount = 40;
  const std::string id = std::to_string(2000000 + ::getpid() % 100000);
  auto b = Agora({"--config", d + "/b.cfg", "--no-inner", "--no-finder", "--subscribe", "21", "--expect",
                  std::to_string(2 * kCount), "--duration", "30", "--out", d + "/b.txt"});
  ASSERT_TRUE(WaitReady(d + "/b.txt"));
  for (int run = 0; run < 2; ++run) {
    const std::string out = d + "/a" + std::to_string(run) + ".txt";
    auto a = Agora({"--config", d + "/a.cfg", "--no-inner", "--no-finder", "--id", id, "--publish", "21",
                    "--warranty", "guaranteed", "--count", std::to_string(kCount), "--rate", "200", "--wait-peers",
                    "1", "--duration", "30", "--out", out});
    const size_t want = static_cast<size_t>((run + 1) * kCount);
    EXPECT_TRUE(WaitFor([&] { return lines(d + "/b.txt", "recv ").size() >= want; }, 15000))
        << "run " << run << ": " << slurp(d + "/b.txt") << slurp(out);
    a->kill();  // SIGKILL: no goodbye of any kind
  }
  EXPECT_EQ(b->wait(10000), 0);
  auto recv = lines(d + "/b.txt", "recv ");
  ASSERT_EQ(recv.size(), static_cast<size_t>(2 * kCount)) << slurp(d + "/b.txt");
  for (int run = 0; run < 2; ++run) {
    for (int i = 0; i < kCount; ++i) {
      const auto& l = recv[static_cast<size_t>(run * kCount + i)];
      EXPECT_EQ(field(l, "agora"), id) << l;
      EXPECT_EQ(field(l, "seq"), std::to_string(i + 1)) << l;  // the second run counts from 1 again
      EXPECT_EQ(field(l, "payload"), "message " + std::to_string(i)) << l;
    }
  }
}

TEST(Integration, FinderDiscoversAgorasByMulticastOnLoopback) {
  const std::string da = TempDir("fa"), db = TempDir("fb");
  const int port = free_port();
  write_file(da + "/f.cfg", NetLine(port));
  auto b = Agora({"--config", da + "/f.cfg", "--inner-dir", db, "--subscribe", "23", "--expect", "5", "--duration",
                  "10", "--out", db + "/b.txt"});
  ASSERT_TRUE(WaitReady(db + "/b.txt"));
  auto a = Agora({"--config", da + "/f.cfg", "--inner-dir", da, "--publish", "23", "--count", "5", "--rate", "100",
                  "--wait-peers", "1", "--duration", "10", "--out", da + "/a.txt"});
  EXPECT_EQ(b->wait(12000), 0) << slurp(db + "/b.txt") << slurp(da + "/a.txt");
  a->wait(12000);
  auto recv = lines(db + "/b.txt", "recv ");
  ASSERT_EQ(recv.size(), 5u);
  for (auto& l : recv) EXPECT_EQ(field(l, "scope"), "remote");  // Finder channels are links
}

TEST(Integration, FinderReconnectsToAnAgoraThatRestarted) {
  const std::string da = TempDir("fra"), db = TempDir("frb");
  const int port = free_port();
  write_file(da + "/f.cfg", NetLine(port));
  const std::string id_a = std::to_string(1000000 + ::getpid() * 2), id_b = std::to_string(1000001 + ::getpid() * 2);
  // A (smaller id, the dialling side) publishes for a long time.
  auto a = Agora({"--config", da + "/f.cfg", "--inner-dir", da, "--id", id_a, "--publish", "23", "--count", "100000",
                  "--rate", "50", "--duration", "60", "--out", da + "/a.txt"});
  for (int round = 0; round < 2; ++round) {
    const std::string out = db + "/b" + std::to_string(round) + ".txt";
    // Normally done in a fraction of a second; the bounds leave room for a
    // loaded machine (process start, beacons, dial, HELLO).
    auto b = Agora({"--config", da + "/f.cfg", "--inner-dir", db, "--id", id_b, "--subscribe", "23", "--expect", "5",
                    "--duration", "25", "--out", out});
    EXPECT_EQ(b->wait(28000), 0) << "round " << round << ":\n" << slurp(out) << slurp(da + "/a.txt");
    // At least the 5 expected; more when A had a backlog for B (guaranteed
    // messages queued while B was down are delivered to its next run, the
    // same agora id), but each once and in order: consecutive origin numbers.
    auto recv = lines(out, "recv ");
    EXPECT_GE(recv.size(), 5u);
    for (size_t i = 1; i < recv.size(); ++i)
      EXPECT_EQ(std::stoull(field(recv[i], "seq")), std::stoull(field(recv[i - 1], "seq")) + 1) << recv[i];
  }
}

// Two network namespaces joined by a veth pair, created (and always deleted)
// by the test itself: the only non-loopback addresses any test talks to.
class NetnsPair {
 public:
  static constexpr const char* kAddrA = "10.213.0.1";
  static constexpr const char* kAddrB = "10.213.0.2";

  NetnsPair() {
    for (const char* p : {"/usr/sbin/ip", "/sbin/ip", "/usr/bin/ip", "/bin/ip"})
      if (::access(p, X_OK) == 0) {
        ip_ = p;
        break;
      }
    const std::string pid = std::to_string(::getpid());
    ns_a_ = "dcdt_test_" + pid + "_a";
    ns_b_ = "dcdt_test_" + pid + "_b";
    veth_a_ = "dcdtv" + pid + "a";  // interface names: at most 15 characters
    veth_b_ = "dcdtv" + pid + "b";
    dir_ = TempDir("netns");
  }
  ~NetnsPair() {
    // Deleting a namespace destroys the veth end inside it (and so the pair).
    if (ns_a_created_) Ip({"netns", "del", ns_a_});
    if (ns_b_created_) Ip({"netns", "del", ns_b_});
    if (veth_in_root_) Ip({"link", "del", veth_a_});
  }
  NetnsPair(const NetnsPair&) = delete;
  NetnsPair& operator=(const NetnsPair&) = delete;

  const std::string& ip() const { return ip_; }
  const std::string& dir() const { return dir_; }
  const std::string& ns_a() const { return ns_a_; }
  const std::string& ns_b() const { return ns_b_; }

  /// Creates the two namespaces; "" on success, else why not (then skip).
  std::string CreateNamespaces() {
    if (ip_.empty()) return "iproute2's `ip` was not found";
    std::string out;
    if (!Ip({"netns", "add", ns_a_}, &out)) return "`ip netns add " + ns_a_ + "` failed: " + out;
    ns_a_created_ = true;
    if (!Ip({"netns", "add", ns_b_}, &out)) return "`ip netns add " + ns_b_ + "` failed: " + out;
    ns_b_created_ = true;
    return "";
  }

  /// veth pair, addresses, links up (lo too), multicast routes; "" on success.
  std::string Wire() {
    std::string out;
    if (!Ip({"link", "add", veth_a_, "type", "veth", "peer", "name", veth_b_}, &out))
      return "ip link add (veth): " + out;
    veth_in_root_ = true;
    if (!Ip({"link", "set", veth_a_, "netns", ns_a_}, &out)) return "ip link set netns: " + out;
    veth_in_root_ = false;
    if (!Ip({"link", "set", veth_b_, "netns", ns_b_}, &out)) return "ip link set netns: " + out;
    const std::vector<std::vector<std::string>> cmds = {
        {"-n", ns_a_, "addr", "add", std::string(kAddrA) + "/24", "dev", veth_a_},
        {"-n", ns_b_, "addr", "add", std::string(kAddrB) + "/24", "dev", veth_b_},
        {"-n", ns_a_, "link", "set", "lo", "up"},
        {"-n", ns_b_, "link", "set", "lo", "up"},
        {"-n", ns_a_, "link", "set", veth_a_, "up"},
        {"-n", ns_b_, "link", "set", veth_b_, "up"},
        {"-n", ns_a_, "route", "add", "224.0.0.0/4", "dev", veth_a_},
        {"-n", ns_b_, "route", "add", "224.0.0.0/4", "dev", veth_b_},
    };
    for (const auto& c : cmds) {
      if (!Ip(c, &out)) {
        std::string line = "ip";
        for (const auto& a : c) line += " " + a;
        return line + ": " + out;
      }
    }
    return "";
  }

  /// dcdt_agora with args, inside namespace ns.
  std::unique_ptr<Process> AgoraIn(const std::string& ns, std::vector<std::string> args) const {
    args.insert(args.begin(), {ip_, "netns", "exec", ns, kAgora});
    return std::make_unique<Process>(args);
  }

 private:
  // Runs `ip args` (at most 2 s); its output (stdout + stderr) in *out.
  bool Ip(std::vector<std::string> args, std::string* out = nullptr) const {
    const std::string log = dir_ + "/ip.log";
    args.insert(args.begin(), ip_);
    Process p(args, log);
    const int st = p.started() ? p.wait(2000) : -1;
    if (out) {
      *out = slurp(log);
      while (!out->empty() && (out->back() == '\n' || out->back() == ' ')) out->pop_back();
      if (st != 0) *out += " (exit status " + std::to_string(st) + ")";
    }
    return st == 0;
  }

  std::string ip_, ns_a_, ns_b_, veth_a_, veth_b_, dir_;
  bool ns_a_created_ = false, ns_b_created_ = false, veth_in_root_ = false;
};

// Finder discovery between two Agoras that share no inner links and no
// loopback: A in one namespace, B in the other, only the veth between them.
TEST(Integration, FinderAcrossNetworkNamespaces) {
  if (::geteuid() != 0)
    GTEST_SKIP() << "Finder across network namespaces: needs root to create network namespaces and a veth "
                    "pair (euid "
                 << ::geteuid() << "); discovery is still tested on loopback "
                 << "(FinderDiscoversAgorasByMulticastOnLoopback).";
  NetnsPair net;  // deletes what it created when the test ends, whatever happens
  const std::string why = net.CreateNamespaces();
  if (!why.empty())
    GTEST_SKIP() << "Finder across network namespaces: cannot create network namespaces here (" << why
                 << "); discovery is still tested on loopback (FinderDiscoversAgorasByMulticastOnLoopback).";
  const std::string wired = net.Wire();
  ASSERT_EQ(wired, "") << "network namespaces were created but wiring the veth pair failed";

  const std::string d = net.dir();
  const std::string tail = " " + Group() + " 7400\nPostOffice: SLWB\n";
  write_file(d + "/a.cfg", std::string(NetnsPair::kAddrA) + tail);
  write_file(d + "/b.cfg", std::string(NetnsPair::kAddrB) + tail);
  // B (the subscriber) has the smaller id, so B's Finder dials A's veth
  // address; A keeps running (subscribed to an unused type) until B is done,
  // so B's stats line still lists that dialled channel.
  const std::string id_b = std::to_string(1000000 + ::getpid() * 2), id_a = std::to_string(1000001 + ::getpid() * 2);
  auto b = net.AgoraIn(net.ns_b(), {"--config", d + "/b.cfg", "--no-inner", "--id", id_b, "--subscribe", "23",
                                    "--expect", "5", "--duration", "10", "--out", d + "/b.txt"});
  ASSERT_TRUE(WaitReady(d + "/b.txt", 3000)) << slurp(d + "/b.txt");
  auto a = net.AgoraIn(net.ns_a(), {"--config", d + "/a.cfg", "--no-inner", "--id", id_a, "--publish", "23",
                                    "--count", "5", "--rate", "100", "--wait-peers", "1", "--subscribe", "99",
                                    "--duration", "10", "--out", d + "/a.txt"});
  EXPECT_EQ(b->wait(11000), 0) << slurp(d + "/b.txt") << slurp(d + "/a.txt");
  a->kill();
  auto recv = lines(d + "/b.txt", "recv ");
  ASSERT_EQ(recv.size(), 5u) << slurp(d + "/b.txt") << slurp(d + "/a.txt");
  for (size_t i = 0; i < recv.size(); ++i) {
    EXPECT_EQ(field(recv[i], "agora"), id_a) << recv[i];
    EXPECT_EQ(field(recv[i], "seq"), std::to_string(i + 1)) << recv[i];
    EXPECT_EQ(field(recv[i], "hops"), "1") << recv[i];
    EXPECT_EQ(field(recv[i], "scope"), "remote") << recv[i];  // Finder channels are links
    EXPECT_EQ(field(recv[i], "payload"), "message " + std::to_string(i)) << recv[i];
  }
  // The messages came over the channel B's Finder dialled to A's veth address.
  auto st = lines(d + "/b.txt", "stats ");
  ASSERT_EQ(st.size(), 1u) << slurp(d + "/b.txt");
  EXPECT_NE(st[0].find(std::string("[finder -> ") + NetnsPair::kAddrA + ":"), std::string::npos) << st[0];
}

}  // namespace
