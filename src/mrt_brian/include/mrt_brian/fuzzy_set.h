// The seven fuzzy sets of Mr. BRIAN (manual §10.4.1, corrected by NOTES.md):
// one FuzzySet subclass per shape.
#pragma once

#include <complex>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mrt::brian {

/// A piecewise-linear outline (x, membership) of a polygon fuzzy set, used by
/// barycenter defuzzification; vertices ordered by x, first and last at 0.
using Polygon = std::vector<std::pair<double, double>>;

class FuzzySet {
 public:
  explicit FuzzySet(std::string label) : label_(std::move(label)) {}
  virtual ~FuzzySet() = default;
  const std::string& label() const { return label_; }
  /// Membership degree of x in [0, 1].
  virtual double membership(double x) const = 0;
  /// The identifier of the file grammar: TRI, TOL, TOR, DIV, TRA, REC, SNG.
  virtual const char* type() const = 0;
  /// The point a singleton defuzzyfier uses (SNG: its value; others: the
  /// middle of their core).
  virtual double singleton() const = 0;
  /// Outlines of a bounded set (empty for TOL, TOR, SNG, which have no area).
  virtual std::vector<Polygon> polygons() const { return {}; }

 private:
  std::string label_;
};

/// TRI a b c: 0 at a, 1 at b, 0 at c.
class TriangleSet : public FuzzySet {
 public:
  TriangleSet(std::string label, double a, double b, double c);
  double membership(double x) const override;
  const char* type() const override { return "TRI"; }
  double singleton() const override { return b_; }
  std::vector<Polygon> polygons() const override;
 private:
  double a_, b_, c_;
};

/// TOL a d: open left, 1 up to a, falling to 0 at d.
class OpenLeftSet : public FuzzySet {
 public:
  OpenLeftSet(std::string label, double a, double d);
  double membership(double x) const override;
  const char* type() const override { return "TOL"; }
  double singleton() const override { return a_; }
 private:
  double a_, d_;
};

/// TOR a b: open right, 0 up to a, rising to 1 at b, 1 beyond.
class OpenRightSet : public FuzzySet {
 public:
  OpenRightSet(std::string label, double a, double b);
  double membership(double x) const override;
  const char* type() const override { return "TOR"; }
  double singleton() const override { return b_; }
 private:
  double a_, b_;
};

/// DIV a b c d: the divided triangle of a circular quantity: falls from 1 at
/// a to 0 at b and rises from 0 at c to 1 at d (DIV 0 10 350 360 peaks at
/// 0/360).
class DividedSet : public FuzzySet {
 public:
  DividedSet(std::string label, double a, double b, double c, double d);
  double membership(double x) const override;
  const char* type() const override { return "DIV"; }
  double singleton() const override { return a_; }
  std::vector<Polygon> polygons() const override;
 private:
  double a_, b_, c_, d_;
};

/// TRA a b c d: trapezium, 0 at a, 1 on [b, c], 0 at d.
class TrapeziumSet : public FuzzySet {
 public:
  TrapeziumSet(std::string label, double a, double b, double c, double d);
  double membership(double x) const override;
  const char* type() const override { return "TRA"; }
  double singleton() const override { return 0.5 * (b_ + c_); }
  std::vector<Polygon> polygons() const override;
 private:
  double a_, b_, c_, d_;
};

/// REC b c: 1 on [b, c], else 0.
class RectangleSet : public FuzzySet {
 public:
  RectangleSet(std::string label, double b, double c);
  double membership(double x) const override;
  const char* type() const override { return "REC"; }
  double singleton() const override { return 0.5 * (b_ + c_); }
  std::vector<Polygon> polygons() const override;
 private:
  double b_, c_;
};

/// SNG a: 1 only at exactly a.
class SingletonSet : public FuzzySet {
 public:
  SingletonSet(std::string label, double a);
  double membership(double x) const override { return x == a_ ? 1.0 : 0.0; }
  const char* type() const override { return "SNG"; }
  double singleton() const override { return a_; }
 private:
  double a_;
};

/// Number of parameters of a set type, or -1 for an unknown identifier.
int fuzzy_set_arity(const std::string& type);

/// Builds a set from its file form; throws std::invalid_argument on an
/// unknown type or a wrong number of parameters.
std::unique_ptr<FuzzySet> make_fuzzy_set(const std::string& type, const std::string& label,
                                         const std::vector<double>& params);

/// Area and first moment (integral of x) of min(outline, height).
struct AreaMoment {
  double area = 0.0;
  double moment = 0.0;
};
AreaMoment clipped_area(const Polygon& outline, double height);

/// Circular moment of min(outline, height) on a circular range starting at
/// `lo` with `k` = 2 pi / period: the integral of mu(x) e^{i k (x - lo)} dx
/// (its argument is the circular barycenter, its modulus <= the area).
std::complex<double> clipped_circular_moment(const Polygon& outline, double height, double lo, double k);

}  // namespace mrt::brian
