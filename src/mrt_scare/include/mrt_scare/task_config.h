// The sequencer's YAML configuration (tasks and their conditions). ROS-free.
#pragma once

#include <string>

#include "mrt_scare/sequencer.h"

namespace mrt::scare {

/// Parses the YAML text of a task file (format in the README). Throws
/// mrt::common::ParseError naming `file`, line and column on any error,
/// including unknown keys.
SequencerOptions parse_sequencer_options(const std::string& yaml_text, const std::string& file);
/// Reads and parses a task file (regular files up to 1 MiB).
SequencerOptions load_sequencer_options(const std::string& path);

}  // namespace mrt::scare
