// The typed error every MRT parser throws (ROS-free, header-only).
#pragma once

#include <stdexcept>
#include <string>

namespace mrt::common {

/// A configuration or data file error: names file, line, column (1-based;
/// 0 when unknown) and what was expected. what() reads
/// "file:line:column: message" (column omitted when 0, line too when 0).
class ParseError : public std::runtime_error {
 public:
  ParseError(std::string file, int line, int column, std::string message)
      : std::runtime_error(format(file, line, column, message)),
        file_(std::move(file)), line_(line), column_(column), message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& f, int l, int c, const std::string& m) {
    std::string s = f;
    if (l > 0) s += ":" + std::to_string(l);
    if (l > 0 && c > 0) s += ":" + std::to_string(c);
    return s + ": " + m;
  }
  std::string file_;
  int line_;
  int column_;
  std::string message_;
};

}  // namespace mrt::common
