// The world file's camera block and the sensor mounts taken from the
// robot's URDF (mrt_description).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_sim/description.h"
#include "mrt_sim/world.h"

using namespace mrt::sim;

namespace {

const std::string kHead =
    "name: t\nbounds: [-5, -5, 5, 5]\nrobots:\n  - name: r\n    base: ianus3\n    pose: [0, 0, 0]\n"
    "    sensors:\n";
const std::string kCamera =
    "      camera:\n        rate: 15\n        width: 320\n        height: 240\n"
    "        mirror: {type: isometric, metres_per_px: 0.04, inner_range: 3.0, px_per_rad: 200, theta_max: 1.5}\n";

std::string error_of(const std::string& text, const std::string& dir = "") {
  try {
    parse_world(text, "c.yaml", dir);
  } catch (const mrt::common::ParseError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(WorldCamera, MslFieldCameraFromTheWorldFileAndTheUrdf) {
  const World msl = load_world(std::string(MRT_WORLDS_DIR) + "/msl_field.yaml", MRT_DESCRIPTION_DIR);
  const CameraConfig& c = msl.robots[0].sensors.camera;
  EXPECT_EQ(c.rate, 30.0);
  EXPECT_EQ(c.model.width, 640);
  EXPECT_EQ(c.model.height_px, 480);
  // ianus3.urdf: omni_mirror_joint at (0, 0, 0.7).
  EXPECT_NEAR(c.model.height, 0.7, 1e-12);
  EXPECT_NEAR(c.mount_x, 0.0, 1e-12);
  EXPECT_NEAR(c.mount_y, 0.0, 1e-12);
  // Isometric 2 cm/px built for that height: 3 m on the floor at 150 px.
  EXPECT_NEAR(c.model.profile.radius(std::atan2(3.0, 0.7)), 150.0, 1e-6);
  EXPECT_EQ(c.effects.noise, 2.0);
  EXPECT_EQ(msl.line_width, 0.125);
  // The mice: links mouse_left / mouse_right at y = +-0.1.
  ASSERT_EQ(msl.robots[0].sensors.mice.size(), 2u);
  EXPECT_NEAR(msl.robots[0].sensors.mice[0].mount.y, 0.1, 1e-12);
  EXPECT_NEAR(msl.robots[0].sensors.mice[1].mount.y, -0.1, 1e-12);
  // The sonars: sonar_0 .. sonar_7, 45 deg apart on the 0.25 m body; the
  // third at (0, 0.25) facing left (the URDF writes 8 digits).
  const auto& so = msl.robots[0].sensors.sonars;
  ASSERT_EQ(so.size(), 8u);
  EXPECT_NEAR(so[0].mount.x, 0.25, 1e-8);
  EXPECT_NEAR(so[2].mount.x, 0.0, 1e-8);
  EXPECT_NEAR(so[2].mount.y, 0.25, 1e-8);
  EXPECT_NEAR(so[2].mount.theta, M_PI / 2, 1e-8);
  EXPECT_NEAR(so[5].mount.x, -0.25 / std::sqrt(2.0), 1e-8);
  EXPECT_NEAR(so[5].mount.y, -0.25 / std::sqrt(2.0), 1e-8);
}

TEST(WorldCamera, BlockWithoutUrdfAndOverrides) {
  // No description: the OmniCamera default viewpoint (0.6 m), mount 0.
  World w = parse_world(kHead + kCamera, "c.yaml", "");
  EXPECT_EQ(w.robots[0].sensors.camera.rate, 15.0);
  EXPECT_EQ(w.robots[0].sensors.camera.model.width, 320);
  EXPECT_NEAR(w.robots[0].sensors.camera.model.height, 0.6, 1e-12);
  // A viewpoint_height in the block wins over the URDF; camera_render sets
  // the effects and may move the viewpoint.
  w = parse_world(kHead + kCamera + "        viewpoint_height: 0.65\n" +
                      "      camera_render: {x: 0.05, noise: 3, flicker: 0.2, exposure: 0.01}\n",
                  "c.yaml", MRT_DESCRIPTION_DIR);
  const CameraConfig& c = w.robots[0].sensors.camera;
  EXPECT_NEAR(c.model.height, 0.65, 1e-12);
  EXPECT_EQ(c.mount_x, 0.05);
  EXPECT_EQ(c.effects.noise, 3.0);
  EXPECT_EQ(c.effects.flicker, 0.2);
  EXPECT_EQ(c.effects.exposure, 0.01);
  EXPECT_EQ(parse_world(kHead + kCamera + "      camera_render: {enabled: false}\n", "c.yaml", "")
                .robots[0].sensors.camera.rate, 0.0);
}

TEST(WorldCamera, ErrorsNameFileLineColumn) {
  // line 13 = 8 (sensors) + 5 lines of camera; "      camera_render: {" is 22 chars
  EXPECT_EQ(error_of(kHead + kCamera + "      camera_render: {nosie: 2}\n"),
            "c.yaml:13:23: unknown key 'nosie' in 'camera_render' (expected one of: enabled, x, y, noise, "
            "illumination, illumination_scale, flicker, flicker_period, exposure, white_balance_drift, "
            "white_balance_period)");
  EXPECT_EQ(error_of(kHead + "      camera_render: {noise: 2}\n"),
            "c.yaml:8:22: 'camera_render' needs a 'camera' section");
  EXPECT_EQ(error_of(kHead + kCamera + "      camera_render: {flicker: 1.5}\n").rfind("c.yaml:13:", 0), 0u);
  // Sonars with neither count nor mounts and no URDF to take them from.
  EXPECT_EQ(error_of(kHead + "      sonar: {rate: 10}\n"),
            "c.yaml:8:14: missing required key 'count' or 'mounts' in 'sonar' (the base's URDF has no sonar_<i> "
            "links)");
  // A table mirror (samples [theta, radius px]).
  const World t = parse_world(kHead + "      camera: {mirror: {type: table, samples: [[0, 0], [1.0, 100], [1.5, 200]]}}\n",
                              "c.yaml", "");
  EXPECT_NEAR(t.robots[0].sensors.camera.model.profile.radius(1.25), 150.0, 1e-9);
}

TEST(Description, LinkMountComposesFixedJoints) {
  // base_link -> a: (1, 0, 0.5) turned 90 deg; a -> b: (0.2, 0, 0.1) in a,
  // i.e. (1, 0.2, 0.6) in base_link, yaw 90 deg.
  const std::string urdf =
      "<robot name='t'><link name='base_link'/><link name='a'/><link name='b'/>"
      "<joint name='j1' type='fixed'><parent link='base_link'/><child link='a'/>"
      "<origin xyz='1 0 0.5' rpy='0 0 1.5707963267948966'/></joint>"
      "<joint name='j2' type='fixed'><parent link='a'/><child link='b'/><origin xyz='0.2 0 0.1'/></joint>"
      "</robot>";
  const auto m = link_mount(urdf, "b");
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->position.x(), 1.0, 1e-12);
  EXPECT_NEAR(m->position.y(), 0.2, 1e-12);
  EXPECT_NEAR(m->position.z(), 0.6, 1e-12);
  EXPECT_NEAR(m->yaw, M_PI / 2, 1e-12);
  EXPECT_FALSE(link_mount(urdf, "omni_mirror").has_value());
  // Every shipped base with a mirror has its viewpoint 0.7 m up (the
  // omni_mirror_joint origins of the URDFs).
  for (const char* base : {"ianus3", "triskar", "omni4", "p3at"}) {
    const auto d = read_description(MRT_DESCRIPTION_DIR, base);
    ASSERT_TRUE(d.has_value()) << base;
    if (d->omni_mirror) {
      EXPECT_NEAR(d->omni_mirror->position.z(), 0.7, 1e-12) << base;
    }
  }
  EXPECT_FALSE(read_description(MRT_DESCRIPTION_DIR, "roomba").has_value());
}
