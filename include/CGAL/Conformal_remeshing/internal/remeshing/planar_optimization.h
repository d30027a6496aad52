// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Optimization of a planar triangle mesh after Delaunay refinement: edge flips toward regular
// valences, then vertex moves that improve the shape of the triangles. Refinement meshes are
// shape-bounded but irregular (less than half of the vertices have valence 6, mean equiangle
// skewness near 0.16); this step brings them near 0.10 without moving the boundary or folding a
// triangle. Shapes are measured in the plane: the conformal map keeps angles, and the size field
// only scales the plane locally, which no shape measure sees.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_OPTIMIZATION_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_OPTIMIZATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The parameters of `optimize_planar_triangulation()`.
struct Planar_optimization_parameters
{
  /// No flip or move creates an angle below the smaller of this bound (degrees) and the smallest
  /// angle of the triangles it replaces.
  double angle_bound_degrees = 28.;
  /// shape passes per round (each round: one flip pass, then these)
  int shape_passes = 3;
  /// After the rounds, the vertices whose star has a triangle of equiangle skewness at least
  /// this get a direct search on the skewness of their star; above 1 disables it.
  double skewness_threshold = 0.1;
};

/// What `optimize_planar_triangulation()` did.
struct Planar_optimization_report
{
  bool optimized = false; ///< false when the input is not a manifold triangulation (left as is)
  std::size_t flips = 0;
  std::size_t moves = 0;
};

/// An edge-adjacency view of an indexed planar triangle mesh, with the flips and vertex moves of
/// the optimization. Triangles are counterclockwise; `neighbor_[t][k]` is the triangle across the
/// edge opposite to corner `k` of `t`, or -1 on the boundary.
class Planar_triangulation_optimizer
{
public:
  typedef Epick::Point_2 Point;

  Planar_triangulation_optimizer(std::vector<Point>& points, std::vector<std::array<int, 3> >& triangles,
                                 double angle_bound_degrees)
    : points_(points), triangles_(triangles), cos_bound_(std::cos(angle_bound_degrees * CGAL_PI / 180.))
  {}

  /// Builds the adjacency and the target valences; false if an edge has more than two triangles
  /// or two triangles with the same orientation. Vertices on a boundary edge and the first
  /// `number_of_fixed_points` points are fixed. `surface_angle[v]`, when positive, is the angle
  /// (in [0, pi], radians) between the boundary edges at `v` on the surface: at a corner the
  /// flattening does not keep the boundary's angle, and the valence that makes good triangles
  /// on the surface follows the surface's angle.
  bool initialize(std::size_t number_of_fixed_points, const std::vector<double>& surface_angle)
  {
    const std::size_t nt = triangles_.size(), nv = points_.size();
    neighbor_.assign(nt, {{-1, -1, -1}});
    // Sort the half-edges by their undirected edge: twins become adjacent.
    std::vector<std::pair<std::uint64_t, std::uint32_t> > half_edges;
    half_edges.reserve(3 * nt);
    for(std::size_t t = 0; t < nt; ++t)
      for(int k = 0; k < 3; ++k)
      {
        const std::uint64_t a = std::uint64_t(vertex(int(t), k + 1)), b = std::uint64_t(vertex(int(t), k + 2));
        half_edges.emplace_back((std::min)(a, b) << 32 | (std::max)(a, b), std::uint32_t(3 * t + k));
      }
    std::sort(half_edges.begin(), half_edges.end());
    boundary_.assign(nv, 0);
    valence_.assign(nv, 0);
    for(std::size_t i = 0; i < half_edges.size();)
    {
      std::size_t j = i + 1;
      while(j < half_edges.size() && half_edges[j].first == half_edges[i].first)
        ++j;
      if(j - i > 2)
        return false;
      const int a = int(half_edges[i].first >> 32), b = int(half_edges[i].first & 0xffffffffu);
      ++valence_[a];
      ++valence_[b];
      const std::uint32_t h = half_edges[i].second;
      if(j - i == 2)
      {
        const std::uint32_t g = half_edges[i + 1].second;
        if(vertex(int(h / 3), int(h % 3) + 1) == vertex(int(g / 3), int(g % 3) + 1))
          return false; // both run the same way: inconsistent orientation
        neighbor_[h / 3][h % 3] = int(g / 3);
        neighbor_[g / 3][g % 3] = int(h / 3);
      }
      else
        boundary_[a] = boundary_[b] = 1;
      i = j;
    }
    fixed_ = boundary_;
    for(std::size_t v = 0; v < (std::min)(number_of_fixed_points, nv); ++v)
      fixed_[v] = 1;

    // The ideal valence: 6 inside; on the boundary, one triangle per 60 degrees of the domain's
    // angle (4 edges on a straight boundary), an angle that no operation here changes.
    std::vector<double> angle(nv, 0.);
    incident_.assign(nv, -1);
    for(std::size_t t = 0; t < nt; ++t)
      for(int k = 0; k < 3; ++k)
      {
        const int v = vertex(int(t), k);
        incident_[v] = int(t);
        angle[v] += corner_angle(points_[v], points_[vertex(int(t), k + 1)], points_[vertex(int(t), k + 2)]);
      }
    target_.assign(nv, 6);
    for(std::size_t v = 0; v < nv; ++v)
      if(boundary_[v])
      {
        double a = angle[v];
        if(v < surface_angle.size() && surface_angle[v] > 0.)
          a = (angle[v] > CGAL_PI) ? 2. * CGAL_PI - surface_angle[v] : surface_angle[v]; // reflex in the plane: reflex
        target_[v] = 1 + (std::max)(1, int(std::lround(a * 3. / CGAL_PI)));
      }
    return true;
  }

  /// Flips every interior edge whose flip brings the valences of its four vertices closer to
  /// their targets (sum of squared deviations), when its quad is strictly convex (exact
  /// predicate) and the flip passes the angle bound.
  std::size_t flip_pass()
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
        if(after >= before)
          continue;
        const Point &pa = points_[a], &pb = points_[b], &pc = points_[c], &pd = points_[d];
        if(CGAL::orientation(pc, pa, pd) != CGAL::POSITIVE || CGAL::orientation(pc, pd, pb) != CGAL::POSITIVE)
          continue;
        const double old_worst = (std::max)(min_angle_cosine(pc, pa, pb), min_angle_cosine(pd, pb, pa));
        const double new_worst = (std::max)(min_angle_cosine(pc, pa, pd), min_angle_cosine(pc, pd, pb));
        if(new_worst > (std::max)(old_worst, cos_bound_))
          continue;
        flip(t, k, u, j);
        ++flips;
      }
    return flips;
  }

  /// Moves every free vertex by a gradient step, halved until it is accepted, on the sum over
  /// its star of the inverse mean ratios `(l0^2 + l1^2 + l2^2) / (4 sqrt(3) area)` (1 for an
  /// equilateral triangle, infinite for a flat one).
  std::size_t shape_pass()
  {
    std::size_t moves = 0;
    std::vector<int> ring;
    const double k = 4. * std::sqrt(3.);
    for(std::size_t v = 0; v < points_.size(); ++v)
    {
      if(fixed_[v] || !interior_ring(int(v), ring))
        continue;
      auto energy = [&](const Point& p, double* gx, double* gy) {
        double e = 0.;
        if(gx != nullptr)
          *gx = *gy = 0.;
        for(std::size_t i = 0; i < ring.size(); ++i)
        {
          const Point &q = points_[ring[i]], &r = points_[ring[(i + 1) % ring.size()]];
          const double area = 0.5 * ((q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()));
          if(!(area > 0.))
            return std::numeric_limits<double>::infinity();
          const double sum = CGAL::squared_distance(p, q) + CGAL::squared_distance(p, r) + CGAL::squared_distance(q, r);
          e += sum / (k * area);
          if(gx != nullptr)
          {
            // d area / dp and d sum / dp
            const double dax = 0.5 * (q.y() - r.y()), day = 0.5 * (r.x() - q.x());
            const double dsx = 2. * (2. * p.x() - q.x() - r.x()), dsy = 2. * (2. * p.y() - q.y() - r.y());
            *gx += (dsx * area - sum * dax) / (k * area * area);
            *gy += (dsy * area - sum * day) / (k * area * area);
          }
        }
        return e;
      };
      const Point p = points_[v];
      double gx = 0., gy = 0.;
      const double e0 = energy(p, &gx, &gy);
      const double g = std::sqrt(gx * gx + gy * gy);
      if(!(g > 0.) || !std::isfinite(e0))
        continue;
      // First step: a tenth of the mean edge length.
      double step = 0.1 * mean_ring_distance(p, ring) / g;
      const double limit = move_limit(p, ring);
      for(int attempt = 0; attempt < 6; ++attempt, step *= 0.5)
      {
        const Point moved(p.x() - step * gx, p.y() - step * gy);
        if(energy(moved, nullptr, nullptr) < e0 && star_accepts(moved, ring, limit))
        {
          points_[v] = moved;
          ++moves;
          break;
        }
      }
    }
    return moves;
  }

  /// Moves every free vertex whose star has a triangle of skewness `threshold` or more by a
  /// compass search (4 directions, 4 step lengths) on the sum of the skewnesses of its star: the
  /// shape passes leave the triangles around irregular vertices slightly off the skewness optimum.
  std::size_t skewness_pass(double threshold)
  {
    std::size_t moves = 0;
    std::vector<int> ring;
    for(std::size_t v = 0; v < points_.size(); ++v)
    {
      if(fixed_[v] || !interior_ring(int(v), ring))
        continue;
      const Point p = points_[v];
      double worst = 0.;
      for(std::size_t i = 0; i < ring.size(); ++i)
        worst = (std::max)(worst, skewness(p, points_[ring[i]], points_[ring[(i + 1) % ring.size()]]));
      if(worst < threshold)
        continue;
      auto energy = [&](const Point& x) {
        double e = 0.;
        for(std::size_t i = 0; i < ring.size(); ++i)
          e += skewness(x, points_[ring[i]], points_[ring[(i + 1) % ring.size()]]);
        return e;
      };
      const double limit = move_limit(p, ring);
      double best = energy(p);
      Point best_point = p;
      const double directions[4][2] = {{1., 0.}, {0., 1.}, {-1., 0.}, {0., -1.}};
      for(double step = 0.05 * mean_ring_distance(p, ring), last = step / 8.; step >= last; step *= 0.5)
        for(const auto& d : directions)
        {
          const Point moved(best_point.x() + step * d[0], best_point.y() + step * d[1]);
          const double e = energy(moved);
          if(e < best && star_accepts(moved, ring, limit))
          {
            best = e;
            best_point = moved;
          }
        }
      if(best_point != p)
      {
        points_[v] = best_point;
        ++moves;
      }
    }
    return moves;
  }

  const std::vector<int>& valences() const { return valence_; }
  const std::vector<int>& target_valences() const { return target_; }
  const std::vector<char>& fixed() const { return fixed_; }
  const std::vector<char>& on_boundary() const { return boundary_; }

  /// the cosine of the smallest angle of a triangle (larger is worse), from its edge lengths
  static double min_angle_cosine(const Point& p, const Point& q, const Point& r)
  {
    const double a = CGAL::squared_distance(q, r), b = CGAL::squared_distance(r, p), c = CGAL::squared_distance(p, q);
    // The smallest angle is opposite the shortest edge.
    if(a <= b && a <= c)
      return (b + c - a) / (2. * std::sqrt(b * c));
    if(b <= c)
      return (c + a - b) / (2. * std::sqrt(c * a));
    return (a + b - c) / (2. * std::sqrt(a * b));
  }

  /// the equiangle skewness `max((t_max - 60) / 120, (60 - t_min) / 60)` of a triangle
  static double skewness(const Point& p, const Point& q, const Point& r)
  {
    const double a = CGAL::squared_distance(q, r), b = CGAL::squared_distance(r, p), c = CGAL::squared_distance(p, q);
    auto angle = [](double opposite, double x, double y) {
      return std::acos((std::max)(-1., (std::min)(1., (x + y - opposite) / (2. * std::sqrt(x * y)))));
    };
    const double alpha = angle(a, b, c), beta = angle(b, c, a), gamma = CGAL_PI - alpha - beta;
    const double largest = (std::max)({alpha, beta, gamma}), smallest = (std::min)({alpha, beta, gamma});
    return (std::max)((largest - CGAL_PI / 3.) / (2. * CGAL_PI / 3.), (CGAL_PI / 3. - smallest) / (CGAL_PI / 3.));
  }

private:
  int vertex(int t, int k) const { return triangles_[t][k % 3]; }

  int opposite_corner(int u, int t) const
  {
    for(int j = 0; j < 3; ++j)
      if(neighbor_[u][j] == t)
        return j;
    return -1;
  }

  static double corner_angle(const Point& p, const Point& q, const Point& r)
  {
    const double ux = q.x() - p.x(), uy = q.y() - p.y(), vx = r.x() - p.x(), vy = r.y() - p.y();
    return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
  }

  double mean_ring_distance(const Point& p, const std::vector<int>& ring) const
  {
    double sum = 0.;
    for(int w : ring)
      sum += std::sqrt(CGAL::squared_distance(p, points_[w]));
    return sum / double(ring.size());
  }

  // The largest cosine of a smallest angle a move from p may leave in the star: the bound, or
  // the star's smallest angle if that is already below it.
  double move_limit(const Point& p, const std::vector<int>& ring) const
  {
    double worst = cos_bound_;
    for(std::size_t i = 0; i < ring.size(); ++i)
      worst = (std::max)(worst, min_angle_cosine(p, points_[ring[i]], points_[ring[(i + 1) % ring.size()]]));
    return worst;
  }

  // Whether the star moved to x is positively oriented (exact predicate) and within the limit.
  bool star_accepts(const Point& x, const std::vector<int>& ring, double limit) const
  {
    for(std::size_t i = 0; i < ring.size(); ++i)
    {
      const Point &q = points_[ring[i]], &r = points_[ring[(i + 1) % ring.size()]];
      if(CGAL::orientation(x, q, r) != CGAL::POSITIVE || min_angle_cosine(x, q, r) > limit)
        return false;
    }
    return true;
  }

  // The neighbours of an interior vertex, counterclockwise; false for a vertex on the boundary.
  bool interior_ring(int v, std::vector<int>& ring) const
  {
    ring.clear();
    const int first = incident_[v];
    if(first < 0)
      return false;
    int t = first;
    do
    {
      const int k = vertex(t, 0) == v ? 0 : (vertex(t, 1) == v ? 1 : 2);
      ring.push_back(vertex(t, k + 1));
      t = neighbor_[t][(k + 1) % 3]; // across the edge from v to the next ring vertex
      if(t < 0 || ring.size() > 64)
        return false;
    }
    while(t != first);
    return ring.size() >= 3;
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
  }

  void relink(int w, int from, int to)
  {
    if(w < 0)
      return;
    for(int i = 0; i < 3; ++i)
      if(neighbor_[w][i] == from)
        neighbor_[w][i] = to;
  }

  std::vector<Point>& points_;
  std::vector<std::array<int, 3> >& triangles_;
  const double cos_bound_;
  std::vector<std::array<int, 3> > neighbor_;
  std::vector<int> incident_, valence_, target_;
  std::vector<char> boundary_, fixed_;
};

/// Optimizes the planar triangle mesh `(points, triangles)` (counterclockwise triangles of a
/// manifold domain) in `rounds` rounds of valence-driven edge flips and shape passes, then one
/// skewness pass (see `Planar_optimization_parameters`). Vertices on the boundary and the first
/// `number_of_fixed_points` points never move and boundary edges are never flipped, so the
/// domain and its boundary samples are kept; every triangle stays positively oriented (exact
/// predicates); no operation creates an angle below the smaller of the bound and the smallest
/// angle it replaces, so the smallest angle of the mesh never drops below `min(its initial value,
/// bound)`. Each pass is linear in the size of the mesh. `surface_angle`: see
/// `Planar_triangulation_optimizer::initialize()`; it may be empty.
inline Planar_optimization_report optimize_planar_triangulation(
  std::vector<Epick::Point_2>& points, std::vector<std::array<int, 3> >& triangles, std::size_t number_of_fixed_points,
  int rounds, const std::vector<double>& surface_angle = std::vector<double>(),
  const Planar_optimization_parameters& parameters = Planar_optimization_parameters())
{
  Planar_optimization_report report;
  if(rounds <= 0 || triangles.empty())
    return report;
  Planar_triangulation_optimizer optimizer(points, triangles, parameters.angle_bound_degrees);
  if(!optimizer.initialize(number_of_fixed_points, surface_angle))
    return report;
  report.optimized = true;
  for(int round = 0; round < rounds; ++round)
  {
    report.flips += optimizer.flip_pass();
    for(int pass = 0; pass < parameters.shape_passes; ++pass)
      report.moves += optimizer.shape_pass();
  }
  if(parameters.skewness_threshold <= 1.)
    report.moves += optimizer.skewness_pass(parameters.skewness_threshold);
  return report;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_OPTIMIZATION_H
