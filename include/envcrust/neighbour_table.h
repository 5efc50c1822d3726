// The k nearest other points of every point of a set, searched once and shared by the stages
// that each asked a kd-tree for them (stray samples, normal lines, the boundary's angle gaps).
#pragma once

#include "envcrust/types.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace envcrust {

/// Per point, the indices of its k nearest other points, nearest first. The search runs once,
/// in parallel, along a Hilbert curve (mesh::hilbert_order); each row is the kd-tree's answer
/// for that point alone, so the table does not depend on the threads. Loops over the rows in
/// `order()` read the same points one row after another (they stay in the cache).
/// 1M points, k 32: 128 MB.
class NeighbourTable {
 public:
  NeighbourTable() = default;
  /// Rows of min(k, points.size() - 1) neighbours. @throws InvalidOptions if k is 0.
  NeighbourTable(const std::vector<Point3>& points, unsigned k);

  /// Neighbours per row.
  [[nodiscard]] unsigned k() const { return k_; }
  /// Number of rows (points).
  [[nodiscard]] std::size_t size() const { return order_.size(); }
  /// The neighbours of point i, nearest first, i itself left out (a duplicate of i is not).
  [[nodiscard]] std::span<const std::uint32_t> of(std::size_t i) const {
    return {ids_.data() + i * k_, k_};
  }
  /// The rows' Hilbert order: loops over the points in it stay in one part of space.
  [[nodiscard]] const std::vector<std::size_t>& order() const { return order_; }

  /// The table of the points with keep[i] != 0, numbered in their order: `points` are the
  /// points this table was built on. Rows that lost a neighbour are searched again among the
  /// kept points; the others are renumbered. @throws InvalidInput if the sizes differ.
  [[nodiscard]] NeighbourTable subset(const std::vector<Point3>& points, const std::vector<char>& keep) const;

 private:
  unsigned k_ = 0;
  std::vector<std::uint32_t> ids_;     // size() * k_
  std::vector<std::size_t> order_;
};

}  // namespace envcrust
