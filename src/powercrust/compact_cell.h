// A 64-byte cell for CGAL's 3D triangulation data structure: CGAL's own
// (Triangulation_ds_cell_base_3) holds 4 neighbours, 4 vertices and a 1-byte conflict flag,
// padded to 72 bytes. Here the flag's two bits live in the low bits of the first vertex
// pointer (vertices hold doubles, so their addresses are multiples of 8). An exact torus of
// 1M samples has 20M Delaunay cells: 160 MB less.
//
// It models CGAL's TriangulationDSCellBase_3 concept; the TDS reads the flag only through
// tds_data().clear() / mark_*() / is_*() / processed(), which ConflictFlag provides.
#pragma once

#include <CGAL/TDS_3/internal/Dummy_tds_3.h>

#include <cstdint>

namespace envcrust::powercrust {

template <typename TDS = void>
class CompactCell {
 public:
  using Triangulation_data_structure = TDS;
  using Vertex_handle = typename TDS::Vertex_handle;
  using Cell_handle = typename TDS::Cell_handle;
  using Vertex = typename TDS::Vertex;
  using Cell = typename TDS::Cell;

  template <typename TDS2>
  struct Rebind_TDS {
    using Other = CompactCell<TDS2>;
  };

  /// The TDS's per-cell conflict state, read and written in place in the tagged word.
  class ConflictFlag {
   public:
    explicit ConflictFlag(std::uintptr_t* word) : word_(word) {}
    void clear() { set(0); }
    void mark_in_conflict() { set(1); }
    void mark_on_boundary() { set(2); }
    void mark_processed() { set(1); }
    [[nodiscard]] bool is_clear() const { return state() == 0; }
    [[nodiscard]] bool is_in_conflict() const { return state() == 1; }
    [[nodiscard]] bool is_on_boundary() const { return state() == 2; }
    [[nodiscard]] bool processed() const { return state() == 1; }

   private:
    [[nodiscard]] std::uintptr_t state() const { return *word_ & kFlagBits; }
    void set(std::uintptr_t s) { *word_ = (*word_ & ~kFlagBits) | s; }
    std::uintptr_t* word_;
  };
  using TDS_data = ConflictFlag;

  CompactCell() = default;
  CompactCell(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3) {
    set_vertices(v0, v1, v2, v3);
  }
  CompactCell(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3, Cell_handle n0,
              Cell_handle n1, Cell_handle n2, Cell_handle n3)
      : n_{n0, n1, n2, n3} {
    set_vertices(v0, v1, v2, v3);
  }

  Vertex_handle vertex(int i) const { return Vertex_handle(reinterpret_cast<Vertex*>(v_[i] & ~kFlagBits)); }
  bool has_vertex(Vertex_handle v) const {
    return vertex(0) == v || vertex(1) == v || vertex(2) == v || vertex(3) == v;
  }
  bool has_vertex(Vertex_handle v, int& i) const {
    for (i = 0; i < 4; ++i)
      if (vertex(i) == v) return true;
    return false;
  }
  int index(Vertex_handle v) const {
    for (int i = 0; i < 3; ++i)
      if (vertex(i) == v) return i;
    return 3;
  }

  Cell_handle neighbor(int i) const { return n_[i]; }
  bool has_neighbor(Cell_handle n) const { return n_[0] == n || n_[1] == n || n_[2] == n || n_[3] == n; }
  bool has_neighbor(Cell_handle n, int& i) const {
    for (i = 0; i < 4; ++i)
      if (n_[i] == n) return true;
    return false;
  }
  int index(Cell_handle n) const {
    for (int i = 0; i < 3; ++i)
      if (n_[i] == n) return i;
    return 3;
  }

  void set_vertex(int i, Vertex_handle v) {
    static_assert(alignof(Vertex) >= 4, "vertex addresses must leave two low bits free");
    v_[i] = (v_[i] & kFlagBits) | address(v);
  }
  void set_vertices() {
    for (int i = 0; i < 4; ++i) set_vertex(i, Vertex_handle());
  }
  void set_vertices(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3) {
    set_vertex(0, v0);
    set_vertex(1, v1);
    set_vertex(2, v2);
    set_vertex(3, v3);
  }
  void set_neighbor(int i, Cell_handle n) { n_[i] = n; }
  void set_neighbors() { n_[0] = n_[1] = n_[2] = n_[3] = Cell_handle(); }
  void set_neighbors(Cell_handle n0, Cell_handle n1, Cell_handle n2, Cell_handle n3) {
    n_[0] = n0;
    n_[1] = n1;
    n_[2] = n2;
    n_[3] = n3;
  }

  bool is_valid(bool = false, int = 0) const { return true; }

  // For CGAL's Compact_container, which keeps its own tag bits in this pointer's low bits
  // while the cell is free (as CGAL's cell base does).
  void* for_compact_container() const { return n_[0].for_compact_container(); }
  void for_compact_container(void* p) { n_[0].for_compact_container(p); }

  // The flag sits in v_[0], whose vertex bits set_vertex keeps apart.
  TDS_data tds_data() { return TDS_data(&v_[0]); }
  TDS_data tds_data() const { return TDS_data(const_cast<std::uintptr_t*>(&v_[0])); }

 private:
  static constexpr std::uintptr_t kFlagBits = 3;
  static std::uintptr_t address(Vertex_handle v) {
    return v == Vertex_handle() ? 0 : reinterpret_cast<std::uintptr_t>(&*v);
  }

  Cell_handle n_[4];
  std::uintptr_t v_[4] = {0, 0, 0, 0};
};

/// The rebinding stub, as CGAL's cell bases have it.
template <>
class CompactCell<void> {
 public:
  using Triangulation_data_structure = CGAL::internal::Dummy_tds_3;
  using Vertex_handle = Triangulation_data_structure::Vertex_handle;
  using Cell_handle = Triangulation_data_structure::Cell_handle;
  template <typename TDS2>
  struct Rebind_TDS {
    using Other = CompactCell<TDS2>;
  };
};

}  // namespace envcrust::powercrust
