#include "mrt_recvision/objects.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrt::recvision {

namespace {
// Central lines only: near the object's edges the foot's distance changes
// fast with the bearing and half a pixel of bearing moves it far.
constexpr double kCentral = 0.7;
// Pixels looked at from an object's first pixel to tell it from noise.
constexpr int kWindow = 4;
}  // namespace

ObjectFinder::ObjectFinder(const ObjectOptions& options)
    : o_(options), is_floor_(kColorClasses, false) {
  for (ColorClass c : o_.floor) is_floor_[static_cast<std::size_t>(c)] = true;
}

FirstRun ObjectFinder::first_run(const ScanLine& line, const std::vector<std::uint8_t>& cls) const {
  const auto& pts = line.points;
  const int n = static_cast<int>(pts.size());
  FirstRun r;
  for (int k = 0; k < n; ++k) {
    if (is_floor_[cls[k]]) continue;
    // An object, or a speck of noise on the floor? Near a narrow object's
    // edge the line's pixels (rounded to the image grid) zigzag across it,
    // so its first pixel may be followed by floor: the object is there if
    // min_pixels of the kWindow pixels from here are not floor.
    const int end = std::min(n, k + kWindow);
    int off_floor = 0;
    for (int j = k; j < end; ++j) off_floor += !is_floor_[cls[j]];
    if (off_floor < std::min(o_.min_pixels, end - k)) continue;
    if (k == 0) {  // the line starts on something: its foot is hidden
      r.blocked = true;
      return r;
    }
    r.hit = true;
    r.length = 0;
    for (int j = k; j < n; ++j) r.length += !is_floor_[cls[j]];
    // Its colour: that of its foot (the first classified pixel there).
    r.color = ColorClass::kNone;
    for (int j = k; j < end && r.color == ColorClass::kNone; ++j)
      if (!is_floor_[cls[j]]) r.color = static_cast<ColorClass>(cls[j]);
    const int s = k;
    r.x = 0.5f * (pts[s - 1].x + pts[s].x);
    r.y = 0.5f * (pts[s - 1].y + pts[s].y);
    r.t = std::hypot(r.x, r.y);
    return r;
  }
  return r;
}

void ObjectFinder::find(const ScanGrid& grid, const std::vector<std::vector<std::uint8_t>>& cls,
                        std::vector<FoundObject>& objects, std::vector<LinePoint>& walls) {
  const int n = static_cast<int>(grid.radial().size());
  runs_.resize(n);
  for (int i = 0; i < n; ++i) runs_[i] = first_run(grid.radial()[i], cls[i]);
  if (o_.wall != ColorClass::kNone) {
    for (int i = 0; i < n; i += o_.wall_step) {
      const FirstRun& r = runs_[i];
      if (r.hit && r.color == o_.wall && r.t <= o_.wall_max_distance) walls.push_back({r.x, r.y});
    }
  }
  auto joined = [&](int a, int b) {
    const FirstRun &p = runs_[a], &q = runs_[b];
    return p.hit && q.hit && p.color == q.color && std::abs(p.t - q.t) <= o_.max_jump;
  };
  int start = -1;
  for (int i = 0; i < n && start < 0; ++i)
    if (!joined((i + n - 1) % n, i)) start = i;
  if (start < 0) return;  // one run all round: nothing stands out
  int first = -1, count = 0;
  auto close = [&] {
    const ColorClass c = count > 0 ? runs_[first].color : ColorClass::kNone;
    if (count > 0 && c != ColorClass::kNone && c != o_.wall) measure(first, count, objects);
    count = 0;
  };
  for (int k = 0; k < n; ++k) {
    const int i = (start + k) % n;
    if (count > 0 && joined((i + n - 1) % n, i)) {
      ++count;
      continue;
    }
    close();
    if (runs_[i].hit) first = i, count = 1;
  }
  close();
}

double ObjectFinder::centre_distance(int first, int n, double bearing, double radius) const {
  const int lines = static_cast<int>(runs_.size());
  double sum = 0.0, t_min = std::numeric_limits<double>::infinity();
  int used = 0;
  for (int k = 0; k < n; ++k) {
    const FirstRun& q = runs_[(first + k) % lines];
    t_min = std::min(t_min, q.t);
    const double delta = std::remainder(std::atan2(q.y, q.x) - bearing, 2.0 * M_PI);
    const double s = q.t * std::sin(delta);
    if (std::abs(s) >= kCentral * radius) continue;
    sum += q.t * std::cos(delta) + std::sqrt(radius * radius - s * s);
    ++used;
  }
  return used > 0 ? sum / used : t_min + radius;
}

void ObjectFinder::measure(int first, int n, std::vector<FoundObject>& out) const {
  const int lines = static_cast<int>(runs_.size());
  if (n >= lines - 1) return;
  const double step = 2.0 * M_PI / lines;
  const int last = (first + n - 1) % lines;
  // A side is hidden when the line beyond it sees a nearer object (or
  // starts on one).
  auto hides = [&](int beyond, int edge) {
    const FirstRun& q = runs_[beyond];
    return q.blocked || (q.hit && q.t < runs_[edge].t);
  };
  const bool hidden_lo = hides((first + lines - 1) % lines, first), hidden_hi = hides((last + 1) % lines, last);
  if (hidden_lo && hidden_hi) return;
  double t_min = std::numeric_limits<double>::infinity();
  int pixels = 0;
  for (int k = 0; k < n; ++k) {
    t_min = std::min(t_min, runs_[(first + k) % lines].t);
    pixels += runs_[(first + k) % lines].length;
  }
  const double b_first = step * first, b_last = b_first + (n - 1) * step;
  const ColorClass color = runs_[first].color;
  std::vector<FoundObject> candidates;
  bool ambiguous = false;
  for (std::size_t k = 0; k < o_.kinds.size(); ++k) {
    const ObjectKind& kind = o_.kinds[k];
    if (std::find(kind.colors.begin(), kind.colors.end(), color) == kind.colors.end()) continue;
    FoundObject f;
    f.kind = static_cast<int>(k);
    f.color = color;
    f.lines = n;
    f.pixels = pixels;
    f.occluded = hidden_lo || hidden_hi;
    double bearing = 0.5 * (b_first + b_last), d = 0.0, r = kind.radius;
    const double half = 0.5 * n * step;  // half the angle covered
    if (!f.occluded) {
      if (r <= 0.0) {  // the radius from the apparent width: sin(half) = R / (t_min + R)
        const double s = std::sin(half);
        if (s >= 0.95) continue;
        r = t_min * s / (1.0 - s);
        d = t_min + r;
      } else {
        d = centre_distance(first, n, bearing, r);
      }
      const double width = 2.0 * d * std::sin(half);
      if (width < kind.min_width || width > kind.max_width) continue;
    } else {
      // A partial view of a kind of unknown radius tells neither its size
      // nor its centre: it may be that kind, so the view is ambiguous.
      if (r <= 0.0) {
        candidates.push_back(f);
        ambiguous = true;
        continue;
      }
      const double a = std::asin(std::min(1.0, r / (t_min + r)));
      bearing = hidden_hi ? b_first - 0.5 * step + a : b_last + 0.5 * step - a;
      if (bearing < b_first - 0.5 * step || bearing > b_last + 0.5 * step) {  // its centre would be hidden:
        candidates.push_back(f);                                               // this kind cannot be ruled out
        ambiguous = true;
        continue;
      }
      d = centre_distance(first, n, bearing, r);
      if (2.0 * d * std::sin(half) > kind.max_width) continue;  // already wider than this kind
    }
    f.radius = r;
    f.x = d * std::cos(bearing);
    f.y = d * std::sin(bearing);
    candidates.push_back(f);
  }
  if (candidates.size() == 1 && !ambiguous) out.push_back(candidates.front());  // not none, not ambiguous
}

}  // namespace mrt::recvision
