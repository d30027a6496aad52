// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The segmentation and flattening stage of `remesh_conformal()`: the input cut into poly-annuli,
// every patch flattened (bisected where it fails or stretches too much), and the local scale of
// every flattening. What it returns, the later stages read and never change.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SEGMENT_AND_FLATTEN_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SEGMENT_AND_FLATTEN_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/flatten_poly_annuli.h>
#include <CGAL/Conformal_remeshing/parameters.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>
#include <CGAL/Conformal_remeshing/internal/process_memory.h>
#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/flattened_patch.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/remeshing_options.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The input cut into flattened patches. The patches are shared, never changed: each patch job
/// (patch_job.h) holds its own and can outlive the surface.
struct Flattened_surface
{
  Poly_annulus_segmentation segmentation; ///< with the bisections of the patches that failed
  std::vector<std::shared_ptr<const Flattened_patch> > patches; ///< by patch index of `segmentation`
};

inline std::string without_caller(const std::string& message)
{
  const std::string caller = "remesh_conformal: "; // the start of the flattening's messages
  return message.compare(0, caller.size(), caller) == 0 ? message.substr(caller.size()) : message;
}

inline void add_flattening_statistics(const Poly_annulus_segmentation& segmentation, std::size_t bisections,
                                      const std::vector<Flattened_patch>& patches, Remeshing_report& report,
                                      Remeshing_statistics& statistics)
{
  report.patch_bisections = bisections;
  report.number_of_patches = patches.size();
  report.plane_cuts = segmentation.plane_cuts;
  report.feature_edges = segmentation.feature_edges;
  report.dangling_feature_edges = segmentation.dangling_feature_edges;
  report.narrow_strip_feature_edges = segmentation.narrow_strip_feature_edges;
  for(const Flattened_patch& patch : patches)
  {
    const Flattening_report& r = patch.flattening.report;
    statistics.max_newton_iterations = (std::max)(statistics.max_newton_iterations, r.iterations);
    statistics.max_curvature_error = (std::max)(statistics.max_curvature_error, r.curvature_error);
    statistics.flips += r.flips;
    statistics.retriangulated_faces += r.retriangulated_faces;
    statistics.max_scale_ratio = (std::max)(statistics.max_scale_ratio, r.max_scale / r.min_scale);
    statistics.seconds_ricci_flow += r.seconds_flow;
    statistics.patches.push_back(r);
  }
}

// Whether a callable was given: an empty `std::function` is none.
template <typename Callable>
bool is_given(const Callable&)
{
  return true;
}
template <typename Signature>
bool is_given(const std::function<Signature>& f)
{
  return bool(f);
}

/// `patch` and its `flattening` (moved from) reduced to what the meshing reads, for the target
/// edge length `h`: the meshing reads the tips, not the patch's mesh, and walks the flattening's
/// triangles back to the patch without the final triangulation's connectivity or lengths.
inline Flattened_patch compacted(Extracted_patch& patch, Conformal_flattening& flattening, double h)
{
  Flattened_patch result;
  result.scale = local_scale(flattening);
  result.tips = tip_candidates(patch.mesh, h, kept_tip_tolerance);
  result.tip_length = h;
  result.patch = std::move(patch);
  result.patch.mesh = Extracted_patch::Mesh();
  result.flattening = std::move(flattening);
  result.flattening.triangulation.keep_only_correspondence();
  return result;
}

/// Segments `input` and flattens its patches into `result` (an output parameter: a segmentation
/// is not copied). The segmentation takes its parameters from `np`;
/// the flow resolves the map at twice the target edge length unless `np` says otherwise (finer on
/// tubes: see `flow_edge_length()`), and snaps to cutting planes within a tenth of it.
///
/// The `flattened_patch_visitor` of `np`, if any, is shown each final patch and its flattening,
/// in patch order; then the patches are held whole until all are flattened. Without a visitor,
/// each patch is compacted (see `Flattened_patch`) as soon as it is flattened.
///
/// When a patch cannot be flattened even after bisection and the segmentation has sharp features,
/// the surface is segmented again without them if `options.features_fallback` is on: features
/// taken from noise bound patches that the bisections cannot flatten with a bounded scale, while
/// without them the patches are the surface's own. The report says so.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters, typename Progress>
void segment_and_flatten(const TriangleMesh& input, const Remeshing_options& options, const NamedParameters& np,
                         const Time_limit& time_limit, const Progress& progress, Remeshing_report& report,
                         Remeshing_statistics& statistics, Flattened_surface& result)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::chrono::steady_clock Clock;
  const double h = options.target_edge_length;
  const double snap = choose_parameter(get_parameter(np, internal_np::snap_distance), 0.1 * h);
  const double flow_length = choose_parameter(get_parameter(np, internal_np::maximum_edge_length), 2. * h);
  Clock::time_point start;
  Flattened_poly_annuli flattened;
  // Each patch compacted as soon as it is flattened, so that the flattening stage holds the full
  // patches and flows of the patches in flight only; unless a visitor is to see them whole.
  typedef std::function<void(const Extracted_patch&, const Conformal_flattening&)> Visitor;
  const auto visit = choose_parameter(get_parameter(np, internal_np::flattened_patch_visitor), Visitor());
  std::vector<Flattened_patch> patches;
  Flattening_observer compact_as_flattened;
  const bool visited = is_given(visit);
  if(!visited)
  {
    compact_as_flattened.round_started = [&](std::size_t n) { patches.assign(n, Flattened_patch()); };
    compact_as_flattened.patch_flattened = [&](std::size_t p, Extracted_patch& patch, Conformal_flattening& flattening) {
      patches[p] = compacted(patch, flattening, h);
    };
  }
  const auto run = [&](const auto& segmentation_parameters) {
    start = Clock::now();
    progress("segmenting into poly-annuli");
    segment_into_poly_annuli(input, result.segmentation, segmentation_parameters);
    statistics.seconds_segmentation += std::chrono::duration<double>(Clock::now() - start).count();
    statistics.peak_resident_mb_segmentation = peak_resident_megabytes();
    time_limit.check("after the segmentation");
    start = Clock::now();
    flatten_poly_annuli<ConcurrencyTag>(result.segmentation, flattened,
                                        parameters::maximum_edge_length(flow_length, parameters::snap_distance(snap, np)),
                                        time_limit, "remesh_conformal", compact_as_flattened);
    statistics.seconds_flattening += std::chrono::duration<double>(Clock::now() - start).count();
    statistics.peak_resident_mb_flattening = peak_resident_megabytes();
  };
  try
  {
    run(parameters::snap_distance(snap, np));
  }
  catch(const Error& e)
  {
    if(e.code() == Error_code::TIME_LIMIT_EXCEEDED || result.segmentation.feature_edges == 0 || !options.features_fallback)
      throw;
    statistics.seconds_flattening += std::chrono::duration<double>(Clock::now() - start).count();
    report.features_dropped = true;
    report.features_fallback_reason = without_caller(e.what());
    progress("no flattening with the " + std::to_string(result.segmentation.feature_edges) + " sharp feature edges ("
             + report.features_fallback_reason + "): segmenting again without them");
    run(parameters::features_angle(0., parameters::snap_distance(snap, np)));
  }
  if(visited)
  {
    patches.assign(flattened.patches.size(), Flattened_patch());
    for(std::size_t p = 0; p < patches.size(); ++p)
    {
      visit(flattened.patches[p], flattened.flattenings[p]);
      patches[p] = compacted(flattened.patches[p], flattened.flattenings[p], h);
    }
  }
  add_flattening_statistics(result.segmentation, flattened.bisections, patches, report, statistics);
  result.patches.clear();
  for(Flattened_patch& patch : patches)
    result.patches.push_back(std::make_shared<const Flattened_patch>(std::move(patch)));
  release_free_memory(); // the patches' meshes and the flows' triangulations
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SEGMENT_AND_FLATTEN_H
