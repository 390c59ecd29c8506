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
// If play hands a ball job to another robot before the drop (even just before
// the removal), one must still be held by a survivor after the drop (SCARE's drop-out itself, at
// most one cycle, is mrt_scare's gtest).
// Play continues: in the 20 s after the take, a survivor on a ball job (the
// heir, or whoever play hands the ball to) travels 0.5 m or more.
// A robot is removed only while the ball is in play (3 s after a restart)
// and a survivor sees the ball with its own camera (within the last 0.3 s):
// a removed robot that was the ball's only observer takes the ball out of
// the team's sight, and its slot is rightly not re-assigned (seen: the
// ball then lay behind the removed robot, unseen, for the next 45 s). When
// no ball job was opportune any more at the drop all the same (the ball
// went out of play in that second, or out of sight), the removal says
// nothing, and the next survivor alone on a ball job is removed (two
// removals at most: a lone survivor rightly keeps Defense over the ball).
#include <gtest/gtest.h>
#include <ros/network.h>
#include <xmlrpcpp/XmlRpc.h>

#include <algorithm>
#include <limits>
#include <set>

#include <mrt_msgs/Percept.h>

#include "mrt_common_ros/rostest_helpers.h"
#include "rostest_team.h"

using mrt::robocup::test::Sample;
using mrt::robocup::test::TeamWatch;
using mrt::ros_common::wait_for;

namespace {

const std::vector<std::string> kRobots{"robot1", "robot2", "robot3", "robot4"};
constexpr double kDropTimeout = 1.0, kCycle = 0.1, kTransport = 0.1;
constexpr double kMinOpportunity = 0.05;  // robocup_team.yaml's min_opportunity
constexpr double kSeenRecently = 0.3;      // s: a survivor sees the ball itself
// The ball jobs: opportune as long as the ball stays free or ours, so the
// slot is still wanted when its holder is dropped (Defense, Blocking, ...
// follow the ball's half and may rightly go unfilled for a while: seen, a
// Defense re-assigned 6 s later, once the ball came back).
const std::set<std::string> kBallJobs{"RecoverWanderingBall", "BringBall", "PassageToMate.passer"};

// When each robot last saw the ball itself (sim s): its own percepts
// (removal.test's ideal vision, `<robot>/percepts`).
class BallSight {
 public:
  explicit BallSight(const std::vector<std::string>& robots) {
    for (const std::string& r : robots)
      subs_.push_back(nh_.subscribe<mrt_msgs::Percept>(
          "/" + r + "/percepts", 20, [this, r](const mrt_msgs::Percept::ConstPtr& m) {
            for (const auto& o : m->objects)
              if (o.membership_class == "Ball") last[r] = std::max(last[r], m->header.stamp.toSec());
          }));
  }
  /// Whether a robot other than `victim`, and not gone, saw the ball in the last kSeenRecently s.
  bool seen_by_other(const std::set<std::string>& gone, const std::string& victim, double now) const {
    for (const auto& [r, t] : last)
      if (r != victim && !gone.count(r) && now - t <= kSeenRecently) return true;
    return false;
  }
  std::map<std::string, double> last;

 private:
  ros::NodeHandle nh_;
  std::vector<ros::Subscriber> subs_;
};

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
// The first survivor holding a ball job, "" none.
std::string ball_job_holder(const TeamWatch& team, const std::set<std::string>& gone) {
  for (const auto& r : kRobots)
    if (!gone.count(r) && team.job.count(r) && kBallJobs.count(team.job.at(r))) return r;
  return "";
}

void expect_held_after_drop(const TeamWatch& team, const std::set<std::string>& gone, const std::string& slot,
                            double last) {
  ROS_INFO("%s was taken over by play before the drop; checking it is still held after the drop", slot.c_str());
  const double after_drop = last + kDropTimeout + kCycle + kTransport;
  wait_for([&] { return ros::Time::now().toSec() >= after_drop; }, 30.0);
  EXPECT_FALSE(ball_job_holder(team, gone).empty()) << "no ball job held after the removed robot was dropped (" << slot << " taken by play before)";
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
bool ball_job_taken(TeamWatch& team, const std::set<std::string>& gone, double since, std::string* heir,
                    std::string* job, double* when) {
  for (const auto& r : kRobots) {
    if (gone.count(r)) continue;
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

// What the coordinators said from `from` to `to` (their own messages, sim
// s): intention, which teammates they still hold (the drop), and the
// opportunities and times to reach each one sent, for the log of every run.
void log_timeline(const TeamWatch& team, const std::string& victim, double from, double to) {
  for (const auto& m : team.own) {
    const double t = m->header.stamp.toSec();
    if (t < from || t > to || m->robot_id == victim) continue;
    std::string opp;
    for (std::size_t a = 0; a < m->activities.size() && a < m->opportunity.size(); ++a)
      opp += " " + m->activities[a] + "=" + std::to_string(m->opportunity[a]).substr(0, 4);
    opp += "; times";
    for (double x : m->time) opp += " " + std::to_string(x).substr(0, 4);
    const bool holds = std::find(m->heard_ids.begin(), m->heard_ids.end(), victim) != m->heard_ids.end();
    ROS_INFO("  %.2f %s job '%s' since %.2f, %s %s;%s", t, m->robot_id.c_str(), m->intention.c_str(),
             m->intention_since, holds ? "holds" : "dropped", victim.c_str(), opp.c_str());
  }
}

// Whether the ball jobs were still wanted when the silent robot was dropped:
// in every cycle of the drop's window [from, to], the survivors' mean
// opportunity of some ball job at least min_opportunity (0.05) and at least
// half of what it was when the robot was last heard (`last`). The ball may
// go out of play in that second (seen: a goal kick 1.1 s after the
// removal), or out of the survivors' sight with the removed robot, its only
// observer: its reliability, and so the opportunity, then decays as
// exp(-age / 1 s) (seen: 0.87 at the removal, 0.29 at the drop, 0 a cycle
// later). An unwanted slot is rightly not re-assigned.
bool ball_jobs_wanted(const TeamWatch& team, const std::set<std::string>& gone, double last, double from,
                      double to) {
  std::map<long, std::pair<double, int>> cycles;  // cycle -> (sum of ball opportunity, messages)
  const long first = std::lround(last / kCycle);
  for (const auto& m : team.own) {
    const double t = m->header.stamp.toSec();
    if ((t < from && std::lround(t / kCycle) != first) || t > to || gone.count(m->robot_id)) continue;
    double o = 0.0;
    for (std::size_t a = 0; a < m->activities.size() && a < m->opportunity.size(); ++a)
      for (const auto& job : kBallJobs)  // a job's activity: its slot name up to the role
        if (job.substr(0, job.find('.')) == m->activities[a]) o = std::max(o, m->opportunity[a]);
    auto& c = cycles[std::lround(t / kCycle)];
    c.first += o;
    ++c.second;
  }
  const auto at_last = cycles.find(first);
  const double before = at_last == cycles.end() ? 0.0 : at_last->second.first / at_last->second.second;
  const double floor = std::max(kMinOpportunity, 0.5 * before);
  for (const auto& [k, c] : cycles)
    if (k != first && c.first / c.second < floor) return false;
  return cycles.size() > (at_last == cycles.end() ? 0u : 1u);
}

// The robot (not gone) alone on a ball job it has held for 3 s, at least
// 8 s into play and 3 s after the last restart (the ball in play: seen, a
// removal 0.03 s into a throw-in's set-up, the jobs then those of the set
// piece), while another survivor sees the ball itself; false while there is
// none, or a robot has no job.
bool pick_victim(TeamWatch& team, const BallSight& sight, const std::set<std::string>& gone, double start,
                 std::string* victim, std::string* slot) {
  const double now = ros::Time::now().toSec();
  if (now < start + 8.0 || team.referee.empty() || team.referee.back().name != "start" ||
      now < team.referee.back().header.stamp.toSec() + 3.0)
    return false;
  std::map<std::string, int> holders;
  for (const auto& r : kRobots) {
    if (gone.count(r)) continue;
    auto it = team.job.find(r);
    if (it == team.job.end() || it->second.empty()) return false;
    ++holders[it->second];
  }
  for (const auto& r : kRobots) {
    if (gone.count(r)) continue;
    const std::string& j = team.job.at(r);
    const auto& changes = team.job_changes[r];
    const double since = changes.empty() ? 1e9 : changes.back().first;
    if (holders[j] == 1 && kBallJobs.count(j) && now - since >= 3.0 && sight.seen_by_other(gone, r, now)) {
      *victim = r;
      *slot = j;
      return true;
    }
  }
  return false;
}

// The way `robot` travelled (its true path, m) from `from` to `to` (sim s)
// while it held a ball job (both histories are in time order).
double ball_job_travel(TeamWatch& team, const std::string& robot, double from, double to) {
  const auto& changes = team.job_changes[robot];
  const auto& truth = team.truth[robot];
  auto s = std::lower_bound(truth.begin(), truth.end(), from, [](const Sample& x, double t) { return x.t < t; });
  std::size_t next = 0;  // the first job change after the sample
  const std::string* job = nullptr;
  double path = 0.0;
  const Sample* prev = nullptr;
  for (; s != truth.end() && s->t <= to; ++s) {
    for (; next < changes.size() && changes[next].first <= s->t; ++next) job = &changes[next].second;
    const bool counts = job && kBallJobs.count(*job);
    if (counts && prev) path += std::hypot(s->x - prev->x, s->y - prev->y);
    prev = counts ? &*s : nullptr;
  }
  return path;
}

// Play continues: in the 20 s after the take, a survivor on a ball job
// travels at least 0.5 m (the heir, or whoever play then hands the ball to:
// seen, an heir 9.7 m from the ball took RecoverWanderingBall and left it
// to a nearer teammate 0.2 s later). Each survivor's way and jobs are logged.
void expect_play_continues(TeamWatch& team, const std::set<std::string>& gone, double taken) {
  std::string who;
  double most = 0.0, until = taken;
  auto played = [&] {
    until = ros::Time::now().toSec();
    for (const auto& r : kRobots)
      if (!gone.count(r)) {
        const double d = ball_job_travel(team, r, taken, std::min(until, taken + 20.0));
        if (d > most) most = d, who = r;
      }
    return most >= 0.5 || until > taken + 20.0;
  };
  wait_for(played, 60.0);
  for (const auto& r : kRobots) {
    if (gone.count(r)) continue;
    std::string jobs;
    for (const auto& [t, j] : team.job_changes[r])
      if (t >= taken - 0.5 && t <= until)
        jobs += " " + (j.empty() ? "(none)" : j) + "@" + std::to_string(t).substr(0, 6);
    ROS_INFO("in the %.1f s after: %s travelled %.2f m on ball jobs; its jobs:%s", until - taken, r.c_str(),
             ball_job_travel(team, r, taken, until), jobs.c_str());
  }
  EXPECT_GE(most, 0.5) << "no survivor on a ball job travelled 0.5 m in the " << until - taken
                       << " s after the take (most: " << who << ", " << most << " m)";
}

TEST(RoboCupTeam, RemovedRobotsJobIsReassignedWithinOneCycle) {
  TeamWatch team(kRobots);
  BallSight sight(kRobots);
  ASSERT_TRUE(wait_for([&] { return team.command("start") != nullptr; }, 90.0)) << "the match never started";
  // Every robot with a job, and one of them alone on its job, held for 3 s
  // at least 8 s into play (right after the kick-off the jobs still move,
  // and a slot that stops being opportune is not re-assigned: rightly).
  const double start = team.command("start")->header.stamp.toSec();
  std::set<std::string> gone;  // removed robots
  std::string victim, slot;
  auto pick = [&] { return pick_victim(team, sight, gone, start, &victim, &slot); };
  // Up to two removals: one whose ball jobs were no longer wanted at the
  // drop (ball out of play) says nothing, and the next survivor holding one
  // is removed instead.
  std::string heir, taken_job;
  double taken = 0.0, last = 0.0;
  for (int attempt = 0; attempt < 2 && heir.empty(); ++attempt) {
    if (!wait_for(pick, 90.0)) {
      std::string seen;
      for (const auto& r : kRobots)
        seen += " " + r + "=" + (team.job.count(r) ? "'" + team.job.at(r) + "'" : "(none)") + " heard " +
                std::to_string(team.last_heard.count(r) ? team.last_heard.at(r) : -1.0) + " saw the ball " +
                std::to_string(sight.last.count(r) ? sight.last.at(r) : -1.0);
      FAIL() << "no robot holds a ball job of its own while another sees the ball:" << seen;
    }
    ROS_INFO("removing %s, which holds %s", victim.c_str(), slot.c_str());
    for (const auto& [r, t] : sight.last) ROS_INFO("  %s last saw the ball itself at %.2f", r.c_str(), t);
    for (const char* node : {"scare_coordinator", "player", "dcdt_bridge"})
      EXPECT_TRUE(shutdown_node("/" + victim + "/" + node)) << "/" << victim << "/" << node;
    const double removed = ros::Time::now().toSec();
    gone.insert(victim);
    auto taken_now = [&] { return ball_job_taken(team, gone, removed, &heir, &taken_job, &taken); };
    // Taken within the drop's window (and its messages here), or not.
    const double window_end = team.last_heard[victim] + kDropTimeout + kCycle + kTransport;
    wait_for([&] { return taken_now() || ros::Time::now().toSec() > window_end + 0.5; }, 30.0);
    last = team.last_heard[victim];
    const double drop_end = last + kDropTimeout + kCycle + kTransport;
    // Play may have handed the ball over just before the removal (seen: a
    // survivor took BringBall 0.15 s before, the removed robot's
    // RecoverWanderingBall no longer wanted): that ball job counts.
    if (heir.empty() && !(heir = ball_job_holder(team, gone)).empty()) {
      taken_job = team.job.at(heir);
      taken = team.job_changes[heir].back().first;
    }
    if (heir.empty() && !ball_jobs_wanted(team, gone, last, last + kDropTimeout, drop_end)) {
      ROS_INFO("no ball job was opportune when %s was dropped (ball out of play or unseen): it says nothing",
               victim.c_str());
      log_timeline(team, victim, last + kDropTimeout - kCycle, drop_end);
      continue;
    }
    if (heir.empty() && !wait_for(taken_now, 30.0)) {
      log_timeline(team, victim, last - 0.1, drop_end + 1.0);
      FAIL() << "no survivor took a ball job after " << victim << " (" << slot << ") was removed";
    }
    taken = std::min(taken, announced_take(team, heir, taken_job, last));
    ROS_INFO("%s took %s (%s held %s) %.3f s after it was last heard (removed at %.3f, last heard %.3f)",
             heir.c_str(), taken_job.c_str(), victim.c_str(), slot.c_str(), taken - last, removed, last);
    EXPECT_LE(taken - last, kDropTimeout + kCycle + kTransport);
    log_timeline(team, victim, last - 0.1, std::max(taken, last + kDropTimeout + kCycle) + 0.1);
    if (taken - last <= kDropTimeout - kCycle) expect_held_after_drop(team, gone, taken_job, last);
  }
  ASSERT_FALSE(heir.empty()) << "two removals, and at neither drop was a ball job still opportune";
  expect_play_continues(team, gone, taken);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rostest_robocup_removal");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
