#include "mrt_brian/rule_parser.h"

#include "mrt_brian/lexer.h"
#include "mrt_brian/predicate_parser.h"

namespace mrt::brian {

std::vector<RuleDef> parse_rules(const std::string& text, const std::string& file) {
  TokenStream ts(tokenize(text), file);
  std::vector<RuleDef> out;
  while (!ts.at_end()) {
    RuleDef r;
    r.start_line = ts.peek().line;
    if (ts.peek().kind != Token::kOpen)
      ts.fail(ts.peek(), "expected '(' starting a rule precondition, got " + describe(ts.peek()));
    r.precondition = parse_expression(ts);
    ts.expect(Token::kArrow, "'=>' after the rule precondition");
    // An action is '(' word word ')'; anything else opening with '(' is the
    // precondition of the next rule: the ';' of this one is missing.
    while (ts.peek().kind == Token::kOpen) {
      if (!r.actions.empty() && !(ts.peek(1).kind == Token::kWord && ts.peek(2).kind == Token::kWord &&
                                  ts.peek(3).kind == Token::kClose))
        ts.fail(ts.peek(), "expected ';' after rule (rule starting at line " + std::to_string(r.start_line) +
                               "), got " + describe(ts.peek()));
      ts.next();
      ActionDef a;
      const Token& name = ts.expect_word("an action name");
      a.line = name.line;
      a.column = name.column;
      if (name.text.rfind("&DEL.", 0) == 0) {
        a.del = true;
        a.action = name.text.substr(5);
        if (a.action.empty()) ts.fail(name, "expected an action name after &DEL.");
      } else if (name.text[0] == '&') {
        ts.fail(name, "expected an action name or &DEL.<Action>, got '" + name.text + "'");
      } else {
        a.action = name.text;
      }
      a.label = ts.expect_word("an action label after " + name.text).text;
      ts.expect(Token::kClose, "')' closing the action " + name.text);
      r.actions.push_back(std::move(a));
    }
    if (r.actions.empty())
      ts.fail(ts.peek(), "expected '(' of an action after '=>', got " + describe(ts.peek()));
    const Token& semi = ts.peek();
    if (semi.kind != Token::kSemicolon)
      ts.fail(semi, "expected ';' after rule (rule starting at line " + std::to_string(r.start_line) + "), got " +
                        describe(semi));
    r.line = semi.line;
    ts.next();
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace mrt::brian
