#include "mrt_brian/checker.h"

#include <functional>
#include <map>
#include <set>

#include "mrt_brian/behavior_list_parser.h"
#include "mrt_brian/lexer.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/rule_parser.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

namespace {

class Run {
 public:
  std::vector<Diagnostic> out;
  std::set<std::string> failed;  // files that could not be read or parsed

  void report(const std::string& file, int line, const std::string& msg) { out.push_back({file, line, msg}); }
  bool ok(const std::string& file) const { return !failed.count(file); }

  // Parses a file with `parse`, reporting a read or syntax error.
  template <typename T, typename F>
  std::vector<T> parse(const std::string& file, F parse_fn) {
    if (file.empty()) return {};
    try {
      return parse_fn(read_text_file(file), file);
    } catch (const ParseError& e) {
      report(e.file(), e.line(), e.message());
      failed.insert(file);
    }
    return {};
  }
};

struct Shapes {
  std::map<std::string, std::set<std::string>> labels;  // shape -> labels
};

Shapes collect_shapes(Run& run, const std::vector<ShapeDef>& defs, const std::string& file) {
  Shapes s;
  for (const auto& d : defs) {
    if (s.labels.count(d.name)) {  // the engine refuses it; its labels are not checked
      run.report(file, d.line, "shape '" + d.name + "' defined twice");
      continue;
    }
    auto& l = s.labels[d.name];
    for (const auto& set : d.sets) {
      if (l.count(set.label)) run.report(file, set.line, "label '" + set.label + "' defined twice in shape '" + d.name + "'");
      l.insert(set.label);
    }
  }
  return s;
}

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

Names collect_assocs(Run& run, const std::vector<AssociationDef>& defs, const Shapes& shapes, bool shapes_ok,
                     const std::string& file, const char* what) {
  Names out;
  out.complete = run.ok(file);
  std::map<std::string, int> first;
  for (const auto& a : defs) {
    if (!first.emplace(a.name, a.line).second)
      run.report(file, a.line, std::string(what) + " '" + a.name + "' associated twice (first at line " +
                                   std::to_string(first[a.name]) + ")");
    auto it = shapes.labels.find(a.shape);
    if (it == shapes.labels.end()) {
      if (shapes_ok) run.report(file, a.line, "unknown shape '" + a.shape + "' for " + what + " '" + a.name + "'");
      out.labels[a.name];
      out.opaque.insert(a.name);
      continue;
    }
    out.labels[a.name] = it->second;
    out.opaque.erase(a.name);
  }
  return out;
}

}  // namespace

std::vector<Diagnostic> Checker::check_path(const std::string& path) const {
  try {
    return check(ConfigFiles::locate(path));
  } catch (const ParseError& e) {
    return {{e.file(), e.line(), e.message()}};
  }
}

std::vector<Diagnostic> Checker::check(const ConfigFiles& f) const {
  Run run;
  const auto shapes_in = run.parse<ShapeDef>(f.shape_ctof, parse_shapes);
  const auto assocs_in = run.parse<AssociationDef>(f.ctof, parse_associations);
  const auto preds = run.parse<DefinitionDef>(f.predicates, parse_definitions);
  const auto pacts = run.parse<DefinitionDef>(f.predicate_actions, parse_definitions);
  const auto cando = run.parse<DefinitionDef>(f.cando, parse_definitions);
  const auto blist = run.parse<BehaviorDef>(f.behaviors, parse_behavior_list);
  const auto want = run.parse<DefinitionDef>(f.want, parse_definitions);
  const auto assocs_out = run.parse<AssociationDef>(f.s_ftoc, parse_associations);
  const auto shapes_out = run.parse<ShapeDef>(f.s_shape, parse_shapes);

  const Shapes in_shapes = collect_shapes(run, shapes_in, f.shape_ctof);
  const Shapes out_shapes = collect_shapes(run, shapes_out, f.s_shape);
  const Names data = collect_assocs(run, assocs_in, in_shapes, run.ok(f.shape_ctof), f.ctof, "datum");
  const Names actions = collect_assocs(run, assocs_out, out_shapes, run.ok(f.s_shape), f.s_ftoc, "action");
  const bool behaviors_ok = run.ok(f.behaviors);
  const bool predicates_ok = run.ok(f.predicates) && run.ok(f.predicate_actions);

  // Behaviours, levels.
  std::map<std::string, int> level_of;
  std::map<int, int> first_line_of_level;
  for (const auto& b : blist) {
    if (level_of.count(b.name)) run.report(f.behaviors, b.line, "behaviour '" + b.name + "' listed twice");
    level_of[b.name] = b.level;
    if (!first_line_of_level.count(b.level)) first_line_of_level[b.level] = b.line;
  }
  {
    int expected = 1;
    for (const auto& [level, line] : first_line_of_level) {
      if (level != expected)
        run.report(f.behaviors, line,
                   "level gap: level " + std::to_string(level) + " used but level " + std::to_string(expected) +
                       " has no behaviour");
      expected = level + 1;
    }
  }

  // Predicates: where each is defined (file index 0 = Predicate.ini, 1 = PredicateActions.ini).
  struct Where { int file; int line; };
  std::map<std::string, Where> defined;
  auto define = [&](const std::vector<DefinitionDef>& defs, int index, const std::string& file) {
    for (const auto& d : defs) {
      auto [it, fresh] = defined.emplace(d.name, Where{index, d.line});
      if (!fresh)
        run.report(file, d.line, "predicate '" + d.name + "' defined twice (first at " +
                                     (it->second.file == 0 ? f.predicates : f.predicate_actions) + ":" +
                                     std::to_string(it->second.line) + ")");
    }
  };
  define(preds, 0, f.predicates);
  define(pacts, 1, f.predicate_actions);

  // Checks one expression. `file_index`/`line`: position of the definition
  // being checked (for forward references), file_index -1 in rules and
  // kConditions in CANDO/WANT.
  constexpr int kConditions = -2;
  std::function<void(const ExprAst&, const std::string&, int, int)> expr =
      [&](const ExprAst& e, const std::string& file, int file_index, int def_line) {
        switch (e.kind) {
          case ExprAst::kAnd:
          case ExprAst::kOr:
          case ExprAst::kNot:
            for (const auto& a : e.args) expr(a, file, file_index, def_line);
            break;
          case ExprAst::kDatum: {
            if (data.unknown_name(e.name))
              run.report(file, e.line, "unknown datum '" + e.name + "' (not in " + f.ctof + ")");
            else if (data.unknown_label(e.name, e.label))
              run.report(file, e.line, "unknown label '" + e.label + "' of datum '" + e.name + "'");
            break;
          }
          case ExprAst::kPredicate: {
            auto it = defined.find(e.name);
            if (it == defined.end()) {
              if (predicates_ok) run.report(file, e.line, "unknown predicate '" + e.name + "'");
            } else if (file_index == kConditions && it->second.file == 1) {
              run.report(file, e.line, "predicate action '" + e.name +
                                           "' in a CANDO/WANT condition, which is evaluated before any predicate action");
            } else if (file_index >= 0 && (it->second.file > file_index ||
                                           (it->second.file == file_index && it->second.line >= def_line))) {
              run.report(file, e.line, "forward reference to predicate '" + e.name + "' (defined at line " +
                                           std::to_string(it->second.line) + "), which reads 0 here");
            }
            break;
          }
          case ExprAst::kProposal: {
            if (behaviors_ok && e.name != "SOMEBEHAVIOR" && !level_of.count(e.name))
              run.report(file, e.line, "unknown behaviour '" + e.name + "' in &" + e.name + "." + e.action + "." + e.label);
            if (actions.unknown_name(e.action))
              run.report(file, e.line, "unknown action '" + e.action + "' (not in " + f.s_ftoc + ")");
            else if (e.label != "ANY" && actions.unknown_label(e.action, e.label))
              run.report(file, e.line, "unknown label '" + e.label + "' of action '" + e.action + "'");
            break;
          }
        }
      };

  for (const auto& d : preds) expr(d.expr, f.predicates, 0, d.line);
  for (const auto& d : pacts) expr(d.expr, f.predicate_actions, 1, d.line);
  auto conditions = [&](const std::vector<DefinitionDef>& defs, const std::string& file, const char* what) {
    std::set<std::string> seen;
    for (const auto& d : defs) {
      if (behaviors_ok && !level_of.count(d.name))
        run.report(file, d.line, std::string(what) + " for undefined behaviour '" + d.name + "'");
      if (!seen.insert(d.name).second) run.report(file, d.line, std::string(what) + " of '" + d.name + "' defined twice");
      expr(d.expr, file, kConditions, 0);
    }
  };
  conditions(cando, f.cando, "CANDO");
  conditions(want, f.want, "WANT");

  for (const auto& b : blist) {
    const std::string path = f.resolve(b.path);
    std::vector<RuleDef> rules;
    try {
      rules = parse_rules(read_text_file(path), path);
    } catch (const ParseError& e) {
      if (e.line() == 0) run.report(f.behaviors, b.line, "cannot open behaviour file '" + path + "'");
      else run.report(e.file(), e.line(), e.message());
      continue;
    }
    for (const auto& r : rules) {
      expr(r.precondition, path, -1, 0);
      for (const auto& a : r.actions) {
        if (actions.unknown_name(a.action)) {
          run.report(path, a.line, "unknown action '" + a.action + "' (not in " + f.s_ftoc + ")");
        } else if (!(a.del && (a.label == "ANY" || a.label[0] == '*')) && actions.unknown_label(a.action, a.label)) {
          run.report(path, a.line, "unknown label '" + a.label + "' of action '" + a.action + "'");
        }
        if (a.del && b.level == 1)
          run.report(path, a.line, "&DEL." + a.action + " in level-1 behaviour '" + b.name +
                                       "': there is no lower level to delete from");
      }
    }
  }
  return run.out;
}

}  // namespace mrt::brian
