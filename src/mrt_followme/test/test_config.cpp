// The configuration: the shipped file and errors naming file:line:column.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_followme/museum.h"
#include "mrt_world/world_loader.h"

using namespace mrt::followme;

TEST(Config, ShippedFile) {
  const FollowMeConfig c = load_followme_config(std::string(MRT_FOLLOWME_CONFIG) + "/followme.yaml");
  ASSERT_EQ(c.exhibits.size(), 5u);
  EXPECT_EQ(c.doors.size(), 4u);
  ASSERT_EQ(c.tour.size(), 4u);
  EXPECT_EQ(c.tour[0], "statue");
  EXPECT_EQ(c.tour[3], "vase");
  EXPECT_EQ(c.exhibit_index("vase"), 3u);
  EXPECT_DOUBLE_EQ(c.exhibits[3].stop.x, 15.0);
  EXPECT_DOUBLE_EQ(c.exhibits[3].spot.y, 3.0);
  EXPECT_DOUBLE_EQ(c.guide.keep_max, 2.8);
  EXPECT_EQ(c.visitor.wander_after, 2);
  EXPECT_EQ(c.visitor.wander_to, "globe");
  EXPECT_DOUBLE_EQ(c.door("north_door").b.y, 9.6);
  EXPECT_THROW(c.exhibit_index("mona_lisa"), std::out_of_range);
}

TEST(Config, UnknownExhibitInTourNamesTheLine) {
  try {
    load_followme_config(std::string(MRT_FOLLOWME_TEST_DATA) + "/bad_tour.yaml");
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    const std::string what = e.what();
    // the tour is the flow sequence on line 3, column 7
    EXPECT_NE(what.find("bad_tour.yaml:3:7:"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown exhibit 'mona_lisa'"), std::string::npos) << what;
  }
}

TEST(Config, UnknownKeyNamesTheLine) {
  try {
    load_followme_config(std::string(MRT_FOLLOWME_TEST_DATA) + "/bad_key.yaml");
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad_key.yaml:5:3: unknown key 'keep_maximum'"), std::string::npos) << what;
  }
}

TEST(Config, CheckTour) {
  FollowMeConfig c;
  c.exhibits = {{"a", {0, 0}, {1, 1}}, {"b", {2, 2}, {3, 3}}};
  EXPECT_EQ(check_tour(c, {"b", "a"}), "");
  EXPECT_EQ(check_tour(c, {}), "the tour has no exhibit");
  EXPECT_EQ(check_tour(c, {"a", "a"}), "exhibit 'a' twice in the tour");
  EXPECT_EQ(check_tour(c, {"a", "z"}), "unknown exhibit 'z'");
}

// The doors are in the museum world too (mrt_world's `doors:`): FollowMe
// reads its own (followme.yaml, the configuration's format keeps them), and
// the two must name the same walls.
TEST(Config, DoorsAgreeWithTheMuseumWorld) {
  const FollowMeConfig c = load_followme_config(std::string(MRT_FOLLOWME_CONFIG) + "/followme.yaml");
  const mrt::world::World w = mrt::world::load_world(std::string(MRT_WORLDS_DIR) + "/museum.yaml");
  ASSERT_EQ(w.doors.size(), c.doors.size());
  for (const Door& d : c.doors) {
    const mrt::world::Door& wd = w.door(d.name);
    EXPECT_DOUBLE_EQ(wd.span.a.x, d.a.x) << d.name;
    EXPECT_DOUBLE_EQ(wd.span.a.y, d.a.y) << d.name;
    EXPECT_DOUBLE_EQ(wd.span.b.x, d.b.x) << d.name;
    EXPECT_DOUBLE_EQ(wd.span.b.y, d.b.y) << d.name;
  }
}
