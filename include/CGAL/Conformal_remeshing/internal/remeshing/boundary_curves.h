// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Patch boundaries sampled once, in 3D, on the input polylines: both patches
// beside a curve use the same samples, so the remeshed patches glue into one watertight mesh.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_BOUNDARY_CURVES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_BOUNDARY_CURVES_H

#include <CGAL/Conformal_remeshing/conformal_flatten.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_sample.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/sizing.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The samples of every patch boundary curve of a segmentation. A sample is either at a vertex
/// of the segmented mesh (curve ends: junctions of three or more patches, corners) or inside
/// one of its edges.
struct Curve_samples
{
  typedef Poly_annulus_segmentation::Vertex Vertex;
  std::vector<Epick::Point_3> points;
  std::vector<Poly_annulus_segmentation::Face> face; ///< a face of the segmented mesh holding each sample
  std::map<Vertex, std::size_t> at_vertex;
  /// samples inside the edge (`first`, `second`) with `first < second`: the fraction of the way
  /// from `first`, increasing
  std::map<std::pair<Vertex, Vertex>, std::vector<std::pair<double, std::size_t> > > on_edge;
  std::size_t number_of_curves = 0;
  /// the curve of each chord between consecutive samples of a curve, by its sample pair (smaller first)
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> curve_of_chord;
  /// whether the chords of each curve must stay output edges: curves along a sharp feature, a
  /// border or a user patch border (a curve with any such edge); the others are cuts
  std::vector<char> is_kept_curve;

  /// whether the segment between samples `i` and `j` is a chord of a kept curve
  bool is_kept_chord(std::size_t i, std::size_t j) const
  {
    const auto found = curve_of_chord.find(std::minmax(i, j));
    return found != curve_of_chord.end() && is_kept_curve[found->second];
  }
};

/// Pieces of cut (patch borders that are not features, borders or user borders) shorter than
/// this times the target length do not end at a turn (see `sample_boundary_curves()`). On a
/// scanned model this raises the smallest angles (from 17 to 21 degrees at 1%) and keeps the
/// distances to the input; a larger bound, 0.5, raises them more but moves the output away from
/// the input.
constexpr double shortest_cut_piece = 0.3;

/// A border curve is sampled closer where it bends, so that its chords stand at most about
/// `border_chord_deviation` times the spacing off it, but never closer than
/// `closest_border_samples` times the spacing. Why: the output surface ends at the chords, so a
/// chord's sagitta is the distance from the input border to the output; at the spacing, a border
/// of radius 7 times the target (a flat sheet's rounded corners) would stand 0.018 times the
/// target off, farther than with `isotropic_remeshing`, which keeps the input's border vertices.
/// At 0.8 times the spacing, the edges stay within [0.7, 1.4] times the target. Features are left
/// at the spacing: on a scan their polylines zigzag, and their turns are noise, not curvature
/// (sampling them closer moves the output away from the input).
constexpr double border_chord_deviation = 0.008;
constexpr double closest_border_samples = 0.8;

/// A curve shorter than `tiny_curve` times the target length (one chord) grades the sampling of
/// the curves that meet it: their spacing grows from its length by `boundary_grading` times the
/// distance along them. Why: the planar refinement cannot split a boundary chord, and where a chord
/// a target long meets one a fortieth of it, the points the refinement puts near the short one
/// stand almost on the long one on the surface. (On CGAL's blade.off, whose flat strip along the
/// trailing edge is a fortieth of the target wide, this grading raises the smallest angle from
/// 0.03 to 17 degrees; slower ones, 0.5 or 0.75, give no larger angle, as the flattening still
/// shears the strip's slivers.)
constexpr double tiny_curve = 0.25;
constexpr double boundary_grading = 1.;

/// The angle in radians between the directions `in` and `out` of a polyline at a vertex: how
/// much it turns there (0 where it goes straight on).
inline double turn_angle(const Epick::Vector_3& in, const Epick::Vector_3& out)
{
  const double c = (in * out) / (std::sqrt(in.squared_length()) * std::sqrt(out.squared_length()));
  return std::acos((std::max)(-1., (std::min)(1., c)));
}

/// The curvature of a border polyline at each of its vertices (its turn over the mean length of
/// the two edges there), 0 at the ends of an open curve, which are corners or junctions.
template <typename Mesh, typename Vertex>
std::vector<double> polyline_curvatures(const Mesh& m, const std::vector<Vertex>& curve)
{
  std::vector<double> curvature(curve.size(), 0.);
  const bool closed = curve.front() == curve.back();
  for(std::size_t i = 0; i < curve.size(); ++i)
  {
    if(!closed && (i == 0 || i + 1 == curve.size()))
      continue;
    // a closed curve repeats its first vertex at the end
    const std::size_t before = i == 0 ? curve.size() - 2 : i - 1, after = i + 1 == curve.size() ? 1 : i + 1;
    const Epick::Vector_3 in = m.point(curve[i]) - m.point(curve[before]), out = m.point(curve[after]) - m.point(curve[i]);
    curvature[i] = turn_angle(in, out) / (0.5 * (std::sqrt(in.squared_length()) + std::sqrt(out.squared_length())));
  }
  return curvature;
}

// The steps of `sample_boundary_curves()`.

// The patch on the side of `h` in `s`, `std::size_t(-1)` on the border.
inline std::size_t patch_beside(const Poly_annulus_segmentation& s, Poly_annulus_segmentation::Mesh::Halfedge_index h)
{
  const std::size_t border = std::size_t(-1);
  return s.mesh.is_border(h) ? border : s.patch[s.mesh.face(h)];
}

// The patches on the two sides of the edge of `h`, smaller first. (By value: std::minmax of two
// temporaries returns references to them, dangling here.)
inline std::pair<std::size_t, std::size_t> patches_beside(const Poly_annulus_segmentation& s,
                                                           Poly_annulus_segmentation::Mesh::Halfedge_index h)
{
  return std::minmax(patch_beside(s, h), patch_beside(s, s.mesh.opposite(h)));
}

// Whether the output keeps the curve of `e` as a chain of its edges: a feature, a user patch
// border or the border; the other curve edges are cuts.
inline bool is_kept_curve_edge(const Poly_annulus_segmentation& s, Poly_annulus_segmentation::Mesh::Edge_index e)
{
  return s.is_feature[e] || s.is_user_border[e] || s.mesh.is_border(e);
}

// A face of `m` beside the halfedge `h`: its own, or the opposite one on the border.
inline Poly_annulus_segmentation::Face face_of_curve_halfedge(const Poly_annulus_segmentation::Mesh& m,
                                                              Poly_annulus_segmentation::Mesh::Halfedge_index h)
{
  return m.is_border(h) ? m.face(m.opposite(h)) : m.face(h);
}

// The halfedges of the curve edges of `s` (`is_curve_edge()`) out of each vertex.
inline std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> >
outgoing_curve_halfedges(const Poly_annulus_segmentation& s)
{
  typedef Poly_annulus_segmentation::Mesh::Halfedge_index Halfedge;
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  std::vector<std::vector<Halfedge> > outgoing(m.number_of_vertices());
  for(auto e : m.edges())
    if(s.is_curve_edge(e))
      for(Halfedge h : {m.halfedge(e), m.opposite(m.halfedge(e))})
        outgoing[m.source(h)].push_back(h);
  return outgoing;
}

// The vertices of `m` (1 at a vertex, else 0) at the same point as another vertex: where sheets
// of the surface touch (two holes meeting at a corner, sheets cut apart along a non-manifold
// edge).
inline std::vector<char> contact_vertices(const Poly_annulus_segmentation::Mesh& m)
{
  typedef Curve_samples::Vertex Vertex;
  std::vector<std::pair<Epick::Point_3, Vertex> > by_point;
  by_point.reserve(m.number_of_vertices());
  for(Vertex v : m.vertices())
    by_point.emplace_back(m.point(v), v);
  std::sort(by_point.begin(), by_point.end());
  std::vector<char> contact(m.number_of_vertices(), 0);
  for(std::size_t i = 0; i + 1 < by_point.size(); ++i)
    if(by_point[i].first == by_point[i + 1].first)
      contact[by_point[i].second] = contact[by_point[i + 1].second] = 1;
  return contact;
}

// The curve ends of `s` (1 at a vertex, else 0): the vertices where other than two curve edges
// meet (`outgoing`), where the pair of patches changes, or where the curve turns by more than
// `corner_degrees`.
inline std::vector<char> curve_junctions(const Poly_annulus_segmentation& s,
                                         const std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> >& outgoing,
                                         double corner_degrees)
{
  typedef Poly_annulus_segmentation::Mesh::Halfedge_index Halfedge;
  typedef Curve_samples::Vertex Vertex;
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  std::vector<char> junction(m.number_of_vertices(), 0);
  for(Vertex v : m.vertices())
  {
    const std::vector<Halfedge>& out = outgoing[v];
    if(out.empty())
      continue;
    if(out.size() != 2 || patches_beside(s, out[0]) != patches_beside(s, out[1]))
    {
      junction[v] = 1;
      continue;
    }
    const Epick::Vector_3 in = m.point(v) - m.point(m.target(out[0])), next = m.point(m.target(out[1])) - m.point(v);
    junction[v] = turn_angle(in, next) * 180. / CGAL_PI > corner_degrees;
  }
  return junction;
}

// A cut between patches follows input edges, and on a scan it zigzags: a turn above the corner
// angle between two pieces of cut, one of them shorter than `shortest_cut_piece` times the
// `target` length, is no curve end: its samples, a short chord apart, would leave a sliver between
// them and the next output vertex. Features, borders and user borders keep their corners. Clears
// such turns in `junction`.
inline void smooth_short_cut_turns(const Poly_annulus_segmentation& s,
                                   const std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> >& outgoing,
                                   double target, std::vector<char>& junction)
{
  typedef Poly_annulus_segmentation::Mesh::Halfedge_index Halfedge;
  typedef Curve_samples::Vertex Vertex;
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  const double short_piece = shortest_cut_piece * target;
  std::vector<Vertex> smoothed_turns;
  for(Vertex v : m.vertices())
  {
    const std::vector<Halfedge>& out = outgoing[v];
    if(!junction[v] || out.size() != 2 || patches_beside(s, out[0]) != patches_beside(s, out[1])
       || is_kept_curve_edge(s, m.edge(out[0])) || is_kept_curve_edge(s, m.edge(out[1])))
      continue;
    for(Halfedge h : out)
    {
      double length = 0.; // along the cut to the next curve end
      for(Halfedge g = h;;)
      {
        length += std::sqrt(CGAL::squared_distance(m.point(m.source(g)), m.point(m.target(g))));
        const Vertex w = m.target(g);
        if(junction[w] || w == v || length >= short_piece)
          break;
        g = (m.edge(outgoing[w][0]) == m.edge(g)) ? outgoing[w][1] : outgoing[w][0];
      }
      if(length < short_piece)
      {
        smoothed_turns.push_back(v);
        break;
      }
    }
  }
  for(Vertex v : smoothed_turns)
    junction[v] = 0;
}

// The curves of `m` as vertex polylines, each from a `junction` along the `outgoing` curve edges
// to the next: first from every junction, then the closed curves left (their first vertex
// repeated at the end).
inline std::vector<std::vector<Curve_samples::Vertex> >
trace_boundary_curves(const Poly_annulus_segmentation::Mesh& m,
                      const std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> >& outgoing,
                      const std::vector<char>& junction)
{
  typedef Poly_annulus_segmentation::Mesh::Halfedge_index Halfedge;
  typedef Curve_samples::Vertex Vertex;
  std::vector<std::vector<Vertex> > curves;
  std::vector<char> done(m.number_of_edges(), 0);
  auto trace = [&](Halfedge h) {
    std::vector<Vertex> curve{m.source(h)};
    for(;;)
    {
      done[m.edge(h)] = 1;
      const Vertex v = m.target(h);
      curve.push_back(v);
      if(junction[v] || v == curve.front())
        break;
      const std::vector<Halfedge>& out = outgoing[v];
      h = (m.edge(out[0]) == m.edge(h)) ? out[1] : out[0];
    }
    curves.push_back(curve);
  };
  for(Vertex v : m.vertices())
    if(junction[v])
      for(Halfedge h : outgoing[v])
        if(!done[m.edge(h)])
          trace(h);
  for(Vertex v : m.vertices())
    for(Halfedge h : outgoing[v])
      if(!done[m.edge(h)])
        trace(h);
  return curves;
}

// Whether the output keeps each of the `curves` (1, else 0): whether any of its edges is kept
// (`is_kept_curve_edge()`).
inline std::vector<char> kept_curves(const Poly_annulus_segmentation& s, const std::vector<std::vector<Curve_samples::Vertex> >& curves)
{
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  std::vector<char> is_kept_curve;
  for(const auto& curve : curves)
  {
    bool kept = false;
    for(std::size_t i = 0; i + 1 < curve.size() && !kept; ++i)
    {
      kept = is_kept_curve_edge(s, m.edge(m.halfedge(curve[i], curve[i + 1])));
    }
    is_kept_curve.push_back(kept);
  }
  return is_kept_curve;
}

// The length of the shortest curve other than `c` at `end` (`curves_at`: the curves that end at
// each vertex), if it is tiny (`tiny_curve` times the `target` length), else infinity.
inline double tiny_curve_grading_start(std::size_t c, Curve_samples::Vertex end,
                                       const std::map<Curve_samples::Vertex, std::vector<std::size_t> >& curves_at,
                                       const std::vector<double>& curve_length, double target)
{
  double shortest = std::numeric_limits<double>::infinity();
  for(std::size_t other : curves_at.at(end))
    if(other != c)
      shortest = (std::min)(shortest, curve_length[other]);
  return shortest < tiny_curve * target ? shortest : std::numeric_limits<double>::infinity();
}

// A piece of a curve to sample: the part from `t0` to `t1` of its `edge`-th edge, worth `units`
// of the curve's spacing.
struct Curve_piece
{
  std::size_t edge;
  double t0, t1, units;
};

// The curve in pieces, each weighted by the target over the local size: whole edges where
// the sizing is uniform (their lengths), else pieces of an edge at most half the local size
// long (trapezoidal rule), so that a long input edge is sampled as finely as the faces
// beside it are meshed; on a border, also by how much closer its bend needs the samples.
// `curve_spacing` is the curve's spacing at the target size, `curve_length` its length and
// `grade_front`, `grade_back` the spacings at its ends near a tiny curve
// (`tiny_curve_grading_start()`). Adds the pieces' units to `total`.
inline std::vector<Curve_piece> curve_pieces(const Poly_annulus_segmentation::Mesh& m, const std::vector<Curve_samples::Vertex>& curve,
                                             const Sizing& sizing, double curve_spacing, double curve_length,
                                             double grade_front, double grade_back, double& total)
{
  typedef Poly_annulus_segmentation::Mesh::Halfedge_index Halfedge;
  std::vector<Curve_piece> pieces_of_curve;
  const Halfedge first_edge = m.halfedge(curve[0], curve[1]);
  const bool border = m.is_border(m.edge(first_edge));
  const std::vector<double> curvature = border ? polyline_curvatures(m, curve) : std::vector<double>();
  // how many times closer than `spacing` the samples on the curve's `i`-th edge must be
  auto closer_on_bend = [&](std::size_t i, double spacing) {
    if(!border)
      return 1.;
    const double bend = (std::max)(curvature[i], curvature[i + 1]);
    // a chord of length l on a circle of curvature k stands k l^2 / 8 off it
    const double closer = std::sqrt(bend * spacing / (8. * border_chord_deviation));
    return (std::min)(1. / closest_border_samples, (std::max)(1., closer));
  };
  // The spacing near a tiny curve at either end (see `tiny_curve`), at arc length `s`; it is
  // concave in `s`, so the smallest over an edge is at one of its ends.
  auto graded = [&](double s) {
    return (std::min)(grade_front + boundary_grading * s, grade_back + boundary_grading * (curve_length - s));
  };
  double along = 0.; // the arc length after edge i
  for(std::size_t i = 0; i + 1 < curve.size(); ++i)
  {
    const double length = std::sqrt(CGAL::squared_distance(m.point(curve[i]), m.point(curve[i + 1])));
    const double start = along; // the arc length before edge i
    along += length;
    const double graded_here = (std::min)(graded(start), graded(along));
    if(sizing.is_uniform() && !(graded_here < sizing.target()))
    {
      const double units = length * closer_on_bend(i, curve_spacing);
      pieces_of_curve.push_back(Curve_piece{i, 0., 1., units});
      total += units;
      continue;
    }
    const double smallest = (std::min)({sizing.at(curve[i]), sizing.at(curve[i + 1]), graded_here});
    const double closer = closer_on_bend(i, smallest * curve_spacing / sizing.target());
    const int n = int((std::min)(256., std::ceil(2. * length / smallest)));
    double size0 = (std::min)(sizing.at(curve[i]), graded(start));
    for(int j = 0; j < n; ++j)
    {
      const double t0 = double(j) / n, t1 = double(j + 1) / n;
      const double size1 = (std::min)(j + 1 == n ? sizing.at(curve[i + 1]) : sizing.at(curve[i], curve[i + 1], t1), graded(start + t1 * length));
      const double units = closer * (t1 - t0) * length * 0.5 * (sizing.target() / size0 + sizing.target() / size1);
      pieces_of_curve.push_back(Curve_piece{i, t0, t1, units});
      total += units;
      size0 = size1;
    }
  }
  return pieces_of_curve;
}

// The sample of `samples` at the vertex `v`, added if there is none yet, with a face beside one
// of the curve edges out of it (`outgoing`).
inline void add_vertex_sample(const Poly_annulus_segmentation::Mesh& m,
                              const std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> >& outgoing,
                              Curve_samples::Vertex v, Curve_samples& samples)
{
  auto found = samples.at_vertex.find(v);
  if(found != samples.at_vertex.end())
    return;
  samples.at_vertex[v] = samples.points.size();
  samples.points.push_back(m.point(v));
  samples.face.push_back(face_of_curve_halfedge(m, outgoing[v].front()));
}

// How many pieces the `curve` is sampled in: as many as its `total` units at the spacing
// `curve_spacing` give, with the fewest it needs. `curves_between` counts the curves between
// each pair of ends (smaller first).
inline std::size_t number_of_curve_pieces(const Poly_annulus_segmentation& s, const std::vector<Curve_samples::Vertex>& curve,
                                          double total, double curve_spacing,
                                          const std::map<std::pair<Curve_samples::Vertex, Curve_samples::Vertex>, int>& curves_between)
{
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  const auto first_edge = m.halfedge(curve[0], curve[1]);
  // A slit (a feature inside a patch, the same patch on both sides) is traversed once per side
  // by the same loop: with one piece, a slit whose ends are both free would be a loop of two
  // samples, a polygon of no area in the plane.
  const bool slit = patch_beside(s, first_edge) == patch_beside(s, m.opposite(first_edge));
  const std::size_t fewest = curve.front() == curve.back() ? 3
                             : (slit || curves_between.at(std::minmax(curve.front(), curve.back())) > 1) ? 2 : 1;
  return (std::max<std::size_t>)(fewest, std::size_t(std::round(total / curve_spacing)));
}

// The curves of `around` (those of one patch) in the order of its boundary, if they make one
// loop in which each curve end is the end of exactly one other curve; else none.
inline std::vector<std::size_t> curves_in_loop_order(const std::vector<std::size_t>& around,
                                                     const std::vector<std::vector<Curve_samples::Vertex> >& curves)
{
  std::map<Curve_samples::Vertex, std::vector<std::size_t> > curves_at;
  for(std::size_t c : around)
  {
    if(curves[c].front() == curves[c].back())
      return {};
    curves_at[curves[c].front()].push_back(c);
    curves_at[curves[c].back()].push_back(c);
  }
  for(const auto& at : curves_at)
    if(at.second.size() != 2 || at.second[0] == at.second[1])
      return {};
  std::vector<std::size_t> order{around.front()};
  Curve_samples::Vertex v = curves[around.front()].back();
  while(order.size() < around.size())
  {
    const std::vector<std::size_t>& two = curves_at.at(v);
    const std::size_t next = two[0] == order.back() ? two[1] : two[0];
    if(next == order.front())
      break;
    order.push_back(next);
    v = curves[next].front() == v ? curves[next].back() : curves[next].front();
  }
  return order.size() == around.size() ? order : std::vector<std::size_t>();
}

// The curves of `s` beside each patch (a slit's twice).
inline std::map<std::size_t, std::vector<std::size_t> >
curves_of_patches(const Poly_annulus_segmentation& s, const std::vector<std::vector<Curve_samples::Vertex> >& curves)
{
  const std::size_t none = std::size_t(-1);
  std::map<std::size_t, std::vector<std::size_t> > curves_of_patch;
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    const std::pair<std::size_t, std::size_t> sides = patches_beside(s, s.mesh.halfedge(curves[c][0], curves[c][1]));
    for(std::size_t patch : {sides.first, sides.second})
      if(patch != none)
        curves_of_patch[patch].push_back(c);
  }
  return curves_of_patch;
}

// Whether every vertex of `curve` has a vertex of `other` within `distance`.
inline bool runs_within(const Poly_annulus_segmentation::Mesh& m, const std::vector<Curve_samples::Vertex>& curve,
                        const std::vector<Curve_samples::Vertex>& other, double distance)
{
  const double squared = distance * distance;
  return std::all_of(curve.begin(), curve.end(), [&](Curve_samples::Vertex v) {
    return std::any_of(other.begin(), other.end(),
                       [&](Curve_samples::Vertex w) { return CGAL::squared_distance(m.point(v), m.point(w)) < squared; });
  });
}

// Starts the closed curve `curve` (its first vertex repeated at the end) at its vertex nearest
// to `across`.
inline void start_across_from(const Poly_annulus_segmentation::Mesh& m, const Epick::Point_3& across,
                              std::vector<Curve_samples::Vertex>& curve)
{
  const auto nearest = std::min_element(curve.begin(), curve.end() - 1, [&](Curve_samples::Vertex v, Curve_samples::Vertex w) {
    return CGAL::squared_distance(across, m.point(v)) < CGAL::squared_distance(across, m.point(w));
  });
  std::vector<Curve_samples::Vertex> rotated(nearest, curve.end() - 1);
  rotated.insert(rotated.end(), curve.begin(), nearest + 1);
  curve.swap(rotated);
}

// The closed curves to sample half a step out of phase: one side of every narrow band, restarted
// across from the other side's start, each with the vertex it started at before. A band is a
// patch bounded by two closed curves (no junction on them) with as many pieces each, every
// vertex of either within `target` of the other: the wall of a hole in a plate thinner than the
// target, or the rim of such a plate. Why: the rule of `out_of_phase_curves()`, for a strip that
// closes on itself; sampled alike from starts across from each other, the two sides' samples
// face each other across the band, and half a step out of phase they make a zigzag of isosceles
// triangles. A curve beside two bands keeps the phase of the first.
inline std::vector<std::pair<std::size_t, Curve_samples::Vertex> >
stagger_narrow_bands(const Poly_annulus_segmentation& s, std::vector<std::vector<Curve_samples::Vertex> >& curves,
                     const std::vector<char>& junction, const std::vector<std::size_t>& pieces, double target)
{
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  const auto free_loop = [&](std::size_t c) { return curves[c].front() == curves[c].back() && !junction[curves[c].front()]; };
  std::vector<char> placed(curves.size(), 0);
  std::vector<std::pair<std::size_t, Curve_samples::Vertex> > restarted;
  for(const auto& patch : curves_of_patches(s, curves))
  {
    if(patch.second.size() != 2)
      continue;
    std::size_t a = patch.second[0], b = patch.second[1];
    if(placed[b])
      std::swap(a, b);
    if(a == b || placed[b] || !free_loop(a) || !free_loop(b) || pieces[a] != pieces[b] ||
       !runs_within(m, curves[a], curves[b], target) || !runs_within(m, curves[b], curves[a], target))
      continue;
    restarted.emplace_back(b, curves[b].front());
    start_across_from(m, m.point(curves[a].front()), curves[b]);
    placed[a] = placed[b] = 1;
  }
  return restarted;
}

// The curves of `s` to sample half a step out of phase (1, else 0): one side of every strip. A
// strip is a patch bounded by one loop of curves whose two shortest, its ends, are of one piece,
// shorter than the `target` and than every other curve, and not next to each other; its sides
// are the two chains of curves between them, with as many pieces each (`pieces[c]` is curve
// `c`'s, `length[c]` its length). Why: sampled alike, the two sides' samples face each other
// across the strip, which is then meshed in right triangles whose smallest angle is
// atan(width / spacing) (20 degrees at a width of 0.37 spacings), or with a point in the middle
// of each cell, no better (a thin plate's rims: CGAL's boeing.off); half a step out of phase,
// each sample faces the middle of a chord of the other side, and the strip is a zigzag of
// isosceles triangles whose smallest angle is atan(2 width / spacing) (36 degrees there; at
// widths near the spacing, nearly equilateral). A curve beside two strips keeps the phase the
// first one gives it; a strip that would need the other one is left as it is.
inline std::vector<char> out_of_phase_curves(const Poly_annulus_segmentation& s,
                                             const std::vector<std::vector<Curve_samples::Vertex> >& curves,
                                             const std::vector<std::size_t>& pieces, const std::vector<double>& length,
                                             double target)
{
  const std::map<std::size_t, std::vector<std::size_t> > curves_of_patch = curves_of_patches(s, curves);
  std::vector<int> phase(curves.size(), -1); // -1: none asked yet; 0: in phase; 1: out of phase
  for(const auto& patch : curves_of_patch)
  {
    const std::vector<std::size_t> loop = curves_in_loop_order(patch.second, curves);
    if(loop.size() < 4)
      continue;
    std::vector<std::size_t> by_length(loop.size());
    for(std::size_t i = 0; i < loop.size(); ++i)
      by_length[i] = i;
    std::sort(by_length.begin(), by_length.end(), [&](std::size_t i, std::size_t j) { return length[loop[i]] < length[loop[j]]; });
    const std::size_t first_end = (std::min)(by_length[0], by_length[1]), second_end = (std::max)(by_length[0], by_length[1]);
    const bool ends = pieces[loop[first_end]] == 1 && pieces[loop[second_end]] == 1 &&
                      length[loop[by_length[1]]] < target && length[loop[by_length[1]]] < length[loop[by_length[2]]];
    if(!ends || second_end == first_end + 1 || (first_end == 0 && second_end + 1 == loop.size()))
      continue;
    // the sides: `side[0]` between the ends, `side[1]` around the loop's start
    std::array<std::vector<std::size_t>, 2> side;
    std::array<std::size_t, 2> side_pieces{{0, 0}};
    for(std::size_t i = 0; i < loop.size(); ++i)
      if(i != first_end && i != second_end)
      {
        const int k = (i > first_end && i < second_end) ? 0 : 1;
        side[k].push_back(loop[i]);
        side_pieces[k] += pieces[loop[i]];
      }
    if(side_pieces[0] != side_pieces[1])
      continue;
    // the phase of side 0 that no curve with a phase already contradicts, if any
    auto contradicts = [&](int side_0_phase) {
      for(int k = 0; k < 2; ++k)
        for(std::size_t c : side[k])
          if(phase[c] >= 0 && phase[c] != (k == 0 ? side_0_phase : 1 - side_0_phase))
            return true;
      return false;
    };
    const int side_0_phase = !contradicts(0) ? 0 : (!contradicts(1) ? 1 : -1);
    if(side_0_phase < 0)
      continue;
    for(int k = 0; k < 2; ++k)
      for(std::size_t c : side[k])
        phase[c] = k == 0 ? side_0_phase : 1 - side_0_phase;
  }
  std::vector<char> out_of_phase(curves.size(), 0);
  for(std::size_t c = 0; c < curves.size(); ++c)
    out_of_phase[c] = phase[c] == 1;
  return out_of_phase;
}

// Samples the `c`-th curve, `curve`, into `samples`: its ends, and between them `pieces` - 1
// points evenly spaced along its `pieces_of_curve` (`curve_pieces()`, `total` units in all),
// or `out_of_phase`, `pieces` points half a step later (the first and last chords half as
// long; on a closed curve, one chord across its start instead, which is not sampled); the
// chords between consecutive samples are recorded as the curve's. A curve of one edge
// between two contacts (`contact_edge`) is cut into equal parts from its lexicographically
// smaller end, so that every sheet through the edge gets the same points to the last bit.
inline void place_curve_samples(const Poly_annulus_segmentation& s,
                                const std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> >& outgoing,
                                const std::vector<Curve_samples::Vertex>& curve, std::size_t c,
                                const std::vector<Curve_piece>& pieces_of_curve, double total, std::size_t pieces,
                                bool contact_edge, bool out_of_phase, Curve_samples& samples)
{
  typedef Poly_annulus_segmentation::Mesh::Halfedge_index Halfedge;
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  const double step = total / double(pieces);
  // A closed curve sampled out of phase has no sample at its start: its chords run from its
  // first sample around to its first sample.
  const bool sampled_at_start = !(out_of_phase && curve.front() == curve.back());
  const std::size_t none = std::size_t(-1);
  std::size_t previous = none, first = none;
  if(sampled_at_start)
  {
    add_vertex_sample(m, outgoing, curve.front(), samples);
    add_vertex_sample(m, outgoing, curve.back(), samples);
    previous = samples.at_vertex[curve.front()];
  }
  auto chord_to = [&](std::size_t next) {
    if(previous != none)
      samples.curve_of_chord[std::minmax(previous, next)] = c;
    else
      first = next;
    previous = next;
  };
  std::size_t piece = 0;
  double before = 0.; // curve units before the piece
  const bool smaller_first = contact_edge && m.point(curve.front()) < m.point(curve.back());
  const std::size_t inner_samples = out_of_phase ? pieces : pieces - 1;
  for(std::size_t k = 1; k <= inner_samples; ++k)
  {
    if(contact_edge)
    {
      const Epick::Point_3 &a = m.point(smaller_first ? curve.front() : curve.back()),
                           &b = m.point(smaller_first ? curve.back() : curve.front());
      const double from_a = out_of_phase ? double(smaller_first ? k : pieces + 1 - k) - 0.5 : double(smaller_first ? k : pieces - k);
      const double t = from_a / double(pieces);
      const bool a_is_smaller_vertex = (smaller_first ? curve.front() : curve.back()) < (smaller_first ? curve.back() : curve.front());
      samples.on_edge[std::minmax(curve.front(), curve.back())].emplace_back(a_is_smaller_vertex ? t : 1. - t, samples.points.size());
      chord_to(samples.points.size());
      samples.points.push_back(Epick::Point_3(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z())));
      samples.face.push_back(face_of_curve_halfedge(m, m.halfedge(curve.front(), curve.back())));
      continue;
    }
    const double at = step * (out_of_phase ? double(k) - 0.5 : double(k));
    while(before + pieces_of_curve[piece].units < at && piece + 1 < pieces_of_curve.size())
      before += pieces_of_curve[piece++].units;
    const Curve_piece& p = pieces_of_curve[piece];
    const std::size_t e = p.edge;
    const double t = p.t0 + (p.t1 - p.t0) * (std::min)(1., (std::max)(0., (at - before) / p.units));
    const Epick::Point_3 &a = m.point(curve[e]), &b = m.point(curve[e + 1]);
    const Halfedge h = m.halfedge(curve[e], curve[e + 1]);
    const bool forward = curve[e] < curve[e + 1];
    samples.on_edge[std::minmax(curve[e], curve[e + 1])].emplace_back(forward ? t : 1. - t, samples.points.size());
    chord_to(samples.points.size());
    samples.points.push_back(Epick::Point_3(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z())));
    samples.face.push_back(face_of_curve_halfedge(m, h));
  }
  chord_to(sampled_at_start ? samples.at_vertex[curve.back()] : first);
}

// Gives each curve of `is_contact_edge` (one edge between two contacts) the largest `value` of
// the curves on the same two points: every sheet through a contact edge must get the same samples.
template <typename T>
void agree_on_contact_edges(const Poly_annulus_segmentation::Mesh& m, const std::vector<std::vector<Curve_samples::Vertex> >& curves,
                            const std::vector<char>& is_contact_edge, std::vector<T>& value)
{
  const auto points = [&](std::size_t c) {
    return std::make_pair((std::min)(m.point(curves[c].front()), m.point(curves[c].back())),
                          (std::max)(m.point(curves[c].front()), m.point(curves[c].back())));
  };
  std::map<std::pair<Epick::Point_3, Epick::Point_3>, T> largest;
  for(std::size_t c = 0; c < curves.size(); ++c)
    if(is_contact_edge[c])
    {
      T& most = largest[points(c)];
      most = (std::max)(most, value[c]);
    }
  for(std::size_t c = 0; c < curves.size(); ++c)
    if(is_contact_edge[c])
      value[c] = largest.at(points(c));
}

/// Splits the patch boundaries of `s` (edges between two patches, borders, and sharp features
/// inside a patch, along which the patch is slit open) into curves
/// between junctions (vertices where other than two boundary edges meet, where the pair of
/// patches changes, or where the curve turns by more than `corner_degrees`, except on a cut
/// beside a piece of cut shorter than `shortest_cut_piece` times the target), and samples each
/// curve at spacing close to `sizing` (interpolated between the curve's vertices), divided by
/// 2^`halvings[c]` on curve `c` when given (the curves are numbered in the same order by every
/// call on the same segmentation), closer where a border bends (`border_chord_deviation`) and
/// near the ends of tiny curves (`tiny_curve`).
/// A curve that closes on itself gets at least 3 pieces, and a
/// slit or two curves with the same ends at least 2 each, so every patch loop has 3 samples or more.
inline Curve_samples sample_boundary_curves(const Poly_annulus_segmentation& s, const Sizing& sizing, double corner_degrees,
                                            const std::vector<int>& halvings = std::vector<int>())
{
  typedef Curve_samples::Vertex Vertex;
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  const std::vector<std::vector<Poly_annulus_segmentation::Mesh::Halfedge_index> > outgoing = outgoing_curve_halfedges(s);
  std::vector<char> junction = curve_junctions(s, outgoing, corner_degrees);
  smooth_short_cut_turns(s, outgoing, sizing.target(), junction);
  // Every sheet through a contact keeps it as a sample, so that the remeshed sheets touch at the
  // input's points and along its polylines, and do not cross there.
  const std::vector<char> contact = contact_vertices(m);
  for(Vertex v : m.vertices())
    if(contact[v] && !outgoing[v].empty())
      junction[v] = 1;
  std::vector<std::vector<Vertex> > curves = trace_boundary_curves(m, outgoing, junction);

  std::map<std::pair<Vertex, Vertex>, int> curves_between;
  for(const auto& curve : curves)
    ++curves_between[std::minmax(curve.front(), curve.back())];
  // The curves' lengths, and the curves that end at each vertex.
  std::vector<double> curve_length(curves.size(), 0.);
  std::map<Vertex, std::vector<std::size_t> > curves_at;
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    for(std::size_t i = 0; i + 1 < curves[c].size(); ++i)
      curve_length[c] += std::sqrt(CGAL::squared_distance(m.point(curves[c][i]), m.point(curves[c][i + 1])));
    curves_at[curves[c].front()].push_back(c);
    curves_at[curves[c].back()].push_back(c);
  }

  std::vector<std::vector<Curve_piece> > pieces_of_curve(curves.size());
  std::vector<double> total(curves.size(), 0.);
  std::vector<std::size_t> pieces(curves.size());
  const auto cut_into_pieces = [&](std::size_t c) {
    const std::vector<Vertex>& curve = curves[c];
    const double curve_spacing = c < halvings.size() ? std::ldexp(sizing.target(), -halvings[c]) : sizing.target();
    const double grade_front = tiny_curve_grading_start(c, curve.front(), curves_at, curve_length, sizing.target()),
                 grade_back = tiny_curve_grading_start(c, curve.back(), curves_at, curve_length, sizing.target());
    total[c] = 0.;
    pieces_of_curve[c] = curve_pieces(m, curve, sizing, curve_spacing, curve_length[c], grade_front, grade_back, total[c]);
    pieces[c] = number_of_curve_pieces(s, curve, total[c], curve_spacing, curves_between);
  };
  for(std::size_t c = 0; c < curves.size(); ++c)
    cut_into_pieces(c);
  const std::vector<std::pair<std::size_t, Vertex> > staggered = stagger_narrow_bands(s, curves, junction, pieces, sizing.target());
  for(const auto& restarted : staggered)
  {
    const std::size_t c = restarted.first; // a free loop: no other curve ends on its vertices
    curves_at.erase(restarted.second);
    curves_at[curves[c].front()] = {c, c};
    cut_into_pieces(c);
  }
  // The sheets through a contact edge cut it into the same number of pieces, the most any asks,
  // and sample it out of phase if any asks.
  std::vector<char> is_contact_edge(curves.size(), 0);
  for(std::size_t c = 0; c < curves.size(); ++c)
    is_contact_edge[c] = curves[c].size() == 2 && contact[curves[c].front()] && contact[curves[c].back()];
  agree_on_contact_edges(m, curves, is_contact_edge, pieces);
  std::vector<char> out_of_phase = out_of_phase_curves(s, curves, pieces, curve_length, sizing.target());
  for(const auto& restarted : staggered)
    out_of_phase[restarted.first] = 1;
  agree_on_contact_edges(m, curves, is_contact_edge, out_of_phase);
  Curve_samples samples;
  samples.number_of_curves = curves.size();
  samples.is_kept_curve = kept_curves(s, curves);
  for(std::size_t c = 0; c < curves.size(); ++c)
    place_curve_samples(s, outgoing, curves[c], c, pieces_of_curve[c], total[c], pieces[c], is_contact_edge[c] != 0,
                        out_of_phase[c] != 0, samples);
  for(auto& edge : samples.on_edge)
    std::sort(edge.second.begin(), edge.second.end());
  return samples;
}

/// Sampling at a uniform `spacing`.
inline Curve_samples sample_boundary_curves(const Poly_annulus_segmentation& s, double spacing, double corner_degrees,
                                            const std::vector<int>& halvings = std::vector<int>())
{
  return sample_boundary_curves(s, Sizing(s, spacing), corner_degrees, halvings);
}

/// The samples of one boundary loop of a flattened patch, in loop order, with their planar
/// positions: a sample inside an input edge is placed on the planar image of that edge (a
/// polyline when the flattening split it) at the same fraction of its length. `ids` receives
/// the index of each sample in `samples`.
inline std::vector<Boundary_sample> loop_samples(const std::vector<Domain_point>& loop, const Extracted_patch& patch,
                                                 const Curve_samples& samples, std::vector<std::size_t>& ids)
{
  typedef Curve_samples::Vertex Vertex;
  std::vector<std::size_t> corners; // loop positions of input vertices
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(loop[i].input_vertex != Domain_point::none)
      corners.push_back(i);
  std::vector<Boundary_sample> result;
  const std::size_t n = loop.size();
  for(std::size_t k = 0; k < corners.size(); ++k)
  {
    const std::size_t first = corners[k], last = corners[(k + 1) % corners.size()];
    const Vertex a = patch.segmented_vertex[loop[first].input_vertex], b = patch.segmented_vertex[loop[last].input_vertex];
    const auto at_a = samples.at_vertex.find(a);
    if(at_a != samples.at_vertex.end())
    {
      result.push_back(Boundary_sample{loop[first].uv, samples.points[at_a->second], at_a->second});
      ids.push_back(at_a->second);
    }
    const auto inside = samples.on_edge.find(std::minmax(a, b));
    if(inside == samples.on_edge.end())
      continue;
    // The planar polyline of the edge, by 3D length (split points lie on the edge).
    std::vector<std::size_t> path{first};
    for(std::size_t i = (first + 1) % n; path.back() != last; i = (i + 1) % n)
      path.push_back(i);
    std::vector<double> along{0.};
    for(std::size_t i = 0; i + 1 < path.size(); ++i)
      along.push_back(along.back() + std::sqrt(CGAL::squared_distance(loop[path[i]].point, loop[path[i + 1]].point)));
    std::vector<std::pair<double, std::size_t> > edge_samples = inside->second;
    if(b < a)
      for(auto& sample : edge_samples)
        sample.first = 1. - sample.first;
    std::sort(edge_samples.begin(), edge_samples.end());
    std::size_t piece = 0;
    for(const auto& sample : edge_samples)
    {
      const double at = sample.first * along.back();
      while(piece + 2 < path.size() && along[piece + 1] < at)
        ++piece;
      const double span = along[piece + 1] - along[piece];
      const double t = span > 0. ? (std::min)(1., (std::max)(0., (at - along[piece]) / span)) : 0.;
      const Epick::Point_2 &p = loop[path[piece]].uv, &q = loop[path[piece + 1]].uv;
      result.push_back(Boundary_sample{Epick::Point_2(p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y())),
                                       samples.points[sample.second], sample.second});
      ids.push_back(sample.second);
    }
  }
  return result;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_BOUNDARY_CURVES_H
