// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adjacency of indexed triangles, shared by the planar point location (its walks) and the
// surface optimization (its flips).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TRIANGLE_ADJACENCY_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TRIANGLE_ADJACENCY_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// Fills `neighbor[t][k]` with the triangle across the edge opposite corner `k` of triangle `t`
/// (-1 on the boundary) and calls `visit_edge(a, b, interior)` once per undirected edge. False,
/// with `neighbor` incomplete, if an edge has more than two triangles or two that run it the
/// same way (inconsistent orientation).
template <typename Edge_visitor>
bool link_triangles(const std::vector<std::array<int, 3> >& triangles, std::vector<std::array<int, 3> >& neighbor,
                    const Edge_visitor& visit_edge)
{
  const std::size_t nt = triangles.size();
  neighbor.assign(nt, {{-1, -1, -1}});
  auto corner = [&](std::uint32_t h, int shift) { return triangles[h / 3][(h % 3 + shift) % 3]; };
  // Sort the half-edges by their undirected edge: twins become adjacent.
  std::vector<std::pair<std::uint64_t, std::uint32_t> > half_edges;
  half_edges.reserve(3 * nt);
  for(std::size_t t = 0; t < nt; ++t)
    for(std::uint32_t k = 0; k < 3; ++k)
    {
      const std::uint32_t h = std::uint32_t(3 * t) + k;
      const std::uint64_t a = std::uint64_t(corner(h, 1)), b = std::uint64_t(corner(h, 2));
      half_edges.emplace_back((std::min)(a, b) << 32 | (std::max)(a, b), h);
    }
  std::sort(half_edges.begin(), half_edges.end());
  for(std::size_t i = 0; i < half_edges.size();)
  {
    std::size_t j = i + 1;
    while(j < half_edges.size() && half_edges[j].first == half_edges[i].first)
      ++j;
    if(j - i > 2)
      return false;
    const std::uint32_t h = half_edges[i].second;
    if(j - i == 2)
    {
      const std::uint32_t g = half_edges[i + 1].second;
      if(corner(h, 1) == corner(g, 1))
        return false;
      neighbor[h / 3][h % 3] = int(g / 3);
      neighbor[g / 3][g % 3] = int(h / 3);
    }
    visit_edge(int(half_edges[i].first >> 32), int(half_edges[i].first & 0xffffffffu), j - i == 2);
    i = j;
  }
  return true;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TRIANGLE_ADJACENCY_H
