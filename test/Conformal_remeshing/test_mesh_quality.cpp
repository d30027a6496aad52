// Tests of the quality measures against hand-computed triangles, of the comparison with a
// reference mesh (Hausdorff distances and the deviation of each face) on deliberately displaced
// and self-intersecting copies, and of the small angles a sharp corner of the reference forces.

#include <CGAL/Conformal_remeshing/angles_at_sharp_corners.h>
#include <CGAL/Conformal_remeshing/face_deviations.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <cad_like_models.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Simple_cartesian<double>::Point_3 Fast_point;

namespace {

Mesh single_triangle(const Point& p, const Point& q, const Point& r)
{
  Mesh m;
  m.add_face(m.add_vertex(p), m.add_vertex(q), m.add_vertex(r));
  return m;
}

// An n x n grid of unit squares in the plane z = 0, each split into two triangles.
Mesh grid(int n)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      v.push_back(m.add_vertex(Point(i, j, 0)));
  auto at = [&](int i, int j) { return v[j * (n + 1) + i]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

} // namespace

TEST(TriangleQuality, Equilateral)
{
  const CR::Triangle_quality t = CR::triangle_quality(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, std::sqrt(3.) / 2, 0));
  for(double a : t.angles)
    EXPECT_NEAR(a, 60., 1e-12);
  EXPECT_NEAR(t.skewness, 0., 1e-12);
  EXPECT_NEAR(t.aspect_ratio, 1., 1e-12);
}

TEST(TriangleQuality, RightIsosceles)
{
  // Angles 45, 45, 90. Equiangle skewness max((90-60)/120, (60-45)/60) = 0.25. Aspect ratio:
  // legs 1, hypotenuse sqrt(2), area 1/2: sqrt(2) (2 + sqrt(2)) / (4 sqrt(3) / 2).
  const CR::Triangle_quality t = CR::triangle_quality(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0));
  EXPECT_NEAR(t.angles[0], 90., 1e-12);
  EXPECT_NEAR(t.angles[1], 45., 1e-12);
  EXPECT_NEAR(t.angles[2], 45., 1e-12);
  EXPECT_NEAR(t.skewness, 0.25, 1e-12);
  EXPECT_NEAR(t.aspect_ratio, std::sqrt(2.) * (2 + std::sqrt(2.)) / (2 * std::sqrt(3.)), 1e-12);
}

TEST(TriangleQuality, ObtuseIsosceles)
{
  // Angles 30, 30, 120: skewness max(60/120, 30/60) = 0.5.
  const CR::Triangle_quality t = CR::triangle_quality(Point(0, 0, 0), Point(2, 0, 0), Point(1, 1 / std::sqrt(3.), 0));
  EXPECT_NEAR(t.angles[0], 30., 1e-12);
  EXPECT_NEAR(t.angles[2], 120., 1e-12);
  EXPECT_NEAR(t.skewness, 0.5, 1e-12);
}

TEST(TriangleQuality, DegenerateTriangle)
{
  const CR::Triangle_quality t = CR::triangle_quality(Point(0, 0, 0), Point(1, 0, 0), Point(3, 0, 0));
  EXPECT_EQ(t.angles[0] + t.angles[1] + t.angles[2], 180.);
  EXPECT_EQ(t.skewness, 1.);
  EXPECT_TRUE(std::isinf(t.aspect_ratio));
}

TEST(MeshQuality, RightIsoscelesGrid)
{
  const Mesh m = grid(4);
  const CR::Mesh_quality_report q = CR::mesh_quality(m);
  EXPECT_EQ(q.number_of_faces, 32u);
  EXPECT_EQ(q.number_of_vertices, 25u);
  EXPECT_NEAR(q.minimum_angle.min, 45., 1e-12);
  EXPECT_NEAR(q.maximum_angle.max, 90., 1e-12);
  EXPECT_NEAR(q.skewness.mean, 0.25, 1e-12);
  EXPECT_NEAR(q.skewness.max, 0.25, 1e-12);
  // 45 degrees is not below 30: no triangle below any threshold.
  EXPECT_EQ(q.share_with_minimum_angle_below(30.), 0.);
  // Angle histogram: two corners at 45 and one at 90 per triangle, in 1 degree bins.
  EXPECT_EQ(q.angle_histogram.total(), 96u);
  EXPECT_EQ(q.angle_histogram.counts[45] + q.angle_histogram.counts[44], 64u);
  EXPECT_EQ(q.angle_histogram.counts[90] + q.angle_histogram.counts[89], 32u);
  // Edge lengths: 40 unit edges and 16 diagonals.
  EXPECT_EQ(q.edge_length.min, 1.);
  EXPECT_NEAR(q.edge_length.max, std::sqrt(2.), 1e-15);
  EXPECT_NEAR(q.edge_length.mean, (40 + 16 * std::sqrt(2.)) / 56, 1e-12);
  EXPECT_EQ(q.median_edge_length, 1.);
  // Valences: interior vertices of this split grid have 6 neighbours (9 of them).
  ASSERT_GT(q.valence_histogram.size(), 6u);
  EXPECT_EQ(q.valence_histogram[6], 9u);
}

TEST(MeshQuality, SharesBelowThresholds)
{
  // One equilateral and one sliver triangle (minimum angle about 5.7 degrees).
  Mesh m = single_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, std::sqrt(3.) / 2, 0));
  m.add_face(m.add_vertex(Point(0, 0, 1)), m.add_vertex(Point(10, 0, 1)), m.add_vertex(Point(5, 0.5, 1)));
  const CR::Mesh_quality_report q = CR::mesh_quality(m);
  EXPECT_EQ(q.share_with_minimum_angle_below(10.), 0.5);
  EXPECT_EQ(q.share_with_minimum_angle_below(30.), 0.5);
  EXPECT_NEAR(q.minimum_angle.min, std::atan(0.1) * 180 / CGAL_PI, 1e-12);
  EXPECT_EQ(q.minimum_angle_histogram.counts[5] + q.minimum_angle_histogram.counts[59], 2u);
  EXPECT_THROW(q.share_with_minimum_angle_below(15.), CR::Error);
}

TEST(MeshQuality, RejectsNonTriangleFaces)
{
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1, 0, 0)), m.add_vertex(Point(1, 1, 0)), m.add_vertex(Point(0, 1, 0)));
  EXPECT_THROW(CR::mesh_quality(m), CR::Error);
}

TEST(ReferenceComparison, IdenticalCopy)
{
  const Mesh m = grid(8);
  const CR::Reference_comparison c = CR::compare_to_reference(m, m);
  EXPECT_NEAR(c.reference_diagonal, 8 * std::sqrt(2.), 1e-12);
  EXPECT_LT(c.relative_hausdorff_distance(), 1e-12);
  EXPECT_NEAR(c.area_ratio, 1., 1e-12);
  EXPECT_FALSE(c.self_intersects);
}

TEST(ReferenceComparison, DisplacedCopy)
{
  // Raise the centre vertex of the grid by h: the displaced copy is h away from the reference
  // at that vertex (sampled exactly), and the reference is closer to the copy than that.
  const Mesh reference = grid(8);
  Mesh displaced = reference;
  const double h = 0.5;
  for(auto v : displaced.vertices())
    if(displaced.point(v) == Point(4, 4, 0))
      displaced.point(v) = Point(4, 4, h);
  const CR::Reference_comparison c = CR::compare_to_reference(displaced, reference);
  const double diagonal = 8 * std::sqrt(2.);
  EXPECT_NEAR(c.relative_distance_to_reference, h / diagonal, 1e-12);
  EXPECT_GT(c.relative_distance_from_reference, 0.);
  EXPECT_LT(c.relative_distance_from_reference, h / diagonal);
  EXPECT_GT(c.area_ratio, 1.);
  EXPECT_FALSE(c.self_intersects);
  // Where: the raised vertex itself, and a point of the reference under the raised star.
  EXPECT_EQ(c.farthest_point_to_reference, (std::array<double, 3>{{4., 4., h}}));
  EXPECT_LT(std::abs(c.farthest_point_from_reference[0] - 4.), 1.);
  EXPECT_LT(std::abs(c.farthest_point_from_reference[1] - 4.), 1.);
  EXPECT_EQ(c.farthest_point_from_reference[2], 0.);

  // A whole-mesh translation by t along z: both one-sided distances are t.
  Mesh translated = reference;
  for(auto v : translated.vertices())
    translated.point(v) = translated.point(v) + K::Vector_3(0, 0, 0.25);
  const CR::Reference_comparison t = CR::compare_to_reference(translated, reference);
  EXPECT_NEAR(t.relative_distance_to_reference, 0.25 / diagonal, 1e-12);
  EXPECT_NEAR(t.relative_distance_from_reference, 0.25 / diagonal, 1e-12);
}

TEST(ReferenceComparison, SelfIntersectingCopy)
{
  // Drag an interior vertex across its neighbours: its star folds over the adjacent faces.
  const Mesh reference = grid(4);
  Mesh folded = reference;
  for(auto v : folded.vertices())
    if(folded.point(v) == Point(2, 2, 0))
      folded.point(v) = Point(3.5, 2.2, 0.);
  EXPECT_FALSE(CR::compare_to_reference(reference, reference).self_intersects);
  const CR::Reference_comparison c = CR::compare_to_reference(folded, reference);
  EXPECT_TRUE(c.self_intersects);
}

TEST(ReferenceComparison, SamplesComeFromTheSeedAlone)
{
  // A flat coarse copy of a bumpy grid: the distance from the copy to the bumps is that of the
  // farthest sample, so it depends on where the random points fall (CGAL 5.5's sampler drew them
  // from its default generator whatever the seed).
  const auto bumpy = [](Mesh m, double period) {
    for(auto v : m.vertices())
    {
      const Point p = m.point(v);
      m.point(v) = Point(p.x(), p.y(), std::sin(p.x() * period) * std::cos(p.y() * period));
    }
    return m;
  };
  const Mesh reference = bumpy(grid(24), 1.3);
  Mesh coarse = grid(6);
  for(auto v : coarse.vertices())
    coarse.point(v) = Point(4 * coarse.point(v).x(), 4 * coarse.point(v).y(), 0.);
  const auto with_seed = [&](unsigned int seed) {
    return CR::compare_to_reference(coarse, reference, CGAL::parameters::number_of_points_on_faces(500).random_seed(seed));
  };
  const CR::Reference_comparison first = with_seed(7), again = with_seed(7), other = with_seed(8);
  EXPECT_EQ(first.relative_distance_to_reference, again.relative_distance_to_reference);
  EXPECT_EQ(first.relative_distance_from_reference, again.relative_distance_from_reference);
  EXPECT_NE(first.relative_distance_to_reference, other.relative_distance_to_reference);
  EXPECT_GT(first.relative_distance_from_reference, 0.5 / first.reference_diagonal); // near the bumps' height of 1
}

TEST(ReferenceComparison, FarthestPointInsideATriangleIsFound)
{
  // A triangle over a square tent 0.3 deep with its corners at the square's corners: the
  // distance from the triangle to the tent is 0 at its three corners (on the tent's rim) and
  // largest, 0.15 / sqrt(0.34), at the square's centre, inside the triangle, where the four
  // faces of the tent are equally far. Ten random points on the triangle come nowhere near that
  // point alone; the search from the farthest of them finds it.
  Mesh tent;
  const auto apex = tent.add_vertex(Point(0.5, 0.5, -0.3));
  const std::array<Mesh::Vertex_index, 4> corner{{tent.add_vertex(Point(0, 0, 0)), tent.add_vertex(Point(1, 0, 0)),
                                                  tent.add_vertex(Point(1, 1, 0)), tent.add_vertex(Point(0, 1, 0))}};
  for(int i = 0; i < 4; ++i)
    tent.add_face(corner[i], corner[(i + 1) % 4], apex);
  const Mesh triangle = single_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0));
  const double farthest = 0.15 / std::sqrt(0.34), diagonal = std::sqrt(2.09);
  for(unsigned int seed : {0u, 1u, 2u})
  {
    const CR::Reference_comparison c =
      CR::compare_to_reference(triangle, tent, CGAL::parameters::number_of_points_on_faces(10).random_seed(seed));
    EXPECT_NEAR(c.reference_diagonal, diagonal, 1e-12);
    EXPECT_GT(c.relative_distance_to_reference, (1. - 1e-3) * farthest / diagonal) << "seed " << seed;
    EXPECT_LE(c.relative_distance_to_reference, (1. + 1e-12) * farthest / diagonal) << "seed " << seed;
    EXPECT_NEAR(c.farthest_point_to_reference[0], 0.5, 1e-3);
    EXPECT_NEAR(c.farthest_point_to_reference[1], 0.5, 1e-3);
  }
}

TEST(ReferenceComparison, SamplesLieOnTheMesh)
{
  // Vertices, as many points on the edges, then the points on the faces; all on the flat grid.
  const Mesh m = grid(5);
  const auto points = CR::internal::sample_points(m, 1000, 3);
  ASSERT_EQ(points.size(), 2 * m.number_of_vertices() + 1000);
  std::size_t inside_the_lower_left_quarter = 0;
  for(const auto& p : points)
  {
    EXPECT_EQ(p.z(), 0.);
    EXPECT_TRUE(p.x() >= 0. && p.x() <= 5. && p.y() >= 0. && p.y() <= 5.) << p;
    inside_the_lower_left_quarter += (p.x() < 2.5 && p.y() < 2.5);
  }
  // Points spread by area: a quarter of the grid gets about a quarter of them.
  EXPECT_GT(inside_the_lower_left_quarter, points.size() / 6);
  EXPECT_LT(inside_the_lower_left_quarter, points.size() / 3);

  // The same points with where each face sample is: the last 1000, at (u, w) in their triangle.
  std::vector<std::array<Fast_point, 3> > triangles;
  std::vector<CR::internal::Face_sample> where;
  const auto again = CR::internal::sample_points(m, 1000, 3, &triangles, &where);
  ASSERT_EQ(again, points);
  ASSERT_EQ(triangles.size(), m.number_of_faces());
  ASSERT_EQ(where.size(), 1000u);
  for(std::size_t i = 0; i < where.size(); ++i)
  {
    const auto& t = triangles.at(where[i].triangle);
    const Fast_point& p = points[points.size() - where.size() + i];
    EXPECT_TRUE(where[i].u >= 0. && where[i].w >= 0. && where[i].u + where[i].w <= 1.);
    EXPECT_NEAR(p.x(), t[0].x() + where[i].u * (t[1].x() - t[0].x()) + where[i].w * (t[2].x() - t[0].x()), 1e-12);
    EXPECT_NEAR(p.y(), t[0].y() + where[i].u * (t[1].y() - t[0].y()) + where[i].w * (t[2].y() - t[0].y()), 1e-12);
  }
}

TEST(ReferenceComparison, CoverOfACadPlateIsItsSurfaceWithoutTheFans)
{
  // The default plate's top and bottom faces are fans of slivers between the rim and the holes;
  // the cover the closest-point searches use retriangulates them.
  Mesh plate;
  CGAL::Conformal_remeshing::benchmarks::make_perforated_plate(plate, CGAL::Conformal_remeshing::benchmarks::Perforated_plate_parameters());
  typedef CGAL::Simple_cartesian<double> Fast;
  const std::vector<Fast::Triangle_3> cover = CR::internal::well_shaped_cover(plate);

  // Slivers (smallest angle below 5 degrees) on the top and bottom faces (normal along z).
  const auto is_flat_sliver = [](const Fast::Point_3& p, const Fast::Point_3& q, const Fast::Point_3& r) {
    const std::array<double, 3> a = CR::triangle_quality(p, q, r).angles;
    const Fast::Vector_3 n = CGAL::cross_product(q - p, r - p);
    return n.x() == 0. && n.y() == 0. && (std::min)({a[0], a[1], a[2]}) < 5.;
  };
  double area = 0.;
  std::size_t cover_slivers = 0, plate_slivers = 0;
  for(const Fast::Triangle_3& t : cover)
  {
    area += std::sqrt(t.squared_area());
    cover_slivers += is_flat_sliver(t[0], t[1], t[2]);
  }
  std::vector<Fast::Triangle_3> faces;
  for(auto f : plate.faces())
  {
    std::vector<Fast::Point_3> c;
    for(auto v : CGAL::vertices_around_face(plate.halfedge(f), plate))
      c.emplace_back(plate.point(v).x(), plate.point(v).y(), plate.point(v).z());
    faces.emplace_back(c[0], c[1], c[2]);
    plate_slivers += is_flat_sliver(c[0], c[1], c[2]);
  }
  const double plate_area = CGAL::Polygon_mesh_processing::area(plate);
  EXPECT_NEAR(area, plate_area, 1e-9 * plate_area);
  EXPECT_GT(plate_slivers, 1000u);
  EXPECT_LT(cover_slivers, 20u) << cover.size() << " triangles";

  // The same closest distances as the plate's own faces, from points on it and around it.
  const CR::Reference_comparison c = CR::compare_to_reference(plate, plate);
  EXPECT_LT(c.relative_hausdorff_distance(), 1e-12);
  std::vector<Fast::Point_3> queries = CR::internal::sample_points(plate, 200, 5);
  CGAL::Random random(11);
  for(int i = 0; i < 300; ++i)
    queries.emplace_back(random.get_double(-70., 70.), random.get_double(-50., 50.), random.get_double(-8., 8.));
  const auto distance_to = [](const std::vector<Fast::Triangle_3>& triangles, const Fast::Point_3& q) {
    double d = std::numeric_limits<double>::infinity();
    for(const Fast::Triangle_3& t : triangles)
      d = (std::min)(d, CGAL::squared_distance(q, t));
    return std::sqrt(d);
  };
  for(const Fast::Point_3& q : queries)
    EXPECT_NEAR(distance_to(cover, q), distance_to(faces, q), 1e-9 * c.reference_diagonal) << q;
}

TEST(ReferenceComparison, CoverDoesNotDependOnTheOrderOfTheFaces)
{
  // A planar region's outline comes in the order the region grew from its first face; the
  // triangulation of that outline must not depend on it. The plate's faces listed backwards
  // give the same covered area and the same closest distances.
  Mesh plate;
  CGAL::Conformal_remeshing::benchmarks::make_perforated_plate(plate, CGAL::Conformal_remeshing::benchmarks::Perforated_plate_parameters());
  Mesh backwards;
  std::vector<Mesh::Vertex_index> vertex_of;
  for(Mesh::Vertex_index v : plate.vertices())
    vertex_of.push_back(backwards.add_vertex(plate.point(v)));
  std::vector<Mesh::Face_index> faces(plate.faces().begin(), plate.faces().end());
  for(auto f = faces.rbegin(); f != faces.rend(); ++f)
  {
    std::vector<Mesh::Vertex_index> corners;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(plate.halfedge(*f), plate))
      corners.push_back(vertex_of[std::size_t(v)]);
    ASSERT_TRUE(backwards.add_face(corners) != Mesh::null_face());
  }
  typedef CGAL::Simple_cartesian<double> Fast;
  const std::vector<Fast::Triangle_3> forward_cover = CR::internal::well_shaped_cover(plate);
  const std::vector<Fast::Triangle_3> backward_cover = CR::internal::well_shaped_cover(backwards);
  const auto area = [](const std::vector<Fast::Triangle_3>& triangles) {
    double a = 0.;
    for(const Fast::Triangle_3& t : triangles)
      a += std::sqrt(t.squared_area());
    return a;
  };
  const double plate_area = CGAL::Polygon_mesh_processing::area(plate);
  EXPECT_NEAR(area(forward_cover), plate_area, 1e-9 * plate_area);
  EXPECT_NEAR(area(backward_cover), plate_area, 1e-9 * plate_area);
  const CR::internal::Distance_to_surface forward(plate), backward(backwards);
  std::vector<Fast::Point_3> queries = CR::internal::sample_points(plate, 200, 5);
  CGAL::Random random(13);
  for(int i = 0; i < 300; ++i)
    queries.emplace_back(random.get_double(-70., 70.), random.get_double(-50., 50.), random.get_double(-8., 8.));
  const std::vector<double> d_forward = forward.squared_distances<CGAL::Sequential_tag>(queries);
  const std::vector<double> d_backward = backward.squared_distances<CGAL::Sequential_tag>(queries);
  for(std::size_t i = 0; i < queries.size(); ++i)
    EXPECT_NEAR(std::sqrt(d_forward[i]), std::sqrt(d_backward[i]), 1e-9) << queries[i];
}

TEST(ReferenceComparison, CoverBuiltInParallelIsTheSameTriangleForTriangle)
{
  // Regions are retriangulated in parallel but appended in the order they are found: the
  // closest-point searches, and so the remesher's surface-distance bound, do not depend on the
  // number of threads. Three plates side by side give many regions, coplanar and not.
  Mesh plates;
  for(int i = 0; i < 3; ++i)
  {
    Mesh plate;
    CGAL::Conformal_remeshing::benchmarks::Perforated_plate_parameters parameters;
    parameters.seed = 1 + i;
    CGAL::Conformal_remeshing::benchmarks::make_perforated_plate(plate, parameters);
    for(auto v : plate.vertices())
      plate.point(v) = plate.point(v) + CGAL::Epick::Vector_3(200. * i, 0., 0.);
    CGAL::copy_face_graph(plate, plates);
  }
  typedef CGAL::Simple_cartesian<double> Fast;
  const std::vector<Fast::Triangle_3> in_order = CR::internal::well_shaped_cover<CGAL::Sequential_tag>(plates);
  const std::vector<Fast::Triangle_3> in_parallel = CR::internal::well_shaped_cover<CGAL::Parallel_if_available_tag>(plates);
  EXPECT_GT(in_order.size(), 1000u);
  ASSERT_EQ(in_parallel.size(), in_order.size());
  for(std::size_t i = 0; i < in_order.size(); ++i)
    for(int k = 0; k < 3; ++k)
      ASSERT_EQ(in_parallel[i][k], in_order[i][k]) << "triangle " << i;
}

TEST(ReferenceComparison, IndexedCoverSharesEachCornerAmongItsTriangles)
{
  // The closest-point tree holds the cover as corners indexed into shared points: the mesh's
  // vertices first, by index, then the points the retriangulations of the fans added.
  Mesh plate;
  CGAL::Conformal_remeshing::benchmarks::make_perforated_plate(plate, CGAL::Conformal_remeshing::benchmarks::Perforated_plate_parameters());
  typedef CGAL::Simple_cartesian<double> Fast;
  const CR::internal::Indexed_cover cover = CR::internal::well_shaped_indexed_cover(plate);
  const std::vector<Fast::Triangle_3> triangles = CR::internal::well_shaped_cover(plate);
  ASSERT_EQ(cover.triangles.size(), triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    ASSERT_EQ(cover.triangle(t), triangles[t]) << "triangle " << t;

  const std::size_t vertices = plate.number_of_vertices();
  ASSERT_GT(cover.points.size(), vertices); // the fans' retriangulations added points
  for(Mesh::Vertex_index v : plate.vertices())
    EXPECT_EQ(cover.points[std::size_t(v)], Fast::Point_3(plate.point(v).x(), plate.point(v).y(), plate.point(v).z()));
  std::vector<std::size_t> uses(cover.points.size(), 0);
  for(const auto& t : cover.triangles)
    for(std::uint32_t c : t)
    {
      ASSERT_LT(std::size_t(c), cover.points.size());
      ++uses[c];
    }
  // An added point splits a side or a triangle: stored once, it is the corner of two triangles
  // or more.
  for(std::size_t i = vertices; i < cover.points.size(); ++i)
    EXPECT_GE(uses[i], 2u) << "added point " << i;
}

TEST(FaceDeviations, OnlyTheFacesAroundARaisedVertexStrayAndByHowMuch)
{
  const Mesh reference = grid(8);
  Mesh raised = reference;
  const double h = 0.5;
  Mesh::Vertex_index top;
  for(auto v : raised.vertices())
    if(raised.point(v) == Point(4, 4, 0))
      raised.point(top = v) = Point(4, 4, h);
  const CR::Face_deviations d = CR::face_deviations(raised, reference);
  ASSERT_EQ(d.of_mesh_faces.size(), raised.number_of_faces());
  ASSERT_EQ(d.of_reference_faces.size(), reference.number_of_faces());
  EXPECT_NEAR(d.reference_diagonal, 8 * std::sqrt(2.), 1e-12);
  // The raised vertex is a corner of its faces, h above the plane; every other face lies in it.
  std::size_t f = 0, raised_faces = 0;
  for(auto face : raised.faces())
  {
    bool around_top = false;
    for(auto v : raised.vertices_around_face(raised.halfedge(face)))
      around_top = around_top || v == top;
    raised_faces += around_top;
    if(around_top)
      EXPECT_DOUBLE_EQ(d.of_mesh_faces[f], h);
    else
      EXPECT_LT(d.of_mesh_faces[f], 1e-12); // on the plane, up to the rounding of the points
    ++f;
  }
  EXPECT_EQ(raised_faces, 6u); // valence 6 in this grid
  EXPECT_DOUBLE_EQ(d.largest_of_mesh(), h);
  // The reference's faces under the raised star are closer to it than h, the others on it.
  EXPECT_GT(d.largest_of_reference(), 0.1 * h);
  EXPECT_LT(d.largest_of_reference(), h);
  const std::size_t on_it = std::size_t(
    std::count_if(d.of_reference_faces.begin(), d.of_reference_faces.end(), [](double x) { return x < 1e-12; }));
  EXPECT_GE(on_it, reference.number_of_faces() - 6);

  // The histogram: the faces off the plane in the last bin, the others in the first.
  const std::vector<double> share = CR::deviation_histogram(d.of_mesh_faces, {1e-9, 0.25 * h});
  ASSERT_EQ(share.size(), 3u);
  EXPECT_NEAR(share[0], 1. - 6. / double(raised.number_of_faces()), 1e-12);
  EXPECT_EQ(share[1], 0.);
  EXPECT_NEAR(share[2], 6. / double(raised.number_of_faces()), 1e-12);
}

TEST(FaceDeviations, AFaceAcrossACreaseIsFoundAsFarAsTheHausdorffDistanceSays)
{
  // A folded grid (a roof ridge along x = 4) against the flat one: each face's largest distance
  // is at its highest corner, and over the mesh it is the ridge's height, as for the Hausdorff
  // distance.
  const Mesh reference = grid(8);
  Mesh roof = reference;
  for(auto v : roof.vertices())
  {
    const Point p = roof.point(v);
    roof.point(v) = Point(p.x(), p.y(), 0.1 * (4. - std::abs(p.x() - 4.)));
  }
  const CR::Face_deviations d = CR::face_deviations(roof, reference);
  const CR::Reference_comparison c = CR::compare_to_reference(roof, reference);
  EXPECT_NEAR(d.largest_of_mesh(), 0.4, 1e-12);
  EXPECT_NEAR(d.largest_of_mesh(), c.relative_distance_to_reference * c.reference_diagonal, 1e-9);
  EXPECT_NEAR(d.largest_of_reference(), c.relative_distance_from_reference * c.reference_diagonal, 1e-3);
}

TEST(FaceDeviations, RefusesAnEmptyMesh)
{
  const Mesh m = grid(2), empty;
  EXPECT_THROW(CR::face_deviations(empty, m), CR::Error);
  EXPECT_THROW(CR::face_deviations(m, empty), CR::Error);
}

namespace {

// The apex of a 15-degree wedge and the ends of its base, 10 from the apex and 2 * 1.3165 long.
const Point wedge_apex(0, 0, 0), wedge_left(10, -1.3165, 0), wedge_right(10, 1.3165, 0);

} // namespace

TEST(AnglesAtSharpCorners, OnlyTheAnglesAtTheNarrowCornerAreForced)
{
  const Mesh reference = single_triangle(wedge_apex, wedge_left, wedge_right);
  // The wedge cut into three by a point just inside its base: two triangles keep 7.5 degrees at
  // the apex, the third has about 4 degrees at the base's ends, whose corners are 82.5 degrees wide.
  Mesh mesh;
  const auto a = mesh.add_vertex(wedge_apex), l = mesh.add_vertex(wedge_left), r = mesh.add_vertex(wedge_right),
             p = mesh.add_vertex(Point(9.9, 0, 0));
  mesh.add_face(a, l, p);
  mesh.add_face(a, p, r);
  mesh.add_face(l, r, p);

  const CR::Sharp_corner_angles same = CR::angles_at_sharp_corners(reference, reference);
  EXPECT_EQ(same.sharp_corners, 1u);
  EXPECT_EQ(same.triangles_below, 1u);
  EXPECT_EQ(same.triangles_below_at_sharp_corners, 1u);
  EXPECT_EQ(same.share_below_away_from_sharp_corners(), 0.);

  const CR::Sharp_corner_angles cut = CR::angles_at_sharp_corners(mesh, reference);
  EXPECT_EQ(cut.triangles, 3u);
  EXPECT_EQ(cut.triangles_below, 3u);
  EXPECT_EQ(cut.triangles_below_at_sharp_corners, 2u);
  EXPECT_DOUBLE_EQ(cut.share_below_away_from_sharp_corners(), 1. / 3.);
  // Below 5 degrees only the base's triangle is small, and not at a sharp corner.
  const CR::Sharp_corner_angles five = CR::angles_at_sharp_corners(mesh, reference, 5.);
  EXPECT_EQ(five.sharp_corners, 0u);
  EXPECT_EQ(five.triangles_below, 1u);
  EXPECT_EQ(five.triangles_below_at_sharp_corners, 0u);
}

TEST(AnglesAtSharpCorners, SharpEdgesBoundTheSectorsOfAClosedWedge)
{
  // A closed prism over the wedge, 10 long: at each apex the cap's sector is 15 degrees between
  // two sharp edges, the side walls' sectors 90 degrees. The narrow wall under the base is cut
  // into triangles of about 15 degrees whose small angles sit at the base's ends, in walls
  // 90 degrees wide: not forced.
  Mesh prism;
  std::array<Mesh::Vertex_index, 6> v;
  const std::array<Point, 3> section{{wedge_apex, wedge_left, wedge_right}};
  for(int i = 0; i < 3; ++i)
  {
    v[i] = prism.add_vertex(Point(section[i].x(), section[i].y(), 0));
    v[i + 3] = prism.add_vertex(Point(section[i].x(), section[i].y(), 10));
  }
  prism.add_face(v[0], v[2], v[1]);
  prism.add_face(v[3], v[4], v[5]);
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3;
    prism.add_face(v[i], v[j], v[j + 3]);
    prism.add_face(v[i], v[j + 3], v[i + 3]);
  }
  ASSERT_TRUE(CGAL::is_closed(prism));

  const CR::Sharp_corner_angles a = CR::angles_at_sharp_corners(prism, prism);
  EXPECT_EQ(a.sharp_corners, 2u);
  EXPECT_EQ(a.triangles_below, 4u); // the two caps and the two triangles under the base
  EXPECT_EQ(a.triangles_below_at_sharp_corners, 2u);
  // Without sharp edges (a features angle above every turn) no corner is narrower than 25 degrees.
  const CR::Sharp_corner_angles smooth =
    CR::angles_at_sharp_corners(prism, prism, 25., CR::parameters::features_angle(179.));
  EXPECT_EQ(smooth.sharp_corners, 0u);
  EXPECT_EQ(smooth.triangles_below_at_sharp_corners, 0u);
}

TEST(AnglesAtSharpCorners, RefusesFacesThatAreNotTriangles)
{
  Mesh square;
  square.add_face(square.add_vertex(Point(0, 0, 0)), square.add_vertex(Point(1, 0, 0)), square.add_vertex(Point(1, 1, 0)),
                  square.add_vertex(Point(0, 1, 0)));
  const Mesh triangle = single_triangle(wedge_apex, wedge_left, wedge_right);
  const std::pair<const Mesh*, const Mesh*> pairs[] = {{&square, &triangle}, {&triangle, &square}};
  for(const auto& meshes : pairs)
  {
    try
    {
      CR::angles_at_sharp_corners(*meshes.first, *meshes.second);
      ADD_FAILURE() << "a quadrangle was measured";
    }
    catch(const CR::Error& e)
    {
      EXPECT_EQ(e.code(), CR::Error_code::INVALID_INPUT);
      EXPECT_NE(std::string(e.what()).find("triangle meshes"), std::string::npos);
    }
  }
}
