// CSV reading and writing for the command-line tools (ROS-free, header-only).
//
// Format: first line is a header of column names, then one record per line,
// fields separated by ',', no quoting; blank lines and lines starting with
// '#' are skipped; surrounding spaces of a field are ignored. A format with
// fixed columns may leave the header out (the three-argument constructor).
#pragma once

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mrt_common/parse_error.h"

namespace mrt::common {

/// One data record of a CSV file, with where it came from.
struct CsvRow {
  int line = 0;
  std::vector<std::string> fields;
  std::vector<int> columns;  // 1-based column of each field's first character
};

class CsvReader {
 public:
  /// Reads a whole stream; `file` is the name used in error messages.
  /// Throws ParseError on a missing header or a record with the wrong number
  /// of fields.
  CsvReader(std::istream& in, std::string file) : file_(std::move(file)) { parse(in); }

  /// Reads a format of fixed columns, `columns`, whose header row is
  /// optional: a first line equal to `columns` is the header, any other
  /// first line is already a record.
  CsvReader(std::istream& in, std::string file, std::vector<std::string> columns)
      : file_(std::move(file)), header_(std::move(columns)), optional_header_(true) {
    parse(in);
  }

  /// The same, where the first column's header may also be spelt
  /// `first_aliases` (a format two tools name differently); the reader's
  /// column names are `columns` whichever spelling the file used.
  CsvReader(std::istream& in, std::string file, std::vector<std::string> columns,
            std::vector<std::string> first_aliases)
      : file_(std::move(file)), header_(std::move(columns)), first_aliases_(std::move(first_aliases)),
        optional_header_(true) {
    parse(in);
  }

  /// Opens and reads a file; throws ParseError if it cannot be opened.
  static CsvReader open(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw ParseError(path, 0, 0, "cannot open file");
    return CsvReader(in, path);
  }

  const std::string& file() const { return file_; }
  const std::vector<std::string>& header() const { return header_; }
  /// Whether the file had a header row (always, but for an optional one).
  bool has_header_row() const { return header_line_ > 0; }
  const std::vector<CsvRow>& rows() const { return rows_; }

  /// Index of a header column; throws ParseError naming the header line if
  /// it is absent.
  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header_.size(); ++i)
      if (header_[i] == name) return i;
    throw ParseError(file_, header_line_, 0, "expected a column named '" + name + "' in the header");
  }

  /// Throws unless the header is exactly `names` (in order).
  void require_header(const std::vector<std::string>& names) const {
    if (header_ == names) return;
    std::string want;
    for (const auto& n : names) want += (want.empty() ? "" : ",") + n;
    throw ParseError(file_, header_line_, 1, "expected header '" + want + "'");
  }

  /// Field `col` of `row` as a finite double; ParseError otherwise.
  double number(const CsvRow& row, std::size_t col) const {
    const std::string& s = row.fields.at(col);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      throw ParseError(file_, row.line, row.columns.at(col),
                       "expected a number in column '" + header_.at(col) + "', got '" + s + "'");
    return v;
  }

  /// Field `col` of `row` as a 64-bit integer; ParseError otherwise.
  long long integer(const CsvRow& row, std::size_t col) const {
    const std::string& s = row.fields.at(col);
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE)
      throw ParseError(file_, row.line, row.columns.at(col),
                       "expected an integer in column '" + header_.at(col) + "', got '" + s + "'");
    return v;
  }

 private:
  static std::vector<std::string> split(const std::string& line, std::vector<int>* cols) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      const std::size_t stop = comma == std::string::npos ? line.size() : comma;
      std::size_t b = start, e = stop;
      while (b < e && (line[b] == ' ' || line[b] == '\t')) ++b;
      while (e > b && (line[e - 1] == ' ' || line[e - 1] == '\t' || line[e - 1] == '\r')) --e;
      out.push_back(line.substr(b, e - b));
      if (cols) cols->push_back(static_cast<int>(b) + 1);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return out;
  }

  bool is_header(const std::vector<std::string>& fields) const {
    if (fields == header_) return true;
    if (fields.empty() || fields.size() != header_.size()) return false;
    return std::find(first_aliases_.begin(), first_aliases_.end(), fields.front()) != first_aliases_.end() &&
           std::equal(fields.begin() + 1, fields.end(), header_.begin() + 1);
  }

  void parse(std::istream& in) {
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      std::size_t first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#') continue;
      if (optional_header_ && rows_.empty() && header_line_ == 0 && is_header(split(line, nullptr))) {
        header_line_ = n;
        continue;
      }
      if (header_.empty()) {
        header_ = split(line, nullptr);
        header_line_ = n;
        continue;
      }
      CsvRow row;
      row.line = n;
      row.fields = split(line, &row.columns);
      if (row.fields.size() != header_.size())
        throw ParseError(file_, n, 0,
                         "expected " + std::to_string(header_.size()) + " fields, got " +
                             std::to_string(row.fields.size()));
      rows_.push_back(std::move(row));
    }
    if (header_.empty()) throw ParseError(file_, n > 0 ? 1 : 0, 0, "expected a header line");
  }

  std::string file_;
  std::vector<std::string> header_;
  std::vector<std::string> first_aliases_;
  int header_line_ = 0;
  bool optional_header_ = false;
  std::vector<CsvRow> rows_;
};

/// Writes a header, then rows of numbers with full round-trip precision.
class CsvWriter {
 public:
  CsvWriter(std::ostream& out, const std::vector<std::string>& header) : out_(out) {
    write_fields(header);
    out_ << std::setprecision(std::numeric_limits<double>::max_digits10);
  }

  void row(const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << values[i];
    out_ << '\n';
  }

  void row_fields(const std::vector<std::string>& fields) { write_fields(fields); }

 private:
  void write_fields(const std::vector<std::string>& f) {
    for (std::size_t i = 0; i < f.size(); ++i) out_ << (i ? "," : "") << f[i];
    out_ << '\n';
  }
  std::ostream& out_;
};

}  // namespace mrt::common
