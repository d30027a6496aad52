// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Optimization of a patch's remeshing after Delaunay refinement: edge flips toward regular
// valences and vertex moves toward better shapes. Refinement meshes are shape-bounded but
// irregular (fewer than half of the vertices have valence 6, mean equiangle skewness near 0.15).
//
// The mesh lives in the plane (connectivity, and validity: every triangle stays positively
// oriented, by exact predicates, so the patch's flattening is never folded) but its quality is
// measured on the surface, at the vertices' images under the plane-to-surface map: that map is
// only piecewise conformal (each flat triangle is distorted differently, most on CAD slivers),
// so a planar angle of 28 degrees may be 22 degrees on the surface.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_OPTIMIZATION_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_OPTIMIZATION_H

#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/triangle_adjacency.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <set>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// What `optimize_on_surface()` did.
struct Surface_optimization_report
{
  bool optimized = false; ///< false when the input is not a manifold triangulation (left as is)
  std::size_t flips = 0;
  std::size_t moves = 0;
  std::size_t angle_changes = 0; ///< flips and moves of the angle passes
  std::size_t splits = 0;        ///< edges split (see `Surface_mesh_optimizer::split_pass()`)
  std::size_t chord_splits = 0;  ///< of those, the edges split because their chord stood off the surface
  std::size_t collapses = 0;     ///< short edges collapsed (see `Surface_mesh_optimizer::collapse_pass()`)
  /// wall seconds of the phases of `optimize_on_surface()`: the first rounds of flips and
  /// smoothing, the split passes with the rounds after them, the collapse pass with its round,
  /// the skewness passes, and the angle passes with the removal of the collapsed vertices (the
  /// set-up is in none)
  double seconds_first_rounds = 0., seconds_splits = 0., seconds_collapses = 0., seconds_skewness_passes = 0.,
         seconds_angle_passes = 0.;
};

/// Edges whose chord stands off the surface: longer than `shortest`, with the chord's midpoint
/// farther than `farthest` from the surface point of the edge's planar midpoint (a `farthest`
/// of 0 names none).
struct Chord_bound
{
  double shortest = 0.;
  double farthest = 0.;

  bool names(double length_squared, double sag_squared) const
  {
    return farthest > 0. && length_squared > shortest * shortest && sag_squared > farthest * farthest;
  }
};

/// Which inner edges the optimization splits (see `Surface_mesh_optimizer::split_pass()`).
struct Edge_split_bounds
{
  double longest = 0.;     ///< edges longer than this on the surface (0: none for their length)
  Chord_bound across_bend; ///< edges across a bend sharper than the target
  Chord_bound tight_curve; ///< long edges where the surface curves tightly

  bool names_any() const { return longest > 0. || across_bend.farthest > 0. || tight_curve.farthest > 0.; }

  bool names_chord(double length_squared, double sag_squared) const
  {
    return across_bend.names(length_squared, sag_squared) || tight_curve.names(length_squared, sag_squared);
  }

  /// the length from which a chord bound applies (infinite when none does)
  double shortest_chord() const
  {
    double shortest = std::numeric_limits<double>::infinity();
    for(const Chord_bound& bound : {across_bend, tight_curve})
      if(bound.farthest > 0.)
        shortest = (std::min)(shortest, bound.shortest);
    return shortest;
  }
};

/// Shape measures of a triangle in space.
struct Triangle_shape
{
  /// the cosine of the smallest angle (larger is worse; 1 for a degenerate triangle)
  static double min_angle_cosine(const Epick::Point_3& p, const Epick::Point_3& q, const Epick::Point_3& r)
  {
    const double a = CGAL::squared_distance(q, r), b = CGAL::squared_distance(r, p), c = CGAL::squared_distance(p, q);
    // The smallest angle is opposite the shortest edge.
    const double x = (a <= b && a <= c) ? b : (b <= c ? c : a), y = (a <= b && a <= c) ? c : (b <= c ? a : b);
    const double opposite = (std::min)({a, b, c});
    const double xy = std::sqrt(x * y);
    return xy > 0. ? (x + y - opposite) / (2. * xy) : 1.;
  }

  /// the equiangle skewness `max((t_max - 60) / 120, (60 - t_min) / 60)` (1 for a degenerate triangle)
  ///
  /// In a triangle the second term is never the smaller: `t_max - 60 <= 120 - 2 t_min` says
  /// `t_max + 2 t_min <= 180 = t_min + t_mid + t_max`, that is `t_min <= t_mid`. So the skewness
  /// is `1 - t_min / 60`, one arc cosine instead of two: the optimization evaluates tens of
  /// millions of them (its skewness and smoothing passes are most of its time).
  static double skewness(const Epick::Point_3& p, const Epick::Point_3& q, const Epick::Point_3& r)
  {
    return skewness_of_squared_sides(CGAL::squared_distance(q, r), CGAL::squared_distance(r, p), CGAL::squared_distance(p, q));
  }

  /// the skewness of a triangle with squared side lengths `a`, `b` and `c`
  static double skewness_of_squared_sides(double a, double b, double c)
  {
    if(!(a > 0. && b > 0. && c > 0.))
      return 1.;
    // The smallest angle is opposite the shortest side.
    const double shortest = (std::min)({a, b, c}), longest = (std::max)({a, b, c});
    const double middle = a < b ? (b < c ? b : (std::max)(a, c)) : (a < c ? a : (std::max)(b, c));
    const double smallest = arc_cosine((middle + longest - shortest) / (2. * std::sqrt(middle * longest)));
    return (CGAL_PI / 3. - smallest) / (CGAL_PI / 3.);
  }

  /// `acos` of `x` clamped to [-1, 1], within 2e-8 (Abramowitz and Stegun 4.4.46): the
  /// optimization evaluates tens of millions of skewnesses, and `std::acos` would take a
  /// seventh of its time; it only compares them.
  static double arc_cosine(double x)
  {
    const double t = (std::min)(1., std::abs(x));
    double polynomial = -0.0012624911;
    for(double coefficient : {0.0066700901, -0.0170881256, 0.0308918810, -0.0501743046, 0.0889789874, -0.2145988016, 1.5707963050})
      polynomial = polynomial * t + coefficient;
    const double angle = std::sqrt(1. - t) * polynomial;
    return x < 0. ? CGAL_PI - angle : angle;
  }

  /// the unit normal of the triangle (the null vector for a degenerate one)
  static Epick::Vector_3 unit_normal(const Epick::Point_3& p, const Epick::Point_3& q, const Epick::Point_3& r)
  {
    const Epick::Vector_3 n = CGAL::cross_product(q - p, r - p);
    const double length = std::sqrt(n.squared_length());
    return length > 0. ? n / length : CGAL::NULL_VECTOR;
  }

  static double angle(const Epick::Point_3& p, const Epick::Point_3& q, const Epick::Point_3& r) // at p
  {
    const Epick::Vector_3 u = q - p, v = r - p;
    return std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v);
  }
};

/// The triangles (x, ring[i], ring[i + 1]) of a vertex's star as the vertex tries points x: the
/// ring's surface points and the squared lengths of its edges, which no move of the vertex
/// changes, gathered once for the many points a search tries; each squared distance from x to
/// the ring serves its two triangles. (The same sums as from three distances per triangle, to
/// the bit: the optimization evaluates tens of millions of these triangles.)
class Moving_star
{
public:
  typedef Epick::Point_3 Point_3;
  /// the most triangles a star may have
  static constexpr std::size_t max_ring_size = 64;

  /// `ring` (at most `max_ring_size` vertices, in the order of the star's triangles) indexes `positions`
  Moving_star(const std::vector<Point_3>& positions, const std::vector<int>& ring) : size_(ring.size())
  {
    CGAL_precondition(size_ <= max_ring_size);
    for(std::size_t i = 0; i < size_; ++i)
      corner_[i] = positions[ring[i]];
    for(std::size_t i = 0; i < size_; ++i)
      ring_side_[i] = CGAL::squared_distance(corner_[i], corner_[next(i)]);
  }

  /// the summed skewness of the star with the vertex at `x`; its largest in `worst` if given
  double skewness_sum(const Point_3& x, double* worst = nullptr) const
  {
    std::array<double, max_ring_size> to_x;
    for(std::size_t i = 0; i < size_; ++i)
      to_x[i] = CGAL::squared_distance(x, corner_[i]);
    double sum = 0.;
    for(std::size_t i = 0; i < size_; ++i)
    {
      const double s = Triangle_shape::skewness_of_squared_sides(ring_side_[i], to_x[next(i)], to_x[i]);
      sum += s;
      if(worst != nullptr)
        *worst = (std::max)(*worst, s);
    }
    return sum;
  }

private:
  std::size_t next(std::size_t i) const { return i + 1 == size_ ? 0 : i + 1; }

  std::size_t size_;
  std::array<Point_3, max_ring_size> corner_;
  std::array<double, max_ring_size> ring_side_;
};

/// Flips and moves on an indexed planar triangle mesh whose vertices also have surface
/// positions, kept up to date through `lift` (`lift(p, hint)`: the surface point of the planar
/// point `p`; `hint`, a `std::size_t` that starts as `no_hint`, is where the search for `p`
/// starts and becomes where `p` was found, so a point lifted near one lifted before is found
/// fast; the optimizer keeps one per vertex). The moves of a pass may run in parallel (see
/// `run_in_parallel()`): `lift` is then called from several threads at once, with different
/// hints. Triangles are counterclockwise; `neighbor_[t][k]` is the triangle across the edge
/// opposite corner `k` of `t`, or -1 on the boundary.
template <typename Lift>
class Surface_mesh_optimizer
{
public:
  typedef Epick::Point_2 Point_2;
  typedef Epick::Point_3 Point_3;
  static constexpr std::size_t no_hint = std::size_t(-1);

  /// `points[v]` and `positions[v]` are vertex `v` in the plane and on the surface. No
  /// operation creates a surface angle below the smaller of `angle_bound_degrees` and the
  /// smallest angle of the triangles it replaces. Flips make no edge longer than
  /// `longest_edge` unless the edge they remove was longer.
  Surface_mesh_optimizer(std::vector<Point_2>& points, std::vector<Point_3>& positions,
                         std::vector<std::array<int, 3> >& triangles, const Lift& lift, double angle_bound_degrees,
                         double longest_edge)
    : points_(points), positions_(positions), triangles_(triangles), lift_(lift),
      cos_bound_(std::cos(angle_bound_degrees * CGAL_PI / 180.)), longest_squared_(longest_edge * longest_edge)
  {}

  /// Builds the adjacency and the target valences; false if an edge has more than two triangles
  /// or two triangles with the same orientation. Vertices on a boundary edge and the first
  /// `number_of_fixed_points` points never move. The first points are images of the surface
  /// samples `sample_ids` when given: no flip then joins two images of one sample, the samples
  /// of a pair in `forbidden_diagonals` (smaller first) or of a boundary edge, or a vertex to two
  /// images of one sample.
  /// `hints[v]` (optional) is where the lift of `positions[v]` was found: the hint its next lift
  /// starts from (without one, the first lift of each vertex searches the whole plane).
  bool initialize(std::size_t number_of_fixed_points, const std::vector<std::size_t>& sample_ids = {},
                  const std::set<std::pair<std::size_t, std::size_t> >& forbidden_diagonals = {},
                  const std::vector<std::size_t>& hints = {})
  {
    sample_ids_ = sample_ids;
    forbidden_diagonals_ = forbidden_diagonals;
    const std::size_t nt = triangles_.size(), nv = points_.size();
    fixed_.assign(nv, 0);
    moves_.assign(nv, 0);
    hints_.assign(nv, no_hint);
    std::copy_n(hints.begin(), (std::min)(hints.size(), nv), hints_.begin());
    settled_.assign(nv, 0);
    valence_.assign(nv, 0);
    // A patch that touches itself (at a sample that its loop passes twice) has two images of one
    // chord's end: a diagonal from the other image to the chord's other end would be a second edge
    // on the chord in the glued mesh (as with frontal insertion on CGAL's femur).
    const auto is_sample = [&](int v) { return std::size_t(v) < sample_ids_.size(); };
    if(!link_triangles(triangles_, neighbor_, [&](int a, int b, bool interior) {
         ++valence_[a];
         ++valence_[b];
         if(!interior)
         {
           fixed_[a] = fixed_[b] = 1;
           if(is_sample(a) && is_sample(b))
             forbidden_diagonals_.insert(std::minmax(sample_ids_[std::size_t(a)], sample_ids_[std::size_t(b)]));
         }
       }))
      return false;
    // The ideal valence: 6 inside; on the boundary, one triangle per 60 degrees of the surface
    // angle there (4 edges where the boundary runs straight), which no operation here changes.
    std::vector<double> angle(nv, 0.);
    incident_.assign(nv, -1);
    for(std::size_t t = 0; t < nt; ++t)
      for(int k = 0; k < 3; ++k)
      {
        const int v = vertex(int(t), k);
        incident_[v] = int(t);
        angle[v] += Triangle_shape::angle(positions_[v], positions_[vertex(int(t), k + 1)], positions_[vertex(int(t), k + 2)]);
      }
    target_.assign(nv, 6);
    for(std::size_t v = 0; v < nv; ++v)
      if(fixed_[v])
        target_[v] = 1 + (std::max)(1, int(std::lround(angle[v] * 3. / CGAL_PI)));
    for(std::size_t v = 0; v < (std::min)(number_of_fixed_points, nv); ++v)
      fixed_[v] = 1;
    return true;
  }

  /// Whether the vertex moves of a pass run in parallel (with TBB, when CGAL is linked with it).
  /// The result is the same either way: see `move_pass()`.
  void run_in_parallel(bool parallel) { parallel_ = parallel; }

  /// What a flip pass goes for.
  enum Flip_goal
  {
    VALENCE, ///< valences of the edge's four vertices closer to their targets (sum of squared deviations)
    SHAPE    ///< a lower skewness of the worse of the two triangles, with valences no farther from their targets
  };

  /// Flips every interior edge whose flip serves `goal`, when its quad is strictly convex in the
  /// plane (exact predicate) and the flip keeps the angle and length bounds on the surface.
  std::size_t flip_pass(Flip_goal goal)
  {
    std::size_t flips = 0;
    for(int t = 0; t < int(triangles_.size()); ++t)
      for(int k = 0; k < 3; ++k)
      {
        const int u = neighbor_[t][k];
        if(u < t) // each interior edge once; never a boundary edge
          continue;
        const int c = vertex(t, k), a = vertex(t, k + 1), b = vertex(t, k + 2), j = opposite_corner(u, t), d = vertex(u, j);
        auto deviation = [&](int v, int change) { const int e = valence_[v] + change - target_[v]; return e * e; };
        const int before = deviation(a, 0) + deviation(b, 0) + deviation(c, 0) + deviation(d, 0);
        const int after = deviation(a, -1) + deviation(b, -1) + deviation(c, 1) + deviation(d, 1);
        if(goal == VALENCE ? after >= before : after > before)
          continue;
        const Point_3 &pa = positions_[a], &pb = positions_[b], &pc = positions_[c], &pd = positions_[d];
        if(goal == SHAPE
           && !((std::max)(Triangle_shape::skewness(pc, pa, pd), Triangle_shape::skewness(pc, pd, pb))
                < (std::max)(Triangle_shape::skewness(pc, pa, pb), Triangle_shape::skewness(pd, pb, pa)) - 1e-3))
          continue;
        if(CGAL::orientation(points_[c], points_[a], points_[d]) != CGAL::POSITIVE
           || CGAL::orientation(points_[c], points_[d], points_[b]) != CGAL::POSITIVE)
          continue;
        // The edge bounds last: the chord bound lifts a point.
        if(!keeps_angle_bound(pa, pb, pc, pd) || joins_a_surface_point_twice(c, d) || !keeps_edge_bounds(a, b, c, d))
          continue;
        flip(t, k, u, j);
        ++flips;
      }
    return flips;
  }

  /// Moves every free vertex toward the centroid of its star's triangle centroids weighted by
  /// their surface areas (a Lloyd-like step: it evens out sizes and shapes), or part of the way,
  /// when that lowers the summed skewness of the star on the surface and keeps the bounds.
  /// A vertex within a hundredth of its edges from that centroid stays.
  std::size_t smoothing_pass()
  {
    return move_pass(SMOOTHING, [this](int v, const std::vector<int>& ring) -> Move_outcome {
      const Point_2 p = points_[v];
      double weight = 0., x = 0., y = 0.;
      for(std::size_t i = 0; i < ring.size(); ++i)
      {
        const int q = ring[i], r = ring[(i + 1) % ring.size()];
        const double area = std::sqrt(CGAL::cross_product(positions_[q] - positions_[v], positions_[r] - positions_[v]).squared_length());
        weight += area;
        x += area * (p.x() + points_[q].x() + points_[r].x()) / 3.;
        y += area * (p.y() + points_[q].y() + points_[r].y()) / 3.;
      }
      if(!(weight > 0.))
        return SKIPPED;
      const Point_2 centroid(x / weight, y / weight);
      if(CGAL::squared_distance(p, centroid) < CGAL::square(0.01 * mean_planar_edge(v, ring)))
        return REFUSED;
      const Moving_star star(positions_, ring);
      const double limit = move_limit(positions_[v], ring), energy = star.skewness_sum(positions_[v]);
      const Linear_map_2_3 jacobian = star_jacobian(v, ring);
      for(double t : {1., 0.5, 0.25})
      {
        // The linear map predicts the surface move: no lift for a move that would not help.
        const Epick::Vector_2 step = t * (centroid - p);
        if(star.skewness_sum(positions_[v] + jacobian(step)) < energy && try_move(v, p + step, ring, limit, star, energy))
          return MOVED;
      }
      return REFUSED;
    });
  }

  /// Moves every free vertex whose star has a triangle of skewness `threshold` or more by a
  /// compass search in the plane (4 directions, 3 step lengths) on the summed skewness of its
  /// star on the surface: the smoothing leaves the triangles around irregular vertices off the
  /// optimum. The search runs on the star's linear map (`star_jacobian()`), which costs no lift;
  /// its end point is then lifted and judged on the surface, and half of its step is tried when
  /// that is refused. (Lifting every improving step of the search would take most of the
  /// optimization's time on a CAD part, for no measurable gain in mean skewness.) A vertex
  /// whose star has no such triangle is left unsettled: a neighbour's move may make one.
  std::size_t skewness_pass(double threshold)
  {
    return move_pass(SKEWNESS, [this, threshold](int v, const std::vector<int>& ring) -> Move_outcome {
      const Moving_star star(positions_, ring);
      double worst = 0.;
      const double energy = star.skewness_sum(positions_[v], &worst);
      if(worst < threshold)
        return SKIPPED;
      double predicted = energy;
      const Epick::Vector_2 step = compass_search(v, ring, [&](const Point_3& x) { return star.skewness_sum(x); }, predicted);
      if(!(predicted < energy))
        return REFUSED;
      const double limit = move_limit(positions_[v], ring);
      const Point_2 p = points_[v];
      return (try_move(v, p + step, ring, limit, star, energy) || try_move(v, p + 0.5 * step, ring, limit, star, energy)) ? MOVED : REFUSED;
    });
  }

  /// Splits the interior edges that `bounds` names at their planar midpoint (lifted by the map),
  /// when the four triangles it makes are positively oriented in the plane (exact predicate) and
  /// keep the angle bound on the surface; from then on, the longest edge bound of the flips and
  /// moves is `bounds.longest` if that is smaller. Two kinds of edges stand far from a curved
  /// input. The refinement leaves sparse clusters of nearly equilateral triangles with edges just
  /// under its bound, around vertices of valence 7; shapes are good there, so no flip or move
  /// touches them, but the chord error grows like the square of the circumradius. And an edge
  /// across a bend sharper than the target cuts under it, whatever its length; its planar midpoint
  /// lifted by the map is the surface point the chord's midpoint stands in for, so their distance
  /// says how far it cuts (the new vertex then sits on the bend); where the surface curves tightly
  /// (a radius of a few targets), the long edges cut under it the same way, by less. Returns the
  /// number of splits and adds the chords to `chord_splits`; the new vertices have valence 4, for
  /// the flip passes that follow.
  std::size_t split_pass(const Edge_split_bounds& bounds, std::size_t& chord_splits)
  {
    const double longest_squared = bounds.longest * bounds.longest, shortest_chord_squared = CGAL::square(bounds.shortest_chord());
    if(bounds.longest > 0.)
      longest_squared_ = (std::min)(longest_squared_, longest_squared);
    const auto is_candidate = [&](double length_squared) {
      return (bounds.longest > 0. && length_squared > longest_squared) || length_squared > shortest_chord_squared;
    };
    lift_midpoints_first(is_candidate);
    std::size_t splits = 0;
    for(int t = 0; t < int(triangles_.size()); ++t)
      for(int k = 0; k < 3; ++k)
      {
        const int u = neighbor_[t][k];
        if(u < 0)
          continue;
        const int c = vertex(t, k), a = vertex(t, k + 1), b = vertex(t, k + 2), j = opposite_corner(u, t), d = vertex(u, j);
        const Point_3 &pa = positions_[a], &pb = positions_[b], &pc = positions_[c], &pd = positions_[d];
        const double length_squared = CGAL::squared_distance(pa, pb);
        const bool too_long = bounds.longest > 0. && length_squared > longest_squared;
        if(!is_candidate(length_squared))
          continue;
        if(has_two_images_of_a_sample(std::array<int, 4>{{a, b, c, d}}))
          continue;
        const Point_2 m = CGAL::midpoint(points_[a], points_[b]);
        if(CGAL::orientation(points_[c], points_[a], m) != CGAL::POSITIVE || CGAL::orientation(points_[c], m, points_[b]) != CGAL::POSITIVE
           || CGAL::orientation(points_[d], points_[b], m) != CGAL::POSITIVE || CGAL::orientation(points_[d], m, points_[a]) != CGAL::POSITIVE)
          continue;
        const Point_3 x = lifted_midpoint(t, k, u, j);
        const bool off_surface = !too_long && bounds.names_chord(length_squared, CGAL::squared_distance(x, CGAL::midpoint(pa, pb)));
        if(!too_long && !off_surface)
          continue;
        const double old_worst = (std::max)(Triangle_shape::min_angle_cosine(pc, pa, pb), Triangle_shape::min_angle_cosine(pd, pb, pa));
        const double new_worst = (std::max)({Triangle_shape::min_angle_cosine(pc, pa, x), Triangle_shape::min_angle_cosine(pc, x, pb),
                                             Triangle_shape::min_angle_cosine(pd, pb, x), Triangle_shape::min_angle_cosine(pd, x, pa)});
        if(!keeps_angle_bound(old_worst, new_worst))
          continue;
        split(t, k, u, j, m, x);
        ++splits;
        chord_splits += off_surface;
      }
    return splits;
  }

  /// Collapses the inner edges shorter than `shortest` on the surface, in triangle order: the
  /// free end goes and the other end, when it is free too, moves to the planar midpoint (lifted);
  /// a fixed end stays. Both ends must be interior vertices and share no neighbour but the edge's
  /// two opposite vertices (so the mesh stays a manifold triangulation), and the merged star must
  /// stay positively oriented in the plane (exact predicate), keep the angle bound, make no edge
  /// longer than the length bound, no chord the kept bounds name unless it replaces one that stood
  /// farther off (see `keep_chords()`), and join no vertex to two images of one sample. The split
  /// passes leave the halves of the edges they split, 0.63 times the target long, and where the
  /// refinement's lattice of one planar spacing meets a coarser part, clusters of them. Returns
  /// the number of collapses; `remove_collapsed_vertices()` drops the vertices that went. With
  /// `local_ratio` (the size field over the target length at a planar point, at most 1), both
  /// bounds shrink by the ratio at the edge's planar midpoint.
  std::size_t collapse_pass(double shortest, const std::function<double(const Point_2&)>& local_ratio = nullptr)
  {
    std::size_t collapses = 0;
    std::vector<int> ring_a, ring_b, merged, sorted;
    std::vector<char> collapsed_triangle(triangles_.size(), 0);
    removed_.resize(points_.size(), 0);
    for(int t = 0; t < int(triangles_.size()); ++t)
      for(int k = 0; k < 3 && !collapsed_triangle[t]; ++k)
      {
        const int u = neighbor_[t][k];
        if(u < t || collapsed_triangle[u]) // each inner edge once
          continue;
        int a = vertex(t, k + 1), b = vertex(t, k + 2);
        const double squared_length = CGAL::squared_distance(positions_[a], positions_[b]);
        if(!(squared_length < shortest * shortest) || (fixed_[a] && fixed_[b]) || !interior_ring(a, ring_a) || !interior_ring(b, ring_b))
          continue;
        const double ratio = local_ratio ? local_ratio(CGAL::midpoint(points_[a], points_[b])) : 1.;
        if(!(squared_length < ratio * ratio * shortest * shortest))
          continue;
        const double longest_squared = ratio * ratio * longest_squared_;
        if(fixed_[b])
        {
          std::swap(a, b);
          std::swap(ring_a, ring_b);
        }
        // b goes. The merged ring is a's with b replaced by b's ring strictly between the apexes
        // of t and u: a's ring runs (x, b, y) and b's (y, a, x), x and y those apexes.
        const std::size_t at = std::size_t(std::find(ring_b.begin(), ring_b.end(), a) - ring_b.begin());
        merged.clear();
        for(int w : ring_a)
          if(w != b)
            merged.push_back(w);
          else
            for(std::size_t i = 2; i + 1 < ring_b.size(); ++i)
              merged.push_back(ring_b[(at + i) % ring_b.size()]);
        // The link condition: no vertex twice in the merged ring.
        sorted.assign(merged.begin(), merged.end());
        std::sort(sorted.begin(), sorted.end());
        // A merged vertex of valence above 9 is left: the flips would have to undo it.
        if(merged.size() < 3 || merged.size() > 9 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()
           || has_two_images_of_a_sample(merged))
          continue;
        Point_2 p = points_[a];
        Point_3 x = positions_[a];
        std::size_t hint = hints_[a];
        if(!fixed_[a])
        {
          p = CGAL::midpoint(points_[a], points_[b]);
          x = lift_(p, hint);
        }
        const double limit = (std::max)(move_limit(positions_[a], ring_a), move_limit(positions_[b], ring_b));
        bool valid = true;
        for(std::size_t i = 0; i < merged.size() && valid; ++i)
        {
          const int q = merged[i], r = merged[(i + 1) % merged.size()];
          valid = CGAL::orientation(p, points_[q], points_[r]) == CGAL::POSITIVE
                  && Triangle_shape::min_angle_cosine(x, positions_[q], positions_[r]) <= limit
                  && CGAL::squared_distance(x, positions_[q]) <= longest_squared;
        }
        for(std::size_t i = 0; i < merged.size() && valid; ++i)
        {
          const int w = merged[i];
          const bool of_a = std::find(ring_a.begin(), ring_a.end(), w) != ring_a.end();
          valid = !cuts_further_under(Chord{p, x, points_[w], positions_[w], hint}, of_a ? chord(a, w) : chord(b, w));
        }
        if(!valid)
          continue;
        collapse(t, u, a, b, vertex(t, k), vertex(u, opposite_corner(u, t)), p, x, hint);
        collapsed_triangle[t] = collapsed_triangle[u] = 1;
        removed_[b] = 1;
        unsettle(a);
        for(int w : merged)
          unsettle(w);
        ++collapses;
      }
    if(collapses > 0)
      drop_triangles(collapsed_triangle);
    return collapses;
  }

  /// Drops the vertices that collapse passes removed (none of the fixed points, which keep their
  /// indices) and numbers the others in their order. The optimizer is done after this.
  void remove_collapsed_vertices()
  {
    removed_.resize(points_.size(), 0);
    const std::vector<int> index = keep_undropped(removed_, points_, positions_);
    for(auto& triangle : triangles_)
      for(int& v : triangle)
        v = index[v];
  }

  /// After this call, no flip or move makes a chord that `bounds` names (see `split_pass()`),
  /// unless it replaces one that stood farther off the surface.
  void keep_chords(const Edge_split_bounds& bounds) { kept_chords_ = bounds; }

  /// Raises the smallest surface angles below `target_degrees`: every interior edge of a
  /// triangle below it is flipped when that raises the smaller of the two triangles' smallest
  /// angles, and every free corner of one is moved by a compass search (on the star's linear
  /// map, as `skewness_pass()`) on the smallest angle of its star, which the lifted move must
  /// raise. The other passes go for the mean shape and leave a few triangles between the bound
  /// and 30 degrees (0.2% on a large CAD part); here valences and skewness may get
  /// worse, but no angle below the target gets smaller. Returns the flips and moves made.
  std::size_t angle_pass(double target_degrees)
  {
    const double cos_target = std::cos(target_degrees * CGAL_PI / 180.);
    auto worst_cosine = [&](int t) {
      return Triangle_shape::min_angle_cosine(positions_[vertex(t, 0)], positions_[vertex(t, 1)], positions_[vertex(t, 2)]);
    };
    std::size_t changes = 0;
    std::vector<int> ring;
    for(int t = 0; t < int(triangles_.size()); ++t)
    {
      if(!(worst_cosine(t) > cos_target))
        continue;
      bool flipped = false;
      for(int k = 0; k < 3 && !flipped; ++k)
      {
        const int u = neighbor_[t][k];
        if(u < 0)
          continue;
        const int c = vertex(t, k), a = vertex(t, k + 1), b = vertex(t, k + 2), j = opposite_corner(u, t), d = vertex(u, j);
        const Point_3 &pa = positions_[a], &pb = positions_[b], &pc = positions_[c], &pd = positions_[d];
        const double old_t = Triangle_shape::min_angle_cosine(pc, pa, pb), old_u = Triangle_shape::min_angle_cosine(pd, pb, pa);
        const double new_t = Triangle_shape::min_angle_cosine(pc, pa, pd), new_u = Triangle_shape::min_angle_cosine(pc, pd, pb);
        const int below_before = (old_t > cos_target) + (old_u > cos_target), below_after = (new_t > cos_target) + (new_u > cos_target);
        if(!((std::max)(new_t, new_u) < (std::max)(old_t, old_u) - 1e-9) || below_after > below_before || CGAL::orientation(points_[c], points_[a], points_[d]) != CGAL::POSITIVE
           || CGAL::orientation(points_[c], points_[d], points_[b]) != CGAL::POSITIVE
           || joins_a_surface_point_twice(c, d) || !keeps_edge_bounds(a, b, c, d))
          continue;
        flip(t, k, u, j);
        flipped = true;
        ++changes;
      }
      for(int k = 0; k < 3 && !flipped && worst_cosine(t) > cos_target; ++k)
      {
        const int v = vertex(t, k);
        if(fixed_[v] || !interior_ring(v, ring))
          continue;
        auto star_worst = [&](const Point_3& x) {
          double worst = -1.;
          for(std::size_t i = 0; i < ring.size(); ++i)
            worst = (std::max)(worst, Triangle_shape::min_angle_cosine(x, positions_[ring[i]], positions_[ring[(i + 1) % ring.size()]]));
          return worst;
        };
        auto below_target = [&](const Point_3& x) {
          int below = 0;
          for(std::size_t i = 0; i < ring.size(); ++i)
            below += Triangle_shape::min_angle_cosine(x, positions_[ring[i]], positions_[ring[(i + 1) % ring.size()]]) > cos_target;
          return below;
        };
        const double now = star_worst(positions_[v]);
        double predicted = now;
        const Epick::Vector_2 step = compass_search(v, ring, star_worst, predicted);
        // The lifted move must raise the star's smallest angle (the limit) and leave no more of
        // its triangles below the target.
        const int below = below_target(positions_[v]);
        const auto no_more_below = [&](const Point_3& x) { return below_target(x) <= below; };
        if(predicted < now
           && (try_move(v, points_[v] + step, ring, now - 1e-9, no_more_below) || try_move(v, points_[v] + 0.5 * step, ring, now - 1e-9, no_more_below)))
        {
          unsettle_star(v, ring);
          ++changes;
        }
      }
    }
    return changes;
  }

private:
  struct Lifted_midpoint
  {
    int a = -1, b = -1; // the edge's ends, when they had moved moves_a and moves_b times
    unsigned moves_a = 0, moves_b = 0;
    Point_3 x;
  };

  // A vertex whose last smoothing (or skewness) move was refused, or that sits at its centroid, is
  // settled for that kind of move until it or a neighbour moves, or a flip changes its star:
  // trying again would lift the same points and refuse them again.
  enum Settled : unsigned char
  {
    SMOOTHING = 1,
    SKEWNESS = 2
  };

  void unsettle(int v) { settled_[v] = 0; }

  void unsettle_star(int v, const std::vector<int>& ring)
  {
    unsettle(v);
    for(int w : ring)
      unsettle(w);
  }

  // What a move pass did with a vertex: a refused vertex is settled for that kind of move.
  enum Move_outcome
  {
    MOVED,
    REFUSED,
    SKIPPED
  };

  // The rings of the vertices a move pass may move (free, interior, not settled for its kind), in
  // index order: the ring of `vertices[i]` is `neighbors[start[i]]` to `neighbors[start[i + 1]]`.
  // No flip happens during a pass, so each ring is walked once, for the classes, the moves and
  // the stars to unsettle.
  struct Pass_rings
  {
    std::vector<int> vertices;
    std::vector<std::size_t> start{0};
    std::vector<int> neighbors;

    void copy_ring(std::size_t i, std::vector<int>& ring) const
    {
      ring.assign(neighbors.begin() + std::ptrdiff_t(start[i]), neighbors.begin() + std::ptrdiff_t(start[i + 1]));
    }
  };

  Pass_rings rings_to_move(Settled kind) const
  {
    Pass_rings rings;
    std::vector<int> ring;
    for(std::size_t v = 0; v < points_.size(); ++v)
      if(!fixed_[v] && !(settled_[v] & kind) && interior_ring(int(v), ring))
      {
        rings.vertices.push_back(int(v));
        rings.neighbors.insert(rings.neighbors.end(), ring.begin(), ring.end());
        rings.start.push_back(rings.neighbors.size());
      }
    return rings;
  }

  // Runs `move(v, ring)` on every free interior vertex not settled for `kind`, class by class of
  // `independent_classes()`. No two vertices of a class are neighbours, so the move of one reads
  // its star and writes its own vertex only, which no other move of its class reads: the moves of
  // a class may run at once. The stars of the vertices that moved are unsettled after each class.
  // The order is the same in parallel or not, and so is the result. Returns the number of moves.
  template <typename Move>
  std::size_t move_pass(Settled kind, const Move& move)
  {
    std::size_t moves = 0;
    const Pass_rings rings = rings_to_move(kind);
    for(const std::vector<std::size_t>& members : independent_classes(rings))
    {
      std::vector<char> outcome(members.size(), SKIPPED);
      for_each_block(parallel_, members.size(), 64, [&](std::size_t begin, std::size_t end) {
        std::vector<int> star;
        for(std::size_t i = begin; i < end; ++i)
        {
          rings.copy_ring(members[i], star);
          outcome[i] = char(move(rings.vertices[members[i]], star));
        }
      });
      for(std::size_t i = 0; i < members.size(); ++i) // no two are neighbours: any order will do
      {
        const std::size_t m = members[i];
        if(outcome[i] == REFUSED)
          settled_[rings.vertices[m]] |= kind;
        else if(outcome[i] == MOVED)
        {
          ++moves;
          unsettle(rings.vertices[m]);
          for(std::size_t k = rings.start[m]; k < rings.start[m + 1]; ++k)
            unsettle(rings.neighbors[k]);
        }
      }
    }
    return moves;
  }

  // The vertices of `rings` (as indices into it) in classes of which no two are neighbours: each
  // vertex, in index order, joins the first class that has none of its neighbours. Refinement
  // meshes need about seven.
  std::vector<std::vector<std::size_t> > independent_classes(const Pass_rings& rings) const
  {
    std::vector<std::vector<std::size_t> > classes;
    std::vector<int> class_of(points_.size(), -1);
    std::vector<char> taken;
    for(std::size_t i = 0; i < rings.vertices.size(); ++i)
    {
      taken.assign(classes.size() + 1, 0);
      for(std::size_t k = rings.start[i]; k < rings.start[i + 1]; ++k)
        if(class_of[rings.neighbors[k]] >= 0)
          taken[std::size_t(class_of[rings.neighbors[k]])] = 1;
      const std::size_t c = std::size_t(std::find(taken.begin(), taken.end(), 0) - taken.begin());
      if(c == classes.size())
        classes.emplace_back();
      classes[c].push_back(i);
      class_of[rings.vertices[i]] = int(c);
    }
    return classes;
  }

  // The plane-to-surface map near a vertex, to first order: the linear map that best carries the
  // planar edges of its star to their surface edges (least squares). It predicts the surface move
  // of a small planar move well enough to skip, without lifting them, the moves that would not
  // lower the star's skewness: each lift walks back through the flow's flips (up to millions on
  // CAD fans), and on large CAD parts lifting every trial would be most of the meshing stage.
  // Every move made is still judged at its lifted point.
  struct Linear_map_2_3
  {
    Epick::Vector_3 column_x, column_y;
    Epick::Vector_3 operator()(const Epick::Vector_2& d) const { return d.x() * column_x + d.y() * column_y; }
  };

  // A compass search for v in the plane (4 directions, steps of 0.1, 0.05 and 0.025 of its mean
  // planar edge) on `energy` of v's surface point, predicted by the star's linear map: no lift.
  // `energy` is v's at the start and becomes the smallest found; returns the step to it.
  template <typename Energy_at>
  Epick::Vector_2 compass_search(int v, const std::vector<int>& ring, const Energy_at& energy_at, double& energy) const
  {
    const double mean = mean_planar_edge(v, ring);
    const Linear_map_2_3 jacobian = star_jacobian(v, ring);
    const double directions[4][2] = {{1., 0.}, {0., 1.}, {-1., 0.}, {0., -1.}};
    Epick::Vector_2 step = CGAL::NULL_VECTOR;
    for(double length = 0.1 * mean; length >= 0.1 * mean / 4.; length *= 0.5)
      for(const auto& d : directions)
      {
        const Epick::Vector_2 candidate = step + Epick::Vector_2(length * d[0], length * d[1]);
        const double e = energy_at(positions_[v] + jacobian(candidate));
        if(e < energy)
        {
          step = candidate;
          energy = e;
        }
      }
    return step;
  }

  double mean_planar_edge(int v, const std::vector<int>& ring) const
  {
    double sum = 0.;
    for(int w : ring)
      sum += std::sqrt(CGAL::squared_distance(points_[v], points_[w]));
    return sum / double(ring.size());
  }

  Linear_map_2_3 star_jacobian(int v, const std::vector<int>& ring) const
  {
    double a = 0., b = 0., c = 0.; // the normal matrix [a b; b c] of the planar edges
    Epick::Vector_3 bx = CGAL::NULL_VECTOR, by = CGAL::NULL_VECTOR;
    for(int w : ring)
    {
      const Epick::Vector_2 d = points_[w] - points_[v];
      const Epick::Vector_3 e = positions_[w] - positions_[v];
      a += d.x() * d.x();
      b += d.x() * d.y();
      c += d.y() * d.y();
      bx = bx + d.x() * e;
      by = by + d.y() * e;
    }
    const double det = a * c - b * b;
    if(!(det > 0.))
      return {CGAL::NULL_VECTOR, CGAL::NULL_VECTOR};
    return {(c * bx - b * by) / det, (a * by - b * bx) / det};
  }

  // A chord between the surface points x and y of the planar points p and q; lifts near p start
  // from `hint`.
  struct Chord
  {
    Point_2 p;
    Point_3 x;
    Point_2 q;
    Point_3 y;
    std::size_t hint;
  };

  Chord chord(int a, int b) const
  {
    return Chord{points_[a], positions_[a], points_[b], positions_[b], hints_[a] != no_hint ? hints_[a] : hints_[b]};
  }

  // The squared distance from the chord's midpoint to the surface point of its planar midpoint;
  // 0, without a lift, for a chord shorter than every kept bound.
  double chord_sag_squared(const Chord& c) const
  {
    if(!(CGAL::squared_distance(c.x, c.y) > CGAL::square(kept_chords_.shortest_chord())))
      return 0.;
    std::size_t hint = c.hint;
    return CGAL::squared_distance(lift_(CGAL::midpoint(c.p, c.q), hint), CGAL::midpoint(c.x, c.y));
  }

  // Whether the new chord is one the kept bounds name, standing farther off the surface than the
  // old one it replaces.
  bool cuts_further_under(const Chord& new_chord, const Chord& old_chord) const
  {
    const double sag = chord_sag_squared(new_chord);
    return kept_chords_.names_chord(CGAL::squared_distance(new_chord.x, new_chord.y), sag) && sag > chord_sag_squared(old_chord);
  }

  // Whether flipping the edge a-b of the quad (c, a, d, b) into c-d keeps the length bound (or
  // shortens the edge) and makes no chord the kept bounds name, unless a-b stood farther off.
  bool keeps_edge_bounds(int a, int b, int c, int d) const
  {
    if(CGAL::squared_distance(positions_[c], positions_[d]) > (std::max)(longest_squared_, CGAL::squared_distance(positions_[a], positions_[b])))
      return false;
    return !cuts_further_under(chord(c, d), chord(a, b));
  }

  // Whether flipping (c, a, b), (d, b, a) into (c, a, d), (c, d, b) creates no angle below the
  // smaller of the bound and the smallest angle before.
  bool keeps_angle_bound(const Point_3& pa, const Point_3& pb, const Point_3& pc, const Point_3& pd) const
  {
    return keeps_angle_bound((std::max)(Triangle_shape::min_angle_cosine(pc, pa, pb), Triangle_shape::min_angle_cosine(pd, pb, pa)),
                             (std::max)(Triangle_shape::min_angle_cosine(pc, pa, pd), Triangle_shape::min_angle_cosine(pc, pd, pb)));
  }

  // The same rule for any operation, given the cosines of the smallest angles of the triangles it
  // replaces and of those it makes (the largest of each).
  bool keeps_angle_bound(double old_worst_cosine, double new_worst_cosine) const
  {
    return new_worst_cosine <= (std::max)(old_worst_cosine, cos_bound_);
  }

  int vertex(int t, int k) const { return triangles_[t][k % 3]; }

  int opposite_corner(int u, int t) const
  {
    for(int j = 0; j < 3; ++j)
      if(neighbor_[u][j] == t)
        return j;
    return -1;
  }

  // The largest cosine of a smallest angle a move may leave in the star: the bound, or the
  // star's smallest angle if that is already below it.
  double move_limit(const Point_3& x, const std::vector<int>& ring) const
  {
    double worst = cos_bound_;
    for(std::size_t i = 0; i < ring.size(); ++i)
      worst = (std::max)(worst, Triangle_shape::min_angle_cosine(x, positions_[ring[i]], positions_[ring[(i + 1) % ring.size()]]));
    return worst;
  }

  // Moves v to `moved` if its star stays positively oriented in the plane (exact predicate),
  // keeps the angle limit on the surface, makes no edge longer than the longest edge bound (or
  // than it was), its summed skewness drops below `energy` and it makes no chord the kept bounds
  // name (see `keep_chords()`). (Unbounded moves stretch edges up to 1.75 times the target on a
  // spherical cap, and the largest triangles set the distance to the input.)
  bool try_move(int v, const Point_2& moved, const std::vector<int>& ring, double limit, const Moving_star& star, double energy)
  {
    return try_move(v, moved, ring, limit, [&](const Point_3& x) { return star.skewness_sum(x) < energy; });
  }

  // The same with what the move must achieve at the surface point `x` said by `improves(x)`.
  template <typename Improves>
  bool try_move(int v, const Point_2& moved, const std::vector<int>& ring, double limit, const Improves& improves)
  {
    for(std::size_t i = 0; i < ring.size(); ++i)
      if(CGAL::orientation(moved, points_[ring[i]], points_[ring[(i + 1) % ring.size()]]) != CGAL::POSITIVE)
        return false;
    std::size_t hint = hints_[v];
    const Point_3 x = lift_(moved, hint);
    for(std::size_t i = 0; i < ring.size(); ++i)
      if(Triangle_shape::min_angle_cosine(x, positions_[ring[i]], positions_[ring[(i + 1) % ring.size()]]) > limit)
        return false;
    for(int w : ring)
      if(CGAL::squared_distance(x, positions_[w]) > (std::max)(longest_squared_, CGAL::squared_distance(positions_[v], positions_[w])))
        return false;
    if(!improves(x))
      return false;
    for(int w : ring)
      if(cuts_further_under(Chord{moved, x, points_[w], positions_[w], hint}, chord(v, w)))
        return false;
    points_[v] = moved;
    positions_[v] = x;
    hints_[v] = hint;
    ++moves_[v];
    return true;
  }

  // Whether a new edge c-d would join two samples of a forbidden diagonal (another patch has it)
  // or two images of one sample, or a vertex to a second image of one sample (the sides of a
  // slit): the glue needs none of them.
  bool joins_a_surface_point_twice(int c, int d) const
  {
    const auto is_sample = [&](int v) { return std::size_t(v) < sample_ids_.size(); };
    if(!is_sample(c) && !is_sample(d))
      return false;
    if(is_sample(c) && is_sample(d))
    {
      const std::size_t a = sample_ids_[std::size_t(c)], b = sample_ids_[std::size_t(d)];
      return a == b || forbidden_diagonals_.count(std::minmax(a, b)) > 0;
    }
    const int inner = is_sample(c) ? d : c, sample = is_sample(c) ? c : d;
    std::vector<int> ring;
    if(!interior_ring(inner, ring))
      return true;
    return std::any_of(ring.begin(), ring.end(),
                       [&](int r) { return is_sample(r) && sample_ids_[std::size_t(r)] == sample_ids_[std::size_t(sample)]; });
  }

  // The neighbours of an interior vertex, counterclockwise; false for a vertex on the boundary.
  bool interior_ring(int v, std::vector<int>& ring) const
  {
    ring.clear();
    return for_each_star_triangle(v, [&](int t, int k) { ring.push_back(vertex(t, k + 1)); }) && ring.size() >= 3;
  }

  // Calls `visit(t, k)` for every triangle t of v's star, v at its corner k, counterclockwise;
  // false (after a partial walk) for a vertex on the boundary, or with more than 64 triangles.
  template <typename Visit>
  bool for_each_star_triangle(int v, const Visit& visit) const
  {
    const int first = incident_[v];
    if(first < 0)
      return false;
    int t = first, count = 0;
    do
    {
      const int k = vertex(t, 0) == v ? 0 : (vertex(t, 1) == v ? 1 : 2);
      visit(t, k);
      t = neighbor_[t][(k + 1) % 3]; // across the edge from v to the next ring vertex
      if(t < 0 || ++count > int(Moving_star::max_ring_size))
        return false;
    }
    while(t != first);
    return true;
  }

  // Flips the edge opposite corner k of t, shared with corner j of u:
  // (c, a, b) and (d, b, a) become (c, a, d) and (c, d, b).
  void flip(int t, int k, int u, int j)
  {
    const int c = vertex(t, k), a = vertex(t, k + 1), b = vertex(t, k + 2), d = vertex(u, j);
    const int n_ca = neighbor_[t][(k + 2) % 3], n_bc = neighbor_[t][(k + 1) % 3];
    const int n_ad = neighbor_[u][(j + 1) % 3], n_db = neighbor_[u][(j + 2) % 3];
    triangles_[t] = {{c, a, d}};
    neighbor_[t] = {{n_ad, u, n_ca}};
    triangles_[u] = {{c, d, b}};
    neighbor_[u] = {{n_db, n_bc, t}};
    relink(n_ad, u, t);
    relink(n_bc, t, u);
    incident_[a] = incident_[c] = t;
    incident_[b] = incident_[d] = u;
    --valence_[a];
    --valence_[b];
    ++valence_[c];
    ++valence_[d];
    for(int v : {a, b, c, d})
      unsettle(v);
  }

  // Keeps the entries of the parallel arrays `first` and `second` that `dropped` does not name,
  // in their order, and returns each old index's new one (-1 for a dropped entry).
  template <typename First, typename Second>
  static std::vector<int> keep_undropped(const std::vector<char>& dropped, First& first, Second& second)
  {
    std::vector<int> index(first.size(), -1);
    std::size_t kept = 0;
    for(std::size_t i = 0; i < first.size(); ++i)
      if(!dropped[i])
      {
        index[i] = int(kept);
        first[kept] = first[i];
        second[kept] = second[i];
        ++kept;
      }
    first.resize(kept);
    second.resize(kept);
    return index;
  }

  // Whether two of the vertices are images of one sample (the sides of a slit): a vertex joined
  // to both, or inside a quad of both, would join them.
  template <typename Vertices>
  bool has_two_images_of_a_sample(const Vertices& vertices) const
  {
    std::vector<std::size_t> ids;
    for(int v : vertices)
      if(std::size_t(v) < sample_ids_.size())
        ids.push_back(sample_ids_[std::size_t(v)]);
    std::sort(ids.begin(), ids.end());
    return std::adjacent_find(ids.begin(), ids.end()) != ids.end();
  }

  // Splits the edge opposite corner k of t, shared with corner j of u, at the new vertex m
  // (planar point `p`, surface point `x`): (c, a, b) and (d, b, a) become (c, a, m), (c, m, b),
  // (d, b, m) and (d, m, a).
  void split(int t, int k, int u, int j, const Point_2& p, const Point_3& x)
  {
    const int c = vertex(t, k), a = vertex(t, k + 1), b = vertex(t, k + 2), d = vertex(u, j);
    const int n_ca = neighbor_[t][(k + 2) % 3], n_bc = neighbor_[t][(k + 1) % 3];
    const int n_ad = neighbor_[u][(j + 1) % 3], n_db = neighbor_[u][(j + 2) % 3];
    const int m = int(points_.size()), t2 = int(triangles_.size()), u2 = t2 + 1;
    points_.push_back(p);
    positions_.push_back(x);
    fixed_.push_back(0);
    moves_.push_back(0);
    hints_.push_back(hints_[a]);
    settled_.push_back(0);
    valence_.push_back(4);
    target_.push_back(6);
    incident_.push_back(t);
    triangles_[t] = {{c, a, m}};
    neighbor_[t] = {{u2, t2, n_ca}};
    triangles_.push_back({{c, m, b}});
    neighbor_.push_back({{u, n_bc, t}});
    triangles_[u] = {{d, b, m}};
    neighbor_[u] = {{t2, u2, n_db}};
    triangles_.push_back({{d, m, a}});
    neighbor_.push_back({{t, n_ad, u}});
    relink(n_bc, t, t2);
    relink(n_ad, u, u2);
    incident_[a] = incident_[c] = t;
    incident_[b] = t2;
    incident_[d] = u;
    ++valence_[c];
    ++valence_[d];
    for(int v : {a, b, c, d})
      unsettle(v);
  }

  // Lifts, before a split pass and in parallel when the moves are, the planar midpoints of the
  // inner edges whose surface length `is_candidate` names and whose kept lift is out of date,
  // each from the side of its lower triangle, where the pass meets it first: the pass then finds
  // them in lifted_midpoint(), with the same result. (The split passes can be a fifth of the
  // optimization, mostly in lifted_midpoint().)
  template <typename Is_candidate>
  void lift_midpoints_first(const Is_candidate& is_candidate)
  {
    if(!parallel_)
      return;
    reserve_lifted_midpoints();
    std::vector<std::array<int, 2> > to_lift; // (t, k) of the edges
    for(int t = 0; t < int(triangles_.size()); ++t)
      for(int k = 0; k < 3; ++k)
      {
        const int u = neighbor_[t][k], a = vertex(t, k + 1), b = vertex(t, k + 2);
        if(u > t && is_candidate(CGAL::squared_distance(positions_[a], positions_[b])) && !known_midpoint(t, k, u, opposite_corner(u, t)))
          to_lift.push_back({{t, k}});
      }
    for_each_block(parallel_, to_lift.size(), 64, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
      {
        const int t = to_lift[i][0], k = to_lift[i][1], u = neighbor_[t][k];
        lift_midpoint(t, k, u, opposite_corner(u, t));
      }
    });
  }

  // The surface point of the planar midpoint of the edge opposite corner k of t, shared with
  // corner j of u. The split passes look at every edge from both sides, and again in each pass: the
  // point is lifted again only if an end of the edge moved (a lift walks back through the flow's
  // flips, and most of these lifts are of a midpoint lifted before).
  Point_3 lifted_midpoint(int t, int k, int u, int j)
  {
    reserve_lifted_midpoints();
    if(const Lifted_midpoint* known = known_midpoint(t, k, u, j))
      return known->x;
    return lift_midpoint(t, k, u, j);
  }

  // The kept lift of that midpoint, if the edge's ends have not moved since; null otherwise.
  const Lifted_midpoint* known_midpoint(int t, int k, int u, int j) const
  {
    const int a = vertex(t, k + 1), b = vertex(t, k + 2);
    for(const std::size_t half_edge : {std::size_t(3 * t + k), std::size_t(3 * u + j)})
    {
      const Lifted_midpoint& known = lifted_midpoints_[half_edge];
      if(std::minmax(known.a, known.b) == std::minmax(a, b) && known.moves_a == moves_[known.a] && known.moves_b == moves_[known.b])
        return &known;
    }
    return nullptr;
  }

  // Lifts that midpoint from a's hint and keeps it for both half-edges (reserve first: the lifts
  // of lift_midpoints_first() run at once).
  Point_3 lift_midpoint(int t, int k, int u, int j)
  {
    const int a = vertex(t, k + 1), b = vertex(t, k + 2);
    std::size_t hint = hints_[a];
    const Lifted_midpoint lifted{a, b, moves_[a], moves_[b], lift_(CGAL::midpoint(points_[a], points_[b]), hint)};
    lifted_midpoints_[3 * t + k] = lifted_midpoints_[3 * u + j] = lifted;
    return lifted.x;
  }

  void reserve_lifted_midpoints()
  {
    if(lifted_midpoints_.size() < 3 * triangles_.size())
      lifted_midpoints_.resize(2 * 3 * triangles_.size());
  }

  // Collapses the edge a-b of t = (c, ., .) and u = (d, ., .) into a, which moves to (p, x): b's
  // triangles become a's; t and u are unlinked and stay in the arrays until drop_triangles().
  void collapse(int t, int u, int a, int b, int c, int d, const Point_2& p, const Point_3& x, std::size_t hint)
  {
    const int t_ca = across(t, c, a), t_cb = across(t, c, b), u_da = across(u, d, a), u_db = across(u, d, b);
    std::vector<std::pair<int, int> > fan; // b's triangles and its corner in each
    for_each_star_triangle(b, [&](int f, int k) { fan.emplace_back(f, k); });
    for(const auto& f : fan)
      triangles_[f.first][f.second] = a;
    relink(t_ca, t, t_cb);
    relink(t_cb, t, t_ca);
    relink(u_da, u, u_db);
    relink(u_db, u, u_da);
    neighbor_[t] = neighbor_[u] = {{-1, -1, -1}};
    incident_[a] = incident_[c] = t_ca;
    incident_[d] = u_da;
    incident_[b] = -1;
    fixed_[b] = 1;
    valence_[a] += valence_[b] - 4;
    --valence_[c];
    --valence_[d];
    points_[a] = p;
    positions_[a] = x;
    hints_[a] = hint;
    ++moves_[a];
  }

  // The neighbour of triangle f across its edge p-q.
  int across(int f, int p, int q) const
  {
    for(int i = 0; i < 3; ++i)
    {
      const int v = vertex(f, i + 1), w = vertex(f, i + 2);
      if((v == p && w == q) || (v == q && w == p))
        return neighbor_[f][i];
    }
    return -1;
  }

  // Drops the triangles `dropped` names and numbers the others in their order.
  void drop_triangles(const std::vector<char>& dropped)
  {
    const std::vector<int> index = keep_undropped(dropped, triangles_, neighbor_);
    for(auto& neighbors : neighbor_)
      for(int& u : neighbors)
        if(u >= 0)
          u = index[u];
    for(int& t : incident_)
      if(t >= 0)
        t = index[t];
    lifted_midpoints_.clear(); // by half-edge
  }

  void relink(int w, int from, int to)
  {
    if(w < 0)
      return;
    for(int i = 0; i < 3; ++i)
      if(neighbor_[w][i] == from)
        neighbor_[w][i] = to;
  }

  std::vector<Point_2>& points_;
  std::vector<Point_3>& positions_;
  std::vector<std::array<int, 3> >& triangles_;
  const Lift& lift_;
  const double cos_bound_;
  double longest_squared_;
  Edge_split_bounds kept_chords_; // see keep_chords(); none at first
  std::vector<std::array<int, 3> > neighbor_;
  std::vector<int> incident_, valence_, target_;
  std::vector<char> fixed_;
  std::vector<unsigned char> settled_;
  std::vector<unsigned> moves_; // how many times each vertex moved
  std::vector<std::size_t> hints_; // where each vertex was found by its last lift (see `Lift`)
  std::vector<char> removed_; // the vertices that collapse passes removed
  bool parallel_ = false;
  std::vector<Lifted_midpoint> lifted_midpoints_; // by half-edge, 3 t + k (see lifted_midpoint())
  std::vector<std::size_t> sample_ids_;
  std::set<std::pair<std::size_t, std::size_t> > forbidden_diagonals_;
};

/// Optimizes a patch's remeshing: `rounds` rounds of valence-driven edge flips and smoothing
/// passes; then, when `split` names any edge, a split of the interior edges it names and two
/// more rounds, and up to two more splits of what the rounds made, each with one more round
/// (from the first split on, no flip or move makes an edge longer than `split.longest`, when
/// that is set, unless it replaces a longer one, nor a chord across a bend that
/// `split.across_bend` names, unless it replaces a deeper one); then, when `shortest_edge` is
/// positive, a collapse of the interior edges shorter than it on the surface (times
/// `local_size_ratio` at their planar midpoints, when given: the size field over the target
/// length, which also shrinks the length bound of the collapse) and one more round
/// (the collapsed vertices are removed at the end, and the others numbered in their order; the
/// first `number_of_fixed_points` keep their indices); then skewness passes, which
/// also make no chord `split.tight_curve` names, and angle passes toward 30 degrees (see
/// `Surface_mesh_optimizer`). `points` and `triangles` are the planar mesh (counterclockwise
/// triangles of a manifold domain), `positions` the surface points of its vertices (the splits'
/// new vertices are appended to both) and `lift` the plane-to-surface map. Boundary vertices and
/// the first `number_of_fixed_points` points never move and boundary edges are never flipped, so the
/// domain and its boundary samples are kept; every triangle stays positively oriented in the
/// plane (exact predicates); no operation creates a surface angle below the smaller of
/// `angle_bound_degrees` and the smallest angle it replaces, so the smallest angle never drops
/// below the smaller of its initial value and the bound. Each pass is linear in the mesh size.
/// With `in_parallel`, the vertex moves of each pass run in parallel (see
/// `Surface_mesh_optimizer::run_in_parallel()`), with the same result.
template <typename Lift>
Surface_optimization_report optimize_on_surface(std::vector<Epick::Point_2>& points, std::vector<Epick::Point_3>& positions,
                                                std::vector<std::array<int, 3> >& triangles, std::size_t number_of_fixed_points,
                                                const Lift& lift, double angle_bound_degrees, double longest_edge, const Edge_split_bounds& split, int rounds,
                                                const std::vector<std::size_t>& sample_ids = {},
                                                const std::set<std::pair<std::size_t, std::size_t> >& forbidden_diagonals = {},
                                                bool in_parallel = false, double shortest_edge = 0.,
                                                const std::vector<std::size_t>& hints = {},
                                                const std::function<double(const Epick::Point_2&)>& local_size_ratio = nullptr)
{
  Surface_optimization_report report;
  if(rounds <= 0 || triangles.empty())
    return report;
  Surface_mesh_optimizer<Lift> optimizer(points, positions, triangles, lift, angle_bound_degrees, longest_edge);
  if(!optimizer.initialize(number_of_fixed_points, sample_ids, forbidden_diagonals, hints))
    return report;
  optimizer.run_in_parallel(in_parallel);
  report.optimized = true;
  // Adds to `phase` the seconds since the previous phase ended.
  std::chrono::steady_clock::time_point phase_start = std::chrono::steady_clock::now();
  const auto end_phase = [&phase_start](double& phase) {
    const std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
    phase += std::chrono::duration<double>(now - phase_start).count();
    phase_start = now;
  };
  // Each round: valence flips, then flips that improve shapes without hurting valences, then two
  // smoothing passes; the skewness passes at the end polish what smoothing leaves. (On CGAL's
  // CAD-like models, rounds beyond 5 and a lower skewness threshold gain less than 0.003 in mean
  // skewness.)
  const auto flip_and_smooth = [&]() {
    report.flips += optimizer.flip_pass(Surface_mesh_optimizer<Lift>::VALENCE);
    report.flips += optimizer.flip_pass(Surface_mesh_optimizer<Lift>::SHAPE);
    report.moves += optimizer.smoothing_pass();
    report.moves += optimizer.smoothing_pass();
  };
  for(int round = 0; round < rounds; ++round)
    flip_and_smooth();
  end_phase(report.seconds_first_rounds);
  // From the first split on, the rounds make no chord across a bend (the split passes after them
  // catch the rest); keeping the long chords on tight curves too would hold back the smoothing
  // of scanned surfaces. The skewness passes, with no split after them, keep both; the angle
  // passes only the bends (keeping both, they would leave smaller angles on scanned surfaces).
  Edge_split_bounds bends;
  bends.across_bend = split.across_bend;
  if(split.names_any())
  {
    report.splits = optimizer.split_pass(split, report.chord_splits);
    optimizer.keep_chords(bends);
    for(int round = 0; round < 2; ++round)
      flip_and_smooth();
    // The flips and moves after a split make new chords, some across a bend: split those too.
    // (On a scanned model this lowers the distances to and from the input by 5 to 10%; more
    // passes split few more edges and change no distance.)
    for(int again = 0; again < 2; ++again)
    {
      const std::size_t splits = optimizer.split_pass(split, report.chord_splits);
      if(splits == 0)
        break;
      report.splits += splits;
      flip_and_smooth();
    }
  }
  end_phase(report.seconds_splits);
  // The short edges the splits and the refinement leave are collapsed (keeping both chord bounds,
  // as nothing splits after this), and one more round evens out what that changed.
  if(shortest_edge > 0.)
  {
    optimizer.keep_chords(split);
    report.collapses = optimizer.collapse_pass(shortest_edge, local_size_ratio);
    optimizer.keep_chords(bends);
    flip_and_smooth();
  }
  end_phase(report.seconds_collapses);
  optimizer.keep_chords(split);
  for(int pass = 0; pass < 3; ++pass)
    report.moves += optimizer.skewness_pass(0.12);
  end_phase(report.seconds_skewness_passes);
  // Then the triangles below 30 degrees (a common threshold of mesh quality), or below the
  // bound where that is higher.
  optimizer.keep_chords(bends);
  for(int pass = 0; pass < 3; ++pass)
    report.angle_changes += optimizer.angle_pass((std::max)(30., angle_bound_degrees));
  optimizer.remove_collapsed_vertices();
  end_phase(report.seconds_angle_passes);
  return report;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_OPTIMIZATION_H
