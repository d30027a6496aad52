// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's entry point: remeshing a surface by conformal flattening, planar Delaunay
// refinement and pull-back onto the input surface.

#ifndef CGAL_REMESH_CONFORMAL_H
#define CGAL_REMESH_CONFORMAL_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_locator.h>
#include <CGAL/Conformal_remeshing/internal/named_parameters.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_mesher.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

// Named parameters of `remesh_conformal()` (see its documentation): `target_edge_length(l)`,
// `relative_target_edge_length(r)` (default 0.01 of the bounding-box diagonal),
// `minimum_angle(degrees)` (default 28), `corner_angle(degrees)` (default 30) and
// `smoothing_iterations(n)` (default 3).
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(target_edge_length)
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(relative_target_edge_length)
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(minimum_angle)
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(corner_angle)
CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(smoothing_iterations)

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// What `remesh_conformal()` did.
struct Remeshing_report
{
  Flattening_report flattening;
  double target_edge_length = 0.;
  std::size_t boundary_samples = 0;
  std::size_t output_vertices = 0;
  std::size_t output_faces = 0;
  /// output vertices whose planar position fell outside the flat patch (between a boundary
  /// chord and the boundary polyline) and were clamped onto the nearest patch triangle
  std::size_t clamped_vertices = 0;
  double seconds_checks_and_flattening = 0., seconds_planar_meshing = 0., seconds_pull_back = 0.;
};

/// \ingroup PkgConformalRemeshingRef
/// Where an output vertex lies on the input surface: an input face and barycentric coordinates
/// (corner order of `CGAL::Polygon_mesh_processing::locate()`).
struct Surface_location
{
  std::size_t input_face = 0;
  std::array<double, 3> coordinates{{0., 0., 0.}};
};

/// \ingroup PkgConformalRemeshingRef
/// Remeshes the triangle mesh `input` into `output` by conformal flattening (paper Sec. 4):
/// `conformal_flatten()` maps the surface onto a planar domain with no overlap, the domain's
/// boundary loops are resampled on the input boundary at the target edge length, CGAL's
/// constrained Delaunay refinement meshes the domain with a minimum angle bound and a size bound
/// in 3D units (the planar size is the target length times the local scale of the map), and every
/// planar vertex is carried back onto the input surface through the flow's bijective
/// correspondence (no projection).
///
/// For now `input` must be a genus-0 patch with at least one boundary loop; other inputs raise
/// an `Error` with `Error_code::INVALID_INPUT` until segmentation lands.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal point property map
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_edge_length}
///     \cgalParamDescription{the target edge length in the units of the input (`Conformal_remeshing::parameters::target_edge_length()`)}
///     \cgalParamDefault{1% of the bounding-box diagonal}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_target_edge_length}
///     \cgalParamDescription{the target edge length as a fraction of the bounding-box diagonal}
///     \cgalParamDefault{0.01}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_angle}
///     \cgalParamDescription{the minimum angle of the planar refinement in degrees}
///     \cgalParamDefault{28}
///   \cgalParamNEnd
///   \cgalParamNBegin{corner_angle}
///     \cgalParamDescription{boundary vertices turning by more than this (degrees) are kept}
///     \cgalParamDefault{30}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_iterations}
///     \cgalParamDescription{passes of Laplacian smoothing in the plane}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// The parameters of `conformal_flatten()` are passed on to it.
///
/// \param input the mesh to remesh
/// \param output receives the new mesh (cleared first)
/// \param np the named parameters above
/// \param locations if not null, receives the input face and barycentric coordinates of every
///        output vertex, in the order of `vertices(output)`.
/// \returns what happened, with times per stage
/// \throws Error on invalid input and when the flattening fails (the message says why).
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Remeshing_report remesh_conformal(const TriangleMesh& input, TriangleMesh& output,
                                  const NamedParameters& np = CGAL::parameters::default_values(),
                                  std::vector<Surface_location>* locations = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  Remeshing_report report;

  Clock::time_point start = Clock::now();
  const CGAL::Bbox_3 box = Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                    + CGAL::square(box.zmax() - box.zmin()));
  const double relative = choose_parameter(get_parameter(np, internal_np::relative_target_edge_length), 0.01);
  const double h = choose_parameter(get_parameter(np, internal_np::target_edge_length), relative * diagonal);
  const double min_angle = choose_parameter(get_parameter(np, internal_np::minimum_angle), 28.);
  if(!(h > 0.) || !std::isfinite(h))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the target edge length must be positive");
  if(!(min_angle > 0. && min_angle <= 34.))
    throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the minimum angle must be in (0, 34] degrees "
                                           "(Delaunay refinement does not terminate far beyond 30)");
  report.target_edge_length = h;

  // Input edges longer than twice the target are split first: in a longer triangle the affine
  // map cannot follow the conformal factor, and pulled-back triangles shear (CAD slivers).
  const Conformal_flattening flat = conformal_flatten(input, parameters::maximum_edge_length(2. * h, np));
  report.flattening = flat.report;
  if(flat.report.status != Error_code::SUCCESS)
    throw Error(flat.report.status, std::string("remesh_conformal: the flattening failed: ") + error_message(flat.report.status)
                                      + " (" + flat.report.embedding.summary() + ")");
  report.seconds_checks_and_flattening = seconds_since(start);

  // --- the size field: the target length times the map's local scale -------------------------
  start = Clock::now();
  const internal::remeshing::Planar_locator locator(flat.layout, flat.triangles);
  std::vector<double> vertex_scale(flat.layout.size(), 0.), vertex_weight(flat.layout.size(), 0.);
  for(std::size_t t = 0; t < flat.triangles.size(); ++t)
  {
    std::array<Epick::Point_3, 3> corner;
    for(int c = 0; c < 3; ++c)
    {
      std::array<double, 3> b{{0., 0., 0.}};
      b[c] = 1.;
      corner[c] = flat.to_surface(t, b).point;
    }
    double planar = 0., spatial = 0.;
    for(int c = 0; c < 3; ++c)
    {
      planar += std::sqrt(CGAL::squared_distance(flat.layout[flat.triangles[t][c]], flat.layout[flat.triangles[t][(c + 1) % 3]]));
      spatial += std::sqrt(CGAL::squared_distance(corner[c], corner[(c + 1) % 3]));
    }
    for(int c = 0; c < 3; ++c)
    {
      vertex_scale[flat.triangles[t][c]] += planar / spatial;
      vertex_weight[flat.triangles[t][c]] += 1.;
    }
  }
  for(std::size_t v = 0; v < vertex_scale.size(); ++v)
    if(vertex_weight[v] > 0.)
      vertex_scale[v] /= vertex_weight[v];
  const std::function<double(const Epick::Point_2&)> planar_size = [&](const Epick::Point_2& p) {
    const internal::remeshing::Planar_locator::Location l = locator.locate(p);
    double s = 0.;
    for(int c = 0; c < 3; ++c)
      s += l.coordinates[c] * vertex_scale[flat.triangles[l.triangle][c]];
    // The refinement bounds the longest edge of a triangle; 1.4 h leaves edges near h on average.
    return 1.4 * h * s;
  };

  // --- planar meshing --------------------------------------------------------------------------
  const double corner = choose_parameter(get_parameter(np, internal_np::corner_angle), 30.);
  std::vector<std::vector<internal::remeshing::Boundary_sample> > loops;
  loops.push_back(internal::remeshing::resample_loop(flat.outer_boundary, h, corner));
  for(const auto& hole : flat.holes)
    loops.push_back(internal::remeshing::resample_loop(hole, h, corner));
  const internal::remeshing::Planar_mesh planar = internal::remeshing::mesh_planar_domain<Epick>(
    loops, min_angle, planar_size, choose_parameter(get_parameter(np, internal_np::smoothing_iterations), 3));
  report.boundary_samples = planar.number_of_samples;
  report.seconds_planar_meshing = seconds_since(start);

  // --- pull-back ------------------------------------------------------------------------------
  start = Clock::now();
  std::vector<Epick::Point_3> boundary_point;
  for(const auto& loop : loops)
    for(const auto& s : loop)
      boundary_point.push_back(s.point);
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  auto vpm = get(CGAL::vertex_point, output);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Output_point;
  clear(output);
  std::vector<vertex_descriptor> vertex;
  vertex.reserve(planar.points.size());
  if(locations != nullptr)
    locations->clear();
  for(std::size_t i = 0; i < planar.points.size(); ++i)
  {
    const internal::remeshing::Planar_locator::Location l = locator.locate(planar.points[i]);
    const Domain_point q = flat.to_surface(l.triangle, l.coordinates);
    if((std::min)({l.coordinates[0], l.coordinates[1], l.coordinates[2]}) == 0. && i >= planar.number_of_samples)
      ++report.clamped_vertices;
    // Boundary samples keep their exact place on the input boundary edges.
    const Epick::Point_3 p = i < boundary_point.size() ? boundary_point[i] : q.point;
    vertex.push_back(add_vertex(output));
    put(vpm, vertex.back(), Output_point(p.x(), p.y(), p.z()));
    if(locations != nullptr)
      locations->push_back(Surface_location{q.input_face, q.input_coordinates});
  }
  for(const auto& t : planar.triangles)
  {
    const std::array<vertex_descriptor, 3> corners{{vertex[t[0]], vertex[t[1]], vertex[t[2]]}};
    if(CGAL::Euler::add_face(corners, output) == boost::graph_traits<TriangleMesh>::null_face())
      throw Error(Error_code::INVALID_INPUT, "remesh_conformal: the planar mesh could not be assembled (internal error)");
  }
  report.output_vertices = num_vertices(output);
  report.output_faces = num_faces(output);
  report.seconds_pull_back = seconds_since(start);
  return report;
}

/// \ingroup PkgConformalRemeshingRef
/// Remeshes `mesh` in place, like `CGAL::Polygon_mesh_processing::isotropic_remeshing()`; see the
/// other overload for the parameters.
template <typename TriangleMesh, typename T, typename Tag, typename Base>
Remeshing_report remesh_conformal(TriangleMesh& mesh, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  TriangleMesh output;
  const Remeshing_report report = remesh_conformal(static_cast<const TriangleMesh&>(mesh), output, np);
  mesh = std::move(output);
  return report;
}

/// \ingroup PkgConformalRemeshingRef
/// Remeshes `mesh` in place with the default parameters.
template <typename TriangleMesh>
Remeshing_report remesh_conformal(TriangleMesh& mesh)
{
  return remesh_conformal(mesh, CGAL::parameters::default_values());
}

} // namespace Conformal_remeshing

using Conformal_remeshing::remesh_conformal;

} // namespace CGAL

#endif // CGAL_REMESH_CONFORMAL_H
