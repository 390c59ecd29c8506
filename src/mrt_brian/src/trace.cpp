#include "mrt_brian/trace.h"

#include <algorithm>
#include <charconv>

namespace mrt::brian {

namespace {
// One trace line: a tag, then words and numbers separated by single spaces,
// numbers exactly as printf's "%f" writes them (std::to_chars, fixed, 6
// decimals: the same digits, "nan", "inf", and the sign of -0), without
// printf's format parsing.
class Line {
 public:
  explicit Line(const char* tag) : s_(tag) { s_.reserve(64); }
  Line& word(const std::string& w) {
    s_ += ' ';
    s_ += w;
    return *this;
  }
  Line& num(double v) {
    char buf[400];  // the longest: -DBL_MAX, 309 digits + ".000000"
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6);
    s_ += ' ';
    s_.append(buf, r.ptr);
    return *this;
  }
  Line& integer(int v) {
    char buf[16];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    s_ += ' ';
    s_.append(buf, r.ptr);
    return *this;
  }
  operator std::string() { return std::move(s_); }  // hands the text over, once

 private:
  std::string s_;
};
}  // namespace

std::vector<std::string> CycleTrace::lines(bool full) const {
  std::vector<std::string> out;
  out.reserve(commands.size() + (full ? crisp.size() + fuzzy.size() + predicates.size() + cando.size() +
                                            want.size() + rules.size() + proposals.size() + actions.size()
                                      : 0));
  for (const auto& c : commands) out.push_back(Line("CMD").word(c.name).num(c.value));
  if (full) {
    for (const auto& c : crisp) out.push_back(Line("CRISP").word(c.name).num(c.value).num(c.reliability));
    for (const auto& f : fuzzy)
      out.push_back(Line("FUZZY").word(f.datum).word(f.label).num(f.v.value).num(f.v.reliability));
    for (const auto& p : predicates) out.push_back(Line("PRED").word(p.name).num(p.v.value).num(p.v.reliability));
    for (const auto& p : cando) out.push_back(Line("CANDO").word(p.name).num(p.v.value).num(p.v.reliability));
    for (const auto& p : want) out.push_back(Line("WANT").word(p.name).num(p.v.value));
    for (const auto& r : rules) out.push_back(Line("RULE").word(r.behavior).integer(r.line).num(r.mu));
    for (const auto& p : proposals)
      out.push_back(Line("PACT").word(p.action).word(p.label).word(p.behavior).num(p.mu).num(p.rel));
    for (const auto& a : actions) out.push_back(Line("ACT").word(a.action).word(a.label).num(a.mu));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace mrt::brian
