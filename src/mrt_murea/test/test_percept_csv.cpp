// The percept CSV reader and the murea_localize command-line tool.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include "mrt_common/parse_error.h"
#include "mrt_murea/percept_csv.h"

using namespace mrt::murea;
using mrt::common::ParseError;

namespace {

const std::string kHeader = "frame,class,color,distance,bearing,reliability\n";

std::vector<PerceptFrame> parse(const std::string& text) {
  std::istringstream in(text);
  return read_percept_csv(in, "mem.csv");
}

// Message of the ParseError `text` raises ("" if none).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

// Runs a shell command; returns its exit status, stdout in `out`.
int run(const std::string& cmd, std::string* out) {
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  std::array<char, 512> buf;
  out->clear();
  while (fgets(buf.data(), buf.size(), p)) *out += buf.data();
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream s(line);
  std::string x;
  while (std::getline(s, x, ',')) f.push_back(x);
  if (!line.empty() && line.back() == ',') f.push_back("");
  return f;
}

}  // namespace

TEST(PerceptCsv, FramesInOrderOfFirstAppearance) {
  const auto frames = parse(kHeader + "7,Line,,1.5,0.25,0.9\n3,Goal,yellow,4,-1,1\n7,Landmark,red,2,3,0.5\n");
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].id, "7");
  EXPECT_EQ(frames[0].line, 2);
  ASSERT_EQ(frames[0].percepts.size(), 2u);
  EXPECT_EQ(frames[0].percepts[1].cls, FeatureClass::Landmark);
  EXPECT_EQ(frames[0].percepts[1].color, "red");
  EXPECT_DOUBLE_EQ(frames[0].percepts[0].bearing, 0.25);
  EXPECT_DOUBLE_EQ(frames[0].percepts[0].reliability, 0.9);
  EXPECT_EQ(frames[1].percepts[0].cls, FeatureClass::Goal);
  EXPECT_DOUBLE_EQ(frames[1].percepts[0].distance, 4.0);
}

TEST(PerceptCsv, UnusablePerceptsAreDroppedAndCounted) {
  const auto frames = parse(kHeader +
                            "1,Ball,orange,1,0,1\n"     // unknown class
                            "1,Robot,black,2,0,1\n"     // unknown class
                            "1,Line,,nan,0,1\n"         // non-finite
                            "1,Line,,1,inf,1\n"         // non-finite
                            "1,Line,,-1,0,1\n"          // negative distance
                            "1,Line,,1,0,1.5\n"         // reliability > 1
                            "1,Line,,1,0,0\n"           // reliability 0
                            "1,Wall,,1,0,1\n");         // kept
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].percepts.size(), 1u);
  EXPECT_EQ(frames[0].dropped.unknown_class, 2u);
  EXPECT_EQ(frames[0].dropped.non_finite, 2u);
  EXPECT_EQ(frames[0].dropped.out_of_range, 3u);
  EXPECT_EQ(frames[0].dropped.total(), 7u);
}

TEST(PerceptCsv, MalformedRowsNameFileLineAndColumn) {
  EXPECT_EQ(error_of(kHeader + "1,Line,,1,0,1\n1,Line,,x,0,1\n"),
            "mem.csv:3:9: expected a number in column 'distance', got 'x'");
  EXPECT_EQ(error_of(kHeader + "1,Line,,1,0\n"), "mem.csv:2: expected 6 fields, got 5");
  EXPECT_EQ(error_of(kHeader + "\n# comment\n,Line,,1,0,1\n"), "mem.csv:4:1: expected a frame id");
  EXPECT_EQ(error_of("frame,class,distance,bearing\n"), "mem.csv:1: expected 6 fields, got 4");
  EXPECT_EQ(error_of(kHeader + "1,Line,,1,0.5x,1\n"), "mem.csv:2:11: expected a number in column 'bearing', got '0.5x'");
}

TEST(PerceptCsv, ResultRowWithAndWithoutRunnerUp) {
  Result r;
  r.best = {Pose2D(1.05, -2.05, 0.45), 7.25};
  r.estimate.mean = Pose2D(1, -2, 0.5);  // x, y, theta come from the estimate
  r.time_ms = 3.5;
  std::ostringstream out;
  write_result_header(out);
  write_result_row(out, "12", r);
  r.ambiguous = true;
  r.alternative = Hypothesis{Pose2D(-1, 2, -2.5), 7.0};
  write_result_row(out, "13", r);
  EXPECT_EQ(out.str(),
            "frame,x,y,theta,evidence,ambiguous,alt_x,alt_y,alt_theta,alt_evidence,time_ms\n"
            "12,1.0000,-2.0000,0.50000,7.2500,0,,,,,3.500\n"
            "13,1.0000,-2.0000,0.50000,7.2500,1,-1.0000,2.0000,-2.50000,7.0000,3.500\n");
}

// room_frames.csv, in room.yaml: frame 1 is the robot at (-1, 0) facing +y
// (walls 2 ahead, 1 left, 3 right, 2 behind; red post at sqrt(8.5),
// -1.03038 rad; at -30 deg (heading 60) the wall y = 2 at (0.1547, 2),
// 2/cos(30) = 2.3094 m; at +60 deg (heading 150) the wall x = -2 at
// (-2, 0.5774), 1/cos(30) = 1.1547 m); frame 2 the robot at (1, 1) facing
// -y (walls 3 ahead, 1 left = x 2, 3 right, 1 behind = y 2; the post at
// (1.5, 1.5) is 0.5 m behind and 0.5 m left: sqrt(0.5) at 135 deg; at -30
// deg (heading -120) the wall y = -2 at 3/cos(30) = 3.4641 m; at +60 deg
// (heading -30) the wall x = 2 at 1.1547 m), plus a Ball percept and a nan
// distance, dropped and counted on stderr. The oblique wall points pin the
// heading, which the perpendicular ones leave loose.
TEST(MureaLocalize, KnownPosesFromFiles) {
  std::string out;
  ASSERT_EQ(run(std::string(MUREA_LOCALIZE) + " --map " MRT_MUREA_DATA "/room.yaml --percepts " MRT_MUREA_DATA
                    "/room_frames.csv --accuracy 0.05 0.0174533 --timeout 5",
                &out),
            0)
      << out;
  std::istringstream lines(out);
  std::string line;
  std::vector<std::vector<std::string>> rows;
  bool dropped_reported = false;
  while (std::getline(lines, line)) {
    if (line.find("dropped 2 percepts (1 unknown class, 1 non-finite") != std::string::npos) dropped_reported = true;
    else rows.push_back(split(line));
  }
  EXPECT_TRUE(dropped_reported) << out;
  ASSERT_EQ(rows.size(), 3u) << out;
  EXPECT_EQ(rows[0][0], "frame");
  const double expect[2][3] = {{-1, 0, 1.5707963}, {1, 1, -1.5707963}};
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(rows[i + 1].size(), 11u);
    EXPECT_EQ(rows[i + 1][0], std::to_string(i + 1));
    EXPECT_NEAR(std::stod(rows[i + 1][1]), expect[i][0], 0.15);
    EXPECT_NEAR(std::stod(rows[i + 1][2]), expect[i][1], 0.15);
    EXPECT_NEAR(std::stod(rows[i + 1][3]), expect[i][2], 0.1);
    EXPECT_EQ(rows[i + 1][4], "7.0000");  // 6 wall points + the post
    EXPECT_EQ(rows[i + 1][5], "0");
  }
}

// The contract of issue 15: rows with no header row. room_frames.csv with
// its header line left out gives the same estimates (all but time_ms).
// The same estimates from rows with no header and with recvision_run's
// header (`stamp` first, issue 14) as with `frame` first.
TEST(MureaLocalize, ReadsRowsWithoutAHeader) {
  std::ifstream in(MRT_MUREA_DATA "/room_frames.csv");
  const std::string bare_file = ::testing::TempDir() + "room_frames_bare.csv";
  const std::string stamp_file = ::testing::TempDir() + "room_frames_stamp.csv";
  std::ofstream bare(bare_file), stamped(stamp_file);
  std::string line;
  int headers = 0;
  while (std::getline(in, line)) {
    if (line.rfind("frame,", 0) == 0) {
      ++headers;
      stamped << "stamp," << line.substr(6) << '\n';
    } else {
      bare << line << '\n';
      stamped << line << '\n';
    }
  }
  bare.close();
  stamped.close();
  ASSERT_EQ(headers, 1);
  const std::string args = " --map " MRT_MUREA_DATA "/room.yaml --accuracy 0.05 0.0174533 --timeout 5 --percepts ";
  std::string with, without;
  ASSERT_EQ(run(std::string(MUREA_LOCALIZE) + args + MRT_MUREA_DATA "/room_frames.csv", &with), 0);
  ASSERT_EQ(run(std::string(MUREA_LOCALIZE) + args + bare_file, &without), 0);
  std::string with_stamp;
  ASSERT_EQ(run(std::string(MUREA_LOCALIZE) + args + stamp_file, &with_stamp), 0);
  auto estimates = [](const std::string& text) {
    std::istringstream lines(text);
    std::string l;
    std::vector<std::vector<std::string>> rows;
    while (std::getline(lines, l)) {
      if (l.rfind("murea_localize: ", 0) == 0) continue;  // stderr: the dropped percepts
      auto row = split(l);
      row.pop_back();  // time_ms
      rows.push_back(row);
    }
    return rows;
  };
  const auto a = estimates(with), b = estimates(without);
  ASSERT_EQ(a.size(), 3u) << with;
  EXPECT_EQ(a, b) << with << "\n" << without;
  EXPECT_EQ(a, estimates(with_stamp)) << with_stamp;
}

TEST(MureaLocalize, ErrorsNameFileAndLineAndExitTwo) {
  std::string out;
  EXPECT_EQ(run(std::string(MUREA_LOCALIZE) + " --map " MRT_MUREA_DATA "/room.yaml --percepts " MRT_MUREA_DATA
                    "/bad_percepts.csv",
                &out),
            2);
  EXPECT_NE(out.find("bad_percepts.csv:3:9: expected a number in column 'distance', got 'two'"), std::string::npos)
      << out;
  EXPECT_EQ(run(std::string(MUREA_LOCALIZE) + " --map " MRT_MUREA_DATA "/bad_map.yaml --percepts " MRT_MUREA_DATA
                    "/room_frames.csv",
                &out),
            2);
  EXPECT_NE(out.find("bad_map.yaml:4:5: expected a list of 4 numbers for 'field_lines'"), std::string::npos) << out;
  EXPECT_EQ(run(std::string(MUREA_LOCALIZE) + " --map " MRT_MUREA_DATA "/room.yaml --percepts /nonexistent.csv", &out),
            2);
  EXPECT_NE(out.find("/nonexistent.csv: cannot open file"), std::string::npos) << out;
  EXPECT_EQ(run(std::string(MUREA_LOCALIZE) + " --map " MRT_MUREA_DATA "/room.yaml", &out), 2);  // --percepts missing
}
