// Members: periodic, cyclic and message-driven execution, LetsWork/Shutdown,
// and the manual's MemberZero example run as a program.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <dcdt.h>

#include "test_util.h"

using namespace mrt::dcdt;
using Clock = std::chrono::steady_clock;

namespace {

class Periodic : public DCDT_Member {
 public:
  Periodic(DCDT_Agora* a, int period, int stop_after) : DCDT_Member(a, period), stop_after_(stop_after) {}
  void DoYourJob(int n) override {
    times.push_back(Clock::now());
    EXPECT_EQ(n, static_cast<int>(times.size()) - 1);
    if (static_cast<int>(times.size()) == stop_after_) Terminate();
  }
  std::vector<Clock::time_point> times;
  int stop_after_;
};

TEST(Member, PeriodicRunsAtItsPeriodAndTerminatingEndsLetsWork) {
  DCDT_Agora agora(dcdt_test::IsolatedOptions());
  Periodic p(&agora, 20, 6);
  agora.AddMember(&p);
  agora.ActivateMember(&p);
  auto t0 = Clock::now();
  agora.LetsWork();
  auto elapsed = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  ASSERT_EQ(p.times.size(), 6u);
  // 6 activations at 0, 20, ..., 100 ms.
  const double span = std::chrono::duration<double, std::milli>(p.times.back() - p.times.front()).count();
  EXPECT_GE(span, 95.0);
  EXPECT_LT(span, 400.0);
  EXPECT_LT(elapsed, 2000.0);
  EXPECT_EQ(p.GetState(), MemberState::TERMINATED);
}

// On-CPU and run-queue waiting time of the calling thread, in ns
// (/proc/thread-self/schedstat); false when the kernel does not provide it.
bool ThreadSchedNs(uint64_t* on_cpu, uint64_t* waiting) {
  std::ifstream f("/proc/thread-self/schedstat");
  return static_cast<bool>(f >> *on_cpu >> *waiting);
}

class Cyclic : public DCDT_Member {
 public:
  explicit Cyclic(DCDT_Agora* a) : DCDT_Member(a) {}
  void DoYourJob(int) override {
    if (++count == 1) {
      t0 = Clock::now();
      sched_ok = ThreadSchedNs(&cpu0, &wait0);
    }
    if (count == 1000) {
      t1 = Clock::now();
      sched_ok = sched_ok && ThreadSchedNs(&cpu1, &wait1);
      Shutdown();
    }
  }
  int count = 0;
  Clock::time_point t0, t1;
  uint64_t cpu0 = 0, wait0 = 0, cpu1 = 0, wait1 = 0;
  bool sched_ok = false;
};

TEST(Member, CyclicRunsWithoutDelayAndShutdownStopsTheAgora) {
  DCDT_Agora agora(dcdt_test::IsolatedOptions());
  Cyclic c(&agora);
  Periodic slow(&agora, 60000, 1000);  // waits 60 s after its first job: only Shutdown ends it sooner
  agora.AddMember(&c);
  agora.AddMember(&slow);
  agora.ActivateMember(&c);
  agora.ActivateMember(&slow);
  agora.LetsWork();
  const auto returned = Clock::now();
  ASSERT_GE(c.count, 1000);
  const double wall_ms = std::chrono::duration<double, std::milli>(c.t1 - c.t0).count();
  if (c.sched_ok) {
    // Without delay: between its 1st and 1000th job the Member's thread is
    // either on a CPU or waiting for one (a loaded machine makes that wait
    // long: it is not counted), never asleep. A Member that waited even
    // 1 ms between jobs would sleep >= 999 ms. Sleep = wall - on CPU - queued.
    const double asleep_ms = wall_ms - static_cast<double>((c.cpu1 - c.cpu0) + (c.wait1 - c.wait0)) / 1e6;
    RecordProperty("asleep_us", static_cast<int>(asleep_ms * 1000));
    EXPECT_LT(asleep_ms, 100.0) << "wall " << wall_ms << " ms";
  } else {
    EXPECT_LT(wall_ms, 2000.0);  // no schedstat: 999 jobs of >= 1 ms would take >= 999 ms
  }
  // Shutdown interrupts the periodic Member's 60 s wait: LetsWork returns
  // long before it would end (5 s leaves room for a loaded machine).
  EXPECT_LT(std::chrono::duration<double>(returned - c.t1).count(), 5.0);
}

// A producer shares N messages; a message-driven consumer (no period,
// subscribes in Init) is woken for them and stops after the last.
class Producer : public DCDT_Member {
 public:
  Producer(DCDT_Agora* a, int n) : DCDT_Member(a, 1), n_(n) {}
  void DoYourJob(int k) override {
    DCDT_Msg* m = CreateMsg(MSG_FROM_VISION, DCDT_DW_NONE);
    int v = k;
    m->SetPayload(&v, sizeof v);
    ShareMsg(m);
    if (k + 1 == n_) Terminate();
  }
  int n_;
};

class Consumer : public DCDT_Member {
 public:
  Consumer(DCDT_Agora* a, int n) : DCDT_Member(a), n_(n) {}
  void Init() override { SubscribeMsgType(MSG_FROM_VISION, DCDT_LOCAL_MSG); }
  void DoYourJob(int pending) override {
    EXPECT_GE(pending, 1);
    ++jobs;
    while (DCDT_Msg* m = ReceiveMsg()) {
      EXPECT_EQ(m->ReadType(), MSG_FROM_VISION);
      EXPECT_EQ(m->ReadPayloadLen(), static_cast<int>(sizeof(int)));
      EXPECT_GT(m->ReadCreationTime(), 0);
      agora_ids.push_back(m->ReadAgoraID());
      int v;
      std::memcpy(&v, m->GetPayload(), sizeof v);
      values.push_back(v);
      RemoveCurrMsg();
    }
    if (static_cast<int>(values.size()) == n_) Terminate();
  }
  int n_;
  int jobs = 0;
  std::vector<int> values;
  std::vector<int> agora_ids;
};

class MessageDriven : public ::testing::TestWithParam<PostOfficePolicy> {};

TEST_P(MessageDriven, ConsumerGetsEveryMessageInOrder) {
  DCDT_Agora agora(dcdt_test::IsolatedOptions(GetParam()));
  Producer p(&agora, 50);
  Consumer c(&agora, 50);
  agora.AddMember(&p);
  agora.AddMember(&c);
  agora.ActivateMember(&c);
  agora.ActivateMember(&p);
  std::thread guard([&] {
    // Bound the test: a lost message would otherwise block LetsWork.
    for (int i = 0; i < 500 && c.GetState() != MemberState::TERMINATED; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    agora.Shutdown();
  });
  agora.LetsWork();
  guard.join();
  ASSERT_EQ(c.values.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(c.values[i], i);
  for (int id : c.agora_ids) EXPECT_EQ(id, agora.GetAgoraID());
  EXPECT_GE(c.jobs, 1);
}

INSTANTIATE_TEST_SUITE_P(AllPolicies, MessageDriven,
                         ::testing::Values(PostOfficePolicy::SLWB, PostOfficePolicy::SLWDWCV, PostOfficePolicy::SLWSM),
                         [](const auto& info) { return std::string(policy_name(info.param)); });

TEST(Member, ReceiveMsgWithoutMessagesReturnsNull) {
  DCDT_Agora agora(dcdt_test::IsolatedOptions());
  Consumer c(&agora, 1);
  agora.AddMember(&c);
  EXPECT_EQ(c.ReceiveMsg(), nullptr);
  c.RemoveCurrMsg();  // harmless without a current message
}

TEST(Member, TwoStandaloneAgorasOnOneMachineTalkThroughInnerLinks) {
  const std::string dir = dcdt_test::TempDir("inner2");
  AgoraOptions o;
  o.inner_dir = dir;
  DCDT_Agora a(o), b(o);
  Consumer c(&b, 20);
  Producer p(&a, 20);
  b.AddMember(&c);
  b.ActivateMember(&c);
  a.AddMember(&p);
  a.ActivateMember(&p);
  std::thread tb([&] { b.LetsWork(); });
  // Wait until each Agora sees the other before producing.
  ASSERT_TRUE(dcdt_test::WaitFor([&] { return a.stats().inner_peers == 1 && b.stats().inner_peers == 1; }));
  EXPECT_EQ(a.stats().peer_ids, std::vector<int>{b.GetAgoraID()});
  ASSERT_TRUE(dcdt_test::WaitFor([&] { return c.GetState() == MemberState::RUNNING; }));
  std::thread guard([&] {
    for (int i = 0; i < 500 && c.GetState() != MemberState::TERMINATED; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    b.Shutdown();
  });
  a.LetsWork();
  tb.join();
  guard.join();
  ASSERT_EQ(c.values.size(), 20u);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(c.values[i], i);
  for (int id : c.agora_ids) EXPECT_EQ(id, a.GetAgoraID());
}

// Every legacy name of dcdt.h reaches the snake_case API: a producer made
// with the (agora, period) constructor shares one message built with each
// CreateMsg overload; a message-driven consumer reads every header field back.
class LegacyProducer : public DCDT_Member {
 public:
  explicit LegacyProducer(DCDT_Agora* a) : DCDT_Member(a, 5) {}
  void DoYourJob(int) override {
    DCDT_Msg* m = CreateMsg(MSG_FROM_MAP, DCDT_DW_NONE);
    m->SetPriority(7);
    char* p = static_cast<char*>(m->AllocPayload(3));
    std::memcpy(p, "abc", 3);
    ShareMsg(m);
    DCDT_Msg* d = CreateMsg(MSG_FROM_MAP);  // default warranty: guaranteed
    d->SetPayload("xy", 2);
    ShareMsg(d);
    Terminate();
  }
};

class LegacyConsumer : public DCDT_Member {
 public:
  explicit LegacyConsumer(DCDT_Agora* a) : DCDT_Member(a) {}
  void Init() override {
    SubscribeMsgType(MSG_FROM_VISION);
    UnSubscribeMsgType(MSG_FROM_VISION);
    UnSubscribeAll();
    SubscribeMsgType(MSG_FROM_MAP, DCDT_LOCAL_MSG);
  }
  void DoYourJob(int) override {
    while (DCDT_Msg* m = ReceiveMsg()) {
      types.push_back(m->ReadType());
      member_ids.push_back(m->ReadMemberID());
      agora_ids.push_back(m->ReadAgoraID());
      priorities.push_back(m->ReadPriority());
      warranties.push_back(m->ReadDeliveryWarranty());
      payloads.emplace_back(static_cast<const char*>(m->GetPayload()), m->ReadPayloadLen());
      RemoveCurrMsg();
    }
    if (payloads.size() == 2) Terminate();
  }
  std::vector<int> types, member_ids, agora_ids, priorities, warranties;
  std::vector<std::string> payloads;
};

TEST(Member, EveryLegacyNameOfDcdtHForwards) {
  DCDT_Agora agora(dcdt_test::IsolatedOptions());
  LegacyProducer p(&agora);
  LegacyConsumer c(&agora);
  agora.AddMember(&p);
  agora.AddMember(&c);
  agora.ActivateMember(&c);
  agora.ActivateMember(&p);
  std::thread guard([&] {
    for (int i = 0; i < 500 && c.GetState() != MemberState::TERMINATED; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    agora.Shutdown();
  });
  agora.LetsWork();
  guard.join();
  EXPECT_EQ(p.GetPeriod(), 5);
  EXPECT_EQ(c.GetPeriod(), 0);
  EXPECT_EQ(p.GetAgora(), &agora);
  EXPECT_NE(p.GetMemberID(), c.GetMemberID());
  // Both messages of MSG_FROM_MAP (23) from p, in order: "abc" with priority
  // 7 and DCDT_DW_NONE (0), then "xy" with priority 0 and DCDT_DW_GUARANTEED (2).
  EXPECT_EQ(c.types, (std::vector<int>{23, 23}));
  EXPECT_EQ(c.member_ids, (std::vector<int>{p.GetMemberID(), p.GetMemberID()}));
  EXPECT_EQ(c.agora_ids, (std::vector<int>{agora.GetAgoraID(), agora.GetAgoraID()}));
  EXPECT_EQ(c.priorities, (std::vector<int>{7, 0}));
  EXPECT_EQ(c.warranties, (std::vector<int>{0, 2}));
  EXPECT_EQ(c.payloads, (std::vector<std::string>{"abc", "xy"}));
}

TEST(Member, ManualMemberZeroExampleRuns) {
  const std::string dir = dcdt_test::TempDir("member_zero");
  {
    std::ofstream f(dir + "/dcdt.conf");
    f << "127.0.0.1 239.255.42.42 " << (41000 + ::getpid() % 20000) << "\nPostOffice: SLWB\n";
  }
  const std::string out = dir + "/out.txt";
  const std::string cmd = "cd '" + dir + "' && DCDT_INNER_DIR='" + dir + "' timeout 20 '" DCDT_MEMBER_ZERO "' > '" +
                          out + "' 2>&1";
  auto t0 = Clock::now();
  int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0);
  // The period is 20 s; Shutdown from the first job must end it at once.
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 5.0);
  std::ifstream f(out);
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("MemberZero job 0"), std::string::npos) << text;
  EXPECT_NE(text.find("shares type 31, 19 bytes"), std::string::npos) << text;
  EXPECT_NE(text.find("MemberZero closed"), std::string::npos) << text;
  EXPECT_NE(text.find("LetsWork returned"), std::string::npos) << text;
}

}  // namespace
