#include "mrt_scare/crisp_builder.h"

#include <algorithm>
#include <limits>

#include "mrt_common/angle.h"

namespace mrt::scare {

std::vector<Crisp> build_crisp(const CrispInputs& in) {
  std::vector<Crisp> out;
  out.push_back({"Status", in.mode == Mode::kAuto ? 1.0 : 0.0, 1.0});
  out.push_back({"HaveGoal", in.goal ? 1.0 : 0.0, 1.0});
  if (in.goal) {
    out.push_back({"GoalDistance", in.goal->distance_cm, 1.0});
    out.push_back({"GoalBearing", in.goal->bearing_deg, 1.0});
  }
  const double inf = std::numeric_limits<double>::infinity();
  double left = inf, right = inf;
  for (std::size_t i = 0; i < in.sector_names.size() && i < in.sector_distances.size(); ++i) {
    const std::string& n = in.sector_names[i];
    const double cm = 100.0 * in.sector_distances[i];
    out.push_back({n, cm, 1.0});
    if (n == "ObstacleFrontLeft" || n == "ObstacleLeft") left = std::min(left, cm);
    if (n == "ObstacleFrontRight" || n == "ObstacleRight") right = std::min(right, cm);
  }
  if (left < inf && right < inf) out.push_back({"FreeSide", left - right, 1.0});
  const RemoteCommand r = in.remote.value_or(RemoteCommand{});
  out.push_back({"RemoteSpeed", 100.0 * r.speed, 1.0});
  out.push_back({"RemoteTurn", common::rad_to_deg(r.turn), 1.0});
  out.push_back({"LastSpeed", in.last_speed_cm, 1.0});
  out.push_back({"LastJog", in.last_jog_deg, 1.0});
  return out;
}

}  // namespace mrt::scare
