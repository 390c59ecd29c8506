#include "mrt_map/tracker.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mrt_map/assignment.h"
#include "mrt_map/imm.h"
#include "mrt_map/kalman.h"

namespace mrt::map {

namespace {
double position_sigma_max(const Mat4& P) { return std::sqrt(principal_axes(P.topLeftCorner<2, 2>()).major); }
}  // namespace

void Tracker::refine_class(Anchor& a, int c, double degree) const {
  if (c == a.class_index) {
    a.degree = degree;
  } else if (model_.is_a(c, a.class_index)) {
    a.class_index = c;
    a.degree = degree;
  }
}

Anchor& Tracker::create(double now, int class_index, double degree) {
  Anchor a;
  a.id = next_id_++;
  a.class_index = class_index;
  a.degree = degree;
  a.first_seen = a.last_seen = now;
  anchors_.push_back(std::move(a));
  return anchors_.back();
}

void Tracker::cycle(double now, const std::vector<Observation>& observations, std::vector<RemoteTrack> remote) {
  now_ = now;
  for (Anchor& a : anchors_) {
    const ClassDef& c = model_.at(a.class_index);
    a.fused = predict(a.fused, c, now);
    if (a.has_imm) {
      imm_predict(a.imm, c, now);
      a.local = imm_combine(a.imm);
    } else if (a.has_local) {
      a.local = predict(a.local, c, now);
    }
    a.remote.clear();
  }
  seen_.clear();
  own_seen_.clear();
  coalesced_cycle_ = 0;
  associate_local(now, observations);
  associate_remote(now, remote);
  fuse(now);
  coalesce();
  refine_teammates(now);
  life_cycle(now);
}

void Tracker::coalesce() {
  // Two anchors of compatible classes whose states (position and velocity)
  // stay within the coalescence gate for coalesce_after seconds are one
  // object (objects crossing are close only briefly): the older (lower id)
  // keeps its symbol and takes the other's support.
  const double gate = model_.tracker().coalesce_gate;
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> still_close;
  if (!(gate > 0.0)) return;
  for (std::size_t i = 0; i < anchors_.size(); ++i) {
    for (std::size_t j = i + 1; j < anchors_.size(); ++j) {
      Anchor& a = anchors_[i];
      Anchor& b = anchors_[j];
      if (b.status == AnchorStatus::kDropped || a.status == AnchorStatus::kDropped) continue;
      if (!model_.compatible(a.class_index, b.class_index)) continue;
      const Vec4 y = a.fused.x - b.fused.x;
      // Cheap sufficient reject: the position part alone exceeds the gate.
      if (y.head<2>().squaredNorm() > gate * (a.fused.P(0, 0) + a.fused.P(1, 1) + b.fused.P(0, 0) + b.fused.P(1, 1)))
        continue;
      // Seen apart: one frame of an own sensor held a distinct observation
      // for each this cycle (the association gives one observation to one
      // anchor): two objects side by side, not one with two symbols; each
      // keeps its id. Two frames of one sensor queued into one cycle (a
      // lagging node) are not "apart": the second can open a duplicate.
      if (seen_in_one_frame(a.id, b.id)) continue;
      // Of a class with a cardinality, also one teammate's two tracks (it
      // sees two objects; for every class measured worse in map_bench).
      const bool card_a = cardinality_class(a.class_index) >= 0, card_b = cardinality_class(b.class_index) >= 0;
      if ((card_a || card_b) && one_teammate_apart(a, b)) continue;
      // A lost anchor of a class with a cardinality (unsupported this
      // cycle) stays for its object's return: its prediction meeting
      // another anchor (its covariance grown wide) says nothing of identity.
      if ((card_a && !seen_.count(a.id)) || (card_b && !seen_.count(b.id))) continue;
      const Mat4 S = a.fused.P + b.fused.P;
      if (y.dot(S.ldlt().solve(y)) > gate) continue;
      const auto key = std::make_pair(std::min(a.id, b.id), std::max(a.id, b.id));
      const auto since = close_since_.find(key);
      const double t0 = since == close_since_.end() ? now_ : since->second;
      if (now_ - t0 < model_.tracker().coalesce_after) {
        still_close[key] = t0;
        continue;
      }
      Anchor& keep = a.id < b.id ? a : b;
      Anchor& gone = a.id < b.id ? b : a;
      if (gone.has_local && (!keep.has_local || gone.local_last_seen > keep.local_last_seen)) {
        keep.local = gone.local;
        keep.has_local = true;
        keep.imm = gone.imm;
        keep.has_imm = gone.has_imm;
        keep.local_hits = std::max(keep.local_hits, gone.local_hits);
        keep.local_last_seen = gone.local_last_seen;
      }
      if (model_.is_a(gone.class_index, keep.class_index)) keep.class_index = gone.class_index;
      keep.hits = std::max(keep.hits, gone.hits);
      keep.last_seen = std::max(keep.last_seen, gone.last_seen);
      keep.sources.insert(gone.sources.begin(), gone.sources.end());
      for (const auto& [robot, id] : gone.remote_ids) keep.remote_ids.emplace(robot, id);
      if (gone.status == AnchorStatus::kConfirmed) keep.status = AnchorStatus::kConfirmed;
      else if (keep.status == AnchorStatus::kTentative) keep.status = gone.status;
      if (seen_.count(gone.id)) seen_.insert(keep.id);
      gone.status = AnchorStatus::kDropped;
      ++coalesced_;
      ++coalesced_cycle_;
    }
  }
  close_since_ = std::move(still_close);
}

void Tracker::keep_lost_off_held(std::vector<std::vector<double>>& cost, double gate) const {
  // An observation (or track) inside the gate of an anchor that is not
  // lost is that anchor's or a duplicate of it: it cannot bring back a
  // lost anchor of a class with a cardinality, whose wide gate would
  // otherwise take another object's detections.
  std::vector<bool> lost(anchors_.size());  // coasting, of a class with a cardinality
  bool any = false;
  for (std::size_t c = 0; c < anchors_.size(); ++c) {
    lost[c] = anchors_[c].status == AnchorStatus::kCoasting && cardinality_class(anchors_[c].class_index) >= 0;
    any = any || lost[c];
  }
  if (!any) return;
  for (std::vector<double>& row : cost) {
    bool held = false;
    for (std::size_t c = 0; c < row.size() && !held; ++c)
      held = row[c] < gate && anchors_[c].status != AnchorStatus::kCoasting;
    if (!held) continue;
    for (std::size_t c = 0; c < row.size(); ++c)
      if (lost[c]) row[c] = kInfeasible;
  }
}

Anchor* Tracker::reidentify(int class_index, const Vec2& z, const Mat2& R) {
  const double gate = model_.tracker().reid_gate;
  Anchor* best = nullptr;
  double best_d = gate;
  if (!(gate > 0.0)) return nullptr;
  for (Anchor& a : anchors_) {
    if (a.status != AnchorStatus::kCoasting || seen_.count(a.id) || !model_.compatible(class_index, a.class_index))
      continue;
    const double d = mahalanobis2(a.fused, z, R);
    if (d <= best_d) best_d = d, best = &a;
  }
  return best;
}

void Tracker::associate_local(double now, const std::vector<Observation>& obs) {
  const double gate = model_.tracker().gate;
  const double radius = model_.tracker().maneuver_radius;
  std::vector<std::vector<double>> cost(obs.size(), std::vector<double>(anchors_.size(), kInfeasible));
  for (std::size_t r = 0; r < obs.size(); ++r)
    for (std::size_t c = 0; c < anchors_.size(); ++c) {
      if (!model_.compatible(obs[r].class_index, anchors_[c].class_index)) continue;
      const bool far = (obs[r].z - anchors_[c].fused.x.head<2>()).norm() > radius;
      if (far && outside_gate(anchors_[c].fused, obs[r].z, obs[r].R, gate)) continue;
      const double d = mahalanobis2(anchors_[c].fused, obs[r].z, obs[r].R);
      // Within the gate; or a confirmed anchor's manoeuvre (a kick), at the
      // worst cost so that any gated pair wins.
      if (d <= gate) cost[r][c] = d;
      else if (anchors_[c].status != AnchorStatus::kTentative &&
               (obs[r].z - anchors_[c].fused.x.head<2>()).norm() <= radius)
        cost[r][c] = gate;
    }
  keep_lost_off_held(cost, gate);
  const std::vector<int> match = assign(cost, gate);
  const std::size_t existing = anchors_.size();
  std::map<int, std::vector<std::size_t>> pending;  // by class at its cardinality: unmatched observations
  for (std::size_t r = 0; r < obs.size(); ++r) {
    const Observation& o = obs[r];
    Anchor* a = nullptr;
    if (match[r] >= 0 && static_cast<std::size_t>(match[r]) < existing) {
      a = &anchors_[static_cast<std::size_t>(match[r])];
      refine_class(*a, o.class_index, o.degree);
    } else {
      bool gated = false;  // a second detection of an anchored object: no new symbol
      for (std::size_t k = 0; k < existing && !gated; ++k) gated = cost[r][k] < gate;
      if (gated) continue;
      a = reidentify(o.class_index, o.z, o.R);
      if (!a) {
        const int card = at_cardinality(o.class_index);
        if (card >= 0) {
          pending[card].push_back(r);
          continue;
        }
      }
      if (a) refine_class(*a, o.class_index, o.degree);
      else a = &create(now, o.class_index, o.degree);
    }
    apply_local(now, *a, o);
  }
  for (const auto& [card, rows] : pending) {
    std::vector<std::pair<Vec2, Mat2>> zs;
    for (std::size_t r : rows) zs.emplace_back(obs[r].z, obs[r].R);
    const std::vector<int> lost = claim_lost(card, zs);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Observation& o = obs[rows[i]];
      Anchor* a = nullptr;
      if (lost[i] >= 0) {
        a = &anchors_[static_cast<std::size_t>(lost[i])];
        refine_class(*a, o.class_index, o.degree);
      } else {
        a = &create(now, o.class_index, o.degree);
      }
      apply_local(now, *a, o);
    }
  }
}

void Tracker::apply_local(double now, Anchor& anchor, const Observation& o) {
  Anchor* a = &anchor;
  const ClassDef& c = model_.at(a->class_index);
  const bool imm = c.imm.on && c.motion == MotionModel::kConstantVelocity;
  if (!a->has_local) {
    a->local = initialize(o, c);
    a->local = predict(a->local, c, now);
    a->has_local = true;
    a->has_imm = imm;
    if (imm) a->imm = imm_start(a->local, c.imm);
    a->local_hits = 0;
    if (a->hits == 0) a->fused = a->local;
  } else {
    if (mahalanobis2(a->local, o.z, o.R) > model_.tracker().gate)  // manoeuvre: keep the symbol
      for (Estimate* e : {&a->local, &a->imm.model[0], &a->imm.model[1]})
        maneuver(*e, c, std::max(0.0, now - a->local_last_seen), o.R);
    if (a->has_imm) {
      imm_update(a->imm, o.z, o.R);
      a->local = imm_combine(a->imm);
    } else {
      update(a->local, o.z, o.R);
    }
  }
  ++a->local_hits;
  a->local_last_seen = a->last_seen = now;
  a->sources.insert(o.sensors.begin(), o.sensors.end());
  seen_.insert(a->id);
  for (const auto& s : o.sensors) own_seen_[a->id].insert({s, o.stamp});
}

bool Tracker::seen_in_one_frame(std::uint32_t a, std::uint32_t b) const {
  const auto fa = own_seen_.find(a), fb = own_seen_.find(b);
  if (fa == own_seen_.end() || fb == own_seen_.end()) return false;
  for (const auto& frame : fa->second)
    if (fb->second.count(frame)) return true;
  return false;
}

bool Tracker::one_teammate_apart(const Anchor& a, const Anchor& b) {
  for (const auto& [robot, t] : a.remote) {
    const auto o = b.remote.find(robot);
    if (o != b.remote.end() && o->second.id != t.id) return true;
  }
  return false;
}

int Tracker::cardinality_class(int class_index) const {
  for (int k = class_index; k >= 0; k = model_.at(k).parent)
    if (model_.at(k).max_count > 0) return k;
  return -1;
}

int Tracker::live_count(int card) const {
  int live = 0;
  for (const Anchor& a : anchors_)
    if ((a.status == AnchorStatus::kConfirmed || a.status == AnchorStatus::kCoasting) &&
        model_.is_a(a.class_index, card))
      ++live;
  return live;
}

int Tracker::at_cardinality(int class_index) const {
  const int card = cardinality_class(class_index);
  return card >= 0 && live_count(card) >= model_.at(card).max_count ? card : -1;
}

std::vector<int> Tracker::claim_lost(int card_class, const std::vector<std::pair<Vec2, Mat2>>& zs) const {
  std::vector<int> cols;  // lost anchors: coasting, not supported this cycle
  for (std::size_t i = 0; i < anchors_.size(); ++i) {
    const Anchor& a = anchors_[i];
    if (a.status == AnchorStatus::kCoasting && !seen_.count(a.id) && model_.is_a(a.class_index, card_class))
      cols.push_back(static_cast<int>(i));
  }
  std::vector<int> out(zs.size(), -1);
  if (cols.empty()) return out;
  // Square matrix: rows = observations, columns = lost anchors, padded with
  // a uniform "no anchor" cost so that every cheaper real pair wins.
  const std::size_t n = std::max(zs.size(), cols.size());
  constexpr double kNone = 1e12;
  std::vector<std::vector<double>> cost(n, std::vector<double>(n, kNone));
  for (std::size_t r = 0; r < zs.size(); ++r)
    for (std::size_t c = 0; c < cols.size(); ++c) {
      const Estimate& e = anchors_[static_cast<std::size_t>(cols[c])].fused;
      const Mat2 S = e.P.topLeftCorner<2, 2>() + zs[r].second;
      cost[r][c] = mahalanobis2(e, zs[r].first, zs[r].second) + std::log(S.determinant());
    }
  const std::vector<int> m = hungarian(cost);
  for (std::size_t r = 0; r < zs.size(); ++r)
    if (m[r] >= 0 && static_cast<std::size_t>(m[r]) < cols.size()) out[r] = cols[static_cast<std::size_t>(m[r])];
  return out;
}

void Tracker::life_cycle(double now) {
  const TrackerOptions& o = model_.tracker();
  for (Anchor& a : anchors_) {
    const ClassDef& c = model_.at(a.class_index);
    // A coasting anchor of a class at its cardinality is kept (lost, not
    // dropped): the object still exists and will be claimed back.
    const int card = a.status == AnchorStatus::kCoasting ? cardinality_class(a.class_index) : -1;
    const bool keep_lost = card >= 0 && live_count(card) <= model_.at(card).max_count;
    const double drop_after = c.drop_after > 0.0 ? c.drop_after : o.drop_after;
    const double max_sigma = c.max_sigma > 0.0 ? c.max_sigma : o.max_sigma;
    if (seen_.count(a.id)) {
      ++a.hits;
      if ((a.status == AnchorStatus::kTentative && a.hits >= o.confirm_hits) || a.status == AnchorStatus::kCoasting)
        a.status = AnchorStatus::kConfirmed;
    } else {
      const double age = now - a.last_seen;
      if (a.status == AnchorStatus::kTentative && age > o.tentative_timeout) a.status = AnchorStatus::kDropped;
      else if (a.status == AnchorStatus::kConfirmed && age > o.coast_after) a.status = AnchorStatus::kCoasting;
      if (!keep_lost && a.status == AnchorStatus::kCoasting && age > drop_after) a.status = AnchorStatus::kDropped;
      if (!keep_lost && position_sigma_max(a.fused.P) > max_sigma) a.status = AnchorStatus::kDropped;
    }
    // Predicted out of the world (model `world:`): nothing real is there.
    if (!model_.world().contains(a.fused.x(0), a.fused.x(1))) a.status = AnchorStatus::kDropped;
    if (a.has_local && now - a.local_last_seen > drop_after) {
      a.has_local = a.has_imm = false;
      a.local_hits = 0;
    }
  }
  const auto before = anchors_.size();
  anchors_.erase(std::remove_if(anchors_.begin(), anchors_.end(),
                                [](const Anchor& a) { return a.status == AnchorStatus::kDropped; }),
                 anchors_.end());
  dropped_ += before - anchors_.size() - coalesced_cycle_;
}

double Tracker::reliability(const Anchor& a, double now) const {
  return a.degree * std::exp(-std::max(0.0, now - a.last_seen) / model_.tracker().reliability_tau);
}

double Tracker::support(const Anchor& a, double now) const {
  const double c = model_.tracker().source_confidence, tau = model_.tracker().reliability_tau;
  auto doubt = [&](double last_seen) { return 1.0 - c * std::exp(-std::max(0.0, now - last_seen) / tau); };
  double none = a.has_local ? doubt(a.local_last_seen) : 1.0;  // no source is right
  for (const auto& [robot, t] : a.remote) none *= doubt(t.last_seen);
  return a.degree * (1.0 - none);
}

// The team side: teammates' tracks associated with the anchors, the fusion
// of each anchor's parts, teammates' poses refining classes, and the own
// tracks sent to the teammates.
namespace {
// The anchor was linked to this teammate's track (robot, its symbol) before.
bool linked(const Anchor& a, const std::string& robot, std::uint32_t id) {
  const auto link = a.remote_ids.find(robot);
  return link != a.remote_ids.end() && link->second == id;
}
}  // namespace

void Tracker::associate_remote(double now, std::vector<RemoteTrack>& remote) {
  const double gate = model_.team().gate;
  const double radius = model_.tracker().maneuver_radius;
  const double fresh = model_.tracker().coast_after;
  std::map<std::string, std::vector<RemoteTrack*>> by_robot;
  for (RemoteTrack& t : remote) by_robot[t.robot].push_back(&t);
  for (const auto& [robot, tracks] : by_robot) {
    const std::size_t existing = anchors_.size();
    std::vector<std::vector<double>> cost(tracks.size(), std::vector<double>(existing, kInfeasible));
    for (std::size_t r = 0; r < tracks.size(); ++r)
      for (std::size_t c = 0; c < existing; ++c) {
        const Anchor& a = anchors_[c];
        if (!model_.compatible(tracks[r]->class_index, a.class_index)) continue;
        const Vec2 z = tracks[r]->estimate.x.head<2>();
        const double off = (z - a.fused.x.head<2>()).norm();
        // keep_teammate_link: its own symbol says it is this object, however far (a kick it saw first).
        if (off <= model_.at(a.class_index).keep_link && linked(a, robot, tracks[r]->id)) {
          cost[r][c] = 0.0;
          continue;
        }
        if (off > radius && outside_gate(a.fused, z, tracks[r]->estimate.P.topLeftCorner<2, 2>(), gate)) continue;
        const double d = mahalanobis2(a.fused, z, tracks[r]->estimate.P.topLeftCorner<2, 2>());
        const bool manoeuvre = a.status != AnchorStatus::kTentative && off <= radius;
        if (d > gate && !manoeuvre) continue;
        cost[r][c] = linked(a, robot, tracks[r]->id) ? 0.0 : std::min(d, gate);  // sticky while it gates
      }
    keep_lost_off_held(cost, gate);
    const std::vector<int> match = assign(cost, gate);
    for (std::size_t r = 0; r < tracks.size(); ++r) {
      RemoteTrack& t = *tracks[r];
      const bool is_fresh = t.last_seen >= now - fresh;
      Anchor* a = nullptr;
      if (match[r] >= 0) {
        a = &anchors_[static_cast<std::size_t>(match[r])];
        refine_class(*a, t.class_index, t.degree);
      } else if (is_fresh) {
        // A track inside another anchor's gate is the teammate's duplicate.
        bool gated = false;
        for (std::size_t k = 0; k < existing && !gated; ++k) gated = cost[r][k] < gate;
        if (gated) continue;
        const Vec2 z = t.estimate.x.head<2>();
        const Mat2 R = t.estimate.P.topLeftCorner<2, 2>();
        a = reidentify(t.class_index, z, R);
        const int card = a ? -1 : at_cardinality(t.class_index);
        if (card >= 0) {
          const int lost = claim_lost(card, {{z, R}})[0];
          if (lost >= 0) a = &anchors_[static_cast<std::size_t>(lost)];
        }
        if (a) {
          refine_class(*a, t.class_index, t.degree);
        } else {
          a = &create(now, t.class_index, t.degree);
          a->fused = t.estimate;
        }
      } else {
        continue;
      }
      a->remote_ids[robot] = t.id;
      if (is_fresh) {
        a->last_seen = std::max(a->last_seen, t.last_seen);
        a->sources.insert(t.sensors.begin(), t.sensors.end());
        seen_.insert(a->id);
      }
      a->remote[robot] = std::move(t);  // t's last use
    }
  }
}

void Tracker::fuse(double now) {
  for (Anchor& a : anchors_) {
    const auto rule = model_.at(a.class_index).fusion;
    const bool ci = rule == ClassDef::Fusion::kTeam ? model_.team().covariance_intersection
                                                    : rule == ClassDef::Fusion::kCovarianceIntersection;
    std::vector<const Estimate*> parts;
    if (a.has_local) parts.push_back(&a.local);
    for (const auto& [robot, t] : a.remote) parts.push_back(&t.estimate);
    if (parts.empty()) continue;
    // Only an own filter older than the last support left (teammates' just
    // ended): keep the team estimate, predicted (the stale one jumps, wide).
    if (a.remote.empty() && a.local_last_seen < a.last_seen && a.hits > 0) continue;
    Estimate f = *parts[0];
    for (std::size_t i = 1; i < parts.size(); ++i)
      f = ci ? covariance_intersection(f, *parts[i]) : fuse_estimates(f, *parts[i]);
    f.stamp = now;
    a.fused = f;
  }
}

void Tracker::set_teammate_pose(const std::string& robot, const Vec2& p, const Mat2& cov, double stamp) {
  teammates_[robot] = {p, cov, stamp};
}

void Tracker::refine_teammates(double now) {
  if (teammates_.empty()) return;
  for (Anchor& a : anchors_) {
    int target = -1;
    for (int c = 0; c < model_.size(); ++c)
      if (model_.at(c).refined_by_teammate_pose && c != a.class_index && model_.is_a(c, a.class_index)) target = c;
    if (target < 0) continue;
    for (const auto& [robot, t] : teammates_) {
      if (now - t.stamp > model_.team().max_latency) continue;
      if (mahalanobis2(a.fused, t.p, t.cov) <= model_.team().gate) {
        a.class_index = target;
        a.sources.insert(robot + "/pose");
        break;
      }
    }
  }
}

std::vector<RemoteTrack> Tracker::local_tracks(const std::string& robot) const {
  std::vector<RemoteTrack> out;
  for (const Anchor& a : anchors_) {
    if (!a.has_local || a.local_hits < model_.tracker().confirm_hits) continue;
    if (a.status == AnchorStatus::kDropped || now_ - a.local_last_seen > model_.tracker().coast_after) continue;
    RemoteTrack t;
    t.robot = robot;
    t.id = a.id;
    t.class_index = a.class_index;
    t.degree = a.degree;
    t.estimate = a.local;
    t.last_seen = a.local_last_seen;
    for (const std::string& s : a.sources)
      if (s.rfind(robot + "/", 0) == 0) t.sensors.insert(s);
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace mrt::map
