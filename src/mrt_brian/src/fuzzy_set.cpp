#include "mrt_brian/fuzzy_set.h"

#include <stdexcept>

namespace mrt::brian {

TriangleSet::TriangleSet(std::string label, double a, double b, double c)
    : FuzzySet(std::move(label)), a_(a), b_(b), c_(c) {}

double TriangleSet::membership(double x) const {
  if (x == b_) return 1.0;
  if (x <= a_ || x >= c_) return 0.0;
  if (x < b_) return (x - a_) / (b_ - a_);
  return (c_ - x) / (c_ - b_);
}

std::vector<Polygon> TriangleSet::polygons() const { return {{{a_, 0.0}, {b_, 1.0}, {c_, 0.0}}}; }

OpenLeftSet::OpenLeftSet(std::string label, double a, double d)
    : FuzzySet(std::move(label)), a_(a), d_(d) {}

double OpenLeftSet::membership(double x) const {
  if (x <= a_) return 1.0;
  if (x >= d_) return 0.0;
  return (d_ - x) / (d_ - a_);
}

OpenRightSet::OpenRightSet(std::string label, double a, double b)
    : FuzzySet(std::move(label)), a_(a), b_(b) {}

double OpenRightSet::membership(double x) const {
  // b is tested first: the 2009 engine gives 1 beyond b even when a > b
  // (IsAac's `(TOR (RIGHT 15 5))`).
  if (x >= b_) return 1.0;
  if (x <= a_) return 0.0;
  return (x - a_) / (b_ - a_);
}

DividedSet::DividedSet(std::string label, double a, double b, double c, double d)
    : FuzzySet(std::move(label)), a_(a), b_(b), c_(c), d_(d) {}

double DividedSet::membership(double x) const {
  if (x == a_ || x == d_) return 1.0;
  if (x > a_ && x < b_) return (b_ - x) / (b_ - a_);
  if (x > c_ && x < d_) return (x - c_) / (d_ - c_);
  return 0.0;
}

std::vector<Polygon> DividedSet::polygons() const {
  return {{{a_, 0.0}, {a_, 1.0}, {b_, 0.0}}, {{c_, 0.0}, {d_, 1.0}, {d_, 0.0}}};
}

TrapeziumSet::TrapeziumSet(std::string label, double a, double b, double c, double d)
    : FuzzySet(std::move(label)), a_(a), b_(b), c_(c), d_(d) {}

double TrapeziumSet::membership(double x) const {
  if (x >= b_ && x <= c_) return 1.0;
  if (x <= a_ || x >= d_) return 0.0;
  if (x < b_) return (x - a_) / (b_ - a_);
  return (d_ - x) / (d_ - c_);
}

std::vector<Polygon> TrapeziumSet::polygons() const {
  return {{{a_, 0.0}, {b_, 1.0}, {c_, 1.0}, {d_, 0.0}}};
}

RectangleSet::RectangleSet(std::string label, double b, double c)
    : FuzzySet(std::move(label)), b_(b), c_(c) {}

double RectangleSet::membership(double x) const { return (x >= b_ && x <= c_) ? 1.0 : 0.0; }

std::vector<Polygon> RectangleSet::polygons() const {
  return {{{b_, 0.0}, {b_, 1.0}, {c_, 1.0}, {c_, 0.0}}};
}

SingletonSet::SingletonSet(std::string label, double a) : FuzzySet(std::move(label)), a_(a) {}

int fuzzy_set_arity(const std::string& t) {
  if (t == "TRI") return 3;
  if (t == "TOL" || t == "TOR" || t == "REC") return 2;
  if (t == "DIV" || t == "TRA") return 4;
  if (t == "SNG") return 1;
  return -1;
}

std::unique_ptr<FuzzySet> make_fuzzy_set(const std::string& t, const std::string& label,
                                         const std::vector<double>& p) {
  const int n = fuzzy_set_arity(t);
  if (n < 0) throw std::invalid_argument("unknown fuzzy set type '" + t + "'");
  if (static_cast<int>(p.size()) != n)
    throw std::invalid_argument(t + " takes " + std::to_string(n) + " values, got " +
                                std::to_string(p.size()));
  if (t == "TRI") return std::make_unique<TriangleSet>(label, p[0], p[1], p[2]);
  if (t == "TOL") return std::make_unique<OpenLeftSet>(label, p[0], p[1]);
  if (t == "TOR") return std::make_unique<OpenRightSet>(label, p[0], p[1]);
  if (t == "DIV") return std::make_unique<DividedSet>(label, p[0], p[1], p[2], p[3]);
  if (t == "TRA") return std::make_unique<TrapeziumSet>(label, p[0], p[1], p[2], p[3]);
  if (t == "REC") return std::make_unique<RectangleSet>(label, p[0], p[1]);
  return std::make_unique<SingletonSet>(label, p[0]);
}

namespace {
// Area and moment under the segment (x0,y0)-(x1,y1) with y linear.
AreaMoment linear_piece(double x0, double y0, double x1, double y1) {
  const double w = x1 - x0;
  return {0.5 * (y0 + y1) * w, w * (x0 * (2 * y0 + y1) + x1 * (y0 + 2 * y1)) / 6.0};
}

// Calls piece(x0, y0, x1, y1) for each linear piece of min(outline, h) with
// a positive width.
template <typename F>
void for_each_clipped_piece(const Polygon& outline, double h, F piece) {
  if (!(h > 0.0)) return;
  for (std::size_t i = 0; i + 1 < outline.size(); ++i) {
    const double x0 = outline[i].first, y0 = outline[i].second;
    const double x1 = outline[i + 1].first, y1 = outline[i + 1].second;
    if (x1 <= x0) continue;  // vertical edge: no area
    const bool lo0 = y0 <= h, lo1 = y1 <= h;
    if (lo0 && lo1) {
      piece(x0, y0, x1, y1);
    } else if (!lo0 && !lo1) {
      piece(x0, h, x1, h);
    } else {
      const double xc = x0 + (h - y0) * (x1 - x0) / (y1 - y0);
      if (lo0) {
        piece(x0, y0, xc, h);
        piece(xc, h, x1, h);
      } else {
        piece(x0, h, xc, h);
        piece(xc, h, x1, y1);
      }
    }
  }
}
}  // namespace

AreaMoment clipped_area(const Polygon& outline, double h) {
  AreaMoment out;
  for_each_clipped_piece(outline, h, [&out](double x0, double y0, double x1, double y1) {
    const AreaMoment p = linear_piece(x0, y0, x1, y1);
    out.area += p.area;
    out.moment += p.moment;
  });
  return out;
}

std::complex<double> clipped_circular_moment(const Polygon& outline, double h, double lo, double k) {
  // With y(x) = y0 + m (x - x0), an antiderivative of y e^{i k (x - lo)} is
  // e^{i k (x - lo)} (y(x) / (i k) + m / k^2).
  using C = std::complex<double>;
  C out(0.0, 0.0);
  const C ik(0.0, k);
  for_each_clipped_piece(outline, h, [&](double x0, double y0, double x1, double y1) {
    const double m = (y1 - y0) / (x1 - x0);
    auto f = [&](double x, double y) { return std::polar(1.0, k * (x - lo)) * (y / ik + m / (k * k)); };
    out += f(x1, y1) - f(x0, y0);
  });
  return out;
}

}  // namespace mrt::brian
