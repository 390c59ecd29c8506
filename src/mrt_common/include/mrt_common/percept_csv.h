// The percept CSV format of the stack (ROS-free, header-only): what
// recvision_run writes and murea_localize reads. An optional header row,
//   stamp,class,color,distance,bearing,reliability
// as recvision_run writes it (its contract, issue 14), or with `frame` for
// `stamp` (murea_localize's name for the column, issue 15); a file without
// it is read the same. Then one object per row: the frame's id (a stamp or a name), its class
// (ontology), its colour ("" for none), distance (m) and bearing (rad) in
// the robot's frame, reliability in (0, 1]. Rows of a frame need not be
// adjacent; '#' lines and blank lines are skipped (mrt_common/csv.h).
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "mrt_common/csv.h"
#include "mrt_common/parse_error.h"
#include "mrt_common/percept.h"

namespace mrt::common {

inline const std::vector<std::string>& percept_csv_columns() {
  static const std::vector<std::string> c{"frame", "class", "color", "distance", "bearing", "reliability"};
  return c;
}

/// The first column's other accepted header name; the header written.
inline const std::string& percept_csv_stamp_column() {
  static const std::string s = "stamp";
  return s;
}

inline void write_percept_csv_header(std::ostream& out) {
  const auto& c = percept_csv_columns();
  out << percept_csv_stamp_column();
  for (std::size_t i = 1; i < c.size(); ++i) out << "," << c[i];
  out << "\n";
}

/// One row (distance to 0.1 mm, bearing to 10 urad, reliability to 0.001);
/// nothing for an object without a position.
inline void write_percept_csv_row(std::ostream& out, const std::string& frame, const PerceptObject& o) {
  const auto p = polar(o);
  if (!p) return;
  char buf[96];
  std::snprintf(buf, sizeof buf, ",%.4f,%.5f,%.3f\n", p->distance, p->bearing, p->reliability);
  out << frame << ',' << o.membership_class << ',' << o.symbol("color") << buf;
}

/// The objects of one frame of a percept CSV, in file order.
struct PerceptCsvFrame {
  std::string id;
  int line = 0;  // of the frame's first row
  std::vector<PerceptObject> objects;
};

/// Reads a percept CSV (these columns; the header row optional). Frames come
/// out in order of first appearance. Throws ParseError (file:line:column)
/// on a malformed row: wrong field count, empty frame id, a field that is
/// not a number. nan and inf are read as such (the consumer decides).
inline std::vector<PerceptCsvFrame> read_percept_csv(std::istream& in, const std::string& file) {
  const CsvReader csv(in, file, percept_csv_columns(), {percept_csv_stamp_column()});
  // Without a header row, a bad first row may be a misspelt header: say so.
  const int first_line = csv.has_header_row() || csv.rows().empty() ? -1 : csv.rows().front().line;
  std::string header;
  for (const auto& c : percept_csv_columns()) header += (header.empty() ? "" : ",") + c;
  auto number = [&](const CsvRow& row, std::size_t col) {
    const std::string& s = row.fields[col];
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || (errno == ERANGE && std::isfinite(v) && v != 0.0))
      throw ParseError(file, row.line, row.columns[col],
                       "expected a number in column '" + percept_csv_columns()[col] + "', got '" + s + "'" +
                           (row.line == first_line ? " (a header row is exactly '" + header + "', or with '" +
                                                           percept_csv_stamp_column() + "' first)"
                                                     : ""));
    return v;
  };
  std::vector<PerceptCsvFrame> frames;
  std::map<std::string, std::size_t> index;
  for (const CsvRow& row : csv.rows()) {
    const std::string& id = row.fields[0];
    if (id.empty()) throw ParseError(file, row.line, row.columns[0], "expected a frame id");
    const double distance = number(row, 3), bearing = number(row, 4), reliability = number(row, 5);
    auto [it, fresh] = index.emplace(id, frames.size());
    if (fresh) frames.push_back({id, row.line, {}});
    PerceptObject o("", row.fields[1]);
    o.set("distance", distance, 0.0, reliability).set("bearing", bearing, 0.0, reliability);
    o.set_symbol("color", row.fields[2]);
    frames[it->second].objects.push_back(std::move(o));
  }
  return frames;
}

inline std::vector<PerceptCsvFrame> load_percept_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  return read_percept_csv(in, path);
}

}  // namespace mrt::common
