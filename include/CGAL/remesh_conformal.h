// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's entry point: remeshing a surface by conformal flattening, planar Delaunay
// refinement and pull-back onto the input surface. The stages live in
// Conformal_remeshing/internal/remeshing/, one header each.

#ifndef CGAL_REMESH_CONFORMAL_H
#define CGAL_REMESH_CONFORMAL_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/parameters.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/prepare_input.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/component_batches.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/remeshing_options.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// Remeshes the triangle mesh `input` into `output` by conformal flattening (paper Sec. 3-4).
///
/// The surface is segmented into poly-annuli (`segment_into_poly_annuli()`: along sharp
/// features, user patches and cutting planes, then plane bisection until every piece has genus 0
/// and a boundary). Each patch is flattened by `conformal_flatten()` with no overlap; a patch whose
/// flattening fails, or whose local scale varies by more than `maximum_scale_ratio`, is bisected
/// and flattened again. Every patch boundary curve is sampled once, in 3D, on the input polyline
/// at the target length, keeping junctions and corners; both patches beside a curve use the same
/// samples. Each planar domain is meshed by frontal Delaunay insertion (rows of nearly equilateral
/// triangles grown from the boundary samples), then CGAL's constrained Delaunay refinement with a
/// minimum angle bound and a size bound in 3D units (the planar size is the target length times the
/// local scale of the map), never adding points on the shared boundaries; every new planar vertex
/// is carried back onto the input surface through the flow's bijective correspondence (no
/// projection). The patches are glued at their shared samples: the output is closed and manifold
/// where the input is, with the input's components, boundary loops and genus. On the glued
/// output, edges across the cuts between patches are flipped and the cuts' samples and their
/// neighbours moved on the input surface where that improves the shapes. Where the glued output
/// intersects itself and the input does not, those places are meshed again with shorter edges
/// (half the target, then a quarter, then an eighth).
///
/// \tparam ConcurrencyTag `CGAL::Parallel_if_available_tag` (the default: patches are flattened and
///         meshed in parallel when CGAL is linked with TBB), `CGAL::Parallel_tag` or `CGAL::Sequential_tag`
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal point property map
///
/// The package's parameters are built with `CGAL::Conformal_remeshing::parameters::name(value)`,
/// CGAL's with `CGAL::parameters::name(value)`; either chains the other as its second argument.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_edge_length}
///     \cgalParamDescription{the target edge length in the units of the input}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`relative_target_edge_length` times the bounding-box diagonal}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_target_edge_length}
///     \cgalParamDescription{the target edge length as a fraction of the bounding-box diagonal}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0.01`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sizing_field}
///     \cgalParamDescription{the wanted edge length at a point of the input surface; the target edge length stays the upper bound, and sizes below 1/16 of it count as 1/16}
///     \cgalParamType{a callable `double(const CGAL::Epick::Point_3&)`}
///     \cgalParamDefault{none: uniform}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_chord_error}
///     \cgalParamDescription{curvature-adaptive sizing: where the surface bends, edges are shortened so that a chord of the largest normal curvature deviates from the surface by at most this distance (input units), graded to grow by at most half the distance, between 1/16 of the target edge length and the target}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`: none}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_surface_distance}
///     \cgalParamDescription{a bound on the distance between the output and the input, both ways (input units): after gluing, where a face of the output stands farther from the input than this, or a point of the input (a vertex, or on an edge or a face) stands farther from the output (a crease under the features angle cut off, a small feature rounded away), the surface is meshed again with edges of half the target there (along the whole of an input edge that stands too far), graded back to the target by half the distance, and halved again where it still stands too far, in at most four rounds (down to 1/16 of the target); the meshes of the patches those places do not reach are kept, and a round that brings the output no closer is dropped. The distances are measured at samples (face centroids, the input's vertices and edge midpoints, and a grid a quarter target apart near the bound), not everywhere. What is still farther after that is counted in `Remeshing_report::output_faces_beyond_surface_distance`, `input_vertices_beyond_surface_distance`, `input_edges_beyond_surface_distance` and `input_faces_beyond_surface_distance`, and placed in `places_still_beyond_surface_distance`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{a quarter of the target edge length (`0`: none)}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_angle}
///     \cgalParamDescription{in degrees, in (0, 34]: no flip or move of the optimization on the surface creates a smaller angle, and its angle passes raise the triangles below the larger of this and 30 degrees; the planar Delaunay refinement's shape bound is the smaller of this and 20.7 degrees, the bound for which refinement provably ends}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`28`}
///   \cgalParamNEnd
///   \cgalParamNBegin{corner_angle}
///     \cgalParamDescription{in degrees: boundary and feature vertices turning by more than this are kept; so are those of the cuts between patches, except where the cut runs less than 0.3 target lengths to the next curve end}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`30`}
///   \cgalParamNEnd
///   \cgalParamNBegin{frontal_insertion}
///     \cgalParamDescription{whether the planar meshing places its points by frontal Delaunay insertion before the Delaunay refinement (Rebay 1993): rows of nearly equilateral triangles grown from the boundary samples, the refinement then enforcing the bounds where the fronts met. With `false`, the refinement alone places them (the paper's planar stage), followed by one Laplacian pass. Should the surface not mesh with frontally placed points (patches that do not glue, an output that intersects itself even after meshing again finer), it is meshed again without them, and `Remeshing_report::frontal_dropped` says so, with the reason}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_iterations}
///     \cgalParamDescription{passes of Laplacian smoothing in the plane before the optimization on the surface, each followed by a triangulation and refinement again}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`0` with `frontal_insertion`, `1` without}
///   \cgalParamNEnd
///   \cgalParamNBegin{lloyd_iterations}
///     \cgalParamDescription{after the Laplacian passes, at most this many iterations of CGAL's Lloyd smoothing in the plane (`lloyd_optimize_mesh_2()`, with the density of the mesh's own edge lengths, so the grading stays; the fixed points and the boundary samples do not move), then one more refinement to restore the bounds; the iterations stop at the `maximum_running_time` too}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`0`: none}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_rounds}
///     \cgalParamDescription{rounds of edge flips toward valence 6 and vertex smoothing after the refinement, judged by the triangles' shapes on the surface; after them, inner edges longer than 1.26 times the target, and those across bends, are split and two more rounds run, then up to two more splits of the same kinds with a round each; no round lowers the smallest angle below the `minimum_angle` bound or stretches an edge past 1.4 times the target (1.26 after the splits)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`5`}
///   \cgalParamNEnd
///   \cgalParamNBegin{repair_input}
///     \cgalParamDescription{repair what keeps the input from being remeshed but leaves its surface as it is: non-manifold vertices are split (CGAL's `duplicate_non_manifold_vertices()`: each fan of faces gets a vertex of its own) and faces of zero area are collapsed or flipped away (CGAL's `remove_degenerate_faces()`); the counts are in `Remeshing_report`. Off, such an input is refused. Vertices at the same point as another are never a defect: they stay distinct points of the surface}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{features_fallback}
///     \cgalParamDescription{when a patch cannot be flattened even after bisection, and the segmentation has sharp features, segment again without them (and say so in `Remeshing_report::features_dropped`), rather than fail. On scans the features angle takes noise for sharp edges, which cut the surface into patches whose conformal scale varies by many orders of magnitude even after the bisections}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{batch_faces}
///     \cgalParamDescription{an input of more faces than this and of several connected components (an assembly of parts) is remeshed a batch of whole components at a time, each batch of at most this many faces (a larger component is a batch of its own): each batch is segmented, flattened, meshed and glued alone and its flattenings released before the next, so that the peak memory is that of the largest batch rather than of the whole input. The batches' outputs are then checked against each other, and batches whose outputs cross where the input does not are remeshed together (`Remeshing_report::component_batches`, `Remeshing_report::merged_batches`). `0`: never in batches. The output of one batch equals that of the same components remeshed alone}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`2000000`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_scale_ratio}
///     \cgalParamDescription{a patch whose largest local scale exceeds its smallest by more than this is bisected}
///     \cgalParamType{`double`, above 1}
///     \cgalParamDefault{`1000`}
///   \cgalParamNEnd
///   \cgalParamNBegin{snap_distance}
///     \cgalParamDescription{vertices closer than this to a cutting or bisecting plane are taken as on it (see `segment_into_poly_annuli()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{a tenth of the target edge length}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_edge_length}
///     \cgalParamDescription{the longest edge the Ricci flow keeps in a patch's intrinsic triangulation: the resolution of the conformal map, finer on tubes (see `conformal_flatten()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{twice the target edge length}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{told when each stage starts, with a sentence naming it}
///     \cgalParamType{a callable `void(const std::string&)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{CGAL's parameter (`CGAL::parameters::maximum_running_time()`, also offered as `Conformal_remeshing::parameters::maximum_running_time()`): a limit in seconds on the wall-clock time of the call, checked between the stages, between the patches and between the Newton iterations of every flow; past it the call throws `Error` with `Error_code::TIME_LIMIT_EXCEEDED` and leaves `output` untouched}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{stop_requested}
///     \cgalParamDescription{polled wherever the `maximum_running_time` is checked (the patches' flows included); once it returns `true`, the call stops as past its time limit, with `Error_code::TIME_LIMIT_EXCEEDED` and a message saying that a stop was requested, `output` untouched: how a program ends a long call from outside (the Python module on Ctrl-C). It must be cheap, safe to call from several threads at once, and keep returning `true` once it has}
///     \cgalParamType{a callable `bool()`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_locations}
///     \cgalParamDescription{an output: receives the input face (by the face index map) and barycentric coordinates (corner order of `CGAL::Polygon_mesh_processing::locate()`) of every output vertex, in the order of `vertices(output)`; pass it as `std::ref(locations)`. `verify_remesh()` checks them}
///     \cgalParamType{`std::reference_wrapper<std::vector<Surface_location> >`}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{flattened_patch_visitor}
///     \cgalParamDescription{called with every patch that the meshing stage meshes (after the bisections, and without the sharp features when the `features_fallback` dropped them) and its flattening, in patch order, once they are all flattened and before any is meshed: how to look at the patches and their planar domains (the tool's `--save-patches` writes them). A batch of components (`batch_faces`) shows its own patches; batches whose outputs cross each other and are remeshed together show theirs again. With a visitor the flattening stage holds every patch whole until the last one is flattened; without one (an empty `std::function` is none) it keeps of each patch, as soon as it is flattened, only what the meshing reads}
///     \cgalParamType{a callable `void(const Extracted_patch&, const Conformal_flattening&)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{an output: receives the timings and counters of the stages (see `Remeshing_statistics`); pass it as `std::ref(statistics)`}
///     \cgalParamType{`std::reference_wrapper<Remeshing_statistics>`}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the points of the vertices of `input`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, input)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{the face indices of `input` that `vertex_locations` refers to}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{the internal face index map of `input`, initialized if needed}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// The other parameters of `segment_into_poly_annuli()` (`features_angle`, `crease_angle`,
/// `cut_planes`, `face_patch_map`, `edge_is_constrained_map`) and of `conformal_flatten()`
/// (`annulus_inner_radius`, `curvature_tolerance`, `number_of_iterations`) are passed on to them.
///
/// \param input the mesh to remesh
/// \param output receives the new mesh (cleared first)
/// \param np the named parameters above
/// \returns what happened (the timings and counters go to the `statistics` output)
/// \throws Error with `Error_code::INVALID_INPUT` when the input is not an orientable triangle
///         mesh that the repairs above make a valid manifold, or a parameter is out of range, and with the flattening's
///         code when a patch cannot be flattened even after bisection, and without sharp
///         features if `features_fallback` is on (the message says why);
///         with `Error_code::TIME_LIMIT_EXCEEDED` past the `maximum_running_time`; with
///         `Error_code::NOT_AN_EMBEDDING` when the remeshed surface would intersect itself where
///         the input does not (checked with exact predicates) even after those places were meshed
///         again three times with shorter edges, down to an eighth of the target (`output` is then
///         left untouched).
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Remeshing_report remesh_conformal(const TriangleMesh& input, TriangleMesh& output,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace stages = internal::remeshing;
  Remeshing_report report;
  Remeshing_statistics statistics;
  const internal::Time_limit time_limit = internal::Time_limit::from(np, "remesh_conformal");
  const std::function<void(const std::string&)> progress =
    choose_parameter(get_parameter(np, internal_np::progress), [](const std::string&) {});

  progress("checking the input");
  const stages::Remeshing_options options = stages::remeshing_options(input, np);
  report.target_edge_length = options.target_edge_length;
  const bool repair = choose_parameter(get_parameter(np, internal_np::repair_input), true);
  stages::Prepared_input prepared = stages::prepare_input(input, np, repair, report.input);
  if(report.input.repaired())
    progress("repaired the input: " + report.input.summary());
  if(report.input.coincident_vertices > 0)
    progress("keeping " + std::to_string(report.input.coincident_vertices) + " vertices at the same point as others as distinct vertices (e.g. "
             + report.input.coincident_example + ")");

  constexpr bool with_locations =
    !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::vertex_locations_t>::value;
  stages::Remeshed_output<TriangleMesh> remeshed;
  if(!prepared.is_copy)
    remeshed = stages::remesh_in_batches<ConcurrencyTag, TriangleMesh>(input, np, options, time_limit, progress, report, statistics,
                                                                       with_locations);
  else
  {
    remeshed = stages::remesh_in_batches<ConcurrencyTag, TriangleMesh>(
      prepared.mesh, stages::parameters_of_copy(prepared, input, np), options, time_limit, progress, report, statistics, false);
    if(with_locations)
      remeshed.locations = stages::locate_on_input(input, np, remeshed.points);
  }
  output = std::move(remeshed.mesh);
  if constexpr(with_locations)
    CGAL::parameters::get_parameter_reference(np, internal_np::vertex_locations) = std::move(remeshed.locations);
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::statistics_t>::value)
    CGAL::parameters::get_parameter_reference(np, internal_np::statistics) = std::move(statistics);
  report.output_vertices = num_vertices(output);
  report.output_faces = num_faces(output);
  return report;
}

/// \ingroup PkgConformalRemeshingRef
/// Remeshes `mesh` in place, like `CGAL::Polygon_mesh_processing::isotropic_remeshing()`; see the
/// other overload for the parameters.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename T, typename Tag, typename Base>
Remeshing_report remesh_conformal(TriangleMesh& mesh, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  TriangleMesh output;
  const Remeshing_report report = remesh_conformal<ConcurrencyTag>(static_cast<const TriangleMesh&>(mesh), output, np);
  mesh = std::move(output);
  return report;
}

/// \ingroup PkgConformalRemeshingRef
/// Remeshes `mesh` in place with the default parameters.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh>
Remeshing_report remesh_conformal(TriangleMesh& mesh)
{
  return remesh_conformal<ConcurrencyTag>(mesh, CGAL::parameters::default_values());
}

} // namespace Conformal_remeshing

using Conformal_remeshing::remesh_conformal;

} // namespace CGAL

#endif // CGAL_REMESH_CONFORMAL_H
