// Fuzzyfier (manual §10.3.1): crisp data -> fuzzy data through the shapes
// associated with each datum (shape_ctof.txt + ctof.txt). The crisp
// reliability is carried unchanged to every fuzzy datum.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"
#include "mrt_brian/shape.h"
#include "mrt_brian/symbol_table.h"
#include "mrt_brian/types.h"

namespace mrt::brian {

class Fuzzyfier {
 public:
  Fuzzyfier() = default;
  /// Throws mrt::common::ParseError naming `assoc_file` for an association
  /// to an unknown shape, and `shapes_file` for a bad or duplicate shape.
  Fuzzyfier(const std::vector<ShapeDef>& shapes, const std::vector<AssociationDef>& assocs,
            const std::string& shapes_file = "shapes", const std::string& assoc_file = "associations");

  /// Datum id of an associated crisp datum, or -1.
  int datum_id(const std::string& name) const { return data_.find(name); }
  const std::string& datum_name(int id) const { return data_.name(id); }
  int datum_count() const { return data_.size(); }
  /// Fuzzy slot of <datum, label>, or -1 when the datum or label is unknown.
  int slot(int datum, const std::string& label) const;
  int slot(const std::string& datum, const std::string& label) const;
  int slot_count() const { return slot_count_; }
  int first_slot(int datum) const { return first_slot_[static_cast<std::size_t>(datum)]; }
  const Shape& shape_of(int datum) const { return shapes_[static_cast<std::size_t>(shape_of_[static_cast<std::size_t>(datum)])]; }

  /// Writes the membership of `value` to each set of the datum's shape, with
  /// reliability `reliability`, into `slots[first_slot(datum) ...]`.
  void fuzzify(int datum, double value, double reliability, FuzzyValue* slots) const;

  /// Convenience: the fuzzy data list of a crisp data list, without the
  /// entries <0, 1> (which are not stored).
  struct FuzzyDatum {
    std::string name, label;
    FuzzyValue value;
  };
  std::vector<FuzzyDatum> fuzzify(const CrispDataList& crisp) const;

 private:
  std::vector<Shape> shapes_;
  SymbolTable data_;
  std::vector<int> shape_of_, first_slot_;
  int slot_count_ = 0;
};

}  // namespace mrt::brian
