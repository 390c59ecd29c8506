// Default file locations of the team session (source tree or install
// space, given by the build) and the --world convenience: a match file
// passed as --world means "that match on the MSL field world".
// ROS-free.
#pragma once

#include <string>

#include "mrt_robocup/team_session.h"

namespace mrt::robocup {

/// Options with the package's defaults under `package_root` (config/...,
/// the match config/msl_match.yaml among them) and the field of mrt_world's
/// worlds under `worlds` (msl_field.yaml).
TeamSessionOptions default_session_options(const std::string& package_root, const std::string& worlds);

/// If `o.world` is a match file (it has `opponents` or `referee` and no
/// `robots`), it becomes o.match and the world `field_world`. Throws
/// mrt::common::ParseError when the file does not parse.
void resolve_world_or_match(TeamSessionOptions& o, const std::string& field_world);

}  // namespace mrt::robocup
