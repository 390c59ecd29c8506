#include "mrt_spike/movingai.h"

#include <fstream>
#include <sstream>

#include "mrt_common/parse_error.h"

namespace mrt::spike {

using mrt::common::ParseError;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

int header_int(const std::vector<std::string>& lines, size_t i, const std::string& key,
               const std::string& name) {
  std::istringstream in(i < lines.size() ? lines[i] : "");
  std::string k;
  long v = 0;
  std::string rest;
  if (!(in >> k) || k != key || !(in >> v) || (in >> rest) || v <= 0 || v > 1000000)
    throw ParseError(name, static_cast<int>(i) + 1, 0,
                     "expected '" + key + " <positive integer>'");
  return static_cast<int>(v);
}

}  // namespace

OccupancyGrid parse_movingai_map(const std::string& text, const std::string& name) {
  const std::vector<std::string> lines = split_lines(text);
  if (lines.empty() || lines[0].rfind("type", 0) != 0)
    throw ParseError(name, 1, 0, "expected 'type octile'");
  const int h = header_int(lines, 1, "height", name);
  const int w = header_int(lines, 2, "width", name);
  if (lines.size() < 4 || lines[3] != "map") throw ParseError(name, 4, 0, "expected 'map'");
  if (static_cast<long>(w) * h > 100000000L) throw ParseError(name, 2, 0, "map too large");
  OccupancyGrid grid(w, h);
  for (int y = 0; y < h; ++y) {
    const size_t li = 4 + static_cast<size_t>(y);
    const int line_no = static_cast<int>(li) + 1;
    if (li >= lines.size())
      throw ParseError(name, line_no, 0, "expected " + std::to_string(h) + " map rows, got " +
                                             std::to_string(y));
    const std::string& row = lines[li];
    if (static_cast<int>(row.size()) != w)
      throw ParseError(name, line_no, 0, "expected a row of " + std::to_string(w) +
                                             " characters, got " + std::to_string(row.size()));
    for (int x = 0; x < w; ++x) {
      switch (row[x]) {
        case '.': case 'G': case 'S': break;
        case '@': case 'O': case 'T': case 'W': grid.set_blocked(x, y, true); break;
        default:
          throw ParseError(name, line_no, x + 1, std::string("expected one of . G S @ O T W, got '") +
                                                     row[x] + "'");
      }
    }
  }
  return grid;
}

OccupancyGrid load_movingai_map(const std::string& path) {
  return parse_movingai_map(read_file(path), path);
}

std::vector<ScenarioQuery> parse_scenario(const std::string& text, const std::string& name) {
  const std::vector<std::string> lines = split_lines(text);
  {
    std::istringstream in(lines.empty() ? "" : lines[0]);
    std::string k;
    double v = 0;
    if (!(in >> k >> v) || k != "version") throw ParseError(name, 1, 0, "expected 'version <n>'");
  }
  std::vector<ScenarioQuery> out;
  for (size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].find_first_not_of(" \t") == std::string::npos) continue;
    std::istringstream in(lines[i]);
    ScenarioQuery q;
    std::string rest;
    if (!(in >> q.bucket >> q.map >> q.width >> q.height >> q.start.x >> q.start.y >> q.goal.x >>
          q.goal.y >> q.optimal_length) ||
        (in >> rest))
      throw ParseError(name, static_cast<int>(i) + 1, 0,
                       "expected 'bucket map width height start_x start_y goal_x goal_y "
                       "optimal_length'");
    out.push_back(q);
  }
  return out;
}

std::vector<ScenarioQuery> load_scenario(const std::string& path) {
  return parse_scenario(read_file(path), path);
}

std::vector<int> load_indices(const std::string& path) {
  const std::vector<std::string> lines = split_lines(read_file(path));
  std::vector<int> out;
  for (size_t i = 0; i < lines.size(); ++i) {
    std::string s = lines[i].substr(0, lines[i].find('#'));
    if (s.find_first_not_of(" \t") == std::string::npos) continue;
    std::istringstream in(s);
    int v = -1;
    std::string rest;
    if (!(in >> v) || (in >> rest) || v < 0)
      throw ParseError(path, static_cast<int>(i) + 1, 0, "expected a non-negative query index");
    out.push_back(v);
  }
  return out;
}

}  // namespace mrt::spike
