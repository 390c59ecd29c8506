// A hook into Simulator::step() (ROS-free): code that acts on the world
// around every physics step without the simulator knowing it (a game's
// rules, a scripted actor, a disturbance). Register it with
// Simulator::add_hook.
#pragma once

namespace mrt::sim {

class Simulator;

class StepHook {
 public:
  virtual ~StepHook() = default;

  /// Called by Simulator::step() before the physics step, with the time and
  /// step count still those of the previous step: set what the step is to
  /// use (wheel set-points, movers' targets).
  virtual void before_step(Simulator& sim) { (void)sim; }
  /// Called by Simulator::step() after the physics step and the sensor
  /// update, with the new time: act on its outcome (move the ball, judge).
  virtual void after_step(Simulator& sim) { (void)sim; }

 protected:
  StepHook() = default;
  StepHook(const StepHook&) = default;
  StepHook& operator=(const StepHook&) = default;
};

}  // namespace mrt::sim
