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
  // The half-edges ordered by their undirected edge (smaller vertex, larger vertex, then the
  // half-edge): twins become adjacent. A counting sort by the smaller vertex, the indices being
  // dense, then a sort of each vertex's few: a sort of all of them took a third of building the
  // point location of a flattened CAD part.
  std::uint32_t vertices = 0;
  for(const auto& t : triangles)
    for(int v : t)
      vertices = (std::max)(vertices, std::uint32_t(v) + 1);
  // the ends of half-edge h, smaller first (by value: std::minmax's references would dangle)
  auto ends = [&](std::uint32_t h) -> std::pair<std::uint32_t, std::uint32_t> {
    const std::uint32_t a = std::uint32_t(corner(h, 1)), b = std::uint32_t(corner(h, 2));
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  };
  std::vector<std::uint32_t> start(std::size_t(vertices) + 1, 0);
  for(std::uint32_t h = 0; h < 3 * nt; ++h)
    ++start[std::size_t(ends(h).first) + 1];
  for(std::size_t v = 1; v < start.size(); ++v)
    start[v] += start[v - 1];
  std::vector<std::pair<std::uint32_t, std::uint32_t> > half_edges(3 * nt); // larger vertex, half-edge
  {
    std::vector<std::uint32_t> filled(start.begin(), start.end() - 1);
    for(std::uint32_t h = 0; h < 3 * nt; ++h)
    {
      const std::pair<std::uint32_t, std::uint32_t> e = ends(h);
      half_edges[filled[e.first]++] = std::make_pair(e.second, h);
    }
  }
  for(std::uint32_t a = 0; a < vertices; ++a)
  {
    const auto first = half_edges.begin() + std::ptrdiff_t(start[a]), last = half_edges.begin() + std::ptrdiff_t(start[a + 1]);
    std::sort(first, last);
    for(auto i = first; i != last;)
    {
      auto j = i + 1;
      while(j != last && j->first == i->first)
        ++j;
      if(j - i > 2)
        return false;
      const std::uint32_t h = i->second;
      if(j - i == 2)
      {
        const std::uint32_t g = (i + 1)->second;
        if(corner(h, 1) == corner(g, 1))
          return false;
        neighbor[h / 3][h % 3] = int(g / 3);
        neighbor[g / 3][g % 3] = int(h / 3);
      }
      visit_edge(int(a), int(i->first), j - i == 2);
      i = j;
    }
  }
  return true;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TRIANGLE_ADJACENCY_H
