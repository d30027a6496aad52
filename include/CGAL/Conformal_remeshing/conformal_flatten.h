// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Flattening of a genus-0 patch with any number of boundary loops onto a planar domain, with no
// overlap anywhere: conformal welding, discrete Ricci flow, layout, exact embedding check.

#ifndef CGAL_CONFORMAL_REMESHING_CONFORMAL_FLATTEN_H
#define CGAL_CONFORMAL_REMESHING_CONFORMAL_FLATTEN_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Intrinsic_triangulation.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/check_planar_embedding.h>
#include <CGAL/Conformal_remeshing/discrete_ricci_flow.h>
#include <CGAL/Conformal_remeshing/parameters.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/welding/retriangulate_flat_regions.h>
#include <CGAL/Conformal_remeshing/internal/welding/weld.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <sstream>
#include <string>
#include <vector>


namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// A point of the planar domain's boundary, with the surface point it is the image of.
struct Domain_point
{
  Epick::Point_2 uv;
  Epick::Point_3 point;
  /// the input face holding `point`, and its barycentric coordinates there (in the corner order
  /// of `CGAL::Polygon_mesh_processing::locate()`)
  std::size_t input_face = 0;
  std::array<double, 3> input_coordinates{{0., 0., 0.}};
  /// the input vertex (by the vertex index map) this point is the image of, or `none` for a
  /// point inside an input edge
  std::size_t input_vertex = none;
  static constexpr std::size_t none = std::size_t(-1);
};

/// \ingroup PkgConformalRemeshingRef
/// What happened during `conformal_flatten()`.
struct Flattening_report
{
  /// `SUCCESS`, `NOT_CONVERGED` (the flow stopped above its tolerance) or `NOT_AN_EMBEDDING`
  Error_code status = Error_code::SUCCESS;
  bool converged = false;
  int iterations = 0;
  double curvature_error = 0.;
  std::size_t flips = 0;
  /// part of `flips`: those in the hole fills (a fill by a loop's polygon without interior
  /// points flipped with the square of the loop's size)
  std::size_t hole_fill_flips = 0;
  std::size_t boundary_loops = 0;
  /// boundary edges split at their midpoints before welding (the welded loop's edges are kept
  /// below 1/32 of its length, so that the annulus' inscribed polygon is well defined)
  std::size_t boundary_splits = 0;
  /// intrinsic edges split at their midpoints because they were longer than `maximum_edge_length`
  std::size_t edge_splits = 0;
  /// when the flow on the input's own edges did not give an embedding (long slivers shear it),
  /// the edge length to which the flow's edges were split for the flattening returned (a
  /// fiftieth or a hundredth of the diagonal); 0 when not needed or `maximum_edge_length` is given
  double refined_edge_length = 0.;
  /// faces of flat regions (developable or exactly coplanar) replaced by their constrained
  /// Delaunay triangulation in the plane before the flips (a CAD fan of slivers needs a number
  /// of flips quadratic in its size)
  std::size_t retriangulated_faces = 0;
  std::size_t welded_vertices = 0;  ///< vertices of the welded disc (patch, fills, annulus)
  /// sides shortened by about 1e-14 of their length to open faces that are flat in double
  /// lengths (CAD slivers whose largest angle is within about 1e-8 of pi; see the manual)
  std::size_t flat_sides_shortened = 0;
  /// range of the local scale of the map (planar length over surface length) at the input vertices
  double min_scale = 0.;
  double max_scale = 0.;
  /// the exact check of the final triangulation of the patch region with its boundary loops
  Planar_embedding_report embedding;
  /// input triangles whose corners' uv are not counterclockwise: the flat metric's triangulation
  /// differs from the input's, so straight input triangles in uv may fold even though the map
  /// itself is an embedding (informative only)
  std::size_t folded_input_triangles_in_uv = 0;
  double seconds_welding = 0., seconds_flow = 0., seconds_layout = 0., seconds_check = 0.;
  /// part of `seconds_welding`: the intrinsic Delaunay flips and splits of `maximum_edge_length`
  double seconds_refinement = 0.;
  /// why the flow stopped (`Ricci_flow_result::message`)
  std::string flow_message;
  /// parts of `seconds_flow`: flips and splits, Hessian factorizations, triangular solves and
  /// conjugate gradients, line search (the rest is the assembly of curvatures and Hessian)
  double seconds_flips = 0., seconds_factorization = 0., seconds_solve = 0., seconds_line_search = 0.;
};

/// \ingroup PkgConformalRemeshingRef
/// The part of the welded disc a face of the flat triangulation belongs to.
enum class Welded_region : unsigned char
{
  PATCH,     ///< the input patch
  HOLE_FILL, ///< the cone fill of a hole
  ANNULUS    ///< the welded annulus
};

/// \ingroup PkgConformalRemeshingRef
/// The result of `conformal_flatten()`: the planar position of every input vertex, the planar
/// domain with the surface points of its boundary, and the map from the plane to the surface.
namespace internal {
namespace flattening {
struct Patch_access;
} // namespace flattening
} // namespace internal

struct Conformal_flattening
{
  /// the planar position of input vertex `i` (by the vertex index map)
  std::vector<Epick::Point_2> uv;
  /// the conformal factor at each input vertex: the `log` of the local scale of the map there
  /// (planar length over surface length), from the flow's vertex scaling
  std::vector<double> conformal_factor;
  /// the outer boundary of the domain, counterclockwise
  std::vector<Domain_point> outer_boundary;
  /// the holes, clockwise
  std::vector<std::vector<Domain_point> > holes;
  Flattening_report report;

  /// The flat triangulation of the patch region: vertex positions and triangles
  /// (counterclockwise). Together with `to_surface()` this is the plane to surface map.
  std::vector<Epick::Point_2> layout;
  std::vector<std::array<int, 3> > triangles;
  std::vector<int> triangle_face; ///< the face of `triangulation` each of `triangles` is
  /// the region of every face of `triangulation` (whose vertices are laid out in `layout`)
  std::vector<Welded_region> face_region;

  /// A point of the patch region: a face of `patch` and barycentric coordinates there.
  typedef std::pair<int, std::array<double, 3> > Patch_location;

  /// Where the point at barycentric coordinates `b` of `triangles[t]` lies on the patch, through
  /// the bijective correspondence of the flow (a walk back through its flips and splits).
  Patch_location patch_location_of_triangle(std::size_t t, const std::array<double, 3>& b) const
  {
    typedef Intrinsic_triangulation<double>::Face_location Location;
    const Location initial = triangulation.to_input(Location{triangle_face[t], {{b[0], b[1], b[2]}}});
    return patch_location(initial.face, {{initial.coordinates[0], initial.coordinates[1], initial.coordinates[2]}});
  }

  /// The surface point at a patch location, with its input face and barycentric coordinates
  /// there (`uv` is left at the origin).
  Domain_point to_surface(const Patch_location& l) const
  {
    Domain_point p;
    p.uv = Epick::Point_2(0., 0.);
    p.point = surface_point(l);
    const auto location = patch_.input_location(l.first, l.second);
    p.input_face = std::size_t(location.first);
    p.input_coordinates = location.second;
    return p;
  }

  /// The surface point at a patch location alone, without locating it in an input face (which
  /// takes a walk in a retriangulated flat region; a developed one takes it for the point too).
  Epick::Point_3 surface_point(const Patch_location& l) const
  {
    const internal::welding::Vec3 x = patch_.point_in_face(l.first, l.second);
    return Epick::Point_3(x[0], x[1], x[2]);
  }

  /// The surface point at barycentric coordinates `b` of `triangles[t]`: the input face and
  /// barycentric coordinates there, through the bijective correspondence of the flow.
  Domain_point to_surface(std::size_t t, const std::array<double, 3>& b) const
  {
    Domain_point p = to_surface(patch_location_of_triangle(t, b));
    p.uv = Epick::Point_2(b[0] * layout[triangles[t][0]].x() + b[1] * layout[triangles[t][1]].x() + b[2] * layout[triangles[t][2]].x(),
                          b[0] * layout[triangles[t][0]].y() + b[1] * layout[triangles[t][1]].y() + b[2] * layout[triangles[t][2]].y());
    return p;
  }

  /// The surface point of `to_surface(t, b)` alone.
  Epick::Point_3 surface_point(std::size_t t, const std::array<double, 3>& b) const
  {
    return surface_point(patch_location_of_triangle(t, b));
  }

  /// The surface point at corner `c` of `triangles[t]`: the image of that vertex.
  Domain_point corner_to_surface(std::size_t t, int c) const
  {
    std::array<double, 3> b{{0., 0., 0.}};
    b[c] = 1.;
    return to_surface(t, b);
  }

  /// the final intrinsic triangulation of the welded disc
  Intrinsic_triangulation<double> triangulation;
  /// the faces of the welded disc before the flow (the patch's faces first)
  std::vector<std::array<int, 3> > welded_faces;
  /// the patch faces around each patch vertex `v`: `faces_of_vertex[faces_of_vertex_start[v] ..
  /// faces_of_vertex_start[v + 1])`
  std::vector<int> faces_of_vertex_start, faces_of_vertex;

  /// The number of points of the patch the flow started from: the input vertices (by the vertex
  /// index map), then the points that split its boundary edges.
  std::size_t number_of_patch_points() const { return patch_.points.size(); }

  /// Point `i` of the patch the flow started from.
  Epick::Point_3 patch_point(std::size_t i) const
  {
    const internal::welding::Vec3& x = patch_.points[i];
    return Epick::Point_3(x[0], x[1], x[2]);
  }

private:
  friend struct internal::flattening::Patch_access;
  // The patch the flow started from: a copy of the input patch as indices, with its boundary
  // edges split and its flat regions retriangulated (see weld.h).
  internal::welding::Indexed_patch patch_;

  // A location in a face of the welded disc, as a location in a patch face. A point of the patch
  // that lies on a seam (a boundary or hole loop) may come back from the correspondence in the
  // annulus or hole fill beside it, with weight only on seam vertices: it is moved across.
  std::pair<int, std::array<double, 3> > patch_location(int face, std::array<double, 3> b) const
  {
    if(face < int(patch_.faces.size()))
      return {face, b};
    const std::array<int, 3>& corners = welded_faces[face];
    const int patch_vertices = int(patch_.points.size());
    double kept = 0.;
    for(int c = 0; c < 3; ++c)
    {
      if(corners[c] >= patch_vertices)
        b[c] = 0.;
      kept += b[c];
    }
    std::array<double, 3> result{{0., 0., 0.}};
    int best_face = -1, best_shared = 0;
    // The seam vertex with the most weight: the patch face sought is one of its faces. (Not just
    // any vertex with weight: a face of a hole's fill may have a third seam vertex far away,
    // with a weight of rounding.)
    int anchor = -1;
    for(int c = 0; c < 3; ++c)
      if(b[c] > 0. && (anchor < 0 || b[c] > b[std::find(corners.begin(), corners.end(), anchor) - corners.begin()]))
        anchor = corners[c];
    for(int k = (anchor < 0 ? 0 : faces_of_vertex_start[anchor]); anchor >= 0 && k < faces_of_vertex_start[anchor + 1]; ++k)
    {
      const int f = faces_of_vertex[k];
      int shared = 0;
      for(int c = 0; c < 3; ++c)
        shared += (b[c] > 0. && std::find(patch_.faces[f].begin(), patch_.faces[f].end(), corners[c]) != patch_.faces[f].end());
      if(shared > best_shared)
      {
        best_shared = shared;
        best_face = f;
      }
    }
    if(best_face < 0 || kept <= 0.)
      throw Error(Error_code::NOT_AN_EMBEDDING, "conformal_flatten: a point of the patch maps outside it (internal error)");
    // (A hole filled by a triangulation of its loop has faces with three seam vertices: the
    // weight of one that the patch face lacks is dropped too, as that of a fill's own points.)
    double matched = 0.;
    for(int c = 0; c < 3; ++c)
      for(int d = 0; d < 3; ++d)
        if(patch_.faces[best_face][d] == corners[c])
        {
          result[d] += b[c];
          matched += b[c];
        }
    for(double& x : result)
      x /= matched;
    return {best_face, result};
  }
};

namespace internal {

// Orders the boundary halfedges of a set of faces into loops, with the faces on the left.
// The patch region of a flattening is a manifold with boundary. When a folded layout makes it
// pinched at a vertex (two boundary halfedges leaving it) or its boundary does not close into
// simple loops, the layout cannot be an embedding: that is reported, not walked.
inline std::vector<std::vector<int> > region_boundary_loops(const Intrinsic_triangulation<double>& tri,
                                                            const std::vector<char>& in_region)
{
  auto not_simple = [](const char* what, int v) {
    return Error(Error_code::NOT_AN_EMBEDDING, std::string("conformal_flatten: the patch region of the flattened "
                                                           "triangulation ") + what + " at vertex " + std::to_string(v)
                                                 + " (a folded layout)");
  };
  std::map<int, int> next_vertex; // along each loop, faces on the left
  for(int f = 0; f < tri.number_of_faces(); ++f)
  {
    if(!in_region[f])
      continue;
    for(int c = 0; c < 3; ++c)
    {
      const int h = Intrinsic_triangulation<double>::halfedge(f, c);
      const int twin = tri.opposite(h);
      if((twin < 0 || !in_region[Intrinsic_triangulation<double>::face(twin)])
         && !next_vertex.emplace(tri.source(h), tri.target(h)).second)
        throw not_simple("is pinched", tri.source(h));
    }
  }
  std::vector<std::vector<int> > loops;
  std::map<int, bool> used;
  for(const auto& start : next_vertex)
  {
    if(used[start.first])
      continue;
    loops.emplace_back();
    int v = start.first;
    do
    {
      if(used[v])
        throw not_simple("has a boundary that runs into itself", v);
      used[v] = true;
      loops.back().push_back(v);
      const auto next = next_vertex.find(v);
      if(next == next_vertex.end())
        throw not_simple("has a boundary that stops", v);
      v = next->second;
    } while(v != start.first);
  }
  return loops;
}

// Splits the edges of the patch region of `tri` (edges of its first `patch_faces` faces, and of
// the faces that flips and these splits make of them) longer than `maximum_length` at their midpoints, in the intrinsic
// Delaunay triangulation, until none is left, so that the conformal factor is resolved at that
// length everywhere. Splitting on the input instead keeps a long CAD sliver a fan of slivers,
// which the flow's first flips then undo (tens of millions of flips on a large CAD part). The
// longest edge goes first and the Delaunay property is restored around each new vertex before
// the next split: splitting all long edges of a round at once puts the midpoints of a CAD fan's
// edges on one arc, as close together as the fan's slivers, and refines from there (dozens of
// times the splits needed to resolve the area at that length). Counts the splits in `splits`;
// false past `split_limit` of them (a length far below the mesh's edges would split without end
// in sight).
inline bool split_long_patch_edges(Intrinsic_triangulation<double>& tri, std::size_t patch_faces,
                                   double maximum_length, std::size_t split_limit, std::size_t& splits)
{
  typedef Intrinsic_triangulation<double> Tri;
  // Flips keep a face in its region (they never cross a seam); a split face's new half is
  // appended, in the region of the face it comes from.
  std::vector<char> in_patch(tri.number_of_faces(), 0);
  std::fill(in_patch.begin(), in_patch.begin() + std::ptrdiff_t((std::min)(patch_faces, in_patch.size())), 1);
  auto is_long = [&](int e) {
    const int h = tri.halfedge(e), t = tri.opposite(h);
    return tri.length(e) > maximum_length && (in_patch[Tri::face(h)] || (t >= 0 && in_patch[Tri::face(t)]));
  };
  // A halfedge leaving `v` in a face of edge `e`, or -1 if `e` does not end at `v`.
  auto leaving = [&](int v, int e) {
    const int h = tri.halfedge(e);
    return tri.source(h) == v ? h : (tri.target(h) == v ? Tri::next(h) : -1);
  };
  // The halfedges leaving `v`, counterclockwise, from either end of its fan on the boundary.
  std::vector<int> around;
  auto outgoing = [&](int v, int start) {
    around.clear();
    int h = start;
    do
    {
      around.push_back(h);
      const int twin = tri.opposite(Tri::prev(h));
      if(twin < 0)
        break;
      h = twin;
    } while(h != start);
    if(h != start) // a boundary vertex: the other side of the fan
      for(int t = tri.opposite(start); t >= 0 && tri.source(Tri::next(t)) == v;)
      {
        h = Tri::next(t);
        around.push_back(h);
        t = tri.opposite(h);
      }
  };
  splits = 0;
  tri.make_delaunay();
  std::priority_queue<std::pair<double, int> > longest;
  for(;;)
  {
    for(int e = 0; e < tri.number_of_edges(); ++e)
      if(is_long(e))
        longest.emplace(tri.length(e), e);
    if(longest.empty())
      return true;
    std::size_t done = 0;
    while(!longest.empty())
    {
      const std::pair<double, int> top = longest.top();
      longest.pop();
      if(tri.length(top.second) != top.first || !is_long(top.second))
        continue; // flipped since it was queued
      if(splits >= split_limit)
        return false;
      const int h = tri.halfedge(top.second), t = tri.opposite(h);
      const char region_a = in_patch[Tri::face(h)], region_b = t >= 0 ? in_patch[Tri::face(t)] : 0;
      const int v = tri.split_edge(top.second);
      if(v < 0) // refused by rounding: a sliver too thin to split
        continue;
      in_patch.push_back(region_a); // the new faces: the one from h's face, then the one from t's
      if(t >= 0)
        in_patch.push_back(region_b);
      ++splits;
      ++done;
      // The split keeps the first half in the edge, so the edge still ends at v.
      outgoing(v, leaving(v, top.second));
      std::vector<int> link;
      for(int g : around)
        link.push_back(tri.edge(Tri::next(g)));
      tri.make_delaunay(link);
      // Lawson's flips after an insertion make edges at the new vertex only (the next round's
      // scan finds any other, should rounding flip elsewhere).
      const int out = leaving(v, top.second);
      if(out < 0)
        continue;
      outgoing(v, out);
      for(int g : around)
        if(is_long(tri.edge(g)))
          longest.emplace(tri.length(tri.edge(g)), tri.edge(g));
    }
    if(done == 0)
      return true;
  }
}

namespace flattening {

/// The flattening steps' access to the patch a flattening starts from.
struct Patch_access
{
  static welding::Indexed_patch& of(Conformal_flattening& f) { return f.patch_; }
  static const welding::Indexed_patch& of(const Conformal_flattening& f) { return f.patch_; }
};

// The state the steps of `conformal_flatten()` share, besides the result they fill.
struct Flattening_state
{
  // a planar patch (a CAD face), laid out isometrically with no welding, no flow and no split
  bool planar = false;
  // the boundary loop welded to the annulus (the outer boundary of the domain)
  std::size_t welded = 0;
  // `maximum_edge_length`, 0 for no splitting
  double maximum_length = 0.;
  // the welded disc (or, for a planar patch, the patch alone)
  welding::Welded_disc disc;
  // the flips of the refinement before the flow (part of `Flattening_report::flips`)
  std::size_t refinement_flips = 0;
  Ricci_flow_result<double> flow;
  // the faces of the final triangulation in the patch region
  std::vector<char> in_patch;
  // the boundary loops of the patch region, the outer one first
  std::vector<std::vector<int> > loops;
};

// The input must be a patch: valid, connected, genus 0, with a boundary.
template <typename TriangleMesh, typename NamedParameters>
Mesh_check_report check_patch(const TriangleMesh& mesh, const NamedParameters& np)
{
  Mesh_check_report checks = check_mesh(mesh, np);
  // Two vertices at one place are fine here: a patch cut from a surface may touch itself at a
  // vertex, which its mesh has twice. Every other defect is not.
  if(!checks.is_manifold_surface())
    throw Error(Error_code::INVALID_INPUT, "conformal_flatten: invalid input mesh: " + checks.summary());
  if(checks.components.size() != 1)
    throw Error(Error_code::INVALID_INPUT, "conformal_flatten: the mesh has " + std::to_string(checks.components.size())
                                             + " connected components; a patch has one");
  if(checks.components[0].genus != 0)
    throw Error(Error_code::INVALID_INPUT, "conformal_flatten: the mesh has genus " + std::to_string(checks.components[0].genus)
                                             + "; a patch must have genus 0 (cut its handles first)");
  if(checks.components[0].boundary_loops == 0)
    throw Error(Error_code::INVALID_INPUT, "conformal_flatten: the mesh is closed; a patch needs at least one boundary loop");
  return checks;
}

// The inner radius of the annulus, in (0, 1), the outer radius being 1.
template <typename NamedParameters>
double checked_inner_radius(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double inner_radius = choose_parameter(get_parameter(np, internal_np::annulus_inner_radius), 0.3);
  if(!(inner_radius > 0. && inner_radius < 1.))
    throw Error(Error_code::INVALID_INPUT, "conformal_flatten: the annulus inner radius must be in (0, 1)");
  return inner_radius;
}

// Valid coordinates can still be out of range for the lengths and areas the flow computes
// (their squares overflow or underflow): say so rather than fail on a zero length later.
inline void check_edge_length_range(const welding::Indexed_patch& patch)
{
  for(const auto& f : patch.faces)
    for(int c = 0; c < 3; ++c)
    {
      const double length = internal::welding::distance(patch.points[f[c]], patch.points[f[(c + 1) % 3]]);
      if(!(length >= 1e-125 && length <= 1e125))
      {
        std::ostringstream os;
        os << "conformal_flatten: an edge length of " << length
           << " is out of the range of the flow's double precision computations (1e-125 to 1e125); scale the mesh";
        throw Error(Error_code::INVALID_INPUT, os.str());
      }
    }
}

// The loop to weld: the one of the given border halfedge, or the longest.
template <typename TriangleMesh, typename VertexIndexMap, typename NamedParameters>
std::size_t welded_loop(const TriangleMesh& mesh, VertexIndexMap vim, const welding::Indexed_patch& patch,
                        const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::size_t welded = 0;
  const auto chosen = get_parameter(np, internal_np::welded_boundary);
  if constexpr(!std::is_same<std::decay_t<decltype(chosen)>, CGAL::internal_np::Param_not_found>::value)
  {
    const halfedge_descriptor h = chosen;
    if(!is_border(h, mesh))
      throw Error(Error_code::INVALID_INPUT, "conformal_flatten: welded_boundary() needs a border halfedge");
    const int v = int(get(vim, source(h, mesh)));
    for(std::size_t l = 0; l < patch.boundary_loops.size(); ++l)
      if(std::find(patch.boundary_loops[l].begin(), patch.boundary_loops[l].end(), v) != patch.boundary_loops[l].end())
        welded = l;
  }
  else
  {
    for(std::size_t l = 1; l < patch.boundary_loops.size(); ++l)
      if(patch.loop_length(patch.boundary_loops[l]) > patch.loop_length(patch.boundary_loops[welded]))
        welded = l;
  }
  return welded;
}

// Before the welding of a patch that is not planar: the welded loop's long edges are split, and
// the flat regions retriangulated.
inline void prepare_patch(welding::Indexed_patch& patch, const Flattening_state& state, Flattening_report& report)
{
  const std::size_t points_before = patch.points.size();
  patch.split_long_boundary_edges(state.welded, patch.loop_length(patch.boundary_loops[state.welded]) / 32.);
  report.boundary_splits = patch.points.size() - points_before;
  // (A planar patch is not flipped: its own triangles are laid out.) Grid points inside the
  // coplanar regions at 1/1.5 of the maximum length: the diagonals of their squares are short
  // enough not to be split.
  report.retriangulated_faces = internal::welding::retriangulate_flat_regions(patch, state.maximum_length / 1.5);
}

// The patch faces around each patch vertex (`Conformal_flattening::faces_of_vertex`).
inline void index_faces_of_vertices(Conformal_flattening& result)
{
  const welding::Indexed_patch& patch = Patch_access::of(result);
  result.faces_of_vertex_start.assign(patch.points.size() + 1, 0);
  for(const auto& f : patch.faces)
    for(int v : f)
      ++result.faces_of_vertex_start[v + 1];
  for(std::size_t v = 0; v < patch.points.size(); ++v)
    result.faces_of_vertex_start[v + 1] += result.faces_of_vertex_start[v];
  result.faces_of_vertex.resize(result.faces_of_vertex_start.back());
  {
    std::vector<int> fill(result.faces_of_vertex_start.begin(), result.faces_of_vertex_start.end() - 1);
    for(std::size_t f = 0; f < patch.faces.size(); ++f)
      for(int v : patch.faces[f])
        result.faces_of_vertex[fill[v]++] = int(f);
  }
}

// The welded disc (for a planar patch, the patch alone) and its intrinsic triangulation, whose
// seams (welded and hole loops) are never flipped.
inline void weld_patch(Conformal_flattening& result, Flattening_state& state, double inner_radius)
{
  const welding::Indexed_patch& patch = Patch_access::of(result);
  Flattening_report& report = result.report;
  state.disc = state.planar ? internal::welding::unwelded_disc(patch)
                            : internal::welding::weld(patch, state.welded, inner_radius, state.maximum_length / 1.5);
  welding::Welded_disc& disc = state.disc;
  report.flat_sides_shortened = internal::welding::open_numerically_flat_faces(disc);
  result.welded_faces = disc.faces;
  index_faces_of_vertices(result);
  report.welded_vertices = disc.number_of_vertices;
  Intrinsic_triangulation<double>& tri = result.triangulation;
  tri = Intrinsic_triangulation<double>(disc.number_of_vertices, disc.faces, disc.lengths);
  {
    std::map<std::pair<int, int>, bool> seam;
    for(const auto& e : disc.seams)
      seam[std::minmax(e.first, e.second)] = true;
    for(int f = 0; f < tri.number_of_faces(); ++f)
      for(int c = 0; c < 3; ++c)
        if(seam.count(std::minmax(tri.vertex(f, c), tri.vertex(f, (c + 1) % 3))))
          tri.set_unflippable(tri.edge(f, c));
  }
}

// The intrinsic Delaunay flips and the splits of `maximum_edge_length` in the patch region.
inline void refine_patch_region(Conformal_flattening& result, Flattening_state& state)
{
  Intrinsic_triangulation<double>& tri = result.triangulation;
  const welding::Welded_disc& disc = state.disc;
  const double maximum_length = state.maximum_length;
  const std::size_t split_limit = (std::max)(std::size_t(1000000), 20 * Patch_access::of(result).points.size());
  if(maximum_length > 0. && !state.planar &&
     !internal::split_long_patch_edges(tri, disc.patch_faces, disc.scale * maximum_length, split_limit,
                                       result.report.edge_splits))
  {
    std::ostringstream os;
    os << "conformal_flatten: a maximum_edge_length of " << maximum_length << " needs more than " << split_limit
       << " edge splits on this mesh; give a length closer to its edge lengths";
    throw Error(Error_code::INVALID_INPUT, os.str());
  }
  state.refinement_flips = tri.number_of_flips();
}

// The flow: flat everywhere, convex free boundary. The welded disc's only boundary is the
// annulus' inner circle. A planar patch is flat already.
template <typename NamedParameters>
void run_flow(Intrinsic_triangulation<double>& tri, Flattening_state& state, const Time_limit& time_limit,
              const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Ricci_flow_result<double>& flow = state.flow;
  if(state.planar)
  {
    flow.status = Error_code::SUCCESS;
    flow.converged = true;
    flow.conformal_factors.assign(tri.number_of_vertices(), 0.);
  }
  else
  {
    try
    {
      flow = discrete_ricci_flow(
        tri, disc_flattening_targets(tri),
        parameters::maximum_running_time(
          time_limit.remaining(),
          parameters::stop_requested(time_limit.stop_request(), parameters::curvature_tolerance(
            choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-10),
            CGAL::parameters::number_of_iterations(
              choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 50))))));
    }
    catch(const Error& e)
    {
      // The flow's message counts from its own start: say it with this call's limit.
      if(e.code() == Error_code::TIME_LIMIT_EXCEEDED)
        time_limit.check("during the Ricci flow");
      throw;
    }
  }
}

// What the flow did, in the report.
inline void report_flow(Flattening_report& report, const Flattening_state& state)
{
  const Ricci_flow_result<double>& flow = state.flow;
  report.converged = flow.converged;
  report.iterations = flow.iterations;
  report.curvature_error = flow.max_curvature_error;
  report.flips = state.refinement_flips + flow.number_of_flips;
  report.flow_message = flow.message;
  report.seconds_flips = flow.seconds_flips;
  report.seconds_factorization = flow.seconds_factorization;
  report.seconds_solve = flow.seconds_solve;
  report.seconds_line_search = flow.seconds_line_search;
}

// The region of every face of the final triangulation (`Conformal_flattening::face_region`),
// the faces of the patch region, and the flips in the hole fills.
inline void find_welded_regions(Conformal_flattening& result, Flattening_state& state)
{
  const Intrinsic_triangulation<double>& tri = result.triangulation;
  const welding::Welded_disc& disc = state.disc;
  typedef Intrinsic_triangulation<double>::Face_location Location;
  std::vector<char>& in_patch = state.in_patch;
  in_patch.assign(tri.number_of_faces(), 0);
  result.face_region.resize(tri.number_of_faces());
  // The regions are bounded by seams (welded and hole loops), which are never flipped, and their
  // split halves: one walk back through the correspondence per connected set of faces across the
  // other edges suffices (a walk per face is far slower on large CAD parts).
  {
    std::vector<char> seen(tri.number_of_faces(), 0);
    std::vector<int> stack;
    for(int start = 0; start < tri.number_of_faces(); ++start)
    {
      if(seen[start])
        continue;
      const Location initial = tri.to_input(Location{start, {{1. / 3, 1. / 3, 1. / 3}}});
      const Welded_region region = initial.face < int(disc.patch_faces) ? Welded_region::PATCH
                                   : initial.face < int(disc.patch_faces + disc.fill_faces) ? Welded_region::HOLE_FILL
                                                                                            : Welded_region::ANNULUS;
      seen[start] = 1;
      stack.assign(1, start);
      while(!stack.empty())
      {
        const int f = stack.back();
        stack.pop_back();
        result.face_region[f] = region;
        in_patch[f] = region == Welded_region::PATCH;
        for(int c = 0; c < 3; ++c)
        {
          const int h = tri.halfedge(f, c), t = tri.opposite(h);
          if(t < 0 || tri.is_unflippable(tri.edge(h)) || seen[tri.face(t)])
            continue;
          seen[tri.face(t)] = 1;
          stack.push_back(tri.face(t));
        }
      }
    }
  }
  // Seams are never flipped, so the faces of a flip stay in one region.
  for(std::size_t i = 0; i < tri.number_of_flips(); ++i)
    result.report.hole_fill_flips += result.face_region[tri.faces_of_flip(i).first] == Welded_region::HOLE_FILL ? 1 : 0;
}

// The layout of the final triangulation (for a planar patch, its isometric one), the triangles of
// its patch region and the planar positions of the input vertices.
inline void lay_out(Conformal_flattening& result, const Flattening_state& state, const Time_limit& time_limit)
{
  const Intrinsic_triangulation<double>& tri = result.triangulation;
  const welding::Indexed_patch& patch = Patch_access::of(result);
  const std::vector<char>& in_patch = state.in_patch;
  const std::vector<Intrinsic_triangulation<double>::Point_2> positions =
    state.planar ? internal::welding::planar_coordinates(patch) : tri.layout();
  time_limit.check("after the layout");
  result.layout.reserve(positions.size());
  for(const auto& p : positions)
    result.layout.push_back(Epick::Point_2(p[0], p[1]));
  for(int f = 0; f < tri.number_of_faces(); ++f)
    if(in_patch[f])
    {
      result.triangles.push_back({{tri.vertex(f, 0), tri.vertex(f, 1), tri.vertex(f, 2)}});
      result.triangle_face.push_back(f);
    }

  result.uv.assign(result.layout.begin(), result.layout.begin() + std::ptrdiff_t(patch.number_of_input_vertices));
}

// A vertex of the outer loop among `loops`: the welded one; for a planar patch, the one
// enclosing the largest area.
inline int outer_loop_marker(const Conformal_flattening& result, const Flattening_state& state,
                             const std::vector<std::vector<int> >& loops)
{
  int outer_marker = Patch_access::of(result).boundary_loops[state.welded].front();
  if(state.planar)
  {
    double largest = -std::numeric_limits<double>::infinity();
    for(const std::vector<int>& loop : loops)
    {
      double area = 0.;
      for(std::size_t i = 0; i < loop.size(); ++i)
      {
        const Epick::Point_2 &p = result.layout[loop[i]], &q = result.layout[loop[(i + 1) % loop.size()]];
        area += p.x() * q.y() - q.x() * p.y();
      }
      if(area > largest)
      {
        largest = area;
        outer_marker = loop.front();
      }
    }
  }
  return outer_marker;
}

// The domain boundary: loops of the patch region, each vertex with its surface point. Leaves
// the loops in `state.loops`, the outer one first.
inline void make_domain_boundary(Conformal_flattening& result, Flattening_state& state)
{
  const Intrinsic_triangulation<double>& tri = result.triangulation;
  const welding::Indexed_patch& patch = Patch_access::of(result);
  std::vector<std::vector<int> >& loops = state.loops;
  loops = internal::region_boundary_loops(tri, state.in_patch);
  // The first corner of a patch triangle at each vertex (visited backwards, the first one written
  // last), to map the loops' vertices, the only ones the domain needs, to the surface.
  std::vector<std::pair<std::size_t, int> > corner_at(tri.number_of_vertices());
  for(std::size_t t = result.triangles.size(); t-- > 0;)
    for(int c = 3; c-- > 0;)
      corner_at[result.triangles[t][c]] = {t, c};
  auto domain_point = [&](int v) {
    Domain_point point = result.corner_to_surface(corner_at[v].first, corner_at[v].second);
    point.uv = result.layout[v];
    if(v < int(patch.number_of_input_vertices))
      point.input_vertex = std::size_t(v);
    return point;
  };
  const int outer_marker = outer_loop_marker(result, state, loops);
  for(const std::vector<int>& loop : loops)
  {
    std::vector<Domain_point> polygon;
    for(int v : loop)
      polygon.push_back(domain_point(v));
    if(std::find(loop.begin(), loop.end(), outer_marker) != loop.end())
      result.outer_boundary = polygon;
    else
      result.holes.push_back(polygon);
  }
  // Outer loop first for the check, as indices into the layout.
  std::stable_partition(loops.begin(), loops.end(), [&](const std::vector<int>& loop) {
    return std::find(loop.begin(), loop.end(), outer_marker) != loop.end();
  });
}

// The exact check of the patch region's triangulation with its boundary loops, outer one first.
inline Planar_embedding_report check_domain_embedding(const Conformal_flattening& result,
                                                      const std::vector<std::vector<int> >& loops)
{
  std::vector<std::array<std::size_t, 3> > triangles;
  for(const auto& t : result.triangles)
    triangles.push_back({{std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])}});
  std::vector<std::vector<std::size_t> > index_loops;
  for(const auto& loop : loops)
    index_loops.emplace_back(loop.begin(), loop.end());
  return check_planar_embedding(result.layout, triangles, index_loops);
}

// The conformal factor: vertex scaling multiplies lengths at vertex i by exp(2 u_i) (paper
// Eqn. 3.5), after the welding's uniform scale, and the layout is isometric to the final metric.
inline void compute_conformal_factors(Conformal_flattening& result, const Flattening_state& state)
{
  const welding::Indexed_patch& patch = Patch_access::of(result);
  Flattening_report& report = result.report;
  result.conformal_factor.resize(patch.number_of_input_vertices);
  for(std::size_t v = 0; v < patch.number_of_input_vertices; ++v)
    result.conformal_factor[v] = 2. * state.flow.conformal_factors[v] + std::log(state.disc.scale);
  const auto range = std::minmax_element(result.conformal_factor.begin(), result.conformal_factor.end());
  report.min_scale = std::exp(*range.first);
  report.max_scale = std::exp(*range.second);
}

// The input triangles whose corners' uv are not counterclockwise
// (`Flattening_report::folded_input_triangles_in_uv`).
template <typename TriangleMesh, typename VertexIndexMap>
void count_folded_input_triangles(const TriangleMesh& mesh, VertexIndexMap vim, Conformal_flattening& result)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  Flattening_report& report = result.report;
  for(auto f : faces(mesh))
  {
    if(report.embedding.non_finite_points > 0)
      break;
    const halfedge_descriptor h0 = halfedge(f, mesh);
    if(CGAL::orientation(result.uv[get(vim, source(h0, mesh))], result.uv[get(vim, target(h0, mesh))],
                         result.uv[get(vim, target(next(h0, mesh), mesh))]) != CGAL::POSITIVE)
      ++report.folded_input_triangles_in_uv;
  }
}

// The status of the report: not converged, or not an embedding (which prevails).
inline void set_flattening_status(Flattening_report& report)
{
  if(!report.converged)
    report.status = Error_code::NOT_CONVERGED;
  if(!report.embedding.is_embedding())
    report.status = Error_code::NOT_AN_EMBEDDING;
}

template <typename TriangleMesh, typename NamedParameters>
double bounding_box_diagonal(const TriangleMesh& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  Bbox_3 box;
  for(auto v : vertices(mesh))
    box += get(vpm, v).bbox();
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) + CGAL::square(box.zmax() - box.zmin()));
}

/// The stages of `conformal_flatten()` after its input checks (`checks`), with the flow's
/// edges split to at most `maximum_length` (0: not split).
template <typename TriangleMesh, typename NamedParameters>
Conformal_flattening flatten_patch(const TriangleMesh& mesh, const NamedParameters& np, const Mesh_check_report& checks,
                                   double maximum_length, const Time_limit& time_limit)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };

  // --- welding ---------------------------------------------------------------------------------
  const Clock::time_point start = Clock::now();
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  auto fim = CGAL::get_initialized_face_index_map(mesh, np);
  const double inner_radius = checked_inner_radius(np);

  Conformal_flattening result;
  Flattening_report& report = result.report;
  welding::Indexed_patch& patch = Patch_access::of(result);
  patch = welding::make_indexed_patch(mesh, vpm, vim, fim);
  report.boundary_loops = patch.boundary_loops.size();
  check_edge_length_range(patch);

  Flattening_state state;
  state.welded = welded_loop(mesh, vim, patch, np);
  // A planar patch (a CAD face) is flat already: its isometric layout is the flattening, with
  // no welding, no flow and no split (the map is the identity inside every triangle). Not if it
  // touches itself (a slit along a feature): the flow must open it.
  state.planar = checks.count(Mesh_defect::DUPLICATED_VERTEX) == 0 && welding::is_planar(patch);
  state.maximum_length = maximum_length;
  if(!state.planar)
    prepare_patch(patch, state, report);

  weld_patch(result, state, inner_radius);
  const Clock::time_point refinement_start = Clock::now();
  refine_patch_region(result, state);
  report.seconds_refinement = seconds_since(refinement_start);
  report.seconds_welding = seconds_since(start);
  time_limit.check("after the welding");

  // --- the flow: flat everywhere, convex free boundary ----------------------------------------
  const Clock::time_point flow_start = Clock::now();
  run_flow(result.triangulation, state, time_limit, np);
  report.seconds_flow = seconds_since(flow_start);
  time_limit.check("after the Ricci flow");
  report_flow(report, state);
  result.triangulation.compact_history(); // no flip or split follows: only walks back

  // --- layout, and the patch region of the final triangulation --------------------------------
  const Clock::time_point layout_start = Clock::now();
  find_welded_regions(result, state);
  lay_out(result, state, time_limit);
  make_domain_boundary(result, state);
  report.seconds_layout = seconds_since(layout_start);

  // --- verification with exact predicates -------------------------------------------------------
  const Clock::time_point check_start = Clock::now();
  report.embedding = check_domain_embedding(result, state.loops);
  report.seconds_check = seconds_since(check_start);

  // --- the report ------------------------------------------------------------------------------
  compute_conformal_factors(result, state);
  count_folded_input_triangles(mesh, vim, result);
  set_flattening_status(report);
  return result;
}

} // namespace flattening

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Flattens a genus-0 triangle mesh with at least one boundary loop onto a planar domain,
/// conformally and with no overlap anywhere (paper Sec. 4.1-4.4).
///
/// One boundary loop (the longest by default) is welded to a planar annulus, every other loop
/// is filled (with a cone vertex, or by the constrained Delaunay triangulation of its polygon
/// seen along its normal where the cone's fan is not Delaunay, with grid points inside at 2/3
/// of `maximum_edge_length`), and the discrete Ricci flow makes the welded disc flat with
/// the annulus' inner circle as a convex boundary (targets: 0 at every vertex, 2&pi;/n at the n
/// vertices of the inner circle). The flat disc is laid out; a locally injective map of a disc
/// with a convex boundary is an embedding, so the patch region is embedded, which is then
/// verified with exact predicates. Welded loop edges longer than 1/32 of the loop are split at
/// their midpoints first (exactly on the input edges), and every edge-connected set of at least
/// 16 faces that unfolds into the plane isometrically (CAD fans of slivers on planar faces, and
/// the bends between them, not across edges turning by 30 degrees or more) or that are exactly
/// coplanar is replaced by its constrained Delaunay triangulation in the plane, whose Delaunay
/// flips do not grow with the square of the fans; points in such a region are still located in
/// their input faces (`Flattening_report::retriangulated_faces`).
///
/// Long CAD slivers can shear the map of a flow run on the input's own edges until a triangle
/// folds, the flow having converged (CGAL's `blade.off`). When that happens and
/// `maximum_edge_length` is not given, the patch is flattened again with the flow's edges split
/// to at most a fiftieth, then a hundredth of its bounding-box diagonal, and the first
/// embedding is returned (`Flattening_report::refined_edge_length`).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{welded_boundary}
///     \cgalParamDescription{a border halfedge of the loop to weld (`Conformal_remeshing::parameters::welded_boundary()`)}
///     \cgalParamType{`boost::graph_traits<TriangleMesh>::%halfedge_descriptor`}
///     \cgalParamDefault{a halfedge of the longest loop}
///   \cgalParamNEnd
///   \cgalParamNBegin{annulus_inner_radius}
///     \cgalParamDescription{the inner radius of the annulus (`Conformal_remeshing::parameters::annulus_inner_radius()`)}
///     \cgalParamType{`double`, in (0, 1), the outer radius being 1}
///     \cgalParamDefault{0.3}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_edge_length}
///     \cgalParamDescription{edges of the patch longer than this are split at their midpoints in its intrinsic Delaunay triangulation before the flow (each new vertex lies exactly on the surface), until none is left, so that the conformal factor is resolved at that length and long CAD slivers do not shear the map; flat regions of at least 16 faces (developable or coplanar) get the points of a square grid of side 1/1.5 of it first, in their constrained Delaunay retriangulation (`Conformal_remeshing::parameters::maximum_edge_length()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no splitting}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the maximum number of Newton iterations of the flow}
///     \cgalParamType{`int`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{curvature_tolerance}
///     \cgalParamDescription{the flow stops when the curvature error is below it (`Conformal_remeshing::parameters::curvature_tolerance()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e-10}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{a limit in seconds on the wall-clock time of the call, checked between the stages and between the Newton iterations of the flow (`Conformal_remeshing::parameters::maximum_running_time()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the flattening; `report.status` says whether the flow converged and the result is
///          an embedding. A result that is not an embedding is never returned as a success.
///          A flow that does not converge leaves the best state it reached (the lowest curvature
///          error), which is laid out and checked like a converged one.
/// \throws Error with `Error_code::INVALID_INPUT` when the mesh is not a valid triangle mesh, not
///         connected, not of genus 0, or has no boundary, or when `maximum_edge_length` is so small
///         that more than max(10^6, 20 n) splits would be needed (n vertices); the message names
///         the problem. With `Error_code::TIME_LIMIT_EXCEEDED` when the call runs longer than
///         `maximum_running_time`.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Conformal_flattening conformal_flatten(const TriangleMesh& mesh,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace flattening = internal::flattening;
  const internal::Time_limit time_limit = internal::Time_limit::from(np, "conformal_flatten");

  // --- the input must be a patch: valid, connected, genus 0, with a boundary ----------------
  const Mesh_check_report checks = flattening::check_patch(mesh, np);
  time_limit.check("after the input checks");

  const double given_length = choose_parameter(get_parameter(np, internal_np::maximum_edge_length), 0.);
  Conformal_flattening result = flattening::flatten_patch(mesh, np, checks, given_length, time_limit);
  if(given_length > 0. || result.report.embedding.is_embedding())
    return result;
  // Long slivers can shear the map of a flow on the input's own edges until a triangle folds:
  // flattened again with the flow's edges split at a fiftieth, then a hundredth of the diagonal.
  const double diagonal = flattening::bounding_box_diagonal(mesh, np);
  for(const double fraction : {0.02, 0.01})
  {
    Conformal_flattening refined = flattening::flatten_patch(mesh, np, checks, fraction * diagonal, time_limit);
    if(refined.report.embedding.is_embedding())
    {
      refined.report.refined_edge_length = fraction * diagonal;
      return refined;
    }
  }
  return result;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_CONFORMAL_FLATTEN_H
