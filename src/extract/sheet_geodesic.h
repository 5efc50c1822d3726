// Distances along the edges of the sheet: the balls and bands that the topology cuts remove.
#pragma once

#include "envcrust/mesh_graph.h"
#include "envcrust/types.h"

#include <limits>
#include <span>
#include <vector>

namespace envcrust::extract {

/// Each vertex's neighbours with the edge lengths, and its faces (compressed rows).
struct MeshAdjacency {
  std::vector<std::size_t> neighbour_begin;
  std::vector<std::pair<Index, double>> neighbours;
  std::vector<std::size_t> face_begin;
  std::vector<std::uint32_t> faces;
};

MeshAdjacency mesh_adjacency(const TriangleMesh& mesh, const topology::MeshGraph& graph);

/// The vertices within a radius of some sources, along mesh edges (Dijkstra), with their
/// distances. Reusable: each grow() clears only what the last one reached.
class GeodesicBall {
 public:
  explicit GeodesicBall(std::size_t vertices)
      : distance_(vertices, std::numeric_limits<double>::infinity()) {}

  void grow(const MeshAdjacency& adjacency, std::span<const Index> sources, double radius);

  /// Distance of v from the nearest source; infinity when farther than the radius.
  [[nodiscard]] double distance(Index v) const { return distance_[v]; }
  [[nodiscard]] bool contains(Index v) const { return distance_[v] != std::numeric_limits<double>::infinity(); }
  /// The vertices reached, in the order they were first reached.
  [[nodiscard]] const std::vector<Index>& reached() const { return reached_; }

 private:
  std::vector<double> distance_;
  std::vector<Index> reached_;
};

}  // namespace envcrust::extract
