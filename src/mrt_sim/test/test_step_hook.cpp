// The simulator's step hooks (step_hook.h, Simulator::add_hook): when they
// are called, in which order, and that what they do takes effect in the
// step. Expected values by hand in the comments.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_sim/simulator.h"
#include "mrt_sim/step_hook.h"

using namespace mrt::sim;

namespace {

// A 10 x 10 m room, one IANUS3 at the origin facing +x; the ball at rest at
// (2, 3), no friction to speak of.
Simulator room() {
  return Simulator(parse_world("name: t\nbounds: [-5, -5, 5, 5]\n"
                               "ball: {x: 2, y: 3, friction: 0.4}\n"
                               "robots:\n  - {name: r, base: ianus3, pose: [0, 0, 0]}\n",
                               "t.yaml"),
                   0.001);
}

// Counts its calls and notes the step count and time each one saw.
struct Counter : StepHook {
  int before = 0, after = 0;
  std::vector<std::uint64_t> steps_before, steps_after;
  std::vector<double> time_after;
  void before_step(Simulator& sim) override {
    ++before;
    steps_before.push_back(sim.steps());
  }
  void after_step(Simulator& sim) override {
    ++after;
    steps_after.push_back(sim.steps());
    time_after.push_back(sim.time());
  }
};

// Writes its name and the phase to a shared log.
struct Logger : StepHook {
  std::string name;
  std::vector<std::string>* log;
  Logger(std::string n, std::vector<std::string>* l) : name(std::move(n)), log(l) {}
  void before_step(Simulator&) override { log->push_back(name + ".before"); }
  void after_step(Simulator&) override { log->push_back(name + ".after"); }
};

// Before each step: the robot drives at 1 m/s (set-points for that very
// step). After each step: the ball is carried 1 mm along +y.
struct Pusher : StepHook {
  void before_step(Simulator& sim) override { sim.set_twist(0, {1.0, 0.0, 0.0}); }
  void after_step(Simulator& sim) override { sim.ball().position.y += 0.001; }
};

TEST(StepHook, CalledAroundEveryStep) {
  // 10 steps of 1 ms: 10 calls each; before step k (1-based) the simulator
  // has made k - 1 steps, after it k, at time k * 0.001 s.
  Simulator sim = room();
  Counter c;
  sim.add_hook(c);
  for (int k = 0; k < 10; ++k) sim.step();
  EXPECT_EQ(c.before, 10);
  EXPECT_EQ(c.after, 10);
  ASSERT_EQ(c.steps_before.size(), 10u);
  EXPECT_EQ(c.steps_before.front(), 0u);
  EXPECT_EQ(c.steps_before.back(), 9u);
  EXPECT_EQ(c.steps_after.front(), 1u);
  EXPECT_EQ(c.steps_after.back(), 10u);
  EXPECT_NEAR(c.time_after.front(), 0.001, 1e-15);
  EXPECT_NEAR(c.time_after.back(), 0.010, 1e-15);
}

TEST(StepHook, HooksRunInTheOrderTheyWereAdded) {
  // Per step: every before_step in the order of add_hook, the physics, then
  // every after_step in the same order. Adding a hook twice adds it once.
  Simulator sim = room();
  std::vector<std::string> log;
  Logger a("a", &log), b("b", &log);
  sim.add_hook(a);
  sim.add_hook(b);
  sim.add_hook(a);
  sim.step();
  sim.step();
  const std::vector<std::string> expected{"a.before", "b.before", "a.after", "b.after",
                                          "a.before", "b.before", "a.after", "b.after"};
  EXPECT_EQ(log, expected);
}

TEST(StepHook, WhatAHookDoesActsInTheStep) {
  // The robot's set-points given in before_step drive the step itself: its
  // first step already moves it 1 m/s * 1 ms = 1 mm; 1000 steps of 1 ms at
  // 1 m/s straight ahead = 1.000 m (its wheels: 1 / 0.05 = 20 rad/s, under
  // the IANUS3's 24). The ball at rest is carried 1 mm per step by
  // after_step: 3 + 1000 * 0.001 = 4.000 m, x unchanged.
  Simulator sim = room();
  Pusher p;
  sim.add_hook(p);
  sim.step();
  EXPECT_NEAR(sim.robots()[0].pose.x, 0.001, 1e-12);
  for (int k = 1; k < 1000; ++k) sim.step();
  EXPECT_NEAR(sim.robots()[0].pose.x, 1.0, 1e-9);
  EXPECT_NEAR(sim.robots()[0].pose.y, 0.0, 1e-12);
  EXPECT_NEAR(sim.world().ball.position.x, 2.0, 1e-12);
  EXPECT_NEAR(sim.world().ball.position.y, 4.0, 1e-9);
}

TEST(StepHook, RemovedHooksAndCopiesAreNotCalled) {
  // remove_hook stops the calls; a copy of the simulator has no hooks (a
  // hook belongs to the simulator it was added to), the original keeps its.
  Simulator sim = room();
  Counter c;
  sim.add_hook(c);
  sim.step();
  Simulator copy = sim;
  copy.step();
  EXPECT_EQ(c.after, 1);
  sim.step();
  EXPECT_EQ(c.after, 2);
  sim.remove_hook(c);
  sim.remove_hook(c);  // not registered any more: nothing
  sim.step();
  EXPECT_EQ(c.before, 2);
  EXPECT_EQ(c.after, 2);
  EXPECT_EQ(sim.steps(), 3u);
}

}  // namespace
