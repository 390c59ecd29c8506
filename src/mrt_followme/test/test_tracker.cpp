// The visitor tracker: percepts placed in the map, colour, gate, velocity.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mrt_followme/visitor_tracker.h"

using namespace mrt::followme;

TEST(VisitorTracker, PlacesThePerceptWithThePose) {
  VisitorTracker t("purple");
  const Pose2D robot(1.0, 2.0, M_PI / 2);  // facing +y
  // 2 m straight ahead of a robot at (1, 2) facing +y: (1, 4); the green
  // person is someone else.
  const std::vector<PersonPercept> seen{{"green", 1.0, 0.0}, {"purple", 2.0, 0.0}};
  ASSERT_TRUE(t.update(0.0, robot, seen));
  EXPECT_NEAR(t.track()->position.x, 1.0, 1e-12);
  EXPECT_NEAR(t.track()->position.y, 4.0, 1e-12);
  // 1 m to the left (bearing +90 deg) of a robot facing +y is -x: (0, 2).
  VisitorTracker u("purple");
  ASSERT_TRUE(u.update(0.0, robot, std::vector<PersonPercept>{{"purple", 1.0, M_PI / 2}}));
  EXPECT_NEAR(u.track()->position.x, 0.0, 1e-12);
  EXPECT_NEAR(u.track()->position.y, 2.0, 1e-12);
}

TEST(VisitorTracker, IgnoresOtherColoursAndFarJumps) {
  VisitorTracker t("purple", 1.5);
  const Pose2D robot(0.0, 0.0, 0.0);
  EXPECT_FALSE(t.update(0.0, robot, std::vector<PersonPercept>{{"green", 2.0, 0.0}}));
  EXPECT_FALSE(t.track().has_value());
  EXPECT_GT(t.unseen_for(0.0), 1e6);
  ASSERT_TRUE(t.update(0.0, robot, std::vector<PersonPercept>{{"purple", 2.0, 0.0}}));
  // 0.1 s later a purple person 5 m from the track: beyond the 1.5 m gate.
  EXPECT_FALSE(t.update(0.1, robot, std::vector<PersonPercept>{{"purple", 7.0, 0.0}}));
  EXPECT_NEAR(t.unseen_for(0.5), 0.5, 1e-12);
}

TEST(VisitorTracker, VelocityOverTheWindow) {
  VisitorTracker t("purple", 1.5, 1.0);
  const Pose2D robot(0.0, 0.0, 0.0);
  t.update(0.0, robot, std::vector<PersonPercept>{{"purple", 2.0, 0.0}});
  EXPECT_DOUBLE_EQ(t.track()->speed(), 0.0);
  t.update(0.5, robot, std::vector<PersonPercept>{{"purple", 2.25, 0.0}});
  t.update(1.0, robot, std::vector<PersonPercept>{{"purple", 2.5, 0.0}});
  // (2.5 - 2.0) m over 1.0 s along +x
  EXPECT_NEAR(t.track()->velocity.x, 0.5, 1e-12);
  EXPECT_NEAR(t.track()->velocity.y, 0.0, 1e-12);
  t.update(2.0, robot, std::vector<PersonPercept>{{"purple", 2.5, 0.0}});
  // the window keeps t = 1.0 and 2.0: it stood still
  EXPECT_NEAR(t.track()->speed(), 0.0, 1e-12);
}
