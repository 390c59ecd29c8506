// sim_bench: throughput of the simulator core on the MSL world.
// Prints `name: value unit` lines; the ratios compare against a bare
// kinematics loop measured in the same run, which is what to watch on a
// shared, noisy machine.
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <functional>
#include <string>

#include "mrt_common/angle.h"
#include "mrt_common/cli.h"
#include "mrt_sim/camera.h"
#include "mrt_sim/simulator.h"

using namespace mrt::sim;

namespace {

volatile double g_sink = 0.0;  // keeps the optimiser from dropping the work

// Calls `f` (one operation per call) in batches until `seconds` elapsed;
// returns operations per second.
double rate(double seconds, int batch, const std::function<void()>& f) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  long long n = 0;
  double elapsed = 0.0;
  do {
    for (int i = 0; i < batch; ++i) f();
    n += batch;
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  } while (elapsed < seconds);
  return n / elapsed;
}

void print(const char* name, double value, const char* unit) { std::printf("%s: %.4g %s\n", name, value, unit); }

// The MSL world with `n` robots driving circles of 2 m radius that stay
// clear of each other.
World msl_world(const std::string& path, int n) {
  World w = load_world(path);
  const double xs[] = {-2.0, -7.0, -7.0, -3.5};
  const double ys[] = {0.0, -4.0, 1.5, -4.5};
  const RobotConfig first = w.robots[0];
  w.robots.clear();
  for (int k = 0; k < n; ++k) {
    RobotConfig r = first;
    r.name = "robot" + std::to_string(k + 1);
    r.initial_pose = Pose2D(xs[k], ys[k], 0.0);
    w.robots.push_back(r);
  }
  return w;
}

// The rendered camera of the world's first robot: frames per second with
// the world file's effects and without, and the simulator of one robot
// rendering its camera at its rate, as a real-time factor.
void camera_metrics(const std::string& path, double secs, double kin) {
  Simulator sim(msl_world(path, 1));
  const RobotConfig& rc = sim.robots()[0].config;
  const CameraConfig& cc = rc.sensors.camera;
  cv::Mat img;
  for (const bool effects : {true, false}) {
    CameraOptions o = camera_options(rc, 1);
    if (!effects) o.effects = CameraEffects();
    CameraRenderer r(sim.world(), cc.model, o);
    double a = 0.0;
    long long n = 0;
    const std::clock_t c0 = std::clock();
    const double fps = rate(secs, 5, [&] {
      a += 0.05;
      ++n;
      r.render(Pose2D(-2.0 + std::cos(a), std::sin(a), a), sim.other_robots(0), a, img, {1.0, 0.0, 0.5});
    });
    const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / static_cast<double>(n);
    const std::string name = std::string("camera_render_msl") + (effects ? "" : "_no_effects");
    print(name.c_str(), 1000.0 / fps, "ms/frame");
    print((name + "_cpu").c_str(), cpu_ms, "ms/frame");  // CPU time: less sensitive to a loaded machine
    print((name + "_rate").c_str(), fps, "frames/s");
    print((name + "_vs_kinematics").c_str(), fps / kin, "ratio");
  }
  CameraRenderer r(sim.world(), cc.model, camera_options(rc, 1));
  sim.set_twist(0, {0.5, 0.0, 0.25});
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const double t0 = sim.time();
  double elapsed = 0.0;
  long long frames = 0;
  do {
    for (int i = 0; i < 100; ++i) {
      sim.step();
      const RobotState& s = sim.robots()[0];
      if (s.camera_ready) {
        r.render(s.pose, sim.other_robots(0), sim.time(), img, s.twist);
        ++frames;
      }
    }
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  } while (elapsed < secs);
  const std::string size = std::to_string(cc.model.width) + "x" + std::to_string(cc.model.height_px);
  std::printf("sim_with_camera_msl_1_robot_realtime_factor: %.4g x (%s at %g Hz, %lld frames)\n",
              (sim.time() - t0) / elapsed, size.c_str(), cc.rate, frames);
}

}  // namespace

int main(int argc, char** argv) {
  // Run from the workspace root by default.
  std::string path = "mrt_world/worlds/msl_field.yaml";
  double secs = 1.0;
  CLI::App app{"Simulator benchmark: prints `metric: value unit` lines.", "sim_bench"};
  app.add_option("world", path, "world file (YAML), default mrt_world/worlds/msl_field.yaml");
  app.add_option("seconds", secs, "wall time per metric (s, > 0), default 1")->check(CLI::PositiveNumber);
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  World world;
  try {
    world = load_world(path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }

  // Baseline: the kinematic part of a step alone, for one robot.
  const BaseConfig g = world.robots[0].base;
  Pose2D pose;
  const double kin = rate(secs, 10000, [&] {
    auto w = twist_to_wheels(g, {0.5, 0.0, 0.25});
    saturate_wheels(g, w);
    const Twist2D t = wheels_to_twist(g, w);
    pose = pose * mrt::common::exp_twist(t.vx, t.vy, t.omega, 0.001);
    g_sink = g_sink + pose.x;
  });
  print("kinematics_baseline", kin, "steps/s");

  for (int n : {1, 4}) {
    Simulator sim(msl_world(path, n));
    for (std::size_t i = 0; i < sim.robots().size(); ++i) sim.set_twist(i, {0.5, 0.0, 0.25});
    const double r = rate(secs, 1000, [&] { sim.step(); });
    const std::string name = "sim_step_msl_" + std::to_string(n) + (n == 1 ? "_robot" : "_robots");
    print(name.c_str(), r, "steps/s");
    print((name + "_realtime_factor").c_str(), r * sim.dt(), "x");
    print((name + "_vs_kinematics").c_str(), r / kin, "ratio");
  }

  const RobotConfig& robot = world.robots[0];
  const Pose2D at = robot.initial_pose;
  double angle = 0.0;
  const double rays = rate(secs, 10000, [&] {
    angle += 0.01;
    g_sink = g_sink + ray_cast(world, {}, {at.x, at.y}, angle, 10.0).value_or(0.0);
  });
  print("ray_cast_msl", rays, "rays/s");
  print("ray_cast_msl_vs_kinematics", rays / kin, "ratio");

  std::size_t k = 0;
  const double sonars = rate(secs, 10000, [&] {
    const auto& s = robot.sensors.sonars;
    g_sink = g_sink + sonar_range(world, {}, at, s[k++ % s.size()]);
  });
  print("sonar_cone_msl", sonars, "readings/s");
  print("sonar_cone_msl_vs_kinematics", sonars / kin, "ratio");

  std::size_t seen = 0;
  const double vision = rate(secs, 100, [&] {
    const auto v = vision_percepts(world, {}, at, robot.sensors);
    seen = v.size();
  });
  print("vision_msl", vision, "calls/s");
  print("vision_msl_objects", static_cast<double>(seen), "objects");
  print("vision_msl_vs_kinematics", vision / kin, "ratio");
  if (robot.sensors.camera.rate > 0.0) camera_metrics(path, secs, kin);
  return 0;
}
