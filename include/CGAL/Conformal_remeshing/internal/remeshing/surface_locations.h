// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the output vertices of `remesh_conformal()` lie on the input surface: an input face and
// barycentric coordinates for each.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_LOCATIONS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_LOCATIONS_H

#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

// Barycentric coordinates of `p` (on the triangle's plane) in the triangle `t`, from cross
// products, not from the Gram determinant |u|^2 |v|^2 - (u.v)^2, which cancels on CAD slivers. A
// triangle without area gives the point's place on its longest side.
inline std::array<double, 3> barycentric(const Epick::Point_3& p, const std::array<Epick::Point_3, 3>& t)
{
  const Epick::Vector_3 u = t[1] - t[0], v = t[2] - t[0], w = p - t[0];
  const Epick::Vector_3 n = CGAL::cross_product(u, v);
  const double nn = n * n;
  if(nn > 0.)
  {
    const double b1 = (CGAL::cross_product(w, v) * n) / nn, b2 = (CGAL::cross_product(u, w) * n) / nn;
    return {{1. - b1 - b2, b1, b2}};
  }
  int longest = 0; // the side from corner `longest` to the next corner
  double longest_length = -1.;
  for(int c = 0; c < 3; ++c)
  {
    const double l = CGAL::squared_distance(t[c], t[(c + 1) % 3]);
    if(l > longest_length)
    {
      longest = c;
      longest_length = l;
    }
  }
  std::array<double, 3> b{{0., 0., 0.}};
  b[longest] = 1.;
  if(longest_length > 0.)
  {
    const double s = ((p - t[longest]) * (t[(longest + 1) % 3] - t[longest])) / longest_length;
    b[longest] = 1. - s;
    b[(longest + 1) % 3] = s;
  }
  return b;
}


/// The location on `input` of each point of `points`, which lies in the segmented face of the same
/// index in `point_faces` (the segmented faces refine the input's).
template <typename TriangleMesh, typename NamedParameters>
std::vector<Surface_location> surface_locations(const TriangleMesh& input, const NamedParameters& np,
                                                const Poly_annulus_segmentation& segmentation,
                                                const std::vector<Epick::Point_3>& points,
                                                const std::vector<Poly_annulus_segmentation::Face>& point_faces)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto fim = CGAL::get_initialized_face_index_map(input, np);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, input));
  std::vector<std::array<Epick::Point_3, 3> > input_triangle(num_faces(input));
  for(auto f : faces(input))
  {
    int c = 0; // corner order of Polygon_mesh_processing::locate(): from the source of halfedge(f)
    for(auto hf : CGAL::halfedges_around_face(halfedge(f, input), input))
    {
      const auto p = get(vpm, source(hf, input));
      if(c < 3)
        input_triangle[get(fim, f)][c] = Epick::Point_3(p.x(), p.y(), p.z());
      ++c;
    }
  }
  std::vector<Surface_location> locations;
  locations.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const std::size_t f = segmentation.input_face[point_faces[i]];
    locations.push_back(Surface_location{f, barycentric(points[i], input_triangle[f])});
  }
  return locations;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SURFACE_LOCATIONS_H
