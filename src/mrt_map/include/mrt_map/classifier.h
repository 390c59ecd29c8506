// Classifier (manual chapter 8): percept objects become perceived objects
// of the best-matching class of the conceptual model, with a matching
// degree, placed in the world frame.
#pragma once

#include <optional>
#include <string>

#include "mrt_map/conceptual_model.h"
#include "mrt_map/types.h"

namespace mrt::map {

/// Why a percept object was not turned into an observation.
enum class Rejection { kNone, kUnknownClass, kNonFinite, kNoPosition, kUnmatched };
const char* to_string(Rejection r);

struct Classification {
  int class_index = -1;
  double degree = 0.0;
};

class Classifier {
 public:
  explicit Classifier(const ConceptualModel& model) : model_(model) {}

  /// Degree of `object` in class `c`: the minimum (fuzzy AND, as in
  /// Mr. BRIAN) of the matchers of `c` and its ancestors up to `from`
  /// (excluded, -1 = all) over the attributes the object has; 1 when none
  /// applies. Empty when `require_all` and an attribute is missing.
  std::optional<double> degree(const PerceptObject& object, int c, int from, bool require_all) const;

  /// The class of `object`: starting from its declared class (which must be
  /// in the model), descend to a child while exactly one child reaches the
  /// threshold or the best beats the next by the ambiguity margin; a child
  /// without matchers of its own, or whose attributes the object lacks, is
  /// not a candidate (an ambiguous
  /// object keeps the most specific class it surely belongs to).
  std::optional<Classification> classify(const PerceptObject& object, Rejection* why = nullptr) const;

  /// Classifies and places `object`, seen from `pose` at `stamp`, in the
  /// world frame: position from distance/bearing (preferred) or x/y in the
  /// robot frame, covariance from their variabilities (the class's
  /// default_sigma when 0) rotated into the world plus the pose's own.
  std::optional<Observation> observe(const PerceptObject& object, const RobotPose& pose, double stamp,
                                     const std::string& robot, const std::string& sensor,
                                     Rejection* why = nullptr) const;

 private:
  const ConceptualModel& model_;
};

}  // namespace mrt::map
