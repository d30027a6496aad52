// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The defect finder behind check_polygon_soup() and check_mesh(). It works on indices only, so
// it can judge inputs that no halfedge data structure can hold (non-manifold edges,
// inconsistent orientation, Möbius strips).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_SOUP_DEFECTS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_SOUP_DEFECTS_H

#include <CGAL/Conformal_remeshing/Mesh_defect.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

// Counts defects by kind and keeps the first example of each.
class Defect_counter
{
public:
  void add(Mesh_defect d, const std::string& example)
  {
    Entry& e = entries_[static_cast<std::size_t>(d)];
    if(e.count++ == 0)
      e.example = example;
  }

  std::vector<Defect_summary> summaries() const
  {
    std::vector<Defect_summary> result;
    for(std::size_t i = 0; i < entries_.size(); ++i)
      if(entries_[i].count > 0)
        result.push_back(Defect_summary{static_cast<Mesh_defect>(i), entries_[i].count, entries_[i].example});
    return result;
  }

private:
  struct Entry { std::size_t count = 0; std::string example; };
  std::array<Entry, static_cast<std::size_t>(Mesh_defect::NON_ORIENTABLE) + 1> entries_;
};

class Union_find
{
public:
  explicit Union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }

  std::size_t find(std::size_t i)
  {
    while(parent_[i] != i)
      i = parent_[i] = parent_[parent_[i]];
    return i;
  }

  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

private:
  std::vector<std::size_t> parent_;
};

// One side of an edge: the face it belongs to, its endpoints in the face's order, and the
// corners (positions in the flattened corner array) of those endpoints.
struct Soup_halfedge
{
  std::size_t source, target, face, source_corner, target_corner;

  std::pair<std::size_t, std::size_t> key() const { return std::minmax(source, target); }
};

template <typename Point>
std::string describe_point(const Point& p)
{
  std::ostringstream out;
  out.precision(17);
  out << "(" << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << ", " << CGAL::to_double(p.z()) << ")";
  return out.str();
}

// The corners of all faces, flattened in face order: face `f` has corners
// `offsets[f]` to `offsets[f + 1] - 1`.
template <typename PolygonRange>
std::vector<std::size_t> soup_corner_offsets(const PolygonRange& polygons)
{
  const std::size_t nf = polygons.size();
  std::vector<std::size_t> corner_offset(nf + 1, 0);
  for(std::size_t f = 0; f < nf; ++f)
    corner_offset[f + 1] = corner_offset[f] + polygons[f].size();
  return corner_offset;
}

// Non-finite coordinates; returns, for each vertex, whether its coordinates are finite.
template <typename PointRange>
std::vector<bool> find_non_finite_vertices(const PointRange& points, Defect_counter& defects)
{
  const std::size_t nv = points.size();
  std::vector<bool> finite(nv, true);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const auto& p = points[v];
    if(!(std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y()))
         && std::isfinite(CGAL::to_double(p.z()))))
    {
      finite[v] = false;
      defects.add(Mesh_defect::NON_FINITE_COORDINATES, "vertex " + std::to_string(v) + " at " + describe_point(p));
    }
  }
  return finite;
}

// Invalid vertex indices, non-triangle faces and degenerate faces, face by face. `usable` tells
// the faces that take part in the combinatorial checks (those whose indices are all valid and
// that visit no vertex twice), `used` the vertices of the faces whose indices are all valid.
template <typename Kernel, typename PointRange, typename PolygonRange>
void find_face_defects(const PointRange& points, const PolygonRange& polygons, const std::vector<bool>& finite,
                       Defect_counter& defects, std::vector<bool>& usable, std::vector<bool>& used)
{
  const std::size_t nv = points.size();
  const std::size_t nf = polygons.size();
  usable.assign(nf, true);
  used.assign(nv, false);
  typename Kernel::Collinear_3 collinear = Kernel().collinear_3_object();
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& polygon = polygons[f];
    const std::size_t n = polygon.size();
    for(std::size_t v : polygon)
    {
      if(v >= nv)
      {
        usable[f] = false;
        defects.add(Mesh_defect::INVALID_VERTEX_INDEX, "face " + std::to_string(f) + " refers to vertex "
                                                         + std::to_string(v) + " of " + std::to_string(nv));
        break;
      }
    }
    if(n != 3)
      defects.add(Mesh_defect::NON_TRIANGLE_FACE, "face " + std::to_string(f) + " has " + std::to_string(n) + " vertices");
    if(!usable[f])
      continue;
    for(std::size_t v : polygon)
      used[v] = true;

    bool repeated = false;
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j)
        repeated = repeated || polygon[i] == polygon[j];
    bool degenerate = repeated || n < 3;
    if(!degenerate && n == 3 && finite[polygon[0]] && finite[polygon[1]] && finite[polygon[2]])
      degenerate = collinear(points[polygon[0]], points[polygon[1]], points[polygon[2]]);
    if(degenerate)
    {
      std::ostringstream example;
      example << "face " << f << " (vertices";
      for(std::size_t v : polygon)
        example << " " << v;
      example << ")" << (repeated ? " repeats a vertex" : " has collinear vertices");
      defects.add(Mesh_defect::DEGENERATE_FACE, example.str());
    }
    // A face through one vertex twice runs along an edge both ways: the edge and fan checks
    // would report that one defect again as a non-manifold edge and vertices.
    if(repeated)
      usable[f] = false;
  }
}

// Duplicates: equal coordinates end up next to each other after a lexicographic sort.
template <typename PointRange>
void find_duplicated_vertices(const PointRange& points, const std::vector<bool>& finite, Defect_counter& defects)
{
  const std::size_t nv = points.size();
  std::vector<std::size_t> order;
  order.reserve(nv);
  for(std::size_t v = 0; v < nv; ++v)
    if(finite[v])
      order.push_back(v);
  auto less = [&](std::size_t a, std::size_t b) {
    const auto& p = points[a];
    const auto& q = points[b];
    if(p.x() != q.x()) return p.x() < q.x();
    if(p.y() != q.y()) return p.y() < q.y();
    if(p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  for(std::size_t i = 1; i < order.size(); ++i)
    if(points[order[i]] == points[order[i - 1]])
      defects.add(Mesh_defect::DUPLICATED_VERTEX, "vertices " + std::to_string(order[i - 1]) + " and "
                                                    + std::to_string(order[i]) + " at "
                                                    + describe_point(points[order[i]]));
}

inline void find_isolated_vertices(const std::vector<bool>& used, Defect_counter& defects)
{
  for(std::size_t v = 0; v < used.size(); ++v)
    if(!used[v])
      defects.add(Mesh_defect::ISOLATED_VERTEX, "vertex " + std::to_string(v));
}

// The sides of the edges of the usable faces, sorted so that the sides of one edge are
// adjacent (and, within one edge, in face order).
template <typename PolygonRange>
std::vector<Soup_halfedge> sorted_soup_halfedges(const PolygonRange& polygons, const std::vector<bool>& usable,
                                                 const std::vector<std::size_t>& corner_offset)
{
  const std::size_t nf = polygons.size();
  std::vector<Soup_halfedge> sides;
  sides.reserve(corner_offset[nf]);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!usable[f])
      continue;
    const auto& polygon = polygons[f];
    const std::size_t n = polygon.size();
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t j = (i + 1) % n;
      if(polygon[i] != polygon[j])
        sides.push_back(Soup_halfedge{polygon[i], polygon[j], f, corner_offset[f] + i, corner_offset[f] + j});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Soup_halfedge& a, const Soup_halfedge& b) {
    return a.key() < b.key() || (a.key() == b.key() && a.face < b.face);
  });
  return sides;
}

// Face adjacency across a manifold edge; `same_direction` means the two faces traverse the
// edge the same way, i.e. they disagree on the orientation.
struct Soup_adjacency { std::size_t other; bool same_direction; };

// What the edges tell about the faces around them: the adjacency of faces across manifold
// edges, the fans of corners joined across these edges, and the edges whose two faces
// disagree on the orientation (how many, and the first of them).
struct Soup_edge_structure
{
  Soup_edge_structure(std::size_t nb_faces, std::size_t nb_corners) : adjacent(nb_faces), fans(nb_corners) {}

  std::vector<std::vector<Soup_adjacency> > adjacent;
  Union_find fans;
  std::size_t inconsistent_edges = 0;
  std::string inconsistent_example;
};

// Non-manifold edges (sides of more than two faces), and the structure of the faces joined
// across the other edges, from the sides sorted by `sorted_soup_halfedges()`.
inline Soup_edge_structure find_edge_defects(const std::vector<Soup_halfedge>& sides, std::size_t nb_faces,
                                             std::size_t nb_corners, Defect_counter& defects)
{
  Soup_edge_structure edges(nb_faces, nb_corners);
  for(std::size_t first = 0; first < sides.size();)
  {
    std::size_t last = first + 1;
    while(last < sides.size() && sides[last].key() == sides[first].key())
      ++last;
    const std::size_t multiplicity = last - first;
    if(multiplicity > 2)
    {
      std::ostringstream example;
      example << "edge between vertices " << sides[first].key().first << " and " << sides[first].key().second
              << ", shared by " << multiplicity << " faces (";
      for(std::size_t k = first; k < last; ++k)
        example << (k == first ? "" : ", ") << sides[k].face;
      example << ")";
      defects.add(Mesh_defect::NON_MANIFOLD_EDGE, example.str());
    }
    else if(multiplicity == 2)
    {
      const Soup_halfedge& a = sides[first];
      const Soup_halfedge& b = sides[first + 1];
      const bool same = (a.source == b.source);
      edges.adjacent[a.face].push_back(Soup_adjacency{b.face, same});
      edges.adjacent[b.face].push_back(Soup_adjacency{a.face, same});
      if(same)
      {
        edges.fans.unite(a.source_corner, b.source_corner);
        edges.fans.unite(a.target_corner, b.target_corner);
        if(edges.inconsistent_edges++ == 0)
          edges.inconsistent_example = "edge between vertices " + std::to_string(a.key().first) + " and "
                                       + std::to_string(a.key().second) + " runs the same way in faces "
                                       + std::to_string(a.face) + " and " + std::to_string(b.face);
      }
      else
      {
        edges.fans.unite(a.source_corner, b.target_corner);
        edges.fans.unite(a.target_corner, b.source_corner);
      }
    }
    first = last;
  }
  return edges;
}

// Orientability: propagate a flip flag over each component; a contradiction means that no
// choice of orientations agrees along every edge. Returns the number of non-orientable
// components.
inline std::size_t find_non_orientable_components(const std::vector<bool>& usable,
                                                  const std::vector<std::vector<Soup_adjacency> >& adjacent,
                                                  Defect_counter& defects)
{
  const std::size_t nf = usable.size();
  std::vector<int> flip(nf, -1);
  std::size_t non_orientable_components = 0;
  std::vector<std::size_t> stack;
  for(std::size_t seed = 0; seed < nf; ++seed)
  {
    if(!usable[seed] || flip[seed] != -1)
      continue;
    bool orientable = true;
    flip[seed] = 0;
    stack.assign(1, seed);
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(const Soup_adjacency& a : adjacent[f])
      {
        const int wanted = flip[f] ^ static_cast<int>(a.same_direction);
        if(flip[a.other] == -1)
        {
          flip[a.other] = wanted;
          stack.push_back(a.other);
        }
        else if(flip[a.other] != wanted)
          orientable = false;
      }
    }
    if(!orientable)
    {
      ++non_orientable_components;
      defects.add(Mesh_defect::NON_ORIENTABLE, "the component of face " + std::to_string(seed));
    }
  }
  return non_orientable_components;
}

// A manifold vertex has all its corners in one fan (corners joined across shared edges).
template <typename PolygonRange>
void find_non_manifold_vertices(const PolygonRange& polygons, std::size_t nb_vertices, const std::vector<bool>& usable,
                                const std::vector<std::size_t>& corner_offset, Union_find& fans,
                                Defect_counter& defects)
{
  const std::size_t nf = polygons.size();
  std::vector<std::vector<std::size_t> > corners_of(nb_vertices);
  for(std::size_t f = 0; f < nf; ++f)
    if(usable[f])
      for(std::size_t i = 0; i < polygons[f].size(); ++i)
        corners_of[polygons[f][i]].push_back(corner_offset[f] + i);
  for(std::size_t v = 0; v < nb_vertices; ++v)
  {
    std::vector<std::size_t> roots;
    for(std::size_t c : corners_of[v])
      roots.push_back(fans.find(c));
    std::sort(roots.begin(), roots.end());
    const std::size_t nb_fans = std::unique(roots.begin(), roots.end()) - roots.begin();
    if(nb_fans > 1)
      defects.add(Mesh_defect::NON_MANIFOLD_VERTEX, "vertex " + std::to_string(v) + " joins "
                                                      + std::to_string(nb_fans) + " separate fans of faces");
  }
}

template <typename Kernel, typename PointRange, typename PolygonRange>
std::vector<Defect_summary> find_soup_defects(const PointRange& points, const PolygonRange& polygons)
{
  const std::size_t nv = points.size();
  const std::size_t nf = polygons.size();
  Defect_counter defects;

  if(nf == 0)
    defects.add(Mesh_defect::EMPTY_MESH, nv == 0 ? std::string("no vertex and no face")
                                                 : std::to_string(nv) + " vertices but no face");

  const std::vector<bool> finite = find_non_finite_vertices(points, defects);

  // Faces whose indices are all valid take part in the combinatorial checks.
  std::vector<bool> usable, used;
  find_face_defects<Kernel>(points, polygons, finite, defects, usable, used);

  find_duplicated_vertices(points, finite, defects);
  find_isolated_vertices(used, defects);

  // Edges: sort the sides of all edges so that the sides of one edge are adjacent.
  const std::vector<std::size_t> corner_offset = soup_corner_offsets(polygons);
  const std::vector<Soup_halfedge> sides = sorted_soup_halfedges(polygons, usable, corner_offset);
  Soup_edge_structure edges = find_edge_defects(sides, nf, corner_offset[nf], defects);

  const std::size_t non_orientable_components = find_non_orientable_components(usable, edges.adjacent, defects);
  if(edges.inconsistent_edges > 0 && non_orientable_components == 0)
    for(std::size_t k = 0; k < edges.inconsistent_edges; ++k)
      defects.add(Mesh_defect::INCONSISTENT_ORIENTATION, edges.inconsistent_example);

  find_non_manifold_vertices(polygons, nv, usable, corner_offset, edges.fans, defects);

  return defects.summaries();
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_SOUP_DEFECTS_H
