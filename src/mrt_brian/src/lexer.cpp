#include "mrt_brian/lexer.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

std::string describe(const Token& t) {
  switch (t.kind) {
    case Token::kOpen: return "'('";
    case Token::kClose: return "')'";
    case Token::kEquals: return "'='";
    case Token::kArrow: return "'=>'";
    case Token::kSemicolon: return "';'";
    case Token::kWord: return "'" + t.text + "'";
    case Token::kEnd: return "end of file";
  }
  return "?";
}

std::vector<BlockComment> find_block_comments(const std::string& s) {
  std::vector<BlockComment> out;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = s.size();
  while (i < n) {
    if (s[i] == '\n') ++line;
    if (s[i] != '#') { ++i; continue; }
    if (i + 1 < n && s[i + 1] == '(') {
      BlockComment b;
      b.line = line;
      while (i < n && s[i] != ';') {
        if (s[i] == '\n') ++line;
        if (s[i] == '=') {
          b.swallows = true;
          if (i + 1 < n && s[i + 1] == '>') b.rule = true;
        }
        ++i;
      }
      b.end_line = line;
      out.push_back(b);
      if (i < n) ++i;
    } else {
      while (i < n && s[i] != '\n') ++i;
    }
  }
  return out;
}

std::vector<Token> tokenize(const std::string& s, bool comments, bool block_comments) {
  std::vector<Token> out;
  int line = 1;
  std::size_t line_start = 0;
  std::size_t i = 0;
  const std::size_t n = s.size();
  auto blank_len = [&](std::size_t k) -> std::size_t {
    const unsigned char c = static_cast<unsigned char>(s[k]);
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') return 1;
    if (c == 0xC2 && k + 1 < n && static_cast<unsigned char>(s[k + 1]) == 0xA0) return 2;
    return 0;
  };
  auto newline = [&](std::size_t k) { ++line; line_start = k + 1; };
  while (i < n) {
    const char c = s[i];
    if (std::size_t b = blank_len(i)) {
      if (c == '\n') newline(i);
      i += b;
      continue;
    }
    const int col = static_cast<int>(i - line_start) + 1;
    if (c == '#' && comments) {
      if (block_comments && i + 1 < n && s[i + 1] == '(') {
        while (i < n && s[i] != ';') {
          if (s[i] == '\n') newline(i);
          ++i;
        }
        if (i < n) ++i;
      } else {
        while (i < n && s[i] != '\n') ++i;
      }
      continue;
    }
    Token t;
    t.line = line;
    t.column = col;
    if (c == '(') { t.kind = Token::kOpen; ++i; }
    else if (c == ')') { t.kind = Token::kClose; ++i; }
    else if (c == ';') { t.kind = Token::kSemicolon; ++i; }
    else if (c == '=') {
      if (i + 1 < n && s[i + 1] == '>') { t.kind = Token::kArrow; i += 2; }
      else { t.kind = Token::kEquals; ++i; }
    } else {
      t.kind = Token::kWord;
      const std::size_t start = i;
      while (i < n && !blank_len(i) && s[i] != '(' && s[i] != ')' && s[i] != ';' &&
             s[i] != '=' && !(comments && s[i] == '#'))
        ++i;
      t.text = s.substr(start, i - start);
    }
    out.push_back(std::move(t));
  }
  Token end;
  end.kind = Token::kEnd;
  end.line = line;
  end.column = static_cast<int>(n - line_start) + 1;
  out.push_back(end);
  return out;
}

const Token& TokenStream::peek(std::size_t ahead) const {
  const std::size_t k = pos_ + ahead;
  return k < tokens_.size() ? tokens_[k] : tokens_.back();
}

const Token& TokenStream::next() {
  const Token& t = peek();
  if (pos_ < tokens_.size() - 1) ++pos_;
  return t;
}

const Token& TokenStream::expect(Token::Kind k, const std::string& what) {
  const Token& t = peek();
  if (t.kind != k) fail(t, "expected " + what + ", got " + describe(t));
  return next();
}

double TokenStream::expect_number(const std::string& what) {
  const Token& t = peek();
  double v = 0.0;
  if (t.kind == Token::kWord && parse_number(t.text, &v)) {
    next();
    return v;
  }
  fail(t, "expected " + what + ", got " + describe(t));
}

bool parse_number(const std::string& text, double* value) {
  char* end = nullptr;
  errno = 0;
  *value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0' && errno != ERANGE && std::isfinite(*value);
}

void TokenStream::fail(const Token& at, const std::string& message) const {
  throw ParseError(file_, at.line, at.column, message);
}

std::string read_text_file(const std::string& path) {
  // Configuration files are small regular files: refuse devices, FIFOs and
  // anything that would not fit a rule base.
  constexpr std::uintmax_t kMaxBytes = 64u << 20;
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(st))
    throw ParseError(path, 0, 0, ec && ec != std::errc::no_such_file_or_directory ? "cannot open file: " + ec.message()
                                                                               : std::string("cannot open file"));
  if (!std::filesystem::is_regular_file(st)) throw ParseError(path, 0, 0, "not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw ParseError(path, 0, 0, "cannot open file: " + ec.message());
  if (size > kMaxBytes) throw ParseError(path, 0, 0, "file larger than 64 MiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace mrt::brian
