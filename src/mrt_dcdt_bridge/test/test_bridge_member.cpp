// The bridge's Member on an Agora: a bridge that only shares ROS topics
// (no DCDT -> ROS mapping, like the referee box's) must not keep a core
// busy; one with DCDT -> ROS mappings waits for its mail.
#include <gtest/gtest.h>
#include <time.h>

#include <chrono>
#include <thread>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt_bridge/bridge_member.h"

using namespace mrt::dcdt;

namespace {

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

AgoraOptions alone() {
  AgoraOptions o;
  o.inner_links = false;  // no other Agora of this machine
  return o;
}

// The process's CPU time over `wall` of an Agora running `mapping`'s member.
double cpu_while_running(const BridgeMapping& mapping, std::chrono::milliseconds wall) {
  Agora agora(alone());
  BridgeMember member(&agora, mapping, [](const TopicMapping&, const Msg&, const XmlMessage*) { return true; });
  agora.add_member(&member);
  agora.activate_member(&member);
  std::thread worker([&] { agora.lets_work(); });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // started
  const double c0 = process_cpu_s();
  std::this_thread::sleep_for(wall);
  const double cpu = process_cpu_s() - c0;
  agora.shutdown();
  worker.join();
  return cpu;
}

TopicMapping referee_out() {
  TopicMapping m;
  m.type = 28;  // MSG_FROM_REFBOX
  m.topic = "referee";
  m.kind = PayloadKind::REFEREE;
  return m;
}

TEST(BridgeMember, OnlySharingItIsPeriodicAndIdle) {
  BridgeMapping mapping;
  mapping.to_dcdt.push_back(referee_out());
  // Free-running (period 0), its thread took 0.45-0.5 s of CPU in 0.5 s.
  EXPECT_LT(cpu_while_running(mapping, std::chrono::milliseconds(500)), 0.1);
  Agora agora(alone());
  EXPECT_EQ(BridgeMember(&agora, mapping, nullptr).period_ms(), BridgeMember::kIdlePeriodMs);
}

TEST(BridgeMember, ReceivingItIsMessageDrivenAndIdle) {
  BridgeMapping mapping;
  mapping.to_ros.push_back(referee_out());
  EXPECT_LT(cpu_while_running(mapping, std::chrono::milliseconds(500)), 0.1);
  Agora agora(alone());
  EXPECT_EQ(BridgeMember(&agora, mapping, nullptr).period_ms(), 0);
}

}  // namespace
