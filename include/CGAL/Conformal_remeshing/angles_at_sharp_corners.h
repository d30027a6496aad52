// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which small angles of a remeshing the input forces: a triangle whose smallest angle sits at a
// corner of the input narrower than the angle cannot be better, whatever the remesher.

#ifndef CGAL_CONFORMAL_REMESHING_ANGLES_AT_SHARP_CORNERS_H
#define CGAL_CONFORMAL_REMESHING_ANGLES_AT_SHARP_CORNERS_H

#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Conformal_remeshing/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// The triangles of a mesh whose smallest angle is below a threshold, and how many of them have
/// that angle at a sharp corner of a reference surface (see `angles_at_sharp_corners()`).
struct Sharp_corner_angles
{
  double threshold_degrees = 25.;
  /// corners of the reference narrower than the threshold
  std::size_t sharp_corners = 0;
  std::size_t triangles = 0;
  /// triangles whose smallest angle is below the threshold
  std::size_t triangles_below = 0;
  /// of those, the triangles whose smallest angle is at a sharp corner of the reference
  std::size_t triangles_below_at_sharp_corners = 0;

  /// the fraction of the triangles whose smallest angle is below the threshold
  double share_below() const { return triangles > 0 ? double(triangles_below) / double(triangles) : 0.; }
  /// the fraction of the triangles whose smallest angle is below the threshold elsewhere than at
  /// a sharp corner of the reference
  double share_below_away_from_sharp_corners() const
  {
    return triangles > 0 ? double(triangles_below - triangles_below_at_sharp_corners) / double(triangles) : 0.;
  }
};

namespace internal {

/// The faces around one vertex of a reference surface, and whether each lies in a sector
/// narrower than the threshold.
struct Corner_sectors
{
  std::vector<Epick::Triangle_3> faces;
  std::vector<bool> in_sharp_sector;
  std::size_t sharp_sectors = 0;
};

template <typename Point>
Epick::Point_3 epick_point(const Point& p)
{
  return Epick::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

/// The corners of `reference` with a sector narrower than `threshold_degrees`, keyed by their
/// point. The sectors of a vertex are the fans of its faces between consecutive curve edges
/// (border edges, and edges whose faces' normals turn by more than `features_angle_degrees`); a
/// sector's angle is the sum of its faces' angles at the vertex. A vertex on no curve is one
/// sector, sharp when its whole angle sum is narrower (the tip of a needle).
template <typename ReferenceMesh, typename VertexPointMap>
std::map<Epick::Point_3, Corner_sectors> sharp_corner_sectors(const ReferenceMesh& reference, const VertexPointMap& vpm,
                                                              double threshold_degrees, double features_angle_degrees)
{
  using halfedge_descriptor = typename boost::graph_traits<ReferenceMesh>::halfedge_descriptor;
  const auto point = [&](auto v) { return epick_point(get(vpm, v)); };
  const auto triangle = [&](halfedge_descriptor h) {
    return Epick::Triangle_3(point(source(h, reference)), point(target(h, reference)),
                             point(target(next(h, reference), reference)));
  };
  // Not `detect_sharp_edges()`: it takes the edges of zero-area faces for sharp, and a
  // degenerate face of an input (which the remesher's repairs remove) is no corner.
  const double cosine_of_features = std::cos(features_angle_degrees * CGAL_PI / 180.);
  const auto is_curve = [&](halfedge_descriptor h) {
    if(is_border_edge(h, reference))
      return true;
    const Epick::Vector_3 a = triangle(h).supporting_plane().orthogonal_vector();
    const Epick::Vector_3 b = triangle(opposite(h, reference)).supporting_plane().orthogonal_vector();
    const double norms = std::sqrt(a.squared_length() * b.squared_length());
    return features_angle_degrees > 0. && norms > 0. && a * b < cosine_of_features * norms;
  };
  // The angle at the target of `h` in its face.
  const auto angle_at_target = [&](halfedge_descriptor h) {
    const Epick::Point_3 c = point(target(h, reference));
    const Epick::Vector_3 u = point(source(h, reference)) - c, w = point(target(next(h, reference), reference)) - c;
    return std::atan2(std::sqrt(CGAL::cross_product(u, w).squared_length()), u * w) * 180. / CGAL_PI;
  };

  std::map<Epick::Point_3, Corner_sectors> corners;
  for(auto v : vertices(reference))
  {
    if(halfedge(v, reference) == boost::graph_traits<ReferenceMesh>::null_halfedge())
      continue;
    // The halfedges into v in turning order; face(h) lies between edge(h) and the next one's edge.
    std::vector<halfedge_descriptor> around;
    for(auto h : halfedges_around_target(halfedge(v, reference), reference))
      around.push_back(h);
    std::vector<char> curve(around.size());
    std::transform(around.begin(), around.end(), curve.begin(), is_curve);
    const std::size_t first_curve = std::size_t(std::find(curve.begin(), curve.end(), 1) - curve.begin()) % around.size();
    std::rotate(around.begin(), around.begin() + std::ptrdiff_t(first_curve), around.end());
    std::rotate(curve.begin(), curve.begin() + std::ptrdiff_t(first_curve), curve.end());

    Corner_sectors sectors;
    std::size_t start = 0;
    double angle = 0.;
    for(std::size_t i = 0; i <= around.size(); ++i)
    {
      const bool sector_ends = (i == around.size()) || (i > 0 && curve[i]);
      if(sector_ends)
      {
        const bool narrow = i > start && angle < threshold_degrees;
        for(std::size_t k = start; k < i; ++k)
          sectors.in_sharp_sector[sectors.in_sharp_sector.size() - (i - k)] = narrow;
        sectors.sharp_sectors += narrow;
        start = i;
        angle = 0.;
      }
      if(i == around.size() || is_border(around[i], reference))
      {
        start = i + 1; // the hole is no sector
        continue;
      }
      sectors.faces.push_back(triangle(around[i]));
      sectors.in_sharp_sector.push_back(false);
      angle += angle_at_target(around[i]);
    }
    if(sectors.sharp_sectors > 0)
      corners.emplace(point(v), std::move(sectors));
  }
  return corners;
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Counts the triangles of `mesh` whose smallest angle is below `threshold_degrees`, and among
/// them those whose smallest angle is at a sharp corner of `reference` (the surface `mesh`
/// remeshes): a triangle whose smallest angle is at a vertex of `mesh` at the very point of a
/// vertex of `reference`, inside a sector of that vertex narrower than the threshold. The sectors
/// of a vertex are the fans of its faces between consecutive sharp edges or borders (edges whose
/// faces' normals turn by more than the features angle), each as wide as the sum of its faces'
/// angles at the vertex; the triangle lies in the sector of the reference face closest to its
/// centroid. No remeshing that keeps such a corner can have its triangles there above the
/// threshold, so quality goals are stated away from them ("at least 99% of the triangles above
/// 25 degrees, except at input corners sharper than that").
///
/// \tparam TriangleMesh, ReferenceMesh models of `FaceListGraph` and `HalfedgeListGraph` with an
///         internal point property map
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{features_angle}
///     \cgalParamDescription{the dihedral angle in degrees above which an edge of `reference` is sharp (`Conformal_remeshing::parameters::features_angle()`; 0 or less: only borders)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60, as in `remesh_conformal()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Error with `Error_code::INVALID_INPUT` if `mesh` or `reference` has a face that is
///         not a triangle.
template <typename TriangleMesh, typename ReferenceMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Sharp_corner_angles angles_at_sharp_corners(const TriangleMesh& mesh, const ReferenceMesh& reference,
                                            double threshold_degrees = 25.,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!is_triangle_mesh(mesh) || !is_triangle_mesh(reference))
    throw Error(Error_code::INVALID_INPUT, "angles_at_sharp_corners() needs triangle meshes");
  const double features_angle =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::features_angle), 60.);
  const auto corners =
    internal::sharp_corner_sectors(reference, get(CGAL::vertex_point, reference), threshold_degrees, features_angle);

  Sharp_corner_angles result;
  result.threshold_degrees = threshold_degrees;
  for(const auto& corner : corners)
    result.sharp_corners += corner.second.sharp_sectors;

  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto f : faces(mesh))
  {
    ++result.triangles;
    const auto h = halfedge(f, mesh);
    const std::array<Epick::Point_3, 3> p{{internal::epick_point(get(vpm, source(h, mesh))),
                                           internal::epick_point(get(vpm, target(h, mesh))),
                                           internal::epick_point(get(vpm, target(next(h, mesh), mesh)))}};
    const Triangle_quality t = triangle_quality(p[0], p[1], p[2]);
    const std::size_t smallest = std::size_t(std::min_element(t.angles.begin(), t.angles.end()) - t.angles.begin());
    if(!(t.angles[smallest] < threshold_degrees))
      continue;
    ++result.triangles_below;
    const auto corner = corners.find(p[smallest]);
    if(corner == corners.end())
      continue;
    const Epick::Point_3 centroid = CGAL::centroid(p[0], p[1], p[2]);
    const auto& sectors = corner->second;
    std::size_t closest = 0;
    double closest_distance = std::numeric_limits<double>::infinity();
    for(std::size_t k = 0; k < sectors.faces.size(); ++k)
    {
      const double d = CGAL::squared_distance(centroid, sectors.faces[k]);
      if(d < closest_distance)
        closest = k, closest_distance = d;
    }
    result.triangles_below_at_sharp_corners += sectors.in_sharp_sector[closest];
  }
  return result;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_ANGLES_AT_SHARP_CORNERS_H
