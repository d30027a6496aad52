// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex moves on the glued output, around the cuts between patches. Each patch is optimized
// with its boundary samples fixed (both neighbours must agree on them to glue), and a cut is
// sampled at its turns: on a scan, where cuts follow input edges and zigzag, the triangles at
// those samples are the worst of the output (on a scanned model, about twice the mean equiangle
// skewness of those away from the samples). Once the patches are glued, a cut is no more
// than a line on the surface: its samples and their neighbours may move on the surface like any
// vertex. The samples of features, borders and user patch borders stay.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MOVES_AFTER_GLUING_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MOVES_AFTER_GLUING_H

#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_curves.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/surface_optimization.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The point of the segmented surface closest to `target` among the faces reachable from `start`
/// without crossing a sharp feature, a user patch border or the border, and closer to `target`
/// than `radius`, with its face. (A search from the face a vertex is on, not a search of the
/// whole surface: the closest point of a nearby sheet is never taken.)
inline std::pair<Epick::Point_3, Poly_annulus_segmentation::Face>
closest_point_nearby(const Poly_annulus_segmentation& s, Poly_annulus_segmentation::Face start, const Epick::Point_3& target,
                     double radius, std::vector<Poly_annulus_segmentation::Face>& visited)
{
  typedef Poly_annulus_segmentation::Face Face;
  const auto& m = s.mesh;
  auto triangle = [&](Face f) {
    const auto h = m.halfedge(f);
    return Epick::Triangle_3(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
  };
  const auto project = Epick().construct_projected_point_3_object();
  std::pair<Epick::Point_3, Face> best(project(triangle(start), target), start);
  double best_distance = CGAL::squared_distance(best.first, target);
  visited.assign(1, start);
  const double limit = radius * radius;
  // At most a few hundred faces: the moves are fractions of an output edge.
  for(std::size_t i = 0; i < visited.size() && visited.size() < 512; ++i)
    for(auto h : CGAL::halfedges_around_face(m.halfedge(visited[i]), m))
    {
      const auto e = m.edge(h);
      if(m.is_border(e) || s.is_feature[e] || s.is_user_border[e])
        continue;
      const Face g = m.face(m.opposite(h));
      if(std::find(visited.begin(), visited.end(), g) != visited.end())
        continue;
      const Epick::Point_3 q = project(triangle(g), target);
      const double d = CGAL::squared_distance(q, target);
      if(d > limit)
        continue;
      visited.push_back(g);
      if(d < best_distance)
      {
        best_distance = d;
        best = {q, g};
      }
    }
  return best;
}

/// Which points of a glued triangle soup may move after gluing: the samples of `samples` on no
/// kept curve (feature, border, user patch border), and the points that share a triangle with one
/// and are no sample (the samples are the first points of the soup). (Moving the neighbours too
/// raises the smallest angle of a scanned model by a few degrees.)
inline std::vector<char> points_around_cuts(const Curve_samples& samples, const std::vector<std::array<std::size_t, 3> >& triangles,
                                            std::size_t number_of_points)
{
  std::vector<char> on_cut(number_of_points, 0);
  std::fill(on_cut.begin(), on_cut.begin() + samples.points.size(), 1);
  for(const auto& chord : samples.curve_of_chord)
    if(samples.is_kept_curve[chord.second])
      on_cut[chord.first.first] = on_cut[chord.first.second] = 0;
  std::vector<char> movable(on_cut);
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k)
      if(on_cut[t[k]])
        for(int j = 1; j < 3; ++j)
          if(t[(k + j) % 3] >= samples.points.size())
            movable[t[(k + j) % 3]] = 1;
  return movable;
}

/// How far a moved star may pass from where its vertex first was, in mean edge lengths of the
/// star: a turn of a cut at an input vertex is often on a crease, and a star that cuts the crease
/// off moves the output away from the input. (Any value from 0.02 to 0.1 gives about the same
/// skewness and distances to the input on a scanned model.)
constexpr double largest_cut_off = 0.05;

// The steps of `move_points_after_gluing()`.

// The star of each point `v` with `movable[v]` of a soup of `triangles` on `number_of_points`
// points: the other corners of its triangles, in order.
inline std::vector<std::vector<std::pair<std::size_t, std::size_t> > >
movable_stars(const std::vector<std::array<std::size_t, 3> >& triangles, const std::vector<char>& movable, std::size_t number_of_points)
{
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > star(number_of_points); // the other corners, in order
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k)
      if(movable[t[k]])
        star[t[k]].emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
  return star;
}

// The bounds every move after gluing keeps: the cosines of the target angle and of the largest
// turn of a triangle, and the squared longest edge.
struct Move_bounds
{
  double cos_target, cos_turn, longest_squared;
};

// A star with its vertex at a trial place (see `star_at_point()`).
struct Star_at
{
  bool allowed = true;
  double skewness = 0., worst_cosine = -1.;
  int below = 0;
};

// The star `ring` of v with v at x: its summed skewness, the cosine of its smallest angle and its
// triangles below the target, and whether x keeps the bounds (`limit`: the largest cosine of a
// smallest angle allowed). `normals` are the unit normals of the star's triangles with v where
// it is, `mean_edge` the mean length of its edges there, `original` the points where they first
// were.
inline Star_at star_at_point(const std::vector<Epick::Point_3>& points, const std::vector<Epick::Point_3>& original,
                             const std::vector<std::pair<std::size_t, std::size_t> >& ring, std::size_t v, const Epick::Point_3& x,
                             double limit, const std::vector<Epick::Vector_3>& normals, double mean_edge, const Move_bounds& bounds)
{
  typedef Epick::Point_3 Point_3;
  Star_at result;
  double cut_off = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < ring.size(); ++i)
  {
    const Point_3 &q = points[ring[i].first], &r = points[ring[i].second];
    const double c = Triangle_shape::min_angle_cosine(x, q, r);
    if(!(Triangle_shape::unit_normal(x, q, r) * normals[i] >= bounds.cos_turn) || c > limit
       || CGAL::squared_distance(x, q) > (std::max)(bounds.longest_squared, CGAL::squared_distance(points[v], q)))
      result.allowed = false;
    result.skewness += Triangle_shape::skewness(x, q, r);
    result.worst_cosine = (std::max)(result.worst_cosine, c);
    result.below += c > bounds.cos_target;
    // The star must not cut the surface off where the point was first (a turn of a cut at an
    // input vertex is often a crease): the distance from there to the moved star is bounded.
    cut_off = (std::min)(cut_off, CGAL::squared_distance(original[v], Epick::Triangle_3(x, q, r)));
  }
  if(cut_off > CGAL::square(largest_cut_off * mean_edge))
    result.allowed = false;
  return result;
}

// Looks for a better place for the point at `p` on `face`: `better(x)` says whether its star
// with it at the surface point x is better than at the best place so far, and if so makes x the
// best; a step toward the star's centroid first, when `to_centroid` is given, then a compass
// search in the tangent plane (of `normal`) around where that ended, with steps from a tenth of
// `mean_edge` down to a fortieth. Returns the best place, the point's own if none was better.
template <typename Better>
std::pair<Epick::Point_3, Poly_annulus_segmentation::Face>
search_star_place(const Poly_annulus_segmentation& s, const Epick::Point_3& p, Poly_annulus_segmentation::Face face,
                  const Epick::Vector_3* to_centroid, const Epick::Vector_3& normal, double mean_edge, const Better& better,
                  std::vector<Poly_annulus_segmentation::Face>& visited)
{
  typedef Epick::Vector_3 Vector_3;
  typedef std::pair<Epick::Point_3, Poly_annulus_segmentation::Face> Located;
  Located best(p, face), located;
  auto try_step = [&](const Vector_3& step) {
    located = closest_point_nearby(s, face, p + step, 2. * std::sqrt(step.squared_length()) + 1e-3 * mean_edge, visited);
    if(!better(located.first))
      return false;
    best = located;
    return true;
  };
  if(to_centroid != nullptr)
    for(double t : {1., 0.5, 0.25})
      if(try_step(t * *to_centroid))
        break;
  const Vector_3 n = normal / std::sqrt(normal.squared_length());
  Vector_3 e1 = CGAL::cross_product(n, std::abs(n.x()) < 0.6 ? Vector_3(1., 0., 0.) : Vector_3(0., 1., 0.));
  e1 = e1 / std::sqrt(e1.squared_length());
  const Vector_3 e2 = CGAL::cross_product(n, e1);
  for(double length = 0.1 * mean_edge; length >= 0.1 * mean_edge / 4.; length *= 0.5)
    for(const Vector_3& d : {e1, e2, -e1, -e2})
      try_step((best.first - p) + length * d);
  return best;
}

// One move of `move_points_after_gluing()` of the movable point `v`, whose star `ring` is not
// empty: to a place of lower summed skewness of its star, or with `raise_angles`, of a larger
// smallest angle when it is below the target. `normals` is room for the star's normals.
// Returns whether it moved `v` (`points[v]` and `point_face[v]`).
inline bool move_point_after_gluing(const Poly_annulus_segmentation& s, std::vector<Epick::Point_3>& points,
                                    std::vector<Poly_annulus_segmentation::Face>& point_face,
                                    const std::vector<Epick::Point_3>& original,
                                    const std::vector<std::pair<std::size_t, std::size_t> >& ring, std::size_t v,
                                    bool raise_angles, const Move_bounds& bounds, std::vector<Epick::Vector_3>& normals,
                                    std::vector<Poly_annulus_segmentation::Face>& visited)
{
  typedef Epick::Point_3 Point_3;
  typedef Epick::Vector_3 Vector_3;
  typedef std::pair<Point_3, Poly_annulus_segmentation::Face> Located;
  const Point_3 p = points[v];
  double edge_sum = 0., weight = 0.;
  Vector_3 centroid = CGAL::NULL_VECTOR, normal = CGAL::NULL_VECTOR;
  normals.clear();
  for(const auto& qr : ring)
  {
    const Point_3 &q = points[qr.first], &r = points[qr.second];
    edge_sum += std::sqrt(CGAL::squared_distance(p, q));
    const Vector_3 n = CGAL::cross_product(q - p, r - p);
    const double area = std::sqrt(n.squared_length());
    weight += area;
    centroid = centroid + area * ((p - CGAL::ORIGIN) + (q - CGAL::ORIGIN) + (r - CGAL::ORIGIN)) / 3.;
    normal = normal + n;
    normals.push_back(Triangle_shape::unit_normal(p, q, r));
  }
  if(!(weight > 0.) || !(normal.squared_length() > 0.))
    return false;
  const double mean_edge = edge_sum / double(ring.size());
  const Star_at now = star_at_point(points, original, ring, v, p, std::numeric_limits<double>::infinity(), normals, mean_edge, bounds);
  Located best;
  if(!raise_angles)
  {
    const double limit = (std::max)(bounds.cos_target, now.worst_cosine);
    double best_energy = now.skewness;
    const Vector_3 to_centroid = (CGAL::ORIGIN + centroid / weight) - p;
    best = search_star_place(s, points[v], point_face[v], &to_centroid, normal, mean_edge, [&](const Point_3& x) {
      const Star_at at = star_at_point(points, original, ring, v, x, limit, normals, mean_edge, bounds);
      if(!at.allowed || !(at.skewness < best_energy))
        return false;
      best_energy = at.skewness;
      return true;
    }, visited);
    if(!(best_energy < now.skewness - 1e-6))
      return false;
  }
  else
  {
    if(!(now.worst_cosine > bounds.cos_target))
      return false;
    double best_worst = now.worst_cosine;
    best = search_star_place(s, points[v], point_face[v], nullptr, normal, mean_edge, [&](const Point_3& x) {
      const Star_at at = star_at_point(points, original, ring, v, x, best_worst, normals, mean_edge, bounds);
      if(!at.allowed || !(at.worst_cosine < best_worst) || at.below > now.below)
        return false;
      best_worst = at.worst_cosine;
      return true;
    }, visited);
    if(!(best_worst < now.worst_cosine - 1e-9))
      return false;
  }
  points[v] = best.first;
  point_face[v] = best.second;
  return true;
}

/// Moves the points `i` with `movable[i]` of a glued triangle soup (consistently oriented, a
/// manifold) on the segmented surface, by a Lloyd-like step toward the area-weighted centroid of
/// their star and a compass search in their tangent plane, each point projected onto the nearby
/// surface (`closest_point_nearby()`). A move is taken when it lowers the summed equiangle
/// skewness of the star, turns no triangle of it by more than 30 degrees, makes no angle below
/// the smaller of `target_degrees` and the star's smallest angle, no edge longer than
/// `longest_edge` (or than it was), and leaves the point's first position within
/// `largest_cut_off` mean edge lengths of the star. `point_face` follows the moved points.
/// In up to `passes` passes; then as many passes of moves that raise the smallest angle of the
/// stars that have one below `target_degrees`, by a compass search on it, with the same bounds and
/// no more triangles below the target (at a turn of a cut, two fixed samples and the patch's
/// own passes can leave a triangle near 20 degrees, that the skewness moves raise only by
/// chance). Returns the moves made.
inline std::size_t move_points_after_gluing(const Poly_annulus_segmentation& s, std::vector<Epick::Point_3>& points,
                                             std::vector<Poly_annulus_segmentation::Face>& point_face,
                                             const std::vector<std::array<std::size_t, 3> >& triangles,
                                             const std::vector<char>& movable, double target_degrees, double longest_edge,
                                             int passes)
{
  const std::vector<std::vector<std::pair<std::size_t, std::size_t> > > star = movable_stars(triangles, movable, points.size());
  const Move_bounds bounds{std::cos(target_degrees * CGAL_PI / 180.), std::cos(30. * CGAL_PI / 180.), longest_edge * longest_edge};
  std::vector<Poly_annulus_segmentation::Face> visited;
  const std::vector<Epick::Point_3> original = points;
  std::vector<Epick::Vector_3> normals; // of the star of the point being moved

  std::size_t moves = 0;
  for(int stage = 0; stage < 2; ++stage)
  {
    const bool raise_angles = stage == 1;
    for(int pass = 0; pass < passes; ++pass)
    {
      const std::size_t moves_before = moves;
      for(std::size_t v = 0; v < points.size(); ++v)
      {
        const auto& ring = star[v];
        if(!movable[v] || ring.empty())
          continue;
        if(move_point_after_gluing(s, points, point_face, original, ring, v, raise_angles, bounds, normals, visited))
          ++moves;
      }
      if(moves == moves_before)
        break;
    }
  }
  return moves;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MOVES_AFTER_GLUING_H
