// Interface objects of Mr. BRIAN (manual §10.3): crisp data in, commands out,
// and the <value, reliability> pair every fuzzy datum and predicate carries.
#pragma once

#include <string>
#include <vector>

namespace mrt::brian {

/// A crisp input <name, value, reliability> (manual §10.4.1).
struct CrispDatum {
  std::string name;
  double value = 0.0;
  double reliability = 1.0;
};
using CrispDataList = std::vector<CrispDatum>;

/// A set-point produced by the Defuzzyfier.
struct Command {
  std::string name;
  double value = 0.0;
};
using CommandList = std::vector<Command>;

/// Truth value and reliability of a fuzzy datum, predicate, CANDO or WANT.
/// A missing entry reads <0, 1> (manual §10.3.6), which is the default.
struct FuzzyValue {
  double value = 0.0;
  double reliability = 1.0;
  /// Entries with value 0 and reliability 1 are not stored (§10.3.1).
  bool stored() const { return !(value == 0.0 && reliability == 1.0); }
};

/// The two semantics the engine implements (see README.md).
enum class Profile { kManual, kLegacy };

}  // namespace mrt::brian
