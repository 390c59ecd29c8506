#include "mrt_brian/checker.h"

#include <iterator>

#include "mrt_brian/behavior_list_parser.h"
#include "mrt_brian/lexer.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/rule_parser.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

namespace {

// Parses what it can, reporting every read or syntax error, and remembers
// which files failed (validate() does not report what depends on them).
class Run {
 public:
  std::vector<Diagnostic> out;
  std::set<std::string> failed;

  void report(const std::string& file, int line, const std::string& msg) { out.push_back({file, line, msg}); }

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

  // A `#( ... ;` block comment that contains '=' swallowed a definition or
  // a rule (it runs to the next ';', not to the end of the line).
  void block_comments(const std::string& file) {
    if (file.empty() || failed.count(file)) return;
    try {
      for (const BlockComment& b : find_block_comments(read_text_file(file)))
        if (b.swallows)
          out.push_back({file, b.line,
                         "block comment '#(' runs to the ';' at line " + std::to_string(b.end_line) +
                             " and swallows a " + (b.rule ? "rule" : "definition") + " (a '#' comment ends at the end of the line)",
                         Diagnostic::kWarning});
    } catch (const ParseError&) {
    }
  }
};

// Every file of a slot, concatenated (each definition keeps its file).
template <typename T, typename F>
std::vector<T> parse_slot(Run& run, const ConfigFiles& f, Slot slot, F parse_fn) {
  std::vector<T> out;
  for (const std::string& file : f.all(slot)) {
    std::vector<T> defs = run.parse<T>(file, parse_fn);
    out.insert(out.end(), std::make_move_iterator(defs.begin()), std::make_move_iterator(defs.end()));
  }
  return out;
}

ParsedConfig parse_all(Run& run, const ConfigFiles& f) {
  ParsedConfig c;
  c.files = f;
  c.shapes = parse_slot<ShapeDef>(run, f, Slot::kShapeCtof, parse_shapes);
  c.assocs = parse_slot<AssociationDef>(run, f, Slot::kCtof, parse_associations);
  c.predicates = parse_slot<DefinitionDef>(run, f, Slot::kPredicates, parse_definitions);
  c.predicate_actions = parse_slot<DefinitionDef>(run, f, Slot::kPredicateActions, parse_definitions);
  c.cando = parse_slot<DefinitionDef>(run, f, Slot::kCando, parse_definitions);
  c.behaviors = parse_slot<BehaviorDef>(run, f, Slot::kBehaviors, parse_behavior_list);
  c.want = parse_slot<DefinitionDef>(run, f, Slot::kWant, parse_definitions);
  c.out_assocs = parse_slot<AssociationDef>(run, f, Slot::kSFtoc, parse_associations);
  c.out_shapes = parse_slot<ShapeDef>(run, f, Slot::kSShape, parse_shapes);
  for (Slot s : {Slot::kPredicates, Slot::kPredicateActions, Slot::kCando, Slot::kWant})
    for (const std::string& file : f.all(s)) run.block_comments(file);
  for (const auto& b : c.behaviors) {
    const std::string path = f.resolve(b.path);
    c.behavior_files.push_back(path);
    c.rules.emplace_back();
    try {
      c.rules.back() = parse_rules(read_text_file(path), path);
      run.block_comments(path);
    } catch (const ParseError& e) {
      if (e.line() == 0) run.report(b.file.empty() ? f.behaviors : b.file, b.line, "cannot open behaviour file '" + path + "'");
      else run.report(e.file(), e.line(), e.message());
      run.failed.insert(path);
    }
  }
  return c;
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
  const ParsedConfig c = parse_all(run, f);
  std::vector<Diagnostic> out = std::move(run.out);
  for (auto& d : validate(c, run.failed)) out.push_back(std::move(d));
  return out;
}

}  // namespace mrt::brian
