#include "mrt_scare/allocator.h"

#include "allocator_tables.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrt::scare {

Allocator::Allocator(const ActivitySet& set) : set_(set), slots_(set.slots()) {
  for (std::size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].role == 0) first_slot_.push_back(static_cast<int>(s));
}

double Allocator::fit(const RobotView& r, int s) const {
  const double t = r.time[static_cast<std::size_t>(s)];
  if (!(t < std::numeric_limits<double>::infinity())) return 0.0;
  return r.confidence * r.attitude[static_cast<std::size_t>(s)] / (1.0 + t / set_.options.time_scale);
}

double Allocator::utility(const TeamInput& in, const RobotView& r, int s) const {
  const ActivitySpec& a = set_.activities[static_cast<std::size_t>(slots_[static_cast<std::size_t>(s)].activity)];
  const double opp = in.opportunity[static_cast<std::size_t>(slots_[static_cast<std::size_t>(s)].activity)];
  const bool kept = r.incumbent == s || std::find(in.vacated.begin(), in.vacated.end(), s) != in.vacated.end();
  return a.priority * opp * fit(r, s) + (kept ? set_.options.hysteresis : 0.0);
}

bool Allocator::dwelling(const RobotView& r) const {
  return set_.options.dwell > 0.0 && r.incumbent >= 0 && r.held < set_.options.dwell;
}

std::vector<AgendaEntry> Allocator::agenda(const TeamInput& in) const {
  std::vector<AgendaEntry> all;
  for (std::size_t a = 0; a < set_.activities.size(); ++a) {
    // An activity below min_opportunity stays on the agenda while it is
    // still opportune at all and a robot within its dwell holds it.
    bool kept = false;
    for (const RobotView& r : in.robots)
      kept = kept || (dwelling(r) && slots_[static_cast<std::size_t>(r.incumbent)].activity == static_cast<int>(a));
    if (!(in.opportunity[a] >= set_.options.min_opportunity || (kept && in.opportunity[a] > 0.0))) continue;
    AgendaEntry e;
    e.activity = static_cast<int>(a);
    e.opportunity = in.opportunity[a];
    e.priority = set_.activities[a].priority;
    for (const RobotView& r : in.robots)
      for (std::size_t k = 0; k < set_.activities[a].roles.size(); ++k)
        e.fit = std::max(e.fit, fit(r, first_slot_[a] + static_cast<int>(k)));
    e.score = e.priority * e.opportunity * e.fit;
    e.layer = -1;
    all.push_back(e);
  }
  auto dominates = [](const AgendaEntry& p, const AgendaEntry& q) {
    return p.opportunity >= q.opportunity && p.priority >= q.priority && p.fit >= q.fit &&
           (p.opportunity > q.opportunity || p.priority > q.priority || p.fit > q.fit);
  };
  for (int layer = 0, left = static_cast<int>(all.size()); left > 0; ++layer) {
    std::vector<std::size_t> now;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (all[i].layer >= 0) continue;
      bool dominated = false;
      for (std::size_t j = 0; j < all.size() && !dominated; ++j)
        dominated = j != i && all[j].layer < 0 && dominates(all[j], all[i]);
      if (!dominated) now.push_back(i);
    }
    for (std::size_t i : now) all[i].layer = layer;
    left -= static_cast<int>(now.size());
  }
  std::stable_sort(all.begin(), all.end(), [](const AgendaEntry& p, const AgendaEntry& q) {
    if (p.layer != q.layer) return p.layer < q.layer;
    if (p.score != q.score) return p.score > q.score;
    return p.activity < q.activity;
  });
  return all;
}

Allocator::Tables Allocator::tables(const TeamInput& in, const std::vector<AgendaEntry>& agenda) const {
  Tables t;
  t.n = static_cast<int>(in.robots.size());
  t.on_agenda.assign(set_.activities.size(), 0);
  const int nslots = slot_count();
  std::vector<int> rank(slots_.size(), nslots);  // slots in agenda order
  int next = 0;
  for (const AgendaEntry& e : agenda) {
    t.on_agenda[static_cast<std::size_t>(e.activity)] = 1;
    for (std::size_t k = 0; k < set_.activities[static_cast<std::size_t>(e.activity)].roles.size(); ++k)
      rank[static_cast<std::size_t>(first_slot_[static_cast<std::size_t>(e.activity)]) + k] = next++;
  }
  // Tie-break: among allocations of equal utility, the lower robot ids take
  // the slots earlier on the agenda. The term sums to less than 1e-9.
  const double eps = 1e-9 / (static_cast<double>(t.n + 1) * (nslots + 1) * (t.n + 1));
  t.u.assign(static_cast<std::size_t>(t.n), std::vector<double>(slots_.size(), kNone));
  for (int i = 0; i < t.n; ++i)
    for (int s = 0; s < nslots; ++s)
      if (t.on_agenda[static_cast<std::size_t>(slots_[static_cast<std::size_t>(s)].activity)])
        t.u[static_cast<std::size_t>(i)][static_cast<std::size_t>(s)] =
            utility(in, in.robots[static_cast<std::size_t>(i)], s) +
            eps * (t.n - i) * (nslots - rank[static_cast<std::size_t>(s)]);
  // Dwell: a robot within its dwell keeps its slot whenever some feasible
  // allocation lets it. Its slot earns a bonus larger than every robot's
  // utility together (priority * 1 * 1 + hysteresis each), so the search
  // first keeps as many dwelling robots as cardinality and coverage allow,
  // then maximises utility; a slot off the agenda earns nothing.
  double top = 0.0;
  for (const ActivitySpec& a : set_.activities) top = std::max(top, a.priority);
  const double bonus = (t.n + 1) * (top + set_.options.hysteresis + 1.0);
  for (int i = 0; i < t.n; ++i) {
    const RobotView& r = in.robots[static_cast<std::size_t>(i)];
    double& u = t.u[static_cast<std::size_t>(i)][static_cast<std::size_t>(std::max(0, r.incumbent))];
    if (dwelling(r) && u > kNone) u += bonus;
  }
  return t;
}

bool Allocator::feasible(const std::vector<int>& slot, const std::vector<char>& on_agenda) const {
  std::vector<int> count(slots_.size(), 0);
  for (int s : slot) {
    if (s < 0) continue;
    if (!on_agenda[static_cast<std::size_t>(slots_[static_cast<std::size_t>(s)].activity)]) return false;
    ++count[static_cast<std::size_t>(s)];
  }
  for (std::size_t a = 0; a < set_.activities.size(); ++a) {
    const auto& roles = set_.activities[a].roles;
    int total = 0;
    for (std::size_t k = 0; k < roles.size(); ++k) total += count[static_cast<std::size_t>(first_slot_[a]) + k];
    if (total == 0) continue;
    for (std::size_t k = 0; k < roles.size(); ++k) {
      const int c = count[static_cast<std::size_t>(first_slot_[a]) + k];
      if (c < roles[k].min || c > roles[k].max) return false;
    }
  }
  return true;
}

double Allocator::value(const TeamInput& in, const std::vector<int>& slot) const {
  double v = 0.0;
  for (std::size_t i = 0; i < slot.size(); ++i)
    if (slot[i] >= 0) v += utility(in, in.robots[i], slot[i]);
  return v;
}

Allocation Allocator::allocate(TeamInput in, Method m) const {
  std::sort(in.robots.begin(), in.robots.end(),
            [](const RobotView& p, const RobotView& q) { return p.id < q.id; });
  Allocation out;
  out.agenda = agenda(in);
  for (const RobotView& r : in.robots) out.robots.push_back(r.id);
  const Tables t = tables(in, out.agenda);
  if (m == Method::kAuto)
    m = t.n <= set_.options.exact_max_robots ? Method::kExact : Method::kGreedyLocal;
  if (m == Method::kExact) {
    out.slot = exact(t, out.agenda);
  } else {
    out.slot = greedy(t, out.agenda);
    if (m == Method::kGreedyLocal) improve(t, out.slot);
  }
  out.utility = value(in, out.slot);
  return out;
}

}  // namespace mrt::scare
