// What the Mr. BRIAN file parsers produce: the files' content with names
// still unresolved and the file and line of every element, so that the model
// builder and the checker can both work on it. A BrianConfigs.ini slot may
// name several files (their definitions concatenated): every top-level
// definition keeps the file it came from, so that each message names it.
#pragma once

#include <string>
#include <vector>

namespace mrt::brian {

/// `(TYPE (LABEL v1 v2 ...))` inside a shape.
struct SetDef {
  std::string type, label;
  std::vector<double> params;
  int line = 0, column = 0;
};

/// `(NAME set set ...)` of shape_ctof.txt / s_shape.txt; an item
/// `(CIRCULAR lo hi)` declares the shape's range circular (lo == hi), so that
/// outputs using it are defuzzified with a circular mean over [lo, hi).
struct ShapeDef {
  std::string name;
  std::vector<SetDef> sets;
  bool circular = false;
  double range_lo = 0.0, range_hi = 0.0;
  std::string file;  // the file it was read from (its sets' file too)
  int line = 0, column = 0;
};

/// `(name SHAPE)` of ctof.txt / s_ftoc.txt.
struct AssociationDef {
  std::string name, shape;
  std::string file;
  int line = 0, column = 0;
};

/// A predicate expression: `(AND e e)`, `(OR e e)`, `(NOT e)`,
/// `(D datum label)`, `(P name)` or `(name)`, and `&Behaviour.Action.Label`.
struct ExprAst {
  enum Kind { kAnd, kOr, kNot, kDatum, kPredicate, kProposal };
  Kind kind = kPredicate;
  std::vector<ExprAst> args;
  std::string name;    // datum, predicate or behaviour (or SOMEBEHAVIOR)
  std::string action;  // kProposal only
  std::string label;   // kDatum and kProposal (ANY for any label)
  int line = 0, column = 0;
};

/// `Name = expr;` of Predicate.ini, PredicateActions.ini, Cando.ini, want.txt.
struct DefinitionDef {
  std::string name;
  ExprAst expr;
  std::string file;  // its expressions' file too
  int line = 0, column = 0;
};

/// `(Action Label)` or `(&DEL.Action ANY|Label|*substring)` of a rule.
struct ActionDef {
  bool del = false;
  std::string action, label;
  int line = 0, column = 0;
};

/// `precondition => action ... ;` of a .rul file; `line` is the line of the
/// closing ';' (the line the 2009 engine reports), `start_line` the first.
struct RuleDef {
  ExprAst precondition;
  std::vector<ActionDef> actions;
  int line = 0, start_line = 0;
};

/// `(level <n> <Name> <path>)` of the behaviour list; `path` as written.
struct BehaviorDef {
  int level = 0;
  std::string name, path;
  std::string file;  // the behaviour list it was read from
  int line = 0, column = 0;
};

}  // namespace mrt::brian
