#include "mrt_murea/refine.h"

#include <Eigen/Dense>
#include <cmath>

#include "mrt_common/angle.h"

namespace mrt::murea {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// The normal equations: sum of w J^T J and of w J^T e over the residuals.
struct Normal {
  Matrix3d h = Matrix3d::Zero();
  Vector3d g = Vector3d::Zero();
};

}  // namespace

Refined refine(const Localizer& loc, const std::vector<Percept>& percepts, const Pose2D& start,
               const Pose2D* prior, const Covariance3* prior_cov, const RefineOptions& o) {
  Refined out;
  out.pose = start;
  const std::vector<Localizer::Prepared> ps = loc.prepare(percepts);
  Matrix3d prior_info = Matrix3d::Zero();
  if (prior && prior_cov) {
    const Matrix3d p = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(prior_cov->data());
    Eigen::FullPivLU<Matrix3d> lu(p);
    if (lu.isInvertible()) prior_info = lu.inverse();
  }
  Vector3d q(start.x, start.y, start.theta);
  Matrix3d h;
  for (int it = 0; it < o.iterations; ++it) {
    Normal ne;
    const double cs = std::cos(q[2]), sn = std::sin(q[2]);
    std::size_t used = 0;
    for (const Localizer::Prepared& p : ps) {
      if (p.layer.empty()) continue;
      const double ox = cs * p.lx - sn * p.ly, oy = sn * p.lx + cs * p.ly;
      const double px = q[0] + ox, py = q[1] + oy;
      bool line = false;
      double nx, ny;
      const Point2D c = p.layer.nearest(px, py, &line, &nx, &ny);
      if (std::hypot(px - c.x, py - c.y) > p.tol) continue;  // not matched (outlier)
      ++used;
      // Percept position noise in the world: along (u) and across (v) the ray.
      const double phi = std::atan2(oy, ox), ux = std::cos(phi), uy = std::sin(phi);
      const double sr = o.sigma_range_base + o.sigma_range_per_metre * p.r, sb = p.r * o.sigma_bearing;
      const double dirs[2][2] = {{nx, ny}, {-ny, nx}};
      for (int k = 0; k < (line ? 1 : 2); ++k) {
        const double ax = dirs[k][0], ay = dirs[k][1];
        const double along = ax * ux + ay * uy, across = -ax * uy + ay * ux;
        const double var = sr * sr * along * along + sb * sb * across * across + o.sigma_map * o.sigma_map;
        const double e = ax * (px - c.x) + ay * (py - c.y);
        const Vector3d j(ax, ay, ax * -oy + ay * ox);
        const double z = std::abs(e) / std::sqrt(var);
        const double w = p.w / var * (z > o.huber ? o.huber / z : 1.0);
        ne.h += w * j * j.transpose();
        ne.g += w * j * e;
      }
    }
    out.inliers = used;
    Vector3d dq(q[0] - (prior ? prior->x : 0.0), q[1] - (prior ? prior->y : 0.0),
                prior ? mrt::common::angle_diff(q[2], prior->theta) : 0.0);
    h = ne.h + prior_info;
    const Vector3d g = ne.g + prior_info * dq;
    Eigen::FullPivLU<Matrix3d> lu(h);
    if (used < 3 || !lu.isInvertible() || lu.rcond() < 1e-12) return out;
    const Vector3d step = -lu.solve(g);
    q += step;
    if (step.head<2>().norm() < 1e-5 && std::abs(step[2]) < 1e-6) break;
  }
  out.pose = Pose2D(q[0], q[1], q[2]);
  if (std::hypot(q[0] - start.x, q[1] - start.y) > o.max_shift_xy ||
      std::abs(mrt::common::angle_diff(q[2], start.theta)) > o.max_shift_theta || !q.allFinite())
    return out;
  const Matrix3d cov = h.inverse();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out.covariance[3 * a + b] = cov(a, b);
  out.ok = true;
  return out;
}

}  // namespace mrt::murea
