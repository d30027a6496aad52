// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stages of `remesh_conformal()` after the input's preparation (prepare_input.h), on the
// input itself or on its repaired copy: segmentation and flattening, meshing and gluing, and the
// place of each output vertex on the surface they read. For a copy, the input's named
// parameters are carried over to it (its points, face indices, patches and sharp edges), and the
// places are found on the input again.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_REMESH_PREPARED_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_REMESH_PREPARED_H

#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/mesh_and_glue.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/prepare_input.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/remeshing_options.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/segment_and_flatten.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/surface_locations.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// The output mesh, the points of its vertices and, when asked for, their places on the surface
/// that was remeshed.
template <typename TriangleMesh>
struct Remeshed_output
{
  TriangleMesh mesh;
  std::vector<Epick::Point_3> points;
  std::vector<Surface_location> locations;
};

/// The stages after the preparation, on `mesh` (the input or its repaired copy) with its named
/// parameters `np`.
template <typename ConcurrencyTag, typename OutputMesh, typename Mesh, typename NamedParameters, typename Progress>
Remeshed_output<OutputMesh> remesh_prepared(const Mesh& mesh, const NamedParameters& np, const Remeshing_options& options,
                                            const Time_limit& time_limit, const Progress& progress, Remeshing_report& report,
                                            Remeshing_statistics& statistics, bool with_locations)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Flattened_surface flattened;
  segment_and_flatten<ConcurrencyTag>(mesh, options, np, time_limit, progress, report, statistics, flattened);
  const Flattened_surface& surface = flattened; // read, never changed, from here on

  // Asked only when the output intersects itself, once.
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  int intersects = -1; // not known yet
  const std::function<bool()> input_self_intersects = [&]() {
    if(intersects < 0)
      intersects = has_crossing_faces<ConcurrencyTag>(mesh, CGAL::parameters::vertex_point_map(vpm));
    return intersects == 1;
  };
  Glued_output<OutputMesh> glued =
    mesh_and_glue_with_fallback<ConcurrencyTag, OutputMesh>(surface, options, input_self_intersects, time_limit, progress, report, statistics);

  report.input_crosses_itself = intersects == 1;
  Remeshed_output<OutputMesh> result;
  if(with_locations)
    result.locations = surface_locations(mesh, np, surface.segmentation, glued.vertex_points, glued.vertex_faces);
  result.mesh = std::move(glued.mesh);
  result.points = std::move(glued.vertex_points);
  return result;
}

/// The input's named parameters for its repaired copy: the copy's points and face indices, and
/// the input's patches (`face_patch_map`) and sharp edges (`edge_is_constrained_map`), when
/// given, carried over to the copy's faces and edges.
template <typename TriangleMesh, typename NamedParameters>
auto parameters_of_copy(Prepared_input& prepared, const TriangleMesh& input, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Prepared_input::Mesh Mesh;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor input_face;
  Mesh& mesh = prepared.mesh;
  const auto with_maps = np.vertex_point_map(get(CGAL::vertex_point, mesh)).face_index_map(get(CGAL::face_index, mesh));

  const auto user_patches = get_parameter(np, CGAL::internal_np::face_patch);
  constexpr bool has_patches = !std::is_same<std::decay_t<decltype(user_patches)>, CGAL::internal_np::Param_not_found>::value;
  const auto given_features = get_parameter(np, CGAL::internal_np::edge_is_constrained);
  constexpr bool has_features = !std::is_same<std::decay_t<decltype(given_features)>, CGAL::internal_np::Param_not_found>::value;

  const auto copied_patches = [&]() {
    if constexpr(has_patches)
    {
      typedef typename boost::property_traits<std::decay_t<decltype(user_patches)> >::value_type Patch_id;
      auto fim = CGAL::get_initialized_face_index_map(input, np);
      std::vector<input_face> by_index(num_faces(input));
      for(input_face f : faces(input))
        by_index[get(fim, f)] = f;
      auto copied = mesh.template add_property_map<Mesh::Face_index, Patch_id>("f:copied_patch").first;
      for(Mesh::Face_index f : mesh.faces())
        copied[f] = get(user_patches, by_index[prepared.input_face[f]]);
      return copied;
    }
    else
      return 0;
  };
  const auto copied_features = [&]() {
    if constexpr(has_features)
    {
      auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, input));
      std::map<std::pair<Epick::Point_3, Epick::Point_3>, bool> sharp;
      for(auto e : edges(input))
        if(get(given_features, e))
        {
          const auto a = get(vpm, source(e, input)), b = get(vpm, target(e, input));
          sharp[std::minmax(Epick::Point_3(a.x(), a.y(), a.z()), Epick::Point_3(b.x(), b.y(), b.z()))] = true;
        }
      auto copied = mesh.template add_property_map<Mesh::Edge_index, bool>("e:copied_feature", false).first;
      for(Mesh::Edge_index e : mesh.edges())
        copied[e] = sharp.count(std::minmax(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1)))) > 0;
      return copied;
    }
    else
      return 0;
  };
  if constexpr(has_patches && has_features)
    return with_maps.face_patch_map(copied_patches()).edge_is_constrained_map(copied_features());
  else if constexpr(has_patches)
    return with_maps.face_patch_map(copied_patches());
  else if constexpr(has_features)
    return with_maps.edge_is_constrained_map(copied_features());
  else
    return with_maps;
}

/// The place on `input` of each of `points`, points of its repaired copy: the nearest point of
/// the input surface (the repairs collapse only edges of no length or of zero-area faces), in
/// barycentric coordinates that `barycentric()` computes also in faces of zero area.
template <typename TriangleMesh, typename NamedParameters>
std::vector<Surface_location> locate_on_input(const TriangleMesh& input, const NamedParameters& np,
                                              const std::vector<Epick::Point_3>& points)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, input));
  auto fim = CGAL::get_initialized_face_index_map(input, np);
  typedef decltype(vpm) Vpm;
  typedef typename boost::property_traits<Vpm>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, Vpm> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  const Tree tree(faces(input).first, faces(input).second, input, vpm);
  std::vector<Surface_location> locations;
  locations.reserve(points.size());
  for(const Epick::Point_3& p : points)
  {
    const auto face = tree.closest_point_and_primitive(Point(p.x(), p.y(), p.z())).second;
    std::array<Epick::Point_3, 3> corners;
    int c = 0; // corner order of Polygon_mesh_processing::locate(): from the source of halfedge(f)
    for(auto h : CGAL::halfedges_around_face(halfedge(face, input), input))
      if(c < 3)
      {
        const auto q = get(vpm, source(h, input));
        corners[c++] = Epick::Point_3(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
      }
    locations.push_back(Surface_location{std::size_t(get(fim, face)), barycentric(p, corners)});
  }
  return locations;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_REMESH_PREPARED_H
