// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest ways over a graph out to a bounded length (Dijkstra), for the searches that tell
// another part of a surface or of its curves from the near part of the same one.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_SHORTEST_WAYS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_SHORTEST_WAYS_H

#include <cstddef>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

/// The lengths of the shortest ways from `source` to the vertices they reach within `reach`, by
/// vertex index. `for_each_step(v, step)` calls `step(w, length)` for each vertex `w` one step
/// from `v`, with the length of that step (0 is allowed).
template <typename Vertex, typename For_each_step>
std::unordered_map<std::size_t, double> shortest_ways_within(Vertex source, double reach, const For_each_step& for_each_step)
{
  std::unordered_map<std::size_t, double> way{{std::size_t(source), 0.}};
  typedef std::pair<double, Vertex> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  queue.emplace(0., source);
  while(!queue.empty())
  {
    const Entry top = queue.top();
    queue.pop();
    if(top.first > way[std::size_t(top.second)])
      continue; // reached by a shorter way since
    for_each_step(top.second, [&](Vertex w, double step) {
      const double length = top.first + step;
      if(length > reach)
        return;
      const auto inserted = way.emplace(std::size_t(w), length);
      if(!inserted.second)
      {
        if(!(length < inserted.first->second))
          return;
        inserted.first->second = length;
      }
      queue.emplace(length, w);
    });
  }
  return way;
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_SHORTEST_WAYS_H
