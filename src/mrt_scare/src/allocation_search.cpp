// The allocation searches: exact dynamic programming over robot subsets,
// greedy in agenda order, and bounded local improvement.
#include <algorithm>
#include <vector>

#include "allocator_tables.h"

namespace mrt::scare {

namespace {

/// The best way to give exactly the robots of each subset to one activity:
/// value and role digits (base roles+1, 0 = not in it) per subset mask.
struct ActivityTable {
  std::vector<double> best;
  std::vector<int> code;
};

ActivityTable activity_table(const std::vector<std::vector<double>>& u, int n, int first,
                             const std::vector<RoleSpec>& roles) {
  const int base = static_cast<int>(roles.size()) + 1;
  int total = 1;
  for (int i = 0; i < n; ++i) total *= base;
  ActivityTable t{std::vector<double>(std::size_t{1} << n, kNone), std::vector<int>(std::size_t{1} << n, -1)};
  std::vector<int> count(roles.size());
  for (int code = 1; code < total; ++code) {
    std::fill(count.begin(), count.end(), 0);
    int mask = 0;
    double sum = 0.0;
    bool ok = true;
    for (int i = 0, c = code; i < n && ok; ++i, c /= base) {
      const int d = c % base;
      if (d == 0) continue;
      const double v = u[static_cast<std::size_t>(i)][static_cast<std::size_t>(first + d - 1)];
      ok = v > kNone && ++count[static_cast<std::size_t>(d - 1)] <= roles[static_cast<std::size_t>(d - 1)].max;
      mask |= 1 << i;
      sum += v;
    }
    for (std::size_t k = 0; k < roles.size() && ok; ++k) ok = count[k] >= roles[k].min;
    if (ok && sum > t.best[static_cast<std::size_t>(mask)]) {
      t.best[static_cast<std::size_t>(mask)] = sum;
      t.code[static_cast<std::size_t>(mask)] = code;
    }
  }
  return t;
}

}  // namespace

std::vector<int> Allocator::exact(const Tables& t, const std::vector<AgendaEntry>& agenda) const {
  const std::size_t full = std::size_t{1} << t.n;
  std::vector<double> f(full, kNone);
  f[0] = 0.0;
  std::vector<ActivityTable> tabs;
  std::vector<std::vector<int>> pick;  // [agenda entry][robots used so far]: robots given to the entry
  for (const AgendaEntry& e : agenda) {
    const auto a = static_cast<std::size_t>(e.activity);
    tabs.push_back(activity_table(t.u, t.n, first_slot_[a], set_.activities[a].roles));
    const ActivityTable& at = tabs.back();
    std::vector<double> g = f;
    std::vector<int> p(full, 0);
    for (std::size_t s = 1; s < full; ++s)
      for (std::size_t sub = s; sub > 0; sub = (sub - 1) & s) {
        if (at.best[sub] == kNone || f[s ^ sub] == kNone) continue;
        const double c = f[s ^ sub] + at.best[sub];
        if (c > g[s]) {
          g[s] = c;
          p[s] = static_cast<int>(sub);
        }
      }
    f.swap(g);
    pick.push_back(std::move(p));
  }
  std::size_t s = 0;
  for (std::size_t m = 1; m < full; ++m)
    if (f[m] > f[s]) s = m;
  std::vector<int> slot(static_cast<std::size_t>(t.n), -1);
  for (std::size_t k = agenda.size(); k-- > 0;) {
    const auto sub = static_cast<std::size_t>(pick[k][s]);
    if (sub == 0) continue;
    const auto a = static_cast<std::size_t>(agenda[k].activity);
    const int base = static_cast<int>(set_.activities[a].roles.size()) + 1;
    for (int i = 0, c = tabs[k].code[sub]; i < t.n; ++i, c /= base)
      if (c % base != 0) slot[static_cast<std::size_t>(i)] = first_slot_[a] + c % base - 1;
    s ^= sub;
  }
  return slot;
}

std::vector<int> Allocator::greedy(const Tables& t, const std::vector<AgendaEntry>& agenda) const {
  std::vector<int> slot(static_cast<std::size_t>(t.n), -1);
  std::vector<char> taken(set_.activities.size(), 0);
  // 1. In agenda order, each activity gets the best free robots for the
  //    minimum of every role; an activity that cannot be covered is skipped.
  for (const AgendaEntry& e : agenda) {
    const auto a = static_cast<std::size_t>(e.activity);
    std::vector<int> trial = slot;
    bool covered = true;
    for (std::size_t k = 0; k < set_.activities[a].roles.size() && covered; ++k) {
      const auto s = static_cast<std::size_t>(first_slot_[a]) + k;
      for (int need = set_.activities[a].roles[k].min; need > 0 && covered; --need) {
        int best = -1;
        for (int i = 0; i < t.n; ++i)
          if (trial[static_cast<std::size_t>(i)] < 0 && t.u[static_cast<std::size_t>(i)][s] > kNone &&
              (best < 0 || t.u[static_cast<std::size_t>(i)][s] > t.u[static_cast<std::size_t>(best)][s]))
            best = i;
        covered = best >= 0;
        if (covered) trial[static_cast<std::size_t>(best)] = static_cast<int>(s);
      }
    }
    if (covered) {
      slot = trial;
      taken[a] = 1;
    }
  }
  // 2. Free robots join taken activities up to their maxima, best pair first.
  std::vector<int> count(slots_.size(), 0);
  for (int s : slot)
    if (s >= 0) ++count[static_cast<std::size_t>(s)];
  for (;;) {
    int bi = -1, bs = -1;
    for (int i = 0; i < t.n; ++i) {
      if (slot[static_cast<std::size_t>(i)] >= 0) continue;
      for (int s = 0; s < slot_count(); ++s) {
        const Slot& sl = slots_[static_cast<std::size_t>(s)];
        if (!taken[static_cast<std::size_t>(sl.activity)] ||
            count[static_cast<std::size_t>(s)] >=
                set_.activities[static_cast<std::size_t>(sl.activity)].roles[static_cast<std::size_t>(sl.role)].max)
          continue;
        const double v = t.u[static_cast<std::size_t>(i)][static_cast<std::size_t>(s)];
        if (v > kNone && (bi < 0 || v > t.u[static_cast<std::size_t>(bi)][static_cast<std::size_t>(bs)])) {
          bi = i;
          bs = s;
        }
      }
    }
    if (bi < 0) break;
    slot[static_cast<std::size_t>(bi)] = bs;
    ++count[static_cast<std::size_t>(bs)];
  }
  return slot;
}

void Allocator::improve(const Tables& t, std::vector<int>& slot) const {
  auto u = [&](int i, int s) { return s < 0 ? 0.0 : t.u[static_cast<std::size_t>(i)][static_cast<std::size_t>(s)]; };
  auto ok = [&](int i, int s) { return s < 0 || u(i, s) > kNone; };
  // First-improvement local search, at most 4 n^2 accepted moves: one robot
  // to another slot (or none), then two robots to any two slots at once
  // (swaps, ejections, and both roles of a two-role schema).
  const int bound = 4 * t.n * t.n, ns = slot_count();
  auto single = [&]() {
    for (int i = 0; i < t.n; ++i) {
      const int old = slot[static_cast<std::size_t>(i)];
      for (int s = -1; s < ns; ++s) {
        if (s == old || !ok(i, s) || !(u(i, s) > u(i, old) + 1e-12)) continue;
        slot[static_cast<std::size_t>(i)] = s;
        if (feasible(slot, t.on_agenda)) return true;
        slot[static_cast<std::size_t>(i)] = old;
      }
    }
    return false;
  };
  auto pair = [&]() {
    for (int i = 0; i < t.n; ++i)
      for (int j = i + 1; j < t.n; ++j) {
        const int a = slot[static_cast<std::size_t>(i)], b = slot[static_cast<std::size_t>(j)];
        const double now = u(i, a) + u(j, b);
        for (int s = -1; s < ns; ++s) {
          if (!ok(i, s)) continue;
          for (int r = -1; r < ns; ++r) {
            if ((s == a && r == b) || !ok(j, r) || !(u(i, s) + u(j, r) > now + 1e-12)) continue;
            slot[static_cast<std::size_t>(i)] = s;
            slot[static_cast<std::size_t>(j)] = r;
            if (feasible(slot, t.on_agenda)) return true;
            slot[static_cast<std::size_t>(i)] = a;
            slot[static_cast<std::size_t>(j)] = b;
          }
        }
      }
    return false;
  };
  for (int moves = 0; moves < bound && (single() || pair()); ++moves) {
  }
}

}  // namespace mrt::scare
