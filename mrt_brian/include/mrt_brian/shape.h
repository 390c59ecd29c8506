// A shape: a named collection of fuzzy sets covering the range of a datum or
// of an action (manual §10.3.1).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"
#include "mrt_brian/fuzzy_set.h"

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

 private:
  std::string name_;
  std::vector<std::shared_ptr<const FuzzySet>> sets_;
};

}  // namespace mrt::brian
