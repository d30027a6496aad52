// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planar annulus welded to a patch boundary (paper Alg. 3): its outer circle carries
// exactly the boundary's vertices, its inner circle becomes the free, convex boundary of the
// welded disc.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_ANNULUS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_ANNULUS_H

#include <CGAL/Conformal_remeshing/Error.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

/// The radius of the circle on which a convex polygon with sides `lengths` (in order) is
/// inscribed, when the circle's centre is inside the polygon, i.e. when every side subtends
/// less than half of the circle: the root of `sum 2 asin(l_i / 2R) = 2 pi`.
inline double inscribing_radius(const std::vector<double>& lengths)
{
  const double total = std::accumulate(lengths.begin(), lengths.end(), 0.);
  const double longest = *std::max_element(lengths.begin(), lengths.end());
  auto turning = [&](double r) {
    double sum = 0.;
    for(double l : lengths)
      sum += 2. * std::asin((std::min)(1., l / (2. * r)));
    return sum;
  };
  // turning() decreases in r; it is >= 2 pi at total / (2 pi) since asin(x) >= x, and the
  // centre is inside when turning(longest / 2) >= 2 pi.
  double low = (std::max)(longest / 2., total / (2. * CGAL_PI)), high = total;
  if(turning(longest / 2.) < 2. * CGAL_PI)
    throw Error(Error_code::INVALID_INPUT, "the welded boundary has an edge longer than half its length");
  for(int i = 0; i < 200 && high - low > 1e-15 * high; ++i)
  {
    const double mid = 0.5 * (low + high);
    (turning(mid) > 2. * CGAL_PI ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

/// A triangulated planar annulus. Vertices `[0, outer)` are the outer circle in counterclockwise
/// order, `[outer, outer + inner)` the inner circle in counterclockwise order, the rest interior
/// points added by Delaunay refinement; faces are counterclockwise.
struct Planar_annulus
{
  std::vector<std::array<double, 2> > points;
  std::size_t outer = 0;
  std::size_t inner = 0;
  std::vector<std::array<int, 3> > faces;
};

/// Triangulates the annulus between the polygon through `outer_points` (counterclockwise, on a
/// circle around the origin) and a regular `inner_count`-gon of radius `inner_radius`, with
/// Delaunay refinement to a 20.7 degree minimum angle that never splits the constrained
/// boundary edges (so that no point is added on the welded circle).
inline Planar_annulus make_annulus(const std::vector<std::array<double, 2> >& outer_points, double inner_radius,
                                   std::size_t inner_count)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K, CGAL::Delaunay_mesh_vertex_base_2<K> > Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;
  typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Criteria;

  Planar_annulus annulus;
  annulus.outer = outer_points.size();
  annulus.inner = inner_count;
  annulus.points = outer_points;
  for(std::size_t i = 0; i < inner_count; ++i)
  {
    const double a = 2. * CGAL_PI * double(i) / double(inner_count);
    annulus.points.push_back({{inner_radius * std::cos(a), inner_radius * std::sin(a)}});
  }

  // All at once, spatially sorted: inserted one by one in their order around the circle, every
  // new point is nearly cocircular with all the triangles before it and the flips cascade
  // (about 50 times slower for a loop of tens of thousands of points).
  CDT cdt;
  std::vector<std::pair<K::Point_2, int> > numbered;
  for(std::size_t i = 0; i < annulus.points.size(); ++i)
    numbered.emplace_back(K::Point_2(annulus.points[i][0], annulus.points[i][1]), int(i));
  cdt.insert(numbered.begin(), numbered.end());
  if(cdt.number_of_vertices() != annulus.points.size())
    throw Error(Error_code::INVALID_INPUT, "two vertices of the welded boundary coincide on the circle");
  std::vector<CDT::Vertex_handle> handles(annulus.points.size());
  for(CDT::Vertex_handle v : cdt.finite_vertex_handles())
    handles[v->info()] = v;
  for(std::size_t i = 0; i < annulus.outer; ++i)
    cdt.insert_constraint(handles[i], handles[(i + 1) % annulus.outer]);
  for(std::size_t i = 0; i < annulus.inner; ++i)
    cdt.insert_constraint(handles[annulus.outer + i], handles[annulus.outer + (i + 1) % annulus.inner]);

  // The seed at the centre marks the inner disc as outside the domain.
  const std::vector<K::Point_2> seeds(1, K::Point_2(0, 0));
  CGAL::Delaunay_mesher_no_edge_refinement_2<CDT, Criteria> mesher(cdt, Criteria(0.125, 0.));
  mesher.set_seeds(seeds.begin(), seeds.end(), false);
  mesher.refine_mesh();

  // Steiner points get a default info: tell them from the input points by their handles.
  const std::size_t number_of_input_points = annulus.points.size();
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if(v->info() < 0 || std::size_t(v->info()) >= number_of_input_points || handles[v->info()] != CDT::Vertex_handle(v))
    {
      v->info() = int(annulus.points.size());
      annulus.points.push_back({{v->point().x(), v->point().y()}});
    }
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain())
      annulus.faces.push_back({{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}});
  return annulus;
}

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_ANNULUS_H
