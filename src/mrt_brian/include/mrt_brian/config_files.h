// The nine configuration files of a rule base (manual §10.4.11 plus the
// predicate-actions file) and their parsed content. A slot of a
// BrianConfigs.ini may name several files (whitespace-separated on its
// line): their definitions are concatenated, each keeping its own file.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"
#include "mrt_common/package_path.h"

namespace mrt::brian {

/// The nine slots, in BrianConfigs.ini (constructor) order.
enum class Slot { kCtof, kShapeCtof, kPredicates, kPredicateActions, kCando, kBehaviors, kWant, kSFtoc, kSShape };
inline constexpr std::size_t kSlotCount = 9;

struct ConfigFiles {
  /// The first (or only) file of each slot; "" for no predicate actions.
  std::string ctof, shape_ctof, predicates, predicate_actions, cando, behaviors, want, s_ftoc, s_shape;
  /// Further files of a slot, in order (indexed by Slot).
  std::array<std::vector<std::string>, kSlotCount> more;
  /// Directory relative behaviour paths resolve from (for every behaviour
  /// list of the slot: the directory of BrianConfigs.ini).
  std::string base_dir = ".";
  /// Where `package://<package>/<path>` names (in a BrianConfigs.ini and in
  /// behaviour lists) find their package; empty: ROS_PACKAGE_PATH
  /// (mrt_common/package_path.h).
  common::PackageFinder packages;

  const std::string& first(Slot s) const;
  std::string& first(Slot s);
  /// Every file of slot `s`: the first (unless empty), then `more`.
  std::vector<std::string> all(Slot s) const;

  /// Conventional names in `dir`: ctof.txt, shape_ctof.txt, Predicate.ini,
  /// PredicateActions.ini (optional), Cando.ini, behavior.txt|behaviour.txt,
  /// want.txt|Want.ini, s_ftoc.txt, s_shape.txt. Throws ParseError naming
  /// the missing file.
  static ConfigFiles from_directory(const std::string& dir);
  /// A BrianConfigs.ini: the nine slots one a line in constructor order (or
  /// the manual's eight, without PredicateActions), relative to its folder;
  /// a line may name several files separated by blanks (one slot, several
  /// files).
  static ConfigFiles from_list_file(const std::string& path, common::PackageFinder packages = {});
  /// Directory or list file.
  static ConfigFiles locate(const std::string& path, common::PackageFinder packages = {});
  /// `p` resolved against base_dir unless absolute; `package://<package>/...`
  /// in the package's directory. Throws std::invalid_argument naming the
  /// package when it cannot be found.
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

  /// Reads and parses all files, concatenating the files of a slot; throws
  /// mrt::common::ParseError at the first syntax error. Behaviour files whose extension is in `custom_extensions`
  /// are not rules files: they are only checked to exist (their rules stay
  /// empty) and are left to a BehaviorFactory.
  static ParsedConfig load(const ConfigFiles& files, const std::vector<std::string>& custom_extensions = {});
};

}  // namespace mrt::brian
