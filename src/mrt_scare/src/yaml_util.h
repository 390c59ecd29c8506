// Strict YAML reading for the task and map loaders (private header): the
// shared reader of mrt_common, files capped at 1 MiB.
#pragma once

#include <string>

#include "mrt_common/yaml_reader.h"

namespace mrt::scare::detail {

using common::YamlReader;

inline std::string read_file(const std::string& path) {
  return common::read_file(path, "cannot open file", 1 << 20);
}

}  // namespace mrt::scare::detail
