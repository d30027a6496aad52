// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Self-intersections that are more than a contact. A valid manifold may have distinct vertices
// at one point (two holes touching at a corner, sheets cut apart along a non-manifold edge): the
// faces around them meet there, and CGAL's `self_intersections()`, which knows only the
// combinatorial sharing of vertices, reports them. Such a pair is a contact, not a crossing,
// when the two faces, with their corners at the same points made one vertex, do not intersect
// (exact predicates, CGAL's own test of faces that share a vertex or an edge).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_CROSSING_FACES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_CROSSING_FACES_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

/// Whether the triangles `a` and `b`, which intersect, only touch at corners they have at the
/// same points (or along a side they have at the same points).
template <typename Point>
bool is_contact(const std::array<Point, 3>& a, const std::array<Point, 3>& b)
{
  typedef CGAL::Surface_mesh<Point> Pair_mesh;
  typedef typename Pair_mesh::Vertex_index Vertex;
  Pair_mesh pair;
  std::vector<std::pair<Point, Vertex> > vertices;
  const auto vertex = [&](const Point& p) {
    for(const auto& v : vertices)
      if(v.first == p)
        return v.second;
    vertices.emplace_back(p, pair.add_vertex(p));
    return vertices.back().second;
  };
  const std::array<Vertex, 3> va{{vertex(a[0]), vertex(a[1]), vertex(a[2])}};
  const std::size_t corners_of_a = vertices.size();
  const std::array<Vertex, 3> vb{{vertex(b[0]), vertex(b[1]), vertex(b[2])}};
  const std::size_t common = corners_of_a + 3 - vertices.size();
  if(corners_of_a < 3 || common == 0 || common == 3)
    return false; // a degenerate face, no common corner, or the same triangle twice
  if(pair.add_face(va[0], va[1], va[2]) == Pair_mesh::null_face()
     || (pair.add_face(vb[0], vb[1], vb[2]) == Pair_mesh::null_face() && pair.add_face(vb[2], vb[1], vb[0]) == Pair_mesh::null_face()))
    return false;
  return !Polygon_mesh_processing::does_self_intersect(pair);
}

/// Whether the faces `a` and `b` of `mesh`, which intersect, cross (are not a contact).
template <typename TriangleMesh, typename VertexPointMap, typename Face>
bool is_crossing(const TriangleMesh& mesh, const VertexPointMap& vpm, Face a, Face b)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  const auto corners = [&](Face f) {
    std::array<Point, 3> t;
    int c = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      if(c < 3)
        t[c++] = get(vpm, v);
    return t;
  };
  return a == b || !is_contact(corners(a), corners(b));
}

/// The pairs of faces of `mesh` that intersect and are not a contact (see `is_contact()`).
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                      typename boost::graph_traits<TriangleMesh>::face_descriptor> >
crossing_face_pairs(const TriangleMesh& mesh, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Face;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  std::vector<std::pair<Face, Face> > pairs;
  Polygon_mesh_processing::self_intersections<ConcurrencyTag>(mesh, std::back_inserter(pairs),
                                                              CGAL::parameters::vertex_point_map(vpm));
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&](const std::pair<Face, Face>& p) { return !is_crossing(mesh, vpm, p.first, p.second); }),
              pairs.end());
  return pairs;
}

/// Whether `mesh` has faces that cross (see `crossing_face_pairs()`). Stops at the first
/// crossing pair: a mesh with many overlapping faces (another remesher's output that folds) would
/// otherwise collect millions of pairs.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool has_crossing_faces(const TriangleMesh& mesh, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Face;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  if(!Polygon_mesh_processing::does_self_intersect<ConcurrencyTag>(mesh, CGAL::parameters::vertex_point_map(vpm)))
    return false;
  // Some pair intersects: look for one that is more than a contact, one pair at a time.
  struct Found
  {};
  const auto check = [&](const std::pair<Face, Face>& p) {
    if(is_crossing(mesh, vpm, p.first, p.second))
      throw Found();
  };
  try
  {
    Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(mesh, boost::make_function_output_iterator(check),
                                                                      CGAL::parameters::vertex_point_map(vpm));
  }
  catch(const Found&)
  {
    return true;
  }
  return false;
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_CROSSING_FACES_H
