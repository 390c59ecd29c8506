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

  void report(const std::string& file, int line, const std::string& msg) { out.push_back({file, line, msg}); }

  // Parses a file with `parse`, reporting a read or syntax error.
  template <typename T, typename F>
  std::vector<T> parse(const std::string& file, F parse_fn) {
    if (file.empty()) return {};
    try {
      return parse_fn(read_text_file(file), file);
    } catch (const ParseError& e) {
      report(e.file(), e.line(), e.message());
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
    if (s.labels.count(d.name)) run.report(file, d.line, "shape '" + d.name + "' defined twice");
    auto& l = s.labels[d.name];
    for (const auto& set : d.sets) {
      if (l.count(set.label)) run.report(file, set.line, "label '" + set.label + "' defined twice in shape '" + d.name + "'");
      l.insert(set.label);
    }
  }
  return s;
}

// name -> labels of its shape, reporting associations to unknown shapes.
std::map<std::string, std::set<std::string>> collect_assocs(Run& run, const std::vector<AssociationDef>& defs,
                                                            const Shapes& shapes, const std::string& file,
                                                            const char* what) {
  std::map<std::string, std::set<std::string>> out;
  for (const auto& a : defs) {
    auto it = shapes.labels.find(a.shape);
    if (it == shapes.labels.end()) {
      run.report(file, a.line, "unknown shape '" + a.shape + "' for " + what + " '" + a.name + "'");
      out[a.name];
      continue;
    }
    out[a.name] = it->second;
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
  const auto data = collect_assocs(run, assocs_in, in_shapes, f.ctof, "datum");
  const auto actions = collect_assocs(run, assocs_out, out_shapes, f.s_ftoc, "action");

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
  for (const auto& d : preds)
    if (!defined.count(d.name)) defined[d.name] = {0, d.line};
  for (const auto& d : pacts)
    if (!defined.count(d.name)) defined[d.name] = {1, d.line};

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
            auto it = data.find(e.name);
            if (it == data.end())
              run.report(file, e.line, "unknown datum '" + e.name + "' (not in " + f.ctof + ")");
            else if (!it->second.count(e.label))
              run.report(file, e.line, "unknown label '" + e.label + "' of datum '" + e.name + "'");
            break;
          }
          case ExprAst::kPredicate: {
            auto it = defined.find(e.name);
            if (it == defined.end()) {
              run.report(file, e.line, "unknown predicate '" + e.name + "'");
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
            if (e.name != "SOMEBEHAVIOR" && !level_of.count(e.name))
              run.report(file, e.line, "unknown behaviour '" + e.name + "' in &" + e.name + "." + e.action + "." + e.label);
            auto it = actions.find(e.action);
            if (it == actions.end())
              run.report(file, e.line, "unknown action '" + e.action + "' (not in " + f.s_ftoc + ")");
            else if (e.label != "ANY" && !it->second.count(e.label))
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
      if (!level_of.count(d.name))
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
        auto it = actions.find(a.action);
        if (it == actions.end()) {
          run.report(path, a.line, "unknown action '" + a.action + "' (not in " + f.s_ftoc + ")");
        } else if (!(a.del && (a.label == "ANY" || a.label[0] == '*')) && !it->second.count(a.label)) {
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
