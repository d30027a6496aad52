// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every named parameter of the package, in one place.
//
// CGAL 5.5's list of named parameters is closed, so the package defines its own tags in
// `CGAL::Conformal_remeshing::internal_np` and their builders in
// `CGAL::Conformal_remeshing::parameters`. Where CGAL has a parameter of the same meaning, the
// package reads CGAL's tag, and a package builder of the same name makes CGAL's tag, so that
// `CGAL::parameters::maximum_running_time(10)` and
// `CGAL::Conformal_remeshing::parameters::maximum_running_time(10)` are one parameter. CGAL's
// parameters the package reads: `vertex_point_map`, `face_index_map`, `geom_traits`,
// `edge_is_constrained_map`, `face_patch_map`, `number_of_iterations`, `callback`,
// `random_seed`, `number_of_points_on_faces`, `sparse_linear_solver` and
// `maximum_running_time`.
//
// Every builder takes an optional second argument, the parameters to chain it with, CGAL's or
// the package's:
//   CGAL::Conformal_remeshing::parameters::target_edge_length(0.5, CGAL::parameters::maximum_running_time(60))

#ifndef CGAL_CONFORMAL_REMESHING_PARAMETERS_H
#define CGAL_CONFORMAL_REMESHING_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

/// Declares the builder `CGAL::Conformal_remeshing::parameters::NAME(value[, chained
/// parameters])` of the tag `TAG_TYPE`.
#define CGAL_CONFORMAL_REMESHING_PARAMETER_BUILDER(NAME, TAG_TYPE)                                            \
  namespace CGAL {                                                                                            \
  namespace Conformal_remeshing {                                                                             \
  namespace parameters {                                                                                      \
  template <typename T>                                                                                       \
  Named_function_parameters<T, TAG_TYPE> NAME(const T& value)                                                 \
  {                                                                                                           \
    return Named_function_parameters<T, TAG_TYPE>(value);                                                     \
  }                                                                                                           \
  template <typename T, typename T2, typename Tag, typename Base>                                             \
  Named_function_parameters<T, TAG_TYPE, Named_function_parameters<T2, Tag, Base> >                           \
  NAME(const T& value, const Named_function_parameters<T2, Tag, Base>& np)                                    \
  {                                                                                                           \
    return Named_function_parameters<T, TAG_TYPE, Named_function_parameters<T2, Tag, Base> >(value, np);      \
  }                                                                                                           \
  }                                                                                                           \
  }                                                                                                           \
  }

/// Declares the package's tag `CGAL::Conformal_remeshing::internal_np::NAME` and its builder.
/// Use it at global scope.
#define CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(NAME)                                                        \
  namespace CGAL {                                                                                            \
  namespace Conformal_remeshing {                                                                             \
  namespace internal_np {                                                                                     \
  enum NAME##_t { NAME };                                                                                     \
  }                                                                                                           \
  }                                                                                                           \
  }                                                                                                           \
  CGAL_CONFORMAL_REMESHING_PARAMETER_BUILDER(NAME, CGAL::Conformal_remeshing::internal_np::NAME##_t)

// --- CGAL's own parameters, also offered under the package's namespace ----------------------------
// `maximum_running_time(seconds)`: a limit on the wall-clock time of a call (`double`; default:
// none). Read by every function that runs long; see `internal/time_limit.h`.
CGAL_CONFORMAL_REMESHING_PARAMETER_BUILDER(maximum_running_time, CGAL::internal_np::maximum_running_time_t)

// --- every function that reads `maximum_running_time` --------------------------------------------
// `stop_requested(f)`: `f`, a callable `bool()`, is polled wherever `maximum_running_time` is
// checked; once it returns true the call stops as at its time limit. See `internal/time_limit.h`.
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(stop_requested)

// --- `remesh_conformal()` -----------------------------------------------------------------------
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(target_edge_length)          // double, input units
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(relative_target_edge_length) // double, of the diagonal
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(sizing_field)                // double(const Epick::Point_3&)
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(maximum_chord_error)         // double, input units
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(maximum_surface_distance)    // double, input units
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(minimum_angle)               // double, degrees
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(corner_angle)                // double, degrees
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(frontal_insertion)           // bool
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(smoothing_iterations)        // int
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(lloyd_iterations)            // int
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(optimization_rounds)         // int
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(features_fallback)           // bool
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(repair_input)                // bool
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(batch_faces)                 // std::size_t, faces of a batch of components
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(progress)                    // void(const std::string&)
// Output of `remesh_conformal()`, input of `verify_remesh()`: `std::vector<Surface_location>`,
// the place on the input surface of every output vertex (an output parameter takes
// `std::ref(vector)`).
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(vertex_locations)
// `patch_job_runner(f)`: `f`, an `internal::remeshing::Patch_job_runner`, runs the patch jobs of
// the meshing stage instead of this process's threads (the MPI tool remesh_conformal_mpi hands
// them to other processes); the output is the same wherever the jobs run.
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(patch_job_runner)
// `flattened_patch_visitor(f)`: `f`, a callable `void(const Extracted_patch&, const
// Conformal_flattening&)`, is shown every patch that the meshing stage meshes, with its
// flattening, once they are all flattened (what the tool's `--save-patches` writes); an empty
// `std::function` is no visitor.
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(flattened_patch_visitor)
// Output of `remesh_conformal()`: `Remeshing_statistics`, the timings and counters of its stages
// (`std::ref(statistics)`).
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(statistics)

// --- `segment_into_poly_annuli()` ---------------------------------------------------------------
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(features_angle) // double, degrees
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(crease_angle)   // double, degrees
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(cut_planes)     // std::vector<Epick::Plane_3>
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(snap_distance)  // double, input units

// --- `flatten_poly_annuli()` --------------------------------------------------------------------
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(maximum_scale_ratio) // double

// --- `conformal_flatten()` ----------------------------------------------------------------------
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(welded_boundary)      // halfedge_descriptor
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(annulus_inner_radius) // double
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(maximum_edge_length)  // double, input units

// --- `discrete_ricci_flow()` --------------------------------------------------------------------
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(curvature_tolerance)  // double
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(use_edge_flips)       // bool
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(edge_split_angle)     // double, radians
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(exact_conformal_path) // bool

// --- `verify_remesh()` --------------------------------------------------------------------------
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(distance_tolerance)          // double, input units
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(relative_distance_tolerance) // double, of the diagonal

#endif // CGAL_CONFORMAL_REMESHING_PARAMETERS_H
