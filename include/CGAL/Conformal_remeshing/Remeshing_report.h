// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What `remesh_conformal()` returns: the report of a run, and where each output vertex lies on
// the input surface.

#ifndef CGAL_CONFORMAL_REMESHING_REMESHING_REPORT_H
#define CGAL_CONFORMAL_REMESHING_REMESHING_REPORT_H

#include <CGAL/Conformal_remeshing/Input_preparation_report.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// Where the meshing stage's time goes, in seconds summed over the patches (see
/// `Remeshing_statistics::meshing_phases`). The first three add up to
/// `Remeshing_statistics::seconds_planar_meshing`, the other six to
/// `Remeshing_statistics::seconds_optimization` (wall seconds of each patch's optimization, whose
/// vertex moves may run in parallel).
struct Meshing_phase_seconds
{
  /// the planar meshing's set-up and output: the point locator in the flattening, the input
  /// vertices kept, the seeds, the triangulation of the boundary samples and the numbering of
  /// the output
  double planar_setup = 0.;
  /// the placement of the planar points: the frontal insertion (when `frontal_insertion` is on)
  /// and CGAL's Delaunay refinement of the planar domain
  double planar_refinement = 0.;
  /// the smoothing in the plane, with the triangulation and refinement of the smoothed points
  double planar_smoothing = 0.;
  /// the optimization's set-up: the lifts of the planar points to the surface and the adjacency
  double optimization_setup = 0.;
  double first_rounds = 0.;    ///< its first rounds of flips and smoothing passes
  double splits = 0.;          ///< its split passes and the rounds after them
  double collapses = 0.;       ///< its collapse pass and the round after it
  double skewness_passes = 0.; ///< its skewness passes
  double angle_passes = 0.;    ///< its angle passes and the removal of the collapsed vertices

  /// Calls `f(name, phase)` for each phase in the order above: `name` is the member's name (as in
  /// the tools' JSON reports), `phase` a pointer to the member.
  template <typename F>
  static void for_each_phase(const F& f)
  {
    typedef Meshing_phase_seconds P;
    f("planar_setup", &P::planar_setup);
    f("planar_refinement", &P::planar_refinement);
    f("planar_smoothing", &P::planar_smoothing);
    f("optimization_setup", &P::optimization_setup);
    f("first_rounds", &P::first_rounds);
    f("splits", &P::splits);
    f("collapses", &P::collapses);
    f("skewness_passes", &P::skewness_passes);
    f("angle_passes", &P::angle_passes);
  }

  Meshing_phase_seconds& operator+=(const Meshing_phase_seconds& other)
  {
    for_each_phase([&](const char*, double Meshing_phase_seconds::*phase) { this->*phase += other.*phase; });
    return *this;
  }
};

/// \ingroup PkgConformalRemeshingRef
/// What `remesh_conformal()` did, for its user: the sizes, what was repaired, refined or fell
/// back, and why. The timings and counters of its stages are in `Remeshing_statistics`, an
/// optional output (named parameter `statistics`).
struct Remeshing_report
{
  double target_edge_length = 0.; ///< the target edge length used, in input units
  Input_preparation_report input; ///< what the input preparation repaired and kept
  /// the input has faces that cross (more than touch at coincident vertices): found when the
  /// output crossed itself, which is then not refused, each sheet having been remeshed alone
  bool input_crosses_itself = false;
  std::size_t number_of_patches = 0;
  std::size_t plane_cuts = 0;       ///< cuts by planes: given, and bisections of the segmentation
  std::size_t patch_bisections = 0; ///< patches bisected because their flattening failed or stretched
  std::size_t feature_edges = 0;    ///< sharp edges of the refined input
  /// feature edges inside a patch rather than between two (the patch is slit open along them)
  std::size_t dangling_feature_edges = 0;
  /// sharp edges left out of the features: the side that turns less of a strip between features
  /// (or a feature and the border) narrower than a twentieth of the target edge length, a small
  /// chamfer or bevel whose triangles, between samples about a target apart on both sides, would
  /// be needles; the output passes within a few strip widths of them
  std::size_t narrow_strip_feature_edges = 0;
  /// the sharp features were dropped because a patch could not be flattened with them (see the
  /// named parameter `features_fallback`); `features_fallback_reason` says why
  bool features_dropped = false;
  std::string features_fallback_reason;
  /// the surface was meshed again with Delaunay refinement alone because the frontally placed
  /// points did not mesh it (see the named parameter `frontal_insertion`);
  /// `frontal_fallback_reason` says why
  bool frontal_dropped = false;
  std::string frontal_fallback_reason;
  /// with a chord error bound (named parameter `maximum_chord_error`), the smallest distance from
  /// a vertex of the input to another sheet of it (a part of the surface more than twice as far
  /// along the surface as across, or facing it: the other wall of a thin part, another
  /// component); infinite when none comes within a target edge length, NaN when not measured
  double smallest_gap = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> smallest_gap_point{{0., 0., 0.}}; ///< an input vertex with the smallest gap
  /// input vertices where the gap shortened the target edge length, so that the chords of the
  /// output, where the surface bends, stay within half the gap of it and cannot cross the gap
  std::size_t gap_bounded_vertices = 0;
  /// rounds of meshing again with shorter edges where the output intersected itself (0 to 4)
  std::size_t self_intersection_refinements = 0;
  /// the surface-distance bound (named parameter `maximum_surface_distance`; 0: none)
  double surface_distance_bound = 0.;
  /// rounds of meshing again with shorter edges where the output stood farther from the input
  /// than the bound (0 to 4)
  std::size_t surface_distance_refinements = 0;
  /// the places meshed again for the bound, over all rounds (about a quarter target apart)
  std::size_t places_beyond_surface_distance = 0;
  /// the last rounds of meshing again for the bound, dropped because their output intersected
  /// itself beyond mending (or their patches did not glue) or stood no closer to the input than
  /// the output before: the output is the last one before them
  std::size_t surface_distance_rounds_dropped = 0;
  /// of the output: its largest distance from the input and the input's from it, found at the
  /// samples of the check (the faces' centroids, the input's vertices and edge midpoints, and a
  /// grid a quarter target apart near the bound); 0 when there is no bound
  double largest_surface_distance = 0.;
  /// where that largest distance was found: a sample of the output or of the input
  std::array<double, 3> largest_surface_distance_point{{0., 0., 0.}};
  /// of the output: its faces, and the input's vertices, edges and faces, with a point still
  /// farther than the bound from the other after the last round
  std::size_t output_faces_beyond_surface_distance = 0;
  std::size_t input_vertices_beyond_surface_distance = 0;
  std::size_t input_edges_beyond_surface_distance = 0;
  std::size_t input_faces_beyond_surface_distance = 0;
  /// where those are: the places still farther than the bound after the last round, about a
  /// quarter target apart, at most `max_reported_places` of them (the first found): a crease
  /// cut or a small feature rounded off that the rounds of meshing again could not keep
  std::vector<std::array<double, 3> > places_still_beyond_surface_distance;
  static constexpr std::size_t max_reported_places = 100;
  std::size_t refined_boundary_curves = 0; ///< times a boundary curve of a thin patch was sampled twice as densely
  std::size_t split_diagonals = 0; ///< times a patch split an edge between two samples that another patch also has
  /// batches of whole components the input was remeshed in (named parameter `batch_faces`;
  /// 1: in one piece); the other counts of the report are summed over the batches
  std::size_t component_batches = 1;
  /// batches remeshed again together with another because their outputs crossed each other
  std::size_t merged_batches = 0;
  std::size_t output_vertices = 0;
  std::size_t output_faces = 0;

};

/// \ingroup PkgConformalRemeshingRef
/// The timings and counters of a run of `remesh_conformal()`, written to the named parameter
/// `statistics` when it is given: for benchmarks, profiling and the tools' detailed reports.
/// The counts of the patches' meshing and the seconds add up over every round of meshing again
/// (`Remeshing_report::self_intersection_refinements`, and a fallback to refinement alone);
/// `collapses_after_gluing`, `flips_after_gluing` and `moves_after_gluing` are those of the output.
struct Remeshing_statistics
{
  std::vector<Flattening_report> patches; ///< the flattening of each patch
  int max_newton_iterations = 0;
  double max_curvature_error = 0.;
  std::size_t flips = 0; ///< edge flips of the flows, summed over the patches
  /// faces of flat regions (developable or exactly coplanar) replaced by their constrained
  /// Delaunay triangulation before the flips (`Flattening_report::retriangulated_faces`, summed)
  std::size_t retriangulated_faces = 0;
  double max_scale_ratio = 0.; ///< the largest ratio of the local scales in a patch
  std::size_t boundary_curves = 0;
  std::size_t boundary_samples = 0;
  /// patch jobs run (each meshes one patch on its boundary samples), and jobs that took the
  /// result of an equal job run before instead (a patch whose boundary and sizes did not change
  /// when other curves were sampled again, or that no self-intersection touched)
  std::size_t patch_jobs_run = 0, patch_jobs_kept = 0;
  /// output vertices whose planar position fell outside the flat patch (between a boundary
  /// chord and the boundary polyline) and were clamped onto the nearest patch triangle
  std::size_t clamped_vertices = 0;
  std::size_t optimization_flips = 0; ///< edge flips of the optimization on the surface
  /// edges that the optimization split (one new vertex each): those longer than 1.26 times the
  /// target on the surface, and those across bends (`optimization_chord_splits`)
  std::size_t optimization_splits = 0;
  /// of those, the edges whose chord's midpoint stood more than 0.15 times the target from the
  /// surface point of their planar midpoint (edges of 0.9 times the target or longer)
  std::size_t optimization_chord_splits = 0;
  /// inner edges shorter than 0.7 times the target that the optimization collapsed after its
  /// splits (one vertex fewer each; uniform sizing only)
  std::size_t optimization_collapses = 0;
  /// edge flips on the glued mesh: between boundary samples and at moved points for shape, then
  /// of triangles below 30 degrees; mostly across the cuts between patches
  std::size_t flips_after_gluing = 0;
  /// edge collapses on the glued mesh: edges at samples shorter than a quarter of the size there
  /// (samples that the patches had to keep that close), one vertex fewer each
  std::size_t collapses_after_gluing = 0;
  /// vertex moves on the glued mesh: samples of the cuts between patches and their neighbours,
  /// moved on the input surface for shape
  std::size_t moves_after_gluing = 0;
  /// wall-clock seconds of the stages (the flattening and meshing stages run patches in parallel)
  double seconds_segmentation = 0., seconds_flattening = 0., seconds_meshing_stage = 0., seconds_gluing = 0.;
  double seconds_proximity = 0.; ///< wall-clock seconds of measuring the gaps between sheets
  double seconds_surface_distance = 0.; ///< wall-clock seconds of checking the surface-distance bound
  /// seconds summed over the patches (thread time; the optimization's vertex moves within a
  /// patch run in parallel too, so `seconds_optimization` sums the patches' wall time)
  double seconds_ricci_flow = 0., seconds_planar_meshing = 0., seconds_optimization = 0., seconds_pull_back = 0.;
  /// the seconds of each patch job run (its planar meshing, optimization and pull-back), in the
  /// order of the patches, round after round of the meshing stage: what a scheduler of the jobs
  /// over processes works with (the car benchmark replays it)
  std::vector<double> patch_job_seconds;
  /// the planar meshing's and the optimization's seconds by phase
  Meshing_phase_seconds meshing_phases;
  /// the process's peak resident memory in MB at the end of the segmentation, the flattening, the
  /// meshing and the gluing: the largest so far, so the stage where it rises holds the peak (-1
  /// where the platform does not tell)
  double peak_resident_mb_segmentation = -1., peak_resident_mb_flattening = -1., peak_resident_mb_meshing = -1.,
         peak_resident_mb_gluing = -1.;
};

/// \ingroup PkgConformalRemeshingRef
/// Where an output vertex lies on the input surface: an input face and barycentric coordinates
/// (corner order of `CGAL::Polygon_mesh_processing::locate()`).
struct Surface_location
{
  std::size_t input_face = 0;
  std::array<double, 3> coordinates{{0., 0., 0.}};
};
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_REMESHING_REPORT_H
