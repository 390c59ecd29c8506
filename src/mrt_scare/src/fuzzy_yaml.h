// Private: the `fuzzy:` section shared by the activity and task files, and
// where a YAML scalar's text starts in its file.
#pragma once

#include <memory>
#include <sstream>
#include <string>

#include "mrt_scare/fuzzy_model.h"
#include "yaml_util.h"

namespace mrt::scare::detail {

/// Where a scalar's text starts: a block scalar (| or >) on the next line.
inline TextOrigin origin(const YAML::Node& n, const std::string& file, const std::string& text) {
  TextOrigin o{file, n.Mark().line + 1, n.Mark().column + 1};
  std::istringstream in(text);
  std::string line, next;
  for (int i = 0; i <= n.Mark().line && std::getline(in, line); ++i) {
  }
  const auto col = static_cast<std::size_t>(n.Mark().column);
  if (col < line.size() && (line[col] == '|' || line[col] == '>')) {
    std::getline(in, next);
    o.indent = static_cast<int>(next.find_first_not_of(' '));
    if (o.indent < 0) o.indent = 0;
    o.line += 1;
    o.column = o.indent + 1;
  } else if (col < line.size() && (line[col] == '"' || line[col] == '\'')) {
    o.column += 1;
  }
  return o;
}

/// `fuzzy: {shapes, data, predicates}` -> a FuzzyModel.
inline std::shared_ptr<FuzzyModel> parse_fuzzy(const YamlReader& y, const YAML::Node& fz, const std::string& text) {
  y.map(fz, "fuzzy", {"shapes", "data", "predicates"});
  const YAML::Node sh = y.required(fz, "shapes", "fuzzy"), da = y.required(fz, "data", "fuzzy");
  const YAML::Node pr = fz["predicates"];
  const std::string& file = y.file();
  return std::make_shared<FuzzyModel>(y.string(sh, "shapes"), origin(sh, file, text), y.string(da, "data"),
                                      origin(da, file, text), pr ? y.string(pr, "predicates") : "",
                                      pr ? origin(pr, file, text) : TextOrigin{file, 1, 1, 0});
}

}  // namespace mrt::scare::detail
