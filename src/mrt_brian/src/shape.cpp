#include "mrt_brian/shape.h"

#include <stdexcept>

#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

Shape Shape::from_def(const ShapeDef& def) {
  Shape s(def.name);
  for (const auto& set : def.sets) s.add(make_fuzzy_set(set.type, set.label, set.params));
  if (def.circular) s.set_circular(def.range_lo, def.range_hi);
  return s;
}

int Shape::find(const std::string& label) const {
  for (std::size_t i = 0; i < sets_.size(); ++i)
    if (sets_[i]->label() == label) return static_cast<int>(i);
  return -1;
}

std::vector<Shape> build_shapes(const std::vector<ShapeDef>& defs, const std::string& file, SymbolTable& ids,
                                const std::function<void(const ShapeDef&)>& check) {
  std::vector<Shape> shapes;
  for (const auto& def : defs) {
    const std::string& where = def.file.empty() ? file : def.file;  // its own file when the slot has several
    if (ids.find(def.name) >= 0)
      throw ParseError(where, def.line, def.column, "shape '" + def.name + "' defined twice");
    ids.intern(def.name);
    try {
      shapes.push_back(Shape::from_def(def));
    } catch (const std::invalid_argument& e) {
      throw ParseError(where, def.line, def.column, e.what());
    }
    if (check) check(def);
  }
  return shapes;
}

}  // namespace mrt::brian
