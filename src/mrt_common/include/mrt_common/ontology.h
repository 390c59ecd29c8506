// The shared ontology as data (mrt_common/ontology/mrt.yaml): its classes,
// their hierarchy and required attributes, the attributes with their kinds
// and units; and the check a consumer applies to every percept object
// before using it (drop and count what fails). ROS-free; library
// mrt_common_percept (links yaml-cpp), the standard ontology compiled in.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "mrt_common/percept.h"

namespace mrt::common {

struct AttributeSpec {
  std::string name;
  bool symbol = false;  // a symbol (a label), else a number
  std::string unit;     // SI (REP-103); "" for symbols
  std::string frame;    // "percept" when given in the percept's frame, else ""
  std::string doc;
};

struct ClassSpec {
  std::string name;
  std::string parent;                 // "" for a root
  std::vector<std::string> required;  // attribute names, or "position" (polar or Cartesian)
  std::string doc;
};

/// Why check() refused an object.
enum class PerceptFault { kNone, kUnknownClass, kMissingAttribute, kWrongKind };

/// Percept objects a consumer dropped, by reason (for its diagnostics).
struct PerceptDrops {
  std::size_t unknown_class = 0;      // a class the ontology does not have
  std::size_t missing_attribute = 0;  // a required attribute (or the position) missing
  std::size_t wrong_kind = 0;         // a declared attribute given as a symbol instead of a number or so
  std::size_t total() const { return unknown_class + missing_attribute + wrong_kind; }
  void count(PerceptFault f);
};

class Ontology {
 public:
  /// The stack's ontology (mrt_common/ontology/mrt.yaml as built).
  static const Ontology& standard();
  /// Parses an ontology file's text; throws ParseError (file:line:column).
  static Ontology parse(const std::string& yaml_text, const std::string& file);
  static Ontology load(const std::string& path);

  const ClassSpec* find_class(std::string_view name) const;
  const AttributeSpec* find_attribute(std::string_view name) const;
  /// `cls` is `ancestor` or one of its descendants (false if either is unknown).
  bool is_a(std::string_view cls, std::string_view ancestor) const;
  /// Every requirement of `cls`, its ancestors' included (root first).
  std::vector<std::string> required(std::string_view cls) const;
  const std::map<std::string, ClassSpec, std::less<>>& classes() const { return classes_; }
  const std::map<std::string, AttributeSpec, std::less<>>& attributes() const { return attributes_; }

  /// kNone when `o` is of a known class, carries every required attribute
  /// (the position in either form) and gives each declared attribute in its
  /// kind; undeclared attributes are tolerated. `why`, when given, says
  /// what is wrong.
  PerceptFault check(const PerceptObject& o, std::string* why = nullptr) const;

  /// Removes from `objects` those check() refuses, counting them in `drops`.
  void filter(std::vector<PerceptObject>& objects, PerceptDrops& drops) const;

 private:
  std::map<std::string, ClassSpec, std::less<>> classes_;
  std::map<std::string, AttributeSpec, std::less<>> attributes_;
};

}  // namespace mrt::common
