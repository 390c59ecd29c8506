#include "mrt_brian/crisp_input.h"

#include <sstream>

#include "mrt_brian/lexer.h"
#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

std::vector<CrispDataList> parse_crisp_input(const std::string& text, const std::string& file) {
  std::vector<CrispDataList> cycles;
  CrispDataList current;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    if (f.empty()) continue;
    const int col = static_cast<int>(line.find(f[0])) + 1;
    if (f[0] == "---") {
      if (f.size() != 1) throw ParseError(file, lineno, col, "expected nothing after '---'");
      cycles.push_back(std::move(current));
      current.clear();
      continue;
    }
    if (f.size() < 2 || f.size() > 3)
      throw ParseError(file, lineno, col, "expected 'NAME VALUE [RELIABILITY]', got " + std::to_string(f.size()) + " fields");
    CrispDatum d;
    d.name = f[0];
    if (!parse_number(f[1], &d.value))
      throw ParseError(file, lineno, static_cast<int>(line.find(f[1], static_cast<std::size_t>(col))) + 1,
                       "expected a number as the value of " + d.name + ", got '" + f[1] + "'");
    if (f.size() == 3 && (!parse_number(f[2], &d.reliability) || d.reliability < 0.0 || d.reliability > 1.0))
      throw ParseError(file, lineno, static_cast<int>(line.rfind(f[2])) + 1,
                       "expected a reliability in [0, 1] for " + d.name + ", got '" + f[2] + "'");
    current.push_back(std::move(d));
  }
  if (!current.empty()) cycles.push_back(std::move(current));
  return cycles;
}

}  // namespace mrt::brian
