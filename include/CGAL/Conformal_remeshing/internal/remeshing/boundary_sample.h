// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A sample of a patch boundary loop: what the boundary sampling (boundary_curves.h) hands to the
// planar mesher (planar_mesher.h).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_BOUNDARY_SAMPLE_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_BOUNDARY_SAMPLE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// A boundary sample: its planar position and the surface point it stands for.
struct Boundary_sample
{
  Epick::Point_2 uv;
  Epick::Point_3 point;
  /// the surface sample this is an image of: the two sides of a slit have two images of one
  /// sample, which no vertex may join both (see `mesh_planar_domain()`); `none`: its own point
  std::size_t id = none;
  static constexpr std::size_t none = std::size_t(-1);
};

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_BOUNDARY_SAMPLE_H
