// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input checks: which defects a mesh or a polygon soup has, and its topology per component.

#ifndef CGAL_CONFORMAL_REMESHING_CHECK_MESH_H
#define CGAL_CONFORMAL_REMESHING_CHECK_MESH_H

#include <CGAL/Conformal_remeshing/internal/soup_defects.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// Topology of one connected component of a manifold, orientable triangle mesh.
struct Component_topology
{
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t boundary_loops = 0;
  /// `vertices - edges + faces`
  long euler_characteristic = 0;
  /// `(2 - euler_characteristic - boundary_loops) / 2`
  long genus = 0;
};

/// \ingroup PkgConformalRemeshingRef
/// What `check_mesh()` and `check_polygon_soup()` found.
///
/// `defects` lists every kind of defect found at least once, in the order of `Mesh_defect`,
/// each with a count and one example element. `components` holds the topology of each connected
/// component; it is filled only when the input is a manifold, orientable polygon mesh
/// (`topology_available`), because the Euler characteristic means nothing otherwise.
struct Mesh_check_report
{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  std::vector<Defect_summary> defects;
  bool topology_available = false;
  std::vector<Component_topology> components;

  /// `true` if no defect was found: a valid, manifold, orientable triangle mesh.
  bool is_valid() const { return defects.empty(); }

  /// `true` if the only defect found, if any, is vertices at the same point as others: a valid,
  /// manifold, orientable triangle mesh whose distinct vertices may share points (two holes that
  /// touch at a corner, a seam whose sides were not merged). Such a mesh is remeshed and
  /// flattened as it is, its coincident vertices kept distinct.
  bool is_manifold_surface() const
  {
    for(const Defect_summary& s : defects)
      if(s.defect != Mesh_defect::DUPLICATED_VERTEX)
        return false;
    return true;
  }

  /// The defects for which `remesh_conformal()` refuses the mesh: all but coincident vertices,
  /// which it takes as distinct points of the surface, and, with `repairs` (its `repair_input`
  /// parameter, on by default), but non-manifold vertices and degenerate faces, which it repairs.
  Mesh_check_report refused_by_remeshing(bool repairs) const
  {
    Mesh_check_report refused = *this;
    refused.defects.clear();
    for(const Defect_summary& s : defects)
      if(s.defect != Mesh_defect::DUPLICATED_VERTEX
         && !(repairs && (s.defect == Mesh_defect::NON_MANIFOLD_VERTEX || s.defect == Mesh_defect::DEGENERATE_FACE)))
        refused.defects.push_back(s);
    return refused;
  }

  /// How many elements have defect `d` (0 if none).
  std::size_t count(Mesh_defect d) const
  {
    for(const Defect_summary& s : defects)
      if(s.defect == d)
        return s.count;
    return 0;
  }

  /// Sum of the genera of all components (meaningful only with `topology_available`).
  long total_genus() const
  {
    long g = 0;
    for(const Component_topology& c : components)
      g += c.genus;
    return g;
  }

  /// Total number of boundary loops over all components.
  std::size_t total_boundary_loops() const
  {
    std::size_t b = 0;
    for(const Component_topology& c : components)
      b += c.boundary_loops;
    return b;
  }

  /// One line: "valid" or the defects, e.g. "2 non-manifold edges (e.g. edge 3-7 shared by 3 faces)".
  std::string summary() const
  {
    if(defects.empty())
      return "valid";
    std::ostringstream out;
    for(std::size_t i = 0; i < defects.size(); ++i)
    {
      if(i > 0)
        out << "; ";
      out << defects[i].count << " " << defect_name(defects[i].defect, defects[i].count)
          << " (e.g. " << defects[i].example << ")";
    }
    return out.str();
  }
};

/// \ingroup PkgConformalRemeshingRef
/// Checks a polygon soup for every defect of `Mesh_defect`.
///
/// This is the check to run on what a file reader returns, before trying to build a halfedge
/// data structure: non-manifold edges, inconsistent orientation and non-orientable input cannot
/// be represented in a `CGAL::Surface_mesh` at all. The returned report has no topology
/// (`topology_available == false`); `check_mesh()` adds it once a mesh could be built.
///
/// Degenerate faces are detected with exact predicates (`Kernel::Collinear_3`).
///
/// \tparam PointRange a random access range of points of `Kernel`
/// \tparam PolygonRange a random access range of ranges of indices into `points`
template <typename Kernel, typename PointRange, typename PolygonRange>
Mesh_check_report check_polygon_soup(const PointRange& points, const PolygonRange& polygons)
{
  Mesh_check_report report;
  report.number_of_vertices = points.size();
  report.number_of_faces = polygons.size();
  report.defects = internal::find_soup_defects<Kernel>(points, polygons);
  return report;
}

namespace internal {

// Euler characteristic and boundary loops of every connected component of a face graph.
template <typename FaceGraph>
std::vector<Component_topology> component_topologies(const FaceGraph& mesh)
{
  typedef typename boost::graph_traits<FaceGraph>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<FaceGraph>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<FaceGraph>::face_descriptor face_descriptor;

  std::unordered_map<face_descriptor, std::size_t> face_component;
  const std::size_t nb_components = Polygon_mesh_processing::connected_components(
    mesh, boost::make_assoc_property_map(face_component));

  std::vector<Component_topology> result(nb_components);
  for(face_descriptor f : faces(mesh))
    ++result[face_component[f]].faces;

  // A vertex belongs to the component of any incident face; isolated vertices belong to none.
  for(vertex_descriptor v : vertices(mesh))
  {
    for(halfedge_descriptor h : halfedges_around_target(v, mesh))
    {
      face_descriptor f = face(h, mesh);
      if(f == boost::graph_traits<FaceGraph>::null_face())
        f = face(opposite(h, mesh), mesh);
      if(f != boost::graph_traits<FaceGraph>::null_face())
      {
        ++result[face_component[f]].vertices;
        break;
      }
    }
  }

  std::unordered_map<halfedge_descriptor, bool> visited_border;
  for(auto e : edges(mesh))
  {
    halfedge_descriptor h = halfedge(e, mesh);
    face_descriptor f = face(h, mesh);
    if(f == boost::graph_traits<FaceGraph>::null_face())
      f = face(opposite(h, mesh), mesh);
    if(f == boost::graph_traits<FaceGraph>::null_face())
      continue; // an edge with no face: not part of a surface component
    ++result[face_component[f]].edges;
  }

  for(halfedge_descriptor h : halfedges(mesh))
  {
    if(!is_border(h, mesh) || visited_border[h])
      continue;
    for(halfedge_descriptor b : halfedges_around_face(h, mesh))
      visited_border[b] = true;
    ++result[face_component[face(opposite(h, mesh), mesh)]].boundary_loops;
  }

  for(Component_topology& c : result)
  {
    c.euler_characteristic = static_cast<long>(c.vertices) - static_cast<long>(c.edges)
                             + static_cast<long>(c.faces);
    c.genus = (2 - c.euler_characteristic - static_cast<long>(c.boundary_loops)) / 2;
  }
  return result;
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Checks a face graph for every defect of `Mesh_defect` that it can hold (empty mesh,
/// non-finite coordinates, non-triangle faces, degenerate faces, duplicated vertices, isolated
/// vertices, non-manifold vertices) and reports the topology of each connected component.
///
/// Degenerate faces are detected with exact predicates of the geometric traits.
///
/// \tparam FaceGraph a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param mesh the mesh to check
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename FaceGraph, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_check_report check_mesh(const FaceGraph& mesh,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetGeomTraits<FaceGraph, NamedParameters>::type Kernel;
  typedef typename boost::graph_traits<FaceGraph>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<FaceGraph>::face_descriptor face_descriptor;

  auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(vertex_point, mesh));

  // The soup view of the mesh lets one implementation serve both entry points.
  std::vector<typename Kernel::Point_3> points;
  std::unordered_map<vertex_descriptor, std::size_t> index;
  points.reserve(num_vertices(mesh));
  for(vertex_descriptor v : vertices(mesh))
  {
    index.emplace(v, points.size());
    points.push_back(get(vpm, v));
  }
  std::vector<std::vector<std::size_t> > polygons;
  polygons.reserve(num_faces(mesh));
  for(face_descriptor f : faces(mesh))
  {
    polygons.emplace_back();
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back(index[v]);
  }

  Mesh_check_report report = check_polygon_soup<Kernel>(points, polygons);

  // A halfedge structure with a pinched vertex has a meaningless Euler characteristic.
  report.topology_available = report.count(Mesh_defect::NON_MANIFOLD_VERTEX) == 0
                              && report.count(Mesh_defect::EMPTY_MESH) == 0;
  if(report.topology_available)
    report.components = internal::component_topologies(mesh);
  return report;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_CHECK_MESH_H
