#include "mrt_scare/fuzzy_model.h"

#include "mrt_brian/defuzzyfier.h"
#include "mrt_brian/expression_compiler.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

namespace mrt::scare {

using common::ParseError;

namespace {

/// A ParseError from a parser run on the text alone, moved to the file.
ParseError moved(const ParseError& e, const TextOrigin& at) {
  const int line = e.line() > 0 ? at.line + e.line() - 1 : at.line;
  const int column = e.line() == 1 ? at.column + e.column() - 1 : at.indent + e.column();
  return ParseError(at.file, line, column, e.message());
}

ParseError at_node(const TextOrigin& at, int line, int column, const std::string& msg) {
  return ParseError(at.file, at.line + line - 1, line == 1 ? at.column + column - 1 : at.indent + column, msg);
}

}  // namespace

FuzzyModel::FuzzyModel(const std::string& shapes, const TextOrigin& shapes_at, const std::string& data,
                       const TextOrigin& data_at, const std::string& predicates,
                       const TextOrigin& predicates_at) {
  std::vector<brian::ShapeDef> shape_defs;
  std::vector<brian::AssociationDef> assoc_defs;
  try {
    shape_defs = brian::parse_shapes(shapes, shapes_at.file);
  } catch (const ParseError& e) {
    throw moved(e, shapes_at);
  }
  try {
    assoc_defs = brian::parse_associations(data, data_at.file);
  } catch (const ParseError& e) {
    throw moved(e, data_at);
  }
  for (const auto& a : assoc_defs) {
    bool found = false;
    for (const auto& s : shape_defs) found = found || s.name == a.shape;
    if (!found) throw at_node(data_at, a.line, a.column, "unknown shape '" + a.shape + "'");
  }
  fuzzyfier_ = brian::Fuzzyfier(shape_defs, assoc_defs, shapes_at.file, data_at.file);
  std::vector<brian::DefinitionDef> defs;
  try {
    defs = brian::parse_definitions(predicates, predicates_at.file);
  } catch (const ParseError& e) {
    throw moved(e, predicates_at);
  }
  const brian::SymbolTable no_behaviors;
  const brian::Defuzzyfier no_actions;
  for (const auto& d : defs) {
    check(d.expr, predicates_at);  // a predicate may only use those defined before it
    if (predicates_.find(d.name) >= 0)
      throw at_node(predicates_at, d.line, d.column, "predicate '" + d.name + "' defined twice");
    const int target = predicates_.intern(d.name);
    const brian::ExpressionCompiler compiler(fuzzyfier_, predicates_, no_behaviors, no_actions);
    definitions_.add(target, compiler.compile(d.expr, pool_));
  }
  state_.fuzzy.assign(static_cast<std::size_t>(fuzzyfier_.slot_count()), {});
  state_.predicates.assign(static_cast<std::size_t>(predicates_.size()), {});
}

void FuzzyModel::check(const brian::ExprAst& e, const TextOrigin& at) const {
  switch (e.kind) {
    case brian::ExprAst::kDatum:
      if (fuzzyfier_.datum_id(e.name) < 0)
        throw at_node(at, e.line, e.column, "unknown datum '" + e.name + "' (not in the data associations)");
      if (fuzzyfier_.slot(e.name, e.label) < 0)
        throw at_node(at, e.line, e.column, "unknown label '" + e.label + "' of datum '" + e.name + "'");
      break;
    case brian::ExprAst::kPredicate:
      if (predicates_.find(e.name) < 0)
        throw at_node(at, e.line, e.column, "unknown predicate '" + e.name + "' (not defined before)");
      break;
    case brian::ExprAst::kProposal:
      throw at_node(at, e.line, e.column, "behaviour proposals are not available to SCARE");
    default:
      for (const auto& a : e.args) check(a, at);
  }
}

int FuzzyModel::compile(const std::string& expression, const TextOrigin& at) {
  std::vector<brian::DefinitionDef> defs;
  // One definition `_ = <expression>;`: the prefix is 4 characters long.
  TextOrigin shifted = at;
  shifted.column -= 4;
  try {
    defs = brian::parse_definitions("_ = " + expression + ";", at.file);
  } catch (const ParseError& e) {
    throw moved(e, shifted);
  }
  if (defs.size() != 1) throw ParseError(at.file, at.line, at.column, "expected one predicate expression");
  check(defs[0].expr, shifted);
  const brian::SymbolTable no_behaviors;
  const brian::Defuzzyfier no_actions;
  const brian::ExpressionCompiler compiler(fuzzyfier_, predicates_, no_behaviors, no_actions);
  roots_.push_back(compiler.compile(defs[0].expr, pool_));
  return static_cast<int>(roots_.size()) - 1;
}

void FuzzyModel::evaluate(const CrispMap& crisp) {
  std::fill(state_.fuzzy.begin(), state_.fuzzy.end(), brian::FuzzyValue{});
  for (int d = 0; d < fuzzyfier_.datum_count(); ++d) {
    const auto it = crisp.find(fuzzyfier_.datum_name(d));
    if (it == crisp.end()) continue;  // missing datum: every label reads <0, 1>
    fuzzyfier_.fuzzify(d, it->second.first, it->second.second, state_.fuzzy.data());
  }
  brian::Preacher(&pool_, definitions_).evaluate(state_);
}

brian::FuzzyValue FuzzyModel::value(int id) const {
  return pool_.evaluate(roots_.at(static_cast<std::size_t>(id)), state_);
}

std::vector<std::string> FuzzyModel::data_names() const {
  std::vector<std::string> names;
  for (int d = 0; d < fuzzyfier_.datum_count(); ++d) names.push_back(fuzzyfier_.datum_name(d));
  return names;
}

}  // namespace mrt::scare
