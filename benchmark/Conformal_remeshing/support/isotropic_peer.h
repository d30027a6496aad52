// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The peer every remeshing benchmark runs in the same run as remesh_conformal(): CGAL's
// isotropic_remeshing() at the same target edge length, 5 iterations, with the sharp edges and
// the borders constrained (the set-up of DESIGN.md's reference figures).

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_ISOTROPIC_PEER_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_ISOTROPIC_PEER_H

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// The peer's feature angle (degrees) and number of iterations.
constexpr double isotropic_peer_features_angle = 60.;
constexpr unsigned int isotropic_peer_iterations = 5;

/// Marks the edges the peer keeps: sharp edges (dihedral angle above the feature angle) and
/// borders. Returns the property map (added to `mesh`) holding the marks.
template <typename Point_3>
typename CGAL::Surface_mesh<Point_3>::template Property_map<typename CGAL::Surface_mesh<Point_3>::Edge_index, bool>
constrain_sharp_edges_and_borders(CGAL::Surface_mesh<Point_3>& mesh)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  auto constrained = mesh.template add_property_map<typename Mesh::Edge_index, bool>("e:peer_constrained", false).first;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, isotropic_peer_features_angle, constrained);
  for(auto e : mesh.edges())
    if(mesh.is_border(e))
      constrained[e] = true;
  return constrained;
}

/// Remeshes `mesh` in place at target length `h` with the edges marked by
/// `constrain_sharp_edges_and_borders()` kept.
template <typename Point_3, typename EdgeIsConstrainedMap>
void remesh_isotropically(CGAL::Surface_mesh<Point_3>& mesh, double h, EdgeIsConstrainedMap constrained)
{
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
    faces(mesh), h, mesh,
    CGAL::parameters::number_of_iterations(isotropic_peer_iterations).edge_is_constrained_map(constrained));
  mesh.collect_garbage(); // the removed elements would still count in num_vertices() and the like
}

/// Both steps: what the benchmarks time as the peer.
template <typename Point_3>
void run_isotropic_peer(CGAL::Surface_mesh<Point_3>& mesh, double h)
{
  remesh_isotropically(mesh, h, constrain_sharp_edges_and_borders(mesh));
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_ISOTROPIC_PEER_H
