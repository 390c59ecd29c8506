// Global nearest neighbour data association: the minimum-cost assignment
// of rows (measurements) to columns (anchors) on gated costs, each row or
// column free to stay unassigned at the cost `miss` (Hungarian method on the
// augmented (R+C)x(R+C) matrix, solved per connected component of the
// gating graph so that well-separated objects stay cheap).
#pragma once

#include <limits>
#include <vector>

namespace mrt::map {

constexpr double kInfeasible = std::numeric_limits<double>::infinity();

/// cost[r][c] (kInfeasible when gated out); returns for each row its column
/// or -1. Pairs with cost > miss are never chosen.
std::vector<int> assign(const std::vector<std::vector<double>>& cost, double miss);

/// Minimum-cost perfect assignment of a square matrix of finite costs:
/// result[r] = column (Hungarian method with potentials, O(n^3)).
std::vector<int> hungarian(const std::vector<std::vector<double>>& cost);

}  // namespace mrt::map
