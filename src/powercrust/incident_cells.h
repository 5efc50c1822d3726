// The cells around a vertex of a 3D triangulation, for many vertices from many threads.
#pragma once

#include <cstdint>
#include <vector>

namespace envcrust::powercrust {

/// Collects the cells incident to a vertex by a walk over cell neighbours, like CGAL's
/// incident_cells_threadsafe, but remembers visited cells in a reused open-addressing table
/// instead of a fresh node-based hash set per call (a heap allocation per cell: on an exact
/// torus, where a sample has ~64 incident cells, those allocations were the largest cost of
/// the per-vertex passes). One object per thread; the triangulation must be read-only.
template <class Triangulation>
class IncidentCells {
 public:
  using Cell = typename Triangulation::Cell_handle;
  using Vertex = typename Triangulation::Vertex_handle;

  /// The finite and infinite cells incident to v, in walk order (valid until the next call).
  const std::vector<Cell>& operator()(Vertex v) {
    cells_.clear();
    next_generation();
    const Cell start = v->cell();
    insert(start);
    cells_.push_back(start);
    for (std::size_t head = 0; head < cells_.size(); ++head) {
      const Cell c = cells_[head];
      for (int i = 0; i < 4; ++i) {
        if (c->vertex(i) == v) continue;
        const Cell next = c->neighbor(i);
        if (insert(next)) cells_.push_back(next);
      }
    }
    return cells_;
  }

 private:
  struct Slot {
    const void* cell = nullptr;
    std::uint32_t generation = 0;
  };

  void next_generation() {
    if (++generation_ == 0) {  // wrapped: old marks could read as current
      for (auto& s : slots_) s = Slot{};
      generation_ = 1;
    }
  }

  static std::size_t hash(const void* p) {
    return static_cast<std::size_t>((reinterpret_cast<std::uintptr_t>(p) >> 4) * 0x9e3779b97f4a7c15ULL >> 20);
  }

  // True when c was not yet visited in this generation.
  bool insert(Cell c) {
    if (2 * (cells_.size() + 1) > slots_.size()) grow();
    const void* key = &*c;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash(key) & mask;; i = (i + 1) & mask) {
      Slot& s = slots_[i];
      if (s.generation != generation_) {
        s = {key, generation_};
        return true;
      }
      if (s.cell == key) return false;
    }
  }

  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 256 : 2 * old.size(), Slot{});
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& s : old) {
      if (s.generation != generation_) continue;
      std::size_t i = hash(s.cell) & mask;
      while (slots_[i].generation == generation_) i = (i + 1) & mask;
      slots_[i] = s;
    }
  }

  std::vector<Cell> cells_;
  std::vector<Slot> slots_;
  std::uint32_t generation_ = 0;
};

}  // namespace envcrust::powercrust
