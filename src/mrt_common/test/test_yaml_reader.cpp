// The strict YAML reader: every error names file:line:column (1-based) and
// what was expected. Positions are counted by hand in the YAML texts below.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "mrt_common/yaml_reader.h"

using mrt::common::ParseError;
using mrt::common::YamlReader;

namespace {

// what() of the ParseError `f` throws, "" when it throws none.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

const YamlReader r("f.yaml");

TEST(YamlReader, BadNumber) {
  // "b: [1, x]": 'x' is column 8 of line 2.
  const YAML::Node root = r.load("a: 1\nb: [1, x]\n");
  EXPECT_EQ(r.number(root["a"], "a"), 1.0);
  EXPECT_EQ(error_of([&] { r.number(root["b"][1], "b"); }), "f.yaml:2:8: expected a number for 'b'");
  EXPECT_EQ(error_of([&] { r.numbers(root["b"], "b", 2); }), "f.yaml:2:8: expected a number for 'b'");
  EXPECT_EQ(error_of([&] { r.numbers(root["b"], "b", 3); }), "f.yaml:2:4: expected a list of 3 numbers for 'b'");
}

TEST(YamlReader, UnknownKey) {
  const YAML::Node root = r.load("name: x\nspeed: 2\ncolour: red\n");
  EXPECT_EQ(error_of([&] { r.map(root, "robot", {"name", "speed", "color"}); }),
            "f.yaml:3:1: unknown key 'colour' in 'robot' (expected one of: name, speed, color)");
  EXPECT_EQ(error_of([&] { r.map(root, "robot", {"name", "speed", "colour"}); }), "");
}

TEST(YamlReader, DuplicateKey) {
  // the second "name" starts line 3 after two spaces.
  const YAML::Node root = r.load("robot:\n  name: a\n  name: b\n");
  EXPECT_EQ(error_of([&] { r.map(root["robot"], "robot", {"name"}); }),
            "f.yaml:3:3: duplicate key 'name' in 'robot'");
}

TEST(YamlReader, MissingKey) {
  // names the map that lacks the key: it starts at line 2, column 3.
  const YAML::Node root = r.load("robot:\n  name: a\n");
  EXPECT_EQ(error_of([&] { r.required(root["robot"], "pose", "robot"); }),
            "f.yaml:2:3: missing required key 'pose' in 'robot'");
  EXPECT_EQ(r.required(root["robot"], "name", "robot").Scalar(), "a");
  EXPECT_EQ(error_of([&] { r.string(root["robot"], "pose", "", true, "robot"); }),
            "f.yaml:2:3: missing required key 'pose' in 'robot'");
  EXPECT_EQ(r.string(root["robot"], "color", "red", false, "robot"), "red");
}

TEST(YamlReader, SyntaxError) {
  // a list item where the map of line 1 goes on: the '-' at line 2, column 1.
  EXPECT_EQ(error_of([&] { r.load("a: 1\n- b\n"); }), "f.yaml:2:1: end of map not found");
  EXPECT_EQ(error_of([&] { r.load("a: 1\n- b\n", "YAML syntax error: "); }),
            "f.yaml:2:1: YAML syntax error: end of map not found");
}

TEST(YamlReader, NotAMapNotAList) {
  const YAML::Node root = r.load("a: [1, 2]\nb: 3\n");
  EXPECT_EQ(error_of([&] { r.map(root["a"], "a", {}); }), "f.yaml:1:4: expected a map for 'a'");
  EXPECT_EQ(error_of([&] { r.sequence(root["b"], "b"); }), "f.yaml:2:4: expected a list for 'b'");
  EXPECT_EQ(error_of([&] { r.string(root["a"], "a"); }), "f.yaml:1:4: expected a string for 'a'");
  // a key that is not a name
  EXPECT_EQ(error_of([&] { r.map(r.load("? [1]\n: 2\n"), "top", {"a"}); }),
            "f.yaml:1:3: expected a key name in 'top'");
}

TEST(YamlReader, Bounds) {
  const YAML::Node m = r.load("p: 0.0\nn: -1.5\nf: 1.5\nw: 2\n");
  EXPECT_EQ(error_of([&] { r.positive(m["p"], "p"); }), "f.yaml:1:4: expected 'p' > 0, got 0.0");
  EXPECT_EQ(error_of([&] { r.positive(m, "p", 1.0); }), "f.yaml:1:4: expected 'p' > 0, got 0");
  EXPECT_EQ(error_of([&] { r.non_negative(m["n"], "n"); }), "f.yaml:2:4: expected 'n' >= 0, got -1.5");
  EXPECT_EQ(error_of([&] { r.non_negative(m, "n", 0.0); }), "f.yaml:2:4: expected 'n' >= 0, got -1.5");
  EXPECT_EQ(error_of([&] { r.fraction(m, "f", 0.0); }), "f.yaml:3:4: expected 'f' >= 0 and <= 1, got 1.5");
  EXPECT_EQ(r.positive(m, "absent", 7.0), 7.0);
  EXPECT_EQ(r.bounded(m, "w", 0.0, 2.0, false), 2.0);
  EXPECT_EQ(r.number(m, "absent", 3.0), 3.0);
}

TEST(YamlReader, IntegerBooleanFinite) {
  const YAML::Node m = r.load("k: 12\nx: 1.5\nb: yes\nc: maybe\ni: .inf\n");
  EXPECT_EQ(r.integer(m["k"], "k", 1, 12), 12);
  EXPECT_EQ(error_of([&] { r.integer(m["k"], "k", 1, 11); }), "f.yaml:1:4: expected an integer in [1, 11] for 'k'");
  EXPECT_EQ(error_of([&] { r.integer(m["x"], "x", 1, 11); }), "f.yaml:2:4: expected an integer in [1, 11] for 'x'");
  EXPECT_TRUE(r.boolean(m["b"], "b"));
  EXPECT_FALSE(r.boolean(m, "absent", false));
  EXPECT_EQ(error_of([&] { r.boolean(m, "c", true); }), "f.yaml:4:4: expected true or false for 'c'");
  EXPECT_EQ(error_of([&] { r.number(m["i"], "i"); }), "f.yaml:5:4: expected a number for 'i'");
  // mrt_scare's reader accepts infinities and reports a non-scalar key as unknown
  YamlReader::Options o;
  o.finite_numbers = false;
  o.scalar_keys = false;
  const YamlReader lax("f.yaml", o);
  EXPECT_TRUE(std::isinf(lax.number(m["i"], "i")));
  EXPECT_EQ(error_of([&] { lax.map(r.load("? [1]\n: 2\n"), "top", {"a"}); }),
            "f.yaml:1:3: unknown key '' in 'top' (expected one of: a)");
}

TEST(YamlReader, ConvertedExceptionAndFiles) {
  const YAML::Node m = r.load("a: [1]\n");
  try {
    m["a"].as<double>();
    FAIL();
  } catch (const YAML::Exception& e) {
    EXPECT_EQ(r.error(e).line(), 1);
    EXPECT_EQ(r.error(e).column(), 4);
  }
  EXPECT_EQ(error_of([] { mrt::common::read_file("/nonexistent/x.yaml"); }), "/nonexistent/x.yaml: cannot open file");
  EXPECT_EQ(error_of([] { mrt::common::read_file("/nonexistent/x.yaml", "cannot open world file"); }),
            "/nonexistent/x.yaml: cannot open world file");
  EXPECT_EQ(error_of([] { mrt::common::read_file("/", "cannot open file", 1 << 20); }), "/: not a regular file");
  const std::string path = testing::TempDir() + "mrt_common_yaml_reader_test.yaml";
  {
    std::ofstream out(path);
    out << "a: 1\n" << std::string(2000, '#') << "\n";
  }
  EXPECT_EQ(mrt::common::read_file(path).substr(0, 5), "a: 1\n");
  EXPECT_EQ(error_of([&] { mrt::common::read_file(path, "cannot open file", 1000); }),
            path + ": file larger than 1000 bytes");
  EXPECT_EQ(error_of([&] { mrt::common::read_file(path, "cannot open file", 1 << 20); }), "");
  std::remove(path.c_str());
}

}  // namespace
