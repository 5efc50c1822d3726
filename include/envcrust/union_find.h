// Disjoint-set forest with path halving and union by size.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace envcrust::topology {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) { reset(n); }
  /// Start over with n singletons (the storage is reused: for many small forests in a row).
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
    size_.assign(n, 1);
  }
  std::uint32_t find(std::uint32_t x);
  void unite(std::uint32_t a, std::uint32_t b);
  /// Number the sets 0, 1, ... in order of their first element; `label[x]` gets x's set.
  /// @returns the number of sets.
  std::uint32_t label_sets(std::vector<std::uint32_t>& label);

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> size_;
};

}  // namespace envcrust::topology
