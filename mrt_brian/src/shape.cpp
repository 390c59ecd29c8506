#include "mrt_brian/shape.h"

namespace mrt::brian {

Shape Shape::from_def(const ShapeDef& def) {
  Shape s(def.name);
  for (const auto& set : def.sets) s.add(make_fuzzy_set(set.type, set.label, set.params));
  return s;
}

int Shape::find(const std::string& label) const {
  for (std::size_t i = 0; i < sets_.size(); ++i)
    if (sets_[i]->label() == label) return static_cast<int>(i);
  return -1;
}

}  // namespace mrt::brian
