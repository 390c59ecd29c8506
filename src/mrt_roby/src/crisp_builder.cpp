#include "mrt_roby/crisp_builder.h"

#include <algorithm>
#include <limits>

#include "mrt_common/angle.h"

namespace mrt::roby {

void goal_crisp_data(Mode mode, const std::optional<GoalCrisp>& goal, CrispDataList& out) {
  out.push_back({"Status", mode == Mode::kAuto ? 1.0 : 0.0, 1.0});
  out.push_back({"HaveGoal", goal ? 1.0 : 0.0, 1.0});
  if (goal) {
    out.push_back({"GoalDistance", goal->distance_cm, 1.0});
    out.push_back({"GoalBearing", goal->bearing_deg, 1.0});
  }
}

void remote_crisp_data(const std::optional<RemoteCommand>& remote, CrispDataList& out) {
  const RemoteCommand r = remote.value_or(RemoteCommand{});
  out.push_back({"RemoteSpeed", 100.0 * r.speed, 1.0});
  out.push_back({"RemoteTurn", common::rad_to_deg(r.turn), 1.0});
}

void sonar_crisp_data(const std::vector<std::string>& sector_names, const std::vector<double>& sector_distances,
                      CrispDataList& out) {
  const double inf = std::numeric_limits<double>::infinity();
  double left = inf, right = inf;
  for (std::size_t i = 0; i < sector_names.size() && i < sector_distances.size(); ++i) {
    const std::string& n = sector_names[i];
    const double cm = 100.0 * sector_distances[i];
    out.push_back({n, cm, 1.0});
    if (n == "ObstacleFrontLeft" || n == "ObstacleLeft") left = std::min(left, cm);
    if (n == "ObstacleFrontRight" || n == "ObstacleRight") right = std::min(right, cm);
  }
  if (left < inf && right < inf) out.push_back({"FreeSide", left - right, 1.0});
}

void feedback_crisp_data(double last_speed_cm, double last_jog_deg, CrispDataList& out) {
  out.push_back({"LastSpeed", last_speed_cm, 1.0});
  out.push_back({"LastJog", last_jog_deg, 1.0});
}

CrispDataList build_crisp(const CrispInputs& in) {
  CrispDataList out;
  goal_crisp_data(in.mode, in.goal, out);
  sonar_crisp_data(in.sector_names, in.sector_distances, out);
  remote_crisp_data(in.remote, out);
  feedback_crisp_data(in.last_speed_cm, in.last_jog_deg, out);
  return out;
}

}  // namespace mrt::roby
