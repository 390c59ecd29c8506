#include "mrt_brian/behavior_list_parser.h"

#include <cmath>

#include "mrt_brian/lexer.h"

namespace mrt::brian {

std::vector<BehaviorDef> parse_behavior_list(const std::string& text, const std::string& file) {
  TokenStream ts(tokenize(text, true, false), file);
  std::vector<BehaviorDef> out;
  while (!ts.at_end()) {
    BehaviorDef b = ts.open<BehaviorDef>("'(' opening a behaviour entry");
    const Token& kw = ts.expect_word("'level'");
    if (kw.text != "level") ts.fail(kw, "expected 'level', got '" + kw.text + "'");
    const Token& lv = ts.peek();
    const double level = ts.expect_number("a level number");
    if (level < 1 || level > 1000 || level != std::floor(level))
      ts.fail(lv, "expected a level number >= 1, got '" + lv.text + "'");
    b.level = static_cast<int>(level);
    b.name = ts.expect_word("a behaviour name").text;
    b.file = file;
    b.path = ts.expect_word("the path of the behaviour file").text;
    ts.expect(Token::kClose, "')' closing the entry of " + b.name);
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace mrt::brian
