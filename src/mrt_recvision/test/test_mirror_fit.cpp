// Mirror calibration: fitting r(theta) from marks at known distances, and
// finding white rings along a ray of a hand-drawn image.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <cmath>

#include "mrt_recvision/calibration.h"
#include "mrt_recvision/mirror_fit.h"

using namespace mrt::recvision;

namespace {
// The hyperbolic mirror of test/data/hyperbolic.yaml written out: r = 200 sin t / (0.8 + cos t).
double hyper(double d) {
  const double t = std::atan2(d, 0.6);
  return 200.0 * std::sin(t) / (0.8 + std::cos(t));
}
}  // namespace

TEST(MirrorFit, RecoversAHyperbolicMirrorFromMarks) {
  std::vector<MirrorMark> marks;
  for (double d : {0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0}) marks.push_back({hyper(d), d});
  const MirrorFit f = fit_mirror(marks, 0.6, 1.5, 5);
  EXPECT_LT(f.rms_px, 0.5);
  EXPECT_EQ(f.residual_m.size(), marks.size());
  // Between the marks: at 3.5 m, theta = 1.4013, r = 197.1 / 0.9686 = 203.5 px.
  EXPECT_NEAR(f.profile.radius(std::atan2(3.5, 0.6)), hyper(3.5), 1.0);
  EXPECT_NEAR(hyper(3.5), 203.5, 0.2);
}

TEST(MirrorFit, ReportsResidualsOfABadMark) {
  std::vector<MirrorMark> marks;
  for (double d : {0.5, 1.0, 1.5, 2.0, 3.0, 4.0}) marks.push_back({hyper(d), d});
  marks[2].radius += 6.0;  // one mark 6 px off
  const MirrorFit f = fit_mirror(marks, 0.6, 1.45, 3);
  EXPECT_GT(f.rms_px, 1.0);
  double worst = 0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < f.residual_px.size(); ++i)
    if (std::abs(f.residual_px[i]) > worst) worst = std::abs(f.residual_px[i]), at = i;
  EXPECT_EQ(at, 2u);
}

TEST(MirrorFit, RefusesTooFewMarks) {
  EXPECT_THROW(fit_mirror({{100, 1.0}, {150, 2.0}}, 0.6, 1.4, 3), std::invalid_argument);
}

TEST(MirrorFit, WhiteRingsAlongARay) {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(40, 140, 40));
  cv::circle(img, {320, 240}, 100, cv::Scalar(250, 250, 250), 3);
  cv::circle(img, {320, 240}, 150, cv::Scalar(250, 250, 250), 3);
  Frame f;
  f.rgb = img;
  const Calibration c = load_calibration(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml");
  for (double bearing : {0.0, 1.0, 2.5}) {
    const auto r = white_runs_along_ray(f, c.colors, 320, 240, bearing, 30, 230);
    ASSERT_EQ(r.size(), 2u) << bearing;
    EXPECT_NEAR(r[0], 100.0, 1.0);
    EXPECT_NEAR(r[1], 150.0, 1.0);
  }
}
