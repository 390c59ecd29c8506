#include "mrt_map/classifier.h"

#include <cmath>

namespace mrt::map {

const char* to_string(Rejection r) {
  switch (r) {
    case Rejection::kNone: return "none";
    case Rejection::kUnknownClass: return "unknown class";
    case Rejection::kNonFinite: return "non-finite value";
    case Rejection::kNoPosition: return "no position";
    case Rejection::kUnmatched: return "below matching threshold";
  }
  return "?";
}

const char* to_string(AnchorStatus s) {
  switch (s) {
    case AnchorStatus::kTentative: return "tentative";
    case AnchorStatus::kConfirmed: return "confirmed";
    case AnchorStatus::kCoasting: return "coasting";
    case AnchorStatus::kDropped: return "dropped";
  }
  return "?";
}

std::optional<double> Classifier::degree(const PerceptObject& object, int c, int from, bool require_all) const {
  double d = 1.0;
  for (int k = c; k >= 0 && k != from; k = model_.at(k).parent) {
    for (const AttributeMatcher& m : model_.at(k).matchers) {
      const PerceptAttribute* a = object.find(m.attribute);
      if (!a) {
        if (require_all) return std::nullopt;
        continue;
      }
      if (m.set && !a->symbol.empty()) return std::nullopt;  // wrong kind
      d = std::min(d, m.match(a->value, a->symbol));
    }
  }
  return d;
}

std::optional<Classification> Classifier::classify(const PerceptObject& object, Rejection* why) const {
  Rejection r = Rejection::kNone;
  std::optional<Classification> out;
  const int declared = model_.find(object.membership_class);
  if (declared < 0) {
    r = Rejection::kUnknownClass;
  } else {
    const double thr = model_.classifier().threshold;
    Classification c{declared, degree(object, declared, -1, false).value_or(0.0)};
    if (c.degree < thr) {
      r = Rejection::kUnmatched;
    } else {
      for (;;) {
        int best = -1;
        double d1 = -1.0, d2 = -1.0;
        for (int ch : model_.at(c.class_index).children) {
          if (model_.at(ch).matchers.empty()) continue;  // nothing tells it apart
          const auto d = degree(object, ch, c.class_index, true);
          if (!d || *d < thr) continue;
          const double v = std::min(*d, c.degree);
          if (v > d1) {
            d2 = d1;
            d1 = v;
            best = ch;
          } else if (v > d2) {
            d2 = v;
          }
        }
        if (best < 0 || (d2 >= 0.0 && d1 - d2 < model_.classifier().ambiguity_margin)) break;
        c = {best, d1};
      }
      out = c;
    }
  }
  if (why) *why = r;
  return out;
}

namespace {
bool finite(const PerceptObject& o) {
  for (const PerceptAttribute& a : o.attributes)
    if (!std::isfinite(a.value) || !std::isfinite(a.variability) || !std::isfinite(a.reliability)) return false;
  return true;
}
}  // namespace

std::optional<Observation> Classifier::observe(const PerceptObject& object, const RobotPose& pose, double stamp,
                                               const std::string& robot, const std::string& sensor,
                                               Rejection* why) const {
  Rejection r = Rejection::kNone;
  if (!finite(object)) r = Rejection::kNonFinite;
  const PerceptAttribute *ad = object.find("distance"), *ab = object.find("bearing");
  const PerceptAttribute *ax = object.find("x"), *ay = object.find("y");
  const bool polar = ad && ab;
  const bool cart = ax && ay;
  if (r == Rejection::kNone && !polar && !cart) r = Rejection::kNoPosition;
  std::optional<Classification> c;
  if (r == Rejection::kNone) c = classify(object, &r);
  if (!c) {
    if (why) *why = r;
    return std::nullopt;
  }
  const double def = model_.at(c->class_index).default_sigma;
  auto sigma = [def](const PerceptAttribute& p, double scale) { return p.variability > 0 ? p.variability * scale : def; };
  Vec2 rel;
  Mat2 cov_rel;
  if (polar) {
    // Polar to Cartesian: J = [cos b, -d sin b; sin b, d cos b].
    const double d = ad->value, b = ab->value;
    const double sd = sigma(*ad, 1.0);
    const double sb = ab->variability > 0 ? ab->variability : def / std::max(d, 1e-3);
    rel << d * std::cos(b), d * std::sin(b);
    Mat2 J;
    J << std::cos(b), -d * std::sin(b), std::sin(b), d * std::cos(b);
    cov_rel = J * Eigen::Vector2d(sd * sd, sb * sb).asDiagonal() * J.transpose();
  } else {
    rel << ax->value, ay->value;
    const double sx = sigma(*ax, 1.0), sy = sigma(*ay, 1.0);
    cov_rel = Eigen::Vector2d(sx * sx, sy * sy).asDiagonal();
  }
  Mat2 Rot;
  Rot << std::cos(pose.theta), -std::sin(pose.theta), std::sin(pose.theta), std::cos(pose.theta);
  Observation o;
  o.class_index = c->class_index;
  o.degree = c->degree;
  o.z = Vec2(pose.x, pose.y) + Rot * rel;
  // Heading uncertainty moves the point perpendicular to its world offset.
  const Vec2 perp(-(o.z.y() - pose.y), o.z.x() - pose.x);
  o.R = Rot * cov_rel * Rot.transpose() + pose.cov + pose.theta_sigma * pose.theta_sigma * perp * perp.transpose();
  o.stamp = stamp;
  o.robot = robot;
  o.sensors.insert(robot + "/" + sensor);
  if (why) *why = Rejection::kNone;
  return o;
}

}  // namespace mrt::map
