// The ontology file's reader and the percept check (ontology.h).
#include "mrt_common/ontology.h"

#include <algorithm>
#include <set>

#include "mrt_common/yaml_reader.h"

namespace mrt::common {

namespace detail {
extern const char* const kOntologyYaml;  // ontology_data.cpp, generated
}

void PerceptDrops::count(PerceptFault f) {
  if (f == PerceptFault::kUnknownClass) ++unknown_class;
  else if (f == PerceptFault::kMissingAttribute) ++missing_attribute;
  else if (f == PerceptFault::kWrongKind) ++wrong_kind;
}

const Ontology& Ontology::standard() {
  static const Ontology o = parse(detail::kOntologyYaml, "mrt_common/ontology/mrt.yaml");
  return o;
}

Ontology Ontology::load(const std::string& path) { return parse(read_file(path, "cannot open ontology file"), path); }

Ontology Ontology::parse(const std::string& text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(text, "YAML syntax error: ");
  if (!root.IsMap()) r.fail(root, "expected a map with 'attributes' and 'classes'");
  r.map(root, "ontology", {"attributes", "classes"});
  Ontology o;
  for (const auto& kv : r.required(root, "attributes", "ontology")) {
    const YAML::Node& n = kv.second;
    AttributeSpec a;
    a.name = kv.first.Scalar();
    r.map(n, "attribute " + a.name, {"type", "unit", "frame", "doc"});
    const std::string type = r.string(n, "type", "", true, "attribute " + a.name);
    if (type != "number" && type != "symbol") r.fail(n["type"], "expected 'type' number or symbol, got '" + type + "'");
    a.symbol = type == "symbol";
    a.unit = r.string(n, "unit", "", false, a.name);
    a.frame = r.string(n, "frame", "", false, a.name);
    a.doc = r.string(n, "doc", "", false, a.name);
    o.attributes_[a.name] = a;
  }
  const YAML::Node classes = r.required(root, "classes", "ontology");
  for (const auto& kv : classes) {
    const YAML::Node& n = kv.second;
    ClassSpec c;
    c.name = kv.first.Scalar();
    r.map(n, "class " + c.name, {"parent", "required", "doc"});
    c.parent = r.string(n, "parent", "", false, c.name);
    c.doc = r.string(n, "doc", "", false, c.name);
    if (const YAML::Node q = n["required"])
      for (const YAML::Node& e : r.sequence(q, "required")) {
        const std::string a = r.string(e, "required");
        if (a != "position" && !o.attributes_.count(a)) r.fail(e, "expected a declared attribute or 'position', got '" + a + "'");
        c.required.push_back(a);
      }
    o.classes_[c.name] = c;
  }
  // Parents exist and the hierarchy has no cycle.
  for (const auto& kv : classes) {
    const std::string name = kv.first.Scalar();
    std::set<std::string> seen{name};
    for (const ClassSpec* c = &o.classes_.at(name); !c->parent.empty();) {
      const auto it = o.classes_.find(c->parent);
      if (it == o.classes_.end()) r.fail(kv.second["parent"], "expected a declared class as parent, got '" + c->parent + "'");
      if (!seen.insert(c->parent).second) r.fail(kv.second["parent"], "the class hierarchy has a cycle through '" + name + "'");
      c = &it->second;
    }
  }
  return o;
}

const ClassSpec* Ontology::find_class(std::string_view name) const {
  const auto it = classes_.find(name);
  return it == classes_.end() ? nullptr : &it->second;
}

const AttributeSpec* Ontology::find_attribute(std::string_view name) const {
  const auto it = attributes_.find(name);
  return it == attributes_.end() ? nullptr : &it->second;
}

bool Ontology::is_a(std::string_view cls, std::string_view ancestor) const {
  for (const ClassSpec* c = find_class(cls); c; c = c->parent.empty() ? nullptr : find_class(c->parent))
    if (c->name == ancestor) return true;
  return false;
}

std::vector<std::string> Ontology::required(std::string_view cls) const {
  std::vector<const ClassSpec*> chain;
  for (const ClassSpec* c = find_class(cls); c; c = c->parent.empty() ? nullptr : find_class(c->parent))
    chain.push_back(c);
  std::vector<std::string> out;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it)
    for (const std::string& a : (*it)->required)
      if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
  return out;
}

PerceptFault Ontology::check(const PerceptObject& o, std::string* why) const {
  auto fail = [&](PerceptFault f, const std::string& msg) {
    if (why) *why = msg;
    return f;
  };
  if (!find_class(o.membership_class))
    return fail(PerceptFault::kUnknownClass, "unknown class '" + o.membership_class + "'");
  for (const Attribute& a : o.attributes)
    if (const AttributeSpec* s = find_attribute(a.name); s && s->symbol != a.is_symbol())
      return fail(PerceptFault::kWrongKind, "attribute '" + a.name + "' of " + o.membership_class + " '" + o.name +
                                                "' must be a " + (s->symbol ? "symbol" : "number"));
  for (const std::string& r : required(o.membership_class)) {
    const bool ok = r == "position" ? polar(o).has_value() : o.find(r) != nullptr;
    if (!ok)
      return fail(PerceptFault::kMissingAttribute, o.membership_class + " '" + o.name + "' lacks " +
                                                       (r == "position" ? "a position (distance and bearing, or x and y)"
                                                                        : "attribute '" + r + "'"));
  }
  return PerceptFault::kNone;
}

void Ontology::filter(std::vector<PerceptObject>& objects, PerceptDrops& drops) const {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const PerceptFault f = check(objects[i]);
    if (f != PerceptFault::kNone) {
      drops.count(f);
      continue;
    }
    if (kept != i) objects[kept] = std::move(objects[i]);
    ++kept;
  }
  objects.resize(kept);
}

}  // namespace mrt::common
