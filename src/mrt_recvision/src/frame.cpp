#include "mrt_recvision/frame.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <filesystem>
#include <stdexcept>

namespace mrt::recvision {

bool frame_from_raw(const std::string& encoding, int width, int height, std::size_t step,
                    const std::uint8_t* data, std::size_t size, double stamp, Frame& out, std::string& why) {
  if (encoding != "rgb8" && encoding != "bgr8") {
    why = "encoding '" + encoding + "' (expected rgb8 or bgr8)";
    return false;
  }
  if (width <= 0 || height <= 0 || step < static_cast<std::size_t>(width) * 3 ||
      size < step * static_cast<std::size_t>(height) || data == nullptr) {
    why = "inconsistent size " + std::to_string(width) + "x" + std::to_string(height) + " step " +
          std::to_string(step) + " with " + std::to_string(size) + " bytes";
    return false;
  }
  // Wrap the buffer, then copy (or convert) into memory the frame owns.
  const cv::Mat view(height, width, CV_8UC3, const_cast<std::uint8_t*>(data), step);
  if (encoding == "rgb8")
    view.copyTo(out.rgb);
  else
    cv::cvtColor(view, out.rgb, cv::COLOR_BGR2RGB);
  out.stamp = stamp;
  return true;
}

bool ImageFileSource::next(Frame& out) {
  if (index_ >= paths_.size()) return false;
  const std::string& p = paths_[index_];
  const cv::Mat bgr = cv::imread(p, cv::IMREAD_COLOR);
  if (bgr.empty()) throw std::runtime_error(p + ": cannot read image");
  cv::cvtColor(bgr, out.rgb, cv::COLOR_BGR2RGB);
  out.stamp = static_cast<double>(index_);
  out.frame_id = p;
  ++index_;
  return true;
}

CameraSource::CameraSource(const std::string& device, int width, int height) {
  std::error_code ec;
  file_ = std::filesystem::is_regular_file(device, ec);
  const bool numeric = !device.empty() && device.find_first_not_of("0123456789") == std::string::npos;
  bool ok = false;
  if (file_)
    ok = capture_.open(device, cv::CAP_ANY);
  else
    ok = numeric ? capture_.open(std::stoi(device), cv::CAP_V4L2) : capture_.open(device, cv::CAP_V4L2);
  if (!ok) throw std::runtime_error(device + (file_ ? ": cannot read video" : ": cannot open camera (V4L2)"));
  if (!file_) {
    capture_.set(cv::CAP_PROP_FRAME_WIDTH, width);
    capture_.set(cv::CAP_PROP_FRAME_HEIGHT, height);
  }
}

bool CameraSource::next(Frame& out) {
  cv::Mat bgr;
  if (!capture_.read(bgr) || bgr.empty()) return false;
  cv::cvtColor(bgr, out.rgb, cv::COLOR_BGR2RGB);
  out.stamp = file_ ? capture_.get(cv::CAP_PROP_POS_MSEC) / 1000.0
                    : std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  return true;
}

}  // namespace mrt::recvision
