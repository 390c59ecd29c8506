// MAP as one object: Classifier -> Merger -> Tracker on one robot's
// percepts and its teammates' anchors, SCARE's coordination parameters, and
// the crisp data Mr. BRIAN reads (manual chapter 8 and §2.3.3). ROS-free.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mrt_map/classifier.h"
#include "mrt_map/conceptual_model.h"
#include "mrt_map/merger.h"
#include "mrt_map/tracker.h"

namespace mrt::map {

struct WorldModelOptions {
  std::string robot = "robot";
  double max_percept_age = 0.5;  // s; older (or that far in the future) is stale
};

struct CrispDatum {
  std::string name;
  double value = 0.0;
  double reliability = 0.0;
};

/// What was dropped, by reason (diagnostics).
struct DropCounters {
  std::uint64_t accepted = 0, unknown_class = 0, non_finite = 0, no_position = 0, unmatched = 0, stale = 0,
                stale_team = 0, outside_world = 0;  // outside_world: own or teammates' (model `world:`)
};

class WorldModel {
 public:
  WorldModel(const ConceptualModel& model, WorldModelOptions options);

  /// The robot's own pose (for crisp distances and bearings and to tell
  /// teammates where it is).
  void set_robot_pose(const RobotPose& pose, double stamp);
  const RobotPose& robot_pose() const { return pose_; }

  /// One percept of sensor `sensor`, seen from `pose` at `stamp`, received
  /// at `now`: classified and queued for the next update. A stale percept
  /// is dropped whole; a bad object alone. Returns the objects accepted.
  int add_percept(const std::vector<PerceptObject>& objects, const RobotPose& pose, double stamp, double now,
                  const std::string& sensor);

  /// A teammate's latest model (its own anchors, see Tracker::local_tracks)
  /// and its pose; replaces the previous one of that teammate.
  void add_teammate_model(const std::string& robot, const std::vector<RemoteTrack>& tracks, double stamp,
                          const RobotPose* pose = nullptr);

  /// One cycle at `now`: Merger, latency compensation, Tracker.
  void update(double now);

  /// SCARE writes a coordination parameter into the model.
  void set_parameter(const std::string& name, double value, double reliability, double stamp);
  const std::map<std::string, CrispDatum>& parameters() const { return parameters_; }

  /// The crisp data of the model's `crisp` list at `now`.
  std::vector<CrispDatum> crisp(double now) const;

  const ConceptualModel& model() const { return model_; }
  const Tracker& tracker() const { return tracker_; }
  std::vector<RemoteTrack> local_tracks() const { return tracker_.local_tracks(options_.robot); }
  const DropCounters& counters() const { return counters_; }
  const WorldModelOptions& options() const { return options_; }

 private:
  struct TeammateModel {
    std::vector<RemoteTrack> tracks;
    double stamp = 0.0;
  };
  double quantity(const CrispEntry& e, const Anchor& a) const;

  const ConceptualModel& model_;
  WorldModelOptions options_;
  Classifier classifier_;
  Merger merger_;
  Tracker tracker_;
  RobotPose pose_;
  std::vector<Observation> pending_;
  std::map<std::string, TeammateModel> teammates_;
  std::map<std::string, CrispDatum> parameters_;
  DropCounters counters_;
};

}  // namespace mrt::map
