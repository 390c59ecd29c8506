// RecVision in FollowMe's museum: frames rendered by mrt_sim's camera
// (CameraRenderer on worlds/museum.yaml, pixel noise as the world file
// sets), processed with config/museum.yaml, against the world's geometry.
// Bounds (test/museum_scene.h): distance within 3 cm + one pixel of image
// radius at the object's distance (5 cm at 2 m, 9.6 cm at 5 m, 19.5 cm at
// 8 m: the foot lies between two pixels of a radial line), bearing within
// 2 degrees (the lines are 1 degree apart: an edge is known to half a
// degree). Every landmark, person and exhibit in full sight (test/
// museum_scene.h: rays to its centre and both sides reach it, its foot
// beyond the robot's body, within 8.5 m) must be found, and every object
// reported must be one of the world's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mrt_recvision/detector.h"
#include "mrt_sim/camera.h"
#include "museum_scene.h"

using namespace mrt::recvision;
namespace sim = mrt::sim;

namespace {

struct Museum {
  sim::World world = sim::load_world(MRT_SIM_MUSEUM);
  Calibration cal = load_calibration(MRT_RECVISION_CONFIG_DIR "/museum.yaml");
  Detector detector{cal};
  sim::CameraRenderer renderer{world, world.robots[0].sensors.camera.model,
                               sim::camera_options(world.robots[0], 11)};

  std::vector<Detection> look(const sim::Pose2D& robot) {
    Frame f;
    renderer.render(robot, {}, 0.0, f.rgb);
    return detector.process(f);
  }
  sim::Mover& mover(const std::string& name) {
    for (auto& m : world.movers)
      if (m.name == name) return m;
    throw std::runtime_error("no mover " + name);
  }
};

void expect_all_found(const museum::Tally& t, const std::string& what) {
  EXPECT_EQ(t.found, t.required) << what << ": missed " << ::testing::PrintToString(t.missed);
  EXPECT_EQ(t.false_positives, 0) << what << ": spurious " << ::testing::PrintToString(t.spurious);
}

}  // namespace

// The calibration's camera is the world's: the same image size, centre,
// viewpoint and mirror (the image radius of rays at 0.5, 1.2 and 1.45 rad).
TEST(Museum, CalibrationCameraIsTheWorldsCamera) {
  Museum m;
  const auto& a = m.cal.camera;
  const auto& b = m.world.robots[0].sensors.camera.model;
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height_px, b.height_px);
  EXPECT_DOUBLE_EQ(a.cx, b.cx);
  EXPECT_DOUBLE_EQ(a.cy, b.cy);
  EXPECT_DOUBLE_EQ(a.height, b.height);
  for (double th : {0.5, 1.2, 1.45}) EXPECT_NEAR(a.profile.radius(th), b.profile.radius(th), 1e-9) << th;
  // 0.5 rad is on the isometric part: floor distance 0.7 tan(0.5) = 0.3824 m
  // at 2 cm per pixel = 19.12 px.
  EXPECT_NEAR(a.profile.radius(0.5), 19.12, 0.01);
}

// The robot at stations in every room and by the doors, the visitor near
// it, the other two visitors on their walks: every landmark, person and
// exhibit in full sight found, nothing reported that is not there.
TEST(Museum, EveryLandmarkAndVisitorInSightFound) {
  Museum m;
  struct Station {
    sim::Pose2D robot;
    sim::Point2D guest, v1, v2;
  };
  const std::vector<Station> stations = {
      {{6, 3, M_PI}, {7.4, 3.0}, {11.2, 0.8}, {11.2, 11.2}},   // the world file's start
      {{5, 2, 0.3}, {7.0, 3.5}, {14, 0.8}, {16, 11.2}},
      {{13, 3, 1.0}, {15.0, 4.5}, {14, 0.8}, {12, 11.2}},       // south-east, visitor1 walking by
      {{3, 8, -2.0}, {5.0, 8.5}, {18, 0.8}, {18, 11.2}},        // north-west
      {{17, 8.5, 2.5}, {14.5, 7.5}, {12, 0.8}, {15, 11.2}},     // north-east, visitor2 near
      {{9, 3, 0.0}, {8.0, 4.5}, {12.5, 3.2}, {13, 11.2}},       // by the west door, looking through it
      {{8, 9, -1.2}, {6.5, 10.0}, {18, 0.8}, {18, 11.2}},       // by the globe
  };
  museum::Tally landmarks, persons, exhibits;
  for (const Station& s : stations) {
    m.mover("guest").position = s.guest;
    m.mover("visitor1").position = s.v1;
    m.mover("visitor2").position = s.v2;
    const auto dets = m.look(s.robot);
    const auto truth = museum::truth(m.world, s.robot, m.cal.detector.min_distance);
    const std::string at = "robot at (" + std::to_string(s.robot.x) + ", " + std::to_string(s.robot.y) + ")";
    museum::Tally l, p, e;
    museum::evaluate(dets, truth, "Landmark", m.cal.camera, l);
    museum::evaluate(dets, truth, "Person", m.cal.camera, p);
    museum::evaluate(dets, truth, "Exhibit", m.cal.camera, e);
    expect_all_found(l, "landmarks, " + at);
    expect_all_found(p, "persons, " + at);
    expect_all_found(e, "exhibits, " + at);
    for (auto [one, all] : {std::make_pair(&l, &landmarks), std::make_pair(&p, &persons), std::make_pair(&e, &exhibits)}) {
      all->required += one->required, all->found += one->found;
      all->distance_error.insert(all->distance_error.end(), one->distance_error.begin(), one->distance_error.end());
      all->relative_error.insert(all->relative_error.end(), one->relative_error.begin(), one->relative_error.end());
      all->bearing_error.insert(all->bearing_error.end(), one->bearing_error.begin(), one->bearing_error.end());
    }
  }
  // Enough to mean something: landmarks in several rooms, the visitor at every station.
  EXPECT_GE(landmarks.required, 30);
  EXPECT_GE(persons.required, int(stations.size()));
  for (const auto& [name, t] : {std::make_pair("landmarks", &landmarks), std::make_pair("persons", &persons),
                                std::make_pair("exhibits", &exhibits)})
    std::printf("%s: %d/%d found, distance error max %.3f m (%.2f %%), bearing error max %.2f deg\n", name,
                t->found, t->required, museum::max_of(t->distance_error), 100 * museum::max_of(t->relative_error),
                museum::max_of(t->bearing_error) * 180 / M_PI);
}

// The visitor alone around the robot at 1 to 7 m, every 40 degrees: the
// Person percept of its purple badge at its centre within the bounds.
TEST(Museum, VisitorAroundTheRobot) {
  Museum m;
  m.mover("visitor1").position = {18, 0.8};
  m.mover("visitor2").position = {18, 11.2};
  const sim::Pose2D robot{5.0, 3.0, 0.4};
  int checked = 0;
  for (double d : {1.0, 1.5, 2.0, 3.0, 4.0}) {
    for (int k = 0; k < 9; ++k) {
      const double b = -M_PI + k * 2.0 * M_PI / 9.0 + 0.1, a = robot.theta + b;
      const sim::Point2D g{robot.x + d * std::cos(a), robot.y + d * std::sin(a)};
      if (g.x < 0.5 || g.x > 9.5 || g.y < 0.5 || g.y > 5.5) continue;  // inside the room
      m.mover("guest").position = g;
      const auto truth = museum::truth(m.world, robot, m.cal.detector.min_distance);
      const auto guest = std::find_if(truth.begin(), truth.end(), [](const museum::Truth& t) { return t.name == "guest"; });
      if (!guest->full) continue;  // behind the statue
      museum::Tally p;
      museum::evaluate(m.look(robot), truth, "Person", m.cal.camera, p);
      EXPECT_EQ(p.found, 1) << "guest at " << d << " m, " << b << " rad";
      EXPECT_EQ(p.false_positives, 0) << "guest at " << d << " m, " << b << " rad";
      ++checked;
    }
  }
  EXPECT_GE(checked, 25);
}

// An empty room (the south-west one, every visitor in the north-east one):
// no Person percept, and the landmarks still all found.
TEST(Museum, EmptyRoomHasNoPerson) {
  Museum m;
  m.mover("guest").position = {16, 10};
  m.mover("visitor1").position = {18, 8};
  m.mover("visitor2").position = {13, 11};
  for (const sim::Pose2D& robot : {sim::Pose2D{5, 3, 0.0}, sim::Pose2D{2, 1.5, 2.0}, sim::Pose2D{8, 4.5, -2.5}}) {
    const auto dets = m.look(robot);
    for (const Detection& d : dets) EXPECT_NE(d.membership_class, "Person") << d.distance << " m " << d.bearing;
    museum::Tally l;
    museum::evaluate(dets, museum::truth(m.world, robot, m.cal.detector.min_distance), "Landmark", m.cal.camera, l);
    EXPECT_GE(l.required, 4);
    expect_all_found(l, "landmarks");
  }
}

// Wall points lie on the walls: within 3 cm + one pixel of a wall segment.
TEST(Museum, WallPointsLieOnTheWalls) {
  Museum m;
  const sim::Pose2D robot{5, 3, 0.3};
  int walls = 0;
  for (const Detection& d : m.look(robot)) {
    if (d.membership_class != "Wall") continue;
    ++walls;
    const sim::Point2D g{robot.x + std::cos(robot.theta) * d.x - std::sin(robot.theta) * d.y,
                         robot.y + std::sin(robot.theta) * d.x + std::cos(robot.theta) * d.y};
    double best = 1e9;
    for (const auto& s : m.world.walls) best = std::min(best, sim::distance_to_segment(g, s));
    EXPECT_LE(best, museum::distance_bound(m.cal.camera, d.distance)) << d.distance << " m " << d.bearing;
  }
  // A wall point every 5 degrees up to 5 m: the room is 10 x 6 m, the robot
  // 2-3 m from three walls; the exhibits and landmarks hide a few.
  EXPECT_GE(walls, 30);
}
