#include "mrt_murea/percept_csv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "mrt_common/csv.h"
#include "mrt_common/parse_error.h"

namespace mrt::murea {

using mrt::common::CsvReader;
using mrt::common::CsvRow;
using mrt::common::ParseError;

namespace {

const std::vector<std::string> kColumns{"frame", "class", "color", "distance", "bearing", "reliability"};

// A number; nan and inf are returned as such (the caller drops them).
double parse_number(const CsvReader& csv, const CsvRow& row, std::size_t col) {
  const std::string& s = row.fields[col];
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || (errno == ERANGE && std::isfinite(v) && v != 0.0))
    throw ParseError(csv.file(), row.line, row.columns[col],
                     "expected a number in column '" + kColumns[col] + "', got '" + s + "'");
  return v;
}

}  // namespace

std::vector<PerceptFrame> read_percept_csv(std::istream& in, const std::string& file) {
  const CsvReader csv(in, file);
  csv.require_header(kColumns);
  std::vector<PerceptFrame> frames;
  std::map<std::string, std::size_t> index;
  for (const CsvRow& row : csv.rows()) {
    const std::string& id = row.fields[0];
    if (id.empty()) throw ParseError(file, row.line, row.columns[0], "expected a frame id");
    const double distance = parse_number(csv, row, 3), bearing = parse_number(csv, row, 4),
                 reliability = parse_number(csv, row, 5);
    auto [it, fresh] = index.emplace(id, frames.size());
    if (fresh) frames.push_back({id, row.line, {}, {}});
    PerceptFrame& f = frames[it->second];
    const auto cls = parse_feature_class(row.fields[1]);
    if (!cls) {
      ++f.dropped.unknown_class;
    } else if (!std::isfinite(distance) || !std::isfinite(bearing) || !std::isfinite(reliability)) {
      ++f.dropped.non_finite;
    } else if (distance < 0.0 || !(reliability > 0.0) || reliability > 1.0) {
      ++f.dropped.out_of_range;
    } else {
      f.percepts.push_back({*cls, row.fields[2], distance, bearing, reliability});
    }
  }
  return frames;
}

std::vector<PerceptFrame> load_percept_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  return read_percept_csv(in, path);
}

void write_result_header(std::ostream& out) {
  out << "frame,x,y,theta,evidence,ambiguous,alt_x,alt_y,alt_theta,alt_evidence,time_ms\n";
}

void write_result_row(std::ostream& out, const std::string& frame, const Result& r) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(4) << frame << ',' << r.estimate.mean.x << ',' << r.estimate.mean.y << ','
    << std::setprecision(5) << r.estimate.mean.theta << ',' << std::setprecision(4) << r.best.evidence << ','
    << (r.ambiguous ? 1 : 0) << ',';
  if (r.alternative)
    s << r.alternative->pose.x << ',' << r.alternative->pose.y << ',' << std::setprecision(5)
      << r.alternative->pose.theta << ',' << std::setprecision(4) << r.alternative->evidence;
  else
    s << ",,,";
  s << ',' << std::setprecision(3) << r.time_ms << '\n';
  out << s.str();
}

}  // namespace mrt::murea
