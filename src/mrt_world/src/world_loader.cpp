// The static sections of a world file (format: README).
#include "mrt_world/world_loader.h"

#include <cmath>
#include <set>

#include "mrt_common/angle.h"
#include "mrt_common/ontology.h"
#include "mrt_common/parse_error.h"

namespace mrt::world {

namespace {

using mrt::common::deg_to_rad;
using mrt::common::ParseError;
using mrt::common::YamlReader;
using YAML::Node;

Segment segment(const YamlReader& r, const Node& n, const std::string& key) {
  const auto v = r.numbers(n, key, 4);
  return {{v[0], v[1]}, {v[2], v[3]}};
}

Point2D point(const YamlReader& r, const Node& n, const std::string& key) {
  const auto v = r.numbers(n, key, 2);
  return {v[0], v[1]};
}

// [x1, y1, x2, y2], or an arc {center, radius, segments, from, to} (deg)
// expanded into a polygon of `segments` chords.
void field_line(const YamlReader& r, const Node& n, std::vector<Segment>& out) {
  if (!n.IsMap()) {
    out.push_back(segment(r, n, "field_lines"));
    return;
  }
  r.map(n, "field_lines arc", {"center", "radius", "segments", "from", "to"});
  const Point2D c = point(r, r.required(n, "center", "field_lines arc"), "center");
  r.required(n, "radius", "field_lines arc");
  const double rad = r.positive(n, "radius", 1.0);
  const long long k = n["segments"] ? r.integer(n["segments"], "segments", 1, 3600) : 24;
  const double from = deg_to_rad(r.number(n, "from", 0.0)), to = deg_to_rad(r.number(n, "to", 360.0));
  for (long long i = 0; i < k; ++i) {
    const double a0 = from + (to - from) * i / k, a1 = from + (to - from) * (i + 1) / k;
    out.push_back({{c.x + rad * std::cos(a0), c.y + rad * std::sin(a0)},
                   {c.x + rad * std::cos(a1), c.y + rad * std::sin(a1)}});
  }
}

Post post(const YamlReader& r, const Node& n) {
  r.map(n, "posts", {"name", "class", "color", "x", "y", "radius"});
  Post p;
  p.name = r.string(n, "name", "", true, "posts");
  p.membership_class = r.string(n, "class", "Obstacle", false, "posts");
  if (!mrt::common::Ontology::standard().find_class(p.membership_class))
    r.fail(n["class"], "expected a class of the ontology (mrt_common/ontology/mrt.yaml) for post '" + p.name +
                           "', got '" + p.membership_class + "'");
  p.color = r.string(n, "color", "", false, "posts");
  p.center = {r.number(r.required(n, "x", "posts"), "x"), r.number(r.required(n, "y", "posts"), "y")};
  p.radius = r.positive(n, "radius", p.radius);
  return p;
}

Goal goal(const YamlReader& r, const Node& n) {
  r.map(n, "goals", {"name", "color", "x", "y", "theta", "width", "depth"});
  Goal g;
  g.name = r.string(n, "name", "", true, "goals");
  g.color = r.string(n, "color", "", false, "goals");
  g.pose = Pose2D(r.number(r.required(n, "x", "goals"), "x"), r.number(r.required(n, "y", "goals"), "y"),
                  deg_to_rad(r.number(n, "theta", 0.0)));
  g.width = r.positive(n, "width", g.width);
  g.depth = r.positive(n, "depth", g.depth);
  return g;
}

// {name, wall: [x1, y1, x2, y2]}: the wall that closes the opening.
Door door(const YamlReader& r, const Node& n) {
  r.map(n, "doors", {"name", "wall"});
  return {r.string(n, "name", "", true, "doors"), segment(r, r.required(n, "wall", "doors"), "wall")};
}

// {name, polygon: [[x, y], ...]} with at least 3 corners.
Region region(const YamlReader& r, const Node& n) {
  r.map(n, "regions", {"name", "polygon"});
  Region g;
  g.name = r.string(n, "name", "", true, "regions");
  const Node pn = r.sequence(r.required(n, "polygon", "regions"), "polygon");
  for (const Node& e : pn) g.polygon.push_back(point(r, e, "polygon"));
  if (g.polygon.size() < 3) r.fail(pn, "expected at least 3 corners in the polygon of region '" + g.name + "'");
  return g;
}

// Names unique within a section.
template <class T>
void unique_names(const YamlReader& r, const Node& seq, const std::vector<T>& items, const std::string& what) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (!names.insert(items[i].name).second)
      r.fail(seq[i]["name"], "duplicate " + what + " name '" + items[i].name + "'");
}

}  // namespace

World read_world(const YamlReader& r, const Node& root) {
  if (!root.IsMap()) {
    if (root.IsNull()) throw ParseError(r.file(), 1, 1, "expected a map at the top level, got an empty document");
    r.fail(root, "expected a map at the top level");
  }
  // The map() check with every key of the format: the static ones and the
  // simulator's (read by mrt_sim, skipped here).
  r.map(root, "world", {"name", "bounds", "walls", "field_lines", "line_width", "posts", "goals", "doors", "regions",
                        "seed", "ball", "movers", "robots", "floor_color", "surfaces"});
  World w;
  w.file = r.file();
  w.name = r.string(root, "name", "", true, "world");
  const Node bn = r.required(root, "bounds", "world");
  const auto b = r.numbers(bn, "bounds", 4);
  if (!(b[0] < b[2] && b[1] < b[3])) r.fail(bn, "expected 'bounds' [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax");
  w.min_x = b[0], w.min_y = b[1], w.max_x = b[2], w.max_y = b[3];
  if (const Node n = root["walls"])
    for (const Node& e : r.sequence(n, "walls")) w.walls.push_back(segment(r, e, "walls"));
  w.line_width = r.positive(root, "line_width", w.line_width);
  if (const Node n = root["field_lines"])
    for (const Node& e : r.sequence(n, "field_lines")) field_line(r, e, w.field_lines);
  if (const Node n = root["posts"])
    for (const Node& e : r.sequence(n, "posts")) w.posts.push_back(post(r, e));
  if (const Node n = root["goals"])
    for (const Node& e : r.sequence(n, "goals")) w.goals.push_back(goal(r, e));
  if (const Node n = root["doors"]) {
    for (const Node& e : r.sequence(n, "doors")) w.doors.push_back(door(r, e));
    unique_names(r, n, w.doors, "door");
  }
  if (const Node n = root["regions"]) {
    for (const Node& e : r.sequence(n, "regions")) w.regions.push_back(region(r, e));
    unique_names(r, n, w.regions, "region");
  }
  return w;
}

World parse_world(const std::string& yaml_text, const std::string& file) {
  const YamlReader r(file);
  const Node root = r.load(yaml_text, "YAML syntax error: ");
  try {
    return read_world(r, root);
  } catch (const YAML::Exception& e) {  // a conversion not caught above: still name the place
    throw r.error(e);
  }
}

World load_world(const std::string& path) {
  return parse_world(mrt::common::read_file(path, "cannot open world file"), path);
}

}  // namespace mrt::world
