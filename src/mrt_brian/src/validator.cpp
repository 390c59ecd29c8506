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

// A place in the rule base. A definition of a slot of several files names
// the file it came from; an AST built by hand (no file) falls back to the
// slot's first file.
struct Place {
  std::string file;
  int line = 0;
};

std::string join(const std::vector<std::string>& files) {
  std::string out;
  for (const auto& f : files) out += (out.empty() ? "" : ", ") + f;
  return out;
}

class Validation {
 public:
  Validation(const ParsedConfig& c, const std::set<std::string>& failed) : c_(c), f_(c.files), failed_(failed) {}
  std::vector<Diagnostic> run();

 private:
  // Where a predicate is defined: `seq` its position among the predicates
  // then the predicate actions (the order they are evaluated in).
  struct Where { int seq; Place at; };
  static constexpr int kRules = -1;  // sequence of an expression in a rule

  bool ok(Slot s) const {
    for (const auto& file : f_.all(s))
      if (failed_.count(file)) return false;
    return true;
  }
  std::string file_of(const std::string& def_file, Slot s) const { return def_file.empty() ? f_.first(s) : def_file; }
  void report(const std::string& file, int line, const std::string& msg, Kind kind = Diagnostic::kError) {
    out_.push_back({file, line, msg, kind});
  }
  // "<what> twice" at `here`: the message as for one file when `first` is
  // in the same file (`same_file_note` added), both places otherwise.
  void twice(const Place& here, const Place& first, const std::string& what, const std::string& same_file_note = "") {
    if (here.file == first.file) report(here.file, here.line, what + same_file_note);
    else report(here.file, here.line, what + " (first at " + first.file + ":" + std::to_string(first.line) + ")",
                Diagnostic::kDuplicate);
  }
  Shapes collect_shapes(const std::vector<ShapeDef>& defs, Slot slot);
  Names collect_assocs(const std::vector<AssociationDef>& defs, const Shapes& shapes, bool shapes_ok, Slot slot,
                       const char* what);
  void behaviours();
  void define(const std::vector<DefinitionDef>& defs, Slot slot, int& seq);
  void expr(const ExprAst& e, const std::string& file, int seq);
  void predicate(const ExprAst& e, const std::string& file, int seq);
  void proposal(const ExprAst& e, const std::string& file);
  void conditions(const std::vector<DefinitionDef>& defs, Slot slot, const char* what);
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

Shapes Validation::collect_shapes(const std::vector<ShapeDef>& defs, Slot slot) {
  Shapes s;
  std::map<std::string, Place> first;
  for (const auto& d : defs) {
    const Place here{file_of(d.file, slot), d.line};
    auto [it, fresh] = first.emplace(d.name, here);
    if (!fresh) {  // the engine refuses it; its labels are not checked
      twice(here, it->second, "shape '" + d.name + "' defined twice");
      continue;
    }
    auto& l = s.labels[d.name];
    for (const auto& set : d.sets) {
      if (l.count(set.label))
        report(here.file, set.line, "label '" + set.label + "' defined twice in shape '" + d.name + "'");
      l.insert(set.label);
    }
  }
  return s;
}

Names Validation::collect_assocs(const std::vector<AssociationDef>& defs, const Shapes& shapes, bool shapes_ok,
                                 Slot slot, const char* what) {
  Names out;
  out.complete = ok(slot);
  std::map<std::string, Place> first;
  for (const auto& a : defs) {
    const Place here{file_of(a.file, slot), a.line};
    auto [at, fresh] = first.emplace(a.name, here);
    if (!fresh)
      twice(here, at->second, std::string(what) + " '" + a.name + "' associated twice",
            " (first at line " + std::to_string(at->second.line) + ")");
    auto it = shapes.labels.find(a.shape);
    if (it == shapes.labels.end()) {
      if (shapes_ok) report(here.file, a.line, "unknown shape '" + a.shape + "' for " + what + " '" + a.name + "'");
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
  std::map<int, Place> first_of_level;
  std::map<std::string, Place> listed;
  for (const auto& b : c_.behaviors) {
    const Place here{file_of(b.file, Slot::kBehaviors), b.line};
    auto [it, fresh] = listed.emplace(b.name, here);
    if (!fresh) twice(here, it->second, "behaviour '" + b.name + "' listed twice");
    level_of_[b.name] = b.level;
    first_of_level.emplace(b.level, here);
  }
  int expected = 1;
  for (const auto& [level, at] : first_of_level) {
    if (level != expected)
      report(at.file, at.line,
             "level gap: level " + std::to_string(level) + " used but level " + std::to_string(expected) +
                 " has no behaviour");
    expected = level + 1;
  }
}

void Validation::define(const std::vector<DefinitionDef>& defs, Slot slot, int& seq) {
  for (const auto& d : defs) {
    const Place here{file_of(d.file, slot), d.line};
    auto [it, fresh] = defined_.emplace(d.name, Where{seq++, here});
    if (!fresh) {
      const Place& first = it->second.at;
      report(here.file, here.line,
             "predicate '" + d.name + "' defined twice (first at " + first.file + ":" + std::to_string(first.line) + ")",
             first.file == here.file ? Diagnostic::kError : Diagnostic::kDuplicate);
    }
  }
}

// `seq`: position of the definition being checked among the predicates and
// predicate actions (for forward references), kRules in rules, and
// kConditions in CANDO/WANT (which may read predicate actions, §10.4.3).
void Validation::expr(const ExprAst& e, const std::string& file, int seq) {
  switch (e.kind) {
    case ExprAst::kAnd:
    case ExprAst::kOr:
    case ExprAst::kNot:
      for (const auto& a : e.args) expr(a, file, seq);
      break;
    case ExprAst::kDatum:
      if (data_.unknown_name(e.name))
        report(file, e.line, "unknown datum '" + e.name + "' (not in " + join(f_.all(Slot::kCtof)) + ")",
               Diagnostic::kUnknownName);
      else if (data_.unknown_label(e.name, e.label))
        report(file, e.line, "unknown label '" + e.label + "' of datum '" + e.name + "'", Diagnostic::kUnknownName);
      break;
    case ExprAst::kPredicate:
      predicate(e, file, seq);
      break;
    case ExprAst::kProposal:
      proposal(e, file);
      break;
  }
}

void Validation::predicate(const ExprAst& e, const std::string& file, int seq) {
  auto it = defined_.find(e.name);
  if (it == defined_.end()) {
    if (predicates_ok_) report(file, e.line, "unknown predicate '" + e.name + "'", Diagnostic::kUnknownName);
  } else if (seq >= 0 && it->second.seq >= seq) {
    const Place& at = it->second.at;
    report(file, e.line, "forward reference to predicate '" + e.name + "' (defined at " +
                             (at.file == file ? "line " : at.file + ":") + std::to_string(at.line) +
                             "), which reads 0 here");
  }
}

void Validation::proposal(const ExprAst& e, const std::string& file) {
  if (behaviors_ok_ && e.name != "SOMEBEHAVIOR" && !level_of_.count(e.name))
    report(file, e.line, "unknown behaviour '" + e.name + "' in &" + e.name + "." + e.action + "." + e.label,
           Diagnostic::kUnknownName);
  if (actions_.unknown_name(e.action))
    report(file, e.line, "unknown action '" + e.action + "' (not in " + join(f_.all(Slot::kSFtoc)) + ")",
           Diagnostic::kUnknownName);
  else if (e.label != "ANY" && actions_.unknown_label(e.action, e.label))
    report(file, e.line, "unknown label '" + e.label + "' of action '" + e.action + "'", Diagnostic::kUnknownName);
}

void Validation::conditions(const std::vector<DefinitionDef>& defs, Slot slot, const char* what) {
  constexpr int kConditions = -2;
  std::map<std::string, Place> seen;
  for (const auto& d : defs) {
    const Place here{file_of(d.file, slot), d.line};
    if (behaviors_ok_ && !level_of_.count(d.name))
      report(here.file, d.line, std::string(what) + " for undefined behaviour '" + d.name + "'",
             Diagnostic::kUnknownName);
    auto [it, fresh] = seen.emplace(d.name, here);
    if (!fresh) twice(here, it->second, std::string(what) + " of '" + d.name + "' defined twice");
    expr(d.expr, here.file, kConditions);
  }
}

void Validation::rules() {
  const std::string s_ftoc = join(f_.all(Slot::kSFtoc));
  for (std::size_t i = 0; i < c_.behaviors.size() && i < c_.rules.size(); ++i) {
    const BehaviorDef& b = c_.behaviors[i];
    const std::string& path = c_.behavior_files[i];
    for (const auto& r : c_.rules[i]) {
      expr(r.precondition, path, kRules);
      for (const auto& a : r.actions) {
        if (actions_.unknown_name(a.action)) {
          report(path, a.line, "unknown action '" + a.action + "' (not in " + s_ftoc + ")", Diagnostic::kUnknownName);
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
  const Shapes in_shapes = collect_shapes(c_.shapes, Slot::kShapeCtof);
  const Shapes out_shapes = collect_shapes(c_.out_shapes, Slot::kSShape);
  data_ = collect_assocs(c_.assocs, in_shapes, ok(Slot::kShapeCtof), Slot::kCtof, "datum");
  actions_ = collect_assocs(c_.out_assocs, out_shapes, ok(Slot::kSShape), Slot::kSFtoc, "action");
  behaviors_ok_ = ok(Slot::kBehaviors);
  predicates_ok_ = ok(Slot::kPredicates) && ok(Slot::kPredicateActions);
  behaviours();
  int seq = 0;
  define(c_.predicates, Slot::kPredicates, seq);
  define(c_.predicate_actions, Slot::kPredicateActions, seq);
  // The sequence numbers define() gave, in the same order.
  seq = 0;
  for (const auto& d : c_.predicates) expr(d.expr, file_of(d.file, Slot::kPredicates), seq++);
  for (const auto& d : c_.predicate_actions) expr(d.expr, file_of(d.file, Slot::kPredicateActions), seq++);
  conditions(c_.cando, Slot::kCando, "CANDO");
  conditions(c_.want, Slot::kWant, "WANT");
  rules();
  return std::move(out_);
}

}  // namespace

std::vector<Diagnostic> validate(const ParsedConfig& config, const std::set<std::string>& failed) {
  return Validation(config, failed).run();
}

}  // namespace mrt::brian
