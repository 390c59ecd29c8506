// The world file (YAML) loader: every error names file:line:column (the
// strict readers of mrt_common/yaml_reader.h). Format: mrt_world/README.md.
//
// One world file describes the environment and, optionally, a simulation
// in it: the simulation sections (seed, ball, movers, robots, floor_color,
// surfaces) are read by the simulator (mrt_sim's load_world) and skipped
// here, so the same file is both the map MUREA and SPIKE load and the
// world mrt_sim steps.
#pragma once

#include <string>

#include "mrt_common/yaml_reader.h"
#include "mrt_world/world.h"

namespace mrt::world {

/// Reads the static sections of a parsed world file's top-level map; other
/// keys are refused unless they are simulation keys. Throws ParseError.
World read_world(const mrt::common::YamlReader& reader, const YAML::Node& root);

/// Loads the static world from a world file (a simulator's world file
/// included: its simulation sections are skipped). Throws ParseError.
World load_world(const std::string& path);

/// Same, from YAML text; `file` names it in errors.
World parse_world(const std::string& yaml_text, const std::string& file);

}  // namespace mrt::world
