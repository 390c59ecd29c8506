#include "mrt_brian/predicate_parser.h"

namespace mrt::brian {

namespace {

void set_proposal(TokenStream& ts, const Token& t, ExprAst& e) {
  // &Behaviour.Action.Label
  const std::string body = t.text.substr(1);
  const auto p1 = body.find('.');
  const auto p2 = p1 == std::string::npos ? p1 : body.find('.', p1 + 1);
  if (p1 == std::string::npos || p2 == std::string::npos || p1 == 0 || p2 == p1 + 1 ||
      p2 + 1 >= body.size() || body.find('.', p2 + 1) != std::string::npos)
    ts.fail(t, "expected &Behaviour.Action.Label, got '" + t.text + "'");
  e.kind = ExprAst::kProposal;
  e.name = body.substr(0, p1);
  e.action = body.substr(p1 + 1, p2 - p1 - 1);
  e.label = body.substr(p2 + 1);
}

constexpr int kMaxDepth = 256;  // deeper nesting would only exhaust the stack
thread_local int depth = 0;
struct DepthGuard {
  DepthGuard() { ++depth; }
  ~DepthGuard() { --depth; }
};
}  // namespace

ExprAst parse_expression(TokenStream& ts) {
  DepthGuard guard;
  if (depth > kMaxDepth) ts.fail(ts.peek(), "expression nested deeper than " + std::to_string(kMaxDepth) + " levels");
  ExprAst e = ts.open<ExprAst>("'(' opening an expression");
  const Token& head = ts.expect_word("AND, OR, NOT, D, P or a predicate name");
  if (head.text == "AND" || head.text == "OR") {
    e.kind = head.text == "AND" ? ExprAst::kAnd : ExprAst::kOr;
    while (ts.peek().kind == Token::kOpen) e.args.push_back(parse_expression(ts));
    if (e.args.size() < 2)
      ts.fail(ts.peek(), head.text + " needs two operands, got " + std::to_string(e.args.size()));
  } else if (head.text == "NOT") {
    e.kind = ExprAst::kNot;
    if (ts.peek().kind != Token::kOpen) ts.fail(ts.peek(), "expected '(' of the NOT operand, got " + describe(ts.peek()));
    e.args.push_back(parse_expression(ts));
  } else if (head.text == "D") {
    e.kind = ExprAst::kDatum;
    e.name = ts.expect_word("a datum name after D").text;
    e.label = ts.expect_word("a fuzzy label after the datum name").text;
  } else if (head.text == "P") {
    const Token& n = ts.expect_word("a predicate name after P");
    if (!n.text.empty() && n.text[0] == '&') set_proposal(ts, n, e);
    else { e.kind = ExprAst::kPredicate; e.name = n.text; }
  } else if (head.text[0] == '&') {
    set_proposal(ts, head, e);
  } else {
    e.kind = ExprAst::kPredicate;
    e.name = head.text;
  }
  ts.expect(Token::kClose, "')' closing the expression opened at line " + std::to_string(e.line));
  return e;
}

std::vector<DefinitionDef> parse_definitions(const std::string& text, const std::string& file) {
  TokenStream ts(tokenize(text), file);
  std::vector<DefinitionDef> out;
  while (!ts.at_end()) {
    const Token& name = ts.expect_word("a name at the start of a definition");
    DefinitionDef d;
    d.name = name.text;
    d.file = file;
    d.line = name.line;
    d.column = name.column;
    ts.expect(Token::kEquals, "'=' after " + d.name);
    if (ts.peek().kind != Token::kOpen)
      ts.fail(ts.peek(), "expected '(' starting the definition of " + d.name + ", got " + describe(ts.peek()));
    d.expr = parse_expression(ts);
    ts.expect(Token::kSemicolon, "';' after the definition of " + d.name);
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace mrt::brian
