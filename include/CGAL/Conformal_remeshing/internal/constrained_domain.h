// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces of a constrained triangulation inside the polygons its constraints bound, and
// points of a square grid added inside them: shared by the welding (the annulus and hole fills)
// and the quality measures (a well-shaped cover of flat regions).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_CONSTRAINED_DOMAIN_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_CONSTRAINED_DOMAIN_H

#include <CGAL/Bbox_2.h>
#include <CGAL/squared_distance_2.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

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

/// The points of a square grid of side `spacing` that lie inside a face of the domain of `cdt`
/// (faces marked by `mark_constraint_depth()`), row by row, each with the face holding it
/// (valid until `cdt` changes). None when the grid over the triangulation's bounding box would
/// have more than `largest_grid` points.
template <typename CDT>
std::vector<std::pair<typename CDT::Point, typename CDT::Face_handle> >
grid_points_inside(const CDT& cdt, double spacing, double largest_grid = 4e6)
{
  typedef typename CDT::Point Point;
  std::vector<std::pair<Point, typename CDT::Face_handle> > inside;
  CGAL::Bbox_2 box;
  for(auto v : cdt.finite_vertex_handles())
    box += v->point().bbox();
  if(!(spacing > 0.) || cdt.number_of_vertices() == 0
     || ((box.xmax() - box.xmin()) / spacing + 1.) * ((box.ymax() - box.ymin()) / spacing + 1.) > largest_grid)
    return inside;
  typename CDT::Face_handle hint;
  for(double y = box.ymin() + 0.5 * spacing; y < box.ymax(); y += spacing)
    for(double x = box.xmin() + 0.5 * spacing; x < box.xmax(); x += spacing)
    {
      const Point p(x, y);
      typename CDT::Locate_type type;
      int i = 0;
      const typename CDT::Face_handle f = cdt.locate(p, type, i, hint);
      hint = f;
      if(type == CDT::FACE && f->info() % 2 == 1)
        inside.emplace_back(p, f);
    }
  return inside;
}

/// Inserts `points` (inside the domain of `cdt`, as `grid_points_inside()` gives them) and
/// removes again those nearer than a third of `spacing` to a constraint: a grid point next to a
/// boundary would make a sliver with it. Returns the vertex of each point, a default handle for
/// the removed ones; new vertices get `info()` -1, faces are marked again.
template <typename CDT, typename Point_range>
std::vector<typename CDT::Vertex_handle> insert_away_from_constraints(CDT& cdt, const Point_range& points, double spacing)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  std::vector<Vertex_handle> vertex;
  if(points.empty())
    return vertex;
  vertex.reserve(points.size());
  for(const auto& p : points) // each next to the one before: a short walk
  {
    vertex.push_back(vertex.empty() ? cdt.insert(p) : cdt.insert(p, vertex.back()->face()));
    vertex.back()->info() = -1;
  }
  const double nearest = spacing * spacing / 9.;
  std::vector<char> near_boundary(vertex.size(), 0);
  for(std::size_t k = 0; k < vertex.size(); ++k)
  {
    auto f = cdt.incident_faces(vertex[k]), done = f;
    do
    {
      const int i = f->index(vertex[k]);
      if(cdt.is_constrained(typename CDT::Edge(f, i))
         && CGAL::squared_distance(vertex[k]->point(),
                                   typename CDT::Geom_traits::Segment_2(f->vertex(CDT::cw(i))->point(), f->vertex(CDT::ccw(i))->point())) < nearest)
        near_boundary[k] = 1;
    } while(++f != done && !near_boundary[k]);
  }
  for(std::size_t k = 0; k < vertex.size(); ++k)
    if(near_boundary[k])
    {
      cdt.remove(vertex[k]);
      vertex[k] = Vertex_handle();
    }
  mark_constraint_depth(cdt);
  return vertex;
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_CONSTRAINED_DOMAIN_H
