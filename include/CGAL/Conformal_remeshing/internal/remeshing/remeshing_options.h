// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first stage of `remesh_conformal()`: its named parameters read once, with their defaults,
// and checked. The later stages take these values, not the named parameters.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_REMESHING_OPTIONS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_REMESHING_OPTIONS_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/parameters.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/frontal_insertion.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_mesher.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/sizing.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

struct Remeshing_options
{
  double target_edge_length = 0.;
  double minimum_angle = 28.; // degrees
  double corner_angle = 30.;  // degrees
  double maximum_scale_ratio = 1000.;
  double maximum_chord_error = 0.; // 0: none
  double maximum_surface_distance = 0.; // 0: none; by default `default_surface_distance` times the target
  Sizing::Field sizing_field;      // empty: uniform
  int optimization_rounds = 5;
  bool features_fallback = true;
  /// an input of more faces and several components is remeshed in batches of whole components
  /// of at most this many faces (component_batches.h); 0: in one piece
  std::size_t batch_faces = 2000000;
  /// the planar meshing's point placement and smoothing: by frontal insertion when it is on...
  Frontal_insertion frontal;
  Planar_smoothing smoothing;
  /// ...and the smoothing of the fallback by Delaunay refinement alone
  Planar_smoothing refinement_smoothing;
  /// where the patch jobs run: empty, in this process's threads
  Patch_job_runner patch_job_runner;
};

/// The options of `remesh_conformal(input, output, np)`.
/// \throws Error with `Error_code::INVALID_INPUT` when a parameter is out of range.
template <typename TriangleMesh, typename NamedParameters>
Remeshing_options remeshing_options(const TriangleMesh& input, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Remeshing_options o;
  const CGAL::Bbox_3 box = Polygon_mesh_processing::bbox(input, np);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                    + CGAL::square(box.zmax() - box.zmin()));
  const double relative = choose_parameter(get_parameter(np, internal_np::relative_target_edge_length), 0.01);
  o.target_edge_length = choose_parameter(get_parameter(np, internal_np::target_edge_length), relative * diagonal);
  o.minimum_angle = choose_parameter(get_parameter(np, internal_np::minimum_angle), o.minimum_angle);
  o.corner_angle = choose_parameter(get_parameter(np, internal_np::corner_angle), o.corner_angle);
  o.maximum_scale_ratio = choose_parameter(get_parameter(np, internal_np::maximum_scale_ratio), o.maximum_scale_ratio);
  o.maximum_chord_error = choose_parameter(get_parameter(np, internal_np::maximum_chord_error), o.maximum_chord_error);
  o.sizing_field = choose_parameter(get_parameter(np, internal_np::sizing_field), Sizing::Field());
  o.optimization_rounds = choose_parameter(get_parameter(np, internal_np::optimization_rounds), o.optimization_rounds);
  o.features_fallback = choose_parameter(get_parameter(np, internal_np::features_fallback), o.features_fallback);
  o.batch_faces = choose_parameter(get_parameter(np, internal_np::batch_faces), o.batch_faces);
  o.patch_job_runner = choose_parameter(get_parameter(np, internal_np::patch_job_runner), Patch_job_runner());
  const bool frontal_on = choose_parameter(get_parameter(np, internal_np::frontal_insertion), true);
  const int lloyd_iterations = choose_parameter(get_parameter(np, internal_np::lloyd_iterations), 0);
  // Frontal insertion's rows need no Laplacian pass; the refinement alone gets one.
  o.refinement_smoothing = Planar_smoothing(choose_parameter(get_parameter(np, internal_np::smoothing_iterations), 1), lloyd_iterations);
  o.smoothing = Planar_smoothing(frontal_on ? choose_parameter(get_parameter(np, internal_np::smoothing_iterations), 0)
                                            : o.refinement_smoothing.laplacian_iterations,
                                 lloyd_iterations);
  if(frontal_on)
    o.frontal.target_ratio = frontal_target_ratio;

  const double h = o.target_edge_length;
  if(!(h > 0.) || !std::isfinite(h))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the target edge length must be positive");
  o.maximum_surface_distance = choose_parameter(get_parameter(np, internal_np::maximum_surface_distance), default_surface_distance * h);
  if(!(o.minimum_angle > 0. && o.minimum_angle <= 34.))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the minimum angle must be in (0, 34] degrees "
                                           "(no triangulation of a general domain keeps all its angles far above 30)");
  if(!(o.maximum_scale_ratio > 1.))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the maximum scale ratio must be above 1");
  if(o.smoothing.laplacian_iterations < 0 || o.refinement_smoothing.laplacian_iterations < 0 || o.smoothing.lloyd_iterations < 0)
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the numbers of smoothing and Lloyd iterations must not be negative");
  if(o.optimization_rounds < 0)
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the number of optimization rounds must not be negative");
  if(!(o.maximum_chord_error >= 0.) || !std::isfinite(o.maximum_chord_error))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the maximum chord error must be positive (or 0: none)");
  if(!(o.maximum_surface_distance >= 0.) || !std::isfinite(o.maximum_surface_distance))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the maximum surface distance must be positive (or 0: none)");
  return o;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_REMESHING_OPTIONS_H
