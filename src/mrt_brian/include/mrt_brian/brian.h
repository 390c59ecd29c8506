// The Brian facade (manual §10.2, §10.4.11): built from the nine files,
// run(crisp data) -> commands. Owns one of each module; each module is also
// usable on its own.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_brian/behavior_engine.h"
#include "mrt_brian/candoer.h"
#include "mrt_brian/composer.h"
#include "mrt_brian/config_files.h"
#include "mrt_brian/defuzzyfier.h"
#include "mrt_brian/expression.h"
#include "mrt_brian/expression_compiler.h"
#include "mrt_brian/fuzzyfier.h"
#include "mrt_brian/preacher.h"
#include "mrt_brian/symbol_table.h"
#include "mrt_brian/trace.h"
#include "mrt_brian/types.h"
#include "mrt_brian/wanter.h"

namespace mrt::brian {

/// Builds a behaviour of a kind other than rules (manual §10.3.6: "for a new
/// kind of behavior, you have to define a new child parser class") from its
/// behaviour-list entry and resolved file; actions are resolved through the
/// Defuzzyfier. Throw mrt::common::ParseError on a bad file.
using BehaviorFactory = std::function<std::unique_ptr<Behavior>(
    const BehaviorDef& entry, const std::string& path, const Defuzzyfier& defuzzyfier)>;

struct BrianOptions {
  Profile profile = Profile::kManual;
  /// CANDO threshold (also WANT in legacy).
  double threshold = 0.49;
  /// Threshold the reliability too (default: legacy yes, manual no).
  std::optional<bool> threshold_reliability;
  WeightComposerKind weight_composer = WeightComposerKind::kMult;
  /// Default: manual average, legacy max; kSelectBest: eq. 10.5.
  std::optional<FloatComposerKind> float_composer;
  DefuzzMethod defuzzification = DefuzzMethod::kSingleton;
  /// Other behaviour kinds, by file extension of the behaviour-list entry
  /// (e.g. ".const"); everything else is a rules file.
  std::map<std::string, BehaviorFactory> behavior_kinds;
  /// Where `package://` names of the rule base's files find their package
  /// (ConfigFiles::packages); empty: ROS_PACKAGE_PATH. Used by from_path().
  common::PackageFinder packages;
  /// Legacy profile: called once per unknown name (`file:line: message`,
  /// as brian_check prints it) while loading; default: standard error.
  std::function<void(const std::string&)> warn;
};

/// String forms used by the tools and the node ("manual", "legacy",
/// "mult", "max", "min", "average", "singleton", "barycenter"); throw
/// std::invalid_argument on anything else.
Profile parse_profile(const std::string& s);
WeightComposerKind parse_weight_composer(const std::string& s);
FloatComposerKind parse_float_composer(const std::string& s);
DefuzzMethod parse_defuzz_method(const std::string& s);

class Brian : private HierarchyObserver {
 public:
  /// Throws mrt::common::ParseError (file:line) on any configuration error.
  explicit Brian(const ConfigFiles& files, const BrianOptions& options = {});
  explicit Brian(const ParsedConfig& config, const BrianOptions& options = {});
  /// The manual's constructor plus the predicate-actions file.
  Brian(const std::string& fuzzyassoc, const std::string& fuzzyshapes, const std::string& pries,
        const std::string& predicate_actions, const std::string& candoes, const std::string& behaviors,
        const std::string& wanters, const std::string& defuzzyassoc, const std::string& defuzzyshapes,
        const BrianOptions& options = {});
  /// A directory (conventional names) or a BrianConfigs.ini.
  static std::unique_ptr<Brian> from_path(const std::string& path, const BrianOptions& options = {});
  Brian(const Brian&) = delete;
  Brian& operator=(const Brian&) = delete;

  /// One perception-action cycle. Crisp data not associated in ctof are
  /// ignored. With `trace`, fills it.
  const CommandList& run(const CrispDataList& crisp, CycleTrace* trace = nullptr);

  // Allocation-free interface for tight loops.
  int input_id(const std::string& name) const { return fuzzyfier_.datum_id(name); }
  void clear_inputs();
  void set_input(int id, double value, double reliability = 1.0);
  void run_cycle(CycleTrace* trace = nullptr);
  /// Command of action `action` after run_cycle (false: none this cycle).
  bool command(int action, double* value) const;

  const BrianOptions& options() const { return options_; }
  const Fuzzyfier& fuzzyfier() const { return fuzzyfier_; }
  const Defuzzyfier& defuzzyfier() const { return defuzzyfier_; }
  const BehaviorEngine& engine() const { return engine_; }
  BehaviorEngine& engine() { return engine_; }
  const SymbolTable& predicates() const { return predicate_names_; }
  /// Last cycle's values per behaviour id (for introspection).
  const std::vector<FuzzyValue>& cando() const { return cando_; }
  const std::vector<FuzzyValue>& want() const { return want_; }
  const std::vector<double>& weights() const { return weights_; }
  const std::vector<std::uint8_t>& active() const { return active_; }
  const ProposalList& proposals() const { return proposals_; }
  const EvalState& state() const { return state_; }

 private:
  void build(const ParsedConfig& config);
  void check_names(const ParsedConfig& config) const;
  void build_conditions(const ParsedConfig& config, const ExpressionCompiler& compiler);
  void build_behaviors(const ParsedConfig& config, const ExpressionCompiler& compiler);
  void allocate_state(const ParsedConfig& config);
  void reevaluate_conditions(int level);
  void before_level(int level) override;
  void before_behavior(int behavior) override;
  void evaluate_predicate_actions(bool weighted);
  void fill_trace(CycleTrace& t) const;

  BrianOptions options_;
  Fuzzyfier fuzzyfier_;
  Defuzzyfier defuzzyfier_;
  Composer composer_;
  SymbolTable predicate_names_;
  SymbolTable behavior_names_;
  ExpressionPool pool_;
  Preacher preacher_, predicate_actions_;
  Candoer candoer_;
  Wanter wanter_;
  BehaviorEngine engine_;
  ThresholdFilter want_filter_;  // legacy: the WANT filter
  // Manual: CANDO/WANT conditions reading predicate actions (§10.4.3) are
  // evaluated again before each level above the first.
  bool conditions_read_pacts_ = false;
  std::vector<FuzzyValue> scratch_cando_, scratch_want_;

  // Per-cycle state, allocated once.
  std::vector<double> input_value_, input_rel_;
  std::vector<std::uint8_t> input_present_;
  EvalState state_;
  std::vector<FuzzyValue> cando_, want_;
  std::vector<double> weights_;
  std::vector<double> scores_;  // CANDO x WANT per behaviour (select-best)
  std::vector<std::uint8_t> active_;
  ProposalList proposals_;
  ComposedActions composed_, scratch_composed_;
  std::vector<double> command_value_, scratch_value_;
  std::vector<std::uint8_t> command_has_, scratch_has_;
  std::vector<int> proposed_datum_;  // per action: datum id of Proposed<Action>, or -1
  std::vector<RuleFiring> fired_;
  CommandList commands_;
  BehaviorContext ctx_;
};

}  // namespace mrt::brian
