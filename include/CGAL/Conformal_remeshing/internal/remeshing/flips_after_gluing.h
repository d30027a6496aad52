// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge flips on the glued output, for the shapes the patches cannot improve alone. Each patch
// is optimized with its boundary samples and boundary chords fixed (both neighbours must keep
// the same chords to glue), so a thin triangle leaning on a cut between two patches stays,
// however good the triangle on the other side is (on a scanned model cut every few target
// lengths, a few such triangles are below 20 degrees, down to 5). Once the patches are glued, a
// chord of a cut is an edge like any other and can be flipped; chords of features, borders and
// user patch borders stay.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FLIPS_AFTER_GLUING_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FLIPS_AFTER_GLUING_H

#include <CGAL/Conformal_remeshing/internal/remeshing/surface_optimization.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The flips made on a triangle soup, and how to undo them.
struct Soup_flips
{
  typedef std::array<std::size_t, 3> Triangle;
  std::size_t flips = 0;
  std::vector<std::pair<std::size_t, Triangle> > replaced; ///< each changed triangle as it was first

  void undo(std::vector<Triangle>& triangles) const
  {
    for(const auto& r : replaced)
      triangles[r.first] = r.second;
  }
};

/// Flips on a glued triangle soup (consistently oriented, each edge in at most two triangles: a
/// manifold) whose points never move, so they stay on the surface. An edge `(a, b)` for which
/// `is_kept(a, b)` holds is never flipped. A flip is taken only when it is a small change of the
/// surface's approximation:
///  - the quad is strictly convex seen along the mean normal of its two triangles (no fold),
///  - the new triangles bend against each other by no more than the old ones did, or 20 degrees,
///  - the new edge is no longer than the longest side of the quad or the edge it replaces,
///  - the new edge is not an edge already (the result stays a manifold),
/// and no flip makes an angle below the smaller of `target_degrees` and the smallest angle of the
/// two triangles it replaces.
class Glued_soup_flipper
{
public:
  typedef std::array<std::size_t, 3> Triangle;
  typedef std::function<bool(std::size_t, std::size_t)> Edge_predicate;

  Glued_soup_flipper(const std::vector<Epick::Point_3>& points, std::vector<Triangle>& triangles, const Edge_predicate& is_kept,
                     double target_degrees)
    : points_(points), triangles_(triangles), is_kept_(is_kept), cos_target_(std::cos(target_degrees * CGAL_PI / 180.)),
      star_(points.size()), replaced_(triangles.size(), 0)
  {
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      for(std::size_t v : triangles_[t])
        star_[v].push_back(t);
  }

  /// Every triangle below the target angle has the edge flipped that raises the smaller of its
  /// and its neighbour's smallest angles most, in rounds until none does.
  void angle_passes()
  {
    std::vector<std::size_t> bad;
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      if(is_below_target(t))
        bad.push_back(t);
    for(int round = 0; round < 8 && !bad.empty(); ++round)
    {
      const std::size_t flips_before = result_.flips;
      std::vector<std::size_t> still_bad;
      for(std::size_t t : bad)
      {
        if(!is_below_target(t))
          continue;
        Candidate best;
        for(int k = 0; k < 3; ++k)
        {
          const Candidate c = candidate(t, k);
          if(c.u >= 0 && c.new_worst < c.old_worst && c.new_worst < best.new_worst)
            best = c;
        }
        if(best.u < 0)
        {
          still_bad.push_back(t);
          continue;
        }
        flip(best);
        for(std::size_t w : {t, std::size_t(best.u)})
          if(is_below_target(w))
            still_bad.push_back(w);
      }
      std::sort(still_bad.begin(), still_bad.end());
      still_bad.erase(std::unique(still_bad.begin(), still_bad.end()), still_bad.end());
      if(result_.flips == flips_before) // another round would try the same flips
        break;
      bad.swap(still_bad);
    }
  }

  /// Every edge for which `is_candidate(a, b)` holds is flipped when that lowers the larger
  /// equiangle skewness of its two triangles by 0.01 or more, in up to `passes` passes.
  void shape_passes(const Edge_predicate& is_candidate, int passes)
  {
    // The triangles with a chosen edge, listed once (in order): a flip gives new edges only to
    // its two triangles, which share a chosen edge and so are both listed. On a remeshing these
    // are the few triangles along the patch boundaries, not the whole mesh at every pass.
    std::vector<std::size_t> listed;
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      for(int k = 0; k < 3; ++k)
        if(is_candidate(triangles_[t][k], triangles_[t][(k + 1) % 3]))
        {
          listed.push_back(t);
          break;
        }
    for(int pass = 0; pass < passes; ++pass)
    {
      const std::size_t flips_before = result_.flips;
      for(std::size_t t : listed)
        for(int k = 0; k < 3; ++k)
        {
          const Triangle& tri = triangles_[t];
          if(!is_candidate(tri[(k + 1) % 3], tri[(k + 2) % 3]))
            continue;
          const Candidate c = candidate(t, k);
          if(c.u < 0 || !(c.new_worst <= (std::max)(c.old_worst, cos_target_)))
            continue;
          const Triangle& other = triangles_[std::size_t(c.u)];
          const double old_skewness = (std::max)(skewness(tri[0], tri[1], tri[2]), skewness(other[0], other[1], other[2]));
          const double new_skewness = (std::max)(skewness(c.c, c.a, c.d), skewness(c.c, c.d, c.b));
          if(new_skewness < old_skewness - 0.01)
          {
            flip(c);
            break; // t changed
          }
        }
      if(result_.flips == flips_before)
        break;
    }
  }

  const Soup_flips& result() const { return result_; }

private:
  // Flipping the edge opposite corner k of t, shared with u: (c, a, b) and (d, b, a) become
  // (c, a, d) and (c, d, b); u < 0 when the flip is not allowed.
  struct Candidate
  {
    std::size_t t = 0;
    long u = -1;
    std::size_t a = 0, b = 0, c = 0, d = 0;
    double old_worst = 1., new_worst = 2.; // cosines of the smallest angles
  };

  Candidate candidate(std::size_t t, int k) const
  {
    Candidate r;
    r.t = t;
    r.c = triangles_[t][k];
    r.a = triangles_[t][(k + 1) % 3];
    r.b = triangles_[t][(k + 2) % 3];
    if(is_kept_(r.a, r.b))
      return r;
    const long u = across(r.a, r.b);
    if(u < 0)
      return r;
    r.d = triangles_[std::size_t(u)][(corner_of(std::size_t(u), r.b) + 2) % 3];
    if(r.d == r.c || is_edge(r.c, r.d))
      return r;
    const Epick::Point_3 &a = points_[r.a], &b = points_[r.b], &c = points_[r.c], &d = points_[r.d];
    const Epick::Vector_3 n_t = Triangle_shape::unit_normal(c, a, b), n_u = Triangle_shape::unit_normal(d, b, a), mean = n_t + n_u;
    if(!(CGAL::cross_product(a - c, d - c) * mean > 0.) || !(CGAL::cross_product(d - c, b - c) * mean > 0.))
      return r;
    if(!(Triangle_shape::unit_normal(c, a, d) * Triangle_shape::unit_normal(c, d, b) >= (std::min)(n_t * n_u, cos_bend_)))
      return r;
    const double longest = (std::max)({CGAL::squared_distance(a, b), CGAL::squared_distance(a, c), CGAL::squared_distance(c, b),
                                       CGAL::squared_distance(b, d), CGAL::squared_distance(d, a)});
    if(CGAL::squared_distance(c, d) > longest)
      return r;
    r.old_worst = (std::max)(Triangle_shape::min_angle_cosine(c, a, b), Triangle_shape::min_angle_cosine(d, b, a));
    r.new_worst = (std::max)(Triangle_shape::min_angle_cosine(c, a, d), Triangle_shape::min_angle_cosine(c, d, b));
    r.u = u;
    return r;
  }

  void flip(const Candidate& f)
  {
    const std::size_t t = f.t, u = std::size_t(f.u);
    for(std::size_t w : {t, u})
      if(!replaced_[w])
      {
        replaced_[w] = 1;
        result_.replaced.emplace_back(w, triangles_[w]);
      }
    triangles_[t] = {{f.c, f.a, f.d}};
    triangles_[u] = {{f.c, f.d, f.b}};
    // t lost b and gained d; u lost a and gained c.
    star_[f.b].erase(std::find(star_[f.b].begin(), star_[f.b].end(), t));
    star_[f.d].push_back(t);
    star_[f.a].erase(std::find(star_[f.a].begin(), star_[f.a].end(), u));
    star_[f.c].push_back(u);
    ++result_.flips;
  }

  bool is_below_target(std::size_t t) const
  {
    const Triangle& tri = triangles_[t];
    return Triangle_shape::min_angle_cosine(points_[tri[0]], points_[tri[1]], points_[tri[2]]) > cos_target_;
  }

  double skewness(std::size_t p, std::size_t q, std::size_t r) const
  {
    return Triangle_shape::skewness(points_[p], points_[q], points_[r]);
  }

  int corner_of(std::size_t t, std::size_t v) const
  {
    return int(std::find(triangles_[t].begin(), triangles_[t].end(), v) - triangles_[t].begin());
  }

  // The triangle that runs the edge b -> a (the other side of a -> b), or -1.
  long across(std::size_t a, std::size_t b) const
  {
    for(std::size_t u : star_[a])
    {
      const int j = corner_of(u, b);
      if(j < 3 && triangles_[u][(j + 1) % 3] == a)
        return long(u);
    }
    return -1;
  }

  bool is_edge(std::size_t c, std::size_t d) const
  {
    return std::any_of(star_[c].begin(), star_[c].end(), [&](std::size_t u) { return corner_of(u, d) < 3; });
  }

  const std::vector<Epick::Point_3>& points_;
  std::vector<Triangle>& triangles_;
  Edge_predicate is_kept_;
  double cos_target_;
  const double cos_bend_ = std::cos(20. * CGAL_PI / 180.);
  std::vector<std::vector<std::size_t> > star_; // the triangles around each point
  std::vector<char> replaced_;
  Soup_flips result_;
};

/// The angle passes of `Glued_soup_flipper` alone (see there).
inline Soup_flips flip_small_angles_after_gluing(const std::vector<Epick::Point_3>& points,
                                                 std::vector<std::array<std::size_t, 3> >& triangles,
                                                 const Glued_soup_flipper::Edge_predicate& is_kept, double target_degrees)
{
  Glued_soup_flipper flipper(points, triangles, is_kept, target_degrees);
  flipper.angle_passes();
  return flipper.result();
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FLIPS_AFTER_GLUING_H
