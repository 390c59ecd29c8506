// murea_bench, part 3: a laser robot in a world of walls (the museum):
// the map is the world's occupancy grid at 5 cm (what world_node serves
// and murea_node takes with use_map_topic), its occupied cells as walls;
// the scans are ray-cast in the world file (test/laser_cast.h): 360 beams,
// 8 m, 1 cm noise, 30 valid beams kept (scan_percepts, as murea_node and
// amcl's laser_max_beams). MUREA and the MCL baseline get the same
// percepts: tracking along an ellipse, and global fixes from random poses.
#include <iostream>

#include "../test/laser_cast.h"
#include "bench_common.h"
#include "mrt_murea/scan.h"

namespace mrt::murea::bench {

namespace {

using mrt::common::kPi;
using mrt::murea::test::LaserCaster;

const ScanGeometry kScan{-kPi, 2 * kPi / 360, 0.05, 8.0};

std::vector<Percept> laser_frame(const LaserCaster& caster, const Pose2D& pose, std::mt19937& rng) {
  const std::vector<float> r =
      caster.ranges(pose, 360, kScan.angle_min, kScan.angle_increment, kScan.range_max, 0.01, rng);
  return scan_percepts(r, kScan, 30);
}

// Odometry of the true motion d: 3 % translation noise, heading noise 2 %
// of the turn + 0.01 rad per metre (as the figure-eight recording's).
void add_odometry(Recording& rec, const Pose2D& d, std::mt19937_64& rng) {
  std::normal_distribution<double> n01(0.0, 1.0);
  const double dist = std::hypot(d.x, d.y), st = 0.02 * std::abs(d.theta) + 0.01 * dist;
  rec.odom.emplace_back(d.x * (1 + 0.03 * n01(rng)), d.y * (1 + 0.03 * n01(rng)), d.theta + st * n01(rng));
  const double sxy = 0.03 * dist + 1e-4;
  rec.odom_cov.push_back({sxy * sxy, 0, 0, 0, sxy * sxy, 0, 0, 0, st * st + 1e-8});
}

// 10 Hz scans along the ellipse of the laser rostest (the museum's
// south-west room, centre (6.2, 3), half-axes 2.5 and 1.8 m, 0.45 to 0.63 m/s).
Recording ellipse_run(const LaserCaster& caster, double seconds) {
  Recording rec;
  rec.dt = 0.1;
  std::mt19937 rng(35);
  std::mt19937_64 orng(15);
  const int frames = static_cast<int>(seconds / rec.dt);
  Pose2D prev = mrt::murea::test::ellipse_pose(0.0);
  for (int i = 0; i <= frames; ++i) {
    const Pose2D truth = mrt::murea::test::ellipse_pose(i * rec.dt);
    add_odometry(rec, prev.inverse() * truth, orng);
    prev = truth;
    rec.truth.push_back(truth);
    rec.percepts.push_back(laser_frame(caster, truth, rng));
  }
  return rec;
}

// Global fixes: `trials` random poses of the world with 0.4 m of
// clearance; the robot turns on the spot at 0.5 rad/s for 10 s (100
// scans, 5 rad: amcl's filter runs at each pi/6 turned, about 10 times).
// A fix at 1, 3 and 10 s: the estimate then within 0.3 m and 10 deg of
// the truth (MUREA: tracking, not lost).
void global_fixes(const LaserCaster& caster, const FeatureMap& map, int trials) {
  std::mt19937_64 rng(2035);
  std::mt19937 srng(36);
  const auto& w = caster.world();
  std::uniform_real_distribution<double> ux(w.min_x, w.max_x), uy(w.min_y, w.max_y), ut(-kPi, kPi);
  const int checks[3] = {10, 30, 100};  // scans: 1, 3, 10 s
  int murea_fix[3] = {}, mcl_fix[3] = {};
  std::vector<double> murea_cpu, mcl_cpu;
  TrackerOptions topt;  // murea_node's defaults: 0.05 s of CPU time per search
  topt.search.timeout = 0.05;
  topt.search.timeout_cpu = true;
  MclOptions mopt;
  mopt.range_max = kScan.range_max;
  for (int t = 0; t < trials; ++t) {
    Pose2D p;
    do p = Pose2D(ux(rng), uy(rng), ut(rng));
    while (caster.clearance({p.x, p.y}) < 0.4);
    Tracker tracker(map, topt);
    Mcl mcl(map, mopt, 4242 + t);
    mcl.global_init();
    for (int i = 0; i < 100; ++i) {
      const Pose2D d(0.0, 0.0, i > 0 ? 0.05 : 0.0);
      p = p * d;
      const std::vector<Percept> ps = laser_frame(caster, p, srng);
      double c0 = thread_cpu_ms();
      if (i > 0) tracker.predict(d, {1e-6, 0, 0, 0, 1e-6, 0, 0, 0, 1e-6});
      const TrackResult r = tracker.update(ps);
      murea_cpu.push_back(thread_cpu_ms() - c0);
      c0 = thread_cpu_ms();
      mcl.frame(d, ps);
      mcl_cpu.push_back(thread_cpu_ms() - c0);
      for (int k = 0; k < 3; ++k)
        if (i + 1 == checks[k]) {
          murea_fix[k] += !r.lost && near(r.pose, p);
          mcl_fix[k] += near(mcl.estimate(), p);
        }
    }
  }
  const double pct = 100.0 / std::max(1, trials);
  std::cout << "laser_global_trials: " << trials << " count\n";
  const char* at[3] = {"1s", "3s", "10s"};
  for (int k = 0; k < 3; ++k)
    std::cout << "laser_global_fix_" << at[k] << "_murea: " << murea_fix[k] * pct << " %\n"
              << "laser_global_fix_" << at[k] << "_mcl: " << mcl_fix[k] * pct << " %\n";
  std::cout << "laser_global_cpu_per_scan_median_murea: " << percentile(murea_cpu, 0.5) << " ms\n"
            << "laser_global_cpu_per_scan_median_mcl: " << percentile(mcl_cpu, 0.5) << " ms\n"
            << "laser_global_cpu_per_scan_mean_murea: " << mean(murea_cpu) << " ms\n"
            << "laser_global_cpu_per_scan_mean_mcl: " << mean(mcl_cpu) << " ms\n";
}

}  // namespace

void laser_benchmarks(const std::string& world_file, double seconds, int trials) {
  const LaserCaster caster(world_file);
  const FeatureMap map(mrt::world::occupied_walls(mrt::world::rasterize(caster.world(), 0.05)));
  const Recording rec = ellipse_run(caster, seconds);
  MclOptions mopt;
  mopt.range_max = kScan.range_max;
  const Stats m = run_murea(map, rec, true, true), b = run_mcl(map, rec, true, mopt);
  std::cout << "laser_tracking_frames: " << rec.truth.size() << " count\n";
  const struct {
    const char* name;
    double murea, mcl;
    const char* unit;
  } rows[] = {{"rmse_xy", 100 * m.rmse_xy, 100 * b.rmse_xy, "cm"},
              {"rmse_theta", m.rmse_theta * 180 / kPi, b.rmse_theta * 180 / kPi, "deg"},
              {"worst_xy", 100 * m.worst, 100 * b.worst, "cm"},
              {"converged_after", m.converged_s, b.converged_s, "s"},
              {"update_cpu_median", percentile(m.cpu_ms, 0.5), percentile(b.cpu_ms, 0.5), "ms"},
              {"update_cpu_p95", percentile(m.cpu_ms, 0.95), percentile(b.cpu_ms, 0.95), "ms"},
              {"update_cpu_mean", mean(m.cpu_ms), mean(b.cpu_ms), "ms"},
              // MCL's filter runs only after update_min_d or update_min_a of motion; MUREA at every scan.
              {"filter_update_cpu_median", percentile(m.cpu_ms, 0.5), percentile(b.search_ms, 0.5), "ms"},
              {"filter_updates", static_cast<double>(m.cpu_ms.size()), static_cast<double>(b.search_ms.size()), "count"}};
  for (const auto& r : rows)
    std::cout << "laser_tracking_" << r.name << "_murea: " << r.murea << ' ' << r.unit << '\n'
              << "laser_tracking_" << r.name << "_mcl: " << r.mcl << ' ' << r.unit << '\n';
  global_fixes(caster, map, trials);
}

}  // namespace mrt::murea::bench
