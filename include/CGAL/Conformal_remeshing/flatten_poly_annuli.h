// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every patch of a segmentation flattened, with bisection of the patches whose flattening fails
// or stretches too much: the stage of `remesh_conformal()` between the segmentation and the
// planar meshing, also on its own for pictures of the patches and their flattenings.

#ifndef CGAL_CONFORMAL_REMESHING_FLATTEN_POLY_ANNULI_H
#define CGAL_CONFORMAL_REMESHING_FLATTEN_POLY_ANNULI_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>
#include <CGAL/Conformal_remeshing/parameters.h>
#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <functional>
#include <iterator>
#include <string>
#include <vector>


namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// The patches of a segmentation, each extracted and flattened (see `flatten_poly_annuli()`).
struct Flattened_poly_annuli
{
  std::vector<std::vector<Poly_annulus_segmentation::Face> > faces; ///< the faces of each patch in the segmented mesh
  std::vector<Extracted_patch> patches;
  std::vector<Conformal_flattening> flattenings;
  std::size_t bisections = 0; ///< patches bisected because their flattening failed or stretched too much
};

namespace internal {

/// The largest edge length the flow may keep on `patch` (see `conformal_flatten()`'s
/// `maximum_edge_length`): `longest`, or on a tube a tenth of its shorter loop when that is
/// less, but not below a quarter of `longest` (at most 16 times the vertices). A tube, an
/// annulus whose loops are within a factor of 4 in length, has a map whose scale grows like
/// exp(2 pi d / C) along it, for a circumference C, and the map is affine on each flat triangle,
/// so a triangle must not span much of that growth (on the wall of a small hole of a brake disc,
/// a few target lengths around, a triangle of twice the target length spans a scale factor of
/// about 7, and the remeshed wall is visibly more skewed). (An annulus with a small hole in a
/// large sheet is no tube: its scale changes near the hole only, and a tenth of the hole over
/// the sheet would be costly.)
constexpr double tube_resolution = 1. / 10.;
inline double flow_edge_length(const Extracted_patch& patch, double longest)
{
  if(!(longest > 0.) || patch.boundary_loops != 2)
    return longest;
  std::vector<Extracted_patch::Mesh::Halfedge_index> loops;
  Polygon_mesh_processing::extract_boundary_cycles(patch.mesh, std::back_inserter(loops));
  const double a = Polygon_mesh_processing::face_border_length(loops.at(0), patch.mesh),
               b = Polygon_mesh_processing::face_border_length(loops.at(1), patch.mesh);
  const double shorter = (std::min)(a, b), longer = (std::max)(a, b);
  if(!(longer <= 4. * shorter))
    return longest;
  return (std::min)(longest, (std::max)(0.25 * longest, tube_resolution * shorter));
}

/// What `flatten_poly_annuli()` tells its caller as it goes, so that a caller keeping only part of
/// each patch and flattening can drop the rest as soon as the patch is flattened, not once all
/// of them are: a round of bisections flattens every patch anew, so what the caller kept of a
/// round is void when the next one starts.
struct Flattening_observer
{
  /// before a round flattens the patches, with their number
  std::function<void(std::size_t number_of_patches)> round_started;
  /// patch `p` of the round flattened within the limits, from the thread that flattened it; the
  /// patch and its flattening may be moved from (the result then holds what is left of them)
  std::function<void(std::size_t p, Extracted_patch& patch, Conformal_flattening& flattening)> patch_flattened;
};

// `flatten_poly_annuli()` with the time limit and the name (for messages) of its caller, which
// `observer` follows.
template <typename ConcurrencyTag, typename NamedParameters>
void flatten_poly_annuli(Poly_annulus_segmentation& segmentation, Flattened_poly_annuli& result, const NamedParameters& np,
                         const Time_limit& time_limit, const std::string& caller,
                         const Flattening_observer& observer = Flattening_observer())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Poly_annulus_segmentation::Face Face;
  const std::function<void(const std::string&)> progress =
    choose_parameter(get_parameter(np, internal_np::progress), [](const std::string&) {});
  const double maximum_scale_ratio = choose_parameter(get_parameter(np, internal_np::maximum_scale_ratio), 1000.);
  if(!(maximum_scale_ratio > 1.))
    throw Error(Error_code::INVALID_INPUT, caller + ": the maximum scale ratio must be above 1");
  const double snap = choose_parameter(get_parameter(np, internal_np::snap_distance), 0.);
  // Only the flattening's own parameters go on to it: the others name the input's maps.
  const double longest_edge = choose_parameter(get_parameter(np, internal_np::maximum_edge_length), 0.);
  const auto flattening_parameters = parameters::annulus_inner_radius(
    choose_parameter(get_parameter(np, internal_np::annulus_inner_radius), 0.3),
    parameters::curvature_tolerance(choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-10),
                                    CGAL::parameters::number_of_iterations(
                                      choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 50))));

  result = Flattened_poly_annuli();
  std::vector<std::string> failures;
  for(int round = 0;; ++round)
  {
    result.faces = segmentation.faces_of_patches();
    const std::size_t n = result.faces.size();
    progress("flattening " + std::to_string(n) + " patches");
    result.patches.assign(n, Extracted_patch());
    result.flattenings.assign(n, Conformal_flattening());
    failures.assign(n, std::string());
    if(observer.round_started)
      observer.round_started(n);
    for_each_index<ConcurrencyTag>(n, [&](std::size_t p) {
      try
      {
        result.patches[p] = extract_patch(segmentation, result.faces[p]);
        result.flattenings[p] = conformal_flatten(
          result.patches[p].mesh,
          parameters::maximum_running_time(time_limit.remaining(),
                                           parameters::stop_requested(time_limit.stop_request(),
                                                                      parameters::maximum_edge_length(flow_edge_length(result.patches[p], longest_edge),
                                                                                                      flattening_parameters))));
        const Flattening_report& r = result.flattenings[p].report;
        if(r.status == Error_code::NOT_CONVERGED)
          failures[p] = std::string(error_message(r.status)) + " (" + r.flow_message + ")";
        else if(r.status != Error_code::SUCCESS)
          failures[p] = std::string(error_message(r.status)) + " (" + r.embedding.summary() + ")";
        else if(r.max_scale > maximum_scale_ratio * r.min_scale)
          failures[p] = "scale ratio " + std::to_string(r.max_scale / r.min_scale);
        else if(observer.patch_flattened)
          observer.patch_flattened(p, result.patches[p], result.flattenings[p]);
      }
      catch(const Error& e)
      {
        failures[p] = e.what();
      }
    });
    time_limit.check("while flattening the patches"); // before a patch that ran out of time is bisected
    std::vector<std::size_t> to_bisect;
    for(std::size_t p = 0; p < n; ++p)
      if(!failures[p].empty())
        to_bisect.push_back(p);
    if(to_bisect.empty())
      return;
    const std::size_t first = to_bisect.front();
    if(round == 8)
      throw Error(result.flattenings[first].report.status == Error_code::SUCCESS ? Error_code::NOT_CONVERGED
                                                                                 : result.flattenings[first].report.status,
                  caller + ": a patch of " + std::to_string(result.faces[first].size())
                    + " faces cannot be flattened after 8 bisections: " + failures[first]);
    for(std::size_t p : to_bisect)
    {
      // Said, because the failed attempt can take most of the time on a large part.
      progress("bisecting a patch of " + std::to_string(result.faces[p].size()) + " faces: " + failures[p]);
      ++result.bisections;
      if(!bisect_patch(segmentation, segmentation.faces_of_patch(p), 2, snap))
        throw Error(Error_code::NOT_CONVERGED, caller + ": a patch cannot be flattened (" + failures[p] + ") and no plane bisects it");
    }
    segmentation.renumber_patches();
  }
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Flattens every patch of `segmentation` (made by `segment_into_poly_annuli()`) with
/// `conformal_flatten()`, as `remesh_conformal()` does: a patch whose flattening fails, or whose
/// local scale varies by more than `maximum_scale_ratio`, is bisected by a plane
/// (`bisect_patch()`) and the patches are flattened again, up to 8 rounds. `segmentation` then
/// has the patches of `result`.
///
/// \tparam ConcurrencyTag `CGAL::Parallel_if_available_tag` (the default: patches are flattened
///         in parallel when CGAL is linked with TBB), `CGAL::Parallel_tag` or `CGAL::Sequential_tag`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{maximum_scale_ratio}
///     \cgalParamDescription{a patch whose largest local scale exceeds its smallest by more than this is bisected (`Conformal_remeshing::parameters::maximum_scale_ratio()`)}
///     \cgalParamType{`double`, above 1}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{snap_distance}
///     \cgalParamDescription{vertices closer than this to a bisecting plane are taken as on it (`Conformal_remeshing::parameters::snap_distance()`; `remesh_conformal()` passes a tenth of the target edge length)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{a callable `void(const std::string& stage)` told when each round starts and why a patch is bisected (`Conformal_remeshing::parameters::progress()`)}
///     \cgalParamType{a callable convertible to `std::function<void(const std::string&)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{a limit in seconds on the wall-clock time of the call (`Conformal_remeshing::parameters::maximum_running_time()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// `maximum_edge_length`, `annulus_inner_radius`, `curvature_tolerance` and
/// `number_of_iterations` are passed on to `conformal_flatten()`; on a tube (an annulus whose
/// loops are within a factor of 4 in length) the maximum edge length is at most a tenth of its
/// shorter loop, but not below a quarter of the given one: the map's scale grows exponentially
/// along a tube, and the map is affine on each flat triangle.
///
/// \throws Error with the flattening's code when a patch cannot be flattened even after 8
///         bisections or no plane bisects it, with `Error_code::TIME_LIMIT_EXCEEDED` past the
///         `maximum_running_time`, with `Error_code::INVALID_INPUT` for a scale ratio not above 1
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void flatten_poly_annuli(Poly_annulus_segmentation& segmentation, Flattened_poly_annuli& result,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::flatten_poly_annuli<ConcurrencyTag>(segmentation, result, np, internal::Time_limit::from(np, "flatten_poly_annuli"),
                                                "flatten_poly_annuli");
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_FLATTEN_POLY_ANNULI_H
