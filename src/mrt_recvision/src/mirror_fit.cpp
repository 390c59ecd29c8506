#include "mrt_recvision/mirror_fit.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrt::recvision {

MirrorFit fit_mirror(const std::vector<MirrorMark>& marks, double height, double theta_max, int degree) {
  if (degree < 1 || degree > 6) throw std::invalid_argument("mirror fit: degree must be in [1, 6]");
  if (static_cast<int>(marks.size()) < degree)
    throw std::invalid_argument("mirror fit: need at least " + std::to_string(degree) + " marks, got " +
                                std::to_string(marks.size()));
  Eigen::MatrixXd a(marks.size(), degree);
  Eigen::VectorXd b(marks.size());
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const double th = std::atan2(marks[i].distance, height);
    for (int k = 0; k < degree; ++k) a(i, k) = std::pow(th, k + 1);
    b(i) = marks[i].radius;
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
  MirrorFit fit;
  fit.coefficients.assign(c.data(), c.data() + c.size());
  auto r_of = [&](double th) {
    double r = 0;
    for (int k = 0; k < degree; ++k) r += c(k) * std::pow(th, k + 1);
    return r;
  };
  std::vector<std::pair<double, double>> table;
  const int n = 256;
  for (int i = 0; i < n; ++i) {
    const double th = theta_max * i / (n - 1);
    table.emplace_back(th, r_of(th));
  }
  table[0].second = 0.0;
  for (std::size_t i = 1; i < table.size(); ++i)
    if (!(table[i].second > table[i - 1].second))
      throw std::invalid_argument("mirror fit: the fitted profile does not increase up to theta " +
                                  std::to_string(table[i].first) + " rad (too few or inconsistent marks)");
  fit.profile = mrt::common::MirrorProfile(std::move(table));
  double s_px = 0, s_m = 0;
  for (const MirrorMark& m : marks) {
    const double th = std::atan2(m.distance, height);
    fit.residual_px.push_back(m.radius - r_of(th));
    const double th_meas = fit.profile.theta(m.radius);
    const double d_meas = std::isfinite(th_meas) && th_meas < M_PI / 2 ? height * std::tan(th_meas) : NAN;
    fit.residual_m.push_back(m.distance - d_meas);
    s_px += fit.residual_px.back() * fit.residual_px.back();
    s_m += fit.residual_m.back() * fit.residual_m.back();
  }
  fit.rms_px = std::sqrt(s_px / marks.size());
  fit.rms_m = std::sqrt(s_m / marks.size());
  return fit;
}

std::vector<double> white_runs_along_ray(const Frame& f, const ColorTable& t, double cx, double cy, double bearing,
                                         double r_min, double r_max) {
  constexpr auto kGreen = static_cast<std::uint8_t>(ColorClass::kGreen);
  constexpr auto kWhite = static_cast<std::uint8_t>(ColorClass::kWhite);
  const double s = std::sin(bearing), c = std::cos(bearing);
  std::vector<std::uint8_t> cls;
  std::vector<double> radius;
  // Sample every half pixel (nearest pixel), so thin lines are not skipped.
  for (double r = std::max(0.0, r_min); r <= r_max; r += 0.5) {
    const int u = static_cast<int>(std::lround(cx - r * s)), v = static_cast<int>(std::lround(cy - r * c));
    if (u < 0 || v < 0 || u >= f.rgb.cols || v >= f.rgb.rows) break;
    cls.push_back(t.lookup(f.rgb.ptr<std::uint8_t>(v) + 3 * u));
    radius.push_back(r);
  }
  std::vector<double> out;
  const int n = static_cast<int>(cls.size());
  for (int k = 0; k < n;) {
    if (cls[k] != kWhite) {
      ++k;
      continue;
    }
    const int a = k;
    while (k < n && cls[k] == kWhite) ++k;
    // Green (possibly after 2 unclassified samples) on both sides.
    auto green = [&](int j, int step) {
      for (int g = 0; g < 5 && j >= 0 && j < n; ++g, j += step) {
        if (cls[j] == kGreen) return true;
        if (cls[j] != 0) return false;
      }
      return false;
    };
    if (green(a - 1, -1) && green(k, 1)) out.push_back(0.5 * (radius[a] + radius[k - 1]));
  }
  return out;
}

}  // namespace mrt::recvision
