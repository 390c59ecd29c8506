// Driver sub-module of RecVision (ROS-free): every image source gives the
// processing sub-module the same Frame, an 8-bit RGB image with a time
// stamp. Sources: V4L2 cameras through OpenCV's VideoCapture, image files,
// and raw buffers as they arrive in sensor_msgs/Image (from a topic or a
// bag; the ROS layer hands over the fields, this file converts them).
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mrt::recvision {

/// One camera frame: `rgb` is CV_8UC3 in R, G, B order; `stamp` in seconds.
struct Frame {
  cv::Mat rgb;
  double stamp = 0.0;
  std::string frame_id;
};

/// Converts a raw image buffer (the fields of a sensor_msgs/Image) into a
/// Frame. Accepts the encodings "rgb8" and "bgr8" (converted); any other
/// encoding, a step shorter than a row or a buffer shorter than
/// `step * height` gives false and the reason in `why`.
bool frame_from_raw(const std::string& encoding, int width, int height, std::size_t step,
                    const std::uint8_t* data, std::size_t size, double stamp, Frame& out, std::string& why);

/// A source of frames.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// Next frame; false at the end (or when the device fails).
  virtual bool next(Frame& out) = 0;
};

/// Image files read in order (any format cv::imread reads); the stamp is
/// the file's position in the list (0, 1, 2, ...). A file that cannot be
/// read throws std::runtime_error naming it.
class ImageFileSource : public FrameSource {
 public:
  explicit ImageFileSource(std::vector<std::string> paths) : paths_(std::move(paths)) {}
  bool next(Frame& out) override;

 private:
  std::vector<std::string> paths_;
  std::size_t index_ = 0;
};

/// A V4L2 camera (device number or path such as /dev/video0) through
/// OpenCV's VideoCapture, asked for `width` x `height`; stamps are
/// monotonic seconds. A `device` that is a regular file is a recorded video
/// read through the same VideoCapture (FFmpeg), stamped with its frames'
/// positions in seconds. Throws std::runtime_error naming the device if it
/// cannot be opened.
class CameraSource : public FrameSource {
 public:
  CameraSource(const std::string& device, int width, int height);
  bool next(Frame& out) override;
  bool is_file() const { return file_; }

 private:
  cv::VideoCapture capture_;
  bool file_ = false;
};

}  // namespace mrt::recvision
