#include "mrt_brian/behavior_engine.h"

#include <algorithm>
#include <map>

namespace mrt::brian {

BehaviorEngine::BehaviorEngine() : filter_(std::make_unique<ThresholdFilter>()) {
  threshold_ = static_cast<const ThresholdFilter&>(*filter_).threshold();
}

int BehaviorEngine::add(std::unique_ptr<Behavior> b) {
  behaviors_.push_back(std::move(b));
  return size() - 1;
}

void BehaviorEngine::set_filter(std::unique_ptr<CandoFilter> f) {
  if (const auto* t = dynamic_cast<const ThresholdFilter*>(f.get())) threshold_ = t->threshold();
  filter_ = std::move(f);
}

void BehaviorEngine::set_threshold(double value) {
  threshold_ = value;
  auto* t = dynamic_cast<ThresholdFilter*>(filter_.get());
  if (t) t->set_threshold(value);
  else filter_ = std::make_unique<ThresholdFilter>(value);
}

void BehaviorEngine::finalize(Profile profile) {
  profile_ = profile;
  std::map<int, std::vector<int>> by_level;
  for (int i = 0; i < size(); ++i) by_level[behavior(i).level()].push_back(i);
  schedule_.clear();
  int expected = 1;
  for (auto& [level, ids] : by_level) {
    if (profile == Profile::kLegacy && level != expected) break;
    std::sort(ids.begin(), ids.end(), [this](int a, int b) { return behavior(a).name() < behavior(b).name(); });
    schedule_.emplace_back(level, ids);
    ++expected;
  }
}

std::size_t BehaviorEngine::max_proposals() const {
  std::size_t n = 0;
  for (const auto& b : behaviors_) n += b->max_proposals();
  return n;
}

void BehaviorEngine::run(const std::vector<FuzzyValue>& cando, BehaviorContext& ctx,
                         HierarchyObserver* observer, std::vector<std::uint8_t>& active) const {
  active.assign(behaviors_.size(), 0);
  for (std::size_t i = 0; i < behaviors_.size(); ++i) active[i] = filter_->active(cando[i]) ? 1 : 0;
  for (std::size_t li = 0; li < schedule_.size(); ++li) {
    const auto& [level, ids] = schedule_[li];
    if (profile_ == Profile::kManual && li > 0 && observer) {
      observer->before_level(level);
      // The observer may have evaluated this level's CANDO again (§10.4.3).
      for (int id : ids) active[static_cast<std::size_t>(id)] = filter_->active(cando[static_cast<std::size_t>(id)]) ? 1 : 0;
    }
    for (int id : ids) {
      if (!active[static_cast<std::size_t>(id)]) continue;
      if (profile_ == Profile::kLegacy && li > 0 && observer) observer->before_behavior(id);
      ctx.owner = id;
      ctx.level = level;
      behavior(id).run(ctx);
    }
  }
}

}  // namespace mrt::brian
