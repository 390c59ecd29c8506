// Detections on drawn images with known positions: a disc drawn with
// cv::circle, and scenes ray-cast by test/synthetic_scene.h (ball, goal,
// robot, field lines), under illumination change; bad frames.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <cmath>

#include "mrt_common/yaml_reader.h"
#include "mrt_recvision/detector.h"
#include "synthetic_scene.h"

using namespace mrt::recvision;
namespace ts = mrt::recvision::testing;

namespace {
Calibration cal() { return load_calibration(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml"); }

Frame frame_of(const cv::Mat& rgb) {
  Frame f;
  f.rgb = rgb;
  return f;
}

std::vector<Detection> of_class(const std::vector<Detection>& d, const std::string& cls) {
  std::vector<Detection> out;
  for (const Detection& x : d)
    if (x.membership_class == cls) out.push_back(x);
  return out;
}
}  // namespace

TEST(Detector, DrawnDiscIsABallOnTheRayOfItsCentre) {
  const Calibration c = cal();
  Detector det(c);
  double u = 0, v = 0;
  ASSERT_TRUE(c.camera.project_ground(1.5, 0.0, u, v));
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(40, 140, 40));
  cv::circle(img, {int(std::lround(u)), int(std::lround(v))}, 4, cv::Scalar(255, 120, 0), cv::FILLED);
  const auto balls = of_class(det.process(frame_of(img)), "Ball");
  ASSERT_EQ(balls.size(), 1u);
  // The ray through the disc's centre meets the floor at 1.5 m; the ball's
  // centre is 0.11 m up on it: 1.5 * (0.6 - 0.11) / 0.6 = 1.225 m.
  EXPECT_NEAR(balls[0].distance, 1.225, 0.02);
  EXPECT_NEAR(balls[0].bearing, 0.0, 0.01);
  EXPECT_EQ(balls[0].color, ColorClass::kOrange);
}

TEST(Detector, RayCastBallWithinTwoPercentUpToFiveMetres) {
  const Calibration c = cal();
  Detector det(c);
  for (const auto& p : {Eigen::Vector2d(1.0, 0.5), Eigen::Vector2d(2.0, 1.0), Eigen::Vector2d(-3.0, 1.5),
                        Eigen::Vector2d(4.0, -3.0)}) {
    for (double light : {0.7, 1.0, 1.3}) {
      ts::Scene s;
      s.ball = ts::SceneBall{p, 0.11};
      s.illumination = light;
      const auto balls = of_class(det.process(frame_of(ts::render(c.camera, s, 0, 0, 0))), "Ball");
      ASSERT_EQ(balls.size(), 1u) << p.transpose() << " light " << light;
      EXPECT_NEAR(balls[0].distance, p.norm(), 0.02 * p.norm()) << p.transpose() << " light " << light;
      EXPECT_NEAR(balls[0].bearing, std::atan2(p.y(), p.x()), 0.01);
    }
  }
}

TEST(Detector, MountMovesDetectionsIntoBaseLink) {
  const Calibration c = cal();
  Detector det(c);
  det.set_mount(0.1, -0.05, 0.0);
  ts::Scene s;
  s.ball = ts::SceneBall{Eigen::Vector2d(2.0, 0.0), 0.11};
  const auto balls = of_class(det.process(frame_of(ts::render(c.camera, s, 0, 0, 0))), "Ball");
  ASSERT_EQ(balls.size(), 1u);
  EXPECT_NEAR(balls[0].x, 2.1, 0.04);
  EXPECT_NEAR(balls[0].y, -0.05, 0.01);
}

TEST(Detector, GoalAndPostsFromTheirColour) {
  const Calibration c = cal();
  Detector det(c);
  ts::Scene s;
  s.goals.push_back(ts::SceneGoal{Eigen::Vector2d(3.0, 0.0), 0.0});
  const auto d = det.process(frame_of(ts::render(c.camera, s, 0, 0, 0)));
  const auto goals = of_class(d, "Goal");
  ASSERT_EQ(goals.size(), 1u);
  EXPECT_EQ(goals[0].color, ColorClass::kYellow);
  EXPECT_NEAR(goals[0].distance, 3.0, 0.15);
  EXPECT_NEAR(goals[0].bearing, 0.0, 0.02);
  const auto posts = of_class(d, "GoalPost");
  ASSERT_EQ(posts.size(), 2u);
  // Posts at (3, +-1): bearing atan2(1, 3) = 0.3218, distance 3.162 (their near face: 0.06 m less).
  for (const Detection& p : posts) {
    EXPECT_NEAR(std::abs(p.bearing), 0.3218, 0.03);
    EXPECT_NEAR(p.distance, 3.10, 0.15);
  }
  EXPECT_LT(posts[0].bearing * posts[1].bearing, 0.0);
}

TEST(Detector, RobotWithItsMarkerColour) {
  const Calibration c = cal();
  Detector det(c);
  ts::Scene s;
  s.robots.push_back(ts::SceneRobot{Eigen::Vector2d(2.5, -1.0)});
  s.robots.push_back(ts::SceneRobot{Eigen::Vector2d(-2.0, 2.0), 0.25, 0.6, cv::Vec3b(230, 0, 230)});
  const auto robots = of_class(det.process(frame_of(ts::render(c.camera, s, 0, 0, 0))), "Robot");
  ASSERT_EQ(robots.size(), 2u);
  for (const Detection& r : robots) {
    const bool first = r.bearing < 0;  // (2.5, -1) is to the right
    const Eigen::Vector2d p = first ? Eigen::Vector2d(2.5, -1.0) : Eigen::Vector2d(-2.0, 2.0);
    EXPECT_NEAR(r.distance, p.norm(), 0.12);  // 2.693 and 2.828 m
    EXPECT_NEAR(r.bearing, std::atan2(p.y(), p.x()), 0.03);
    EXPECT_EQ(r.color, first ? ColorClass::kCyan : ColorClass::kMagenta);
  }
}

TEST(Detector, FieldLinePointsLieOnTheLines) {
  const Calibration c = cal();
  Detector det(c);
  ts::Scene s;
  s.lines = {{Eigen::Vector2d(1.5, -6), Eigen::Vector2d(1.5, 6)}, {Eigen::Vector2d(-6, 2.0), Eigen::Vector2d(6, 2.0)},
             {Eigen::Vector2d(-2.5, -6), Eigen::Vector2d(-2.5, 6)}};
  for (double light : {0.7, 1.3}) {
    s.illumination = light;
    s.noise = 3.0;
    const auto lines = of_class(det.process(frame_of(ts::render(c.camera, s, 0, 0, 0))), "Line");
    EXPECT_GE(lines.size(), 60u);
    int far = 0;
    for (const Detection& l : lines) {
      const double e = std::min({std::abs(l.x - 1.5), std::abs(l.y - 2.0), std::abs(l.x + 2.5)});
      far += e > 0.10;
      EXPECT_LE(l.distance, 4.0 + 1e-9);
    }
    EXPECT_LE(far, int(0.02 * lines.size())) << "light " << light;
  }
}

TEST(Detector, EmptyCarpetGivesNothing) {
  const Calibration c = cal();
  Detector det(c);
  ts::Scene s;
  s.noise = 4.0;
  EXPECT_TRUE(det.process(frame_of(ts::render(c.camera, s, 0, 0, 0))).empty());
}

TEST(Detector, RefusesFramesOfTheWrongSizeOrType) {
  Detector det(cal());
  std::string why;
  EXPECT_FALSE(det.accepts(frame_of(cv::Mat(240, 320, CV_8UC3)), why));
  EXPECT_NE(why.find("320x240"), std::string::npos);
  EXPECT_FALSE(det.accepts(frame_of(cv::Mat(480, 640, CV_8UC1)), why));
  EXPECT_THROW(det.process(frame_of(cv::Mat(240, 320, CV_8UC3))), std::invalid_argument);
  EXPECT_TRUE(det.accepts(frame_of(cv::Mat(480, 640, CV_8UC3)), why));
}

TEST(FrameFromRaw, ConvertsBgrAndRefusesOtherEncodings) {
  const std::uint8_t bgr[2 * 3] = {1, 2, 3, 4, 5, 6};
  Frame f;
  std::string why;
  ASSERT_TRUE(frame_from_raw("bgr8", 2, 1, 6, bgr, 6, 1.5, f, why));
  EXPECT_EQ(f.rgb.at<cv::Vec3b>(0, 0), cv::Vec3b(3, 2, 1));
  EXPECT_DOUBLE_EQ(f.stamp, 1.5);
  EXPECT_FALSE(frame_from_raw("mono8", 2, 1, 6, bgr, 6, 0, f, why));
  EXPECT_NE(why.find("mono8"), std::string::npos);
  EXPECT_FALSE(frame_from_raw("rgb8", 2, 2, 6, bgr, 6, 0, f, why));  // buffer holds one row only
}

TEST(Detector, BallPartlyHiddenByTheBodyIsMeasuredFromItsOuterEdge) {
  // The body hides everything inside the image radius of 0.62 m; a ball at
  // 0.63 m (floor extent 0.52 ... 0.74 m) is cut: its visible centroid lies
  // outwards. The detector's blind zone is set to the same 0.62 m.
  std::string text = mrt::common::read_file(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml");
  text.replace(text.find("min_distance: 0.35"), 18, "min_distance: 0.62");
  Detector det(parse_calibration(text, "hidden.yaml"));
  const Calibration c = det.calibration();
  for (double d : {0.63, 0.64}) {
    ts::Scene s;
    s.body_radius = 0.62;
    s.ball = ts::SceneBall{Eigen::Vector2d(0.0, d), 0.11};
    const auto balls = of_class(det.process(frame_of(ts::render(c.camera, s, 0, 0, 0))), "Ball");
    ASSERT_EQ(balls.size(), 1u) << d;
    // Its centroid alone gives 0.6461 at 0.64 m (1 % long); the outer edge 0.6412.
    EXPECT_NEAR(balls[0].distance, d, 0.005 * d) << d;
    EXPECT_NEAR(balls[0].bearing, M_PI / 2, 0.02);
  }
}

// recvision_node's dynamic_reconfigure (retuned): a ray-cast ball at
// (2, -0.5) m is 2.06 m away; the rays through it meet the floor farther
// still (its centre's at 2.06 * 0.6 / (0.6 - 0.11) = 2.52 m), so with
// max_distance 1.5 m none of its pixels is scanned: no ball; with
// min_ball_pixels beyond the whole image's pixel count neither. Bad values
// name the key.
TEST(Detector, RetunedThresholdsChangeWhatIsDetected) {
  const Calibration c = cal();
  ts::Scene s;
  s.ball = ts::SceneBall{Eigen::Vector2d(2.0, -0.5), 0.11};
  const Frame f = frame_of(ts::render(c.camera, s, 0, 0, 0));
  EXPECT_EQ(of_class(Detector(c).process(f), "Ball").size(), 1u);
  DetectorTuning t = tuning_of(c.detector);
  EXPECT_DOUBLE_EQ(t.max_distance, c.detector.max_distance);
  Calibration near = c;
  t.max_distance = 1.5;
  near.detector = retuned(c.detector, t);
  EXPECT_EQ(of_class(Detector(near).process(f), "Ball").size(), 0u);
  Calibration strict = c;
  t = tuning_of(c.detector);
  t.min_ball_pixels = 640 * 480 + 1;
  strict.detector = retuned(c.detector, t);
  EXPECT_EQ(of_class(Detector(strict).process(f), "Ball").size(), 0u);
  t = tuning_of(c.detector);
  t.max_distance = t.min_distance;
  try {
    retuned(c.detector, t);
    ADD_FAILURE() << "max_distance = min_distance accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_distance"), std::string::npos) << e.what();
  }
  t = tuning_of(c.detector);
  t.min_goal_pixels = 0;
  EXPECT_THROW(retuned(c.detector, t), std::invalid_argument);
}
