// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One patch of the segmentation with its flattening: what the segmentation and flattening stage
// hands to the meshing of each patch, and which nothing after it changes.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FLATTENED_PATCH_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FLATTENED_PATCH_H

#include <CGAL/Conformal_remeshing/conformal_flatten.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/kept_input_vertices.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

// The surface point of every vertex of the flat triangulation. A patch vertex has its own point;
// a vertex that the refinement inserted is mapped once through the correspondence (mapping every
// triangle corner back through the flips instead costs millions of lifts on a CAD fan).
inline std::vector<Epick::Point_3> vertex_surface_points(const Conformal_flattening& flat)
{
  std::vector<Epick::Point_3> point(flat.layout.size());
  std::vector<char> known(flat.layout.size(), 0);
  for(std::size_t v = 0; v < (std::min)(flat.number_of_patch_points(), point.size()); ++v)
  {
    point[v] = flat.patch_point(v);
    known[v] = 1;
  }
  for(std::size_t t = 0; t < flat.triangles.size(); ++t)
    for(int c = 0; c < 3; ++c)
      if(!known[flat.triangles[t][c]])
      {
        std::array<double, 3> b{{0., 0., 0.}};
        b[c] = 1.;
        point[flat.triangles[t][c]] = flat.surface_point(t, b);
        known[flat.triangles[t][c]] = 1;
      }
  return point;
}

// The local scale of the map (planar length over surface length) at the vertices of the flat
// triangulation, averaged over their triangles: the factor that turns a target length on the surface into one in
// the plane.
inline std::vector<double> local_scale(const Conformal_flattening& flat)
{
  const std::vector<Epick::Point_3> point = vertex_surface_points(flat);
  std::vector<double> scale(flat.layout.size(), 0.), weight(flat.layout.size(), 0.);
  for(const std::array<int, 3>& triangle : flat.triangles)
  {
    double planar = 0., spatial = 0.;
    for(int c = 0; c < 3; ++c)
    {
      const int v = triangle[c], w = triangle[(c + 1) % 3];
      planar += std::sqrt(CGAL::squared_distance(flat.layout[v], flat.layout[w]));
      spatial += std::sqrt(CGAL::squared_distance(point[v], point[w]));
    }
    for(int v : triangle)
    {
      scale[v] += planar / spatial;
      weight[v] += 1.;
    }
  }
  for(std::size_t v = 0; v < scale.size(); ++v)
    if(weight[v] > 0.)
      scale[v] /= weight[v];
  return scale;
}

/// A patch, its flattening, the local scale of the flattening at the vertices of its flat
/// triangulation (see `local_scale()`), and the patch's vertices that the output would cut (see
/// `tip_candidates()`). What the meshing does not read is freed once the patch is flattened: the
/// patch's mesh (its maps to the segmentation stay), and all of the flattening's intrinsic
/// triangulation but its correspondence record
/// (`Intrinsic_triangulation::keep_only_correspondence()`).
struct Flattened_patch
{
  Extracted_patch patch;
  Conformal_flattening flattening;
  std::vector<double> scale;
  std::vector<Tip_candidate> tips;
  double tip_length = 0.; ///< the target edge length `tips` were found for
};

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FLATTENED_PATCH_H
