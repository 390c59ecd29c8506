// Fuzzy predicates over crisp data for SCARE (opportunities of activities,
// conditions of tasks), written in Mr. BRIAN's predicate language and
// evaluated by mrt_brian's library (manual §10.4.1-10.4.2): shapes as in
// shape_ctof.txt, data->shape associations as in ctof.txt, named predicates
// as in Predicate.ini, and expressions `(AND (D BallDistance NEAR) (P Free))`.
// ROS-free.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mrt_brian/expression.h"
#include "mrt_brian/fuzzyfier.h"
#include "mrt_brian/preacher.h"
#include "mrt_brian/symbol_table.h"

namespace mrt::scare {

/// Crisp data by name: <value, reliability> (what MAP publishes).
using CrispMap = std::map<std::string, std::pair<double, double>>;

/// Where a piece of fuzzy text sits in its file, so that errors of the
/// predicate parser name the file's own line and column.
struct TextOrigin {
  std::string file;
  int line = 1;    // line of the text's first character
  int column = 1;  // column of the text's first character
  int indent = 0;  // columns a block scalar's lines were stripped of (lines after the first)
};

class FuzzyModel {
 public:
  FuzzyModel() = default;
  /// Throws common::ParseError (at the file's line) on a syntax error, an
  /// unknown shape, datum, label or predicate, or a predicate defined twice.
  FuzzyModel(const std::string& shapes, const TextOrigin& shapes_at, const std::string& data,
             const TextOrigin& data_at, const std::string& predicates, const TextOrigin& predicates_at);

  /// Compiles one expression; returns its id. Same errors.
  int compile(const std::string& expression, const TextOrigin& at);

  /// Fuzzifies `crisp` and evaluates the named predicates (missing data
  /// read <0, 1>). Then value(id) reads each compiled expression.
  void evaluate(const CrispMap& crisp);
  brian::FuzzyValue value(int id) const;
  /// value * reliability, the degree Mr. BRIAN also uses for rule firing.
  double degree(int id) const {
    const brian::FuzzyValue v = value(id);
    return v.value * v.reliability;
  }
  /// The crisp data the model reads (its associations).
  std::vector<std::string> data_names() const;

 private:
  void check(const brian::ExprAst& e, const TextOrigin& at) const;

  brian::Fuzzyfier fuzzyfier_;
  brian::SymbolTable predicates_;
  brian::ExpressionPool pool_;
  brian::DefinitionList definitions_;
  std::vector<int> roots_;
  brian::EvalState state_;
};

}  // namespace mrt::scare
