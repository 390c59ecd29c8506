#include "mrt_brian/brian.h"

#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "mrt_brian/rule_behavior.h"
#include "mrt_brian/validator.h"
#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;
namespace fs = std::filesystem;

namespace {
// The 2009 engine stored crisp data as float.
double as_float(double v) {
  volatile float f = static_cast<float>(v);
  return f;
}
}  // namespace

Profile parse_profile(const std::string& s) {
  if (s == "manual") return Profile::kManual;
  if (s == "legacy") return Profile::kLegacy;
  throw std::invalid_argument("profile must be 'manual' or 'legacy', got '" + s + "'");
}
WeightComposerKind parse_weight_composer(const std::string& s) {
  if (s == "mult") return WeightComposerKind::kMult;
  if (s == "max") return WeightComposerKind::kMax;
  if (s == "min") return WeightComposerKind::kMin;
  throw std::invalid_argument("weight composer must be 'mult', 'max' or 'min', got '" + s + "'");
}
FloatComposerKind parse_float_composer(const std::string& s) {
  if (s == "average") return FloatComposerKind::kAverage;
  if (s == "max") return FloatComposerKind::kMax;
  if (s == "min") return FloatComposerKind::kMin;
  if (s == "best") return FloatComposerKind::kSelectBest;
  throw std::invalid_argument("float composer must be 'average', 'max', 'min' or 'best', got '" + s + "'");
}
DefuzzMethod parse_defuzz_method(const std::string& s) {
  if (s == "singleton") return DefuzzMethod::kSingleton;
  if (s == "barycenter") return DefuzzMethod::kBarycenter;
  throw std::invalid_argument("defuzzification must be 'singleton' or 'barycenter', got '" + s + "'");
}

namespace {
std::vector<std::string> custom_extensions(const BrianOptions& o) {
  std::vector<std::string> out;
  for (const auto& kv : o.behavior_kinds) out.push_back(kv.first);
  return out;
}
}  // namespace

Brian::Brian(const ConfigFiles& files, const BrianOptions& options) : options_(options) {
  build(ParsedConfig::load(files, custom_extensions(options)));
}

Brian::Brian(const ParsedConfig& config, const BrianOptions& options) : options_(options) { build(config); }

Brian::Brian(const std::string& fuzzyassoc, const std::string& fuzzyshapes, const std::string& pries,
             const std::string& predicate_actions, const std::string& candoes, const std::string& behaviors,
             const std::string& wanters, const std::string& defuzzyassoc, const std::string& defuzzyshapes,
             const BrianOptions& options)
    : options_(options) {
  ConfigFiles f;
  f.ctof = fuzzyassoc;
  f.shape_ctof = fuzzyshapes;
  f.predicates = pries;
  f.predicate_actions = predicate_actions;
  f.cando = candoes;
  f.behaviors = behaviors;
  f.want = wanters;
  f.s_ftoc = defuzzyassoc;
  f.s_shape = defuzzyshapes;
  f.base_dir = ".";
  build(ParsedConfig::load(f, custom_extensions(options)));
}

std::unique_ptr<Brian> Brian::from_path(const std::string& path, const BrianOptions& options) {
  return std::make_unique<Brian>(ConfigFiles::locate(path, options.packages), options);
}

namespace {
// Does `e` read a predicate named in `names`?
bool reads_any(const ExprAst& e, const std::set<std::string>& names) {
  if (e.kind == ExprAst::kPredicate) return names.count(e.name) > 0;
  for (const auto& a : e.args)
    if (reads_any(a, names)) return true;
  return false;
}
}  // namespace

// The rules brian_check applies (validate()), for names: the manual profile
// refuses a rule base naming anything unknown, with brian_check's
// `file:line: message`; the legacy profile reads it as 0, as the 2009
// engine did, and warns once per name.
void Brian::check_names(const ParsedConfig& c) const {
  std::set<std::string> warned;
  for (const Diagnostic& d : validate(c)) {
    // A name defined in two files of one slot: refused by both profiles
    // (the 2009 engine read one file a slot; nothing legacy to keep).
    if (d.kind == Diagnostic::kDuplicate) throw ParseError(d.file, d.line, 0, d.message);
    if (d.kind != Diagnostic::kUnknownName) continue;
    if (options_.profile == Profile::kManual) throw ParseError(d.file, d.line, 0, d.message);
    if (!warned.insert(d.message).second) continue;
    if (options_.warn) options_.warn(d.str());
    else std::fprintf(stderr, "warning: %s\n", d.str().c_str());
  }
}

void Brian::build(const ParsedConfig& c) {
  check_names(c);
  const bool legacy = options_.profile == Profile::kLegacy;
  const ConfigFiles& files = c.files;
  fuzzyfier_ = Fuzzyfier(c.shapes, c.assocs, files.shape_ctof, files.ctof);
  defuzzyfier_ = Defuzzyfier(c.out_shapes, c.out_assocs, options_.defuzzification, options_.profile,
                             files.s_shape, files.s_ftoc);
  const FloatComposerKind fk =
      options_.float_composer.value_or(legacy ? FloatComposerKind::kMax : FloatComposerKind::kAverage);
  composer_ = Composer(options_.weight_composer, fk, defuzzyfier_.labels_per_action());
  composer_.set_skip_zero_weight(!legacy);

  for (const auto& d : c.predicates) predicate_names_.intern(d.name);
  for (const auto& d : c.predicate_actions) predicate_names_.intern(d.name);
  for (const auto& b : c.behaviors) {
    if (behavior_names_.find(b.name) >= 0)
      throw ParseError(b.file.empty() ? files.behaviors : b.file, b.line, b.column,
                       "behaviour '" + b.name + "' listed twice");
    behavior_names_.intern(b.name);
  }
  ExpressionCompiler compiler(fuzzyfier_, predicate_names_, behavior_names_, defuzzyfier_);
  build_conditions(c, compiler);
  build_behaviors(c, compiler);
  engine_.set_filter(std::make_unique<ThresholdFilter>(options_.threshold,
                                                       options_.threshold_reliability.value_or(legacy), legacy));
  want_filter_ = ThresholdFilter(options_.threshold, true, legacy);
  engine_.finalize(options_.profile);
  allocate_state(c);
}

void Brian::build_conditions(const ParsedConfig& c, const ExpressionCompiler& compiler) {
  DefinitionList preds, pacts, cando, want;
  for (const auto& d : c.predicates) preds.add(predicate_names_.find(d.name), compiler.compile(d.expr, pool_));
  for (const auto& d : c.predicate_actions) pacts.add(predicate_names_.find(d.name), compiler.compile(d.expr, pool_));
  auto behaviour_defs = [&](const std::vector<DefinitionDef>& defs, const std::string& file, const char* what,
                            DefinitionList& out) {
    for (const auto& d : defs) {
      const int id = behavior_names_.find(d.name);
      if (id < 0)
        throw ParseError(d.file.empty() ? file : d.file, d.line, d.column,
                         std::string(what) + " for behaviour '" + d.name + "', which is not in the behaviour list");
      out.add(id, compiler.compile(d.expr, pool_));
    }
  };
  behaviour_defs(c.cando, c.files.cando, "CANDO", cando);
  behaviour_defs(c.want, c.files.want, "WANT", want);
  preacher_ = Preacher(&pool_, preds);
  predicate_actions_ = Preacher(&pool_, pacts);
  candoer_ = Candoer(&pool_, cando);
  wanter_ = Wanter(&pool_, want);
  std::set<std::string> pact_names;
  for (const auto& d : c.predicate_actions) pact_names.insert(d.name);
  conditions_read_pacts_ = false;
  if (options_.profile == Profile::kManual)
    for (const auto* defs : {&c.cando, &c.want})
      for (const auto& d : *defs) conditions_read_pacts_ = conditions_read_pacts_ || reads_any(d.expr, pact_names);
}

void Brian::build_behaviors(const ParsedConfig& c, const ExpressionCompiler& compiler) {
  const ConfigFiles& files = c.files;
  for (std::size_t i = 0; i < c.behaviors.size(); ++i) {
    const BehaviorDef& b = c.behaviors[i];
    std::unique_ptr<Behavior> beh;
    const auto kind = options_.behavior_kinds.find(fs::path(c.behavior_files[i]).extension().string());
    if (kind != options_.behavior_kinds.end() && kind->second) {
      beh = kind->second(b, c.behavior_files[i], defuzzyfier_);
      if (!beh || beh->name() != b.name || beh->level() != b.level)
        throw ParseError(b.file.empty() ? files.behaviors : b.file, b.line, b.column,
                         "the factory for '" + kind->first + "' did not build behaviour '" + b.name + "' at its level");
    } else {
      beh = std::make_unique<RuleBehavior>(b.name, b.level, c.rules[i], c.behavior_files[i], compiler,
                                           defuzzyfier_, pool_);
    }
    if (options_.profile == Profile::kLegacy && b.level == 1 && beh->deletes())
      throw ParseError(b.file.empty() ? files.behaviors : b.file, b.line, b.column,
                       "behaviour '" + b.name + "' uses &DEL at level 1, where there is nothing to delete");
    engine_.add(std::move(beh));
  }
}

void Brian::allocate_state(const ParsedConfig& c) {
  const std::size_t nd = static_cast<std::size_t>(fuzzyfier_.datum_count());
  input_value_.assign(nd, 0.0);
  input_rel_.assign(nd, 1.0);
  input_present_.assign(nd, 0);
  state_.fuzzy.assign(static_cast<std::size_t>(fuzzyfier_.slot_count()), FuzzyValue{});
  state_.predicates.assign(static_cast<std::size_t>(predicate_names_.size()), FuzzyValue{});
  state_.proposals = &proposals_;
  const std::size_t nb = static_cast<std::size_t>(engine_.size());
  cando_.assign(nb, FuzzyValue{});
  want_.assign(nb, FuzzyValue{});
  scratch_cando_.assign(nb, FuzzyValue{});
  scratch_want_.assign(nb, FuzzyValue{});
  weights_.assign(nb, 0.0);
  scores_.assign(nb, 0.0);
  active_.assign(nb, 0);
  proposals_.reserve(engine_.max_proposals() + 16);
  composed_ = composer_.make_output();
  scratch_composed_ = composer_.make_output();
  const std::size_t na = static_cast<std::size_t>(defuzzyfier_.action_count());
  command_value_.assign(na, 0.0);
  command_has_.assign(na, 0);
  scratch_value_.assign(na, 0.0);
  scratch_has_.assign(na, 0);
  for (int a = 0; a < defuzzyfier_.action_count(); ++a)
    proposed_datum_.push_back(fuzzyfier_.datum_id("Proposed" + defuzzyfier_.action_name(a)));
  std::size_t rules = 0;
  for (const auto& r : c.rules) rules += r.size();
  fired_.reserve(rules);
  commands_.reserve(na);
  ctx_.pool = &pool_;
  ctx_.state = &state_;
  ctx_.proposals = &proposals_;
  ctx_.profile = options_.profile;
}

void Brian::clear_inputs() { std::fill(input_present_.begin(), input_present_.end(), 0); }

void Brian::set_input(int id, double value, double reliability) {
  if (id < 0 || id >= static_cast<int>(input_value_.size())) return;
  if (options_.profile == Profile::kLegacy) {  // the 2009 engine kept crisp data as float
    value = as_float(value);
    reliability = as_float(reliability);
  }
  input_value_[static_cast<std::size_t>(id)] = value;
  input_rel_[static_cast<std::size_t>(id)] = reliability;
  input_present_[static_cast<std::size_t>(id)] = 1;
}

bool Brian::command(int action, double* value) const {
  if (action < 0 || action >= static_cast<int>(command_has_.size()) || !command_has_[static_cast<std::size_t>(action)])
    return false;
  *value = command_value_[static_cast<std::size_t>(action)];
  return true;
}

void Brian::evaluate_predicate_actions(bool weighted) {
  composer_.compose(proposals_, weighted ? &weights_ : nullptr, scratch_composed_, &scores_);
  defuzzyfier_.defuzzify(scratch_composed_, scratch_value_, scratch_has_);
  for (std::size_t a = 0; a < proposed_datum_.size(); ++a) {
    const int d = proposed_datum_[a];
    if (d < 0) continue;
    const Shape& s = fuzzyfier_.shape_of(d);
    FuzzyValue* slots = state_.fuzzy.data() + fuzzyfier_.first_slot(d);
    for (int i = 0; i < s.size(); ++i) slots[i] = FuzzyValue{};
    if (scratch_has_[a]) fuzzyfier_.fuzzify(d, scratch_value_[a], 1.0, state_.fuzzy.data());
  }
  if (options_.profile == Profile::kLegacy) predicate_actions_.evaluate_joining(state_);
  else predicate_actions_.evaluate(state_);
}

void Brian::before_level(int level) {
  evaluate_predicate_actions(true);
  if (conditions_read_pacts_) reevaluate_conditions(level);
}

// Manual profile, §10.4.3: the CANDO and WANT of the behaviours of `level`
// are evaluated again now that the predicate actions hold what the lower
// levels propose (the engine reads the new CANDO when it reaches them).
void Brian::reevaluate_conditions(int level) {
  candoer_.evaluate(state_, scratch_cando_);
  wanter_.evaluate(state_, scratch_want_);
  for (int b = 0; b < engine_.size(); ++b) {
    if (engine_.behavior(b).level() != level) continue;
    const std::size_t i = static_cast<std::size_t>(b);
    cando_[i] = scratch_cando_[i];
    want_[i] = scratch_want_[i];
    weights_[i] = want_[i].value;
    scores_[i] = cando_[i].value * want_[i].value;
  }
}

void Brian::before_behavior(int /*behavior*/) {
  composer_.weight_in_place(proposals_, weights_);
  evaluate_predicate_actions(false);
}

void Brian::run_cycle(CycleTrace* trace) {
  const bool legacy = options_.profile == Profile::kLegacy;
  std::fill(state_.fuzzy.begin(), state_.fuzzy.end(), FuzzyValue{});
  for (std::size_t d = 0; d < input_present_.size(); ++d)
    if (input_present_[d])
      fuzzyfier_.fuzzify(static_cast<int>(d), input_value_[d], input_rel_[d], state_.fuzzy.data());
  std::fill(state_.predicates.begin(), state_.predicates.end(), FuzzyValue{});
  proposals_.clear();
  fired_.clear();
  preacher_.evaluate(state_);
  candoer_.evaluate(state_, cando_);
  wanter_.evaluate(state_, want_);
  // Legacy: the WANT filter uses the same threshold as the CANDO filter,
  // also after engine().set_threshold() at run time.
  if (legacy) want_filter_.set_threshold(engine_.threshold());
  for (std::size_t b = 0; b < want_.size(); ++b) {
    weights_[b] = legacy ? (want_filter_.active(want_[b]) ? want_[b].value : 0.0) : want_[b].value;
    scores_[b] = cando_[b].value * want_[b].value;  // eq. 10.5's mu_C * mu_W (select-best)
  }
  ctx_.fired = trace ? &fired_ : nullptr;
  engine_.run(cando_, ctx_, this, active_);
  if (legacy) {
    composer_.weight_in_place(proposals_, weights_);
    composer_.compose(proposals_, nullptr, composed_, &scores_);
  } else {
    composer_.compose(proposals_, &weights_, composed_, &scores_);
  }
  defuzzyfier_.defuzzify(composed_, command_value_, command_has_);
  if (trace) fill_trace(*trace);
}

const CommandList& Brian::run(const CrispDataList& crisp, CycleTrace* trace) {
  clear_inputs();
  for (const auto& c : crisp) set_input(input_id(c.name), c.value, c.reliability);
  run_cycle(trace);
  commands_.clear();
  for (int a = 0; a < defuzzyfier_.action_count(); ++a)
    if (command_has_[static_cast<std::size_t>(a)])
      commands_.push_back({defuzzyfier_.action_name(a), command_value_[static_cast<std::size_t>(a)]});
  if (trace) {
    trace->crisp = crisp;
    if (options_.profile == Profile::kLegacy)
      for (auto& c : trace->crisp) {
        c.value = as_float(c.value);
        c.reliability = as_float(c.reliability);
      }
  }
  return commands_;
}

void Brian::fill_trace(CycleTrace& t) const {
  const bool legacy = options_.profile == Profile::kLegacy;
  t.clear();
  for (int d = 0; d < fuzzyfier_.datum_count(); ++d) {
    if (!input_present_[static_cast<std::size_t>(d)]) continue;
    t.crisp.push_back({fuzzyfier_.datum_name(d), input_value_[static_cast<std::size_t>(d)],
                       input_rel_[static_cast<std::size_t>(d)]});
    const Shape& s = fuzzyfier_.shape_of(d);
    for (int i = 0; i < s.size(); ++i) {
      const FuzzyValue v = state_.fuzzy[static_cast<std::size_t>(fuzzyfier_.first_slot(d) + i)];
      if (v.stored()) t.fuzzy.push_back({fuzzyfier_.datum_name(d), s.set(i).label(), v});
    }
  }
  for (int p = 0; p < predicate_names_.size(); ++p)
    if (state_.predicates[static_cast<std::size_t>(p)].stored())
      t.predicates.push_back({predicate_names_.name(p), state_.predicates[static_cast<std::size_t>(p)]});
  for (int b = 0; b < engine_.size(); ++b) {
    const std::size_t i = static_cast<std::size_t>(b);
    if (cando_[i].stored()) t.cando.push_back({engine_.behavior(b).name(), cando_[i]});
    if (legacy ? want_filter_.active(want_[i]) : want_[i].stored())
      t.want.push_back({engine_.behavior(b).name(), want_[i]});
  }
  for (const auto& r : fired_) t.rules.push_back({engine_.behavior(r.behavior).name(), r.line, r.mu});
  for (const auto& p : proposals_) {
    const double mu = legacy ? p.value : composer_.weight(p.value, weights_[static_cast<std::size_t>(p.owner)]);
    t.proposals.push_back({defuzzyfier_.action_name(p.action), defuzzyfier_.label_name(p.action, p.label),
                           engine_.behavior(p.owner).name(), mu, p.reliability});
  }
  for (int a = 0; a < defuzzyfier_.action_count(); ++a)
    for (int l = 0; l < defuzzyfier_.label_count(a); ++l)
      if (composed_.present(a, l))
        t.actions.push_back({defuzzyfier_.action_name(a), defuzzyfier_.label_name(a, l), composed_.get(a, l)});
  for (int a = 0; a < defuzzyfier_.action_count(); ++a)
    if (command_has_[static_cast<std::size_t>(a)])
      t.commands.push_back({defuzzyfier_.action_name(a), command_value_[static_cast<std::size_t>(a)]});
}

}  // namespace mrt::brian
