#include "mrt_recvision/calibration.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "mrt_common/omni_camera_yaml.h"
#include "mrt_common/ontology.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::recvision {

using mrt::common::YamlReader;

namespace {

void read_color(const YamlReader& r, const YAML::Node& n, ColorTable& table, std::vector<ColorTable>& samples) {
  r.map(n, "colors", {"class", "hsv", "rgb", "samples"});
  const YAML::Node name = r.required(n, "class", "colors");
  ColorClass c;
  if (!parse_color(r.string(name, "class"), c))
    r.fail(name, "expected a colour class (" + color_class_list() + "), got '" + name.Scalar() + "'");
  if (!n["hsv"] && !n["rgb"] && !n["samples"]) r.fail(n, "expected 'hsv', 'rgb' or 'samples' in a colour class");
  if (n["hsv"]) {
    const auto v = r.numbers(n["hsv"], "hsv", 6);
    if (v[0] < 0 || v[1] > 360 || v[0] > 360 || v[1] < 0 || v[2] > v[3] || v[4] > v[5] || v[2] < 0 || v[3] > 1 ||
        v[4] < 0 || v[5] > 1)
      r.fail(n["hsv"], "expected [h_min, h_max, s_min, s_max, v_min, v_max] with hue in [0, 360] and s, v "
                       "ranges inside [0, 1]");
    table.add_range(HsvRange{v[0], v[1], v[2], v[3], v[4], v[5]}, c);
  }
  if (n["rgb"]) {
    const auto v = r.numbers(n["rgb"], "rgb", 6);
    for (int i = 0; i < 6; i += 2)
      if (v[i] < 0 || v[i + 1] > 255 || v[i] > v[i + 1])
        r.fail(n["rgb"], "expected [r_min, r_max, g_min, g_max, b_min, b_max] ranges inside [0, 255]");
    table.add_range(RgbRange{int(v[0]), int(v[1]), int(v[2]), int(v[3]), int(v[4]), int(v[5])}, c);
  }
  if (n["samples"]) {
    ColorTable s;
    const YAML::Node list = n["samples"];  // sequence() returns its argument: keep it alive
    for (const YAML::Node& e : r.sequence(list, "samples")) {
      const auto v = r.numbers(e, "samples", 3);
      for (double x : v)
        if (x < 0 || x > 255 || x != std::floor(x)) r.fail(e, "expected integer RGB values in [0, 255]");
      s.set(std::uint8_t(v[0]), std::uint8_t(v[1]), std::uint8_t(v[2]), c);
    }
    samples.push_back(s);
  }
}

DetectorOptions read_detector(const YamlReader& r, const YAML::Node& n) {
  r.map(n, "detector", {"find", "radial_lines", "circles", "min_distance", "max_distance", "line_max_distance",
                        "line_min_width", "line_max_width", "line_gap", "max_line_points", "ball_radius",
                        "robot_radius", "min_ball_pixels", "min_goal_pixels", "min_robot_pixels"});
  DetectorOptions o;
  if (n["find"]) {
    o.find_lines = o.find_ball = o.find_goals = o.find_robots = false;
    const YAML::Node list = n["find"];
    for (const YAML::Node& e : r.sequence(list, "find")) {
      const std::string f = r.string(e, "find");
      if (f == "lines") o.find_lines = true;
      else if (f == "ball") o.find_ball = true;
      else if (f == "goals") o.find_goals = true;
      else if (f == "robots") o.find_robots = true;
      else r.fail(e, "expected lines, ball, goals or robots in 'find', got '" + f + "'");
    }
  }
  if (n["radial_lines"]) o.radial_lines = int(r.integer(n["radial_lines"], "radial_lines", 8, 4096));
  if (n["circles"]) {
    o.circles.clear();
    const YAML::Node list = n["circles"];
    for (const YAML::Node& e : r.sequence(list, "circles")) o.circles.push_back(r.positive(e, "circles"));
  }
  o.min_distance = r.non_negative(n, "min_distance", o.min_distance);
  o.max_distance = r.positive(n, "max_distance", o.max_distance);
  o.line_max_distance = r.positive(n, "line_max_distance", o.line_max_distance);
  o.line_min_width = r.non_negative(n, "line_min_width", o.line_min_width);
  o.line_max_width = r.positive(n, "line_max_width", o.line_max_width);
  if (n["line_gap"]) o.line_gap = int(r.integer(n["line_gap"], "line_gap", 0, 32));
  if (n["max_line_points"]) o.max_line_points = int(r.integer(n["max_line_points"], "max_line_points", 0, 100000));
  o.ball_radius = r.positive(n, "ball_radius", o.ball_radius);
  o.robot_radius = r.positive(n, "robot_radius", o.robot_radius);
  if (n["min_ball_pixels"]) o.min_ball_pixels = int(r.integer(n["min_ball_pixels"], "min_ball_pixels", 1, 1 << 20));
  if (n["min_goal_pixels"]) o.min_goal_pixels = int(r.integer(n["min_goal_pixels"], "min_goal_pixels", 1, 1 << 20));
  if (n["min_robot_pixels"])
    o.min_robot_pixels = int(r.integer(n["min_robot_pixels"], "min_robot_pixels", 1, 1 << 20));
  if (o.max_distance <= o.min_distance) r.fail(n, "expected 'max_distance' > 'min_distance'");
  if (o.line_max_width <= o.line_min_width) r.fail(n, "expected 'line_max_width' > 'line_min_width'");
  return o;
}

ColorClass color_of(const YamlReader& r, const YAML::Node& n, const std::string& what) {
  ColorClass c;
  if (!parse_color(r.string(n, what), c))
    r.fail(n, "expected a colour class (" + color_class_list() + ") in '" + what + "', got '" + n.Scalar() + "'");
  return c;
}

std::vector<ColorClass> colors_of(const YamlReader& r, const YAML::Node& list, const std::string& what) {
  std::vector<ColorClass> out;
  for (const YAML::Node& e : r.sequence(list, what)) out.push_back(color_of(r, e, what));
  if (out.empty()) r.fail(list, "expected at least one colour class in '" + what + "'");
  return out;
}

ObjectKind read_kind(const YamlReader& r, const YAML::Node& n) {
  r.map(n, "kinds", {"class", "colors", "radius", "width"});
  ObjectKind k;
  k.membership_class = r.string(r.required(n, "class", "kinds"), "class");
  if (!mrt::common::Ontology::standard().find_class(k.membership_class))
    r.fail(n["class"], "expected a class of the ontology (mrt_common/ontology/mrt.yaml), got '" + k.membership_class + "'");
  k.colors = colors_of(r, r.required(n, "colors", "kinds"), "colors");
  k.radius = r.non_negative(n, "radius", 0.0);
  if (n["width"]) {
    const auto w = r.numbers(n["width"], "width", 2);
    if (w[0] < 0 || w[1] <= w[0]) r.fail(n["width"], "expected 'width' as [min, max] with 0 <= min < max (m)");
    k.min_width = w[0];
    k.max_width = w[1];
  }
  return k;
}

ObjectOptions read_objects(const YamlReader& r, const YAML::Node& n) {
  r.map(n, "objects", {"floor", "max_jump", "min_pixels", "kinds", "wall", "wall_step", "wall_max_distance"});
  ObjectOptions o;
  o.enabled = true;
  o.floor = colors_of(r, r.required(n, "floor", "objects"), "floor");
  o.max_jump = r.positive(n, "max_jump", o.max_jump);
  if (n["min_pixels"]) o.min_pixels = int(r.integer(n["min_pixels"], "min_pixels", 1, 1000));
  if (n["kinds"]) {
    const YAML::Node list = n["kinds"];
    for (const YAML::Node& e : r.sequence(list, "kinds")) o.kinds.push_back(read_kind(r, e));
  }
  if (n["wall"]) o.wall = color_of(r, n["wall"], "wall");
  if (n["wall_step"]) o.wall_step = int(r.integer(n["wall_step"], "wall_step", 1, 4096));
  o.wall_max_distance = r.positive(n, "wall_max_distance", o.wall_max_distance);
  return o;
}

std::string directory_of(const std::string& file) {
  const auto slash = file.find_last_of('/');
  return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

}  // namespace

Calibration parse_calibration(const std::string& yaml_text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(yaml_text);
  r.map(root, "calibration", {"camera", "mount", "colors", "lut", "detector", "objects"});
  Calibration cal;
  cal.file = file;
  cal.camera = mrt::common::read_omni_camera(r, r.required(root, "camera", "calibration"));
  if (root["mount"]) {
    const YAML::Node m = root["mount"];
    if (!m.IsSequence() || (m.size() != 2 && m.size() != 3)) r.fail(m, "expected 'mount' as [x, y] or [x, y, yaw]");
    cal.mount_x = r.number(m[0], "mount");
    cal.mount_y = r.number(m[1], "mount");
    if (m.size() == 3) cal.mount_yaw = r.number(m[2], "mount");
  }
  std::vector<ColorTable> samples;
  const YAML::Node colors = r.required(root, "colors", "calibration");
  for (const YAML::Node& c : r.sequence(colors, "colors"))
    read_color(r, c, cal.colors, samples);
  for (const ColorTable& s : samples) cal.colors.overlay(s);
  if (root["lut"]) {
    const std::string name = r.string(root["lut"], "lut");
    const std::string path = !name.empty() && name[0] == '/' ? name : directory_of(file) + name;
    try {
      cal.colors.overlay(ColorTable::load(path));
    } catch (const std::runtime_error& e) {
      r.fail(root["lut"], e.what());
    }
  }
  if (root["detector"]) cal.detector = read_detector(r, root["detector"]);
  if (root["objects"]) cal.objects = read_objects(r, root["objects"]);
  return cal;
}

Calibration scale_calibration(const Calibration& cal, double scale) {
  if (scale == 1.0) return cal;
  Calibration out = cal;
  out.camera = cal.camera.scaled(scale);
  auto scaled = [&](int px, double factor, int at_least) {
    return std::max(at_least, static_cast<int>(std::lround(px * factor)));
  };
  DetectorOptions& d = out.detector;
  d.min_ball_pixels = scaled(cal.detector.min_ball_pixels, scale * scale, 1);
  d.min_goal_pixels = scaled(cal.detector.min_goal_pixels, scale, 1);
  d.min_robot_pixels = scaled(cal.detector.min_robot_pixels, scale, 1);
  d.line_gap = scaled(cal.detector.line_gap, scale, 0);
  out.objects.min_pixels = scaled(cal.objects.min_pixels, scale, 1);
  return out;
}

DetectorTuning tuning_of(const DetectorOptions& o) {
  return {o.min_distance, o.max_distance, o.line_max_distance, o.min_ball_pixels, o.min_goal_pixels,
          o.min_robot_pixels};
}

DetectorOptions retuned(const DetectorOptions& o, const DetectorTuning& t) {
  const auto require = [](bool ok, const char* key, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("detector '") + key + "': expected " + what);
  };
  require(std::isfinite(t.min_distance) && t.min_distance >= 0.0, "min_distance", "a finite number >= 0 (m)");
  require(std::isfinite(t.max_distance) && t.max_distance > t.min_distance, "max_distance",
          "a finite number > 'min_distance' (m)");
  require(std::isfinite(t.line_max_distance) && t.line_max_distance > 0.0, "line_max_distance",
          "a finite number > 0 (m)");
  require(t.min_ball_pixels >= 1, "min_ball_pixels", "an integer >= 1");
  require(t.min_goal_pixels >= 1, "min_goal_pixels", "an integer >= 1");
  require(t.min_robot_pixels >= 1, "min_robot_pixels", "an integer >= 1");
  DetectorOptions out = o;
  out.min_distance = t.min_distance;
  out.max_distance = t.max_distance;
  out.line_max_distance = t.line_max_distance;
  out.min_ball_pixels = t.min_ball_pixels;
  out.min_goal_pixels = t.min_goal_pixels;
  out.min_robot_pixels = t.min_robot_pixels;
  return out;
}

Calibration load_calibration(const std::string& path) {
  return parse_calibration(mrt::common::read_file(path, "cannot open calibration file", 1u << 20), path);
}

}  // namespace mrt::recvision
