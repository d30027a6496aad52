// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where a mesh strays from a reference surface: the largest distance from each face of the mesh
// to the reference and from each face of the reference to the mesh. The Hausdorff distance says
// how far; these say where, so that a lost feature (a cut-off chamfer, a small boss rounded away)
// can be seen on a colour map and counted in a histogram.

#ifndef CGAL_CONFORMAL_REMESHING_FACE_DEVIATIONS_H
#define CGAL_CONFORMAL_REMESHING_FACE_DEVIATIONS_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// The deviation of each face of a mesh from a reference surface and of each face of the
/// reference from the mesh, as `face_deviations()` measures them.
struct Face_deviations
{
  /// the length of the reference's bounding-box diagonal
  double reference_diagonal = 0.;
  /// for each face of the mesh, in the order of `faces(mesh)`: the largest distance from its
  /// points to the reference
  std::vector<double> of_mesh_faces;
  /// for each face of the reference, in the order of `faces(reference)`: the largest distance
  /// from its points to the mesh
  std::vector<double> of_reference_faces;

  /// The largest of `of_mesh_faces` (0 without faces).
  double largest_of_mesh() const { return largest(of_mesh_faces); }
  /// The largest of `of_reference_faces` (0 without faces).
  double largest_of_reference() const { return largest(of_reference_faces); }

private:
  static double largest(const std::vector<double>& d) { return d.empty() ? 0. : *std::max_element(d.begin(), d.end()); }
};

/// \ingroup PkgConformalRemeshingRef
/// The share of `deviations` in each bin of the histogram whose bins end at `upper_bounds`
/// (increasing): bin `i` holds the deviations in `[upper_bounds[i-1], upper_bounds[i])`, the
/// first those below `upper_bounds[0]`, and one more bin at the end those at or above the last
/// bound. The shares add up to 1 (all 0 without deviations).
inline std::vector<double> deviation_histogram(const std::vector<double>& deviations, const std::vector<double>& upper_bounds)
{
  std::vector<double> share(upper_bounds.size() + 1, 0.);
  for(double d : deviations)
    share[std::size_t(std::upper_bound(upper_bounds.begin(), upper_bounds.end(), d) - upper_bounds.begin())] += 1.;
  for(double& s : share)
    s = deviations.empty() ? 0. : s / double(deviations.size());
  return share;
}

namespace internal {

/// Points on each face of `mesh` at about `spacing` from each other, where each is, and the
/// triangle of each face (its longest edge first): rows parallel to the face's longest edge, from that
/// edge to the opposite corner, at most `spacing` apart, each row's points at most `spacing` apart
/// (the corners and the longest edge included). A long CAD sliver gets points along its length,
/// not across it, so the count follows the area and the edges' length, not the tessellation.
template <typename TriangleMesh>
void face_points(const TriangleMesh& mesh, double spacing, std::vector<CGAL::Simple_cartesian<double>::Point_3>& points,
                 std::vector<Face_sample>& where, std::vector<std::array<CGAL::Simple_cartesian<double>::Point_3, 3> >& triangles)
{
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  const auto vpm = get(CGAL::vertex_point, mesh);
  constexpr double most_intervals = 256.;
  const auto intervals = [&](double length) { return (std::min)(most_intervals, (std::max)(1., std::ceil(length / spacing))); };
  std::size_t f = 0;
  for(auto face : faces(mesh))
  {
    std::array<Point, 3> c;
    auto h = halfedge(face, mesh);
    for(int k = 0; k < 3; ++k, h = next(h, mesh))
    {
      const auto& p = get(vpm, target(h, mesh));
      c[k] = Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    int longest = 0; // the longest edge runs from corner `longest` to the next
    for(int k = 1; k < 3; ++k)
      if(CGAL::squared_distance(c[k], c[(k + 1) % 3]) > CGAL::squared_distance(c[longest], c[(longest + 1) % 3]))
        longest = k;
    triangles.push_back({c[longest], c[(longest + 1) % 3], c[(longest + 2) % 3]});
    const Point &a = triangles.back()[0], &b = triangles.back()[1], &apex = triangles.back()[2];
    const double base = std::sqrt(CGAL::squared_distance(a, b));
    const double height = base > 0. ? 2. * std::sqrt(CGAL::squared_area(a, b, apex)) / base : 0.;
    const double rows = intervals(height);
    for(double r = 0.; r <= rows; r += 1.)
    {
      const double t = r / rows, along = intervals((1. - t) * base);
      for(double k = 0.; k <= (r < rows ? along : 0.); k += 1.)
      {
        where.push_back(Face_sample{f, (1. - t) * (k / along), t});
        points.push_back(point_at(triangles.back(), where.back().u, where.back().w));
      }
    }
    ++f;
  }
}

/// The faces whose deviation is searched further, from their farthest point (see
/// `farthest_point_near()`): those at least this share of the largest, at most
/// `refined_faces` of them. Points `spacing` apart find a face's farthest point to within the
/// spacing times the slope of the distance, which across a crease is up to a fifth of the largest.
constexpr double refined_share_of_largest = 0.5;
constexpr std::size_t refined_faces = 4096;

/// The largest distance from the points of each face of `mesh` (see `face_points()`) to
/// `reference`, the faces farthest off searched further.
template <typename Concurrency_tag, typename TriangleMesh>
std::vector<double> largest_distance_per_face(const TriangleMesh& mesh, const TriangleMesh& reference, double spacing)
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<Face_sample> where;
  std::vector<std::array<CGAL::Simple_cartesian<double>::Point_3, 3> > triangles;
  face_points(mesh, spacing, points, where, triangles);
  const Distance_to_surface distance(reference, Concurrency_tag());
  const std::vector<double> squared = distance.squared_distances<Concurrency_tag>(points);
  std::vector<double> largest(triangles.size(), 0.);
  std::vector<std::size_t> farthest_point(triangles.size(), 0);
  for(std::size_t i = 0; i < points.size(); ++i)
    if(squared[i] >= largest[where[i].triangle])
    {
      largest[where[i].triangle] = squared[i];
      farthest_point[where[i].triangle] = i;
    }
  std::vector<std::size_t> far_off(triangles.size());
  std::iota(far_off.begin(), far_off.end(), std::size_t(0));
  const auto farther = [&](std::size_t f, std::size_t g) { return largest[f] > largest[g]; };
  const std::size_t searched = (std::min)(refined_faces, far_off.size());
  std::partial_sort(far_off.begin(), far_off.begin() + searched, far_off.end(), farther);
  far_off.resize(searched);
  const double bound = far_off.empty() ? 0. : CGAL::square(refined_share_of_largest) * largest[far_off.front()];
  far_off.erase(std::find_if(far_off.begin(), far_off.end(), [&](std::size_t f) { return largest[f] < bound; }), far_off.end());
  for_each_index<Concurrency_tag>(far_off.size(), [&](std::size_t i) {
    const std::size_t f = far_off[i];
    const Face_sample& start = where[farthest_point[f]];
    largest[f] = (std::max)(largest[f], farthest_point_near(distance.tree(), triangles[f], start.u, start.w).first);
  });
  for(double& d : largest)
    d = std::sqrt(d);
  return largest;
}

/// The median edge length of `mesh`.
template <typename TriangleMesh>
double median_edge_length(const TriangleMesh& mesh)
{
  std::vector<double> lengths = edge_lengths(mesh, get(CGAL::vertex_point, mesh));
  if(lengths.empty())
    return 0.;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Measures, for each face of `mesh`, the largest distance from its points to `reference`, and
/// for each face of `reference` the largest distance from its points to `mesh`.
///
/// The points of a face are its corners and points on it and on its edges at most a quarter of
/// the mesh's median edge length apart (up to 256 intervals along a side), and on the faces
/// farthest off, the search goes on from their farthest point to a local maximum of the distance. The largest of them all, over the mesh
/// and over the reference, approximates the Hausdorff distance both ways, as
/// `compare_to_reference()` does by random samples.
///
/// \throws Error with `Error_code::INVALID_INPUT` if a mesh is empty or not a triangle mesh.
template <typename Concurrency_tag = CGAL::Parallel_if_available_tag, typename TriangleMesh>
Face_deviations face_deviations(const TriangleMesh& mesh, const TriangleMesh& reference)
{
  for(const TriangleMesh* m : {&mesh, &reference})
    if(is_empty(*m) || faces(*m).empty() || !is_triangle_mesh(*m))
      throw Error(Error_code::INVALID_INPUT, "face_deviations() needs two non-empty triangle meshes");
  Face_deviations result;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(reference);
  result.reference_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                        + CGAL::square(box.zmax() - box.zmin()));
  const double spacing = 0.25 * internal::median_edge_length(mesh);
  result.of_mesh_faces = internal::largest_distance_per_face<Concurrency_tag>(mesh, reference, spacing);
  result.of_reference_faces = internal::largest_distance_per_face<Concurrency_tag>(reference, mesh, spacing);
  return result;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_FACE_DEVIATIONS_H
