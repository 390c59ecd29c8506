// The tour dialogue in rviz (both bringups): a ring on each exhibit; click
// exhibits to choose them in order, then "Start this tour" from any
// exhibit's menu (or "Clear the choice"). The choice goes to `start`, which
// returns "" when the tour is taken, else why it is refused.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <interactive_markers/interactive_marker_server.h>
#include <interactive_markers/menu_handler.h>
#include <ros/ros.h>

namespace mrt::followme::node {

struct ExhibitRing {
  std::string name;
  double x = 0.0, y = 0.0, radius = 0.3;
};

class TourMarkers {
 public:
  using Start = std::function<std::string(const std::vector<std::string>&)>;
  /// `topic_ns`: the server's topics (`<topic_ns>/update`, ...; rviz's
  /// followme.rviz listens on /tour).
  TourMarkers(const std::vector<ExhibitRing>& exhibits, const std::string& frame, Start on_start,
              const std::string& topic_ns = "tour")
      : start_fn_(std::move(on_start)), server_(topic_ns) {
    menu_.insert("Start this tour", [this](const auto&) { start(); });
    menu_.insert("Clear the choice", [this](const auto&) { chosen_.clear(); });
    for (const auto& e : exhibits) {
      visualization_msgs::InteractiveMarker im;
      im.header.frame_id = frame;
      im.name = e.name;
      im.description = e.name + " (click: add to the tour)";
      im.pose.position.x = e.x;
      im.pose.position.y = e.y;
      im.pose.orientation.w = 1.0;
      im.scale = 1.0;
      visualization_msgs::InteractiveMarkerControl c;
      c.interaction_mode = visualization_msgs::InteractiveMarkerControl::BUTTON;
      c.always_visible = true;
      visualization_msgs::Marker m;
      m.type = visualization_msgs::Marker::CYLINDER;
      m.scale.x = m.scale.y = 2 * e.radius + 0.2;
      m.scale.z = 0.05;
      m.color.r = 1.0;
      m.color.g = 0.8;
      m.color.a = 0.5;
      m.pose.orientation.w = 1.0;
      c.markers.push_back(m);
      im.controls.push_back(c);
      server_.insert(im, [this](const auto& fb) {
        if (fb->event_type == visualization_msgs::InteractiveMarkerFeedback::BUTTON_CLICK) {
          chosen_.push_back(fb->marker_name);
          ROS_INFO("tour choice: %zu exhibits, last %s", chosen_.size(), fb->marker_name.c_str());
        }
      });
      menu_.apply(server_, e.name);
    }
    server_.applyChanges();
  }

 private:
  void start() {
    const std::string bad = start_fn_(chosen_);
    if (bad.empty()) {
      ROS_INFO("new tour of %zu exhibits", chosen_.size());
    } else {
      ROS_WARN("tour refused: %s", bad.c_str());
    }
    chosen_.clear();
  }

  Start start_fn_;
  interactive_markers::InteractiveMarkerServer server_;
  interactive_markers::MenuHandler menu_;
  std::vector<std::string> chosen_;
};

}  // namespace mrt::followme::node
