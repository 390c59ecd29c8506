#include "mrt_brian/checker.h"

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

ParsedConfig parse_all(Run& run, const ConfigFiles& f) {
  ParsedConfig c;
  c.files = f;
  c.shapes = run.parse<ShapeDef>(f.shape_ctof, parse_shapes);
  c.assocs = run.parse<AssociationDef>(f.ctof, parse_associations);
  c.predicates = run.parse<DefinitionDef>(f.predicates, parse_definitions);
  c.predicate_actions = run.parse<DefinitionDef>(f.predicate_actions, parse_definitions);
  c.cando = run.parse<DefinitionDef>(f.cando, parse_definitions);
  c.behaviors = run.parse<BehaviorDef>(f.behaviors, parse_behavior_list);
  c.want = run.parse<DefinitionDef>(f.want, parse_definitions);
  c.out_assocs = run.parse<AssociationDef>(f.s_ftoc, parse_associations);
  c.out_shapes = run.parse<ShapeDef>(f.s_shape, parse_shapes);
  for (const std::string& file : {f.predicates, f.predicate_actions, f.cando, f.want}) run.block_comments(file);
  for (const auto& b : c.behaviors) {
    const std::string path = f.resolve(b.path);
    c.behavior_files.push_back(path);
    c.rules.emplace_back();
    try {
      c.rules.back() = parse_rules(read_text_file(path), path);
      run.block_comments(path);
    } catch (const ParseError& e) {
      if (e.line() == 0) run.report(f.behaviors, b.line, "cannot open behaviour file '" + path + "'");
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
