// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stages after the preparation on an input of many connected components, in batches: an
// assembly of parts is remeshed a batch of whole components at a time, each batch copied out,
// segmented, flattened, meshed and glued alone, and its flattenings released before the next one
// starts. The peak memory is that of the input, the outputs so far and the largest batch, instead
// of the flattenings of the whole input. The components of different batches are remeshed
// independently, so their outputs are checked against each other at the end; batches whose
// outputs cross where the input does not are merged and remeshed together.
//
// An input of at most `batch_faces` faces, or of one component, is remeshed in one piece, exactly
// as `remesh_prepared()` does.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_COMPONENT_BATCHES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_COMPONENT_BATCHES_H

#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/Conformal_remeshing/internal/process_memory.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/prepare_input.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/remesh_prepared.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/remeshing_options.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The connected components of `mesh` grouped into batches of at most `batch_faces` faces, in the
/// order of the components' first faces (a larger component is a batch of its own); each batch is
/// the list of its components. One batch when the mesh has at most `batch_faces` faces or
/// `batch_faces` is 0.
template <typename Mesh, typename NamedParameters>
std::vector<std::vector<std::size_t> > component_batches(const Mesh& mesh, const NamedParameters& np, std::size_t batch_faces,
                                                         std::vector<std::size_t>& face_component)
{
  const std::size_t faces_count = num_faces(mesh);
  if(batch_faces == 0 || faces_count <= batch_faces)
    return {};
  auto fim = CGAL::get_initialized_face_index_map(mesh, np);
  face_component.assign(faces_count, 0);
  const auto component_map = boost::make_iterator_property_map(face_component.begin(), fim);
  const std::size_t components =
    CGAL::Polygon_mesh_processing::connected_components(mesh, component_map, CGAL::parameters::face_index_map(fim));
  if(components < 2)
    return {};
  std::vector<std::size_t> size(components, 0);
  for(std::size_t c : face_component)
    ++size[c];
  std::vector<std::vector<std::size_t> > batches(1);
  std::size_t in_batch = 0;
  for(std::size_t c = 0; c < components; ++c)
  {
    if(in_batch > 0 && in_batch + size[c] > batch_faces)
    {
      batches.emplace_back();
      in_batch = 0;
    }
    batches.back().push_back(c);
    in_batch += size[c];
  }
  if(batches.size() < 2)
    return {};
  return batches;
}

/// The faces of `mesh` in the components `components`, copied, with for each copied face the index
/// of its face in `mesh` and the same first corner (the source of `halfedge(f)`), so that
/// barycentric coordinates in a copied face hold in its original too.
template <typename Mesh, typename NamedParameters>
Prepared_input copy_of_components(const Mesh& mesh, const NamedParameters& np, const std::vector<std::size_t>& face_component,
                                  const std::vector<std::size_t>& components)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<Mesh>::face_descriptor Face;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor Vertex;
  typedef Prepared_input::Mesh Copy;
  auto fim = CGAL::get_initialized_face_index_map(mesh, np);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  const std::set<std::size_t> wanted(components.begin(), components.end());
  std::vector<Face> selected;
  for(Face f : faces(mesh))
    if(wanted.count(face_component[get(fim, f)]) > 0)
      selected.push_back(f);

  Prepared_input batch;
  batch.is_copy = true;
  batch.input_face = batch.mesh.add_property_map<Copy::Face_index, std::size_t>("f:input_face", 0).first;
  const CGAL::Face_filtered_graph<Mesh> part(mesh, selected);
  std::vector<std::pair<Face, Copy::Face_index> > face_pairs;
  std::map<Vertex, Copy::Vertex_index> vertex_of;
  CGAL::copy_face_graph(part, batch.mesh,
                        CGAL::parameters::vertex_point_map(vpm)
                          .face_to_face_output_iterator(std::back_inserter(face_pairs))
                          .vertex_to_vertex_map(boost::make_assoc_property_map(vertex_of)));
  for(const auto& pair : face_pairs)
  {
    batch.input_face[pair.second] = get(fim, pair.first);
    const Copy::Vertex_index first = vertex_of[source(halfedge(pair.first, mesh), mesh)];
    for(Copy::Halfedge_index h : CGAL::halfedges_around_face(batch.mesh.halfedge(pair.second), batch.mesh))
      if(batch.mesh.source(h) == first)
        batch.mesh.set_halfedge(pair.second, h);
  }
  return batch;
}

/// `batch`'s report added to `total`'s: counts summed, flags joined, the first reason kept.
inline void add_batch_report(Remeshing_report& total, const Remeshing_report& batch)
{
  total.input_crosses_itself = total.input_crosses_itself || batch.input_crosses_itself;
  total.number_of_patches += batch.number_of_patches;
  total.plane_cuts += batch.plane_cuts;
  total.patch_bisections += batch.patch_bisections;
  total.feature_edges += batch.feature_edges;
  total.dangling_feature_edges += batch.dangling_feature_edges;
  total.narrow_strip_feature_edges += batch.narrow_strip_feature_edges;
  if(batch.features_dropped && !total.features_dropped)
    total.features_fallback_reason = batch.features_fallback_reason;
  total.features_dropped = total.features_dropped || batch.features_dropped;
  if(batch.frontal_dropped && !total.frontal_dropped)
    total.frontal_fallback_reason = batch.frontal_fallback_reason;
  total.frontal_dropped = total.frontal_dropped || batch.frontal_dropped;
  if(!(total.smallest_gap <= batch.smallest_gap)) // NaN (not measured) gives way
  {
    total.smallest_gap = batch.smallest_gap;
    total.smallest_gap_point = batch.smallest_gap_point;
  }
  total.gap_bounded_vertices += batch.gap_bounded_vertices;
  total.self_intersection_refinements = (std::max)(total.self_intersection_refinements, batch.self_intersection_refinements);
  total.surface_distance_bound = batch.surface_distance_bound;
  total.surface_distance_refinements = (std::max)(total.surface_distance_refinements, batch.surface_distance_refinements);
  total.places_beyond_surface_distance += batch.places_beyond_surface_distance;
  total.surface_distance_rounds_dropped += batch.surface_distance_rounds_dropped;
  if(batch.largest_surface_distance > total.largest_surface_distance)
  {
    total.largest_surface_distance = batch.largest_surface_distance;
    total.largest_surface_distance_point = batch.largest_surface_distance_point;
  }
  for(const std::array<double, 3>& place : batch.places_still_beyond_surface_distance)
    if(total.places_still_beyond_surface_distance.size() < Remeshing_report::max_reported_places)
      total.places_still_beyond_surface_distance.push_back(place);
  total.output_faces_beyond_surface_distance += batch.output_faces_beyond_surface_distance;
  total.input_vertices_beyond_surface_distance += batch.input_vertices_beyond_surface_distance;
  total.input_edges_beyond_surface_distance += batch.input_edges_beyond_surface_distance;
  total.input_faces_beyond_surface_distance += batch.input_faces_beyond_surface_distance;
  total.refined_boundary_curves += batch.refined_boundary_curves;
  total.split_diagonals += batch.split_diagonals;
}

/// `batch`'s statistics added to `total`'s: counts and seconds summed, largest values kept.
inline void add_batch_statistics(Remeshing_statistics& total, const Remeshing_statistics& batch)
{
  total.patches.insert(total.patches.end(), batch.patches.begin(), batch.patches.end());
  total.max_newton_iterations = (std::max)(total.max_newton_iterations, batch.max_newton_iterations);
  total.max_curvature_error = (std::max)(total.max_curvature_error, batch.max_curvature_error);
  total.flips += batch.flips;
  total.retriangulated_faces += batch.retriangulated_faces;
  total.max_scale_ratio = (std::max)(total.max_scale_ratio, batch.max_scale_ratio);
  total.boundary_curves += batch.boundary_curves;
  total.boundary_samples += batch.boundary_samples;
  total.patch_jobs_run += batch.patch_jobs_run;
  total.patch_jobs_kept += batch.patch_jobs_kept;
  total.clamped_vertices += batch.clamped_vertices;
  total.optimization_flips += batch.optimization_flips;
  total.optimization_splits += batch.optimization_splits;
  total.optimization_chord_splits += batch.optimization_chord_splits;
  total.optimization_collapses += batch.optimization_collapses;
  total.flips_after_gluing += batch.flips_after_gluing;
  total.collapses_after_gluing += batch.collapses_after_gluing;
  total.moves_after_gluing += batch.moves_after_gluing;
  total.seconds_segmentation += batch.seconds_segmentation;
  total.seconds_flattening += batch.seconds_flattening;
  total.seconds_meshing_stage += batch.seconds_meshing_stage;
  total.seconds_gluing += batch.seconds_gluing;
  total.seconds_proximity += batch.seconds_proximity;
  total.seconds_surface_distance += batch.seconds_surface_distance;
  total.seconds_ricci_flow += batch.seconds_ricci_flow;
  total.seconds_planar_meshing += batch.seconds_planar_meshing;
  total.seconds_optimization += batch.seconds_optimization;
  total.seconds_pull_back += batch.seconds_pull_back;
  total.patch_job_seconds.insert(total.patch_job_seconds.end(), batch.patch_job_seconds.begin(), batch.patch_job_seconds.end());
  total.meshing_phases += batch.meshing_phases;
  total.peak_resident_mb_segmentation = (std::max)(total.peak_resident_mb_segmentation, batch.peak_resident_mb_segmentation);
  total.peak_resident_mb_flattening = (std::max)(total.peak_resident_mb_flattening, batch.peak_resident_mb_flattening);
  total.peak_resident_mb_meshing = (std::max)(total.peak_resident_mb_meshing, batch.peak_resident_mb_meshing);
  total.peak_resident_mb_gluing = (std::max)(total.peak_resident_mb_gluing, batch.peak_resident_mb_gluing);
}

/// One batch remeshed: its own report and statistics, its output with places on `mesh`.
template <typename OutputMesh>
struct Remeshed_batch
{
  Remeshed_output<OutputMesh> output;
  Remeshing_report report;
  Remeshing_statistics statistics;
};

/// The components `components` of `mesh` remeshed alone, the places of the output vertices (when
/// asked for) on `mesh`.
template <typename ConcurrencyTag, typename OutputMesh, typename Mesh, typename NamedParameters, typename Progress>
Remeshed_batch<OutputMesh> remesh_batch(const Mesh& mesh, const NamedParameters& np, const std::vector<std::size_t>& face_component,
                                        const std::vector<std::size_t>& components, const Remeshing_options& options,
                                        const Time_limit& time_limit, const Progress& progress,
                                        const Input_preparation_report& input_report, bool with_locations)
{
  Remeshed_batch<OutputMesh> result;
  result.report.target_edge_length = options.target_edge_length;
  result.report.input = input_report;
  Prepared_input batch = copy_of_components(mesh, np, face_component, components);
  progress(std::to_string(components.size()) + (components.size() == 1 ? " component, " : " components, ")
           + std::to_string(batch.mesh.number_of_faces()) + " faces");
  result.output = remesh_prepared<ConcurrencyTag, OutputMesh>(batch.mesh, parameters_of_copy(batch, mesh, np), options,
                                                              time_limit, progress, result.report, result.statistics,
                                                              with_locations);
  for(Surface_location& location : result.output.locations)
    location.input_face = batch.input_face[Prepared_input::Mesh::Face_index(typename Prepared_input::Mesh::size_type(location.input_face))];
  return result;
}

/// The batches whose outputs cross each other, as sets of batch indices that are to be merged
/// (empty when none cross). `first_face[b]` is the index in `output` of batch `b`'s first face.
template <typename ConcurrencyTag, typename OutputMesh>
std::vector<std::set<std::size_t> > crossing_batches(const OutputMesh& output, const std::vector<std::size_t>& first_face)
{
  typedef typename boost::graph_traits<OutputMesh>::face_descriptor Face;
  std::vector<std::set<std::size_t> > groups;
  if(!has_crossing_faces<ConcurrencyTag>(output))
    return groups;
  auto fim = CGAL::get_initialized_face_index_map(output);
  const auto batch_of = [&](Face f) {
    return std::size_t(std::upper_bound(first_face.begin(), first_face.end(), std::size_t(get(fim, f))) - first_face.begin()) - 1;
  };
  for(const std::pair<Face, Face>& pair : crossing_face_pairs<ConcurrencyTag>(output))
  {
    const std::size_t a = batch_of(pair.first), b = batch_of(pair.second);
    if(a == b)
      continue; // within a batch: the input crosses itself there (the batch's gluing accepted it)
    std::set<std::size_t> joined = {a, b};
    std::vector<std::set<std::size_t> > kept;
    for(std::set<std::size_t>& g : groups)
      if(g.count(a) > 0 || g.count(b) > 0)
        joined.insert(g.begin(), g.end());
      else
        kept.push_back(std::move(g));
    kept.push_back(std::move(joined));
    groups = std::move(kept);
  }
  return groups;
}

/// The batches' outputs as one mesh, in batch order, with the points and places of its vertices;
/// `first_face` receives each batch's first face.
template <typename OutputMesh>
Remeshed_output<OutputMesh> joined_output(const std::vector<Remeshed_batch<OutputMesh> >& batches, std::vector<std::size_t>& first_face)
{
  typedef typename boost::graph_traits<OutputMesh>::vertex_descriptor Vertex;
  Remeshed_output<OutputMesh> joined;
  std::vector<std::pair<Vertex, std::pair<std::size_t, std::size_t> > > origin; // joined vertex, (batch, index in the batch)
  first_face.clear();
  for(std::size_t b = 0; b < batches.size(); ++b)
  {
    const OutputMesh& part = batches[b].output.mesh;
    first_face.push_back(num_faces(joined.mesh));
    const auto vim = CGAL::get_initialized_vertex_index_map(part);
    std::vector<std::pair<Vertex, Vertex> > vertex_pairs;
    CGAL::copy_face_graph(part, joined.mesh, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vertex_pairs)));
    for(const auto& pair : vertex_pairs) // copy_face_graph numbers the vertices in its own order
      origin.emplace_back(pair.second, std::make_pair(b, std::size_t(get(vim, pair.first))));
  }
  const auto vim = CGAL::get_initialized_vertex_index_map(joined.mesh);
  const bool with_locations = !batches.empty() && !batches.front().output.locations.empty();
  joined.points.resize(num_vertices(joined.mesh));
  if(with_locations)
    joined.locations.resize(num_vertices(joined.mesh));
  for(const auto& o : origin)
  {
    const std::size_t v = std::size_t(get(vim, o.first));
    joined.points[v] = batches[o.second.first].output.points[o.second.second];
    if(with_locations)
      joined.locations[v] = batches[o.second.first].output.locations[o.second.second];
  }
  return joined;
}

/// The stages after the preparation on `mesh` (see `remesh_prepared()`), a batch of whole
/// components at a time when it has more than `options.batch_faces` faces and several components.
template <typename ConcurrencyTag, typename OutputMesh, typename Mesh, typename NamedParameters, typename Progress>
Remeshed_output<OutputMesh> remesh_in_batches(const Mesh& mesh, const NamedParameters& np, const Remeshing_options& options,
                                              const Time_limit& time_limit, const Progress& progress, Remeshing_report& report,
                                              Remeshing_statistics& statistics, bool with_locations)
{
  std::vector<std::size_t> face_component;
  std::vector<std::vector<std::size_t> > components = component_batches(mesh, np, options.batch_faces, face_component);
  if(components.empty())
    return remesh_prepared<ConcurrencyTag, OutputMesh>(mesh, np, options, time_limit, progress, report, statistics, with_locations);

  std::vector<Remeshed_batch<OutputMesh> > batches;
  for(std::size_t b = 0; b < components.size(); ++b)
  {
    const std::string batch_name = "batch " + std::to_string(b + 1) + " of " + std::to_string(components.size()) + ": ";
    const std::function<void(const std::string&)> batch_progress = [&](const std::string& message) { progress(batch_name + message); };
    batches.push_back(remesh_batch<ConcurrencyTag, OutputMesh>(mesh, np, face_component, components[b], options, time_limit,
                                                               batch_progress, report.input, with_locations));
    time_limit.check("remesh_conformal");
  }
  report.component_batches = components.size();
  for(;;)
  {
    std::vector<std::size_t> first_face;
    Remeshed_output<OutputMesh> joined = joined_output(batches, first_face);
    progress("checking the " + std::to_string(batches.size()) + " batches' outputs against each other");
    const std::vector<std::set<std::size_t> > groups = crossing_batches<ConcurrencyTag>(joined.mesh, first_face);
    if(groups.empty())
    {
      for(const Remeshed_batch<OutputMesh>& batch : batches)
      {
        add_batch_report(report, batch.report);
        add_batch_statistics(statistics, batch.statistics);
      }
      return joined;
    }
    // Remesh each group of crossing batches as one batch, in the place of its first.
    std::vector<std::vector<std::size_t> > merged_components;
    std::vector<Remeshed_batch<OutputMesh> > merged_batches;
    std::vector<bool> in_group(batches.size(), false);
    for(const std::set<std::size_t>& group : groups)
      for(std::size_t b : group)
        in_group[b] = true;
    for(std::size_t b = 0; b < batches.size(); ++b)
    {
      const auto group = std::find_if(groups.begin(), groups.end(), [&](const std::set<std::size_t>& g) { return g.count(b) > 0; });
      if(!in_group[b])
      {
        merged_components.push_back(std::move(components[b]));
        merged_batches.push_back(std::move(batches[b]));
      }
      else if(*group->begin() == b)
      {
        std::vector<std::size_t> together;
        for(std::size_t m : *group)
          together.insert(together.end(), components[m].begin(), components[m].end());
        std::sort(together.begin(), together.end());
        progress("the outputs of batches " + std::to_string(*group->begin() + 1) + " and " + std::to_string(*group->rbegin() + 1)
                 + " cross each other: remeshing their " + std::to_string(group->size()) + " batches together");
        report.merged_batches += group->size() - 1;
        const std::function<void(const std::string&)> merged_progress = [&](const std::string& message) {
          progress("merged batch: " + message);
        };
        merged_batches.push_back(remesh_batch<ConcurrencyTag, OutputMesh>(mesh, np, face_component, together, options, time_limit,
                                                                          merged_progress, report.input, with_locations));
        merged_components.push_back(std::move(together));
      }
    }
    components = std::move(merged_components);
    batches = std::move(merged_batches);
  }
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_COMPONENT_BATCHES_H
