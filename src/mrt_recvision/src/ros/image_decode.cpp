#include "image_decode.h"

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

#include <cstddef>
#include <exception>

namespace mrt::recvision::ros_layer {

namespace enc = sensor_msgs::image_encodings;

Decoded decode_image(const sensor_msgs::ImageConstPtr& msg, Frame& out, bool& colourless, std::string& why) {
  // Checked before cv_bridge wraps the buffer: it trusts step and height.
  std::size_t bytes_per_pixel = 0;
  try {
    bytes_per_pixel = std::size_t(enc::numChannels(msg->encoding)) * std::size_t(enc::bitDepth(msg->encoding)) / 8;
  } catch (const std::exception&) {
    why = "unknown encoding '" + msg->encoding + "'";
    return Decoded::kUnsupported;
  }
  if (msg->width == 0 || msg->height == 0 || msg->step < std::size_t(msg->width) * bytes_per_pixel ||
      msg->data.size() < std::size_t(msg->step) * msg->height) {
    why = "inconsistent size " + std::to_string(msg->width) + "x" + std::to_string(msg->height) + " " +
          msg->encoding + " step " + std::to_string(msg->step) + " with " + std::to_string(msg->data.size()) +
          " bytes";
    return Decoded::kMalformed;
  }
  try {
    const cv_bridge::CvImageConstPtr cv = cv_bridge::toCvShare(msg, enc::RGB8);
    out.rgb = cv->image;  // shares the message's buffer for rgb8, else cv_bridge's converted copy
  } catch (const std::exception& e) {  // cv_bridge::Exception and cv::Exception
    why = "encoding '" + msg->encoding + "' not convertible to rgb8 (" + e.what() + ")";
    return Decoded::kUnsupported;
  }
  colourless = enc::isMono(msg->encoding);
  out.stamp = msg->header.stamp.toSec();
  out.frame_id = msg->header.frame_id;
  return Decoded::kOk;
}

}  // namespace mrt::recvision::ros_layer
