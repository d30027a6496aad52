// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How close other sheets of the surface come to each vertex: the walls of a thin pipe, two
// parts a hair apart, the sides of a thin blade. The output's triangles are chords of the
// surface, and where the surface bends, a chord stands off it by its sagitta: more than the gap
// to another sheet, and the two remeshed sheets cross. The size field bounds the chords there
// (sizing.h); this is the measure it bounds them by.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PROXIMITY_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PROXIMITY_H

#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/shortest_ways.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// A point of the surface belongs to another sheet than a vertex `v` when the way to it along
/// the surface is more than this many times its distance from `v`: the other wall of a pipe, or
/// of a wedge sharper than about 53 degrees, but not the far side of a bend in one sheet (a
/// half cylinder's way is pi/2 times its width).
constexpr double other_sheet_detour = 2.;

/// A face also belongs to another sheet when it faces `v`: its normal and `v`'s make more than
/// 120 degrees, and its nearest point lies within 60 degrees of `v`'s normal line. Near the rim
/// of a thin wall, the other side is only the rim's width away along the surface, yet the
/// chords of one side can cross the other there.
constexpr double facing_normals_cosine = -0.5;
constexpr double facing_direction_cosine = 0.5;

/// The gap at each vertex of a mesh: the distance to the nearest point of another sheet
/// (`other_sheet_detour`, `facing_normals_cosine`), other components included; infinite where
/// none is within `radius`.
struct Surface_proximity
{
  std::vector<double> gap;
  double smallest_gap = std::numeric_limits<double>::infinity();
  Epick::Point_3 smallest_gap_point = CGAL::ORIGIN; ///< a vertex with the smallest gap
};

typedef Poly_annulus_segmentation::Mesh Proximity_mesh;

/// For each vertex of `m`, the other vertices at its point (sheets in contact).
inline std::vector<std::vector<Proximity_mesh::Vertex_index> > coincident_vertices_of(const Proximity_mesh& m)
{
  typedef Proximity_mesh::Vertex_index Vertex;
  std::vector<std::pair<Epick::Point_3, Vertex> > by_point;
  for(Vertex w : m.vertices())
    by_point.emplace_back(m.point(w), w);
  std::sort(by_point.begin(), by_point.end());
  std::vector<std::vector<Vertex> > twins(m.number_of_vertices());
  for(std::size_t first = 0, last = 0; first < by_point.size(); first = last)
  {
    for(last = first + 1; last < by_point.size() && by_point[last].first == by_point[first].first; ++last) {}
    for(std::size_t i = first; i < last && last - first > 1; ++i)
      for(std::size_t j = first; j < last; ++j)
        if(i != j)
          twins[by_point[i].second].push_back(by_point[j].second);
  }
  return twins;
}

/// The lengths of the shortest ways along the edges of `m` from `v` to the vertices they reach
/// within `reach` (Dijkstra), by vertex index; a way goes through a contact (`twins`, see
/// `coincident_vertices_of()`) at no cost, so that sheets in contact are no gap to each other.
inline std::unordered_map<std::size_t, double> ways_from(const Proximity_mesh& m, Proximity_mesh::Vertex_index v, double reach,
                                                        const std::vector<std::vector<Proximity_mesh::Vertex_index> >& twins)
{
  typedef Proximity_mesh::Vertex_index Vertex;
  return shortest_ways_within(v, reach, [&](Vertex u, const auto& step) {
    for(Vertex w : twins[u])
      step(w, 0.);
    for(Vertex w : m.vertices_around_target(m.halfedge(u)))
      step(w, std::sqrt(CGAL::squared_distance(m.point(u), m.point(w))));
  });
}

inline double cosine(const Epick::Vector_3& a, const Epick::Vector_3& b)
{
  const double l = std::sqrt(a.squared_length() * b.squared_length());
  return l > 0. ? (a * b) / l : 0.;
}

/// The gaps of the vertices of `m` within `radius` (see `Surface_proximity`). Per vertex: the
/// ways along the edges out to `other_sheet_detour` times `radius` (`ways_from()`), then the
/// faces in the ball of `radius` (an AABB tree) that have no corner reached by a way shorter than
/// the detour bound, or that face the vertex; the gap is the distance to the nearest of them.
template <typename ConcurrencyTag>
Surface_proximity surface_proximity(const Proximity_mesh& m, double radius)
{
  typedef Proximity_mesh Mesh;
  typedef Mesh::Vertex_index Vertex;
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Epick, Primitive> > Tree;
  Surface_proximity proximity;
  proximity.gap.assign(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  if(m.is_empty() || !(radius > 0.))
    return proximity;
  Tree tree(faces(m).first, faces(m).second, m);
  tree.build();
  const auto face_normal = [&](Mesh::Face_index f) {
    const auto h = m.halfedge(f);
    return CGAL::normal(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
  };
  const std::vector<std::vector<Vertex> > twins = coincident_vertices_of(m);
  std::vector<Epick::Vector_3> vertex_normal(m.number_of_vertices(), CGAL::NULL_VECTOR); // area-weighted
  for(Mesh::Face_index f : m.faces())
    for(Vertex w : m.vertices_around_face(m.halfedge(f)))
      vertex_normal[w] = vertex_normal[w] + face_normal(f);

  for_each_index<ConcurrencyTag>(m.number_of_vertices(), [&](std::size_t i) {
    const Vertex v(static_cast<Mesh::size_type>(i));
    if(m.is_isolated(v))
      return;
    const Epick::Point_3& p = m.point(v);
    const std::unordered_map<std::size_t, double> way = ways_from(m, v, other_sheet_detour * radius, twins);
    const auto on_own_sheet = [&](Vertex w) {
      const auto found = way.find(std::size_t(w));
      return found != way.end() && found->second <= other_sheet_detour * std::sqrt(CGAL::squared_distance(p, m.point(w)));
    };
    std::vector<Mesh::Face_index> near;
    const Bbox_3 ball(p.x() - radius, p.y() - radius, p.z() - radius, p.x() + radius, p.y() + radius, p.z() + radius);
    tree.all_intersected_primitives(ball, std::back_inserter(near));
    double gap = std::numeric_limits<double>::infinity();
    for(Mesh::Face_index f : near)
    {
      bool own = false, incident = false;
      for(Vertex w : m.vertices_around_face(m.halfedge(f)))
      {
        own = own || on_own_sheet(w);
        incident = incident || m.point(w) == p; // at v, or at a contact with it
      }
      if(incident)
        continue;
      const auto h = m.halfedge(f);
      const Epick::Triangle_3 t(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
      if(own)
      {
        if(!(cosine(face_normal(f), vertex_normal[v]) < facing_normals_cosine))
          continue;
        const Epick::Point_3 q = Epick().construct_projected_point_3_object()(t, p);
        if(!(std::abs(cosine(q - p, vertex_normal[v])) > facing_direction_cosine))
          continue;
      }
      const double d = std::sqrt(CGAL::squared_distance(p, t));
      if(d < radius)
        gap = (std::min)(gap, d);
    }
    proximity.gap[i] = gap;
  });
  for(Vertex v : m.vertices())
    if(proximity.gap[v] < proximity.smallest_gap)
    {
      proximity.smallest_gap = proximity.gap[v];
      proximity.smallest_gap_point = m.point(v);
    }
  return proximity;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PROXIMITY_H
