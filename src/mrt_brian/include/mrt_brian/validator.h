// The rules a Mr. BRIAN rule base must follow beyond its grammar, written
// once and shared by the checker of §10.4.7 (brian_check) and the loaders
// (Brian): unknown shapes, data, labels, predicates, behaviours and actions,
// forward references, &DEL at level 1, level gaps, CANDO/WANT of undefined
// behaviours, duplicate definitions.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "mrt_brian/config_files.h"

namespace mrt::brian {

struct Diagnostic {
  /// kUnknownName: a name that resolves to nothing (the manual profile
  /// refuses to load, the legacy profile reads it as 0 and warns);
  /// kWarning: legal but almost certainly not what was meant;
  /// kDuplicate: a name defined in two files of one slot (a BrianConfigs.ini
  /// line naming several files), both places named; both profiles refuse it.
  enum Kind { kError, kUnknownName, kWarning, kDuplicate };
  std::string file;
  int line = 0;
  std::string message;
  Kind kind = kError;
  std::string str() const {
    return file + ":" + std::to_string(line) + ": " + (kind == kWarning ? "warning: " : "") + message;
  }
};

/// Every semantic problem of `config`, in file order. Files in `failed`
/// (not readable or not parsed) are not complete: what depends on them is
/// not reported, so that one mistake gives one diagnostic.
std::vector<Diagnostic> validate(const ParsedConfig& config, const std::set<std::string>& failed = {});

}  // namespace mrt::brian
