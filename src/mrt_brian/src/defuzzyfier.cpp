#include "mrt_brian/defuzzyfier.h"

#include <cmath>
#include <complex>
#include <stdexcept>

#include "mrt_common/angle.h"
#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::kPi;
using mrt::common::ParseError;

Defuzzyfier::Defuzzyfier(const std::vector<ShapeDef>& shapes, const std::vector<AssociationDef>& assocs,
                         DefuzzMethod method, Profile profile, const std::string& shapes_file,
                         const std::string& assoc_file)
    : method_(method), profile_(profile) {
  SymbolTable shape_ids;
  shapes_ = build_shapes(shapes, shapes_file, shape_ids, [&](const ShapeDef& def) {
    if (method != DefuzzMethod::kBarycenter) return;
    for (const auto& set : def.sets)
      if (set.type == "SNG" || set.type == "TOL" || set.type == "TOR")
        throw ParseError(def.file.empty() ? shapes_file : def.file, set.line, set.column,
                         "barycenter defuzzification needs sets with an area (TRI DIV TRA REC), got " + set.type);
  });
  for (const Shape& sh : shapes_) {
    polygons_.emplace_back();
    for (int l = 0; l < sh.size(); ++l) polygons_.back().push_back(sh.set(l).polygons());
  }
  for (const auto& a : assocs) {
    const int shape = shape_ids.find(a.shape);
    if (shape < 0)
      throw ParseError(a.file.empty() ? assoc_file : a.file, a.line, a.column, "unknown shape '" + a.shape + "' for action '" + a.name + "'");
    const int id = actions_.intern(a.name);
    if (id < static_cast<int>(shape_of_.size())) {
      shape_of_[static_cast<std::size_t>(id)] = shape;
    } else {
      shape_of_.push_back(shape);
      wrap_.push_back(Wrap::kLinear);
    }
    const Shape& sh = shapes_[static_cast<std::size_t>(shape)];
    Wrap& w = wrap_[static_cast<std::size_t>(id)];
    if (profile == Profile::kLegacy && a.name.find("Angle") != std::string::npos) w = Wrap::kLegacyAngle;
    else w = sh.circular() ? Wrap::kCircular : Wrap::kLinear;
  }
  for (int a = 0; a < action_count(); ++a) {
    point_first_.push_back(static_cast<int>(points_.size()));
    for (int l = 0; l < label_count(a); ++l) points_.push_back(singleton_point(a, l));
  }
}

std::vector<int> Defuzzyfier::labels_per_action() const {
  std::vector<int> out;
  for (int a = 0; a < action_count(); ++a) out.push_back(label_count(a));
  return out;
}

double Defuzzyfier::singleton_point(int action, int label) const { return shape(action).set(label).singleton(); }

bool Defuzzyfier::from_circle(int a, double c, double s, double w, double* out) const {
  if (!(w > 0.0) || std::hypot(s, c) <= 1e-12 * w) return false;
  double phi = std::atan2(s, c);  // (-pi, pi]
  if (phi < 0.0) phi += 2.0 * kPi;
  const double p = period(a);
  double x = range_lo(a) + phi * p / (2.0 * kPi);
  if (x >= range_lo(a) + p) x -= p;
  *out = x;
  return true;
}

bool Defuzzyfier::barycenter(int a, const ComposedActions& in, double* out) const {
  const bool circular = wrap(a) != Wrap::kLinear;
  const double k = circular ? 2.0 * kPi / period(a) : 0.0;
  const auto& outlines = polygons_[static_cast<std::size_t>(shape_of_[static_cast<std::size_t>(a)])];
  double num = 0.0, den = 0.0;
  std::complex<double> moment(0.0, 0.0);
  for (int l = 0; l < label_count(a); ++l) {
    if (!in.present(a, l)) continue;
    const double mu = in.get(a, l);
    for (const Polygon& poly : outlines[static_cast<std::size_t>(l)]) {
      const AreaMoment am = clipped_area(poly, mu);
      den += am.area;
      if (circular) moment += clipped_circular_moment(poly, mu, range_lo(a), k);
      else num += am.moment;
    }
  }
  if (circular) return from_circle(a, moment.real(), moment.imag(), den, out);
  if (!(den > 0.0)) return false;
  *out = num / den;
  return true;
}

bool Defuzzyfier::singleton_linear(int a, const ComposedActions& in, double* out) const {
  const int labels = label_count(a);
  const std::size_t slot = static_cast<std::size_t>(in.first[static_cast<std::size_t>(a)]);
  const double* point = points_.data() + point_first_[static_cast<std::size_t>(a)];
  double num = 0.0, den = 0.0;
  for (int l = 0; l < labels; ++l) {
    if (in.count[slot + static_cast<std::size_t>(l)] <= 0) continue;
    const double mu = in.value[slot + static_cast<std::size_t>(l)];
    num += mu * point[l];
    den += mu;
  }
  if (den == 0.0) return false;
  *out = num / den;
  return true;
}

// Weighted circular mean over the declared range, computed here so that the
// cycle neither allocates nor throws.
bool Defuzzyfier::singleton_circular(int a, const ComposedActions& in, double* out) const {
  const double k = 2.0 * kPi / period(a);
  double s = 0.0, c = 0.0, w = 0.0;
  for (int l = 0; l < label_count(a); ++l) {
    if (!in.present(a, l)) continue;
    const double mu = in.get(a, l);
    if (!(mu > 0.0)) continue;
    const double theta = k * (singleton_point(a, l) - range_lo(a));
    s += mu * std::sin(theta);
    c += mu * std::cos(theta);
    w += mu;
  }
  return from_circle(a, c, s, w, out);
}

// The 2009 engine: weighted sum of unit vectors with 0.01745 rad/deg.
bool Defuzzyfier::singleton_legacy_angle(int a, const ComposedActions& in, double* out) const {
  constexpr double k = 0.01745;
  double sx = 0.0, sy = 0.0, w = 0.0;
  for (int l = 0; l < label_count(a); ++l) {
    if (!in.present(a, l)) continue;
    const double mu = in.get(a, l);
    sx += mu * std::cos(singleton_point(a, l) * k);
    sy += mu * std::sin(singleton_point(a, l) * k);
    w += mu;
  }
  if (w == 0.0) return false;
  double deg = std::atan2(sy, sx) / k;
  if (deg < 0.0) deg += 360.0;
  *out = deg;
  return true;
}

void Defuzzyfier::defuzzify(const ComposedActions& in, std::vector<double>& value,
                            std::vector<std::uint8_t>& has) const {
  const std::size_t n = static_cast<std::size_t>(action_count());
  value.assign(n, 0.0);
  has.assign(n, 0);
  const bool barycenter_method = method_ == DefuzzMethod::kBarycenter;
  for (int a = 0; a < action_count(); ++a) {
    double v = 0.0;
    bool ok;
    const Wrap w = wrap_[static_cast<std::size_t>(a)];
    if (barycenter_method) ok = barycenter(a, in, &v);
    else if (w == Wrap::kLinear) ok = singleton_linear(a, in, &v);
    else if (w == Wrap::kCircular) ok = singleton_circular(a, in, &v);
    else ok = singleton_legacy_angle(a, in, &v);
    if (ok) {
      value[static_cast<std::size_t>(a)] = v;
      has[static_cast<std::size_t>(a)] = 1;
    }
  }
}

CommandList Defuzzyfier::defuzzify(const std::vector<Action>& actions) const {
  Composer composer(WeightComposerKind::kMult, FloatComposerKind::kMax, labels_per_action());
  ComposedActions in = composer.make_output();
  for (const auto& act : actions) {
    const int a = action_id(act.name);
    if (a < 0) throw std::invalid_argument("unknown action '" + act.name + "'");
    const int l = label_id(a, act.label);
    if (l < 0) throw std::invalid_argument("unknown label '" + act.label + "' of action '" + act.name + "'");
    const std::size_t s = static_cast<std::size_t>(in.first[static_cast<std::size_t>(a)] + l);
    in.value[s] = in.count[s] ? in.value[s] + act.value : act.value;
    ++in.count[s];
  }
  std::vector<double> value;
  std::vector<std::uint8_t> has;
  defuzzify(in, value, has);
  CommandList out;
  for (int a = 0; a < action_count(); ++a)
    if (has[static_cast<std::size_t>(a)]) out.push_back({action_name(a), value[static_cast<std::size_t>(a)]});
  return out;
}

}  // namespace mrt::brian
