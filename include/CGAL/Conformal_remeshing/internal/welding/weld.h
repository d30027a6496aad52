// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Conformal welding (paper Sec. 4.3, Alg. 3, with the holes filled as in Sec. 4.1): a genus-0
// patch with k boundary loops becomes a topological disc given by connectivity and edge lengths
// only, whose free boundary is the inner circle of a planar annulus welded to one loop.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_WELD_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_WELD_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/welding/annulus.h>
#include <CGAL/Conformal_remeshing/internal/constrained_domain.h>
#include <CGAL/Conformal_remeshing/internal/welding/flat_region.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

typedef std::array<double, 3> Vec3;

inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vec3 operator*(double s, const Vec3& a) { return {{s * a[0], s * a[1], s * a[2]}}; }
inline Vec3 operator/(const Vec3& a, double s) { return {{a[0] / s, a[1] / s, a[2] / s}}; }
inline double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
inline double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }

/// A hash key of the edge from vertex `a` to vertex `b`, and of the edge between them.
inline std::uint64_t directed_key(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }
inline std::uint64_t undirected_key(int a, int b) { return directed_key((std::min)(a, b), (std::max)(a, b)); }

/// A copy of the patch as indices, which welding may refine: boundary edges are split at their
/// midpoints, exactly on the input edge, and flat regions retriangulated
/// (retriangulate_flat_regions.h). Every face remembers the input face it lies in and the
/// barycentric coordinates of its corners there, or the flat region it lies in, so that
/// points map back to the input exactly.
struct Indexed_patch
{
  std::vector<Vec3> points;                         // input vertices first, then split points
  std::size_t number_of_input_vertices = 0;
  std::vector<std::array<int, 3> > faces;           // counterclockwise
  std::vector<int> input_face;                      // the input face each face lies in, or -1 - region
  Corner_coordinates input_coordinates;            // barycentric coordinates of the corners there
  std::vector<Flat_region> flat_regions;
  /// the intrinsic lengths of the edges inside developed flat regions (across a bend, the
  /// straight line of the unfolding is longer than the chord in space)
  std::unordered_map<std::uint64_t, double> developed_lengths;
  /// Boundary loops as vertex cycles in the order of the border halfedges: the missing face of
  /// the edge (loop[i], loop[i+1]) lies on its left.
  std::vector<std::vector<int> > boundary_loops;

  double loop_length(const std::vector<int>& loop) const
  {
    double length = 0.;
    for(std::size_t i = 0; i < loop.size(); ++i)
      length += distance(points[loop[i]], points[loop[(i + 1) % loop.size()]]);
    return length;
  }

  /// The diagonal of the points' bounding box.
  double diagonal() const
  {
    Vec3 low = points.front(), high = low;
    for(const Vec3& p : points)
      for(int k = 0; k < 3; ++k)
      {
        low[k] = (std::min)(low[k], p[k]);
        high[k] = (std::max)(high[k], p[k]);
      }
    return distance(high, low);
  }

  /// The length of the edge between vertices `a` and `b` on the surface.
  double edge_length(int a, int b) const
  {
    if(!developed_lengths.empty())
    {
      const auto it = developed_lengths.find(undirected_key(a, b));
      if(it != developed_lengths.end())
        return it->second;
    }
    return distance(points[a], points[b]);
  }

  /// The 3D point at barycentric coordinates `b` of face `f` (in a developed region, of the
  /// original face holding it: the new face's chord plane cuts through a bend).
  Vec3 point_in_face(int f, const std::array<double, 3>& b) const
  {
    if(input_face[f] < 0)
    {
      const Flat_region& region = flat_regions[std::size_t(-1 - input_face[f])];
      if(region.developed)
      {
        const std::pair<int, std::array<double, 3> > old = region.locate(faces[f], b);
        std::array<int, 3> corners;
        for(int c = 0; c < 3; ++c)
          corners[c] = region.vertices[region.faces[old.first][c]];
        return point_at(corners, old.second);
      }
    }
    return point_at(faces[f], b);
  }

  /// The input face and barycentric coordinates of the point at `b` in face `f`.
  std::pair<int, std::array<double, 3> > input_location(int f, const std::array<double, 3>& b) const
  {
    if(input_face[f] >= 0)
      return {input_face[f], interpolate(input_coordinates[f], b)};
    const Flat_region& region = flat_regions[std::size_t(-1 - input_face[f])];
    const std::pair<int, std::array<double, 3> > old = region.locate(faces[f], b);
    return {region.input_face[old.first], interpolate(region.input_coordinates[old.first], old.second)};
  }

  /// Splits the edges of boundary loop `loop_index` longer than `max_length` at their
  /// midpoints, recursively, so that every edge of the loop ends up at most that long.
  void split_long_boundary_edges(std::size_t loop_index, double max_length)
  {
    Edge_faces face_of = directed_edge_faces();
    std::vector<int> refined;
    const std::vector<int> loop = boundary_loops[loop_index];
    for(std::size_t i = 0; i < loop.size(); ++i)
      refine_boundary_edge(loop[i], loop[(i + 1) % loop.size()], max_length, face_of, refined);
    boundary_loops[loop_index] = refined;
    // The splits grew the arrays by doubling their room, which the patch, kept with its
    // flattening until the output is glued, does not need.
    points.shrink_to_fit();
    faces.shrink_to_fit();
    input_face.shrink_to_fit();
    input_coordinates.shrink_to_fit();
  }

private:
  Vec3 point_at(const std::array<int, 3>& corners, const std::array<double, 3>& b) const
  {
    Vec3 p{{0., 0., 0.}};
    for(int c = 0; c < 3; ++c)
      for(int k = 0; k < 3; ++k)
        p[k] += b[c] * points[corners[c]][k];
    return p;
  }

  static std::array<double, 3> interpolate(const std::array<Vec3, 3>& corners, const std::array<double, 3>& b)
  {
    std::array<double, 3> q{{0., 0., 0.}};
    for(int c = 0; c < 3; ++c)
      for(int k = 0; k < 3; ++k)
        q[k] += b[c] * corners[c][k];
    return q;
  }

  typedef std::map<std::pair<int, int>, int> Edge_faces; // directed edge -> the face holding it

  Edge_faces directed_edge_faces() const
  {
    Edge_faces face_of;
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int c = 0; c < 3; ++c)
        face_of[{faces[f][c], faces[f][(c + 1) % 3]}] = int(f);
    return face_of;
  }

  // Appends the chain from a (included) to b (excluded) after splitting the boundary edge (a, b).
  void refine_boundary_edge(int a, int b, double max_length, Edge_faces& face_of, std::vector<int>& chain)
  {
    if(distance(points[a], points[b]) <= max_length)
    {
      chain.push_back(a);
      return;
    }
    const int m = split_edge(a, b, face_of);
    refine_boundary_edge(a, m, max_length, face_of, chain);
    refine_boundary_edge(m, b, max_length, face_of, chain);
  }

  // Splits the edge (a, b) at its midpoint m: each face (x, y, o) holding it as x -> y becomes
  // (x, m, o) and (m, y, o), with the input coordinates of their corners.
  int split_edge(int a, int b, Edge_faces& face_of)
  {
    auto midpoint = [](const Vec3& x, const Vec3& y) { return Vec3{{0.5 * (x[0] + y[0]), 0.5 * (x[1] + y[1]), 0.5 * (x[2] + y[2])}}; };
    const int m = int(points.size());
    points.push_back(midpoint(points[a], points[b]));
    for(const std::pair<int, int>& side : {std::make_pair(a, b), std::make_pair(b, a)})
    {
      const auto it = face_of.find(side);
      if(it == face_of.end())
        continue; // a boundary edge has one side
      const int f = it->second, x = side.first, y = side.second;
      const int c = int(std::find(faces[f].begin(), faces[f].end(), x) - faces[f].begin());
      const int o = faces[f][(c + 2) % 3];
      const Corner_coordinates::Value cf = input_coordinates[f];
      const Vec3 cx = cf[c], cy = cf[(c + 1) % 3], co = cf[(c + 2) % 3];
      const Vec3 cm = midpoint(cx, cy);
      const int g = int(faces.size());
      faces[f] = {{x, m, o}};
      input_coordinates.set(f, {{cx, cm, co}});
      faces.push_back({{m, y, o}});
      input_face.push_back(input_face[f]);
      input_coordinates.push_back({{cm, cy, co}});
      face_of.erase(side);
      face_of[{x, m}] = f;
      face_of[{m, o}] = f;
      face_of[{m, y}] = g;
      face_of[{y, o}] = g;
      face_of[{o, m}] = g;
    }
    return m;
  }
};

/// Copies a triangle mesh into an `Indexed_patch`, with its boundary loops.
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename FaceIndexMap>
Indexed_patch make_indexed_patch(const TriangleMesh& mesh, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  Indexed_patch patch;
  patch.points.resize(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    patch.points[get(vim, v)] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }
  patch.number_of_input_vertices = patch.points.size();
  patch.faces.resize(num_faces(mesh));
  patch.input_face.resize(num_faces(mesh));
  patch.input_coordinates.assign_identity(num_faces(mesh));
  for(auto f : faces(mesh))
  {
    const std::size_t i = get(fim, f);
    const halfedge_descriptor h = halfedge(f, mesh);
    // Corner order of CGAL::Polygon_mesh_processing::locate(): source(h), target(h), target(next(h)).
    patch.faces[i] = {{int(get(vim, source(h, mesh))), int(get(vim, target(h, mesh))),
                       int(get(vim, target(next(h, mesh), mesh)))}};
    patch.input_face[i] = int(i);
  }
  std::unordered_map<halfedge_descriptor, bool> seen;
  for(halfedge_descriptor h : halfedges(mesh))
  {
    if(!is_border(h, mesh) || seen[h])
      continue;
    patch.boundary_loops.emplace_back();
    for(halfedge_descriptor b : halfedges_around_face(h, mesh))
    {
      seen[b] = true;
      patch.boundary_loops.back().push_back(int(get(vim, source(b, mesh))));
    }
  }
  return patch;
}

/// The welded disc: the patch, a fill for each hole, and the annulus, as
/// connectivity and edge lengths. Patch vertices and faces keep their indices.
struct Welded_disc
{
  std::size_t number_of_vertices = 0;
  std::vector<std::array<int, 3> > faces;
  std::vector<std::array<double, 3> > lengths; // lengths[f][c]: edge faces[f][c] -> faces[f][c+1]
  std::size_t patch_faces = 0;
  std::size_t fill_faces = 0;                  // the hole fills follow the patch faces
  std::vector<int> free_boundary;              // the annulus' inner circle, counterclockwise
  std::vector<std::pair<int, int> > seams;     // welded loop and hole loop edges
  double scale = 1.;                           // welded length = 3D length * scale
};

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline Vec3 face_normal(const Indexed_patch& patch, const std::array<int, 3>& f) // twice the area
{
  return cross(patch.points[f[1]] - patch.points[f[0]], patch.points[f[2]] - patch.points[f[0]]);
}

/// The coordinate axis along which `n` has its largest component: dropping that coordinate
/// projects a plane of normal `n` exactly and bijectively (when the projection of one of its
/// triangles is not flat, which the callers check with exact predicates).
inline int dominant_axis(const Vec3& n)
{
  return int(std::max_element(n.begin(), n.end(), [](double x, double y) { return std::abs(x) < std::abs(y); }) - n.begin());
}

/// The normal of the largest face of `patch` (of length twice its area).
inline Vec3 largest_face_normal(const Indexed_patch& patch)
{
  Vec3 normal{{0., 0., 0.}};
  for(const auto& f : patch.faces)
  {
    const Vec3 n = face_normal(patch, f);
    if(dot(n, n) > dot(normal, normal))
      normal = n;
  }
  return normal;
}

/// `true` if every point of `patch` lies within `1e-9` of its diagonal from the plane of its
/// largest face and every face faces the same way (a planar CAD face, or a single triangle).
inline bool is_planar(const Indexed_patch& patch)
{
  const Vec3 normal = largest_face_normal(patch);
  const double diagonal = patch.diagonal();
  if(!(dot(normal, normal) > 0.))
    return false;
  const double unit = norm(normal);
  const Vec3& origin = patch.points[patch.faces.front()[0]];
  for(const Vec3& p : patch.points)
    if(std::abs(dot(p - origin, normal)) / unit > 1e-9 * diagonal)
      return false;
  for(const auto& f : patch.faces)
    if(dot(face_normal(patch, f), normal) <= 0.)
      return false;
  return true;
}

/// The points of a planar patch (`is_planar()`) in an orthonormal frame of its plane, turned
/// so that its faces are counterclockwise. Its layout: the lengths of the intrinsic
/// triangulation give the same up to rounding, but laying out a CAD sliver from its lengths
/// (angles of 1e-7 and less) can fold it, where these coordinates keep it as it is in space.
inline std::vector<std::array<double, 2> > planar_coordinates(const Indexed_patch& patch)
{
  const Vec3 normal = largest_face_normal(patch);
  const Vec3 n = normal / norm(normal);
  // The frame of `Intrinsic_triangulation::layout()`: the first face's corner 0 at the origin,
  // its corner 1 on the first axis (projected on the plane).
  const Vec3& origin = patch.points[patch.faces.front()[0]];
  Vec3 e1 = patch.points[patch.faces.front()[1]] - origin;
  e1 = e1 - dot(e1, n) * n;
  e1 = e1 / norm(e1);
  const Vec3 e2 = cross(n, e1); // (e1, e2, n) is right-handed: counterclockwise seen from n
  std::vector<std::array<double, 2> > uv;
  uv.reserve(patch.points.size());
  for(const Vec3& p : patch.points)
    uv.push_back({{dot(p - origin, e1), dot(p - origin, e2)}});
  return uv;
}

/// The patch itself as the "welded disc" of a planar patch: no annulus, no fill, no seam.
inline Welded_disc unwelded_disc(const Indexed_patch& patch)
{
  Welded_disc disc;
  disc.number_of_vertices = patch.points.size();
  disc.faces = patch.faces;
  disc.patch_faces = patch.faces.size();
  for(const auto& f : patch.faces)
  {
    std::array<double, 3> l;
    for(int c = 0; c < 3; ++c)
      l[c] = distance(patch.points[f[c]], patch.points[f[(c + 1) % 3]]);
    disc.lengths.push_back(l);
  }
  return disc;
}

/// A hole's fill by the triangulation of its loop's polygon: faces on the loop's vertices and on
/// interior points, which are new vertices numbered on from the `first_new` given.
struct Loop_fill
{
  std::vector<std::array<int, 3> > faces;
  std::vector<Vec3> points; // the interior points, on the loop's mean plane
};

/// The constrained Delaunay triangulation of a hole's loop projected to a coordinate plane (the
/// one most facing `normal`), with the points of a square grid of side `spacing` inside it
/// (none for 0) lifted to the plane through `centre` of normal `normal`; its faces hold the
/// loop's edges in the loop's order. No face when the projection is not a simple polygon.
/// Without interior points a long loop's fill is all slivers between its vertices, which the
/// flow then flips with the square of the loop's size as the conformal factors along it change
/// (on a 100k-vertex CAD part, most of a patch's flips can be in the fills of its pockets).
inline Loop_fill triangulate_loop_in_its_plane(const Indexed_patch& patch, const std::vector<int>& loop, const Vec3& centre,
                                               const Vec3& normal, double spacing, int first_new)
{
  typedef Epick K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K> > Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;
  const int dropped = dominant_axis(normal), x_axis = (dropped + 1) % 3, y_axis = (dropped + 2) % 3;
  std::vector<std::pair<K::Point_2, int> > points;
  for(std::size_t i = 0; i < loop.size(); ++i)
    points.emplace_back(K::Point_2(patch.points[loop[i]][x_axis], patch.points[loop[i]][y_axis]), int(i));
  CDT cdt;
  cdt.insert(points.begin(), points.end());
  if(cdt.number_of_vertices() != loop.size())
    return {};
  std::vector<CDT::Vertex_handle> handle(loop.size());
  for(auto v : cdt.finite_vertex_handles())
    handle[v->info()] = v;
  for(std::size_t i = 0; i < loop.size(); ++i)
    cdt.insert_constraint(handle[i], handle[(i + 1) % loop.size()]);
  if(cdt.number_of_vertices() != loop.size())
    return {};
  mark_constraint_depth(cdt);

  Loop_fill fill;
  std::vector<K::Point_2> grid;
  for(const auto& p : grid_points_inside(cdt, spacing))
    grid.push_back(p.first);
  for(CDT::Vertex_handle v : insert_away_from_constraints(cdt, grid, spacing))
    if(v != CDT::Vertex_handle())
    {
      v->info() = int(loop.size() + fill.points.size());
      Vec3 x;
      x[x_axis] = v->point().x();
      x[y_axis] = v->point().y();
      x[dropped] = centre[dropped] - (normal[x_axis] * (x[x_axis] - centre[x_axis]) + normal[y_axis] * (x[y_axis] - centre[y_axis])) / normal[dropped];
      fill.points.push_back(x);
    }
  auto vertex = [&](CDT::Vertex_handle v) {
    return v->info() < int(loop.size()) ? loop[v->info()] : first_new + v->info() - int(loop.size());
  };
  for(auto f : cdt.finite_face_handles())
    if(f->info() % 2 == 1)
      fill.faces.push_back({{vertex(f->vertex(0)), vertex(f->vertex(1)), vertex(f->vertex(2))}});
  if(fill.faces.size() + 2 != loop.size() + 2 * fill.points.size()) // Euler: a disc
    return {};
  // Each loop edge (a, b) must be a side of a fill face, in that direction (the patch has b -> a).
  std::map<std::pair<int, int>, int> sides;
  for(const auto& f : fill.faces)
    for(int c = 0; c < 3; ++c)
      ++sides[{f[c], f[(c + 1) % 3]}];
  bool forward = true, backward = true;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    forward = forward && sides.count({loop[i], loop[(i + 1) % loop.size()]});
    backward = backward && sides.count({loop[(i + 1) % loop.size()], loop[i]});
  }
  if(!forward && !backward)
    return {};
  if(!forward)
    for(auto& f : fill.faces)
      std::swap(f[1], f[2]);
  return fill;
}

/// Whether the fan from `apex` over `loop` is Delaunay: at every spoke, the two angles facing it
/// sum to at most pi (their cotangents to at least 0).
inline bool fan_is_delaunay(const Indexed_patch& patch, const std::vector<int>& loop, const Vec3& apex)
{
  auto cotangent = [&](const Vec3& at, const Vec3& p, const Vec3& q) { // of the angle at `at`
    const Vec3 u = p - at, v = q - at;
    return dot(u, v) / norm(cross(u, v));
  };
  const std::size_t n = loop.size();
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vec3 &previous = patch.points[loop[(i + n - 1) % n]], &spoke_end = patch.points[loop[i]],
               &next = patch.points[loop[(i + 1) % n]];
    if(!(cotangent(previous, spoke_end, apex) + cotangent(next, spoke_end, apex) >= 0.))
      return false;
  }
  return true;
}

/// Welds `patch` along its loop `welded` to a planar annulus of inner radius `inner_radius` and
/// fills its other loops: with a cone vertex, or, where the cone's fan is not Delaunay, by the
/// triangulation of the loop's polygon (when it is simple) with grid points of side
/// `fill_spacing` inside (none for 0). The loop is scaled to the unit circle: the annulus'
/// outer circle is the polygon inscribed in it whose sides are exactly the loop's edge lengths,
/// so both sides of every seam edge have one length.
inline Welded_disc weld(const Indexed_patch& patch, std::size_t welded, double inner_radius, double fill_spacing = 0.)
{
  const std::vector<int>& seam = patch.boundary_loops[welded];
  const std::size_t n = seam.size();
  std::vector<double> seam_lengths(n);
  for(std::size_t i = 0; i < n; ++i)
    seam_lengths[i] = distance(patch.points[seam[i]], patch.points[seam[(i + 1) % n]]);

  Welded_disc disc;
  const double radius = inscribing_radius(seam_lengths);
  disc.scale = 1. / radius;
  auto length = [&](int a, int b) { return disc.scale * patch.edge_length(a, b); };

  for(const auto& f : patch.faces)
  {
    disc.faces.push_back(f);
    disc.lengths.push_back({{length(f[0], f[1]), length(f[1], f[2]), length(f[2], f[0])}});
  }
  disc.patch_faces = patch.faces.size();
  int next_vertex = int(patch.points.size());

  std::unordered_set<std::uint64_t> patch_edges; // undirected keys; made for the first polygon fill
  // A fill per hole: a cone vertex lifted off the hole along its normal so that no fan triangle
  // is flat, or the loop's polygon triangulated.
  for(std::size_t l = 0; l < patch.boundary_loops.size(); ++l)
  {
    if(l == welded)
      continue;
    const std::vector<int>& loop = patch.boundary_loops[l];
    Vec3 centre{{0., 0., 0.}}, normal{{0., 0., 0.}};
    for(int v : loop)
      for(int k = 0; k < 3; ++k)
        centre[k] += patch.points[v][k] / double(loop.size());
    for(std::size_t i = 0; i < loop.size(); ++i) // Newell's normal of the loop
    {
      const Vec3& p = patch.points[loop[i]];
      const Vec3& q = patch.points[loop[(i + 1) % loop.size()]];
      normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
      normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
      normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    double mean_radius = 0.;
    for(int v : loop)
      mean_radius += distance(centre, patch.points[v]) / double(loop.size());
    const double nn = norm(normal);
    Vec3 apex = centre;
    if(nn > 0.)
      for(int k = 0; k < 3; ++k)
        apex[k] += 0.5 * mean_radius * normal[k] / nn;
    // A cone whose fan is Delaunay fills the hole (a round hole's does). One that is not is far
    // from it on a long loop with straight runs (a pocket cut by a plane): Lawson's flips from it
    // go round in circles among the nearly collinear loop vertices up to the flip cap, on every
    // pass (millions of flips on a patch of a 100k-vertex CAD part). Such a hole is filled by the
    // constrained Delaunay triangulation of its polygon seen along its normal, when that polygon
    // is simple (tens of thousands of flips there instead, and the patch flattens almost twice as
    // fast). (Round holes keep the cone: polygon fills for them too make worse pulled-back
    // triangles near small holes.)
    const bool delaunay_cone = fan_is_delaunay(patch, loop, apex);
    const Loop_fill fill = delaunay_cone || loop.size() < 8 ? Loop_fill()
                                                            : triangulate_loop_in_its_plane(patch, loop, centre, normal, fill_spacing, next_vertex);
    // A chord of the loop that the patch has already (outside the hole) would be doubled.
    bool doubles_an_edge = false;
    if(!fill.faces.empty())
    {
      if(patch_edges.empty())
        for(const auto& f : patch.faces)
          for(int c = 0; c < 3; ++c)
            patch_edges.insert(undirected_key(f[c], f[(c + 1) % 3]));
      std::unordered_set<std::uint64_t> loop_edges; // directed, in the loop's order
      for(std::size_t i = 0; i < loop.size(); ++i)
        loop_edges.insert(directed_key(loop[i], loop[(i + 1) % loop.size()]));
      for(const auto& f : fill.faces)
        for(int c = 0; c < 3; ++c)
          if(!loop_edges.count(directed_key(f[c], f[(c + 1) % 3])))
            doubles_an_edge = doubles_an_edge || patch_edges.count(undirected_key(f[c], f[(c + 1) % 3]));
    }
    if(!fill.faces.empty() && !doubles_an_edge)
    {
      const int first_new = next_vertex;
      auto point = [&](int v) -> const Vec3& { return v < first_new ? patch.points[v] : fill.points[v - first_new]; };
      for(const auto& f : fill.faces)
      {
        disc.faces.push_back(f);
        std::array<double, 3> l;
        for(int c = 0; c < 3; ++c)
        {
          const int a = f[c], b = f[(c + 1) % 3];
          l[c] = a < first_new && b < first_new ? length(a, b) : disc.scale * distance(point(a), point(b));
        }
        disc.lengths.push_back(l);
      }
      next_vertex += int(fill.points.size());
      for(std::size_t i = 0; i < loop.size(); ++i)
        disc.seams.push_back({loop[i], loop[(i + 1) % loop.size()]});
      continue;
    }
    const int cone = next_vertex++;
    for(std::size_t i = 0; i < loop.size(); ++i)
    {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      disc.faces.push_back({{a, b, cone}});
      disc.lengths.push_back({{length(a, b), disc.scale * distance(patch.points[b], apex),
                               disc.scale * distance(apex, patch.points[a])}});
      disc.seams.push_back({a, b});
    }
  }
  disc.fill_faces = disc.faces.size() - disc.patch_faces;

  // The annulus: outer circle through the seam vertices, counterclockwise in the loop's order.
  std::vector<std::array<double, 2> > outer(n);
  double angle = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    outer[i] = {{std::cos(angle), std::sin(angle)}};
    angle += 2. * std::asin((std::min)(1., seam_lengths[i] / (2. * radius)));
  }
  const std::size_t inner_count = (std::max<std::size_t>)(16, std::size_t(std::ceil(double(n) * inner_radius)));
  const Planar_annulus annulus = make_annulus(outer, inner_radius, inner_count);
  std::vector<int> vertex_of(annulus.points.size());
  for(std::size_t i = 0; i < annulus.points.size(); ++i)
    vertex_of[i] = (i < n) ? seam[i] : next_vertex++;
  for(std::size_t i = 0; i < annulus.inner; ++i)
    disc.free_boundary.push_back(vertex_of[n + i]);
  for(std::size_t i = 0; i < n; ++i)
    disc.seams.push_back({seam[i], seam[(i + 1) % n]});

  for(const auto& f : annulus.faces)
  {
    std::array<int, 3> face;
    std::array<double, 3> l;
    for(int c = 0; c < 3; ++c)
    {
      const int i = f[c], j = f[(c + 1) % 3];
      face[c] = vertex_of[i];
      // A seam edge takes the patch's length; elsewhere the annulus is planar.
      const bool on_seam = i < int(n) && j < int(n) && (j == (i + 1) % int(n));
      l[c] = on_seam ? length(seam[i], seam[j])
                     : std::hypot(annulus.points[i][0] - annulus.points[j][0], annulus.points[i][1] - annulus.points[j][1]);
    }
    disc.faces.push_back(face);
    disc.lengths.push_back(l);
  }
  disc.number_of_vertices = std::size_t(next_vertex);
  return disc;
}

/// Opens the faces of `disc` that its double lengths make flat. A CAD sliver whose largest
/// angle is within about 1e-8 of pi is a valid triangle in space (exact predicates) but not in
/// lengths: its longest side rounds to the sum of the other two or more. Such a side is
/// shortened, in both faces that share it, until the face has a margin of 64 ulps (a relative
/// change of about 1e-14 of one length: the apex moves by about 1e-7 of the side off the line
/// through its ends, where the face was already at its rounding floor). A side shortened
/// this way may flatten the face across it, where it is a shorter side; that face is opened in
/// turn, at its own longest side, so the chain goes to ever longer edges and ends. Returns the
/// number of sides shortened; the lengths are left as they are past `4 * faces` of them (the
/// intrinsic triangulation then says which face is flat).
inline std::size_t open_numerically_flat_faces(Welded_disc& disc)
{
  const double margin = 64. * std::numeric_limits<double>::epsilon();
  const std::size_t nf = disc.faces.size();
  // The longest side of face f, if the face lacks the margin; -1 otherwise.
  auto flat_side = [&](std::size_t f) {
    const std::array<double, 3>& l = disc.lengths[f];
    const int c = int(std::max_element(l.begin(), l.end()) - l.begin());
    const double x = l[c], y = l[(c + 1) % 3], z = l[(c + 2) % 3];
    return (y + z) - x > margin * x ? -1 : c;
  };
  std::vector<std::size_t> flat;
  for(std::size_t f = 0; f < nf; ++f)
    if(flat_side(f) >= 0)
      flat.push_back(f);
  if(flat.empty())
    return 0;
  std::unordered_map<std::uint64_t, std::size_t> side_of; // directed edge -> 3 * face + side
  side_of.reserve(3 * nf);
  for(std::size_t f = 0; f < nf; ++f)
    for(int c = 0; c < 3; ++c)
      side_of.emplace(directed_key(disc.faces[f][c], disc.faces[f][(c + 1) % 3]), 3 * f + std::size_t(c));
  std::size_t shortened = 0;
  while(!flat.empty() && shortened < 4 * nf)
  {
    const std::size_t f = flat.back();
    flat.pop_back();
    const int c = flat_side(f);
    if(c < 0)
      continue;
    std::array<double, 3>& l = disc.lengths[f];
    const double x = l[c], opened = (l[(c + 1) % 3] + l[(c + 2) % 3]) - 2. * margin * x;
    if(!(opened > 0.))
      continue; // not a sliver: a side of length zero, rejected by the triangulation
    l[c] = opened;
    ++shortened;
    const auto twin = side_of.find(directed_key(disc.faces[f][(c + 1) % 3], disc.faces[f][c]));
    if(twin != side_of.end())
    {
      disc.lengths[twin->second / 3][twin->second % 3] = opened;
      if(flat_side(twin->second / 3) >= 0)
        flat.push_back(twin->second / 3);
    }
  }
  return shortened;
}

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_WELD_H
