// Strict YAML reading shared by the task and map loaders (private header).
#pragma once

#if defined(__GNUC__) && __GNUC__ >= 12 && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdangling-pointer"
#endif
#include <yaml-cpp/yaml.h>
#if defined(__GNUC__) && __GNUC__ >= 12 && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>
#include <string>
#include <sys/stat.h>

#include "mrt_common/parse_error.h"

namespace mrt::scare::detail {

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  YAML::Node load(const std::string& text) const {
    try {
      return YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw common::ParseError(file_, e.mark.line + 1, e.mark.column + 1, e.msg);
    }
  }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& msg) const {
    const YAML::Mark m = n.Mark();
    throw common::ParseError(file_, m.line >= 0 ? m.line + 1 : 0, m.column >= 0 ? m.column + 1 : 0,
                             msg);
  }

  void map(const YAML::Node& n, const std::string& what,
           std::initializer_list<const char*> allowed) const {
    if (!n.IsMap()) fail(n, "expected a map for '" + what + "'");
    std::set<std::string> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node k = it->first;
      const std::string key = k.Scalar();
      bool ok = false;
      std::string list;
      for (const char* a : allowed) {
        ok = ok || key == a;
        list += (list.empty() ? "" : ", ") + std::string(a);
      }
      if (!ok) fail(k, "unknown key '" + key + "' in '" + what + "' (expected one of: " + list + ")");
      if (!seen.insert(key).second) fail(k, "duplicate key '" + key + "' in '" + what + "'");
    }
  }

  double number(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, "expected a number for '" + what + "'");
    try {
      return n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, "expected a number for '" + what + "'");
    }
  }

  double positive(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v > 0.0)) fail(n, "expected '" + what + "' > 0, got " + n.Scalar());
    return v;
  }

  double non_negative(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v >= 0.0)) fail(n, "expected '" + what + "' >= 0, got " + n.Scalar());
    return v;
  }

  std::string string(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, "expected a string for '" + what + "'");
    return n.Scalar();
  }

  bool boolean(const YAML::Node& n, const std::string& what) const {
    try {
      if (n.IsScalar()) return n.as<bool>();
    } catch (const YAML::Exception&) {
    }
    fail(n, "expected true or false for '" + what + "'");
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

inline std::string read_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw common::ParseError(path, 0, 0, "cannot open file");
  if (!S_ISREG(st.st_mode)) throw common::ParseError(path, 0, 0, "not a regular file");
  if (st.st_size > (1 << 20)) throw common::ParseError(path, 0, 0, "file larger than 1 MiB");
  std::ifstream in(path);
  if (!in) throw common::ParseError(path, 0, 0, "cannot open file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace mrt::scare::detail
