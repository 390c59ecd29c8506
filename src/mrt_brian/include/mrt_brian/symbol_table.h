// Names interned to dense ids once, when a rule base is loaded, so that the
// per-cycle work is array indexing only.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

namespace mrt::brian {

class SymbolTable {
 public:
  /// Id of `name`, adding it if new.
  int intern(const std::string& name) {
    auto it = ids_.find(name);
    if (it != ids_.end()) return it->second;
    const int id = static_cast<int>(names_.size());
    ids_.emplace(name, id);
    names_.push_back(name);
    return id;
  }
  /// Id of `name` or -1.
  int find(const std::string& name) const {
    auto it = ids_.find(name);
    return it == ids_.end() ? -1 : it->second;
  }
  const std::string& name(int id) const { return names_.at(static_cast<std::size_t>(id)); }
  int size() const { return static_cast<int>(names_.size()); }

 private:
  std::unordered_map<std::string, int> ids_;
  std::vector<std::string> names_;
};

}  // namespace mrt::brian
