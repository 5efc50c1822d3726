// Inner/outer labels of the poles: the priority-queue propagation of the original program's labeling and its
// second pass (docs/method.md §7.6).
#include "stages.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace envcrust::powercrust {
namespace {

// Max-heap of poles with re-keying. Equal priorities pop in id order, so the labeling does
// not depend on the order in which neighbours were listed.
class PoleHeap {
 public:
  explicit PoleHeap(std::size_t poles) : position_(poles, kAbsent) {}

  [[nodiscard]] bool empty() const { return heap_.empty(); }
  [[nodiscard]] bool contains(Index p) const { return position_[p] != kAbsent; }

  void set(Index p, double priority) {
    if (!contains(p)) {
      position_[p] = static_cast<Index>(heap_.size());
      heap_.push_back({priority, p});
      sift_up(heap_.size() - 1);
      return;
    }
    const std::size_t i = position_[p];
    heap_[i].first = priority;
    sift_up(i);
    sift_down(position_[p]);
  }

  Index pop() {
    const Index top = heap_.front().second;
    swap_entries(0, heap_.size() - 1);
    heap_.pop_back();
    position_[top] = kAbsent;
    if (!heap_.empty()) sift_down(0);
    return top;
  }

 private:
  static constexpr Index kAbsent = kNoPole;

  [[nodiscard]] bool above(std::size_t a, std::size_t b) const {
    return heap_[a].first > heap_[b].first ||
           (heap_[a].first == heap_[b].first && heap_[a].second < heap_[b].second);
  }
  void swap_entries(std::size_t a, std::size_t b) {
    std::swap(heap_[a], heap_[b]);
    position_[heap_[a].second] = static_cast<Index>(a);
    position_[heap_[b].second] = static_cast<Index>(b);
  }
  void sift_up(std::size_t i) {
    while (i > 0 && above(i, (i - 1) / 2)) {
      swap_entries(i, (i - 1) / 2);
      i = (i - 1) / 2;
    }
  }
  void sift_down(std::size_t i) {
    for (;;) {
      std::size_t best = i;
      for (std::size_t c = 2 * i + 1; c <= 2 * i + 2 && c < heap_.size(); ++c)
        if (above(c, best)) best = c;
      if (best == i) return;
      swap_entries(i, best);
      i = best;
    }
  }

  std::vector<std::pair<double, Index>> heap_;
  std::vector<Index> position_;
};

// Each sample's two poles are opposite to each other with weight w_s (compressed rows).
struct OppositeLists {
  std::vector<std::size_t> offsets;
  std::vector<Index> poles;
  std::vector<double> weights;
};

OppositeLists opposite_lists(std::size_t pole_count, const std::vector<SamplePoles>& sample_poles) {
  OppositeLists o;
  o.offsets.assign(pole_count + 1, 0);
  for (const auto& sp : sample_poles)
    if (sp.is_paired) ++o.offsets[sp.outer + 1], ++o.offsets[sp.inner + 1];
  for (std::size_t p = 0; p < pole_count; ++p) o.offsets[p + 1] += o.offsets[p];
  o.poles.resize(o.offsets.back());
  o.weights.resize(o.offsets.back());
  std::vector<std::size_t> fill(o.offsets.begin(), o.offsets.end() - 1);
  for (const auto& sp : sample_poles) {
    if (!sp.is_paired) continue;
    o.poles[fill[sp.outer]] = sp.inner, o.weights[fill[sp.outer]++] = sp.weight;
    o.poles[fill[sp.inner]] = sp.outer, o.weights[fill[sp.inner]++] = sp.weight;
  }
  return o;
}

class Labeler {
 public:
  Labeler(std::vector<Pole>& poles, const OppositeLists& opposite, const PoleGraph& graph,
          double theta, const std::vector<bool>& deferred)
      : poles_(poles), opposite_(opposite), graph_(graph), theta_(theta), deferred_(deferred),
        in_(poles.size(), 0.0), out_(poles.size(), 0.0), heap_(poles.size()) {}

  void seed_outside(const CGAL::Bbox_3& box) {
    const double lo[3] = {2 * box.xmin() - box.xmax(), 2 * box.ymin() - box.ymax(), 2 * box.zmin() - box.zmax()};
    const double hi[3] = {2 * box.xmax() - box.xmin(), 2 * box.ymax() - box.ymin(), 2 * box.zmax() - box.zmin()};
    for (std::size_t p = 0; p < poles_.size(); ++p) {
      const Point3& c = poles_[p].center;
      bool outside = false;
      for (int k = 0; k < 3; ++k) outside = outside || c[k] > hi[k] || c[k] < lo[k];
      if (!outside) continue;
      out_[p] = 1.0;
      poles_[p].label = PoleLabel::Out;
      heap_.set(static_cast<Index>(p), 1.0);
    }
  }

  void propagate_all() {
    while (!heap_.empty()) {
      const Index p = heap_.pop();
      poles_[p].label = in_[p] > out_[p] ? PoleLabel::In : PoleLabel::Out;
      if (in_[p] == out_[p]) continue;  // the original propagates nothing from a tie
      const bool inside = in_[p] > out_[p];
      for (std::size_t k = opposite_.offsets[p]; k < opposite_.offsets[p + 1]; ++k) {
        const Index q = opposite_.poles[k];
        if (poles_[q].label != PoleLabel::Unknown) continue;
        if (inside) raise(out_, q, in_[p] * opposite_.weights[k]);
        else raise(in_, q, out_[p] * opposite_.weights[k]);
      }
      for (std::size_t k = graph_.offsets[p]; k < graph_.offsets[p + 1]; ++k) {
        const Index q = graph_.neighbours[k];
        if (poles_[q].label != PoleLabel::Unknown) continue;
        const double w = intersection_weight(poles_[p], poles_[q]);
        if (!(w > theta_)) continue;
        if (inside) raise(in_, q, in_[p] * w);
        else raise(out_, q, out_[p] * w);
      }
    }
  }

 private:
  [[nodiscard]] double priority(Index q) const {
    if (in_[q] == 0.0) return out_[q];
    if (out_[q] == 0.0) return in_[q];
    return std::abs(in_[q] - out_[q]) - 1.0;  // conflicting evidence: decide last
  }
  void raise(std::vector<double>& value, Index q, double candidate) {
    if (!deferred_.empty() && deferred_[q]) return;  // labeled by the second pass
    // An unlabeled pole outside the heap was never reached, so its values are still 0.
    if (heap_.contains(q) && !(candidate > value[q])) return;
    value[q] = candidate;
    heap_.set(q, priority(q));
  }

  std::vector<Pole>& poles_;
  const OppositeLists& opposite_;
  const PoleGraph& graph_;
  double theta_;
  const std::vector<bool>& deferred_;
  std::vector<double> in_, out_;
  PoleHeap heap_;
};

PoleLabel flip(PoleLabel l) { return l == PoleLabel::In ? PoleLabel::Out : PoleLabel::In; }

// The common label of p's labeled opposite poles; Unknown when there is none or they disagree.
PoleLabel opposite_label(const std::vector<Pole>& poles, const OppositeLists& o, std::size_t p) {
  PoleLabel common = PoleLabel::Unknown;
  for (std::size_t k = o.offsets[p]; k < o.offsets[p + 1]; ++k) {
    const PoleLabel l = poles[o.poles[k]].label;
    if (l == PoleLabel::Unknown) continue;
    if (common != PoleLabel::Unknown && common != l) return PoleLabel::Unknown;
    common = l;
  }
  return common;
}

// as the original's second pass: decide from the most deeply intersecting In and Out neighbours and
// the opposite poles. Labels set here are seen by later poles of the same pass.
void second_pass(std::vector<Pole>& poles, const OppositeLists& o, const PoleGraph& g, double deep) {
  for (std::size_t p = 0; p < poles.size(); ++p) {
    if (poles[p].label != PoleLabel::Unknown) continue;
    const PoleLabel opp = opposite_label(poles, o, p);
    std::optional<double> w_in, w_out;
    for (std::size_t k = g.offsets[p]; k < g.offsets[p + 1]; ++k) {
      const PoleLabel l = poles[g.neighbours[k]].label;
      if (l == PoleLabel::Unknown) continue;
      auto& w = l == PoleLabel::In ? w_in : w_out;
      const double pq = intersection_weight(poles[p], poles[g.neighbours[k]]);
      if (!w || pq > *w) w = pq;
    }
    const bool in_deep = w_in && *w_in > deep;
    const bool out_deep = w_out && *w_out > deep;
    PoleLabel label = PoleLabel::Unknown;
    if (in_deep != out_deep) label = in_deep ? PoleLabel::In : PoleLabel::Out;
    else if (opp != PoleLabel::Unknown) label = flip(opp);
    else if (in_deep) label = *w_in > *w_out ? PoleLabel::In : PoleLabel::Out;
    poles[p].label = label;
  }
}

// Unknown poles copy the label of their most deeply intersecting labeled neighbour (or the
// flip of their opposite poles' common label), sweeping until nothing changes.
std::size_t resolve_unknown(std::vector<Pole>& poles, const OppositeLists& o, const PoleGraph& g) {
  std::size_t resolved = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t p = 0; p < poles.size(); ++p) {
      if (poles[p].label != PoleLabel::Unknown) continue;
      PoleLabel best = PoleLabel::Unknown;
      double best_w = 0;
      for (std::size_t k = g.offsets[p]; k < g.offsets[p + 1]; ++k) {
        const PoleLabel l = poles[g.neighbours[k]].label;
        if (l == PoleLabel::Unknown) continue;
        const double pq = intersection_weight(poles[p], poles[g.neighbours[k]]);
        if (best == PoleLabel::Unknown || pq > best_w) best = l, best_w = pq;
      }
      if (best == PoleLabel::Unknown) {
        const PoleLabel opp = opposite_label(poles, o, p);
        if (opp != PoleLabel::Unknown) best = flip(opp);
      }
      if (best == PoleLabel::Unknown) continue;
      poles[p].label = best;
      ++resolved;
      changed = true;
    }
  }
  return resolved;
}

}  // namespace

LabelingReport label_poles(std::vector<Pole>& poles, const std::vector<SamplePoles>& sample_poles,
                           const PoleGraph& graph, const Thresholds& thresholds,
                           const CGAL::Bbox_3& sample_bbox, bool resolve, const std::vector<bool>& deferred) {
  const OppositeLists opposite = opposite_lists(poles.size(), sample_poles);
  for (auto& p : poles) p.label = PoleLabel::Unknown;
  {
    Labeler labeler(poles, opposite, graph, thresholds.neighbor, deferred);
    labeler.seed_outside(sample_bbox);
    labeler.propagate_all();
  }
  second_pass(poles, opposite, graph, thresholds.second_pass);
  LabelingReport report;
  report.unknown_after_second_pass = static_cast<std::size_t>(
      std::count_if(poles.begin(), poles.end(), [](const Pole& p) { return p.label == PoleLabel::Unknown; }));
  if (resolve && report.unknown_after_second_pass > 0)
    report.resolved = resolve_unknown(poles, opposite, graph);
  return report;
}

}  // namespace envcrust::powercrust
