#include "mrt_brian/validator.h"

#include <map>

namespace mrt::brian {

namespace {

using Kind = Diagnostic::Kind;

struct Shapes {
  std::map<std::string, std::set<std::string>> labels;  // shape -> labels
};

// Data or actions: name -> labels of its shape. A name whose shape is
// unknown is `opaque` (its labels are not checked again); when the
// association file or its shape file did not parse, the table is not
// `complete` and unknown names are not reported either: one mistake, one
// diagnostic.
struct Names {
  std::map<std::string, std::set<std::string>> labels;
  std::set<std::string> opaque;
  bool complete = true;
  bool unknown_name(const std::string& name) const { return complete && !labels.count(name); }
  bool unknown_label(const std::string& name, const std::string& label) const {
    auto it = labels.find(name);
    return it != labels.end() && !opaque.count(name) && !it->second.count(label);
  }
};

class Validation {
 public:
  Validation(const ParsedConfig& c, const std::set<std::string>& failed) : c_(c), f_(c.files), failed_(failed) {}
  std::vector<Diagnostic> run();

 private:
  // Where a predicate is defined: file 0 = Predicate.ini, 1 = PredicateActions.ini.
  struct Where { int file; int line; };
  static constexpr int kRules = -1;  // file index of an expression in a rule

  bool ok(const std::string& file) const { return !failed_.count(file); }
  void report(const std::string& file, int line, const std::string& msg, Kind kind = Diagnostic::kError) {
    out_.push_back({file, line, msg, kind});
  }
  Shapes collect_shapes(const std::vector<ShapeDef>& defs, const std::string& file);
  Names collect_assocs(const std::vector<AssociationDef>& defs, const Shapes& shapes, bool shapes_ok,
                       const std::string& file, const char* what);
  void behaviours();
  void define(const std::vector<DefinitionDef>& defs, int index, const std::string& file);
  void expr(const ExprAst& e, const std::string& file, int file_index, int def_line);
  void predicate(const ExprAst& e, const std::string& file, int file_index, int def_line);
  void proposal(const ExprAst& e, const std::string& file);
  void conditions(const std::vector<DefinitionDef>& defs, const std::string& file, const char* what);
  void rules();

  const ParsedConfig& c_;
  const ConfigFiles& f_;
  const std::set<std::string>& failed_;
  std::vector<Diagnostic> out_;
  Names data_, actions_;
  std::map<std::string, int> level_of_;
  std::map<std::string, Where> defined_;
  bool behaviors_ok_ = true, predicates_ok_ = true;
};

Shapes Validation::collect_shapes(const std::vector<ShapeDef>& defs, const std::string& file) {
  Shapes s;
  for (const auto& d : defs) {
    if (s.labels.count(d.name)) {  // the engine refuses it; its labels are not checked
      report(file, d.line, "shape '" + d.name + "' defined twice");
      continue;
    }
    auto& l = s.labels[d.name];
    for (const auto& set : d.sets) {
      if (l.count(set.label)) report(file, set.line, "label '" + set.label + "' defined twice in shape '" + d.name + "'");
      l.insert(set.label);
    }
  }
  return s;
}

Names Validation::collect_assocs(const std::vector<AssociationDef>& defs, const Shapes& shapes, bool shapes_ok,
                                 const std::string& file, const char* what) {
  Names out;
  out.complete = ok(file);
  std::map<std::string, int> first;
  for (const auto& a : defs) {
    if (!first.emplace(a.name, a.line).second)
      report(file, a.line, std::string(what) + " '" + a.name + "' associated twice (first at line " +
                               std::to_string(first[a.name]) + ")");
    auto it = shapes.labels.find(a.shape);
    if (it == shapes.labels.end()) {
      if (shapes_ok) report(file, a.line, "unknown shape '" + a.shape + "' for " + what + " '" + a.name + "'");
      out.labels[a.name];
      out.opaque.insert(a.name);
      continue;
    }
    out.labels[a.name] = it->second;
    out.opaque.erase(a.name);
  }
  return out;
}

void Validation::behaviours() {
  std::map<int, int> first_line_of_level;
  for (const auto& b : c_.behaviors) {
    if (level_of_.count(b.name)) report(f_.behaviors, b.line, "behaviour '" + b.name + "' listed twice");
    level_of_[b.name] = b.level;
    if (!first_line_of_level.count(b.level)) first_line_of_level[b.level] = b.line;
  }
  int expected = 1;
  for (const auto& [level, line] : first_line_of_level) {
    if (level != expected)
      report(f_.behaviors, line,
             "level gap: level " + std::to_string(level) + " used but level " + std::to_string(expected) +
                 " has no behaviour");
    expected = level + 1;
  }
}

void Validation::define(const std::vector<DefinitionDef>& defs, int index, const std::string& file) {
  for (const auto& d : defs) {
    auto [it, fresh] = defined_.emplace(d.name, Where{index, d.line});
    if (!fresh)
      report(file, d.line, "predicate '" + d.name + "' defined twice (first at " +
                               (it->second.file == 0 ? f_.predicates : f_.predicate_actions) + ":" +
                               std::to_string(it->second.line) + ")");
  }
}

// `file_index`/`def_line`: position of the definition being checked (for
// forward references): 0 or 1 in the predicate files, kRules in rules, and
// kConditions in CANDO/WANT (which may read predicate actions, §10.4.3).
void Validation::expr(const ExprAst& e, const std::string& file, int file_index, int def_line) {
  switch (e.kind) {
    case ExprAst::kAnd:
    case ExprAst::kOr:
    case ExprAst::kNot:
      for (const auto& a : e.args) expr(a, file, file_index, def_line);
      break;
    case ExprAst::kDatum:
      if (data_.unknown_name(e.name))
        report(file, e.line, "unknown datum '" + e.name + "' (not in " + f_.ctof + ")", Diagnostic::kUnknownName);
      else if (data_.unknown_label(e.name, e.label))
        report(file, e.line, "unknown label '" + e.label + "' of datum '" + e.name + "'", Diagnostic::kUnknownName);
      break;
    case ExprAst::kPredicate:
      predicate(e, file, file_index, def_line);
      break;
    case ExprAst::kProposal:
      proposal(e, file);
      break;
  }
}

void Validation::predicate(const ExprAst& e, const std::string& file, int file_index, int def_line) {
  auto it = defined_.find(e.name);
  if (it == defined_.end()) {
    if (predicates_ok_) report(file, e.line, "unknown predicate '" + e.name + "'", Diagnostic::kUnknownName);
  } else if (file_index >= 0 && (it->second.file > file_index ||
                                 (it->second.file == file_index && it->second.line >= def_line))) {
    report(file, e.line, "forward reference to predicate '" + e.name + "' (defined at line " +
                             std::to_string(it->second.line) + "), which reads 0 here");
  }
}

void Validation::proposal(const ExprAst& e, const std::string& file) {
  if (behaviors_ok_ && e.name != "SOMEBEHAVIOR" && !level_of_.count(e.name))
    report(file, e.line, "unknown behaviour '" + e.name + "' in &" + e.name + "." + e.action + "." + e.label,
           Diagnostic::kUnknownName);
  if (actions_.unknown_name(e.action))
    report(file, e.line, "unknown action '" + e.action + "' (not in " + f_.s_ftoc + ")", Diagnostic::kUnknownName);
  else if (e.label != "ANY" && actions_.unknown_label(e.action, e.label))
    report(file, e.line, "unknown label '" + e.label + "' of action '" + e.action + "'", Diagnostic::kUnknownName);
}

void Validation::conditions(const std::vector<DefinitionDef>& defs, const std::string& file, const char* what) {
  constexpr int kConditions = -2;
  std::set<std::string> seen;
  for (const auto& d : defs) {
    if (behaviors_ok_ && !level_of_.count(d.name))
      report(file, d.line, std::string(what) + " for undefined behaviour '" + d.name + "'", Diagnostic::kUnknownName);
    if (!seen.insert(d.name).second) report(file, d.line, std::string(what) + " of '" + d.name + "' defined twice");
    expr(d.expr, file, kConditions, 0);
  }
}

void Validation::rules() {
  for (std::size_t i = 0; i < c_.behaviors.size() && i < c_.rules.size(); ++i) {
    const BehaviorDef& b = c_.behaviors[i];
    const std::string& path = c_.behavior_files[i];
    for (const auto& r : c_.rules[i]) {
      expr(r.precondition, path, kRules, 0);
      for (const auto& a : r.actions) {
        if (actions_.unknown_name(a.action)) {
          report(path, a.line, "unknown action '" + a.action + "' (not in " + f_.s_ftoc + ")", Diagnostic::kUnknownName);
        } else if (!(a.del && (a.label == "ANY" || a.label[0] == '*')) && actions_.unknown_label(a.action, a.label)) {
          report(path, a.line, "unknown label '" + a.label + "' of action '" + a.action + "'", Diagnostic::kUnknownName);
        }
        if (a.del && b.level == 1)
          report(path, a.line, "&DEL." + a.action + " in level-1 behaviour '" + b.name +
                                   "': there is no lower level to delete from");
      }
    }
  }
}

std::vector<Diagnostic> Validation::run() {
  const Shapes in_shapes = collect_shapes(c_.shapes, f_.shape_ctof);
  const Shapes out_shapes = collect_shapes(c_.out_shapes, f_.s_shape);
  data_ = collect_assocs(c_.assocs, in_shapes, ok(f_.shape_ctof), f_.ctof, "datum");
  actions_ = collect_assocs(c_.out_assocs, out_shapes, ok(f_.s_shape), f_.s_ftoc, "action");
  behaviors_ok_ = ok(f_.behaviors);
  predicates_ok_ = ok(f_.predicates) && ok(f_.predicate_actions);
  behaviours();
  define(c_.predicates, 0, f_.predicates);
  define(c_.predicate_actions, 1, f_.predicate_actions);
  for (const auto& d : c_.predicates) expr(d.expr, f_.predicates, 0, d.line);
  for (const auto& d : c_.predicate_actions) expr(d.expr, f_.predicate_actions, 1, d.line);
  conditions(c_.cando, f_.cando, "CANDO");
  conditions(c_.want, f_.want, "WANT");
  rules();
  return std::move(out_);
}

}  // namespace

std::vector<Diagnostic> validate(const ParsedConfig& config, const std::set<std::string>& failed) {
  return Validation(config, failed).run();
}

}  // namespace mrt::brian
