// The aggregator's core, on hand-worked cases: matching and item names,
// the worst level of a group, stale items, missing expected items, /Other,
// and the configuration errors (file:line:column, key, what was expected).
#include <gtest/gtest.h>

#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_common_ros/diagnostic_aggregator.h"

using namespace mrt::ros_common;

namespace {

const char* const kConfig = R"(
analyzers:
  sensors:
    type: diagnostic_aggregator/GenericAnalyzer
    path: Sensors
    startswith: robot1/sonar
    contains: [laser]
    remove_prefix: robot1/
    timeout: 2.0
  control:
    type: diagnostic_aggregator/GenericAnalyzer
    path: /Control/
    name: ["robot1/brian: Mr. BRIAN"]
    expected: ["robot1/airboard: AIRBoard link"]
    remove_prefix: [robot2/, robot1/]
    timeout: 0
)";

AggStatus status(const std::string& name, std::uint8_t level, const std::string& message = "m") {
  AggStatus s;
  s.name = name;
  s.level = level;
  s.message = message;
  s.hardware_id = "hw";
  s.values = {{"k", "v"}};
  return s;
}

const AggStatus* find(const AggOutput& o, const std::string& name) {
  for (const auto& s : o.statuses)
    if (s.name == name) return &s;
  return nullptr;
}

std::string error_of(const std::string& yaml) {
  try {
    parse_aggregator_config(yaml, "agg.yaml");
  } catch (const mrt::common::ParseError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(AggregatorConfig, ReadsTheGenericAnalyzerEntries) {
  const AggregatorConfig c = parse_aggregator_config(kConfig, "agg.yaml");
  ASSERT_EQ(c.analyzers.size(), 2u);
  EXPECT_DOUBLE_EQ(c.pub_rate, 1.0);
  const AnalyzerSpec& s = c.analyzers[0];
  EXPECT_EQ(s.key, "sensors");
  EXPECT_EQ(s.path, "/Sensors");
  EXPECT_EQ(s.startswith, std::vector<std::string>{"robot1/sonar"});  // a string is a list of one
  EXPECT_EQ(s.contains, std::vector<std::string>{"laser"});
  EXPECT_DOUBLE_EQ(s.timeout, 2.0);
  EXPECT_EQ(c.analyzers[1].path, "/Control");  // slashes trimmed
  EXPECT_EQ(c.analyzers[1].remove_prefix.size(), 2u);
  EXPECT_DOUBLE_EQ(c.analyzers[1].timeout, 0.0);

  const AggregatorConfig b = parse_aggregator_config(
      "pub_rate: 2\nbase_path: Robot\nanalyzers: {a: {type: diagnostic_aggregator/GenericAnalyzer, path: A, "
      "contains: x}}",
      "b.yaml");
  EXPECT_DOUBLE_EQ(b.pub_rate, 2.0);
  EXPECT_EQ(b.analyzers[0].path, "/Robot/A");
  EXPECT_DOUBLE_EQ(b.analyzers[0].timeout, 5.0);  // the default
}

TEST(AggregatorConfig, MatchingAndItemNames) {
  const AggregatorConfig c = parse_aggregator_config(kConfig, "agg.yaml");
  const AnalyzerSpec& s = c.analyzers[0];
  EXPECT_TRUE(analyzer_matches(s, "robot1/sonar_crisp: sonar sectors"));  // startswith
  EXPECT_TRUE(analyzer_matches(s, "front laser: scan"));                  // contains
  EXPECT_FALSE(analyzer_matches(s, "robot2/sonar_crisp: sonar sectors"));
  EXPECT_FALSE(analyzer_matches(s, "Laser"));  // case matters
  const AnalyzerSpec& k = c.analyzers[1];
  EXPECT_TRUE(analyzer_matches(k, "robot1/brian: Mr. BRIAN"));  // name: exact
  EXPECT_FALSE(analyzer_matches(k, "robot1/brian: Mr. BRIAN 2"));
  EXPECT_TRUE(analyzer_matches(k, "robot1/airboard: AIRBoard link"));  // expected also matches

  EXPECT_EQ(item_name(s, "robot1/sonar_crisp: sonar sectors"), "sonar_crisp: sonar sectors");
  EXPECT_EQ(item_name(s, "robot1/unmapped/sonar_crisp: x"), "unmapped sonar_crisp: x");  // '/' -> ' '
  EXPECT_EQ(item_name(k, "robot2/brian: Mr. BRIAN"), "brian: Mr. BRIAN");  // the first prefix that fits
  EXPECT_EQ(item_name(s, "front laser: scan"), "front laser: scan");     // no prefix: as it is
  EXPECT_EQ(item_name(s, "robot1/"), "robot1/");                        // nothing left: the whole name
}

TEST(Aggregator, ParentHasTheWorstLevelOfItsItems) {
  Aggregator a(parse_aggregator_config(kConfig, "agg.yaml"));
  a.add(status("robot1/sonar_crisp: sonar sectors", kAggOk), 10.0);
  a.add(status("front laser: scan", kAggWarn, "noisy"), 10.0);
  a.add(status("robot1/brian: Mr. BRIAN", kAggOk), 10.0);
  a.add(status("robot1/airboard: AIRBoard link", kAggError, "no link"), 10.0);
  const AggOutput o = a.aggregate(10.5);
  // Parents in the configuration's order, each followed by its items by name.
  ASSERT_EQ(o.statuses.size(), 6u);
  EXPECT_EQ(o.statuses[0].name, "/Sensors");
  EXPECT_EQ(o.statuses[1].name, "/Sensors/front laser: scan");
  EXPECT_EQ(o.statuses[2].name, "/Sensors/sonar_crisp: sonar sectors");
  EXPECT_EQ(o.statuses[3].name, "/Control");
  EXPECT_EQ(o.statuses[0].level, kAggWarn);
  EXPECT_EQ(o.statuses[0].message, "Warning: front laser: scan");
  ASSERT_EQ(o.statuses[0].values.size(), 2u);
  EXPECT_EQ(o.statuses[0].values[0].first, "front laser: scan");
  EXPECT_EQ(o.statuses[0].values[0].second, "Warning: noisy");
  // An item keeps the status's message, hardware id and values.
  EXPECT_EQ(o.statuses[1].message, "noisy");
  EXPECT_EQ(o.statuses[1].hardware_id, "hw");
  ASSERT_EQ(o.statuses[1].values.size(), 1u);
  EXPECT_EQ(o.statuses[3].level, kAggError);
  EXPECT_EQ(o.statuses[3].message, "Error: airboard: AIRBoard link");
  EXPECT_EQ(o.toplevel.level, kAggError);
  EXPECT_EQ(o.toplevel.message, "Error: /Control");

  // All fine again: OK everywhere.
  a.add(status("front laser: scan", kAggOk), 11.0);
  a.add(status("robot1/airboard: AIRBoard link", kAggOk), 11.0);
  const AggOutput ok = a.aggregate(11.0);
  EXPECT_EQ(ok.toplevel.level, kAggOk);
  EXPECT_EQ(ok.toplevel.message, "OK");
  EXPECT_EQ(find(ok, "/Sensors")->message, "OK");
}

TEST(Aggregator, ItemsPastTheirTimeoutAreStale) {
  Aggregator a(parse_aggregator_config(kConfig, "agg.yaml"));
  a.add(status("robot1/sonar_crisp: sonar sectors", kAggOk), 10.0);
  a.add(status("front laser: scan", kAggOk), 11.5);
  a.add(status("robot1/brian: Mr. BRIAN", kAggOk), 0.0);
  a.add(status("robot1/airboard: AIRBoard link", kAggOk), 0.0);
  const AggOutput at12 = a.aggregate(12.0);  // sonar 2.0 s old: not past the 2 s timeout yet
  EXPECT_EQ(find(at12, "/Sensors")->level, kAggOk);
  const AggOutput o = a.aggregate(12.5);  // sonar 2.5 s old, laser 1 s
  EXPECT_EQ(find(o, "/Sensors/sonar_crisp: sonar sectors")->level, kAggStale);
  EXPECT_EQ(find(o, "/Sensors/sonar_crisp: sonar sectors")->message, "stale (2 s silent): m");
  EXPECT_EQ(find(o, "/Sensors/front laser: scan")->level, kAggOk);
  EXPECT_EQ(find(o, "/Sensors")->level, kAggStale);
  EXPECT_EQ(find(o, "/Sensors")->message, "Stale: sonar_crisp: sonar sectors");
  // timeout 0: never stale, 12.5 s later.
  EXPECT_EQ(find(o, "/Control")->level, kAggOk);
  EXPECT_EQ(o.toplevel.level, kAggStale);
  EXPECT_EQ(o.toplevel.message, "Stale: /Sensors");
  // Heard again: fresh.
  a.add(status("robot1/sonar_crisp: sonar sectors", kAggWarn), 12.6);
  EXPECT_EQ(find(a.aggregate(12.7), "/Sensors")->level, kAggWarn);
}

TEST(Aggregator, MissingExpectedItemsAndEmptyGroupsAreStale) {
  Aggregator a(parse_aggregator_config(kConfig, "agg.yaml"));
  const AggOutput o = a.aggregate(0.0);
  ASSERT_EQ(o.statuses.size(), 3u);  // /Sensors (no item), /Control, its expected item
  EXPECT_EQ(o.statuses[0].name, "/Sensors");
  EXPECT_EQ(o.statuses[0].level, kAggStale);
  EXPECT_EQ(o.statuses[0].message, "no item yet");
  EXPECT_EQ(o.statuses[2].name, "/Control/airboard: AIRBoard link");
  EXPECT_EQ(o.statuses[2].level, kAggStale);
  EXPECT_EQ(o.statuses[2].message, "expected, never received");
  EXPECT_EQ(o.statuses[1].level, kAggStale);
  EXPECT_EQ(o.toplevel.message, "Stale: /Sensors, /Control");
  // A name-only item (not expected) is not reported until it arrives.
  EXPECT_EQ(find(o, "/Control/brian: Mr. BRIAN"), nullptr);
}

TEST(Aggregator, UnmatchedStatusesGoUnderOtherUntilSilent) {
  Aggregator a(parse_aggregator_config(kConfig, "agg.yaml"), 5.0);
  a.add(status("robot1/brian: Mr. BRIAN", kAggOk), 0.0);
  a.add(status("robot1/airboard: AIRBoard link", kAggOk), 0.0);
  a.add(status("robot1/sonar_crisp: s", kAggOk), 0.0);
  a.add(status("visitor: FollowMe visitor", kAggWarn, "silent"), 0.0);
  const AggOutput o = a.aggregate(1.0);
  const AggStatus* other = find(o, "/Other");
  ASSERT_NE(other, nullptr);
  EXPECT_EQ(other->level, kAggWarn);
  ASSERT_NE(find(o, "/Other/visitor: FollowMe visitor"), nullptr);
  EXPECT_EQ(o.toplevel.level, kAggWarn);
  EXPECT_EQ(o.toplevel.message, "Warning: /Other");
  EXPECT_EQ(find(a.aggregate(5.5), "/Other"), nullptr);  // 5.5 s silent: gone
}

TEST(AggregatorConfig, RefusesBadFilesNamingFileKeyAndExpectation) {
  const std::string head = "analyzers:\n  a:\n    type: diagnostic_aggregator/GenericAnalyzer\n    path: A\n";
  EXPECT_EQ(error_of("analyzers:\n  a:\n    type: diagnostic_aggregator/AnalyzerGroup\n    path: A\n"),
            "agg.yaml:3:11: unknown analyzer type 'diagnostic_aggregator/AnalyzerGroup' in 'analyzers/a/type' "
            "(expected diagnostic_aggregator/GenericAnalyzer, the only type this aggregator implements)");
  EXPECT_EQ(error_of(head + "    contains: x\n    regex: y\n"),
            "agg.yaml:6:5: unknown key 'regex' in 'analyzers/a' (expected one of: type, path, startswith, contains, "
            "name, expected, remove_prefix, timeout)");
  EXPECT_EQ(error_of(head), "agg.yaml:3:5: expected at least one of startswith, contains, name, expected in "
                            "'analyzers/a'");
  EXPECT_EQ(error_of(head + "    contains: {x: 1}\n"),
            "agg.yaml:5:15: expected a string or a list of strings for 'analyzers/a/contains'");
  EXPECT_EQ(error_of(head + "    contains: x\n    timeout: soon\n"),
            "agg.yaml:6:14: expected a number for 'analyzers/a/timeout'");
  EXPECT_EQ(error_of("analyzers:\n  a:\n    path: A\n    contains: x\n"),
            "agg.yaml:3:5: missing required key 'type' in 'analyzers/a'");
  EXPECT_EQ(error_of("analyzer: {}\n"),
            "agg.yaml:1:1: unknown key 'analyzer' in '(top level)' (expected one of: analyzers, pub_rate, base_path)");
  EXPECT_EQ(error_of("analyzers: {}\n"), "agg.yaml:1:12: expected a non-empty map of analyzers for 'analyzers'");
  EXPECT_EQ(error_of(head + "    contains: x\n  b:\n    type: diagnostic_aggregator/GenericAnalyzer\n    path: /A\n"
                            "    contains: y\n"),
            "agg.yaml:7:5: expected a path of its own for 'analyzers/b/path' (/A is taken; /Other holds the "
            "unmatched statuses)");
  EXPECT_EQ(error_of("pub_rate: 0\nanalyzers: {}\n").substr(0, 21), "agg.yaml:1:11: expect");
  EXPECT_EQ(error_of("analyzers: [\n"), error_of("analyzers: [\n"));  // a YAML syntax error: a ParseError too
  EXPECT_EQ(error_of("analyzers: [\n").substr(0, 9), "agg.yaml:");
  try {
    load_aggregator_config("/nonexistent/agg.yaml");
    FAIL() << "a missing file was read";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/agg.yaml: cannot open the aggregator configuration");
  }
}
