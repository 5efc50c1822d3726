// NeighbourTable: every point's k nearest others from one kd-tree, searched in parallel.
#include "envcrust/neighbour_table.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <string>

namespace envcrust {
namespace {

// Search the k nearest others in `index` (over `points`) of the points `rows`, queried in
// the order given, and write them to `ids` (k per row) under the numbering `number` gives
// (an index of `points` -> the table's).
template <class Numbering>
void search_rows(const std::vector<Point3>& points, const NearestIndex& index, unsigned k,
                 const std::vector<std::size_t>& rows, const Numbering& number, std::vector<std::uint32_t>& ids) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const std::size_t i = rows[r];
      std::uint32_t* row = &ids[number(i) * k];
      unsigned found = 0;
      // k + 1: the point itself comes back among them, unless k + 1 duplicates of it do.
      for (const auto& [j, d] : index.nearest(points[i], k + 1)) {
        if (j != i && found < k) row[found++] = static_cast<std::uint32_t>(number(j));
      }
    }
  });
}

}  // namespace

NeighbourTable::NeighbourTable(const std::vector<Point3>& points, unsigned k) {
  if (k == 0) throw InvalidOptions("neighbour table: k must be >= 1 (got 0)");
  if (points.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw InvalidInput("neighbour table: more than 2^32 - 1 points (" + std::to_string(points.size()) + ")");
  }
  order_ = mesh::hilbert_order(points);
  k_ = static_cast<unsigned>(std::min<std::size_t>(k, points.empty() ? 0 : points.size() - 1));
  ids_.assign(points.size() * k_, 0);
  if (k_ == 0) return;
  // The tree over a copy in Hilbert order: its leaves hold nearby points in nearby memory.
  std::vector<Point3> sorted(points.size());
  for (std::size_t r = 0; r < points.size(); ++r) sorted[r] = points[order_[r]];
  const NearestIndex index(sorted);
  std::vector<std::size_t> rows(points.size());
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = r;
  search_rows(sorted, index, k_, rows, [&](std::size_t r) { return order_[r]; }, ids_);
}

NeighbourTable NeighbourTable::subset(const std::vector<Point3>& points, const std::vector<char>& keep) const {
  if (points.size() != size() || keep.size() != size()) {
    throw InvalidInput("neighbour table: subset of " + std::to_string(points.size()) + " points with " +
                       std::to_string(keep.size()) + " flags, table of " + std::to_string(size()) + " rows");
  }
  constexpr std::uint32_t kGone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> renumber(size(), kGone);
  std::vector<Point3> kept;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!keep[i]) continue;
    renumber[i] = static_cast<std::uint32_t>(kept.size());
    kept.push_back(points[i]);
  }
  NeighbourTable out;
  out.k_ = static_cast<unsigned>(std::min<std::size_t>(k_, kept.empty() ? 0 : kept.size() - 1));
  out.order_.reserve(kept.size());
  for (const std::size_t i : order_)
    if (keep[i]) out.order_.push_back(renumber[i]);
  out.ids_.assign(kept.size() * out.k_, 0);
  if (out.k_ == 0) return out;
  std::vector<std::size_t> again;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!keep[i]) continue;
    const std::size_t row = renumber[i];
    bool whole = out.k_ == k_;
    for (unsigned a = 0; whole && a < k_; ++a) whole = renumber[ids_[i * k_ + a]] != kGone;
    if (!whole) {
      again.push_back(row);
      continue;
    }
    for (unsigned a = 0; a < k_; ++a) out.ids_[row * k_ + a] = renumber[ids_[i * k_ + a]];
  }
  if (!again.empty()) {
    const NearestIndex index(kept);
    search_rows(kept, index, out.k_, again, [](std::size_t i) { return i; }, out.ids_);
  }
  return out;
}

}  // namespace envcrust
