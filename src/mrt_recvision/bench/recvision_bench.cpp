// recvision_bench [--frames N] [--calib FILE] [--world FILE] [--scale S]
// Frames rendered by mrt_sim's camera (CameraRenderer) on the MSL field,
// with the robot, the ball, the opponent and two team-mates moving.
// With --scale S (default 1) the camera renders images scaled by S
// (OmniCamera::scaled) and RecVision runs on the scaled calibration
// (scale_calibration): the figures of the bringup's ~camera_scale.
// 0. CPU time per frame of mrt_sim's rendering (median, first 200 frames).
// 1. CPU time per 640x480 frame on one core (median over the first 200
//    frames; the wall-clock median too) of
//    RecVision's processing, and of a straightforward pipeline on the same
//    frames (per-pixel cv::cvtColor to HSV, cv::inRange per colour,
//    findContours), with their ratio.
// 2. Accuracy over N frames against the simulator's ground truth: ball
//    detected where visible within 6 m (mrt_sim's vision_percepts decides
//    visibility: range and occlusion), ball distance error up to 5 m,
//    field-line points farther than 10 cm from a real line; again with the
//    whole image at 70 % and 130 % brightness and with the brightness
//    varying by +-30 % over the field.
// Prints `name: value unit` lines.
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_recvision/detector.h"
#include "mrt_sim/camera.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

using namespace mrt::recvision;
namespace sim = mrt::sim;

namespace {

struct Condition {
  const char* suffix;
  double gain;         // whole image
  double spatial;      // CameraEffects::illumination (+- over the field)
};

struct Tally {
  int visible = 0, found = 0, line_pts = 0, line_far = 0;
  std::vector<double> err;  // relative ball distance error, up to 5 m
};

// The moving scene at frame i (30 Hz): robot pose and twist, ball, others.
struct State {
  sim::Pose2D robot;
  sim::Twist2D twist;
  std::vector<sim::OtherRobot> others;
};

State move(int i, sim::World& w) {
  const double t = i / 30.0;
  State s;
  s.robot = {6.5 * std::sin(0.15 * t), 4.0 * std::sin(0.23 * t + 1.0), 0.5 * t};
  const double vx = 6.5 * 0.15 * std::cos(0.15 * t), vy = 4.0 * 0.23 * std::cos(0.23 * t + 1.0);
  s.twist.vx = std::cos(s.robot.theta) * vx + std::sin(s.robot.theta) * vy;
  s.twist.vy = -std::sin(s.robot.theta) * vx + std::cos(s.robot.theta) * vy;
  s.twist.omega = 0.5;
  const double d = 3.5 + 3.0 * std::sin(0.37 * t), a = 0.9 * t;
  // The ball stays on the field (inside the lines).
  w.ball.position = {std::clamp(s.robot.x + d * std::cos(a), -8.8, 8.8), std::clamp(s.robot.y + d * std::sin(a), -5.8, 5.8)};
  for (std::size_t k = 0; k < w.movers.size(); ++k)
    w.movers[k].position = {5.0 * std::cos(0.2 * t + k), 3.0 * std::sin(0.3 * t + k)};
  for (int k = 0; k < 2; ++k)
    s.others.push_back({"mate" + std::to_string(k), {-4.0 + 3.0 * std::cos(0.25 * t + 2 * k), 4.0 * std::sin(0.2 * t + k)}, 0.25, "cyan"});
  return s;
}

double line_error(const sim::World& w, const sim::Pose2D& p, const Detection& d) {
  const sim::Point2D g{p.x + std::cos(p.theta) * d.x - std::sin(p.theta) * d.y,
                       p.y + std::sin(p.theta) * d.x + std::cos(p.theta) * d.y};
  double best = 1e9;
  for (const auto& s : w.field_lines) best = std::min(best, sim::distance_to_segment(g, s));
  return best;
}

// CPU time of this thread, ms: on a shared machine the wall time of a
// frame includes the time other processes hold the core.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// The straightforward pipeline: HSV of every pixel, a mask per colour
// (orange, yellow, blue, white; OpenCV's 8-bit HSV), contours of each.
std::size_t baseline(const cv::Mat& rgb, cv::Mat& hsv, cv::Mat& mask) {
  cv::cvtColor(rgb, hsv, cv::COLOR_RGB2HSV);
  std::size_t n = 0;
  const cv::Scalar ranges[4][2] = {{{4, 140, 77}, {20, 255, 255}},    {{22, 128, 77}, {35, 255, 255}},
                                   {{100, 128, 51}, {127, 255, 255}}, {{0, 0, 140}, {180, 51, 255}}};
  for (const auto& r : ranges) {
    cv::inRange(hsv, r[0], r[1], mask);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    n += contours.size();
  }
  return n;
}

void tally(const sim::World& w, const State& st, const std::vector<Detection>& dets, bool visible, double truth,
           Tally& a) {
  bool found = false;
  for (const Detection& d : dets) {
    if (d.membership_class == "Ball" && visible && !found) {
      found = true;
      if (truth <= 5.0) a.err.push_back(std::abs(d.distance - truth) / truth);
    }
    if (d.membership_class == "Line") {
      ++a.line_pts;
      a.line_far += line_error(w, st.robot, d) > 0.10;
    }
  }
  a.visible += visible;
  a.found += visible && found;
}

void report(const Condition& c, const Tally& a) {
  int within = 0;
  for (double e : a.err) within += e <= 0.02;
  const double worst = a.err.empty() ? 0.0 : *std::max_element(a.err.begin(), a.err.end());
  std::printf("ball_visible_6m%s: %d frames\n", c.suffix, a.visible);
  std::printf("ball_detected_6m%s: %.2f %%\n", c.suffix, a.visible ? 100.0 * a.found / a.visible : 0.0);
  std::printf("ball_distance_within_2pct_5m%s: %.2f %%\n", c.suffix, a.err.empty() ? 0.0 : 100.0 * within / a.err.size());
  std::printf("ball_distance_error_median_5m%s: %.2f %%\n", c.suffix, 100.0 * median(a.err));
  std::printf("ball_distance_error_max_5m%s: %.2f %%\n", c.suffix, 100.0 * worst);
  std::printf("line_points%s: %d points\n", c.suffix, a.line_pts);
  std::printf("line_points_farther_10cm%s: %.2f %%\n", c.suffix, a.line_pts ? 100.0 * a.line_far / a.line_pts : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 1000;
  std::string calib = MRT_RECVISION_CONFIG_DIR "/msl_omni.yaml", world = MRT_SIM_WORLD;
  CLI::App app{"recvision_bench: RecVision's time per frame and detection figures on frames rendered by mrt_sim"};
  app.add_option("--frames", frames, "rendered frames per condition")->check(CLI::PositiveNumber);
  app.add_option("--calib", calib, "calibration file")->check(CLI::ExistingFile);
  app.add_option("--world", world, "mrt_sim world file (MSL field)");
  double scale = 1.0;
  app.add_option("--scale", scale, "image scale of the camera and the calibration (0.5: half size)")
      ->check(CLI::Range(0.05, 4.0));
  if (const int code = mrt::cli::parse_cli(app, argc, argv); code >= 0) return code;
  if (world.empty()) {
    std::fprintf(stderr, "recvision_bench: give --world (mrt_sim's worlds/msl_field.yaml)\n");
    return 2;
  }
  sim::World w = sim::load_world(world);
  const sim::RobotConfig rc = w.robots.at(0);
  w.robots.clear();  // the robot is driven here, not simulated
  const Calibration cal = scale_calibration(load_calibration(calib), scale);
  const mrt::common::OmniCamera cam = rc.sensors.camera.model.scaled(scale);
  Detector det(cal);
  det.set_mount(rc.sensors.camera.mount_x, rc.sensors.camera.mount_y, 0.0);
  const Condition conds[4] = {{"", 1.0, -1}, {"_dim70", 0.7, -1}, {"_bright130", 1.3, -1}, {"_varying30", 1.0, 0.3}};
  sim::CameraOptions nominal = sim::camera_options(rc, 1), varying = nominal;
  varying.effects.illumination = 0.3;
  sim::CameraRenderer r_nom(w, cam, nominal), r_var(w, cam, varying);
  sim::SensorsConfig vis = rc.sensors;
  vis.vision_range = 6.0;
  Tally acc[4];
  std::vector<double> t_rv, t_base, w_rv, t_render;
  cv::setNumThreads(1);  // one core, for both pipelines
  cv::Mat rgb, lit, hsv, mask;
  mrt::cli::Progress progress("recvision_bench", frames);
  for (int i = 0; i < frames; ++i) {
    progress.update(i);
    const State st = move(i, w);
    bool visible = false;
    for (const auto& s : sim::vision_percepts(w, st.others, st.robot, vis))
      visible = visible || (s.membership_class == "Ball" && s.distance >= 0.5);
    const double truth = std::hypot(w.ball.position.x - st.robot.x, w.ball.position.y - st.robot.y);
    for (int k = 0; k < 4; ++k) {
      const double r0 = cpu_ms();
      (conds[k].spatial > 0 ? r_var : r_nom).render(st.robot, st.others, i / 30.0, rgb, st.twist);
      if (k == 0 && i < 200) t_render.push_back(cpu_ms() - r0);
      if (conds[k].gain != 1.0) rgb.convertTo(rgb, CV_8UC3, conds[k].gain);
      Frame f;
      f.rgb = rgb;
      const auto w0 = std::chrono::steady_clock::now();
      const double c0 = cpu_ms();
      const auto dets = det.process(f);
      const double c1 = cpu_ms();
      const auto w1 = std::chrono::steady_clock::now();
      if (k == 0 && i < 200) {
        t_rv.push_back(c1 - c0);
        w_rv.push_back(std::chrono::duration<double, std::milli>(w1 - w0).count());
        const double c2 = cpu_ms();
        baseline(rgb, hsv, mask);
        t_base.push_back(cpu_ms() - c2);
      }
      tally(w, st, dets, visible, truth, acc[k]);
    }
  }
  progress.finish();
  const double m_rv = median(t_rv), m_base = median(t_base);
  std::printf("scale: %.3g (%dx%d)\n", scale, cam.width, cam.height_px);
  std::printf("render_median: %.3f ms\n", median(t_render));
  std::printf("frame_median: %.3f ms\n", m_rv);
  std::printf("frame_median_wall: %.3f ms\n", median(w_rv));
  std::printf("hsv_contours_frame_median: %.3f ms\n", m_base);
  std::printf("speedup_vs_hsv_contours: %.2f ratio\n", m_base / std::max(m_rv, 1e-9));
  std::printf("frames: %d frames\n", frames);
  for (int k = 0; k < 4; ++k) report(conds[k], acc[k]);
  return 0;
}
