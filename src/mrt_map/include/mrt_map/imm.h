// Interacting multiple model (IMM) filter of a constant-velocity class
// (class `imm:` in the conceptual model): two constant-velocity Kalman
// filters on the same observations, "quiet" (low process noise: a rolling
// ball) and "kicked" (high: a manoeuvre), mixed at each prediction by a
// Markov chain on the two modes and weighted by their likelihoods at each
// update (Blom & Bar-Shalom). The combined (moment-matched) estimate is the
// anchor's own estimate.
#pragma once

#include "mrt_map/conceptual_model.h"
#include "mrt_map/types.h"

namespace mrt::map {

/// Both models start from `e`, the mode probabilities at the Markov chain's
/// stationary distribution (mu_quiet = p_kq / (p_qk + p_kq)).
ImmState imm_start(const Estimate& e, const ImmDef& d);

/// Mixing + model-matched prediction to time t (no-op when t <= stamp):
/// c_j = sum_i p_ij mu_i, mu_i|j = p_ij mu_i / c_j, x0_j = sum_i mu_i|j x_i,
/// P0_j = sum_i mu_i|j (P_i + (x_i - x0_j)(x_i - x0_j)'); each model then
/// predicted with its process noise; mu <- c (the predicted probabilities).
void imm_predict(ImmState& s, const ClassDef& c, double t);

/// Kalman update of each model with a position z (covariance R); mu_j is
/// proportional to N(y_j; 0, S_j) mu_j (in the log domain: no underflow
/// when an observation is far from both).
void imm_update(ImmState& s, const Vec2& z, const Mat2& R);

/// The moment-matched combination: x = sum mu_j x_j,
/// P = sum mu_j (P_j + (x_j - x)(x_j - x)').
Estimate imm_combine(const ImmState& s);

}  // namespace mrt::map
