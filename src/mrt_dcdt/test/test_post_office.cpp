// PostOffice delivery for each subscription scope and each policy.
#include <gtest/gtest.h>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/post_office.h"
#include "test_util.h"

using namespace mrt::dcdt;
using dcdt_test::WaitFor;

namespace {

class PolicyTest : public ::testing::TestWithParam<PostOfficePolicy> {};

MsgPtr MakeMsg(int type, int agora, int member, bool remote, uint64_t seq = 1) {
  auto m = std::make_shared<Msg>(type, member, agora, DCDT_DW_NONE);
  m->mutable_header().remote = remote;
  m->mutable_header().seq = seq;
  return m;
}

TEST_P(PolicyTest, ScopesSelectLocalAndRemoteMessages) {
  auto po = PostOffice::create(GetParam());
  po->agora_id = 1;
  MailBox local, remote, all, none;
  local.member_id = 1;
  remote.member_id = 2;
  all.member_id = 3;
  none.member_id = 4;
  for (auto* b : {&local, &remote, &all, &none}) po->register_mailbox(b);
  po->subscribe(1, 18, DCDT_LOCAL_MSG);
  po->subscribe(2, 18, DCDT_REMOTE_MSG);
  po->subscribe(3, 18, DCDT_ALL_MSG);
  po->subscribe(4, 19, DCDT_ALL_MSG);  // another type

  po->post(MakeMsg(18, 7, 1, false));  // local (from another Agora of this machine)
  po->post(MakeMsg(18, 8, 1, true));   // remote (through a link)
  ASSERT_TRUE(WaitFor([&] { return po->pending(&all) == 2; }));
  EXPECT_EQ(po->pending(&local), 1u);
  EXPECT_EQ(po->pending(&remote), 1u);
  EXPECT_EQ(po->pending(&none), 0u);
  EXPECT_FALSE(po->pop(&local)->header().remote);
  EXPECT_TRUE(po->pop(&remote)->header().remote);
  // ALL keeps the acceptance order.
  EXPECT_EQ(po->pop(&all)->agora_id(), 7);
  EXPECT_EQ(po->pop(&all)->agora_id(), 8);
  EXPECT_EQ(po->pop(&all), nullptr);
}

TEST_P(PolicyTest, UnsubscribeRemovesScopeBitsAndAll) {
  auto po = PostOffice::create(GetParam());
  MailBox b;
  b.member_id = 5;
  po->register_mailbox(&b);
  po->subscribe(5, 21, DCDT_ALL_MSG);
  po->unsubscribe(5, 21, DCDT_REMOTE_MSG);  // LOCAL remains
  po->post(MakeMsg(21, 9, 1, true, 1));
  po->post(MakeMsg(21, 9, 1, false, 2));
  ASSERT_TRUE(WaitFor([&] { return po->pending(&b) == 1; }));
  EXPECT_FALSE(po->pop(&b)->header().remote);
  po->subscribe(5, 22, DCDT_ALL_MSG);
  po->unsubscribe_all(5);
  EXPECT_FALSE(po->has_subscriptions(5));
  po->post(MakeMsg(21, 9, 1, false, 3));
  po->post(MakeMsg(22, 9, 1, false, 4));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(po->pending(&b), 0u);
}

TEST_P(PolicyTest, ProducerNeverReceivesItsOwnMessage) {
  auto po = PostOffice::create(GetParam());
  po->agora_id = 3;
  MailBox a, b;
  a.member_id = 1;
  b.member_id = 2;
  po->register_mailbox(&a);
  po->register_mailbox(&b);
  po->subscribe(1, 18, DCDT_ALL_MSG);
  po->subscribe(2, 18, DCDT_ALL_MSG);
  po->post(MakeMsg(18, 3, 1, false));
  ASSERT_TRUE(WaitFor([&] { return po->pending(&b) == 1; }));
  EXPECT_EQ(po->pending(&a), 0u);
}

TEST_P(PolicyTest, ManyPublishersEveryMessageDeliveredOnceInPerPublisherOrder) {
  auto po = PostOffice::create(GetParam());
  MailBox b;
  b.member_id = 99;
  po->register_mailbox(&b);
  po->subscribe(99, 18, DCDT_ALL_MSG);
  const int kPublishers = 4, kEach = 2000;
  std::vector<std::thread> th;
  for (int p = 0; p < kPublishers; ++p)
    th.emplace_back([&, p] {
      for (int i = 1; i <= kEach; ++i) po->post(MakeMsg(18, 100 + p, 1, false, static_cast<uint64_t>(i)));
    });
  for (auto& t : th) t.join();
  ASSERT_TRUE(WaitFor([&] { return po->pending(&b) == size_t(kPublishers * kEach); }));
  std::vector<uint64_t> last(kPublishers, 0);
  while (auto m = po->pop(&b)) {
    int p = m->agora_id() - 100;
    EXPECT_EQ(m->header().seq, last[p] + 1);
    last[p] = m->header().seq;
  }
}

INSTANTIATE_TEST_SUITE_P(AllPolicies, PolicyTest,
                         ::testing::Values(PostOfficePolicy::SLWB, PostOfficePolicy::SLWDWCV, PostOfficePolicy::SLWSM),
                         [](const auto& info) { return std::string(policy_name(info.param)); });

TEST(PostOffice, PolicyNamesRoundTrip) {
  for (auto p : {PostOfficePolicy::SLWB, PostOfficePolicy::SLWDWCV, PostOfficePolicy::SLWSM}) {
    PostOfficePolicy q;
    ASSERT_TRUE(parse_policy(policy_name(p), &q));
    EXPECT_EQ(p, q);
  }
  PostOfficePolicy q;
  EXPECT_FALSE(parse_policy("SLW", &q));
}

// Routing: scope is decided by the kind of channel a message entered by,
// link forwards only own messages, bridge forwards received ones up to level.
TEST(Routing, LinkAndBridgeForwardingAndScopes) {
  Agora agora(dcdt_test::IsolatedOptions());
  auto link_in = std::make_unique<dcdt_test::FakeChannel>(ChannelMode::LINK);
  auto bridge_in = std::make_unique<dcdt_test::FakeChannel>(ChannelMode::BRIDGE, 1);
  auto bridge0 = std::make_unique<dcdt_test::FakeChannel>(ChannelMode::BRIDGE, 0);
  auto* li = link_in.get();
  auto* bi = bridge_in.get();
  auto* b0 = bridge0.get();
  agora.add_channel(std::move(link_in));
  agora.add_channel(std::move(bridge_in));
  agora.add_channel(std::move(bridge0));

  MailBox box;
  box.member_id = 1000;
  agora.post_office().register_mailbox(&box);
  agora.post_office().subscribe(1000, 18, DCDT_ALL_MSG);

  // A message arriving through the link: REMOTE; forwarded by the level-1
  // bridge (hops 1 <= 1), not by the level-0 bridge, never back to the link.
  auto m1 = std::make_shared<Msg>(18, 1, 555, DCDT_DW_NONE);
  m1->mutable_header().seq = 1;
  agora.route(m1, Source{Source::CHANNEL, li});
  auto got = agora.post_office().pop(&box);
  ASSERT_TRUE(got);
  EXPECT_TRUE(got->header().remote);
  EXPECT_EQ(got->header().hops, 1);
  EXPECT_EQ(li->count(), 0u);
  EXPECT_EQ(bi->count(), 1u);
  EXPECT_EQ(b0->count(), 0u);

  // Through a bridge: LOCAL scope.
  auto m2 = std::make_shared<Msg>(18, 1, 556, DCDT_DW_NONE);
  m2->mutable_header().seq = 1;
  agora.route(m2, Source{Source::CHANNEL, bi});
  got = agora.post_office().pop(&box);
  ASSERT_TRUE(got);
  EXPECT_FALSE(got->header().remote);

  // The same message again (a loop or a second path): dropped.
  auto m2b = std::make_shared<Msg>(18, 1, 556, DCDT_DW_NONE);
  m2b->mutable_header().seq = 1;
  agora.route(m2b, Source{Source::CHANNEL, li});
  EXPECT_EQ(agora.post_office().pop(&box), nullptr);
  EXPECT_EQ(agora.stats().duplicates, 1u);

  // Our own message coming back: dropped.
  auto own = std::make_shared<Msg>(18, 1, agora.agora_id(), DCDT_DW_NONE);
  own->mutable_header().seq = 77;
  agora.route(own, Source{Source::CHANNEL, bi});
  EXPECT_EQ(agora.post_office().pop(&box), nullptr);

  // A message of a local Member goes out on every channel.
  auto mine = std::make_shared<Msg>(18, 1, agora.agora_id(), DCDT_DW_NONE);
  mine->mutable_header().seq = 1;
  agora.route(mine, Source{Source::MEMBER, nullptr});
  EXPECT_EQ(li->count(), 1u);
  EXPECT_EQ(b0->count(), 1u);
  agora.post_office().unregister_mailbox(&box);
}

}  // namespace
