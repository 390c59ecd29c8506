#include "mrt_brian/shape_parser.h"

#include "mrt_brian/fuzzy_set.h"
#include "mrt_brian/lexer.h"

namespace mrt::brian {

namespace {
// `(CIRCULAR lo hi)`: the shape covers the circular range [lo, hi).
void parse_circular(TokenStream& ts, const Token& head, ShapeDef& shape) {
  if (shape.circular) ts.fail(head, "shape " + shape.name + " declared CIRCULAR twice");
  shape.range_lo = ts.expect_number("the start of the circular range");
  shape.range_hi = ts.expect_number("the end of the circular range");
  if (!(shape.range_hi > shape.range_lo))
    ts.fail(head, "CIRCULAR range of shape " + shape.name + " must have its end above its start");
  shape.circular = true;
  ts.expect(Token::kClose, "')' closing CIRCULAR lo hi");
}
}  // namespace

std::vector<ShapeDef> parse_shapes(const std::string& text, const std::string& file) {
  TokenStream ts(tokenize(text, true, false), file);  // no #( ... ; block comments here
  std::vector<ShapeDef> out;
  while (!ts.at_end()) {
    if (ts.peek().kind == Token::kSemicolon) { ts.next(); continue; }
    ShapeDef shape = ts.open<ShapeDef>("'(' opening a shape");
    shape.name = ts.expect_word("a shape name").text;
    shape.file = file;
    while (ts.peek().kind == Token::kOpen) {
      ts.next();
      SetDef set;
      const Token& type = ts.expect_word("a fuzzy set type (TRI TOL TOR DIV TRA REC SNG) or CIRCULAR");
      if (type.text == "CIRCULAR") {
        parse_circular(ts, type, shape);
        continue;
      }
      set.type = type.text;
      set.line = type.line;
      set.column = type.column;
      const int arity = fuzzy_set_arity(set.type);
      if (arity < 0)
        ts.fail(type, "unknown fuzzy set type '" + set.type + "' (expected TRI TOL TOR DIV TRA REC SNG)");
      ts.expect(Token::kOpen, "'(' before the label of the " + set.type + " set");
      set.label = ts.expect_word("a fuzzy set label").text;
      while (ts.peek().kind == Token::kWord) set.params.push_back(ts.expect_number("a number"));
      if (static_cast<int>(set.params.size()) != arity)
        ts.fail(ts.peek(), set.type + " takes " + std::to_string(arity) + " values, got " +
                               std::to_string(set.params.size()));
      ts.expect(Token::kClose, "')' after the values of " + set.label);
      ts.expect(Token::kClose, "')' closing the " + set.type + " set");
      shape.sets.push_back(std::move(set));
    }
    ts.expect(Token::kClose, "'(' of a fuzzy set or ')' closing shape " + shape.name);
    out.push_back(std::move(shape));
  }
  return out;
}

std::vector<AssociationDef> parse_associations(const std::string& text, const std::string& file) {
  TokenStream ts(tokenize(text, true, false), file);  // no #( ... ; block comments here
  std::vector<AssociationDef> out;
  while (!ts.at_end()) {
    if (ts.peek().kind == Token::kSemicolon) { ts.next(); continue; }
    AssociationDef a = ts.open<AssociationDef>("'(' opening an association");
    a.name = ts.expect_word("a datum or action name").text;
    a.file = file;
    a.shape = ts.expect_word("a shape name").text;
    ts.expect(Token::kClose, "')' closing the association of " + a.name);
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace mrt::brian
