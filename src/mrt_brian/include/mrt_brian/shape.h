// A shape: a named collection of fuzzy sets covering the range of a datum or
// of an action (manual §10.3.1).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"
#include "mrt_brian/fuzzy_set.h"
#include "mrt_brian/symbol_table.h"

namespace mrt::brian {

class Shape {
 public:
  Shape() = default;
  explicit Shape(std::string name) : name_(std::move(name)) {}
  /// Builds a shape from its parsed form (throws std::invalid_argument).
  static Shape from_def(const ShapeDef& def);

  const std::string& name() const { return name_; }
  void add(std::unique_ptr<FuzzySet> set) { sets_.push_back(std::move(set)); }
  int size() const { return static_cast<int>(sets_.size()); }
  const FuzzySet& set(int i) const { return *sets_.at(static_cast<std::size_t>(i)); }
  /// Index of the set labelled `label`, or -1.
  int find(const std::string& label) const;
  /// Declared `(CIRCULAR lo hi)`: the range [lo, hi) wraps around.
  bool circular() const { return circular_; }
  double range_lo() const { return range_lo_; }
  double range_hi() const { return range_hi_; }
  void set_circular(double lo, double hi) {
    circular_ = true;
    range_lo_ = lo;
    range_hi_ = hi;
  }

 private:
  std::string name_;
  bool circular_ = false;
  double range_lo_ = 0.0, range_hi_ = 0.0;
  std::vector<std::shared_ptr<const FuzzySet>> sets_;
};

/// The shapes of a shapes file (shape_ctof.txt, s_shape.txt), in order, each
/// name interned in `ids` with its index. Throws mrt::common::ParseError
/// naming `file` for a shape defined twice or a bad set; `check`, if given,
/// is called on each definition once its shape is built and may throw too.
std::vector<Shape> build_shapes(const std::vector<ShapeDef>& defs, const std::string& file, SymbolTable& ids,
                                const std::function<void(const ShapeDef&)>& check = {});

}  // namespace mrt::brian
