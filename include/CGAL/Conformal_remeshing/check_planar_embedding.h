// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Is a planar triangulation (a parameterization, a flattened patch) an embedding? Decided with
// exact predicates only.

#ifndef CGAL_CONFORMAL_REMESHING_CHECK_PLANAR_EMBEDDING_H
#define CGAL_CONFORMAL_REMESHING_CHECK_PLANAR_EMBEDDING_H

#include <CGAL/Box_intersection_d/Box_with_handle_d.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// What `check_planar_embedding()` found. The triangulation is an embedding when every count
/// is zero: then every triangle is positively oriented, no two triangles overlap, the boundary
/// polygons are simple and pairwise disjoint, and every hole lies inside the outer polygon.
struct Planar_embedding_report
{
  std::size_t number_of_faces = 0;
  /// triangles whose orientation is not positive (folded, or degenerate to a segment or point)
  std::size_t non_positive_faces = 0;
  /// pairs of triangles whose interiors overlap (computed only when asked for)
  std::size_t overlapping_face_pairs = 0;
  /// pairs of boundary segments that meet where they should not (crossings, touching,
  /// consecutive segments folding back onto each other)
  std::size_t boundary_intersections = 0;
  /// hole polygons that are not inside the outer polygon, or that lie inside another hole
  std::size_t misplaced_holes = 0;
  /// points with an infinite or NaN coordinate (then nothing else is checked)
  std::size_t non_finite_points = 0;

  bool is_embedding() const
  {
    return non_finite_points == 0 && non_positive_faces == 0 && overlapping_face_pairs == 0 && boundary_intersections == 0 && misplaced_holes == 0;
  }

  /// "embedding", or the failures in one line
  std::string summary() const
  {
    if(is_embedding())
      return "embedding";
    std::ostringstream out;
    const char* separator = "";
    auto item = [&](std::size_t n, const char* what) {
      if(n > 0)
      {
        out << separator << n << " " << what;
        separator = ", ";
      }
    };
    item(non_finite_points, "points with non-finite coordinates");
    item(non_positive_faces, "folded or degenerate triangles");
    item(overlapping_face_pairs, "overlapping triangle pairs");
    item(boundary_intersections, "boundary self-intersections");
    item(misplaced_holes, "holes outside the outer boundary or inside another hole");
    return out.str();
  }
};

namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Embedding_kernel;
typedef Embedding_kernel::Point_2 Embedding_point;

// Pairs of triangles whose interiors overlap: candidates by bounding boxes, then the separating
// axis test with exact orientation predicates. Two convex polygons have disjoint interiors
// exactly when the line of an edge of one leaves the other on its closed outer side. (No
// constructions: CGAL's exact triangle-triangle intersection trips an assertion of its interval
// filter on some nearly degenerate pairs.)
inline std::size_t count_overlapping_triangle_pairs(const std::vector<Embedding_point>& uv,
                                                    const std::vector<std::array<std::size_t, 3> >& faces)
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  std::vector<Box> boxes;
  boxes.reserve(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const CGAL::Bbox_2 b = uv[faces[f][0]].bbox() + uv[faces[f][1]].bbox() + uv[faces[f][2]].bbox();
    boxes.push_back(Box(b, f));
  }
  // `true` if an edge line of face `f` has every corner of face `g` on its closed outer side.
  auto edge_of_separates = [&](std::size_t f, CGAL::Orientation inside, std::size_t g) {
    for(int i = 0; i < 3; ++i)
    {
      const Embedding_point &p = uv[faces[f][i]], &q = uv[faces[f][(i + 1) % 3]];
      bool all_outside = true;
      for(int j = 0; j < 3 && all_outside; ++j)
        all_outside = CGAL::orientation(p, q, uv[faces[g][j]]) != inside;
      if(all_outside)
        return true;
    }
    return false;
  };
  std::size_t overlaps = 0;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const std::size_t f = a.info(), g = b.info();
    const CGAL::Orientation of = CGAL::orientation(uv[faces[f][0]], uv[faces[f][1]], uv[faces[f][2]]),
                            og = CGAL::orientation(uv[faces[g][0]], uv[faces[g][1]], uv[faces[g][2]]);
    if(of == CGAL::COLLINEAR || og == CGAL::COLLINEAR)
      return; // already counted as non-positive
    if(!edge_of_separates(f, of, g) && !edge_of_separates(g, og, f))
      ++overlaps;
  });
  return overlaps;
}

// Pairs of boundary segments that meet where they should not.
inline std::size_t count_boundary_intersections(const std::vector<Embedding_point>& uv,
                                                const std::vector<std::vector<std::size_t> >& loops)
{
  struct Segment_ref { std::size_t loop, index; };
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, Segment_ref> Box;
  std::vector<Box> boxes;
  for(std::size_t l = 0; l < loops.size(); ++l)
    for(std::size_t i = 0; i < loops[l].size(); ++i)
    {
      const std::size_t a = loops[l][i], b = loops[l][(i + 1) % loops[l].size()];
      boxes.push_back(Box(uv[a].bbox() + uv[b].bbox(), Segment_ref{l, i}));
    }

  const Embedding_kernel kernel;
  std::size_t intersections = 0;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const std::vector<std::size_t>& lx = loops[x.info().loop];
    const std::vector<std::size_t>& ly = loops[y.info().loop];
    const std::size_t p = lx[x.info().index], q = lx[(x.info().index + 1) % lx.size()];
    const std::size_t r = ly[y.info().index], s = ly[(y.info().index + 1) % ly.size()];
    // Consecutive segments share one vertex: they may only meet there, so they fold onto each
    // other exactly when they are collinear and leave the shared vertex in the same direction.
    std::size_t shared = 0, other_x = 0, other_y = 0;
    const bool consecutive = (q == r) || (p == s);
    if(consecutive && !(q == r && p == s))
    {
      shared = (q == r) ? q : p;
      other_x = (q == r) ? p : q;
      other_y = (q == r) ? s : r;
      if(CGAL::orientation(uv[shared], uv[other_x], uv[other_y]) == CGAL::COLLINEAR
         && CGAL::angle(uv[other_x], uv[shared], uv[other_y]) == CGAL::ACUTE)
        ++intersections;
      return;
    }
    if(kernel.do_intersect_2_object()(Embedding_kernel::Segment_2(uv[p], uv[q]), Embedding_kernel::Segment_2(uv[r], uv[s])))
      ++intersections;
  });
  return intersections;
}

inline std::vector<Embedding_point> loop_polygon(const std::vector<Embedding_point>& uv, const std::vector<std::size_t>& loop)
{
  std::vector<Embedding_point> polygon;
  polygon.reserve(loop.size());
  for(std::size_t v : loop)
    polygon.push_back(uv[v]);
  return polygon;
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Checks with exact predicates whether a planar triangulation is an embedding.
///
/// \param uv the planar position of every vertex
/// \param faces the triangles, as indices into `uv`; a positive orientation is expected
/// \param boundary_loops the boundary polygons as vertex index cycles: the outer boundary first,
///        then the holes (any orientation)
/// \param count_overlaps also count the pairs of triangles whose interiors overlap (exact
///        constructions on candidate pairs: slower, and not needed to decide that a
///        triangulation with positive triangles and simple, nested boundaries is an embedding)
inline Planar_embedding_report
check_planar_embedding(const std::vector<Epick::Point_2>& uv,
                       const std::vector<std::array<std::size_t, 3> >& faces,
                       const std::vector<std::vector<std::size_t> >& boundary_loops,
                       bool count_overlaps = false)
{
  Planar_embedding_report report;
  report.number_of_faces = faces.size();
  // Exact predicates cannot take NaN or infinity (GMP aborts on them).
  for(const Epick::Point_2& p : uv)
    report.non_finite_points += !(std::isfinite(p.x()) && std::isfinite(p.y()));
  if(report.non_finite_points > 0)
    return report;
  for(const auto& f : faces)
    if(CGAL::orientation(uv[f[0]], uv[f[1]], uv[f[2]]) != CGAL::POSITIVE)
      ++report.non_positive_faces;
  if(count_overlaps)
    report.overlapping_face_pairs = internal::count_overlapping_triangle_pairs(uv, faces);
  report.boundary_intersections = internal::count_boundary_intersections(uv, boundary_loops);

  // With simple, disjoint boundaries, one vertex of a hole tells on which side the hole lies.
  if(!boundary_loops.empty() && report.boundary_intersections == 0)
  {
    std::vector<std::vector<Epick::Point_2> > polygons;
    for(const auto& loop : boundary_loops)
      polygons.push_back(internal::loop_polygon(uv, loop));
    for(std::size_t h = 1; h < polygons.size(); ++h)
    {
      const Epick::Point_2& probe = polygons[h].front();
      bool misplaced = CGAL::bounded_side_2(polygons[0].begin(), polygons[0].end(), probe) != CGAL::ON_BOUNDED_SIDE;
      for(std::size_t other = 1; other < polygons.size() && !misplaced; ++other)
        misplaced = other != h
                    && CGAL::bounded_side_2(polygons[other].begin(), polygons[other].end(), probe) == CGAL::ON_BOUNDED_SIDE;
      if(misplaced)
        ++report.misplaced_holes;
    }
  }
  return report;
}

/// \ingroup PkgConformalRemeshingRef
/// Checks with exact predicates whether a parameterization of a triangle mesh (a `uv` point per
/// vertex, as CGAL's Surface_mesh_parameterization produces) is an embedding. The boundary
/// loop whose image encloses the largest area is taken as the outer boundary.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam UVMap a readable property map from vertices to `Epick::Point_2`
template <typename TriangleMesh, typename UVMap>
Planar_embedding_report check_parameterization(const TriangleMesh& mesh, UVMap uv_map, bool count_overlaps = false)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::unordered_map<vertex_descriptor, std::size_t> index;
  std::vector<Epick::Point_2> uv;
  for(vertex_descriptor v : vertices(mesh))
  {
    index.emplace(v, uv.size());
    uv.push_back(get(uv_map, v));
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  for(auto f : faces(mesh))
  {
    const halfedge_descriptor h = halfedge(f, mesh);
    triangles.push_back({{index[source(h, mesh)], index[target(h, mesh)], index[target(next(h, mesh), mesh)]}});
  }

  std::vector<std::vector<std::size_t> > loops;
  std::unordered_map<halfedge_descriptor, bool> seen;
  for(halfedge_descriptor h : halfedges(mesh))
  {
    if(!is_border(h, mesh) || seen[h])
      continue;
    loops.emplace_back();
    for(halfedge_descriptor b : halfedges_around_face(h, mesh))
    {
      seen[b] = true;
      loops.back().push_back(index[target(b, mesh)]);
    }
  }
  auto enclosed_area = [&](const std::vector<std::size_t>& loop) {
    const std::vector<Epick::Point_2> polygon = internal::loop_polygon(uv, loop);
    return std::abs(CGAL::to_double(CGAL::polygon_area_2(polygon.begin(), polygon.end(), Epick())));
  };
  for(std::size_t l = 1; l < loops.size(); ++l)
    if(enclosed_area(loops[l]) > enclosed_area(loops[0]))
      std::swap(loops[0], loops[l]);
  return check_planar_embedding(uv, triangles, loops, count_overlaps);
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_CHECK_PLANAR_EMBEDDING_H
