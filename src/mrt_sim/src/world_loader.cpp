// The YAML world-file loader: every error names file:line:column (the
// strict readers of mrt_common/yaml_reader.h). The format is documented in
// the README.
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "mrt_common/angle.h"
#include "mrt_common/omni_camera_yaml.h"
#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"
#include "mrt_sim/description.h"
#include "mrt_sim/world.h"
#include "mrt_world/world_loader.h"

namespace mrt::sim {

using mrt::common::deg_to_rad;
using mrt::common::kPi;
using mrt::common::ParseError;

namespace {

using YAML::Node;

// Reads YAML nodes into the world structs; every error names the node
// (the strict readers: mrt_common/yaml_reader.h).
class Loader : public mrt::common::YamlReader {
 public:
  using YamlReader::error;
  using YamlReader::load;

  Loader(const std::string& file, std::string description_dir)
      : YamlReader(file), description_dir_(std::move(description_dir)) {}

  // The static sections through mrt_world's loader (which also checks
  // every top-level key), then the simulation's.
  World world(const Node& root) const {
    World w;
    static_cast<mrt::world::World&>(w) = mrt::world::read_world(*this, root);
    if (const Node n = root["seed"]) w.seed = static_cast<std::uint64_t>(integer(n, "seed", 0, std::numeric_limits<long long>::max()));
    w.floor_color = string(root, "floor_color", w.floor_color, false, "world");
    if (const Node n = root["ball"]) w.ball = ball(n);
    if (const Node n = root["movers"])
      for (const Node& e : sequence(n, "movers")) w.movers.push_back(mover(e));
    if (const Node n = root["surfaces"])
      for (const Node& e : sequence(n, "surfaces")) w.surfaces.push_back(surface(e));

    const Node rn = required(root, "robots", "world");
    std::set<std::string> names;
    for (const Node& e : sequence(rn, "robots")) {
      w.robots.push_back(robot(e));
      if (!names.insert(w.robots.back().name).second)
        fail(e["name"], "duplicate robot name '" + w.robots.back().name + "'");
    }
    if (w.robots.empty()) fail(rn, "expected at least one robot in 'robots'");
    return w;
  }

  // A floor patch for the physical mice: {name, min: [x, y], max: [x, y],
  // resolution, clearance}.
  Surface surface(const Node& n) const {
    map(n, "surfaces", {"name", "min", "max", "resolution", "clearance"});
    Surface f;
    f.name = string(n, "name", "", false, "surfaces");
    const auto lo = numbers(required(n, "min", "surfaces"), "min", 2);
    const Node hn = required(n, "max", "surfaces");
    const auto hi = numbers(hn, "max", 2);
    if (!(lo[0] < hi[0] && lo[1] < hi[1])) fail(hn, "expected 'max' above and right of 'min' in 'surfaces'");
    f.min_x = lo[0], f.min_y = lo[1], f.max_x = hi[0], f.max_y = hi[1];
    f.resolution = positive(n, "resolution", f.resolution);
    f.clearance = number(n, "clearance", f.clearance);
    return f;
  }

  Ball ball(const Node& n) const {
    map(n, "ball", {"x", "y", "vx", "vy", "radius", "friction", "restitution", "color"});
    Ball b;
    b.enabled = true;
    b.position = {number(n, "x", 0.0), number(n, "y", 0.0)};
    b.velocity = {number(n, "vx", 0.0), number(n, "vy", 0.0)};
    b.radius = positive(n, "radius", b.radius);
    b.friction = non_negative(n, "friction", b.friction);
    b.restitution = fraction(n, "restitution", b.restitution);
    b.color = string(n, "color", b.color, false, "ball");
    return b;
  }

  Mover mover(const Node& n) const {
    map(n, "movers", {"name", "class", "color", "radius", "speed", "loop", "waypoints"});
    Mover m;
    m.name = string(n, "name", "", true, "movers");
    m.membership_class = string(n, "class", "Person", false, "movers");
    if (m.membership_class != "Person" && m.membership_class != "Robot")
      fail(n["class"], "expected 'class' Person or Robot, got '" + m.membership_class + "'");
    m.color = string(n, "color", "", false, "movers");
    m.radius = positive(n, "radius", m.radius);
    m.speed = non_negative(n, "speed", m.speed);
    m.loop = boolean(n, "loop", m.loop);
    const Node wp = sequence(required(n, "waypoints", "movers"), "waypoints");
    for (const Node& e : wp) {
      const auto v = numbers(e, "waypoints", 2);
      m.waypoints.push_back({v[0], v[1]});
    }
    if (m.waypoints.size() < 2) fail(wp, "expected at least 2 waypoints for mover '" + m.name + "'");
    m.position = m.waypoints[0];
    return m;
  }

  Pose2D mount(const Node& n, const std::string& what, Pose2D def) const {
    map(n, what, {"x", "y", "theta"});
    return Pose2D(number(n, "x", def.x), number(n, "y", def.y),
                  n["theta"] ? deg_to_rad(number(n["theta"], "theta")) : def.theta);
  }

  RobotConfig robot(const Node& n) const {
    map(n, "robots", {"name", "base", "base_overrides", "color", "pose", "sensors"});
    RobotConfig r;
    r.name = string(n, "name", "", true, "robots");
    const Node bn = required(n, "base", "robots");
    try {
      r.base = base_preset(string(n, "base", "", true, "robots"));
    } catch (const std::invalid_argument& e) {
      fail(bn, e.what());
    }
    if (const Node o = n["base_overrides"]) overrides(o, r.base);
    r.color = string(n, "color", r.color, false, "robots");
    const auto p = numbers(required(n, "pose", "robots"), "pose", 3);
    r.initial_pose = Pose2D(p[0], p[1], deg_to_rad(p[2]));
    std::optional<DescriptionMounts> d;
    try {
      d = read_description(description_dir_, r.base.name);
    } catch (const std::runtime_error& e) {
      fail(bn, e.what());
    }
    r.sensors = sensors(n["sensors"], r.base, d);
    return r;
  }

  void overrides(const Node& n, BaseConfig& g) const {
    const bool diff = g.type == BaseType::kDifferential;
    if (diff)
      map(n, "base_overrides", {"wheel_radius", "track", "max_wheel_speed", "body_radius"});
    else
      map(n, "base_overrides", {"wheel_radius", "omni_radius", "wheel_angles", "max_wheel_speed", "body_radius"});
    g.wheel_radius = positive(n, "wheel_radius", g.wheel_radius);
    g.track = positive(n, "track", g.track);
    g.wheel_distance = positive(n, "omni_radius", g.wheel_distance);
    g.max_wheel_speed = positive(n, "max_wheel_speed", g.max_wheel_speed);
    g.body_radius = positive(n, "body_radius", g.body_radius);
    if (const Node a = n["wheel_angles"]) {
      sequence(a, "wheel_angles");
      if (a.size() < 3) fail(a, "expected at least 3 numbers for 'wheel_angles'");
      g.wheel_angles.clear();
      for (const Node& e : a) g.wheel_angles.push_back(deg_to_rad(number(e, "wheel_angles")));
      try {
        wheels_to_twist(g, std::vector<double>(g.wheel_angles.size(), 0.0));
      } catch (const std::invalid_argument&) {
        fail(a, "expected 'wheel_angles' that determine the body twist (not all collinear)");
      }
    }
  }

  SensorsConfig sensors(const Node& n, const BaseConfig& base, const std::optional<DescriptionMounts>& d) const {
    SensorsConfig s;
    s.rate_mice = s.rate_encoders = s.rate_sonar = s.rate_vision = s.rate_dgps = 0.0;
    if (!n) return s;
    map(n, "sensors", {"mice", "encoders", "sonar", "vision", "dgps", "camera", "camera_render"});
    if (const Node m = n["mice"]) mice(m, s, d);
    if (const Node e = n["encoders"]) encoders(e, s);
    if (const Node so = n["sonar"]) sonar(so, base, d, s);
    if (const Node v = n["vision"]) vision(v, s);
    if (const Node g = n["dgps"]) dgps(g, s);
    if (const Node c = n["camera"]) camera(c, n["camera_render"], s, d);
    else if (const Node f = n["camera_render"]) fail(f, "'camera_render' needs a 'camera' section");
    return s;
  }

  // The two mice: shared settings, then per mouse (left, right) a mount and
  // overrides.
  // The mounts come from the robot's URDF when it has the mouse link; the
  // world file's x, y, theta override them.
  void mice(const Node& m, SensorsConfig& s, const std::optional<DescriptionMounts>& d) const {
    map(m, "mice", {"rate", "counts_per_m", "noise", "fault_rate", "fault_max_fraction", "left", "right", "model",
                    "height", "liftoff", "height_gain", "max_speed", "max_accel", "report_rate", "phase", "drift_ppm"});
    s.rate_mice = non_negative(m, "rate", 50.0);
    MouseConfig shared;
    const std::string model = string(m, "model", "ideal", false, "mice");
    if (model != "ideal" && model != "physical") fail(m["model"], "expected 'model' ideal or physical, got '" + model + "'");
    shared.physics.enabled = model == "physical";
    physics(m, shared.physics);
    shared.counts_per_m = positive(m, "counts_per_m", shared.counts_per_m);
    shared.noise = non_negative(m, "noise", shared.noise);
    shared.fault_rate = fraction(m, "fault_rate", shared.fault_rate);
    shared.fault_max_fraction = fraction(m, "fault_max_fraction", shared.fault_max_fraction);
    for (const char* id : {"left", "right"}) {
      MouseConfig c = shared;
      c.id = id;
      c.mount = Pose2D(0.0, c.id == "left" ? 0.1 : -0.1, 0.0);
      const std::optional<LinkMount>& urdf = !d ? std::nullopt : c.id == "left" ? d->mouse_left : d->mouse_right;
      if (urdf) c.mount = Pose2D(urdf->position.x(), urdf->position.y(), urdf->yaw);
      if (const Node e = m[id]) {
        map(e, id, {"x", "y", "theta", "counts_per_m", "noise", "fault_rate", "fault_max_fraction", "height", "liftoff",
                    "height_gain", "max_speed", "max_accel", "report_rate", "phase", "drift_ppm"});
        physics(e, c.physics);
        c.mount = Pose2D(number(e, "x", c.mount.x), number(e, "y", c.mount.y),
                         e["theta"] ? deg_to_rad(number(e["theta"], "theta")) : c.mount.theta);
        c.counts_per_m = positive(e, "counts_per_m", c.counts_per_m);
        c.noise = non_negative(e, "noise", c.noise);
        c.fault_rate = fraction(e, "fault_rate", c.fault_rate);
        c.fault_max_fraction = fraction(e, "fault_max_fraction", c.fault_max_fraction);
      }
      s.mice.push_back(c);
    }
  }

  // The physical mouse's settings (shared in `mice`, or one mouse's).
  void physics(const Node& n, MousePhysics& p) const {
    p.height = number(n, "height", p.height);
    p.liftoff = non_negative(n, "liftoff", p.liftoff);
    p.height_gain = non_negative(n, "height_gain", p.height_gain);
    p.max_speed = positive(n, "max_speed", p.max_speed);
    p.max_accel = positive(n, "max_accel", p.max_accel);
    p.report_rate = positive(n, "report_rate", p.report_rate);
    p.phase = non_negative(n, "phase", p.phase);
    p.drift_ppm = bounded(n, "drift_ppm", p.drift_ppm, -1e5, false, 1e5);
  }

  void encoders(const Node& e, SensorsConfig& s) const {
    map(e, "encoders", {"rate", "ticks_per_rev", "noise"});
    s.rate_encoders = non_negative(e, "rate", 50.0);
    s.encoder_noise = non_negative(e, "noise", s.encoder_noise);
    if (e["ticks_per_rev"]) s.ticks_per_rev = static_cast<int>(integer(e["ticks_per_rev"], "ticks_per_rev", 1, 1000000000));
  }

  // The omni_camera_yaml.h block plus `rate`; the viewpoint's x, y (and its
  // height unless the block gives `viewpoint_height`) from the URDF's
  // omni_mirror link; the image effects from `camera_render`.
  void camera(const Node& c, const Node& fx, SensorsConfig& s, const std::optional<DescriptionMounts>& d) const {
    CameraConfig& cam = s.camera;
    cam.model = mrt::common::read_omni_camera(*this, c);
    cam.rate = non_negative(c, "rate", 30.0);
    if (d && d->omni_mirror) {
      const Eigen::Vector3d& p = d->omni_mirror->position;
      cam.mount_x = p.x(), cam.mount_y = p.y();
      if (!c["viewpoint_height"]) {
        if (!(p.z() > 0.0)) fail(c, "the URDF's omni_mirror is not above the floor: give 'viewpoint_height'");
        cam.model.height = p.z();
        cam.model.profile = mrt::common::read_mirror_profile(*this, c["mirror"], p.z());
      }
    }
    if (!fx) return;
    map(fx, "camera_render", {"enabled", "x", "y", "noise", "illumination", "illumination_scale", "flicker",
                              "flicker_period", "exposure", "white_balance_drift", "white_balance_period"});
    if (!boolean(fx, "enabled", true)) cam.rate = 0.0;
    cam.mount_x = number(fx, "x", cam.mount_x);
    cam.mount_y = number(fx, "y", cam.mount_y);
    CameraEffects& e = cam.effects;
    e.noise = non_negative(fx, "noise", e.noise);
    e.illumination = bounded(fx, "illumination", e.illumination, 0.0, false, 0.9);
    e.illumination_scale = positive(fx, "illumination_scale", e.illumination_scale);
    e.flicker = bounded(fx, "flicker", e.flicker, 0.0, false, 0.9);
    e.flicker_period = positive(fx, "flicker_period", e.flicker_period);
    e.exposure = non_negative(fx, "exposure", e.exposure);
    e.white_balance_drift = bounded(fx, "white_balance_drift", e.white_balance_drift, 0.0, false, 0.9);
    e.white_balance_period = positive(fx, "white_balance_period", e.white_balance_period);
  }

  void vision(const Node& v, SensorsConfig& s) const {
    map(v, "vision", {"rate", "range", "distance_noise", "bearing_noise", "line_point_spacing", "model",
                      "miss_near", "miss_far", "false_positives"});
    s.rate_vision = non_negative(v, "rate", 10.0);
    s.vision_range = positive(v, "range", s.vision_range);
    s.vision_distance_noise = non_negative(v, "distance_noise", s.vision_distance_noise);
    s.vision_bearing_noise = deg_to_rad(non_negative(v, "bearing_noise", mrt::common::rad_to_deg(s.vision_bearing_noise)));
    s.line_point_spacing = bounded(v, "line_point_spacing", s.line_point_spacing, 0.01, false);
    const std::string model = string(v, "model", "ideal", false, "vision");
    if (model != "ideal" && model != "realistic")
      fail(v["model"], "expected 'model' ideal or realistic, got '" + model + "'");
    s.vision_realistic = model == "realistic";
    s.vision_miss_near = fraction(v, "miss_near", s.vision_miss_near);
    s.vision_miss_far = fraction(v, "miss_far", s.vision_miss_far);
    s.vision_false_positives = bounded(v, "false_positives", s.vision_false_positives, 0.0, false, 100.0);
  }

  void dgps(const Node& d, SensorsConfig& s) const {
    map(d, "dgps", {"rate", "noise", "datum"});
    s.rate_dgps = non_negative(d, "rate", 1.0);
    s.dgps_noise = non_negative(d, "noise", s.dgps_noise);
    if (const Node dn = d["datum"]) {
      const auto ll = numbers(dn, "datum", 2);
      if (std::fabs(ll[0]) > 90.0 || std::fabs(ll[1]) > 180.0)
        fail(dn, "expected 'datum' [latitude, longitude] in degrees within [-90, 90] x [-180, 180]");
      s.datum_latitude = ll[0];
      s.datum_longitude = ll[1];
    }
  }

  // Sonars at `count` positions around the body, at `mounts`, or, with
  // neither, at the URDF's sonar_<i> links.
  void sonar(const Node& n, const BaseConfig& base, const std::optional<DescriptionMounts>& d,
             SensorsConfig& s) const {
    map(n, "sonar", {"rate", "noise", "count", "mounts", "fov", "min_range", "max_range"});
    s.rate_sonar = non_negative(n, "rate", 10.0);
    s.sonar_noise = non_negative(n, "noise", s.sonar_noise);
    SonarConfig c;
    if (const Node f = n["fov"]) c.fov = deg_to_rad(bounded(n, "fov", 0.0, 0.0, false, 179.0));
    c.min_range = non_negative(n, "min_range", c.min_range);
    c.max_range = positive(n, "max_range", c.max_range);
    if (c.max_range <= c.min_range) fail(n["max_range"] ? n["max_range"] : n, "expected 'max_range' > 'min_range'");
    const Node cn = n["count"], mn = n["mounts"];
    if (cn && mn) fail(mn, "expected either 'count' or 'mounts' in 'sonar', not both");
    if (cn) {
      const long long k = integer(cn, "count", 1, 360);
      for (long long i = 0; i < k; ++i) {
        const double a = 2.0 * kPi * i / k;
        c.mount = Pose2D(base.body_radius * std::cos(a), base.body_radius * std::sin(a), a);
        s.sonars.push_back(c);
      }
    } else if (mn) {
      for (const Node& e : sequence(mn, "mounts")) {
        c.mount = mount(e, "mounts", Pose2D());
        s.sonars.push_back(c);
      }
    } else if (d && !d->sonars.empty()) {
      for (const LinkMount& m : d->sonars) {
        c.mount = Pose2D(m.position.x(), m.position.y(), m.yaw);
        s.sonars.push_back(c);
      }
    } else {
      fail(n, "missing required key 'count' or 'mounts' in 'sonar' (the base's URDF has no sonar_<i> links)");
    }
  }

 private:
  std::string description_dir_;
};

}  // namespace

World parse_world(const std::string& yaml_text, const std::string& file, const std::string& description_dir) {
  const Loader loader(file, description_dir);
  const Node root = loader.load(yaml_text, "YAML syntax error: ");
  try {
    return loader.world(root);
  } catch (const YAML::Exception& e) {  // a conversion not caught above: still name the place
    throw loader.error(e);
  }
}

World load_world(const std::string& path, const std::string& description_dir) {
  return parse_world(mrt::common::read_file(path, "cannot open world file"), path, description_dir);
}

}  // namespace mrt::sim
