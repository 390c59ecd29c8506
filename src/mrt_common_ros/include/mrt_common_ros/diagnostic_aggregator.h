// The core of diagnostic_aggregator_node (ROS-free; src/diagnostic_aggregator.cpp,
// compiled into the node and its gtest, needs yaml-cpp): groups the statuses
// heard on /diagnostics under the paths of a configuration in the
// diagnostic_aggregator YAML format, GenericAnalyzer entries only:
//
//   analyzers:
//     sensors:                                   # the analyzer's key
//       type: diagnostic_aggregator/GenericAnalyzer
//       path: Sensors                            # -> "/Sensors", "/Sensors/<item>"
//       startswith: [robot1/sonar_crisp]         # a string or a list of strings
//       contains: [sonar]
//       name: ["robot1/airboard: AIRBoard link"] # exact status names
//       expected: ["robot1/brian: Mr. BRIAN"]    # exact names, stale while missing
//       remove_prefix: [robot1/]                 # taken off the item's name
//       timeout: 5.0                             # s; stale after; <= 0: never
//   pub_rate: 1.0                                # optional (the node's ~pub_rate wins)
//   base_path: ""                                # optional prefix of every path
//
// A status belongs to every analyzer one of whose name / startswith /
// contains / expected entries matches it. An item is "<path>/<name>": the
// status name without its first matching remove_prefix, leading ' ', ':'
// and '/' dropped, any other '/' turned into ' ' (the path's separator).
// Each analyzer's parent "<path>" has the worst level of its items (STALE,
// 3, when an item passed its timeout or an expected one never arrived; no
// item at all: STALE). Statuses no analyzer matches go under "/Other" and
// leave it after `other_timeout` s of silence. The top level is the worst
// parent.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mrt::ros_common {

/// One diagnostic status, as diagnostic_msgs/DiagnosticStatus.
struct AggStatus {
  std::uint8_t level = 0;  // 0 OK, 1 WARN, 2 ERROR, 3 STALE
  std::string name, message, hardware_id;
  std::vector<std::pair<std::string, std::string>> values;
};

constexpr std::uint8_t kAggOk = 0, kAggWarn = 1, kAggError = 2, kAggStale = 3;

struct AnalyzerSpec {
  std::string key;   // the analyzer's key under `analyzers`
  std::string path;  // normalized: "/Sensors" (base_path included)
  std::vector<std::string> startswith, contains, name, expected, remove_prefix;
  double timeout = 5.0;  // s; <= 0: never stale
};

struct AggregatorConfig {
  std::vector<AnalyzerSpec> analyzers;
  double pub_rate = 1.0;  // Hz
  std::string base_path;  // normalized: "" or "/Robot"
};

/// Parses the YAML text of `file` (the name is for the messages only);
/// every error is a mrt::common::ParseError "file:line:column: message"
/// naming the key and what was expected.
AggregatorConfig parse_aggregator_config(const std::string& text, const std::string& file);
/// Reads and parses `file`.
AggregatorConfig load_aggregator_config(const std::string& file);

/// True when the analyzer takes the status named `name`.
bool analyzer_matches(const AnalyzerSpec& a, const std::string& name);
/// The item's name under the analyzer's path (see the file comment).
std::string item_name(const AnalyzerSpec& a, const std::string& name);

/// "OK", "Warning", "Error", "Stale" (levels above 3 read as "Stale").
const char* level_word(std::uint8_t level);

struct AggOutput {
  std::vector<AggStatus> statuses;  // each parent followed by its items
  AggStatus toplevel;               // the worst parent's level
};

class Aggregator {
 public:
  /// `other_timeout`: s of silence after which an item leaves /Other.
  explicit Aggregator(AggregatorConfig config, double other_timeout = 5.0);

  /// A status heard at `now` (s).
  void add(const AggStatus& s, double now);
  /// The aggregated statuses at `now` (s); drops /Other's silent items.
  AggOutput aggregate(double now);

  const AggregatorConfig& config() const { return config_; }

 private:
  struct Item {
    AggStatus status;
    double time = 0.0;
  };
  AggStatus parent(const std::string& path, const std::vector<AggStatus>& items) const;

  AggregatorConfig config_;
  double other_timeout_;
  std::vector<std::map<std::string, Item>> items_;  // per analyzer, by status name
  std::map<std::string, Item> other_;
};

}  // namespace mrt::ros_common
