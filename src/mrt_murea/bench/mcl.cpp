#include "mcl.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "mrt_common/angle.h"

namespace mrt::murea::bench {

using mrt::common::angle_diff;
using mrt::common::kPi;

namespace {

// amcl's histogram bin (kd-tree leaf): 0.5 m, 0.5 m, 10 degrees.
using Bin = std::tuple<long, long, long>;
Bin bin_of(const Pose2D& p) {
  return {static_cast<long>(std::floor(p.x / 0.5)), static_cast<long>(std::floor(p.y / 0.5)),
          static_cast<long>(std::floor(p.theta / (10.0 * kPi / 180.0)))};
}

// amcl's pf_resample_limit: the KLD bound on the sample count for k bins.
int resample_limit(const MclOptions& o, std::size_t k) {
  if (k <= 1) return o.max_particles;
  const double a = 1.0, b = 2.0 / (9.0 * (k - 1.0)), c = std::sqrt(2.0 / (9.0 * (k - 1.0))) * o.kld_z;
  const double x = a - b + c;
  const int n = static_cast<int>(std::ceil((k - 1.0) / (2.0 * o.kld_err) * x * x * x));
  return std::clamp(n, o.min_particles, o.max_particles);
}

}  // namespace

Mcl::Mcl(const FeatureMap& map, const MclOptions& o, std::uint64_t seed) : map_(map), opt_(o), rng_(seed) {}

void Mcl::global_init() {
  std::uniform_real_distribution<double> ux(map_.min_x(), map_.max_x()), uy(map_.min_y(), map_.max_y()),
      ut(-kPi, kPi);
  set_.assign(opt_.max_particles, Particle{});
  for (Particle& p : set_) p = {Pose2D(ux(rng_), uy(rng_), ut(rng_)), 1.0 / opt_.max_particles};
  pending_ = Pose2D();
  force_ = true;
  cluster();
}

void Mcl::set_pose(const Pose2D& pose) {
  std::normal_distribution<double> n01(0.0, 1.0);
  set_.assign(opt_.max_particles, Particle{});
  for (Particle& p : set_)
    p = {Pose2D(pose.x + std::sqrt(opt_.init_cov[0]) * n01(rng_), pose.y + std::sqrt(opt_.init_cov[1]) * n01(rng_),
                pose.theta + std::sqrt(opt_.init_cov[2]) * n01(rng_)),
         1.0 / opt_.max_particles};
  pending_ = Pose2D();
  force_ = true;
  cluster();
}

bool Mcl::frame(const Pose2D& delta, const std::vector<Percept>& percepts) {
  pending_ = pending_ * delta;
  const bool moved = std::abs(pending_.x) > opt_.update_min_d || std::abs(pending_.y) > opt_.update_min_d ||
                     std::abs(pending_.theta) > opt_.update_min_a;
  if (!moved && !force_) return false;
  force_ = false;
  motion(pending_);
  pending_ = Pose2D();
  sensor(percepts);
  if (++updates_ % opt_.resample_interval == 0) resample();
  cluster();
  return true;
}

// amcl's omni model (sample_motion_model_odometry, ODOM_MODEL_OMNI).
void Mcl::motion(const Pose2D& d) {
  const double trans = std::hypot(d.x, d.y), rot = d.theta;
  const double* a = opt_.alpha;
  const double s_trans = std::sqrt(a[2] * trans * trans + a[0] * rot * rot);
  const double s_rot = std::sqrt(a[3] * rot * rot + a[1] * trans * trans);
  const double s_strafe = std::sqrt(a[0] * rot * rot + a[4] * trans * trans);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double heading = std::atan2(d.y, d.x);  // direction of motion in the robot frame
  for (Particle& p : set_) {
    const double bearing = heading + p.pose.theta, cb = std::cos(bearing), sb = std::sin(bearing);
    const double t = trans + s_trans * n01(rng_), r = rot + s_rot * n01(rng_), s = s_strafe * n01(rng_);
    p.pose = Pose2D(p.pose.x + t * cb + s * sb, p.pose.y + t * sb - s * cb, p.pose.theta + r);
  }
}

// amcl's likelihood field model: p = 1 + sum over beams of pz^3.
void Mcl::sensor(const std::vector<Percept>& percepts) {
  std::vector<const Percept*> used;
  for (const Percept& p : percepts)
    if (std::isfinite(p.distance) && std::isfinite(p.bearing) && p.distance < opt_.range_max) used.push_back(&p);
  if (used.empty()) return;
  const std::size_t step = std::max<std::size_t>(1, used.size() / std::max(1, opt_.max_beams));
  std::vector<std::pair<Layer, std::array<double, 2>>> beams;
  for (std::size_t i = 0; i < used.size(); i += step)
    beams.push_back({map_.layer(used[i]->cls, used[i]->color),
                     {used[i]->distance * std::cos(used[i]->bearing), used[i]->distance * std::sin(used[i]->bearing)}});
  const double denom = 2.0 * opt_.sigma_hit * opt_.sigma_hit, rand = opt_.z_rand / opt_.range_max;
  double total = 0.0;
  for (Particle& s : set_) {
    const double c = std::cos(s.pose.theta), sn = std::sin(s.pose.theta);
    double p = 1.0;
    for (const auto& [layer, l] : beams) {
      const double z = std::min(opt_.max_dist, layer.distance(s.pose.x + c * l[0] - sn * l[1], s.pose.y + sn * l[0] + c * l[1]));
      const double pz = opt_.z_hit * std::exp(-z * z / denom) + rand;
      p += pz * pz * pz;
    }
    s.weight *= p;
    total += s.weight;
  }
  for (Particle& s : set_) s.weight = total > 0.0 ? s.weight / total : 1.0 / set_.size();
}

// amcl's pf_update_resample (w_slow = w_fast = 0: no random particles):
// draw by weight until the KLD bound for the bins occupied so far is met.
void Mcl::resample() {
  std::vector<double> cum(set_.size() + 1, 0.0);
  for (std::size_t i = 0; i < set_.size(); ++i) cum[i + 1] = cum[i] + set_[i].weight;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Particle> out;
  std::map<Bin, int> bins;
  while (static_cast<int>(out.size()) < opt_.max_particles) {
    const double r = u01(rng_) * cum.back();
    const std::size_t i = std::min<std::size_t>(
        set_.size() - 1, static_cast<std::size_t>(std::upper_bound(cum.begin(), cum.end(), r) - cum.begin()) - 1);
    out.push_back({set_[i].pose, 1.0});
    ++bins[bin_of(set_[i].pose)];
    if (static_cast<int>(out.size()) > resample_limit(opt_, bins.size())) break;
  }
  for (Particle& p : out) p.weight = 1.0 / out.size();
  set_ = std::move(out);
}

// amcl's pf_cluster_stats: bins connected through their 26 neighbours form
// clusters; the estimate is the weighted mean of the heaviest cluster.
void Mcl::cluster() {
  std::map<Bin, std::vector<std::size_t>> bins;
  for (std::size_t i = 0; i < set_.size(); ++i) bins[bin_of(set_[i].pose)].push_back(i);
  std::map<Bin, int> label;
  double best_w = -1.0;
  for (const auto& [seed, unused] : bins) {
    if (label.count(seed)) continue;
    const int id = static_cast<int>(label.size());
    std::vector<Bin> stack{seed};
    label[seed] = id;
    double w = 0, sx = 0, sy = 0, sc = 0, ss = 0;
    while (!stack.empty()) {
      const Bin b = stack.back();
      stack.pop_back();
      for (const std::size_t i : bins[b]) {
        const Particle& p = set_[i];
        w += p.weight;
        sx += p.weight * p.pose.x;
        sy += p.weight * p.pose.y;
        sc += p.weight * std::cos(p.pose.theta);
        ss += p.weight * std::sin(p.pose.theta);
      }
      for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy)
          for (long dt = -1; dt <= 1; ++dt) {
            const Bin n{std::get<0>(b) + dx, std::get<1>(b) + dy, std::get<2>(b) + dt};
            if (bins.count(n) && !label.count(n)) {
              label[n] = id;
              stack.push_back(n);
            }
          }
    }
    if (w > best_w && w > 0.0) {
      best_w = w;
      estimate_ = Pose2D(sx / w, sy / w, std::atan2(ss, sc));
    }
  }
}

}  // namespace mrt::murea::bench
