// recvision_run --calib FILE (--bag B.bag [--topic T] | IMAGE...)
// Runs RecVision on a bag's sensor_msgs/Image messages or on image files and
// writes every percept on stdout in the stack's percept CSV format
// (mrt_common/percept_csv.h, what murea_localize reads):
//   stamp,class,color,distance,bearing,reliability
// (frame: the message's header stamp, or the image's position in the list;
// distance m and bearing rad in base_link, with the calibration's mount).
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Image.h>

#include <cstdio>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_common/percept_csv.h"
#include "mrt_recvision/detector.h"
#include "../src/ros/image_decode.h"

using namespace mrt::recvision;

namespace {

void write(double stamp, const std::vector<Detection>& dets) {
  char frame[32];
  std::snprintf(frame, sizeof frame, "%.6f", stamp);
  for (const Detection& d : dets) mrt::common::write_percept_csv_row(std::cout, frame, to_percept_object(d));
}

// The image topic to read: `topic`, or the bag's only sensor_msgs/Image topic.
std::string pick_topic(rosbag::Bag& bag, const std::string& topic) {
  if (!topic.empty()) return topic;
  std::set<std::string> images;
  rosbag::View all(bag);
  for (const rosbag::ConnectionInfo* c : all.getConnections())
    if (c->datatype == "sensor_msgs/Image") images.insert(c->topic);
  if (images.size() == 1) return *images.begin();
  std::string list;
  for (const auto& t : images) list += " " + t;
  throw std::invalid_argument(images.empty() ? "no sensor_msgs/Image topic in the bag"
                                             : "several image topics, choose one with --topic:" + list);
}

int run_bag(Detector& det, const std::string& path, const std::string& topic) {
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  const std::string t = pick_topic(bag, topic);
  rosbag::View view(bag, rosbag::TopicQuery(t));
  long frames = 0, dropped = 0;
  mrt::cli::Progress progress("recvision_run", view.size());
  for (const rosbag::MessageInstance& m : view) {
    progress.update(static_cast<double>(frames + dropped + 1));
    const auto img = m.instantiate<sensor_msgs::Image>();
    if (!img) continue;
    Frame f;
    std::string why;
    bool colourless = false;
    if (ros_layer::decode_image(img, f, colourless, why) != ros_layer::Decoded::kOk || !det.accepts(f, why)) {
      if (dropped++ == 0) std::cerr << "recvision_run: frame dropped: " << why << "\n";
      continue;
    }
    ++frames;
    write(f.stamp, det.process(f));
  }
  std::cerr << "recvision_run: " << frames << " frames from " << t << ", " << dropped << " dropped\n";
  return frames == 0 && dropped > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"RecVision on a bag or on image files: percepts as CSV (stamp,class,color,distance,bearing,reliability: the percept CSV murea_localize reads)",
               "recvision_run"};
  std::string calib, bag_path, topic;
  std::vector<std::string> images;
  app.add_option("--calib", calib, "calibration file (camera, colours, detector)")->required();
  auto* bag_opt = app.add_option("--bag", bag_path, "bag with sensor_msgs/Image messages");
  app.add_option("--topic", topic, "image topic in the bag (default: its only image topic)")->needs(bag_opt);
  auto* img_opt = app.add_option("images", images, "image files (PNG, JPEG, ...)");
  bag_opt->excludes(img_opt);
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  if (bag_path.empty() && images.empty()) {
    std::cerr << "recvision_run: give --bag B.bag or image files\nRun with --help for more information.\n";
    return mrt::cli::kUsageError;
  }
  try {
    Detector det(load_calibration(calib));
    mrt::common::write_percept_csv_header(std::cout);
    if (!bag_path.empty()) return run_bag(det, bag_path, topic);
    ImageFileSource src(images);
    Frame f;
    while (src.next(f)) {
      std::string why;
      if (!det.accepts(f, why)) {
        std::cerr << "recvision_run: " << f.frame_id << ": " << why << "\n";
        return 1;
      }
      write(f.stamp, det.process(f));
    }
  } catch (const mrt::common::ParseError& e) {
    std::cerr << "recvision_run: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "recvision_run: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
