// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Replaces the faces of each large set of exactly coplanar faces of a patch by their constrained
// Delaunay triangulation, before the intrinsic Delaunay flips: a CAD exporter's fan of slivers
// on a planar face has all its vertices on the face's boundary, so the fan grows with the mesh
// and Lawson's flips from it grow with its square (issue #7's growth runs: 92 million flips at
// 316k vertices). In the plane the intrinsic Delaunay triangulation is the constrained Delaunay
// one, which CGAL builds in O(n log n).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_RETRIANGULATE_COPLANAR_REGIONS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_RETRIANGULATE_COPLANAR_REGIONS_H

#include <CGAL/Conformal_remeshing/internal/welding/constrained_domain.h>
#include <CGAL/Conformal_remeshing/internal/welding/coplanar_region.h>
#include <CGAL/Conformal_remeshing/internal/welding/weld.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

namespace coplanar {

// The faces around each vertex of `region`, counterclockwise from the one after a boundary side
// (`fan_start`, `fan`); false if the faces at a vertex do not form one fan (a pinched region).
inline bool make_fans(Coplanar_region& region)
{
  std::vector<int> count(region.vertices.size() + 1, 0);
  for(const auto& f : region.faces)
    for(int v : f)
      ++count[v + 1];
  region.fan_start.assign(region.vertices.size() + 1, 0);
  for(std::size_t v = 0; v < region.vertices.size(); ++v)
    region.fan_start[v + 1] = region.fan_start[v] + count[v + 1];
  region.fan.assign(region.fan_start.back(), -1);
  std::vector<int> first(region.vertices.size(), -1); // a face at v, the one after a boundary side if any
  for(std::size_t f = 0; f < region.faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const int v = region.faces[f][c];
      if(first[v] < 0 || region.neighbor[f][c] < 0) // side (c, c + 1) is the first side at v
        first[v] = int(f);
    }
  for(std::size_t v = 0; v < region.vertices.size(); ++v)
  {
    int f = first[v], k = region.fan_start[v];
    do
    {
      if(k == region.fan_start[v + 1])
        return false;
      region.fan[k++] = f;
      const int c = int(std::find(region.faces[f].begin(), region.faces[f].end(), int(v)) - region.faces[f].begin());
      f = region.neighbor[f][(c + 2) % 3]; // across the side from the previous corner to v
    } while(f >= 0 && f != first[v]);
    if(k != region.fan_start[v + 1])
      return false;
  }
  return true;
}

// Adds to `cdt`, the constrained Delaunay triangulation of `region` (vertex `info()`: local
// index; faces marked by `mark_constraint_depth()`), the points of a square grid of side
// `spacing` inside the region, but none within a third of `spacing` of its boundary: the
// intrinsic refinement would otherwise split the long edges of a planar CAD face's triangulation
// (its vertices all on its outline) one at a time, two dozen flips each on the 87k suspension arm
// of issue #7, and every point pulled back later walks back through those flips. The new vertices
// join `region` (patch indices from `first_index` on, with the original faces holding them);
// returns their 3D points, on the original faces.
template <typename CDT>
std::vector<Vec3> add_interior_points(CDT& cdt, Coplanar_region& region, double spacing, int first_index,
                                      const std::vector<Vec3>& patch_points)
{
  typedef typename CDT::Point Point;
  CGAL::Bbox_2 box;
  for(const Point& p : region.points)
    box += p.bbox();
  if(!(spacing > 0.) || ((box.xmax() - box.xmin()) / spacing + 1.) * ((box.ymax() - box.ymin()) / spacing + 1.) > 4e6)
    return {};
  struct Added
  {
    Point point;
    typename CDT::Vertex_handle vertex;
    std::pair<int, std::array<double, 3> > original; // face and barycentric coordinates
  };
  std::vector<Added> added;
  typename CDT::Face_handle hint;
  for(double y = box.ymin() + 0.5 * spacing; y < box.ymax(); y += spacing)
    for(double x = box.xmin() + 0.5 * spacing; x < box.xmax(); x += spacing)
    {
      const Point p(x, y);
      typename CDT::Locate_type type;
      int i = 0;
      const typename CDT::Face_handle f = cdt.locate(p, type, i, hint);
      hint = f;
      if(type != CDT::FACE || f->info() % 2 != 1)
        continue;
      std::array<int, 3> corners;
      for(int c = 0; c < 3; ++c)
        corners[c] = f->vertex(c)->info();
      added.push_back(Added{p, typename CDT::Vertex_handle(), region.locate_point(corners, p)});
    }
  for(std::size_t k = 0; k < added.size(); ++k) // after the walks, which start from the triangulation's vertices
  {
    added[k].vertex = cdt.insert(added[k].point);
    added[k].vertex->info() = -1;
  }
  // Too near the boundary: a constrained side of a face around it is closer than a third of spacing.
  const double nearest = CGAL::square(spacing / 3.);
  std::vector<char> kept(added.size(), 1);
  for(std::size_t k = 0; k < added.size(); ++k)
  {
    auto f = cdt.incident_faces(added[k].vertex), done = f;
    do
    {
      const int i = f->index(added[k].vertex);
      if(cdt.is_constrained(typename CDT::Edge(f, i))
         && CGAL::squared_distance(added[k].vertex->point(),
                                   typename CDT::Geom_traits::Segment_2(f->vertex(CDT::cw(i))->point(), f->vertex(CDT::ccw(i))->point())) < nearest)
        kept[k] = 0;
    } while(++f != done && kept[k]);
  }
  for(std::size_t k = 0; k < added.size(); ++k)
    if(!kept[k])
      cdt.remove(added[k].vertex);
  region.containing_face.assign(region.vertices.size(), -1);
  std::vector<Vec3> points;
  for(std::size_t k = 0; k < added.size(); ++k)
    if(kept[k])
    {
      added[k].vertex->info() = int(region.vertices.size());
      region.vertices.push_back(first_index + int(points.size()));
      region.points.push_back(added[k].vertex->point());
      region.containing_face.push_back(added[k].original.first);
      region.fan_start.push_back(region.fan_start.back()); // no original face has it as a corner
      Vec3 x{{0., 0., 0.}};
      for(int c = 0; c < 3; ++c)
        for(int d = 0; d < 3; ++d)
          x[d] += added[k].original.second[c] * patch_points[region.vertices[region.faces[added[k].original.first][c]]][d];
      points.push_back(x);
    }
  mark_constraint_depth(cdt);
  return points;
}

} // namespace coplanar

/// Retriangulates every edge-connected set of at least `smallest_region` faces of `patch` that
/// are exactly coplanar (exact predicates) and face the same way, by the constrained Delaunay
/// triangulation of its vertices with its boundary sides as constraints. The region keeps its
/// vertices and boundary; a region is left as it is when its projection is not a plane
/// triangulation of the same domain (points that coincide, sides that cross) or when a new edge
/// would double an edge of the patch outside the region. With a `spacing`, points of a square
/// grid of that side inside the region are added to its triangulation first (see
/// `coplanar::add_interior_points()`), appended to `patch.points`. The new faces take the slots
/// of the old ones, then the end of `patch.faces`, with `input_face` `-1 - r` for region `r` of
/// `patch.coplanar_regions`, which locates points among the old faces. Returns the number of
/// faces retriangulated.
inline std::size_t retriangulate_coplanar_regions(Indexed_patch& patch, double spacing = 0., std::size_t smallest_region = 16)
{
  typedef Epick K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K> > Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;

  const int nf = int(patch.faces.size());
  std::unordered_map<std::uint64_t, int> face_of; // directed side -> face (of the input faces)
  std::unordered_set<std::uint64_t> edges;        // the patch's edges
  face_of.reserve(3 * std::size_t(nf));
  edges.reserve(3 * std::size_t(nf));
  for(int f = 0; f < nf; ++f)
    for(int c = 0; c < 3; ++c)
    {
      face_of.emplace(directed_key(patch.faces[f][c], patch.faces[f][(c + 1) % 3]), f);
      edges.insert(undirected_key(patch.faces[f][c], patch.faces[f][(c + 1) % 3]));
    }
  auto across = [&](int f, int c) {
    const auto it = face_of.find(directed_key(patch.faces[f][(c + 1) % 3], patch.faces[f][c]));
    return it == face_of.end() ? -1 : it->second;
  };
  auto point = [&](int v) { return K::Point_3(patch.points[v][0], patch.points[v][1], patch.points[v][2]); };

  std::vector<int> grown_by(std::size_t(nf), -1), position(std::size_t(nf), -1);
  std::size_t replaced = 0;
  for(int seed = 0; seed < nf; ++seed)
  {
    if(grown_by[seed] >= 0)
      continue;
    grown_by[seed] = seed;
    const std::array<int, 3> s = patch.faces[seed];
    const K::Point_3 a = point(s[0]), b = point(s[1]), c = point(s[2]);
    if(CGAL::collinear(a, b, c))
      continue;
    // Drop the coordinate of the normal's largest component (exact: the projection is a bijection
    // on the plane when the seed's projection is not flat, which is checked exactly).
    const Vec3 n = face_normal(patch, s);
    const int dropped = dominant_axis(n);
    auto project = [&](int v, bool mirrored) {
      const double x = patch.points[v][(dropped + 1) % 3], y = patch.points[v][(dropped + 2) % 3];
      return K::Point_2(mirrored ? -x : x, y);
    };
    auto facing = [&](const std::array<int, 3>& f) { return CGAL::orientation(project(f[0], false), project(f[1], false), project(f[2], false)); };
    const CGAL::Orientation side = facing(s);
    if(side == CGAL::COLLINEAR)
      continue;

    std::vector<int> region{seed};
    for(std::size_t i = 0; i < region.size(); ++i)
      for(int k = 0; k < 3; ++k)
      {
        const int g = across(region[i], k);
        if(g < 0 || grown_by[g] >= 0)
          continue;
        const std::array<int, 3>& corners = patch.faces[g];
        bool in_plane = true;
        for(int v : corners)
          in_plane = in_plane && CGAL::coplanar(a, b, c, point(v));
        if(in_plane && facing(corners) == side)
        {
          grown_by[g] = seed;
          region.push_back(g);
        }
      }
    if(region.size() < smallest_region)
      continue;
    for(std::size_t i = 0; i < region.size(); ++i)
      position[region[i]] = int(i);

    // The region with its old faces, in its own indices.
    Coplanar_region r;
    const bool mirrored = side == CGAL::NEGATIVE; // counterclockwise faces in the projection
    for(int f : region)
      r.vertices.insert(r.vertices.end(), patch.faces[f].begin(), patch.faces[f].end());
    std::sort(r.vertices.begin(), r.vertices.end());
    r.vertices.erase(std::unique(r.vertices.begin(), r.vertices.end()), r.vertices.end());
    for(int v : r.vertices)
      r.points.push_back(project(v, mirrored));
    std::unordered_set<std::uint64_t> old_inner_edges;
    for(int f : region)
    {
      std::array<int, 3> local, neighbors;
      for(int k = 0; k < 3; ++k)
      {
        local[k] = r.local_vertex(patch.faces[f][k]);
        const int g = across(f, k);
        neighbors[k] = (g >= 0 && grown_by[g] == seed) ? position[g] : -1;
        if(neighbors[k] >= 0)
          old_inner_edges.insert(undirected_key(patch.faces[f][k], patch.faces[f][(k + 1) % 3]));
      }
      r.faces.push_back(local);
      r.neighbor.push_back(neighbors);
      r.input_face.push_back(patch.input_face[f]);
      r.input_coordinates.push_back(patch.input_coordinates[f]);
    }
    if(!coplanar::make_fans(r))
      continue;

    // Its constrained Delaunay triangulation, faces inside by the parity of constraints crossed.
    CDT cdt;
    std::vector<std::pair<K::Point_2, int> > located;
    for(std::size_t v = 0; v < r.points.size(); ++v)
      located.emplace_back(r.points[v], int(v));
    cdt.insert(located.begin(), located.end());
    if(cdt.number_of_vertices() != r.points.size())
      continue; // two vertices project to one point
    std::vector<CDT::Vertex_handle> handle(r.points.size());
    for(auto v : cdt.finite_vertex_handles())
      handle[v->info()] = v;
    std::vector<std::pair<int, int> > boundary;
    for(std::size_t f = 0; f < r.faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
        if(r.neighbor[f][k] < 0)
        {
          boundary.emplace_back(r.faces[f][k], r.faces[f][(k + 1) % 3]);
          cdt.insert_constraint(handle[boundary.back().first], handle[boundary.back().second]);
        }
    if(cdt.number_of_vertices() != r.points.size())
      continue; // sides cross
    std::sort(boundary.begin(), boundary.end());
    mark_constraint_depth(cdt);
    std::vector<std::array<int, 3> > made;
    std::vector<std::uint64_t> new_inner_edges;
    auto collect_faces = [&]() {
      made.clear();
      new_inner_edges.clear();
      for(auto fh : cdt.finite_face_handles())
        if(fh->info() % 2 == 1)
          made.push_back({{fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()}});
      for(const auto& f : made)
        for(int k = 0; k < 3; ++k)
          if(f[k] < f[(k + 1) % 3]) // once per inner edge: boundary sides are kept
          {
            const std::uint64_t e = undirected_key(r.vertices[f[k]], r.vertices[f[(k + 1) % 3]]);
            if(!std::binary_search(boundary.begin(), boundary.end(), std::make_pair(f[k], f[(k + 1) % 3]))
               && !std::binary_search(boundary.begin(), boundary.end(), std::make_pair(f[(k + 1) % 3], f[k])))
              new_inner_edges.push_back(e);
          }
    };
    // It would join two vertices joined outside the region already.
    auto doubles_an_edge = [&]() {
      for(std::uint64_t e : new_inner_edges)
        if(!old_inner_edges.count(e) && edges.count(e))
          return true;
      return false;
    };
    collect_faces();
    bool same_domain = made.size() == region.size();
    for(std::size_t i = 0; i < boundary.size() && same_domain; ++i)
    {
      CDT::Face_handle fh;
      int k;
      const CDT::Vertex_handle from = handle[boundary[i].first], to = handle[boundary[i].second];
      if(!cdt.is_edge(from, to, fh, k))
        same_domain = false;
      else
      {
        const CDT::Face_handle left = fh->vertex(fh->ccw(k)) == from ? fh : fh->neighbor(k);
        same_domain = !cdt.is_infinite(left) && left->info() % 2 == 1;
      }
    }
    if(!same_domain || doubles_an_edge())
      continue;
    const std::vector<Vec3> added_points =
        coplanar::add_interior_points(cdt, r, spacing, int(patch.points.size()), patch.points);
    if(!added_points.empty())
    {
      collect_faces();
      if(doubles_an_edge())
        continue;
    }

    for(std::uint64_t e : old_inner_edges)
      edges.erase(e);
    edges.insert(new_inner_edges.begin(), new_inner_edges.end());
    patch.points.insert(patch.points.end(), added_points.begin(), added_points.end());
    const int index = -1 - int(patch.coplanar_regions.size());
    for(std::size_t i = 0; i < made.size(); ++i)
    {
      std::array<int, 3> corners;
      for(int k = 0; k < 3; ++k)
        corners[k] = r.vertices[made[i][k]];
      if(i < region.size())
      {
        patch.faces[region[i]] = corners;
        patch.input_face[region[i]] = index;
        patch.input_coordinates[region[i]] = {};
      }
      else
      {
        patch.faces.push_back(corners);
        patch.input_face.push_back(index);
        patch.input_coordinates.push_back({});
      }
    }
    patch.coplanar_regions.push_back(std::move(r));
    replaced += region.size();
  }
  return replaced;
}

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_RETRIANGULATE_COPLANAR_REGIONS_H
