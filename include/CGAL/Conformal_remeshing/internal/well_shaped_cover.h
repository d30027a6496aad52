// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triangles covering a mesh's surface for closest-point searches: a CAD exporter's planar face
// is a fan of slivers whose bounding boxes all cover the face, so an AABB tree over them opens
// every sliver of the fan for every query there, and measuring a CAD part would grow with the
// square of its fans (on a 1M-vertex CAD part, 17 times as long as its remeshing).
// Each region of exactly coplanar faces is replaced by the constrained Delaunay triangulation of
// its outline, refined to well-shaped triangles, which covers the same part of the plane with
// few overlapping boxes.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELL_SHAPED_COVER_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELL_SHAPED_COVER_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/constrained_domain.h>
#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

namespace cover {

typedef CGAL::Epick::Point_3 Point_3;

// One coplanar region: its faces as corner indices into `points`, and the sides on its outline.
struct Coplanar_region
{
  std::vector<std::array<int, 3> > faces;
  std::vector<std::array<int, 2> > outline;
};

// A region's triangles: a corner `c >= 0` is the mesh's vertex `c`, a corner `c < 0` the point
// `added[-c - 1]` that the refinement added.
struct Region_cover
{
  std::vector<Point_3> added;
  std::vector<std::array<std::int64_t, 3> > triangles;
};

// Inserts the sides of `region`'s outline into `cdt` as constraints, their ends projected by
// `project` (a mesh vertex to a `CDT::Point`) and recorded in their `info().value`. The ends are
// inserted first as one range, which CGAL sorts spatially: the outline's sides come in the order
// the region grew, and on a planar CAD face of a large part (a fan of 100k slivers and more) a
// walk from one side's end to the next side's would cross the face.
template <typename CDT, typename Project>
void insert_outline(const Coplanar_region& region, const Project& project, CDT& cdt)
{
  typedef typename CDT::Vertex::Info Info;
  std::vector<int> ends; // the outline's vertices, sorted
  ends.reserve(2 * region.outline.size());
  for(const std::array<int, 2>& side : region.outline)
    ends.insert(ends.end(), side.begin(), side.end());
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<std::pair<typename CDT::Point, Info> > located;
  located.reserve(ends.size());
  for(int v : ends)
  {
    Info info;
    info.value = v;
    located.emplace_back(project(v), info);
  }
  cdt.insert(located.begin(), located.end());
  const auto position = [&](int v) { return std::size_t(std::lower_bound(ends.begin(), ends.end(), v) - ends.begin()); };
  std::vector<typename CDT::Vertex_handle> vertex(ends.size());
  for(auto v : cdt.finite_vertex_handles())
    vertex[position(v->info().value)] = v;
  for(std::size_t i = 0; i < ends.size(); ++i)
    if(vertex[i] == typename CDT::Vertex_handle()) // at the point of another end: its vertex
      vertex[i] = cdt.insert(located[i].first);
  for(const std::array<int, 2>& side : region.outline)
    cdt.insert_constraint(vertex[position(side[0])], vertex[position(side[1])]);
}

// A constrained Delaunay triangulation of `region`'s outline refined by CGAL's Delaunay mesher
// towards smallest angles of about 20 degrees (no size bound: few points where the outline is
// coarse; at most about as many steps as the region has faces), lifted back onto the region's
// plane, in `out`; false (`out` left empty) when that triangulation does not cover the region's
// area (overlapping faces, crossing sides).
inline bool retriangulate(const Coplanar_region& region, const std::vector<Point_3>& points, Region_cover& out)
{
  typedef CGAL::Epick K;
  struct Index
  {
    int value = -1;          // the mesh vertex, -1 for a point the mesher added
    std::int64_t added = -1; // such a point's place in `out.added`, once lifted
  };
  typedef CGAL::Triangulation_vertex_base_with_info_2<Index, K, CGAL::Delaunay_mesh_vertex_base_2<K> > Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<
    K, CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K> > > Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;

  // The plane, and the coordinate plane it projects onto one to one (the normal's largest axis).
  const std::array<int, 3>& seed = region.faces.front();
  const K::Vector_3 normal = CGAL::cross_product(points[seed[1]] - points[seed[0]], points[seed[2]] - points[seed[0]]);
  const double n[3] = {normal.x(), normal.y(), normal.z()};
  int axis = 0;
  for(int i = 1; i < 3; ++i)
    if(std::abs(n[i]) > std::abs(n[axis]))
      axis = i;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const auto project = [&](const Point_3& p) { return K::Point_2(p[u], p[v]); };
  const Point_3& origin = points[seed[0]];
  const auto lift = [&](const K::Point_2& q) {
    double c[3];
    c[u] = q.x();
    c[v] = q.y();
    c[axis] = origin[axis] - (n[u] * (q.x() - origin[u]) + n[v] * (q.y() - origin[v])) / n[axis];
    return Point_3(c[0], c[1], c[2]);
  };

  double area = 0.;
  for(const auto& f : region.faces)
    area += std::abs(CGAL::area(project(points[f[0]]), project(points[f[1]]), project(points[f[2]])));
  CDT cdt;
  insert_outline(region, [&](int v) { return project(points[v]); }, cdt);
  // The region is the faces an odd number of sides away from the outside.
  mark_constraint_depth(cdt);
  for(auto f : cdt.all_face_handles())
    f->set_in_domain(f->info() % 2 == 1);
  // Refined step by step, a bounded number of steps: next to the small angles of a CAD outline
  // the refinement would add points without end (or millions). Stopped early, the triangulation
  // still covers the region, with some triangles left thin.
  CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > mesher(cdt, CGAL::Delaunay_mesh_criteria_2<CDT>(0.125));
  mesher.init(true);
  const std::size_t most_steps = region.faces.size() + 16;
  for(std::size_t step = 0; step < most_steps && mesher.step_by_step_refine_mesh(); ++step)
  {
  }

  double covered = 0.;
  for(auto f : cdt.finite_face_handles())
    if(f->is_in_domain())
    {
      std::array<std::int64_t, 3> corner;
      for(int i = 0; i < 3; ++i)
      {
        Index& index = f->vertex(i)->info();
        if(index.value < 0 && index.added < 0)
        {
          index.added = std::int64_t(out.added.size());
          out.added.push_back(lift(f->vertex(i)->point()));
        }
        corner[i] = index.value >= 0 ? index.value : -index.added - 1;
      }
      covered += std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
      out.triangles.push_back(corner);
    }
  if(!(std::abs(covered - area) <= 1e-9 * area))
  {
    out = Region_cover();
    return false;
  }
  return true;
}

} // namespace cover

/// Triangles whose union is a mesh's surface, as corners indexed into shared points: a triangle
/// takes 12 bytes, not the 72 of its nine coordinates.
struct Indexed_cover
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;
  typedef CGAL::Simple_cartesian<double>::Triangle_3 Triangle_3;

  std::vector<Point_3> points;
  std::vector<std::array<std::uint32_t, 3> > triangles;

  Triangle_3 triangle(std::size_t t) const
  {
    const std::array<std::uint32_t, 3>& c = triangles[t];
    return Triangle_3(points[c[0]], points[c[1]], points[c[2]]);
  }
};

/// Triangles whose union is the surface of `mesh` (up to the rounding of the points added in
/// its planar regions), for closest-point searches: the faces of each edge-connected region of
/// at least `smallest_region` exactly coplanar faces (by `Epick`'s predicates on the points
/// rounded to double) replaced by its outline's constrained Delaunay triangulation, refined to
/// well-shaped triangles; every other face as it is. The points are the mesh's vertices, by
/// index, then the points the refinements added. The regions are retriangulated in parallel
/// with TBB when `ConcurrencyTag` is `Parallel_tag`; the triangles come in the same order either
/// way (region by region, in the order the regions are found).
/// \throws Error with `Error_code::INVALID_INPUT` when the cover has 2^32 points or triangles or more.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh>
Indexed_cover well_shaped_indexed_cover(const TriangleMesh& mesh, std::size_t smallest_region = 16)
{
  using cover::Point_3;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  auto fim = CGAL::get_initialized_face_index_map(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<Point_3> points(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    points[get(vim, v)] = Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  std::vector<face_descriptor> face_of(num_faces(mesh));
  for(face_descriptor f : faces(mesh))
    face_of[get(fim, f)] = f;
  const auto corners = [&](face_descriptor f) {
    const halfedge_descriptor h = halfedge(f, mesh);
    return std::array<int, 3>{int(get(vim, source(h, mesh))), int(get(vim, target(h, mesh))),
                              int(get(vim, target(next(h, mesh), mesh)))};
  };

  Indexed_cover out;
  out.points.reserve(points.size());
  for(const Point_3& p : points)
    out.points.emplace_back(p.x(), p.y(), p.z());
  out.triangles.reserve(face_of.size());
  // The mesh's vertex indices are ints; the points added and the triangles are counted.
  const auto check_indexable = [](std::size_t count) {
    if(count > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
      throw Error(Error_code::INVALID_INPUT, "well_shaped_indexed_cover: 2^32 points or triangles or more to index");
  };
  const auto append_face = [&](const std::array<int, 3>& c) {
    out.triangles.push_back({{std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])}});
  };
  // The regions found and not yet appended to `out`, retriangulated a batch at a time (the
  // batch's triangles are held twice while they are appended: a bounded batch bounds that).
  std::vector<cover::Coplanar_region> batch;
  std::size_t batch_faces = 0;
  const auto append_batch = [&]() {
    std::vector<cover::Region_cover> retriangulated(batch.size());
    std::vector<char> replaced(batch.size(), 0);
    for_each_index<ConcurrencyTag>(batch.size(), [&](std::size_t i) {
      if(batch[i].faces.size() >= smallest_region)
        replaced[i] = cover::retriangulate(batch[i], points, retriangulated[i]);
    });
    for(std::size_t i = 0; i < batch.size(); ++i)
      if(replaced[i])
      {
        const cover::Region_cover& r = retriangulated[i];
        const std::size_t first_added = out.points.size();
        for(const Point_3& p : r.added)
          out.points.emplace_back(p.x(), p.y(), p.z());
        check_indexable(out.points.size());
        for(const std::array<std::int64_t, 3>& c : r.triangles)
        {
          std::array<std::uint32_t, 3> t;
          for(int k = 0; k < 3; ++k)
            t[k] = std::uint32_t(c[k] >= 0 ? std::size_t(c[k]) : first_added + std::size_t(-c[k] - 1));
          out.triangles.push_back(t);
        }
      }
      else
        for(const auto& f : batch[i].faces)
          append_face(f);
    batch.clear();
    batch_faces = 0;
  };
  constexpr std::size_t batch_size = std::size_t(1) << 18; // faces

  std::vector<int> region_of(face_of.size(), -1);
  std::vector<std::size_t> stack;
  // Regions grow from proper triangles first, which define a plane; what is left (degenerate
  // faces no region took) is copied as it is.
  int regions = 0;
  for(std::size_t start = 0; start < face_of.size(); ++start)
  {
    if(region_of[start] >= 0)
      continue;
    const std::array<int, 3> s = corners(face_of[start]);
    if(CGAL::collinear(points[s[0]], points[s[1]], points[s[2]]))
      continue;
    // The faces coplanar with `start` reached across edges.
    const int r = regions++;
    batch.emplace_back();
    cover::Coplanar_region& region = batch.back();
    region_of[start] = r;
    stack.assign(1, start);
    while(!stack.empty())
    {
      const face_descriptor f = face_of[stack.back()];
      stack.pop_back();
      region.faces.push_back(corners(f));
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
      {
        const face_descriptor g = face(opposite(h, mesh), mesh);
        bool inside = false;
        if(g != boost::graph_traits<TriangleMesh>::null_face())
        {
          const std::size_t k = get(fim, g);
          if(region_of[k] < 0 && CGAL::coplanar(points[s[0]], points[s[1]], points[s[2]],
                                                 points[get(vim, target(next(opposite(h, mesh), mesh), mesh))]))
          {
            region_of[k] = r;
            stack.push_back(k);
          }
          inside = region_of[k] == r;
        }
        if(!inside)
          region.outline.push_back({int(get(vim, source(h, mesh))), int(get(vim, target(h, mesh)))});
      }
    }
    batch_faces += region.faces.size();
    if(batch_faces >= batch_size)
      append_batch();
  }
  append_batch();
  for(std::size_t k = 0; k < face_of.size(); ++k)
    if(region_of[k] < 0)
      append_face(corners(face_of[k]));
  check_indexable(out.triangles.size()); // the closest-point tree indexes the triangles too
  out.points.shrink_to_fit();
  out.triangles.shrink_to_fit();
  return out;
}

/// The triangles of `well_shaped_indexed_cover(mesh, smallest_region)`, each with its corners'
/// coordinates.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh>
std::vector<CGAL::Simple_cartesian<double>::Triangle_3> well_shaped_cover(const TriangleMesh& mesh,
                                                                          std::size_t smallest_region = 16)
{
  const Indexed_cover cover = well_shaped_indexed_cover<ConcurrencyTag>(mesh, smallest_region);
  std::vector<CGAL::Simple_cartesian<double>::Triangle_3> out;
  out.reserve(cover.triangles.size());
  for(std::size_t t = 0; t < cover.triangles.size(); ++t)
    out.push_back(cover.triangle(t));
  return out;
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELL_SHAPED_COVER_H
