#include "mrt_brian/trace.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace mrt::brian {

namespace {
std::string fmt(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string fmt(const char* f, ...) {
  char buf[1024];
  va_list ap;
  va_start(ap, f);
  const int n = std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  if (n < 0) return "";
  if (static_cast<std::size_t>(n) < sizeof buf) return std::string(buf, static_cast<std::size_t>(n));
  std::string big(static_cast<std::size_t>(n) + 1, '\0');
  va_start(ap, f);
  std::vsnprintf(&big[0], big.size(), f, ap);
  va_end(ap);
  big.resize(static_cast<std::size_t>(n));
  return big;
}
}  // namespace

std::vector<std::string> CycleTrace::lines(bool full) const {
  std::vector<std::string> out;
  for (const auto& c : commands) out.push_back(fmt("CMD %s %f", c.name.c_str(), c.value));
  if (full) {
    for (const auto& c : crisp) out.push_back(fmt("CRISP %s %f %f", c.name.c_str(), c.value, c.reliability));
    for (const auto& f : fuzzy)
      out.push_back(fmt("FUZZY %s %s %f %f", f.datum.c_str(), f.label.c_str(), f.v.value, f.v.reliability));
    for (const auto& p : predicates) out.push_back(fmt("PRED %s %f %f", p.name.c_str(), p.v.value, p.v.reliability));
    for (const auto& p : cando) out.push_back(fmt("CANDO %s %f %f", p.name.c_str(), p.v.value, p.v.reliability));
    for (const auto& p : want) out.push_back(fmt("WANT %s %f", p.name.c_str(), p.v.value));
    for (const auto& r : rules) out.push_back(fmt("RULE %s %d %f", r.behavior.c_str(), r.line, r.mu));
    for (const auto& p : proposals)
      out.push_back(fmt("PACT %s %s %s %f %f", p.action.c_str(), p.label.c_str(), p.behavior.c_str(), p.mu, p.rel));
    for (const auto& a : actions) out.push_back(fmt("ACT %s %s %f", a.action.c_str(), a.label.c_str(), a.mu));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace mrt::brian
