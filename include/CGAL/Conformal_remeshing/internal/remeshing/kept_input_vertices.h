// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input vertices that become output vertices: the tips of a coarse input. Output vertices lie on
// the input surface but anywhere on it, and where a coarse mesh comes to a point (a vertex that
// stands out from its ring) the output triangles around it cut the tip off, by up to about half
// a target length on a coarse scanned model.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_KEPT_INPUT_VERTICES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_KEPT_INPUT_VERTICES_H

#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// A vertex of a patch that the output would cut: its index in the patch's mesh, its point, and
/// how far the output would cut it.
struct Tip_candidate
{
  double cut;
  std::size_t vertex;
  Epick::Point_3 point;
};

/// The vertices of the patch mesh `m` off its border that are tips the output
/// would cut by more than `tolerance` times the target length `h`: vertices whose height over the
/// centroid of their ring, along the ring's normal, scaled to the distance at which the nearest
/// output vertices are expected (0.6 `h`, or the ring's mean radius if shorter), exceeds the
/// tolerance, and that are either
/// - sharp: their angle sum differs from a full turn by more than half a radian (cones or
///   saddles) and their ring's mean radius exceeds half the target length. A tip on a smaller
///   ring stays cut: the output cannot follow it anyway, and triangles fanning out from it to
///   points a target length away would stand off the surface around it;
/// - or coarse: their ring's mean radius exceeds 2.5 target lengths, whatever their angle sum
///   (the nearly flat vertices of a coarse spherical cap stand a few hundredths of `h` over the
///   output; keeping them brings its distance to the input below isotropic_remeshing's). The
///   radius bound keeps the vertices of finer parts' creases and ridges out: kept, they would
///   pin the optimization (more skewed triangles, a larger distance to the input).
/// Highest first (by `cut`, then by vertex index, both decreasing). The meshing takes some of them
/// (`kept_tips()`); they are found once per patch, when it is flattened, so that the patch's mesh
/// need not be kept for the meshing.
inline std::vector<Tip_candidate> tip_candidates(const Extracted_patch::Mesh& m, double h, double tolerance)
{
  typedef Extracted_patch::Mesh Mesh;
  std::vector<Tip_candidate> candidates;
  std::vector<Epick::Point_3> ring;
  for(Mesh::Vertex_index v : m.vertices())
  {
    if(m.is_border(v))
      continue;
    const Epick::Point_3& p = m.point(v);
    ring.clear();
    for(Mesh::Vertex_index w : CGAL::vertices_around_target(m.halfedge(v), m))
      ring.push_back(m.point(w));
    Epick::Vector_3 normal = CGAL::NULL_VECTOR, to_centroid = CGAL::NULL_VECTOR;
    double radius = 0.;
    for(std::size_t i = 0; i < ring.size(); ++i)
    {
      const Epick::Vector_3 u = ring[i] - p, w = ring[(i + 1) % ring.size()] - p;
      normal = normal + CGAL::cross_product(u, w);
      to_centroid = to_centroid + u;
      radius += std::sqrt(u.squared_length());
    }
    radius /= double(ring.size());
    const double area = std::sqrt(normal.squared_length());
    if(!(area > 0.))
      continue;
    const double height = std::abs(to_centroid * normal) / (double(ring.size()) * area);
    const double cut = height * (std::min)(radius, 0.6 * h) / radius;
    // The angle sum last: its arc tangents would be most of this search on a fine input, whose
    // vertices' tips are far lower than the tolerance.
    if(!(cut > tolerance * h))
      continue;
    if(!(radius > 2.5 * h))
    {
      double angle_sum = 0.;
      for(std::size_t i = 0; i < ring.size(); ++i)
      {
        const Epick::Vector_3 u = ring[i] - p, w = ring[(i + 1) % ring.size()] - p;
        angle_sum += std::atan2(std::sqrt(CGAL::cross_product(u, w).squared_length()), u * w);
      }
      const bool sharp = std::abs(2. * CGAL_PI - angle_sum) > 0.5 && radius > 0.5 * h;
      if(!sharp)
        continue;
    }
    candidates.push_back(Tip_candidate{cut, std::size_t(v), p});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Tip_candidate& a, const Tip_candidate& b) {
    return std::make_pair(a.cut, a.vertex) > std::make_pair(b.cut, b.vertex);
  });
  return candidates;
}

/// Of `candidates` (see `tip_candidates()`, for the same `h`), those taken greedily from the
/// highest, each at least `h` from the others and from every point of `avoid` (the patch's
/// boundary samples), so that the refinement meets no short distance it cannot grade.
inline std::vector<Tip_candidate> kept_tips(const std::vector<Tip_candidate>& candidates, double h,
                                            const std::vector<Epick::Point_3>& avoid)
{
  CGAL_precondition(h > 0.);
  // The points taken so far in a grid of cells of size h: a new one looks at 27 cells.
  std::map<std::array<long, 3>, std::vector<Epick::Point_3> > grid;
  auto cell = [&](const Epick::Point_3& p) {
    return std::array<long, 3>{{long(std::floor(p.x() / h)), long(std::floor(p.y() / h)), long(std::floor(p.z() / h))}};
  };
  auto is_near_a_taken_point = [&](const Epick::Point_3& p) {
    const std::array<long, 3> c = cell(p);
    for(long i = -1; i <= 1; ++i)
      for(long j = -1; j <= 1; ++j)
        for(long k = -1; k <= 1; ++k)
        {
          const auto found = grid.find({{c[0] + i, c[1] + j, c[2] + k}});
          if(found != grid.end()
             && std::any_of(found->second.begin(), found->second.end(),
                            [&](const Epick::Point_3& q) { return CGAL::squared_distance(p, q) < h * h; }))
            return true;
        }
    return false;
  };
  for(const Epick::Point_3& q : avoid)
    grid[cell(q)].push_back(q);
  std::vector<Tip_candidate> kept;
  for(const Tip_candidate& c : candidates)
  {
    if(is_near_a_taken_point(c.point))
      continue;
    kept.push_back(c);
    grid[cell(c.point)].push_back(c.point);
  }
  return kept;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_KEPT_INPUT_VERTICES_H
