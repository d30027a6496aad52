// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The meshing and gluing stages of `remesh_conformal()` and their escalation policy, in one place.
// With a chord error bound, the gaps between sheets (proximity.h) bound the size field before
// anything is meshed, so that the chords of one sheet do not reach another. Defects that show
// only once the patches are glued are mended here, in this order:
//  1. the output intersects itself where the input does not (two parts of the surface closer
//     than the output's chords deviate from it): those places are meshed again with edges of half
//     the target there, graded to the target by half the distance, then a quarter, up to
//     `max_self_intersection_refinements` rounds; the flattenings are kept, and so are the meshes
//     of the patches that have no intersecting triangle and whose boundary samples stay the same;
//  2. with a surface-distance bound, the places where the output stands farther from the input
//     than it, either way (surface_distance.h), are meshed again with edges of half the target
//     there, halved again where it still does (`max_surface_distance_refinements` rounds); what
//     is still farther is reported, not refused, and should a round give an output that policy 1
//     cannot mend (or patches that do not glue), or one no closer to the input than the output
//     before it, that output before it is kept;
//  3. with frontal insertion, should the frontally placed points still not mesh the surface (patches
//     that do not glue, an output that intersects itself), the surface is meshed again by Delaunay
//     refinement alone, with the same rounds.
// The patch-local mending (denser boundary curves, split diagonals) is the meshing stage's own
// (mesh_patches.h); improvements after gluing that make the output intersect itself are given up
// by the gluing stage (glue_patches.h).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_AND_GLUE_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_AND_GLUE_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/internal/process_memory.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/glue_patches.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/mesh_patches.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/proximity.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/remeshing_options.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/segment_and_flatten.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/sizing.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/surface_distance.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <chrono>
#include <functional>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

inline void add_meshing_statistics(const Meshed_patches& meshed, Remeshing_statistics& statistics)
{
  statistics.boundary_samples = meshed.samples.points.size();
  statistics.boundary_curves = meshed.samples.number_of_curves;
  statistics.patch_jobs_run += meshed.jobs_run;
  statistics.patch_jobs_kept += meshed.jobs_kept;
  for(const Remeshed_patch& r : meshed.remeshed)
  {
    if(r.kept_from_earlier_sizes)
      continue;
    statistics.seconds_planar_meshing += r.seconds_planar_meshing;
    statistics.seconds_optimization += r.seconds_optimization;
    statistics.seconds_pull_back += r.seconds_pull_back;
    statistics.patch_job_seconds.push_back(r.seconds_planar_meshing + r.seconds_optimization + r.seconds_pull_back);
    statistics.meshing_phases += r.phases;
    statistics.optimization_flips += r.optimization.flips;
    statistics.optimization_splits += r.optimization.splits;
    statistics.optimization_chord_splits += r.optimization.chord_splits;
    statistics.optimization_collapses += r.optimization.collapses;
    statistics.clamped_vertices += r.clamped_vertices;
  }
}

inline Error self_intersection_error(const std::vector<Epick::Point_3>& crossings, std::size_t coincident_vertices)
{
  const std::string touching =
    coincident_vertices == 0
      ? std::string()
      : "; the input's sheets touch at " + std::to_string(coincident_vertices)
          + " coincident vertices (or along cut non-manifold edges), and sheets remeshed apart that touch along a line or "
            "in a plane can cross there";
  std::ostringstream where;
  if(!crossings.empty())
    where << " near (" << crossings.front().x() << ", " << crossings.front().y() << ", " << crossings.front().z() << ")";
  return Error(Error_code::NOT_AN_EMBEDDING,
               "remesh_conformal: the remeshed patches intersect each other" + where.str()
                 + ", where the input does not intersect itself, even with edges of 1/"
                 + std::to_string(1 << max_self_intersection_refinements)
                 + " of the target there: two parts of the surface come closer there than the output's chords deviate from it "
                   "(nearly touching sheets; a smaller target edge length may help), or false sharp features cut a bent surface "
                   "into many patches (features_angle(0) may help)"
                 + touching);
}

/// The places of `glued` beyond the surface-distance bound, the bound's figures of the output
/// in `report`. `to_input` is built by the first call (once the input's samples are measured
/// and freed), for the next ones.
template <typename ConcurrencyTag, typename TriangleMesh>
Places_beyond_distance check_surface_distance(const Flattened_surface& surface, std::unique_ptr<Distance_to_surface>& to_input,
                                              const Glued_output<TriangleMesh>& glued, const Remeshing_options& options,
                                              Remeshing_report& report, Remeshing_statistics& statistics)
{
  const auto start = std::chrono::steady_clock::now();
  const auto input_surface = [&]() -> const Distance_to_surface& {
    if(!to_input)
      to_input = std::make_unique<Distance_to_surface>(surface.segmentation.mesh, ConcurrencyTag());
    return *to_input;
  };
  Places_beyond_distance far = places_beyond_distance<ConcurrencyTag>(
    surface.segmentation.mesh, input_surface, glued.mesh, options.maximum_surface_distance, 0.25 * options.target_edge_length);
  report.largest_surface_distance = far.largest;
  report.largest_surface_distance_point = {{far.farthest.x(), far.farthest.y(), far.farthest.z()}};
  report.places_still_beyond_surface_distance.clear();
  for(std::size_t i = 0; i < (std::min)(far.places.size(), Remeshing_report::max_reported_places); ++i)
    report.places_still_beyond_surface_distance.push_back({{far.places[i].x(), far.places[i].y(), far.places[i].z()}});
  report.output_faces_beyond_surface_distance = far.output_faces;
  report.input_vertices_beyond_surface_distance = far.input_vertices;
  report.input_edges_beyond_surface_distance = far.input_edges;
  report.input_faces_beyond_surface_distance = far.input_faces;
  statistics.seconds_surface_distance += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return far;
}

/// Whether meshing again for the distance bound brought the output closer to the input than the
/// output of `before`: its largest distance found is smaller, or fewer of its elements (and the
/// input's) stand beyond the bound. Not the largest alone: meshing a patch again moves all its
/// vertices, and one new far place elsewhere can outweigh many mended ones.
inline bool brought_closer(const Places_beyond_distance& far, const Remeshing_report& before)
{
  const std::size_t beyond = far.output_faces + far.input_vertices + far.input_edges + far.input_faces;
  const std::size_t beyond_before = before.output_faces_beyond_surface_distance + before.input_vertices_beyond_surface_distance
                                    + before.input_edges_beyond_surface_distance + before.input_faces_beyond_surface_distance;
  return far.largest < before.largest_surface_distance || beyond < beyond_before;
}

/// The patches of `surface` meshed and glued with `meshing`, meshed again finer where the output
/// intersects itself (policy 1 above) or, with a surface-distance bound, strays farther from the
/// input than it (policy 2).
/// \throws Error with `Error_code::NOT_AN_EMBEDDING` when it still intersects itself after the last round.
template <typename ConcurrencyTag, typename TriangleMesh, typename Progress>
Glued_output<TriangleMesh> mesh_and_glue(const Flattened_surface& surface, const Remeshing_options& options,
                                         const Patch_meshing& meshing, const Surface_proximity& proximity,
                                         const std::function<bool()>& input_self_intersects,
                                         const Time_limit& time_limit, const Progress& progress, Remeshing_report& report,
                                         Remeshing_statistics& statistics)
{
  typedef std::chrono::steady_clock Clock;
  const auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const double h = options.target_edge_length;
  std::vector<Epick::Point_3> crossings; // centroids of intersecting triangles, a quarter target apart
  Distance_refinement far_places(h, 0.5 * h); // places beyond the distance bound, with their sizes
  std::unique_ptr<Distance_to_surface> to_input; // built for the first check of the distance bound
  Meshed_patches meshed;
  std::set<std::size_t> crossing_patches;
  int crossing_rounds = 0, distance_rounds = 0;
  report.surface_distance_bound = options.maximum_surface_distance;
  report.places_beyond_surface_distance = 0;
  report.surface_distance_rounds_dropped = 0;
  // The last output that did not intersect itself, and the report then, while the places beyond
  // the distance bound are meshed again: should that give an output whose crossings cannot be
  // mended, patches that do not glue, or an output no closer to the input, the last one is
  // returned.
  std::unique_ptr<Glued_output<TriangleMesh> > kept;
  Remeshing_report report_of_kept;
  const auto return_kept = [&](const std::string& why) {
    const std::size_t dropped = std::size_t(distance_rounds) - report_of_kept.surface_distance_refinements;
    report = report_of_kept;
    report.surface_distance_rounds_dropped = dropped;
    progress("meshing again for the distance bound " + why + ": the output before it is kept");
    return std::move(*kept);
  };
  for(int round = 0;; ++round)
  {
    Clock::time_point start = Clock::now();
    progress(round == 0 ? "meshing " + std::to_string(surface.patches.size()) + " patches"
                        : crossing_patches.empty() ? "meshing again near " + std::to_string(far_places.places().points.size()) + " places"
                                                   : "meshing again " + std::to_string(crossing_patches.size()) + " patches and their neighbours");
    Local_refinement places = far_places.places();
    places.add(crossings, h / double(1 << crossing_rounds));
    const Sizing sizing(surface.segmentation, h, options.sizing_field, options.maximum_chord_error, places, proximity.gap);
    if(round == 0)
      report.gap_bounded_vertices = sizing.gap_bounded_vertices();
    Glued_output<TriangleMesh> glued;
    try
    {
      meshed = mesh_patches_on_shared_samples<ConcurrencyTag>(surface, sizing, options.corner_angle, meshing,
                                                              options.patch_job_runner, time_limit, progress,
                                                              report, round == 0 ? nullptr : &meshed, crossing_patches);
      statistics.seconds_meshing_stage += seconds_since(start);
      statistics.peak_resident_mb_meshing = peak_resident_megabytes();
      add_meshing_statistics(meshed, statistics);

      start = Clock::now();
      progress("gluing");
      glued = glue_patches<ConcurrencyTag, TriangleMesh>(meshed, surface.segmentation, sizing, options.minimum_angle,
                                                         input_self_intersects, statistics);
      statistics.seconds_gluing += seconds_since(start);
      statistics.peak_resident_mb_gluing = peak_resident_megabytes();
      if(glued.intersects && (crossing_rounds == max_self_intersection_refinements || glued.crossings.empty()))
        throw self_intersection_error(glued.crossings, report.input.coincident_vertices);
    }
    catch(const Error& e)
    {
      if(e.code() != Error_code::NOT_AN_EMBEDDING || !kept)
        throw;
      return return_kept("gave no valid output (" + without_caller(e.what()) + ")");
    }
    if(!glued.intersects)
    {
      if(!(options.maximum_surface_distance > 0.))
        return glued;
      progress("checking the distance to the input");
      const Places_beyond_distance far = check_surface_distance<ConcurrencyTag>(surface, to_input, glued, options, report, statistics);
      if(kept && !brought_closer(far, report_of_kept))
        return return_kept("brought the output no closer to the input (" + std::to_string(far.largest) + " at most, "
                           + std::to_string(report_of_kept.largest_surface_distance) + " before)");
      if(far.places.empty() || distance_rounds == max_surface_distance_refinements)
        return glued;
      report_of_kept = report;
      kept = std::make_unique<Glued_output<TriangleMesh> >(std::move(glued));
      ++distance_rounds;
      far_places.add(far.places);
      report.surface_distance_refinements = std::size_t(distance_rounds);
      report.places_beyond_surface_distance += far.places.size();
      progress(std::to_string(far.output_faces) + " output faces and " + std::to_string(far.input_vertices) + " input vertices, "
               + std::to_string(far.input_edges) + " edges and " + std::to_string(far.input_faces)
               + " faces farther apart than the distance bound (" + std::to_string(far.largest) + " at most, the bound "
               + std::to_string(options.maximum_surface_distance) + "): meshing again with shorter edges there");
      continue;
    }
    const std::set<std::size_t> around = with_neighbours(glued.crossing_patches, meshed);
    crossing_patches.insert(around.begin(), around.end());
    const std::size_t known = crossings.size();
    for(const Epick::Point_3& c : glued.crossings)
      add_if_far(crossings, c, 0.25 * h);
    ++crossing_rounds;
    report.self_intersection_refinements = std::size_t(crossing_rounds);
    std::ostringstream near;
    near << glued.crossings.front().x() << ", " << glued.crossings.front().y() << ", " << glued.crossings.front().z();
    progress("the output intersects itself at " + std::to_string(glued.crossings.size() / 2) + " pairs of triangles, near ("
             + near.str() + ") (" + std::to_string(crossings.size() - known) + " new places): meshing again with edges of 1/"
             + std::to_string(1 << crossing_rounds) + " of the target there");
  }
}

/// `mesh_and_glue()` with the options' point placement, then by Delaunay refinement alone should
/// frontal insertion not mesh the surface (policy 3 above).
template <typename ConcurrencyTag, typename TriangleMesh, typename Progress>
Glued_output<TriangleMesh> mesh_and_glue_with_fallback(const Flattened_surface& surface, const Remeshing_options& options,
                                                       const std::function<bool()>& input_self_intersects,
                                                       const Time_limit& time_limit, const Progress& progress,
                                                       Remeshing_report& report, Remeshing_statistics& statistics)
{
  Patch_meshing meshing;
  meshing.minimum_angle = options.minimum_angle;
  meshing.smoothing = options.smoothing;
  meshing.frontal = options.frontal;
  meshing.optimization_rounds = options.optimization_rounds;
  meshing.moves_in_parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
  // With a chord error bound, the gaps between sheets bound the chords too.
  Surface_proximity proximity;
  if(options.maximum_chord_error > 0.)
  {
    const auto start = std::chrono::steady_clock::now();
    progress("measuring the gaps between sheets");
    proximity = surface_proximity<ConcurrencyTag>(surface.segmentation.mesh, options.target_edge_length);
    statistics.seconds_proximity += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.smallest_gap = proximity.smallest_gap;
    report.smallest_gap_point = {{proximity.smallest_gap_point.x(), proximity.smallest_gap_point.y(), proximity.smallest_gap_point.z()}};
    time_limit.check("remesh_conformal");
  }
  try
  {
    return mesh_and_glue<ConcurrencyTag, TriangleMesh>(surface, options, meshing, proximity, input_self_intersects, time_limit, progress, report, statistics);
  }
  catch(const Error& e)
  {
    if(!options.frontal.is_on() || e.code() != Error_code::NOT_AN_EMBEDDING)
      throw;
    report.frontal_dropped = true;
    report.frontal_fallback_reason = without_caller(e.what());
    progress("the frontally placed points do not mesh the surface (" + report.frontal_fallback_reason
             + "): meshing again with Delaunay refinement alone");
    meshing.frontal = Frontal_insertion();
    meshing.smoothing = options.refinement_smoothing;
    return mesh_and_glue<ConcurrencyTag, TriangleMesh>(surface, options, meshing, proximity, input_self_intersects, time_limit, progress, report, statistics);
  }
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_AND_GLUE_H
