// sensor_msgs/Image -> Frame through cv_bridge (the ROS layer's half of the
// driver sub-module, shared by recvision_node and recvision_run's bags).
// Every encoding cv_bridge converts to rgb8 is accepted: rgb8, bgr8, rgba8,
// bgra8, mono8, mono16, the 16-bit colour ones, yuv422 and the Bayer
// patterns (debayered by cv_bridge with OpenCV's bilinear demosaicing).
// Mono images are replicated to three equal channels: they have no colour,
// so only the black and white classes of the look-up table can match.
#pragma once

#include <sensor_msgs/Image.h>

#include <string>

#include "mrt_recvision/frame.h"

namespace mrt::recvision::ros_layer {

enum class Decoded {
  kOk,           ///< `out.rgb` holds the image as rgb8
  kMalformed,    ///< empty image, a step shorter than a row or a buffer shorter than step * height
  kUnsupported,  ///< cv_bridge cannot convert the encoding to rgb8 (e.g. 32FC1, 8UC3, an unknown name)
};

/// Decodes `msg` into `out` (stamp and frame id from its header). For an
/// rgb8 message `out.rgb` shares the message's buffer (no copy): keep `msg`
/// alive while `out` is used. `colourless` tells a mono image (mono8,
/// mono16). On failure, `why` names the problem.
Decoded decode_image(const sensor_msgs::ImageConstPtr& msg, Frame& out, bool& colourless, std::string& why);

}  // namespace mrt::recvision::ros_layer
