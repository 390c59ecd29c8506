// Tokenizer shared by the Mr. BRIAN file parsers: parentheses, '=', '=>',
// ';' and words; '#' comments to end of line and '#( ... ;' block comments.
// Blanks are space, tab, CR, LF, FF, VT and the UTF-8 no-break space.
#pragma once

#include <string>
#include <vector>

namespace mrt::brian {

struct Token {
  enum Kind { kOpen, kClose, kEquals, kArrow, kSemicolon, kWord, kEnd };
  Kind kind = kEnd;
  std::string text;
  int line = 0;
  int column = 0;
};

/// Human-readable form of a token for error messages.
std::string describe(const Token& t);

/// Splits `text` into tokens; the last one is kEnd. `block_comments` enables
/// '#( ... ;' (predicate, CANDO, WANT and rule files); `comments` enables '#'.
std::vector<Token> tokenize(const std::string& text, bool comments = true,
                            bool block_comments = true);

/// A `#( ... ;` block comment: the line of its '#', the line of the ';'
/// that ends it (or of the end of the text), and whether it contains '='
/// (`swallows`: it ate a definition `Name = ...;`) or '=>' (`rule`).
struct BlockComment {
  int line = 0, end_line = 0;
  bool swallows = false, rule = false;
};
/// The block comments of a predicate, CANDO, WANT or rule file, found as
/// tokenize() skips them.
std::vector<BlockComment> find_block_comments(const std::string& text);

/// Cursor over a token vector that throws mrt::common::ParseError.
class TokenStream {
 public:
  TokenStream(std::vector<Token> tokens, std::string file)
      : tokens_(std::move(tokens)), file_(std::move(file)) {}
  const Token& peek(std::size_t ahead = 0) const;
  const Token& next();
  bool at_end() const { return peek().kind == Token::kEnd; }
  /// Consumes a token of kind `k` or throws "expected <what>".
  const Token& expect(Token::Kind k, const std::string& what);
  const Token& expect_word(const std::string& what) { return expect(Token::kWord, what); }
  double expect_number(const std::string& what);
  /// Consumes the '(' opening an element (or throws "expected <what>") and
  /// returns a `Def` whose line and column are those of the '('.
  template <typename Def>
  Def open(const std::string& what) {
    const Token& t = expect(Token::kOpen, what);
    Def def;
    def.line = t.line;
    def.column = t.column;
    return def;
  }
  [[noreturn]] void fail(const Token& at, const std::string& message) const;
  const std::string& file() const { return file_; }

 private:
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  std::string file_;
};

/// Reads `text`, all of it, as a finite double into `*value`; false if it
/// is not one (empty, trailing characters, out of range, inf, nan).
bool parse_number(const std::string& text, double* value);

/// Reads a whole regular file of at most 64 MiB; throws
/// ParseError(path, 0, 0, "cannot open file ...") otherwise.
std::string read_text_file(const std::string& path);

}  // namespace mrt::brian
