// The rule-base checker of manual §10.4.7 (brian_check): reads every file of
// a configuration and reports every problem it finds as `file:line: message`
// instead of stopping at the first one.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_files.h"
#include "mrt_brian/validator.h"

namespace mrt::brian {

class Checker {
 public:
  /// Syntax errors, missing files and block comments that swallow a
  /// definition or rule (warnings), then validate()'s rules (the ones the
  /// loaders apply): unknown shapes, data, labels, predicates, behaviours
  /// and actions, forward references, &DEL at level 1, level gaps,
  /// CANDO/WANT of undefined behaviours, duplicates.
  std::vector<Diagnostic> check(const ConfigFiles& files) const;
  /// A directory or a BrianConfigs.ini; a list file that cannot be read is
  /// itself reported.
  std::vector<Diagnostic> check_path(const std::string& path) const;
};

}  // namespace mrt::brian
