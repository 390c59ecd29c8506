#include "mrt_airboard/odometry.h"

#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::airboard {

EncoderOdometry::EncoderOdometry(const BaseParams& p, double twist_window)
    : kin_(make_kinematics(p)),
      rad_per_count_(2.0 * mrt::common::kPi / p.counts_per_rev),
      twist_window_(twist_window) {}

void EncoderOdometry::reset() {
  have_ref_ = false;
  twist_ = Twist2D{};
}

void EncoderOdometry::update(const std::vector<int64_t>& counts, double time) {
  if (counts.size() != kin_->wheel_count())
    throw std::invalid_argument("EncoderOdometry::update: wrong number of wheels");
  if (!have_ref_) {
    ref_ = twist_ref_ = counts;
    ref_time_ = twist_ref_time_ = time;
    have_ref_ = true;
    twist_ = Twist2D{};
    return;
  }
  std::vector<double> dphi(counts.size());
  bool moved = false;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    dphi[i] = static_cast<double>(counts[i] - ref_[i]) * rad_per_count_;
    moved = moved || counts[i] != ref_[i];
  }
  const double dt = time - ref_time_;
  if (!moved && dt <= 0.0) return;
  // Wheel angle increments through the forward kinematics give the body
  // displacement as a twist applied for unit time.
  const Twist2D d = kin_->forward(dphi);
  pose_ = pose_ * mrt::common::exp_twist(d.vx, d.vy, d.omega, 1.0);
  const double tw = time - twist_ref_time_;
  if (tw >= twist_window_ * (1.0 - 1e-9) && tw > 0.0) {
    std::vector<double> dw(counts.size());
    for (std::size_t i = 0; i < counts.size(); ++i)
      dw[i] = static_cast<double>(counts[i] - twist_ref_[i]) * rad_per_count_ / tw;
    twist_ = kin_->forward(dw);
    twist_ref_ = counts;
    twist_ref_time_ = time;
  }
  ref_ = counts;
  ref_time_ = time;
}

}  // namespace mrt::airboard
