// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces of a constrained triangulation inside the polygons its constraints bound.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_CONSTRAINED_DOMAIN_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_CONSTRAINED_DOMAIN_H

#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

/// Sets the `info()` of every face of `cdt` (an `int`) to the number of constraints crossed on
/// the way from the infinite face: a face is inside the domain when that number is odd (holes
/// included, as nested polygons).
template <typename CDT>
void mark_constraint_depth(CDT& cdt)
{
  for(auto f : cdt.all_face_handles())
    f->info() = -1;
  std::vector<typename CDT::Face_handle> level{cdt.infinite_face()}, next;
  cdt.infinite_face()->info() = 0;
  for(int depth = 0; !level.empty(); ++depth, std::swap(level, next))
    for(next.clear(); !level.empty();)
    {
      const typename CDT::Face_handle f = level.back();
      level.pop_back();
      for(int i = 0; i < 3; ++i)
        if(f->neighbor(i)->info() < 0)
        {
          const bool crossing = cdt.is_constrained(typename CDT::Edge(f, i));
          f->neighbor(i)->info() = crossing ? depth + 1 : depth;
          (crossing ? next : level).push_back(f->neighbor(i));
        }
    }
}

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_CONSTRAINED_DOMAIN_H
