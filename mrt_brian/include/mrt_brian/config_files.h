// The nine configuration files of a rule base (manual §10.4.11 plus the
// predicate-actions file) and their parsed content.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"

namespace mrt::brian {

struct ConfigFiles {
  std::string ctof, shape_ctof, predicates, predicate_actions, cando, behaviors, want, s_ftoc, s_shape;
  /// Directory relative behaviour paths resolve from.
  std::string base_dir = ".";

  /// Conventional names in `dir`: ctof.txt, shape_ctof.txt, Predicate.ini,
  /// PredicateActions.ini (optional), Cando.ini, behavior.txt|behaviour.txt,
  /// want.txt|Want.ini, s_ftoc.txt, s_shape.txt. Throws ParseError naming
  /// the missing file.
  static ConfigFiles from_directory(const std::string& dir);
  /// A BrianConfigs.ini: the nine files one a line in constructor order (or
  /// the manual's eight, without PredicateActions), relative to its folder.
  static ConfigFiles from_list_file(const std::string& path);
  /// Directory or list file.
  static ConfigFiles locate(const std::string& path);
  /// `p` resolved against base_dir unless absolute.
  std::string resolve(const std::string& p) const;
};

/// Every file of a rule base, parsed (names unresolved).
struct ParsedConfig {
  ConfigFiles files;
  std::vector<ShapeDef> shapes, out_shapes;
  std::vector<AssociationDef> assocs, out_assocs;
  std::vector<DefinitionDef> predicates, predicate_actions, cando, want;
  std::vector<BehaviorDef> behaviors;
  std::vector<std::string> behavior_files;  // resolved paths
  std::vector<std::vector<RuleDef>> rules;  // per behaviour

  /// Reads and parses all files; throws mrt::common::ParseError at the first
  /// syntax error. Behaviour files whose extension is in `custom_extensions`
  /// are not rules files: they are only checked to exist (their rules stay
  /// empty) and are left to a BehaviorFactory.
  static ParsedConfig load(const ConfigFiles& files, const std::vector<std::string>& custom_extensions = {});
};

}  // namespace mrt::brian
