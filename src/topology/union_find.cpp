// Disjoint-set forest used for components and vertex fans.
#include "envcrust/union_find.h"

#include <utility>

namespace envcrust::topology {

std::uint32_t UnionFind::find(std::uint32_t x) {
  while (parent_[x] != x) {
    parent_[x] = parent_[parent_[x]];
    x = parent_[x];
  }
  return x;
}

void UnionFind::unite(std::uint32_t a, std::uint32_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  if (size_[a] < size_[b]) std::swap(a, b);
  parent_[b] = a;
  size_[a] += size_[b];
}

std::uint32_t UnionFind::label_sets(std::vector<std::uint32_t>& label) {
  const auto n = static_cast<std::uint32_t>(parent_.size());
  label.assign(n, 0);
  std::vector<std::uint32_t> id_of_root(n, UINT32_MAX);
  std::uint32_t count = 0;
  for (std::uint32_t x = 0; x < n; ++x) {
    const std::uint32_t r = find(x);
    if (id_of_root[r] == UINT32_MAX) id_of_root[r] = count++;
    label[x] = id_of_root[r];
  }
  return count;
}

}  // namespace envcrust::topology
