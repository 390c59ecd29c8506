// The rule-base checker of manual §10.4.7 (brian_check): reads every file of
// a configuration and reports every problem it finds as `file:line: message`
// instead of stopping at the first one.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_files.h"

namespace mrt::brian {

struct Diagnostic {
  std::string file;
  int line = 0;
  std::string message;
  std::string str() const { return file + ":" + std::to_string(line) + ": " + message; }
};

class Checker {
 public:
  /// Syntax errors, unknown shapes, data, labels, predicates, behaviours and
  /// actions, forward references, &DEL at level 1, level gaps, CANDO/WANT of
  /// undefined behaviours, missing files.
  std::vector<Diagnostic> check(const ConfigFiles& files) const;
  /// A directory or a BrianConfigs.ini; a list file that cannot be read is
  /// itself reported.
  std::vector<Diagnostic> check_path(const std::string& path) const;
};

}  // namespace mrt::brian
