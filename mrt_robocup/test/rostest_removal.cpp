// rostest (issue 21): one robot is removed mid-play; its job is re-assigned
// within one coordination cycle and play continues. removal.test runs the
// whole team (robocup.launch, ideal vision); once every robot holds a job,
// the test takes the robot holding a ball job nobody else holds
// (RecoverWanderingBall, BringBall, PassageToMate.passer) out of the team
// by shutting down its SCARE coordinator, its player and its DCDT bridge
// (roscpp's XML-RPC `shutdown`, as `rosnode kill` does): it falls silent
// and, without commands, the simulator's watchdog stops it where it is.
// SCARE's protocol (mrt_scare README "The distributed protocol"): a
// teammate not heard for drop_timeout (1 s) is dropped and its slot
// re-assigned by the allocation of that same cycle (10 Hz). So a ball job
// must be another robot's by last heard + 1.0 s + one cycle (0.1 s), plus
// 0.1 s for a loaded machine (timers late, the last message's way through
// DCDT). A ball job in the form the ball's state then asks for: the removed
// robot's ball handler lets the ball go, so its BringBall may come back as
// RecoverWanderingBall.
// The time the heir took it is its coordinator's own (the intention_since
// of its team message), else when its job reached this test.
// If play hands the job to another robot before the drop, the slot must
// still be held by a survivor after the drop (SCARE's drop-out itself, at
// most one cycle, is mrt_scare's gtest).
// Play continues: the robot that took the job moves (0.5 m or more) in
// the 20 s after.
#include <gtest/gtest.h>
#include <ros/network.h>
#include <xmlrpcpp/XmlRpc.h>

#include <algorithm>
#include <limits>
#include <set>

#include "mrt_common_ros/rostest_helpers.h"
#include "rostest_team.h"

using mrt::robocup::test::TeamWatch;
using mrt::ros_common::wait_for;

namespace {

const std::vector<std::string> kRobots{"robot1", "robot2", "robot3", "robot4"};
constexpr double kDropTimeout = 1.0, kCycle = 0.1, kTransport = 0.1;
// The ball jobs: opportune as long as the ball stays free or ours, so the
// slot is still wanted when its holder is dropped (Defense, Blocking, ...
// follow the ball's half and may rightly go unfilled for a while: seen, a
// Defense re-assigned 6 s later, once the ball came back).
const std::set<std::string> kBallJobs{"RecoverWanderingBall", "BringBall", "PassageToMate.passer"};

// roscpp's node API: shutdown, as rosnode kill does. False when the node is unknown.
bool shutdown_node(const std::string& name) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = name;
  if (!ros::master::execute("lookupNode", args, result, payload, true)) return false;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return false;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue call, reply;
  call[0] = ros::this_node::getName();
  call[1] = std::string("removed by the removal rostest");
  return client.execute("shutdown", call, reply);
}

// A job taken over by play before the drop (the allocation moved it on its
// merits; seen once in 5 quiet runs) must still be a survivor's once the
// silent robot is dropped, not left vacant.
void expect_held_after_drop(const TeamWatch& team, const std::string& victim, const std::string& slot,
                            double last) {
  ROS_INFO("%s was taken over by play before the drop; checking it is still held after the drop", slot.c_str());
  const double after_drop = last + kDropTimeout + kCycle + kTransport;
  wait_for([&] { return ros::Time::now().toSec() >= after_drop; }, 30.0);
  bool held = false;
  for (const auto& r : kRobots)
    if (r != victim && team.job.count(r) && kBallJobs.count(team.job.at(r))) held = true;
  EXPECT_TRUE(held) << "no ball job held after " << victim << " was dropped (" << slot << " taken by play before)";
}

// When the heir's coordinator took the slot, on its own clock (announced in
// its next team message): not delayed by the job topic and this process.
// Infinity when not announced within 5 s.
double announced_take(TeamWatch& team, const std::string& heir, const std::string& slot, double after) {
  double announced = 0.0;
  wait_for([&] {
    for (const auto& [t, j] : team.intentions[heir])
      if (j == slot && t >= after) announced = t;
    return announced > 0.0;
  }, 5.0);
  return announced > 0.0 ? announced : std::numeric_limits<double>::infinity();
}

// The first survivor that took a ball job at or after `since`, in whichever
// form the ball's state asks for by then: a removed robot's ball handler
// lets the ball go (mrt_sim's ~dribble_timeout), so a BringBall may rightly
// come back as RecoverWanderingBall (seen: BringBall re-taken only 2.4 s
// later, once a survivor had the ball, while another had recovered it at
// once).
bool ball_job_taken(TeamWatch& team, const std::string& victim, double since, std::string* heir,
                    std::string* job, double* when) {
  for (const auto& r : kRobots) {
    if (r == victim) continue;
    for (const auto& [t, j] : team.job_changes[r])
      if (kBallJobs.count(j) && t >= since) {
        *heir = r;
        *job = j;
        *when = t;
        return true;
      }
  }
  return false;
}

TEST(RoboCupTeam, RemovedRobotsJobIsReassignedWithinOneCycle) {
  TeamWatch team(kRobots);
  ASSERT_TRUE(wait_for([&] { return team.command("start") != nullptr; }, 90.0)) << "the match never started";
  // Every robot with a job, and one of them alone on its job, held for 3 s
  // at least 8 s into play (right after the kick-off the jobs still move,
  // and a slot that stops being opportune is not re-assigned: rightly).
  const double start = team.command("start")->header.stamp.toSec();
  std::string victim, slot;
  auto held_since = [&](const std::string& r) {
    const auto& c = team.job_changes[r];
    return c.empty() ? 1e9 : c.back().first;
  };
  auto pick = [&] {
    const double now = ros::Time::now().toSec();
    if (now < start + 8.0) return false;
    std::map<std::string, int> holders;
    for (const auto& r : kRobots) {
      auto it = team.job.find(r);
      if (it == team.job.end() || it->second.empty()) return false;
      ++holders[it->second];
    }
    for (const auto& r : kRobots) {
      const std::string& j = team.job.at(r);
      if (holders[j] == 1 && kBallJobs.count(j) && now - held_since(r) >= 3.0) {
        victim = r;
        slot = j;
        return true;
      }
    }
    return false;
  };
  if (!wait_for(pick, 90.0)) {
    std::string seen;
    for (const auto& r : kRobots)
      seen += " " + r + "=" + (team.job.count(r) ? "'" + team.job.at(r) + "'" : "(none)") + " heard " +
              std::to_string(team.last_heard.count(r) ? team.last_heard.at(r) : -1.0);
    FAIL() << "no robot holds a job of its own:" << seen;
  }
  ROS_INFO("removing %s, which holds %s", victim.c_str(), slot.c_str());
  for (const char* node : {"scare_coordinator", "player", "dcdt_bridge"})
    EXPECT_TRUE(shutdown_node("/" + victim + "/" + node)) << "/" << victim << "/" << node;
  const double removed = ros::Time::now().toSec();
  std::string heir, taken_job;
  double taken = 0.0;
  ASSERT_TRUE(wait_for([&] { return ball_job_taken(team, victim, removed, &heir, &taken_job, &taken); }, 30.0)) << "no survivor took a ball job after " << victim << " (" << slot
                                          << ") was removed";
  const double last = team.last_heard[victim];
  taken = std::min(taken, announced_take(team, heir, taken_job, last));
  ROS_INFO("%s took %s (%s held %s) %.3f s after it was last heard (removed at %.3f, last heard %.3f)",
           heir.c_str(), taken_job.c_str(), victim.c_str(), slot.c_str(), taken - last, removed, last);
  EXPECT_LE(taken - last, kDropTimeout + kCycle + kTransport);
  if (taken - last <= kDropTimeout - kCycle) expect_held_after_drop(team, victim, taken_job, last);
  // Play continues: the heir executes the job (it travels at least 0.5 m
  // in the 20 s after taking it); the ball's travel is logged.
  ASSERT_NE(team.latest(heir), nullptr);
  ASSERT_FALSE(team.ball.empty());
  const auto h0 = *team.latest(heir);
  const auto b0 = team.ball.back();
  wait_for([&] {
    const auto& h = *team.latest(heir);
    return std::hypot(h.x - h0.x, h.y - h0.y) >= 0.5 || h.t - h0.t > 20.0;
  }, 60.0);
  const auto& h = *team.latest(heir);
  const auto& b = team.ball.back();
  ROS_INFO("in the %.1f s after: %s travelled %.2f m, the ball %.2f m", h.t - h0.t, heir.c_str(),
           std::hypot(h.x - h0.x, h.y - h0.y), std::hypot(b.x - b0.x, b.y - b0.y));
  EXPECT_GE(std::hypot(h.x - h0.x, h.y - h0.y), 0.5) << heir << " did not move in the " << h.t - h0.t
                                                     << " s after taking " << taken_job;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rostest_robocup_removal");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
