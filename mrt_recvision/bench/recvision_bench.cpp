// recvision_bench [--frames N] [--calib FILE]
// 1. Time per 640x480 frame (median over MSL scenes) of RecVision's
//    processing, and of a straightforward pipeline on the same frames
//    (per-pixel cv::cvtColor to HSV, cv::inRange per colour, findContours),
//    with their ratio.
// 2. Accuracy over N frames of an MSL field with the robot, the ball and
//    three other robots moving, against the scene's ground truth: ball
//    detected where visible within 6 m, ball distance error up to 5 m,
//    field-line points farther than 10 cm from a real line; again with the
//    illumination at 70 % and 130 %.
// Frames come from the ray-casting painter of test/synthetic_scene.h.
// Prints `name: value unit` lines.
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mrt_recvision/detector.h"
#include "synthetic_scene.h"

using namespace mrt::recvision;
namespace ts = mrt::recvision::testing;

namespace {

using V2 = Eigen::Vector2d;

// The MSL field of mrt_sim/worlds/msl_field.yaml (18 x 12 m, centre circle
// of 2 m as 24 segments, penalty and goal areas; corner arcs left out).
std::vector<ts::Seg2> msl_lines() {
  std::vector<ts::Seg2> l = {{V2(-9, -6), V2(9, -6)}, {V2(-9, 6), V2(9, 6)},    {V2(-9, -6), V2(-9, 6)},
                             {V2(9, -6), V2(9, 6)},   {V2(0, -6), V2(0, 6)}};
  for (double s : {1.0, -1.0}) {
    l.push_back({V2(s * 9, -3.25), V2(s * 6.75, -3.25)});
    l.push_back({V2(s * 6.75, -3.25), V2(s * 6.75, 3.25)});
    l.push_back({V2(s * 6.75, 3.25), V2(s * 9, 3.25)});
    l.push_back({V2(s * 9, -1.75), V2(s * 8.25, -1.75)});
    l.push_back({V2(s * 8.25, -1.75), V2(s * 8.25, 1.75)});
    l.push_back({V2(s * 8.25, 1.75), V2(s * 9, 1.75)});
  }
  for (int i = 0; i < 24; ++i) {
    const double a = 2 * M_PI * i / 24, b = 2 * M_PI * (i + 1) / 24;
    l.push_back({V2(2 * std::cos(a), 2 * std::sin(a)), V2(2 * std::cos(b), 2 * std::sin(b))});
  }
  return l;
}

struct Shot {
  ts::Scene scene;
  double x, y, yaw;  // viewpoint pose
};

// Frame i of the moving scene: the robot on a Lissajous path over the
// field, the ball and three robots on their own.
Shot shot(int i, const std::vector<ts::Seg2>& lines) {
  const double t = 0.1 * i;
  Shot s;
  s.x = 7.0 * std::sin(0.05 * t);
  s.y = 4.5 * std::sin(0.08 * t + 1.0);
  s.yaw = 0.3 * t;
  s.scene.lines = lines;
  s.scene.ball = ts::SceneBall{V2(s.x + 3.5 * std::cos(0.21 * t) + 2.0 * std::sin(0.05 * t), s.y + 3.0 * std::sin(0.17 * t)), 0.11};
  s.scene.goals = {ts::SceneGoal{V2(9, 0), 0.0}, ts::SceneGoal{V2(-9, 0), M_PI, 2.0, 0.5, 1.0, cv::Vec3b(0, 60, 220)}};
  for (int k = 0; k < 3; ++k) {
    const double p = t * (0.07 + 0.02 * k) + 2.1 * k;
    ts::SceneRobot r{V2(6.0 * std::cos(p + k), 4.0 * std::sin(1.3 * p))};
    r.marker = k == 0 ? cv::Vec3b(0, 230, 230) : cv::Vec3b(230, 0, 230);
    s.scene.robots.push_back(r);
  }
  return s;
}

double seg_distance(const V2& p, const std::vector<ts::Seg2>& lines) {
  double best = 1e9;
  for (const auto& l : lines) best = std::min(best, ts::seg_dist(p, l));
  return best;
}

// The ball's centre in the viewpoint frame, and whether it is in view
// (outside the body, within 6 m, its centre not hidden by a robot or goal).
bool ball_visible(const Shot& s, const mrt::common::OmniCamera& cam, V2& local) {
  const V2 d = s.scene.ball->c - V2(s.x, s.y);
  local = V2(std::cos(s.yaw) * d.x() + std::sin(s.yaw) * d.y(), -std::sin(s.yaw) * d.x() + std::cos(s.yaw) * d.y());
  if (d.norm() > 6.0 || d.norm() < 0.5) return false;
  const Eigen::Vector3d o(s.x, s.y, cam.height), c(s.scene.ball->c.x(), s.scene.ball->c.y(), 0.11);
  const Eigen::Vector3d dir = (c - o).normalized();
  const double tb = (c - o).norm();
  for (const auto& r : s.scene.robots)
    if (ts::hit_cylinder(o, dir, r.c, r.r, r.height) < tb) return false;
  return true;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// The straightforward pipeline: HSV of every pixel, a mask per colour, contours.
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

}  // namespace

int main(int argc, char** argv) {
  int frames = 300;
  std::string calib = MRT_RECVISION_CONFIG_DIR "/msl_omni.yaml";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--frames") frames = std::max(1, std::atoi(argv[i + 1]));
    else if (a == "--calib") calib = argv[i + 1];
  }
  const Calibration cal = load_calibration(calib);
  Detector det(cal);
  const auto lines = msl_lines();
  const double lights[3] = {1.0, 0.7, 1.3};
  const char* names[3] = {"", "_dim70", "_bright130"};
  struct Acc { int visible = 0, found = 0, near = 0, near_ok = 0, line_pts = 0, line_far = 0; std::vector<double> err; };
  Acc acc[3];
  std::vector<double> t_rv, t_base;
  cv::Mat hsv, mask;
  for (int i = 0; i < frames; ++i) {
    const Shot s = shot(i, lines);
    const cv::Mat clean = ts::render(cal.camera, s.scene, s.x, s.y, s.yaw);
    V2 ball;
    const bool vis = ball_visible(s, cal.camera, ball);
    for (int k = 0; k < 3; ++k) {
      cv::Mat lit, img;
      clean.convertTo(lit, CV_32FC3, lights[k]);
      cv::Mat n(lit.size(), CV_32FC3);
      cv::randn(n, cv::Scalar::all(0.0), cv::Scalar::all(3.0));
      lit += n;
      lit.convertTo(img, CV_8UC3);
      if (i == 0) std::fprintf(stderr, "light %.1f mean %.1f\n", lights[k], cv::mean(img)[1]);
      Frame f;
      f.rgb = img;
      const auto t0 = std::chrono::steady_clock::now();
      const auto dets = det.process(f);
      const auto t1 = std::chrono::steady_clock::now();
      if (k == 0 && i < 100) {
        t_rv.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        const auto t2 = std::chrono::steady_clock::now();
        baseline(img, hsv, mask);
        t_base.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t2).count());
      }
      Acc& a = acc[k];
      bool found = false;
      for (const Detection& d : dets) {
        if (d.membership_class == "Ball" && vis) {
          found = true;
          if (ball.norm() <= 5.0) a.err.push_back(std::abs(d.distance - ball.norm()) / ball.norm());
        }
        if (d.membership_class == "Line") {
          const V2 w(s.x + std::cos(s.yaw) * d.x - std::sin(s.yaw) * d.y, s.y + std::sin(s.yaw) * d.x + std::cos(s.yaw) * d.y);
          ++a.line_pts;
          a.line_far += seg_distance(w, lines) > 0.10;
        }
      }
      a.visible += vis;
      a.found += vis && found;
    }
  }
  const double m_rv = median(t_rv), m_base = median(t_base);
  std::printf("frame_median: %.3f ms\n", m_rv);
  std::printf("hsv_contours_frame_median: %.3f ms\n", m_base);
  std::printf("speedup_vs_hsv_contours: %.2f ratio\n", m_base / std::max(m_rv, 1e-9));
  std::printf("frames: %d frames\n", frames);
  for (int k = 0; k < 3; ++k) {
    const Acc& a = acc[k];
    int within = 0;
    for (double e : a.err) within += e <= 0.02;
    std::vector<double> e = a.err;
    std::sort(e.begin(), e.end());
    std::printf("ball_visible_6m%s: %d frames\n", names[k], a.visible);
    std::printf("ball_detected_6m%s: %.2f %%\n", names[k], a.visible ? 100.0 * a.found / a.visible : 0.0);
    std::printf("ball_distance_within_2pct_5m%s: %.2f %%\n", names[k], e.empty() ? 0.0 : 100.0 * within / e.size());
    std::printf("ball_distance_error_max_5m%s: %.2f %%\n", names[k], e.empty() ? 0.0 : 100.0 * e.back());
    std::printf("line_points%s: %d points\n", names[k], a.line_pts);
    std::printf("line_points_farther_10cm%s: %.2f %%\n", names[k], a.line_pts ? 100.0 * a.line_far / a.line_pts : 0.0);
  }
  return 0;
}
