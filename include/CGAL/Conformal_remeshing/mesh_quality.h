// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality measures of a triangle mesh (angles, equiangle skewness, aspect ratio, edge lengths,
// valences) and its geometric fidelity to a reference mesh (Hausdorff distance both ways,
// area ratio, self-intersection).

#ifndef CGAL_CONFORMAL_REMESHING_MESH_QUALITY_H
#define CGAL_CONFORMAL_REMESHING_MESH_QUALITY_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/Conformal_remeshing/internal/distance_to_surface.h>
#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/well_shaped_cover.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// A histogram with bins of equal width starting at `lower`: bin `i` counts the values in
/// `[lower + i*bin_width, lower + (i+1)*bin_width)`; the last bin also takes its upper bound.
struct Histogram
{
  double lower = 0.;
  double bin_width = 1.;
  std::vector<std::size_t> counts;

  Histogram() = default;
  Histogram(double lower, double upper, std::size_t nb_bins)
    : lower(lower), bin_width((upper - lower) / double(nb_bins)), counts(nb_bins, 0)
  {}

  void add(double value)
  {
    if(counts.empty() || !std::isfinite(value))
      return;
    const double position = (value - lower) / bin_width;
    const std::size_t last = counts.size() - 1;
    const std::size_t bin = position <= 0. ? 0 : (std::min)(static_cast<std::size_t>(position), last);
    ++counts[bin];
  }

  std::size_t total() const
  {
    std::size_t n = 0;
    for(std::size_t c : counts)
      n += c;
    return n;
  }
};

/// \ingroup PkgConformalRemeshingRef
/// Minimum, maximum and mean of a quantity over a mesh.
struct Statistics
{
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  double mean = std::numeric_limits<double>::quiet_NaN();
};

/// \ingroup PkgConformalRemeshingRef
/// The quality measures of a triangle mesh, with these definitions:
/// - angles in degrees, measured with the numerically stable `atan2(|u x v|, u . v)`;
/// - equiangle skewness (Fluent): `max((t_max - 60) / 120, (60 - t_min) / 60)`, 0 for an
///   equilateral triangle, 1 for a degenerate one;
/// - aspect ratio (Verdict): `L_max (L_0 + L_1 + L_2) / (4 sqrt(3) Area)`, 1 for an equilateral
///   triangle, infinite for a degenerate one.
struct Mesh_quality_report
{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_edges = 0;
  std::size_t number_of_faces = 0;

  /// every corner angle, 1 degree bins over [0, 180]
  Histogram angle_histogram{0., 180., 180};
  /// the smallest angle of each triangle, 1 degree bins over [0, 60]
  Histogram minimum_angle_histogram{0., 60., 60};
  /// statistics of the smallest angle of each triangle (`minimum_angle.min` is the smallest
  /// angle of the mesh)
  Statistics minimum_angle;
  /// statistics of the largest angle of each triangle (`maximum_angle.max` is the largest
  /// angle of the mesh)
  Statistics maximum_angle;

  /// thresholds (degrees) for `share_below`
  static constexpr std::array<double, 4> angle_thresholds{{10., 20., 25., 30.}};
  /// `share_below[i]`: the fraction of triangles whose minimum angle is below `angle_thresholds[i]`
  std::array<double, 4> share_below{{0., 0., 0., 0.}};

  /// equiangle skewness per triangle, 50 bins over [0, 1]
  Histogram skewness_histogram{0., 1., 50};
  Statistics skewness;
  /// Verdict aspect ratio per triangle (infinite for zero-area triangles, which are counted in
  /// `number_of_degenerate_faces` and left out of the mean)
  Statistics aspect_ratio;
  std::size_t number_of_degenerate_faces = 0;

  Statistics edge_length;
  /// the median edge length
  double median_edge_length = std::numeric_limits<double>::quiet_NaN();

  /// `valence_histogram[k]`: the number of vertices with `k` incident edges
  std::vector<std::size_t> valence_histogram;

  /// the fraction of triangles whose minimum angle is below `threshold_degrees`
  /// (one of `angle_thresholds`)
  double share_with_minimum_angle_below(double threshold_degrees) const
  {
    for(std::size_t i = 0; i < angle_thresholds.size(); ++i)
      if(angle_thresholds[i] == threshold_degrees)
        return share_below[i];
    throw Error(Error_code::INVALID_INPUT, "no share is kept for this angle threshold");
  }
};

/// \ingroup PkgConformalRemeshingRef
/// The angles (degrees), equiangle skewness and aspect ratio of one triangle.
struct Triangle_quality
{
  std::array<double, 3> angles;
  double skewness;
  double aspect_ratio;
};

/// \ingroup PkgConformalRemeshingRef
/// Quality of the triangle `(p, q, r)`, with the definitions of `Mesh_quality_report`.
template <typename Point_3>
Triangle_quality triangle_quality(const Point_3& p, const Point_3& q, const Point_3& r)
{
  const std::array<std::array<double, 3>, 3> corners{{
    {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}},
    {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}},
    {{CGAL::to_double(r.x()), CGAL::to_double(r.y()), CGAL::to_double(r.z())}}}};

  Triangle_quality result;
  std::array<double, 3> lengths;
  double twice_area = 0.;
  for(int i = 0; i < 3; ++i)
  {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % 3];
    const auto& c = corners[(i + 2) % 3];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double sine = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double cosine = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    result.angles[i] = std::atan2(sine, cosine) * 180. / CGAL_PI;
    lengths[i] = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    twice_area = (std::max)(twice_area, sine); // the three cross products agree up to rounding
  }
  // Zero-length edges make atan2 return 0 for every angle; a degenerate triangle has 0, 0, 180.
  const double smallest = *std::min_element(result.angles.begin(), result.angles.end());
  const double largest = (twice_area == 0.) ? 180. : *std::max_element(result.angles.begin(), result.angles.end());
  if(twice_area == 0.)
    result.angles = {{0., 0., 180.}};
  result.skewness = (std::max)((largest - 60.) / 120., (60. - smallest) / 60.);
  const double longest = *std::max_element(lengths.begin(), lengths.end());
  result.aspect_ratio = (twice_area == 0.)
                        ? std::numeric_limits<double>::infinity()
                        : longest * (lengths[0] + lengths[1] + lengths[2]) / (4. * std::sqrt(3.) * 0.5 * twice_area);
  return result;
}

namespace internal {

/// The length of each edge of `mesh`, in the order of `edges(mesh)`.
template <typename TriangleMesh, typename VertexPointMap>
std::vector<double> edge_lengths(const TriangleMesh& mesh, const VertexPointMap& vpm)
{
  std::vector<double> lengths;
  lengths.reserve(num_edges(mesh));
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, mesh)), get(vpm, target(h, mesh))))));
  }
  return lengths;
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Computes the quality measures of a triangle mesh.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `EdgeListGraph` and `VertexListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Error with `Error_code::INVALID_INPUT` if `mesh` has a face that is not a triangle.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_quality_report mesh_quality(const TriangleMesh& mesh,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(vertex_point, mesh));
  if(!is_triangle_mesh(mesh))
    throw Error(Error_code::INVALID_INPUT, "mesh_quality() needs a triangle mesh; triangulate the faces first");

  Mesh_quality_report report;
  // Counted by iteration: num_vertices() of a Surface_mesh also counts removed elements until its
  // garbage is collected (as after isotropic_remeshing()).
  report.number_of_vertices = static_cast<std::size_t>(std::distance(vertices(mesh).begin(), vertices(mesh).end()));
  report.number_of_edges = static_cast<std::size_t>(std::distance(edges(mesh).begin(), edges(mesh).end()));
  report.number_of_faces = static_cast<std::size_t>(std::distance(faces(mesh).begin(), faces(mesh).end()));

  // Running minimum, maximum and sum of one per-triangle quantity.
  struct Accumulator
  {
    double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity(), sum = 0.;
    std::size_t n = 0;
    void add(double x) { min = (std::min)(min, x); max = (std::max)(max, x); if(std::isfinite(x)) { sum += x; ++n; } }
    Statistics statistics() const
    {
      return n == 0 ? Statistics{min, max, std::numeric_limits<double>::quiet_NaN()} : Statistics{min, max, sum / double(n)};
    }
  };
  Accumulator smallest_angles, largest_angles, skewnesses, aspect_ratios;
  std::array<std::size_t, 4> below{{0, 0, 0, 0}};
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const Triangle_quality t = triangle_quality(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)),
                                                get(vpm, target(next(h, mesh), mesh)));
    const double smallest = *std::min_element(t.angles.begin(), t.angles.end());
    const double largest = *std::max_element(t.angles.begin(), t.angles.end());
    for(double a : t.angles)
      report.angle_histogram.add(a);
    report.minimum_angle_histogram.add(smallest);
    smallest_angles.add(smallest);
    largest_angles.add(largest);
    for(std::size_t i = 0; i < below.size(); ++i)
      if(smallest < Mesh_quality_report::angle_thresholds[i])
        ++below[i];

    report.skewness_histogram.add(t.skewness);
    skewnesses.add(t.skewness);
    aspect_ratios.add(t.aspect_ratio);
    if(!std::isfinite(t.aspect_ratio))
      ++report.number_of_degenerate_faces;
  }

  if(report.number_of_faces > 0)
  {
    report.minimum_angle = smallest_angles.statistics();
    report.maximum_angle = largest_angles.statistics();
    for(std::size_t i = 0; i < below.size(); ++i)
      report.share_below[i] = double(below[i]) / double(report.number_of_faces);
    report.skewness = skewnesses.statistics();
    report.aspect_ratio = aspect_ratios.statistics();
  }

  std::vector<double> lengths = internal::edge_lengths(mesh, vpm);
  if(!lengths.empty())
  {
    double sum = 0.;
    for(double l : lengths)
      sum += l;
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    report.median_edge_length = lengths[lengths.size() / 2];
    report.edge_length = Statistics{*std::min_element(lengths.begin(), lengths.end()),
                                    *std::max_element(lengths.begin(), lengths.end()),
                                    sum / double(lengths.size())};
  }

  for(auto v : vertices(mesh))
  {
    const std::size_t valence = degree(v, mesh);
    if(report.valence_histogram.size() <= valence)
      report.valence_histogram.resize(valence + 1, 0);
    ++report.valence_histogram[valence];
  }
  return report;
}

/// \ingroup PkgConformalRemeshingRef
/// The fraction of the edges of `mesh` whose length lies in `[min_length, max_length]`, e.g.
/// within [0.7, 1.4] times a remeshing's target edge length.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
double share_of_edges_with_length_in(const TriangleMesh& mesh, double min_length, double max_length,
                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(vertex_point, mesh));
  std::size_t within = 0, total = 0;
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)))));
    within += (l >= min_length && l <= max_length);
    ++total;
  }
  return total > 0 ? double(within) / double(total) : 0.;
}

/// \ingroup PkgConformalRemeshingRef
/// How faithfully a mesh reproduces a reference surface.
struct Reference_comparison
{
  /// the length of the reference's bounding-box diagonal, the unit of the relative distances
  double reference_diagonal = 0.;
  /// approximate Hausdorff distance from the mesh to the reference, over `reference_diagonal`
  double relative_distance_to_reference = 0.;
  /// approximate Hausdorff distance from the reference to the mesh, over `reference_diagonal`
  double relative_distance_from_reference = 0.;
  /// area of the mesh over area of the reference
  double area_ratio = 0.;
  /// whether the mesh (not the reference) has crossing faces, by exact predicates (faces that only
  /// touch at distinct vertices of one point, as the reference's may, are a contact, not a crossing)
  bool self_intersects = false;
  /// where the distances are largest: the sample of the mesh farthest from the reference, and
  /// the sample of the reference farthest from the mesh
  std::array<double, 3> farthest_point_to_reference{{0., 0., 0.}}, farthest_point_from_reference{{0., 0., 0.}};

  /// the larger of the two one-sided relative distances
  double relative_hausdorff_distance() const
  {
    return (std::max)(relative_distance_to_reference, relative_distance_from_reference);
  }
};

namespace internal {

/// Where a random point on a face is: the triangle's index in `mesh`'s face order and the point's
/// coordinates `(u, w)`, the point being `p + u (q - p) + w (r - p)` for the triangle `(p, q, r)`.
struct Face_sample
{
  std::size_t triangle;
  double u, w;
};

/// The point `p + u (q - p) + w (r - p)` of the segment or triangle whose corners are `c` (`r` is
/// the last corner: `w` is 0 on a segment).
template <typename Corners>
CGAL::Simple_cartesian<double>::Point_3 point_at(const Corners& c, double u, double w)
{
  const auto& p = c[0];
  const auto& q = c[1];
  const auto& r = c[c.size() - 1];
  return CGAL::Simple_cartesian<double>::Point_3(p.x() + u * (q.x() - p.x()) + w * (r.x() - p.x()),
                                                 p.y() + u * (q.y() - p.y()) + w * (r.y() - p.y()),
                                                 p.z() + u * (q.z() - p.z()) + w * (r.z() - p.z()));
}

/// Points on `mesh` as `sample_triangle_mesh()` takes them by default: its vertices, as many
/// random points on its edges (by length) and `samples` random points on its faces (by area);
/// all drawn from `seed` (CGAL 5.5's sampler draws the points inside each edge and face from the
/// default generator whatever the seed, so its distances change from run to run). The points on
/// faces come last; `face_samples`, when given, receives where each of them is and `triangles`
/// the triangles.
template <typename TriangleMesh>
std::vector<CGAL::Simple_cartesian<double>::Point_3>
sample_points(const TriangleMesh& mesh, std::size_t samples, unsigned int seed,
              std::vector<std::array<CGAL::Simple_cartesian<double>::Point_3, 3> >* triangles_out = nullptr,
              std::vector<Face_sample>* face_samples = nullptr)
{
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  const auto vpm = get(CGAL::vertex_point, mesh);
  const auto at = [&](auto v) {
    const auto& p = get(vpm, v);
    return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  std::vector<Point> points;
  for(auto v : vertices(mesh))
    points.push_back(at(v));

  CGAL::Random random(seed);
  // `count` points on the simplices `corners` lists, each chosen with probability proportional to `measure`.
  const auto sample = [&](const auto& corners, auto measure, std::size_t count) {
    std::vector<double> cumulative;
    double total = 0.;
    for(const auto& c : corners)
      cumulative.push_back(total += measure(c));
    if(total <= 0.)
      return;
    for(std::size_t i = 0; i < count; ++i)
    {
      const std::size_t k = (std::min)(std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), random.get_double(0., total))
                                                    - cumulative.begin()), cumulative.size() - 1);
      const auto& c = corners[k];
      double u = random.get_double(), w = c.size() == 3 ? random.get_double() : 0.;
      if(u + w > 1.) // fold the parallelogram's far half back onto the triangle
        u = 1. - u, w = 1. - w;
      if(c.size() == 3 && face_samples != nullptr)
        face_samples->push_back(Face_sample{k, u, w});
      points.push_back(point_at(c, u, w));
    }
  };
  std::vector<std::array<Point, 2> > segments;
  for(auto e : edges(mesh))
    segments.push_back({at(source(e, mesh)), at(target(e, mesh))});
  sample(segments, [](const std::array<Point, 2>& s) { return std::sqrt(CGAL::squared_distance(s[0], s[1])); }, num_vertices(mesh));
  std::vector<std::array<Point, 3> > triangles;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    triangles.push_back({at(source(h, mesh)), at(target(h, mesh)), at(target(next(h, mesh), mesh))});
  }
  sample(triangles, [](const std::array<Point, 3>& t) { return std::sqrt(CGAL::squared_area(t[0], t[1], t[2])); }, samples);
  if(triangles_out != nullptr)
    triangles_out->swap(triangles);
  return points;
}

/// The random samples find a triangle's farthest point only to within their spacing (a tenth of
/// its edges at a hundred samples per triangle): with CGAL's default of about 6 per triangle, the
/// largest distance of a remeshing to its input varies by about 10% from seed to seed, even with
/// millions of samples. So the triangles of the farthest samples, this many, are
/// searched further, each from its farthest sample to a local maximum of the distance.
constexpr std::size_t refined_triangles = 256;

/// The point of triangle `t` farthest from the surface of `tree` near `point_at(t, u, w)`, and its
/// squared distance: a compass search on (u, w) in the triangle, in six directions, with steps
/// from a twentieth of its sides down to a ten-thousandth.
template <typename Tree>
std::pair<double, CGAL::Simple_cartesian<double>::Point_3>
farthest_point_near(const Tree& tree, const std::array<CGAL::Simple_cartesian<double>::Point_3, 3>& t, double u, double w)
{
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  const auto at = [&](double cu, double cw) { return point_at(t, cu, cw); };
  Point best_point = at(u, w), closest = tree.closest_point(best_point);
  double best = CGAL::squared_distance(best_point, closest);
  const double directions[6][2] = {{1., 0.}, {-1., 0.}, {0., 1.}, {0., -1.}, {1., -1.}, {-1., 1.}};
  for(double step = 0.05; step >= 1e-4;)
  {
    bool improved = false;
    for(const auto& d : directions)
    {
      const double cu = u + step * d[0], cw = w + step * d[1];
      if(cu < 0. || cw < 0. || cu + cw > 1.)
        continue;
      const Point candidate = at(cu, cw);
      closest = tree.closest_point(candidate, closest);
      const double d2 = CGAL::squared_distance(candidate, closest);
      if(d2 > best)
      {
        best = d2;
        best_point = candidate;
        u = cu;
        w = cw;
        improved = true;
        break;
      }
    }
    if(!improved)
      step *= 0.5;
  }
  return {best, best_point};
}

/// The largest distance from `sample_points(mesh, samples, seed)` to `reference` and the sample
/// at that distance, as `approximate_Hausdorff_distance()` measures it (see
/// `Distance_to_surface`), the triangles of the farthest samples searched further.
template <typename Concurrency_tag, typename TriangleMesh>
std::pair<double, std::array<double, 3> > largest_distance_of_samples(const TriangleMesh& mesh, const TriangleMesh& reference,
                                   std::size_t samples, unsigned int seed)
{
  using Fast = CGAL::Simple_cartesian<double>;
  std::vector<std::array<Fast::Point_3, 3> > triangles;
  std::vector<Face_sample> face_samples;
  std::vector<Fast::Point_3> points = sample_points(mesh, samples, seed, &triangles, &face_samples);
  const std::size_t first_face_sample = points.size() - face_samples.size();
  const Distance_to_surface distance(reference, Concurrency_tag());
  const Distance_to_surface::Tree& tree = distance.tree();
  const std::vector<double> squared_distance = distance.squared_distances<Concurrency_tag>(points);
  std::size_t farthest = std::size_t(std::max_element(squared_distance.begin(), squared_distance.end()) - squared_distance.begin());
  std::pair<double, Fast::Point_3> largest(squared_distance[farthest], points[farthest]);

  // The triangles of the farthest face samples, each searched from its farthest sample.
  constexpr std::size_t none = std::size_t(-1);
  std::vector<std::size_t> farthest_in_triangle(triangles.size(), none);
  const auto farther = [&](std::size_t a, std::size_t b) {
    return squared_distance[first_face_sample + a] > squared_distance[first_face_sample + b];
  };
  for(std::size_t i = 0; i < face_samples.size(); ++i)
  {
    std::size_t& f = farthest_in_triangle[face_samples[i].triangle];
    if(f == none || farther(i, f))
      f = i;
  }
  std::vector<std::size_t> starts;
  std::copy_if(farthest_in_triangle.begin(), farthest_in_triangle.end(), std::back_inserter(starts),
               [&](std::size_t i) { return i != none; });
  const std::size_t searched = (std::min)(refined_triangles, starts.size());
  std::partial_sort(starts.begin(), starts.begin() + searched, starts.end(), farther);
  starts.resize(searched);
  std::vector<std::pair<double, Fast::Point_3> > refined(starts.size());
  for_each_index<Concurrency_tag>(starts.size(), [&](std::size_t s) {
    const Face_sample& start = face_samples[starts[s]];
    refined[s] = farthest_point_near(tree, triangles[start.triangle], start.u, start.w);
  });
  for(const auto& r : refined)
    if(r.first > largest.first)
      largest = r;
  return {std::sqrt((std::max)(0., largest.first)), {{largest.second.x(), largest.second.y(), largest.second.z()}}};
}

} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Compares a triangle mesh with a reference triangle mesh: approximate Hausdorff distance
/// both ways (the largest distance from points sampled on one mesh to the other, as
/// `CGAL::Polygon_mesh_processing::approximate_Hausdorff_distance()` measures it, relative to the
/// reference's bounding-box diagonal), the ratio of their areas, and whether the mesh
/// self-intersects (`CGAL::Polygon_mesh_processing::self_intersections()`, exact predicates;
/// faces that only touch at distinct vertices of one point are a contact, not a crossing).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_points_on_faces}
///     \cgalParamDescription{the number of random points sampled on the faces of each mesh, on
///                           top of its vertices and points on its edges}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`max(100000, 4 * num_faces)` of the sampled mesh}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{the seed of the sampling, for reproducible results}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Error with `Error_code::INVALID_INPUT` if a mesh is empty or not a triangle mesh.
template <typename Concurrency_tag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Reference_comparison compare_to_reference(const TriangleMesh& mesh, const TriangleMesh& reference,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  for(const TriangleMesh* m : {&mesh, &reference})
    if(is_empty(*m) || faces(*m).empty() || !is_triangle_mesh(*m))
      throw Error(Error_code::INVALID_INPUT, "compare_to_reference() needs two non-empty triangle meshes");

  namespace PMP = CGAL::Polygon_mesh_processing;
  const unsigned int seed = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::random_seed), 0u);
  auto samples_on = [&](const TriangleMesh& m) {
    const std::size_t fallback = (std::max<std::size_t>)(100000, 4 * num_faces(m));
    return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::number_of_points_on_faces), fallback);
  };

  Reference_comparison result;
  const CGAL::Bbox_3 box = PMP::bbox(reference);
  result.reference_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                        + CGAL::square(box.zmax() - box.zmin()));
  const double unit = result.reference_diagonal > 0. ? result.reference_diagonal : 1.;
  const auto to = internal::largest_distance_of_samples<Concurrency_tag>(mesh, reference, samples_on(mesh), seed);
  const auto from = internal::largest_distance_of_samples<Concurrency_tag>(reference, mesh, samples_on(reference), seed);
  result.relative_distance_to_reference = to.first / unit;
  result.relative_distance_from_reference = from.first / unit;
  result.farthest_point_to_reference = to.second;
  result.farthest_point_from_reference = from.second;
  const double reference_area = CGAL::to_double(PMP::area(reference));
  result.area_ratio = reference_area > 0. ? CGAL::to_double(PMP::area(mesh)) / reference_area
                                          : std::numeric_limits<double>::infinity();
  result.self_intersects = internal::has_crossing_faces<Concurrency_tag>(mesh);
  return result;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_MESH_QUALITY_H
