// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Collapses of short edges at the samples of the glued output. Each patch is meshed with its
// boundary samples fixed, and two samples can come much closer than the local size: the ends
// and middle of a short slit (a sharp feature that ends inside a patch is sampled at least
// twice), a curve sample beside the end of another curve, two curves that pass close by. The
// planar meshes cannot move or merge them, and the triangles at such a pair are needles. Once
// the patches are glued, a sample inside a curve is one vertex among others: it may be merged
// into a neighbour, along its curve when the curve must stay an output polyline (features,
// borders, user patch borders).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_COLLAPSES_AFTER_GLUING_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_COLLAPSES_AFTER_GLUING_H

#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_curves.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/surface_optimization.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <iterator>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// Collapses on a glued triangle soup (consistently oriented, a manifold) whose first
/// `samples.points.size()` points are the curve samples. An edge is collapsed when it is shorter
/// than `sample_collapse_edge_factor` times its size (`size(a, b)`), into the endpoint that stays:
///  - a sample at a vertex of the segmented mesh (a curve end: a junction, a corner, a contact)
///    never goes, nor a sample at the point of another sample (sheets in contact share points);
///  - a sample inside a curve that must stay an output polyline (`is_kept_chord()`) goes only
///    into its neighbour along that curve, and only if it stands within `border_chord_deviation`
///    times the size of the chord from that neighbour to its other one (a turn of a border or a
///    feature is not cut off), which is then kept (`is_kept_chord()`);
///  - any other point may go.
/// A collapse is taken only when the result stays a manifold (the link condition), no remaining
/// triangle around the point that goes turns over or degenerates (its normal stays within 90
/// degrees of the old one), the new triangles pass the point that goes within
/// `border_chord_deviation` times the size (on a crease they would cut it off), their
/// centroids stand off the input surface (`off_surface`, when given) by no more than that or
/// than the centroids of the triangles they replace, and no angle falls below the smaller of
/// `angle_degrees` and the smallest angle of the triangles it changes or removes; where that
/// smallest angle is below `angle_degrees`, the collapse must raise it. Shortest edges first.
/// Removed triangles are dropped from `triangles` and `patch_of_triangle` (the points that go
/// stay in `points`, used by no triangle). Returns the number of collapses.
class Glued_soup_collapser
{
public:
  typedef std::array<std::size_t, 3> Triangle;
  typedef std::function<double(std::size_t, std::size_t)> Edge_size;
  /// the squared distance from a point to the input surface near the soup's point `near`
  typedef std::function<double(const Epick::Point_3&, std::size_t near)> Off_surface;

  Glued_soup_collapser(const std::vector<Epick::Point_3>& points, std::vector<Triangle>& triangles,
                       std::vector<std::size_t>& patch_of_triangle, const Curve_samples& samples, double angle_degrees,
                       const Off_surface& off_surface = nullptr)
    : points_(points), triangles_(triangles), patch_of_triangle_(patch_of_triangle), samples_(samples),
      cos_angle_(std::cos(angle_degrees * CGAL_PI / 180.)), off_surface_(off_surface), star_(points.size()),
      removable_(points.size(), 1)
  {
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      for(std::size_t v : triangles_[t])
        star_[v].push_back(t);
    for(const auto& at_vertex : samples_.at_vertex)
      removable_[at_vertex.second] = 0;
    std::vector<std::pair<Epick::Point_3, std::size_t> > by_point;
    for(std::size_t i = 0; i < samples_.points.size(); ++i)
      by_point.emplace_back(samples_.points[i], i);
    std::sort(by_point.begin(), by_point.end());
    for(std::size_t k = 1; k < by_point.size(); ++k)
      if(by_point[k].first == by_point[k - 1].first)
        removable_[by_point[k].second] = removable_[by_point[k - 1].second] = 0;
  }

  bool is_kept_chord(std::size_t a, std::size_t b) const
  {
    const std::size_t n = samples_.points.size();
    return (a < n && b < n && samples_.is_kept_chord(a, b)) || kept_chords_.count(std::minmax(a, b)) > 0;
  }

  /// `largest_size`: no edge's size exceeds it (the target), so that `size` is asked only about
  /// the edges short enough for it.
  std::size_t collapse_short_edges(const Edge_size& size, double largest_size)
  {
    const double longest_candidate = sample_collapse_edge_factor * largest_size;
    std::vector<std::tuple<double, std::size_t, std::size_t, double> > candidates; // length^2, ends, size
    for(const Triangle& t : triangles_)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t a = (std::min)(t[k], t[(k + 1) % 3]), b = (std::max)(t[k], t[(k + 1) % 3]);
        const double squared = CGAL::squared_distance(points_[a], points_[b]);
        if(!(squared < longest_candidate * longest_candidate))
          continue;
        const double edge_size = size(a, b);
        if(squared < CGAL::square(sample_collapse_edge_factor * edge_size))
          candidates.emplace_back(squared, a, b, edge_size);
      }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end()); // an inner edge is in two triangles
    std::size_t collapses = 0;
    for(const auto& c : candidates)
    {
      const std::size_t a = std::get<1>(c), b = std::get<2>(c);
      if(!has_edge(a, b))
        continue; // an earlier collapse took it
      const double deviation = border_chord_deviation * std::get<3>(c);
      if(try_collapse(a, b, deviation) || try_collapse(b, a, deviation))
        ++collapses;
    }
    if(collapses > 0)
      drop_removed_triangles();
    return collapses;
  }

private:
  bool has_edge(std::size_t a, std::size_t b) const
  {
    return std::any_of(star_[a].begin(), star_[a].end(), [&](std::size_t t) { return !removed(t) && contains(t, b); });
  }
  bool removed(std::size_t t) const { return triangles_[t][0] == triangles_[t][1]; }
  bool contains(std::size_t t, std::size_t v) const
  {
    return triangles_[t][0] == v || triangles_[t][1] == v || triangles_[t][2] == v;
  }

  // The neighbours of `v` (vertices of its live triangles other than itself).
  std::set<std::size_t> neighbours(std::size_t v) const
  {
    std::set<std::size_t> result;
    for(std::size_t t : star_[v])
      if(!removed(t))
        for(std::size_t w : triangles_[t])
          if(w != v)
            result.insert(w);
    return result;
  }

  // Whether `u` may go into `v` by the rules of the class (`deviation`: how far a sample of a
  // kept curve may stand off the chord that replaces it); then the chord it leaves along a kept
  // curve, if any, in `kept` (`v`'s new neighbour along the curve).
  bool may_go_into(std::size_t u, std::size_t v, double deviation, std::size_t& kept) const
  {
    kept = std::size_t(-1);
    if(!removable_[u])
      return false;
    std::vector<std::size_t> along; // u's neighbours along a kept curve
    for(std::size_t w : neighbours(u))
      if(is_kept_chord(u, w))
        along.push_back(w);
    if(along.empty())
      return true;
    if(along.size() != 2 || std::find(along.begin(), along.end(), v) == along.end())
      return false;
    kept = along[0] == v ? along[1] : along[0];
    return CGAL::squared_distance(points_[u], Epick::Segment_3(points_[v], points_[kept])) <= deviation * deviation;
  }

  bool try_collapse(std::size_t u, std::size_t v, double deviation)
  {
    std::size_t kept = 0;
    if(!may_go_into(u, v, deviation, kept))
      return false;
    // The link condition: the common neighbours of u and v are the third corners of the
    // triangles on their edge.
    std::set<std::size_t> opposite;
    std::vector<std::size_t> on_edge, changed;
    for(std::size_t t : star_[u])
      if(!removed(t))
      {
        if(contains(t, v))
        {
          on_edge.push_back(t);
          for(std::size_t w : triangles_[t])
            if(w != u && w != v)
              opposite.insert(w);
        }
        else
          changed.push_back(t);
      }
    const std::set<std::size_t> of_u = neighbours(u), of_v = neighbours(v);
    std::vector<std::size_t> common;
    std::set_intersection(of_u.begin(), of_u.end(), of_v.begin(), of_v.end(), std::back_inserter(common));
    if(on_edge.empty() || common.size() != opposite.size() || !std::equal(common.begin(), common.end(), opposite.begin()))
      return false;
    if(kept != std::size_t(-1) && of_v.count(kept) > 0)
      return false; // the kept curve would fold onto an existing edge
    // The shapes: no turn-over, and no angle below the bound or the smallest replaced.
    double worst_before = -1.; // the largest cosine of a smallest angle
    for(std::size_t t : star_[u])
      if(!removed(t))
        worst_before = (std::max)(worst_before, min_angle_cosine(triangles_[t]));
    // Cosines: a larger one is a smaller angle. Where an angle is below the bound, the collapse
    // must raise the smallest.
    const double allowed = (std::max)(cos_angle_, worst_before);
    double worst_after = -1., nearest = std::numeric_limits<double>::infinity();
    for(std::size_t t : changed)
    {
      const Triangle moved = with_replaced(triangles_[t], u, v);
      const Epick::Vector_3 before = normal(triangles_[t]), after = normal(moved);
      if(!(before * after > 0.))
        return false;
      worst_after = (std::max)(worst_after, min_angle_cosine(moved));
      nearest = (std::min)(nearest, CGAL::squared_distance(points_[u], triangle(moved)));
    }
    if(worst_after > allowed || (worst_before > cos_angle_ && !(worst_after < worst_before)))
      return false;
    if(!(nearest <= deviation * deviation))
      return false; // the new triangles would pass the point by: a crease cut off
    if(off_surface_ && !stays_on_surface(u, v, changed, on_edge, deviation))
      return false;
    for(std::size_t t : changed)
    {
      triangles_[t] = with_replaced(triangles_[t], u, v);
      star_[v].push_back(t);
    }
    for(std::size_t t : on_edge)
      triangles_[t] = Triangle{{0, 0, 0}}; // removed
    star_[u].clear();
    if(kept != std::size_t(-1))
      kept_chords_.insert(std::minmax(v, kept));
    return true;
  }

  // Whether the centroids of the triangles around `u` once it went into `v` stand off the input
  // surface by at most `deviation`, or by no more than those of the triangles they replace.
  bool stays_on_surface(std::size_t u, std::size_t v, const std::vector<std::size_t>& changed,
                        const std::vector<std::size_t>& on_edge, double deviation) const
  {
    const auto centroid = [&](const Triangle& t) { return CGAL::centroid(points_[t[0]], points_[t[1]], points_[t[2]]); };
    double before = deviation * deviation;
    for(const std::vector<std::size_t>* ts : {&changed, &on_edge})
      for(std::size_t t : *ts)
        before = (std::max)(before, off_surface_(centroid(triangles_[t]), u));
    for(std::size_t t : changed)
      if(off_surface_(centroid(with_replaced(triangles_[t], u, v)), v) > before)
        return false;
    return true;
  }

  static Triangle with_replaced(Triangle t, std::size_t u, std::size_t v)
  {
    std::replace(t.begin(), t.end(), u, v);
    return t;
  }

  double min_angle_cosine(const Triangle& t) const
  {
    return Triangle_shape::min_angle_cosine(points_[t[0]], points_[t[1]], points_[t[2]]);
  }
  Epick::Triangle_3 triangle(const Triangle& t) const { return Epick::Triangle_3(points_[t[0]], points_[t[1]], points_[t[2]]); }
  Epick::Vector_3 normal(const Triangle& t) const
  {
    return CGAL::cross_product(points_[t[1]] - points_[t[0]], points_[t[2]] - points_[t[0]]);
  }

  void drop_removed_triangles()
  {
    std::size_t kept = 0;
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      if(!removed(t))
      {
        triangles_[kept] = triangles_[t];
        patch_of_triangle_[kept] = patch_of_triangle_[t];
        ++kept;
      }
    triangles_.resize(kept);
    patch_of_triangle_.resize(kept);
  }

  const std::vector<Epick::Point_3>& points_;
  std::vector<Triangle>& triangles_;
  std::vector<std::size_t>& patch_of_triangle_;
  const Curve_samples& samples_;
  double cos_angle_;
  Off_surface off_surface_;
  std::vector<std::vector<std::size_t> > star_; // triangles at each point, removed ones included
  std::vector<char> removable_;
  std::set<std::pair<std::size_t, std::size_t> > kept_chords_;
};

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_COLLAPSES_AFTER_GLUING_H
