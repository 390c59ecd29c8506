// The driver sub-module's file sources: image files in order, and a video
// file through the same VideoCapture path the V4L2 camera uses (this
// machine has no camera; a missing device must fail with its name).
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <filesystem>

#include "mrt_recvision/frame.h"

using namespace mrt::recvision;

namespace {
std::string tmp(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mrt_recvision_sources_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}
}  // namespace

TEST(Sources, ImageFilesInOrderAsRgb) {
  // OpenCV writes B, G, R: a pure red image is (0, 0, 255) in BGR.
  cv::imwrite(tmp("a.png"), cv::Mat(4, 6, CV_8UC3, cv::Scalar(0, 0, 255)));
  cv::imwrite(tmp("b.png"), cv::Mat(4, 6, CV_8UC3, cv::Scalar(255, 0, 0)));
  ImageFileSource src({tmp("a.png"), tmp("b.png")});
  Frame f;
  ASSERT_TRUE(src.next(f));
  EXPECT_EQ(f.rgb.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 0, 0));  // red first in RGB
  EXPECT_EQ(f.stamp, 0.0);
  ASSERT_TRUE(src.next(f));
  EXPECT_EQ(f.rgb.at<cv::Vec3b>(3, 5), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(f.stamp, 1.0);
  EXPECT_FALSE(src.next(f));
  ImageFileSource missing({tmp("none.png")});
  try {
    missing.next(f);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("none.png: cannot read image"), std::string::npos) << e.what();
  }
}

TEST(Sources, VideoFileThroughVideoCapture) {
  // 5 frames at 10 fps, frame k of grey level 40 k + 40: stamps k / 10 s.
  const std::string path = tmp("clip.avi");
  {
    cv::VideoWriter w(path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, cv::Size(64, 48));
    ASSERT_TRUE(w.isOpened());
    for (int k = 0; k < 5; ++k) w.write(cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(40 * k + 40)));
  }
  CameraSource src(path, 640, 480);
  EXPECT_TRUE(src.is_file());
  Frame f;
  for (int k = 0; k < 5; ++k) {
    ASSERT_TRUE(src.next(f)) << "frame " << k;
    EXPECT_EQ(f.rgb.size(), cv::Size(64, 48));  // a file keeps its size
    EXPECT_NEAR(f.rgb.at<cv::Vec3b>(24, 32)[1], 40 * k + 40, 4);  // JPEG: a few levels
    EXPECT_NEAR(f.stamp, 0.1 * k, 1e-6);
  }
  EXPECT_FALSE(src.next(f));
}

TEST(Sources, MissingCameraNamesTheDevice) {
  try {
    CameraSource src("/dev/video_mrt_missing", 640, 480);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/video_mrt_missing: cannot open camera (V4L2)");
  }
}
