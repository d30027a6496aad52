// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The places where a glued output stands farther from the surface it remeshes than the
// surface-distance bound, both ways: output faces whose chords leave the surface (a bend sharper
// than the target follows), and input vertices, edges and faces the output passes by (a crease under the features
// angle cut off, a small boss or slot rounded away). The meshing stage meshes those places again
// with smaller edges (mesh_and_glue.h).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_DISTANCE_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_DISTANCE_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/distance_to_surface.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/sizing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// What `places_beyond_distance()` found.
struct Places_beyond_distance
{
  /// the samples farther than the bound, at most one per cell of a grid of the spacing asked
  std::vector<Epick::Point_3> places;
  std::size_t output_faces = 0;   ///< output faces with a sample farther than the bound
  std::size_t input_vertices = 0; ///< input vertices farther than the bound from the output
  std::size_t input_edges = 0;    ///< input edges with a point farther than the bound from the output
  std::size_t input_faces = 0;    ///< input faces with a point farther than the bound from the output
  double largest = 0.;            ///< the largest distance of a sample, either way
  Epick::Point_3 farthest = CGAL::ORIGIN; ///< the first sample at the largest distance
};

/// Keeps, of the points passed to `add()` in turn, the first in each cell of a grid of `spacing`:
/// places at least about `spacing` apart, in time linear in their number.
class Thinned_places
{
public:
  explicit Thinned_places(double spacing) : spacing_(spacing) {}

  void add(const Epick::Point_3& p, std::vector<Epick::Point_3>& places)
  {
    const std::array<std::int64_t, 3> cell{{std::int64_t(std::floor(p.x() / spacing_)), std::int64_t(std::floor(p.y() / spacing_)),
                                            std::int64_t(std::floor(p.z() / spacing_))}};
    if(cells_.insert(cell).second)
      places.push_back(p);
  }

private:
  double spacing_;
  std::set<std::array<std::int64_t, 3> > cells_;
};

/// The places meshed again for the distance bound and their sizes: a new place gets half the
/// smallest size of the earlier places within `reach` of it, or half the target where there is
/// none, so that the edges shrink further only where the output stayed too far after meshing
/// again (meshing a patch again moves all its vertices, so a round can also find new places).
class Distance_refinement
{
public:
  Distance_refinement(double target, double reach) : target_(target), reach_(reach) {}

  const Local_refinement& places() const { return places_; }

  void add(const std::vector<Epick::Point_3>& new_places)
  {
    std::vector<double> sizes;
    for(const Epick::Point_3& p : new_places)
      sizes.push_back(0.5 * smallest_size_near(p));
    for(std::size_t i = 0; i < new_places.size(); ++i)
    {
      cells_[cell(new_places[i])].push_back(places_.points.size());
      places_.points.push_back(new_places[i]);
      places_.sizes.push_back(sizes[i]);
    }
  }

private:
  typedef std::array<std::int64_t, 3> Cell;

  Cell cell(const Epick::Point_3& p) const
  {
    return {{std::int64_t(std::floor(p.x() / reach_)), std::int64_t(std::floor(p.y() / reach_)), std::int64_t(std::floor(p.z() / reach_))}};
  }

  double smallest_size_near(const Epick::Point_3& p) const
  {
    double smallest = target_;
    const Cell c = cell(p);
    for(std::int64_t dx = -1; dx <= 1; ++dx)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dz = -1; dz <= 1; ++dz)
        {
          const auto found = cells_.find(Cell{{c[0] + dx, c[1] + dy, c[2] + dz}});
          if(found != cells_.end())
            for(std::size_t i : found->second)
              if(CGAL::squared_distance(p, places_.points[i]) <= reach_ * reach_)
                smallest = (std::min)(smallest, places_.sizes[i]);
        }
    return smallest;
  }

  double target_, reach_;
  Local_refinement places_;
  std::map<Cell, std::vector<std::size_t> > cells_;
};

/// The number of intervals a side of `length` is sampled with, at most `spacing` apart.
inline std::size_t sample_intervals(double length, double spacing, std::size_t most)
{
  return (std::min)(most, std::size_t((std::max)(1., std::ceil(length / spacing))));
}

typedef Distance_to_surface::Fast::Point_3 Fast_point;

/// A triangle mesh's vertices, edges and triangles in double precision, by index: the edges and
/// triangles give the indices of their vertices, and each triangle the edges from its corner `k`
/// to corner `k + 1`. The indices take 32 bits (a third of the copy of a large input).
struct Indexed_triangles
{
  typedef std::uint32_t Index;
  std::vector<Fast_point> points;
  std::vector<bool> used; ///< the vertices some face has
  std::vector<std::array<Index, 2> > edges;
  std::vector<std::array<Index, 3> > corners, sides;
};

template <typename TriangleMesh>
Indexed_triangles indexed_triangles(const TriangleMesh& mesh)
{
  const auto points = get(CGAL::vertex_point, mesh);
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  const auto eim = CGAL::get_initialized_edge_index_map(mesh);
  Indexed_triangles result;
  std::size_t vertex_count = 0, edge_count = 0;
  for(auto v : CGAL::vertices(mesh))
    vertex_count = (std::max)(vertex_count, std::size_t(get(vim, v)) + 1);
  for(auto e : CGAL::edges(mesh))
    edge_count = (std::max)(edge_count, std::size_t(get(eim, e)) + 1);
  typedef Indexed_triangles::Index Index;
  if((std::max)({vertex_count, edge_count, std::size_t(num_faces(mesh))}) > std::size_t((std::numeric_limits<Index>::max)()))
    throw Error(Error_code::INVALID_INPUT, "indexed_triangles: 2^32 vertices, edges or faces or more to index");
  result.points.resize(vertex_count);
  result.used.assign(vertex_count, false);
  result.edges.resize(edge_count);
  for(auto v : CGAL::vertices(mesh))
  {
    const auto& p = get(points, v);
    result.points[get(vim, v)] = Fast_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  for(auto e : CGAL::edges(mesh))
    result.edges[get(eim, e)] = {{Index(get(vim, source(e, mesh))), Index(get(vim, target(e, mesh)))}};
  result.corners.reserve(num_faces(mesh));
  result.sides.reserve(num_faces(mesh));
  for(auto f : CGAL::faces(mesh))
  {
    std::array<Index, 3> corners, sides;
    auto h = halfedge(f, mesh);
    for(int k = 0; k < 3; ++k, h = next(h, mesh))
    {
      corners[k] = Index(get(vim, source(h, mesh)));
      sides[k] = Index(get(eim, edge(h, mesh)));
      result.used[corners[k]] = true;
    }
    result.corners.push_back(corners);
    result.sides.push_back(sides);
  }
  return result;
}

/// Points, each with the element it lies on (a vertex, edge or triangle), and their squared
/// distances to a surface.
struct Distance_samples
{
  std::vector<Fast_point> points;
  std::vector<Indexed_triangles::Index> element;
  std::vector<double> squared;

  void add(const Fast_point& p, std::size_t e)
  {
    points.push_back(p);
    element.push_back(Indexed_triangles::Index(e));
  }

  template <typename ConcurrencyTag>
  void measure(const Distance_to_surface& surface)
  {
    squared = surface.squared_distances<ConcurrencyTag>(points);
  }

  /// Sets `near[element]` for the samples farther than `sqrt(squared_limit)`.
  void mark_beyond(double squared_limit, std::vector<bool>& near) const
  {
    for(std::size_t i = 0; i < points.size(); ++i)
      if(squared[i] > squared_limit)
        near[element[i]] = true;
  }
};

/// The points of a triangular grid on triangle `t` of `mesh` at most `spacing` apart, its corners
/// excepted.
inline void add_triangle_samples(const Indexed_triangles& mesh, std::size_t t, double spacing, Distance_samples& samples)
{
  const std::array<Indexed_triangles::Index, 3>& c = mesh.corners[t];
  const Fast_point &a = mesh.points[c[0]], &b = mesh.points[c[1]], &d = mesh.points[c[2]];
  const double longest = std::sqrt((std::max)((std::max)(CGAL::squared_distance(a, b), CGAL::squared_distance(b, d)),
                                              CGAL::squared_distance(d, a)));
  const std::size_t n = sample_intervals(longest, spacing, 16);
  for(std::size_t i = 0; i <= n; ++i)
    for(std::size_t j = 0; i + j <= n; ++j)
      if(i != n && j != n && i + j != 0)
        samples.add(a + (double(i) / double(n)) * (b - a) + (double(j) / double(n)) * (d - a), t);
}

/// The points along edge `e` of `mesh` at most `spacing` apart, its ends and its midpoint
/// excepted (the midpoint is sampled first).
inline void add_edge_samples(const Indexed_triangles& mesh, std::size_t e, double spacing, Distance_samples& samples)
{
  const Fast_point &a = mesh.points[mesh.edges[e][0]], &b = mesh.points[mesh.edges[e][1]];
  std::size_t n = sample_intervals(std::sqrt(CGAL::squared_distance(a, b)), spacing, 64);
  n += n % 2; // even, so that the midpoint is among the points
  for(std::size_t k = 1; k < n; ++k)
    if(2 * k != n)
      samples.add(a + (double(k) / double(n)) * (b - a), e);
}

/// The first samples of a mesh, each point once: its vertices, the midpoints of its edges and
/// the centroids of its triangles.
struct Coarse_samples
{
  Distance_samples vertices, midpoints, centroids;
};

/// The coarse samples of `mesh`, measured against `surface`: the centroids, and the vertices and
/// edge midpoints only when `with_vertices_and_edges`.
///
/// With the vertices, a midpoint or a centroid is measured only where its vertices do not already
/// bound its distance below `within` and below the farthest vertex's: the distance to a surface
/// grows by at most the length moved, so a point at most `d(v) + |p - v|` away from a vertex `v`
/// stands no farther than that. Such a point could neither be beyond `within` (half the bound:
/// no place, no finer sampling) nor the largest distance, so leaving it out changes no result;
/// on a tessellation finer than the target, most midpoints and centroids are left out.
template <typename ConcurrencyTag>
Coarse_samples coarse_samples(const Indexed_triangles& mesh, const Distance_to_surface& surface, bool with_vertices_and_edges,
                              double within)
{
  Coarse_samples coarse;
  std::vector<double> vertex_distance;
  double certain = -1.; // a point whose vertices bound its distance below this is not measured
  if(with_vertices_and_edges)
  {
    for(std::size_t v = 0; v < mesh.points.size(); ++v)
      if(mesh.used[v])
        coarse.vertices.add(mesh.points[v], v);
    coarse.vertices.measure<ConcurrencyTag>(surface);
    vertex_distance.assign(mesh.points.size(), 0.);
    double farthest = 0.;
    for(std::size_t i = 0; i < coarse.vertices.points.size(); ++i)
    {
      vertex_distance[coarse.vertices.element[i]] = std::sqrt(coarse.vertices.squared[i]);
      farthest = (std::max)(farthest, coarse.vertices.squared[i]);
    }
    certain = 0.99 * (std::min)(within, std::sqrt(farthest)); // a margin for the rounding
    for(std::size_t e = 0; e < mesh.edges.size(); ++e)
    {
      const std::size_t a = mesh.edges[e][0], b = mesh.edges[e][1];
      const double bound = (std::min)(vertex_distance[a], vertex_distance[b])
                           + 0.5 * std::sqrt(CGAL::squared_distance(mesh.points[a], mesh.points[b]));
      if(!(bound < certain))
        coarse.midpoints.add(CGAL::midpoint(mesh.points[a], mesh.points[b]), e);
    }
  }
  for(std::size_t t = 0; t < mesh.corners.size(); ++t)
  {
    const std::array<Indexed_triangles::Index, 3>& c = mesh.corners[t];
    const Fast_point g = CGAL::centroid(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]]);
    double bound = std::numeric_limits<double>::infinity();
    if(with_vertices_and_edges)
      for(std::size_t v : c)
        bound = (std::min)(bound, vertex_distance[v] + std::sqrt(CGAL::squared_distance(mesh.points[v], g)));
    if(!(bound < certain))
      coarse.centroids.add(g, t);
  }
  coarse.midpoints.measure<ConcurrencyTag>(surface);
  coarse.centroids.measure<ConcurrencyTag>(surface);
  return coarse;
}

/// The distances measured on a mesh: first its coarse samples, then the fine ones near the bound,
/// on its triangles and along its edges.
struct Mesh_samples
{
  Coarse_samples coarse;
  Distance_samples fine_triangles, fine_edges;
};

/// Flags over the edges of `mesh` with a sample of `samples` farther than `sqrt(squared_limit)`.
inline std::vector<bool> edges_beyond(const Indexed_triangles& mesh, const Mesh_samples& samples, double squared_limit)
{
  std::vector<bool> beyond(mesh.edges.size(), false);
  samples.coarse.midpoints.mark_beyond(squared_limit, beyond);
  samples.fine_edges.mark_beyond(squared_limit, beyond);
  return beyond;
}

/// Flags over the triangles of `mesh` with a sample of `samples` farther than
/// `sqrt(squared_limit)`: their centroid, a corner or a point of a side when those are sampled,
/// or a fine sample on them.
inline std::vector<bool> triangles_beyond(const Indexed_triangles& mesh, const Mesh_samples& samples, double squared_limit)
{
  std::vector<bool> vertex_beyond(mesh.points.size(), false), beyond(mesh.corners.size(), false);
  const std::vector<bool> edge_beyond = edges_beyond(mesh, samples, squared_limit);
  samples.coarse.vertices.mark_beyond(squared_limit, vertex_beyond);
  samples.coarse.centroids.mark_beyond(squared_limit, beyond);
  samples.fine_triangles.mark_beyond(squared_limit, beyond);
  for(std::size_t t = 0; t < mesh.corners.size(); ++t)
    for(int k = 0; k < 3; ++k)
      if(vertex_beyond[mesh.corners[t][k]] || edge_beyond[mesh.sides[t][k]])
        beyond[t] = true;
  return beyond;
}

/// Whether triangle `t` of `mesh` is narrower than `spacing` (a CAD sliver).
inline bool is_narrow(const Indexed_triangles& mesh, std::size_t t, double spacing)
{
  const std::array<Indexed_triangles::Index, 3>& c = mesh.corners[t];
  const Fast_point &a = mesh.points[c[0]], &b = mesh.points[c[1]], &d = mesh.points[c[2]];
  const double longest = std::sqrt((std::max)((std::max)(CGAL::squared_distance(a, b), CGAL::squared_distance(b, d)),
                                              CGAL::squared_distance(d, a)));
  return 2. * std::sqrt(CGAL::squared_area(a, b, d)) < spacing * longest;
}

/// The samples of `mesh` measured against `surface`: the coarse ones (the vertices and edge
/// midpoints only `with_edges`), then, where they come within half the bound, fine ones a
/// `spacing` apart: on a grid over each triangle whose centroid does, and along each edge whose
/// midpoint does. With `with_edges`, a narrow triangle is sampled along its sides instead (every
/// point of it is within `spacing` of them), each side once for all the triangles on it.
///
/// A corner or a side near the bound does not make a triangle's interior sampled: on a surface
/// meshed by chords whose ends lie on it, a flat face stands farthest from them along its
/// creases and at its corners, which the edges' samples find; inside a face, only where the
/// chords span a face narrower than themselves (a groove), whose centroid then stands off too.
template <typename ConcurrencyTag>
Mesh_samples measured_samples(const Indexed_triangles& mesh, const Distance_to_surface& surface, bool with_edges,
                              double squared_half, double spacing)
{
  Mesh_samples samples;
  samples.coarse = coarse_samples<ConcurrencyTag>(mesh, surface, with_edges, std::sqrt(squared_half));
  std::vector<bool> near(mesh.corners.size(), false);
  samples.coarse.centroids.mark_beyond(squared_half, near);
  std::vector<bool> edge_near = edges_beyond(mesh, samples, squared_half);
  for(std::size_t t = 0; t < near.size(); ++t)
    if(near[t])
    {
      if(with_edges && is_narrow(mesh, t, spacing))
        for(std::size_t e : mesh.sides[t])
          edge_near[e] = true;
      else
        add_triangle_samples(mesh, t, spacing, samples.fine_triangles);
    }
  if(with_edges)
    for(std::size_t e = 0; e < edge_near.size(); ++e)
      if(edge_near[e])
        add_edge_samples(mesh, e, spacing, samples.fine_edges);
  samples.fine_triangles.template measure<ConcurrencyTag>(surface);
  samples.fine_edges.template measure<ConcurrencyTag>(surface);
  return samples;
}

/// The number of flags set.
inline std::size_t count_set(const std::vector<bool>& flags) { return std::size_t(std::count(flags.begin(), flags.end(), true)); }

/// The samples of one surface farther from another than a bound, in the order they were
/// measured, and the farthest of all its samples: what is kept of a mesh's samples once its
/// distances are measured (they are the largest memory of the check on a large input).
struct Samples_beyond
{
  std::vector<Fast_point> points; ///< the samples farther than the bound
  double largest_squared = 0.;    ///< the largest squared distance of a sample
  Fast_point farthest = Fast_point(0., 0., 0.); ///< the first sample at that distance

  void add(const Distance_samples& samples, double squared_bound)
  {
    for(std::size_t i = 0; i < samples.points.size(); ++i)
    {
      if(samples.squared[i] > largest_squared)
      {
        largest_squared = samples.squared[i];
        farthest = samples.points[i];
      }
      if(samples.squared[i] > squared_bound)
        points.push_back(samples.points[i]);
    }
  }

  void add(const Mesh_samples& samples, double squared_bound)
  {
    for(const Distance_samples* s : {&samples.coarse.vertices, &samples.coarse.midpoints, &samples.coarse.centroids,
                                     &samples.fine_triangles, &samples.fine_edges})
      add(*s, squared_bound);
  }
};

/// The input's vertices, edges and faces measured against the output (see
/// `places_beyond_distance()`).
struct Input_beyond_distance
{
  Samples_beyond samples;
  std::size_t vertices = 0, edges = 0, faces = 0; ///< the input's elements with a sample beyond the bound
  std::vector<std::array<Fast_point, 2> > edges_beyond; ///< the ends of each edge with a sample beyond the bound
};

/// The input's vertices, edges and faces against the output: its samples, the cover of the output
/// and the input's indexed copy are freed on return, before the output's faces are measured.
template <typename ConcurrencyTag, typename InputMesh, typename OutputMesh>
Input_beyond_distance input_beyond_distance(const InputMesh& input, const OutputMesh& output, double bound, double spacing)
{
  const double squared_bound = bound * bound, squared_half = 0.25 * squared_bound;
  const Indexed_triangles in = indexed_triangles(input);
  const Distance_to_surface to_output(output, ConcurrencyTag());
  const Mesh_samples in_samples = measured_samples<ConcurrencyTag>(in, to_output, true, squared_half, spacing);
  Input_beyond_distance result;
  std::vector<bool> vertex_beyond(in.points.size(), false);
  in_samples.coarse.vertices.mark_beyond(squared_bound, vertex_beyond);
  const std::vector<bool> edge_beyond = edges_beyond(in, in_samples, squared_bound);
  result.vertices = count_set(vertex_beyond);
  result.edges = count_set(edge_beyond);
  result.faces = count_set(triangles_beyond(in, in_samples, squared_bound));
  result.samples.add(in_samples, squared_bound);
  for(std::size_t e = 0; e < in.edges.size(); ++e)
    if(edge_beyond[e])
      result.edges_beyond.push_back({{in.points[in.edges[e][0]], in.points[in.edges[e][1]]}});
  return result;
}

/// The samples of `output` and of `input` farther from the other than `bound`: the output's
/// faces (their corners lie on the input) and the input's vertices, edges (where the output cuts
/// a crease or rounds off a tip) and faces. Every face centroid of both, and every vertex and
/// edge midpoint of the input, is measured once; the faces with such a sample (or, for the
/// input's faces, a corner or an edge midpoint) within half the bound of it, and the input's
/// edges whose midpoint is, are sampled again on a grid `spacing` apart. The output's edge
/// midpoints are not sampled first: a chord that cuts a crease under an edge's midpoint by the
/// bound has the centroids of its faces about two thirds as far off, beyond half the bound, and
/// the closest points on the input, a CAD part's fans of slivers, are the expensive queries.
/// `to_input()` gives the `Distance_to_surface` of `input`; it is called once the input's
/// samples are measured and freed, so that a cover built then is never held with them (nor with
/// the output's cover). The places are thinned to one per cell of `spacing`, the output's first.
template <typename ConcurrencyTag, typename InputMesh, typename InputSurface, typename OutputMesh>
Places_beyond_distance places_beyond_distance(const InputMesh& input, const InputSurface& to_input,
                                              const OutputMesh& output, double bound, double spacing)
{
  const double squared_bound = bound * bound, squared_half = 0.25 * squared_bound;
  const Input_beyond_distance from_input = input_beyond_distance<ConcurrencyTag>(input, output, bound, spacing);
  Samples_beyond from_output;
  Places_beyond_distance result;
  {
    const Indexed_triangles out = indexed_triangles(output);
    const Mesh_samples out_samples = measured_samples<ConcurrencyTag>(out, to_input(), false, squared_half, spacing);
    result.output_faces = count_set(triangles_beyond(out, out_samples, squared_bound));
    from_output.add(out_samples, squared_bound);
  }
  result.input_vertices = from_input.vertices;
  result.input_edges = from_input.edges;
  result.input_faces = from_input.faces;

  Thinned_places thinned(spacing);
  for(const Samples_beyond* samples : std::array<const Samples_beyond*, 2>{{&from_output, &from_input.samples}})
    for(const Fast_point& p : samples->points)
      thinned.add(Epick::Point_3(p.x(), p.y(), p.z()), result.places);
  const Samples_beyond& farther = from_input.samples.largest_squared > from_output.largest_squared ? from_input.samples : from_output;
  result.largest = std::sqrt(farther.largest_squared);
  result.farthest = Epick::Point_3(farther.farthest.x(), farther.farthest.y(), farther.farthest.z());
  // An input edge beyond the bound somewhere is a crease the output cuts there; where it does
  // not cut it this time is chance (where the output's vertices fell), so the whole edge
  // becomes places: a CAD edge is then meshed finer along its length at once, a scan's short
  // edge where it is.
  for(const std::array<Fast_point, 2>& ends : from_input.edges_beyond)
  {
    const Fast_point &a = ends[0], &b = ends[1];
    const std::size_t n = sample_intervals(std::sqrt(CGAL::squared_distance(a, b)), spacing, std::size_t(-1));
    for(std::size_t k = 0; k <= n; ++k)
    {
      const Fast_point p = a + (double(k) / double(n)) * (b - a);
      thinned.add(Epick::Point_3(p.x(), p.y(), p.z()), result.places);
    }
  }
  return result;
}

/// `places_beyond_distance()` with the input's `Distance_to_surface` at hand.
template <typename ConcurrencyTag, typename InputMesh, typename OutputMesh>
Places_beyond_distance places_beyond_distance(const InputMesh& input, const Distance_to_surface& to_input,
                                              const OutputMesh& output, double bound, double spacing)
{
  return places_beyond_distance<ConcurrencyTag>(input, [&]() -> const Distance_to_surface& { return to_input; }, output, bound, spacing);
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_DISTANCE_H
