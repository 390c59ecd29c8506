#include "mrt_brian/fuzzyfier.h"

#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

Fuzzyfier::Fuzzyfier(const std::vector<ShapeDef>& shapes, const std::vector<AssociationDef>& assocs,
                     const std::string& shapes_file, const std::string& assoc_file) {
  SymbolTable shape_ids;
  shapes_ = build_shapes(shapes, shapes_file, shape_ids);
  for (const auto& a : assocs) {
    const int shape = shape_ids.find(a.shape);
    if (shape < 0)
      throw ParseError(a.file.empty() ? assoc_file : a.file, a.line, a.column, "unknown shape '" + a.shape + "' for '" + a.name + "'");
    const int id = data_.intern(a.name);
    if (id < static_cast<int>(shape_of_.size())) {  // re-association: last one wins
      shape_of_[static_cast<std::size_t>(id)] = shape;
      first_slot_[static_cast<std::size_t>(id)] = slot_count_;
    } else {
      shape_of_.push_back(shape);
      first_slot_.push_back(slot_count_);
    }
    slot_count_ += shapes_[static_cast<std::size_t>(shape)].size();
  }
}

int Fuzzyfier::slot(int datum, const std::string& label) const {
  if (datum < 0) return -1;
  const int i = shape_of(datum).find(label);
  return i < 0 ? -1 : first_slot(datum) + i;
}

int Fuzzyfier::slot(const std::string& datum, const std::string& label) const {
  return slot(datum_id(datum), label);
}

void Fuzzyfier::fuzzify(int datum, double value, double reliability, FuzzyValue* slots) const {
  const Shape& s = shape_of(datum);
  FuzzyValue* out = slots + first_slot(datum);
  for (int i = 0; i < s.size(); ++i) out[i] = {s.set(i).membership(value), reliability};
}

std::vector<Fuzzyfier::FuzzyDatum> Fuzzyfier::fuzzify(const CrispDataList& crisp) const {
  std::vector<FuzzyValue> slots(static_cast<std::size_t>(slot_count_));
  std::vector<FuzzyDatum> out;
  for (const auto& c : crisp) {
    const int d = datum_id(c.name);
    if (d < 0) continue;
    fuzzify(d, c.value, c.reliability, slots.data());
    const Shape& s = shape_of(d);
    for (int i = 0; i < s.size(); ++i) {
      const FuzzyValue v = slots[static_cast<std::size_t>(first_slot(d) + i)];
      if (v.stored()) out.push_back({c.name, s.set(i).label(), v});
    }
  }
  return out;
}

}  // namespace mrt::brian
