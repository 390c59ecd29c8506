// Strict YAML reading that turns every error into a file:line:column
// ParseError (ROS-free, header-only).
//
// This header includes <yaml-cpp/yaml.h>: only a package that already
// depends on and links yaml-cpp (pkg_check_modules(YAML_CPP REQUIRED
// yaml-cpp), <depend>yaml-cpp</depend>) may include it. The other
// mrt_common headers stay dependency-free.
#pragma once

// yaml-cpp 0.7's node/impl.h trips GCC 12's -Wdangling-pointer at -O2 (a
// false positive in the library's header, not in its users).
#if defined(__GNUC__) && __GNUC__ >= 12 && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdangling-pointer"
#endif
#include <yaml-cpp/yaml.h>
#if defined(__GNUC__) && __GNUC__ >= 12 && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <sys/stat.h>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <initializer_list>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mrt_common/parse_error.h"

namespace mrt::common {

/// Reads a whole file for a parser. Errors are ParseError(path, 0, 0, ...):
/// `cannot_open` when it cannot be opened. With `max_bytes` > 0 the path
/// must also be a regular file ("not a regular file") of at most
/// `max_bytes` ("file larger than 1 MiB"); with 0 it is read as it is.
inline std::string read_file(const std::string& path, const std::string& cannot_open = "cannot open file",
                             std::size_t max_bytes = 0) {
  if (max_bytes > 0) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) throw ParseError(path, 0, 0, cannot_open);
    if (!S_ISREG(st.st_mode)) throw ParseError(path, 0, 0, "not a regular file");
    if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
      const std::string size = max_bytes % (1u << 20) == 0 ? std::to_string(max_bytes >> 20) + " MiB"
                                                            : std::to_string(max_bytes) + " bytes";
      throw ParseError(path, 0, 0, "file larger than " + size);
    }
  }
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, cannot_open);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Strict reader of one YAML file: every error is a ParseError naming the
/// file and the 1-based line and column of the offending node (0 when
/// yaml-cpp has no mark). Messages are "expected ..." and quote the key.
///
/// Two forms of the value readers:
///  * node form, `number(node, what)`: reads the node, fails on it;
///  * key form, `number(map, key, def)`: reads `map[key]`, `def` when absent.
class YamlReader {
 public:
  using Keys = std::initializer_list<const char*>;

  struct Options {
    /// number() rejects .inf and .nan ("expected a number for ...").
    bool finite_numbers = true;
    /// map() rejects a non-scalar key with "expected a key name in '<what>'";
    /// false reports it as an unknown key '' (mrt_scare's YamlReader).
    bool scalar_keys = true;
  };

  explicit YamlReader(std::string file) : file_(std::move(file)) {}
  YamlReader(std::string file, Options options) : file_(std::move(file)), options_(options) {}

  const std::string& file() const { return file_; }
  const Options& options() const { return options_; }

  /// Parses `text`; a YAML error becomes a ParseError at its mark with the
  /// message `prefix` + yaml-cpp's message.
  YAML::Node load(const std::string& text, const std::string& prefix = "") const {
    try {
      return YAML::Load(text);
    } catch (const YAML::Exception& e) {
      throw error(e, prefix);
    }
  }

  /// The ParseError for a yaml-cpp exception (e.g. a conversion thrown
  /// while reading): its mark, `prefix` + its message.
  ParseError error(const YAML::Exception& e, const std::string& prefix = "") const {
    return at(e.mark, prefix + e.msg);
  }

  /// The ParseError at node `n`.
  ParseError error(const YAML::Node& n, const std::string& msg) const { return at(n.Mark(), msg); }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& msg) const { throw error(n, msg); }

  /// Rejects anything but a map whose keys are all in `allowed`, each once.
  void map(const YAML::Node& n, const std::string& what, Keys allowed) const {
    if (!n.IsMap()) fail(n, "expected a map for '" + what + "'");
    std::set<std::string> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node k = it->first;  // a copy: the iterator yields a temporary
      if (options_.scalar_keys && !k.IsScalar()) fail(k, "expected a key name in '" + what + "'");
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

  /// `m[key]`, failing on `m` when it is absent.
  YAML::Node required(const YAML::Node& m, const char* key, const std::string& what) const {
    const YAML::Node n = m[key];
    if (!n) fail(m, "missing required key '" + std::string(key) + "' in '" + what + "'");
    return n;
  }

  /// True and `v` set when `n` is a scalar that reads as a double
  /// (.inf and .nan included).
  static bool decode(const YAML::Node& n, double& v) {
    return n.IsScalar() && YAML::convert<double>::decode(n, v);
  }

  double number(const YAML::Node& n, const std::string& what) const {
    double v = 0.0;
    if (!decode(n, v) || (options_.finite_numbers && !std::isfinite(v)))
      fail(n, "expected a number for '" + what + "'");
    return v;
  }

  double number(const YAML::Node& m, const char* key, double def) const {
    const YAML::Node n = m[key];
    return n ? number(n, key) : def;
  }

  /// Node form: "expected '<what>' > 0, got <the scalar as written>".
  double positive(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v > 0.0)) fail(n, "expected '" + what + "' > 0, got " + n.Scalar());
    return v;
  }

  /// Node form: "expected '<what>' >= 0, got <the scalar as written>".
  double non_negative(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v >= 0.0)) fail(n, "expected '" + what + "' >= 0, got " + n.Scalar());
    return v;
  }

  /// Key form: `m[key]` (or `def`) with a lower bound (strict or not) and
  /// an optional upper one: "expected '<key>' > lo [and <= hi], got <v>".
  double bounded(const YAML::Node& m, const char* key, double def, double lo, bool strict,
                 double hi = INFINITY) const {
    const YAML::Node n = m[key];
    if (!n) return def;
    const double v = number(n, key);
    if ((strict ? v <= lo : v < lo) || v > hi) {
      std::ostringstream os;
      os << "expected '" << key << "' " << (strict ? "> " : ">= ") << lo;
      if (std::isfinite(hi)) os << " and <= " << hi;
      os << ", got " << v;
      fail(n, os.str());
    }
    return v;
  }
  double positive(const YAML::Node& m, const char* key, double def) const {
    return bounded(m, key, def, 0.0, true);
  }
  double non_negative(const YAML::Node& m, const char* key, double def) const {
    return bounded(m, key, def, 0.0, false);
  }
  double fraction(const YAML::Node& m, const char* key, double def) const {
    return bounded(m, key, def, 0.0, false, 1.0);
  }

  /// An integer in [lo, hi]; the bounds also keep a hostile file from
  /// asking for unbounded memory.
  long long integer(const YAML::Node& n, const std::string& what, long long lo, long long hi) const {
    long long v = 0;
    if (!n.IsScalar() || !YAML::convert<long long>::decode(n, v) || v < lo || v > hi)
      fail(n, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] for '" +
                  what + "'");
    return v;
  }

  /// Exactly `count` numbers in a list.
  std::vector<double> numbers(const YAML::Node& n, const std::string& what, std::size_t count) const {
    if (!n.IsSequence() || n.size() != count)
      fail(n, "expected a list of " + std::to_string(count) + " numbers for '" + what + "'");
    std::vector<double> v;
    for (const YAML::Node& e : n) v.push_back(number(e, what));
    return v;
  }

  /// The list itself, by value (a YAML::Node is a handle): iterating over
  /// `sequence(map["key"], ...)` must not outlive a temporary.
  YAML::Node sequence(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence()) fail(n, "expected a list for '" + what + "'");
    return n;
  }

  std::string string(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, "expected a string for '" + what + "'");
    return n.Scalar();
  }

  /// Key form: `m[key]` as a string; absent: `def`, or a failure when `req`.
  std::string string(const YAML::Node& m, const char* key, const std::string& def, bool req,
                     const std::string& what) const {
    const YAML::Node n = req ? required(m, key, what) : m[key];
    return n ? string(n, key) : def;
  }

  bool boolean(const YAML::Node& n, const std::string& what) const {
    bool v = false;
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) fail(n, "expected true or false for '" + what + "'");
    return v;
  }

  bool boolean(const YAML::Node& m, const char* key, bool def) const {
    const YAML::Node n = m[key];
    return n ? boolean(n, key) : def;
  }

 private:
  ParseError at(const YAML::Mark& m, const std::string& msg) const {
    return ParseError(file_, m.line >= 0 ? m.line + 1 : 0, m.column >= 0 ? m.column + 1 : 0, msg);
  }

  std::string file_;
  Options options_;
};

}  // namespace mrt::common
