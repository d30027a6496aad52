// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first stage of `remesh_conformal()`: the input checked and, where a repair keeps its
// surface, repaired. A valid input (coincident but distinct vertices included) is read as it is
// by the later stages; an input with non-manifold vertices or degenerate faces is copied, and the
// copy repaired by CGAL's Polygon Mesh Processing: `duplicate_non_manifold_vertices()` gives each
// fan of faces around a non-manifold vertex a vertex of its own, and `remove_degenerate_faces()`
// collapses and flips away the faces of zero area. The copy remembers which input face each of
// its faces lies in, so that face data of the input (patches, sharp edges) carry over.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PREPARE_INPUT_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PREPARE_INPUT_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Input_preparation_report.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The input as the later stages read it: the input itself when it needs no repair, else a
/// repaired copy.
struct Prepared_input
{
  typedef CGAL::Surface_mesh<Epick::Point_3> Mesh;

  bool is_copy = false; ///< whether the later stages read `mesh` instead of the input
  Mesh mesh;
  /// for each face of `mesh`, the index (in the input's face index map) of an input face it
  /// overlaps: the face it was copied from, or for a face that a flip made, one of the two
  Mesh::Property_map<Mesh::Face_index, std::size_t> input_face;
};

/// The defects that no repair here removes (see `Mesh_check_report::refused_by_remeshing()`).
inline std::vector<Defect_summary> defects_not_repaired(const Mesh_check_report& checks)
{
  return checks.refused_by_remeshing(true).defects;
}

/// The example that `checks` gives of `defect`, empty if it has none.
inline std::string example_of(const Mesh_check_report& checks, Mesh_defect defect)
{
  for(const Defect_summary& d : checks.defects)
    if(d.defect == defect)
      return d.example;
  return std::string();
}

inline std::string defects_summary(const std::vector<Defect_summary>& defects)
{
  Mesh_check_report report;
  report.defects = defects;
  return report.summary();
}

/// `input` copied with the index of each face's input face.
template <typename TriangleMesh, typename NamedParameters>
Prepared_input copy_of_input(const TriangleMesh& input, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor input_face;
  Prepared_input prepared;
  prepared.is_copy = true;
  prepared.input_face = prepared.mesh.add_property_map<Prepared_input::Mesh::Face_index, std::size_t>("f:input_face", 0).first;
  auto fim = CGAL::get_initialized_face_index_map(input, np);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, input));
  std::vector<std::pair<input_face, Prepared_input::Mesh::Face_index> > face_pairs;
  CGAL::copy_face_graph(input, prepared.mesh,
                        CGAL::parameters::vertex_point_map(vpm).face_to_face_output_iterator(std::back_inserter(face_pairs)));
  for(const auto& pair : face_pairs)
    prepared.input_face[pair.second] = get(fim, pair.first);
  return prepared;
}

/// The prepared input of `remesh_conformal()`, with the repairs in `report`. With `repair`
/// false, non-manifold vertices and degenerate faces are refused instead.
/// \throws Error with `Error_code::INVALID_INPUT` naming the defects that remain.
template <typename TriangleMesh, typename NamedParameters>
Prepared_input prepare_input(const TriangleMesh& input, const NamedParameters& np, bool repair,
                             Input_preparation_report& report)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Mesh_check_report checks = check_mesh(input, np);
  report.coincident_vertices = checks.count(Mesh_defect::DUPLICATED_VERTEX);
  report.coincident_example = example_of(checks, Mesh_defect::DUPLICATED_VERTEX);
  const std::vector<Defect_summary> left = defects_not_repaired(checks);
  if(!left.empty())
    throw Error(Error_code::INVALID_INPUT, "invalid input mesh: " + defects_summary(left));
  const bool needs_repair = checks.count(Mesh_defect::NON_MANIFOLD_VERTEX) > 0 || checks.count(Mesh_defect::DEGENERATE_FACE) > 0;
  if(!needs_repair)
    return Prepared_input();
  if(!repair)
    throw Error(Error_code::INVALID_INPUT, "invalid input mesh: " + checks.summary() + " (the repairs are off)");

  Prepared_input prepared = copy_of_input(input, np);
  Prepared_input::Mesh& mesh = prepared.mesh;
  report.split_non_manifold_vertices = PMP::duplicate_non_manifold_vertices(mesh);
  report.non_manifold_example = example_of(checks, Mesh_defect::NON_MANIFOLD_VERTEX);
  report.degenerate_example = example_of(checks, Mesh_defect::DEGENERATE_FACE);
  PMP::remove_degenerate_faces(mesh); // collapses and flips: the faces of zero area are gone, the count may stay
  mesh.collect_garbage();
  const Mesh_check_report after = check_mesh(mesh);
  std::vector<Defect_summary> remaining = defects_not_repaired(after);
  for(const Defect_summary& d : after.defects)
    if(d.defect == Mesh_defect::NON_MANIFOLD_VERTEX || d.defect == Mesh_defect::DEGENERATE_FACE)
      remaining.push_back(d);
  if(!remaining.empty())
    throw Error(Error_code::INVALID_INPUT, "invalid input mesh: " + defects_summary(remaining) + " after its repairs ("
                                             + report.summary() + ")");
  report.removed_degenerate_faces = checks.count(Mesh_defect::DEGENERATE_FACE); // none is left: checked above
  report.coincident_vertices = after.count(Mesh_defect::DUPLICATED_VERTEX);
  report.coincident_example = example_of(after, Mesh_defect::DUPLICATED_VERTEX);
  return prepared;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PREPARE_INPUT_H
