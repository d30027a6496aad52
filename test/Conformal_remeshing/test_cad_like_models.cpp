// Tests of the CAD-like model generators (generators/Conformal_remeshing), of the
// paper-scale models at a small size, and of the shipped default model
// examples/Conformal_remeshing/data/perforated_plate.off.

#include <cad_like_models.h>
#include <paper_models.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace PMP = CGAL::Polygon_mesh_processing;

// The parameters of the documented command that regenerates the default model
// (examples/Conformal_remeshing/data/README.md); spelled out so that a change of the struct's
// defaults cannot silently change what the shipped file is compared with.
bm::Perforated_plate_parameters default_model_parameters()
{
  bm::Perforated_plate_parameters p;
  p.length = 120.;
  p.width = 80.;
  p.thickness = 6.;
  p.corner_radius = 10.;
  p.segments_per_circle = 96;
  p.number_of_random_holes = 7;
  p.seed = 3;
  p.min_hole_radius = 3.;
  p.max_hole_radius = 10.;
  p.min_clearance = 3.;
  return p;
}

std::array<std::size_t, 3> face_vertices(const Mesh& mesh, Mesh::Face_index f)
{
  std::array<std::size_t, 3> v{};
  std::size_t i = 0;
  for(Mesh::Vertex_index w : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    if(i < 3)
      v[i] = std::size_t(w);
    ++i;
  }
  EXPECT_EQ(i, 3u);
  // Same cyclic order, starting at the smallest index: independent of the face's halfedge.
  std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
  return v;
}

// Every hard requirement on a generated model: closed and outward oriented without boundary
// loops, open otherwise.
void expect_valid_model(const Mesh& mesh, long genus, std::size_t boundary_loops)
{
  ASSERT_FALSE(mesh.is_empty());
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_triangle_mesh(mesh));
  EXPECT_EQ(CGAL::is_closed(mesh), boundary_loops == 0);
  for(Mesh::Vertex_index v : mesh.vertices())
    EXPECT_FALSE(PMP::is_non_manifold_vertex(v, mesh)) << "vertex " << v;

  std::size_t degenerate = 0;
  for(Mesh::Face_index f : mesh.faces()) {
    const std::array<std::size_t, 3> v = face_vertices(mesh, f);
    degenerate += CGAL::collinear(mesh.point(Mesh::Vertex_index(Mesh::size_type(v[0]))),
                                  mesh.point(Mesh::Vertex_index(Mesh::size_type(v[1]))),
                                  mesh.point(Mesh::Vertex_index(Mesh::size_type(v[2]))));
  }
  EXPECT_EQ(degenerate, 0u);

  std::vector<Point_3> points(mesh.points().begin(), mesh.points().end());
  std::sort(points.begin(), points.end());
  EXPECT_TRUE(std::adjacent_find(points.begin(), points.end()) == points.end()) << "duplicated vertex";

  EXPECT_FALSE(PMP::does_self_intersect(mesh));
  if(boundary_loops == 0)
    EXPECT_TRUE(PMP::is_outward_oriented(mesh));

  const bm::Cad_model_statistics s = bm::cad_model_statistics(mesh);
  EXPECT_EQ(s.components, 1u);
  EXPECT_EQ(s.boundary_loops, boundary_loops);
  EXPECT_EQ(s.genus, genus);
  EXPECT_EQ(s.euler_characteristic, 2 - 2 * genus - long(boundary_loops));
}

void expect_valid_closed_model(const Mesh& mesh, long genus) { expect_valid_model(mesh, genus, 0); }

bool same_mesh(const Mesh& a, const Mesh& b)
{
  if(a.number_of_vertices() != b.number_of_vertices() || a.number_of_faces() != b.number_of_faces())
    return false;
  for(Mesh::Vertex_index v : a.vertices())
    if(a.point(v) != b.point(v))
      return false;
  for(Mesh::Face_index f : a.faces())
    if(face_vertices(a, f) != face_vertices(b, f))
      return false;
  return true;
}

TEST(CadLikeModels, DefaultPlateIsValidAndFullOfSlivers)
{
  const bm::Perforated_plate_parameters p = default_model_parameters();
  Mesh mesh;
  bm::make_perforated_plate(mesh, p);
  expect_valid_closed_model(mesh, 7);

  const bm::Cad_model_statistics s = bm::cad_model_statistics(mesh);
  EXPECT_GE(s.faces, 2000u);
  EXPECT_LE(s.faces, 10000u);
  EXPECT_GT(s.share_min_angle_below_10, 0.6);
  EXPECT_GT(s.share_min_angle_below_1, 0.);
  EXPECT_LT(s.min_angle_degrees, 1.);
  EXPECT_GT(s.min_angle_degrees, 0.);
}

TEST(CadLikeModels, ExplicitHolesSharpCornersCoarseCircles)
{
  bm::Perforated_plate_parameters p;
  p.length = 50.;
  p.width = 30.;
  p.thickness = 2.;
  p.corner_radius = 0.;
  p.segments_per_circle = 8;
  // Vertically aligned holes of equal radius: many collinear vertex triples to avoid.
  p.holes = {{-15., 0., 4.}, {0., 0., 4.}, {15., 0., 4.}, {0., 10., 2.}};
  Mesh mesh;
  bm::make_perforated_plate(mesh, p);
  expect_valid_closed_model(mesh, 4);
}

TEST(CadLikeModels, ManySmallRandomHoles)
{
  bm::Perforated_plate_parameters p;
  p.length = 60.;
  p.width = 40.;
  p.thickness = 3.;
  p.corner_radius = 5.;
  p.segments_per_circle = 24;
  p.number_of_random_holes = 15;
  p.min_hole_radius = 1.;
  p.max_hole_radius = 3.;
  p.min_clearance = 1.;
  p.seed = 42;
  Mesh mesh;
  bm::make_perforated_plate(mesh, p);
  expect_valid_closed_model(mesh, 15);
}

TEST(CadLikeModels, SeveralSeedsAndNoHoles)
{
  for(std::uint64_t seed = 2; seed < 8; ++seed) {
    bm::Perforated_plate_parameters p = default_model_parameters();
    p.segments_per_circle = 32;
    p.seed = seed;
    Mesh mesh;
    bm::make_perforated_plate(mesh, p);
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_valid_closed_model(mesh, 7);
  }
  bm::Perforated_plate_parameters p = default_model_parameters();
  p.number_of_random_holes = 0;
  Mesh mesh;
  bm::make_perforated_plate(mesh, p);
  expect_valid_closed_model(mesh, 0);
}

TEST(CadLikeModels, Deterministic)
{
  const bm::Perforated_plate_parameters p = default_model_parameters();
  Mesh a, b;
  bm::make_perforated_plate(a, p);
  bm::make_perforated_plate(b, p);
  EXPECT_TRUE(same_mesh(a, b));

  bm::Perforated_plate_parameters q = p;
  q.seed = 4;
  Mesh c;
  bm::make_perforated_plate(c, q);
  EXPECT_FALSE(same_mesh(a, c));
}

TEST(CadLikeModels, InvalidParametersAreRefused)
{
  Mesh mesh;
  bm::Perforated_plate_parameters p = default_model_parameters();
  p.thickness = -1.;
  EXPECT_THROW(bm::make_perforated_plate(mesh, p), std::invalid_argument);

  p = default_model_parameters();
  p.corner_radius = 40.;
  EXPECT_THROW(bm::make_perforated_plate(mesh, p), std::invalid_argument);

  p = default_model_parameters();
  p.segments_per_circle = 3;
  EXPECT_THROW(bm::make_perforated_plate(mesh, p), std::invalid_argument);

  p = default_model_parameters();
  p.holes = {{0., 0., 10.}, {5., 0., 10.}};
  EXPECT_THROW(bm::make_perforated_plate(mesh, p), std::invalid_argument);

  p = default_model_parameters();
  p.number_of_random_holes = 200;
  p.max_placement_attempts = 2000;
  EXPECT_THROW(bm::make_perforated_plate(mesh, p), std::runtime_error);
}

TEST(CadLikeModels, SliverFanDisc)
{
  Mesh mesh;
  bm::make_sliver_fan_disc(mesh, 64, 2.);
  EXPECT_EQ(mesh.number_of_vertices(), 64u);
  EXPECT_EQ(mesh.number_of_faces(), 62u);
  EXPECT_FALSE(CGAL::is_closed(mesh));
  for(Mesh::Face_index f : mesh.faces()) {
    const std::array<std::size_t, 3> v = face_vertices(mesh, f);
    EXPECT_FALSE(CGAL::collinear(mesh.point(Mesh::Vertex_index(Mesh::size_type(v[0]))),
                                 mesh.point(Mesh::Vertex_index(Mesh::size_type(v[1]))),
                                 mesh.point(Mesh::Vertex_index(Mesh::size_type(v[2])))));
  }
  const bm::Cad_model_statistics s = bm::cad_model_statistics(mesh);
  EXPECT_NEAR(s.min_angle_degrees, 180. / 64., 1e-9);
  EXPECT_EQ(s.boundary_loops, 1u);
  EXPECT_EQ(s.genus, 0);
}

// --- paper-scale models (paper_models.h), at 10k vertices ---------------------------------------

void expect_valid_paper_model(bm::Paper_model model)
{
  const bm::Paper_model_info& info = bm::paper_model_info(model);
  SCOPED_TRACE(info.name);
  bm::Paper_model_parameters p;
  p.target_vertices = 10000;
  Mesh mesh;
  bm::make_paper_model(mesh, model, p);
  expect_valid_model(mesh, info.genus, info.boundary_loops);
  // The brake's halves are sized like the whole disc: two of its three vertex levels.
  const double expected = model == bm::Paper_model::brake_disc_upper_half || model == bm::Paper_model::brake_disc_lower_half
                            ? 10000. * 2. / 3. : 10000.;
  EXPECT_NEAR(double(mesh.number_of_vertices()), expected, 0.03 * expected);
  // Even this coarse, nearly half of the triangles or more are slivers, as in CAD exports (fewer
  // on the curved sheets, whose faces have interior points).
  EXPECT_GT(bm::cad_model_statistics(mesh).share_min_angle_below_10, 0.45);
}

TEST(PaperModels, SuspensionArm) { expect_valid_paper_model(bm::Paper_model::suspension_arm); }
TEST(PaperModels, Shield) { expect_valid_paper_model(bm::Paper_model::shield); }
TEST(PaperModels, RadiatorShell) { expect_valid_paper_model(bm::Paper_model::radiator_shell); }
TEST(PaperModels, Chassis) { expect_valid_paper_model(bm::Paper_model::chassis); }
TEST(PaperModels, BrakeDisc) { expect_valid_paper_model(bm::Paper_model::brake_disc); }
TEST(PaperModels, BrakeDiscUpperHalf) { expect_valid_paper_model(bm::Paper_model::brake_disc_upper_half); }
TEST(PaperModels, BrakeDiscLowerHalf) { expect_valid_paper_model(bm::Paper_model::brake_disc_lower_half); }

TEST(PaperModels, TopologyAsInThePaper)
{
  EXPECT_EQ(bm::paper_model_info(bm::Paper_model::brake_disc).genus, 83);
  EXPECT_EQ(bm::paper_model_info(bm::Paper_model::brake_disc_upper_half).boundary_loops, 84u);
  EXPECT_EQ(bm::paper_model_info(bm::Paper_model::brake_disc_lower_half).boundary_loops, 84u);
  for(const bm::Paper_model_info& info : bm::paper_models())
    EXPECT_EQ(bm::paper_model_from_name(info.name), info.model);
  EXPECT_THROW(bm::paper_model_from_name("brake"), std::invalid_argument);
}

// The mid-plane cut of the disc lies on its edges: the two halves are exactly its triangles.
TEST(PaperModels, BrakeHalvesAreTheDiscCutAtItsMidPlane)
{
  bm::Paper_model_parameters p;
  p.target_vertices = 5000;
  p.seed = 9;
  Mesh disc, upper, lower;
  bm::make_brake_disc(disc, p);
  bm::make_brake_disc_half(upper, p, true);
  bm::make_brake_disc_half(lower, p, false);
  auto triangles = [](const Mesh& mesh) {
    std::vector<std::array<Point_3, 3> > result;
    for(Mesh::Face_index f : mesh.faces()) {
      std::array<Point_3, 3> t;
      std::size_t i = 0;
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        t[i++] = mesh.point(v);
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); // keeps the orientation
      result.push_back(t);
    }
    return result;
  };
  std::vector<std::array<Point_3, 3> > whole = triangles(disc), halves = triangles(upper), below = triangles(lower);
  halves.insert(halves.end(), below.begin(), below.end());
  std::sort(whole.begin(), whole.end());
  std::sort(halves.begin(), halves.end());
  EXPECT_TRUE(whole == halves);
  for(const Mesh* half : {&upper, &lower})
    for(Mesh::Halfedge_index h : half->halfedges())
      if(half->is_border(h))
        EXPECT_EQ(half->point(half->target(h)).z(), 14.); // the mid-plane of the 28 mm disc
}

TEST(PaperModels, SizeKnobAndDeterminism)
{
  for(const bm::Paper_model_info& info : bm::paper_models()) {
    SCOPED_TRACE(info.name);
    bm::Paper_model_parameters p;
    p.target_vertices = 25000;
    Mesh a, b, c;
    bm::make_paper_model(a, info.model, p);
    bm::make_paper_model(b, info.model, p);
    EXPECT_TRUE(same_mesh(a, b));
    p.seed = 2;
    bm::make_paper_model(c, info.model, p);
    EXPECT_FALSE(same_mesh(a, c));
    const double whole = info.model == bm::Paper_model::brake_disc_upper_half ||
                         info.model == bm::Paper_model::brake_disc_lower_half ? 2. / 3. : 1.;
    EXPECT_NEAR(double(a.number_of_vertices()), whole * 25000., whole * 25000. * 0.02);
    EXPECT_GT(bm::cad_model_statistics(a).share_min_angle_below_10, 0.8);
  }
}

TEST(PaperModels, RoundedLoops)
{
  typedef bm::Rounded_loop Loop;
  // A rounded square: 4 quarter arcs of 2 segments each at 8 segments per turn, both ends kept.
  const Loop square = Loop::rounded_polygon({{{0., 0.}, {10., 0.}, {10., 10.}, {0., 10.}}}, {2., 2., 2., 2.});
  EXPECT_EQ(square.size(8), 12u);
  std::vector<bm::internal::Planar_point> inner, outer;
  square.sample(-1., 8, inner);
  square.sample(1., 8, outer);
  ASSERT_EQ(inner.size(), 12u);
  ASSERT_EQ(outer.size(), 12u);
  for(std::size_t i = 0; i < inner.size(); ++i) // offset copies lie 2 apart on common normals
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(inner[i], outer[i])), 2., 1e-12);
  EXPECT_EQ(Loop::slot(0., 0., 10., 0., 1.).size(8), 10u);
  EXPECT_EQ(Loop::circle(0., 0., 1.).size(8), 8u);

  EXPECT_THROW(Loop::rounded_polygon({{{0., 0.}, {0., 10.}, {10., 10.}, {10., 0.}}}, {1., 1., 1., 1.}),
               std::invalid_argument); // clockwise
  EXPECT_THROW(Loop(std::vector<Loop::Corner>{{0., 0., 4.}, {1., 0., -4.}}), std::invalid_argument); // no tangent
  EXPECT_THROW(square.sample(-2.5, 8, inner), std::invalid_argument); // the arcs would flip
  EXPECT_THROW(Loop::circle(0., 0., 0.), std::invalid_argument);
}

// A stale default model (generator changed, file not regenerated) fails here.
TEST(CadLikeModels, ShippedDefaultModelMatchesGenerator)
{
  const std::string path = std::string(CONFORMAL_REMESHING_EXAMPLE_DATA) + "/perforated_plate.off";
  Mesh shipped;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, shipped)) << "cannot read " << path;
  Mesh fresh;
  bm::make_perforated_plate(fresh, default_model_parameters());

  ASSERT_EQ(shipped.number_of_vertices(), fresh.number_of_vertices());
  ASSERT_EQ(shipped.number_of_faces(), fresh.number_of_faces());
  for(Mesh::Vertex_index v : fresh.vertices()) {
    const Point_3 &a = shipped.point(v), &b = fresh.point(v);
    for(int i = 0; i < 3; ++i)
      ASSERT_LE(std::abs(a[i] - b[i]), 1e-12 * std::max(1., std::abs(b[i])))
        << "vertex " << v << ", coordinate " << i;
  }
  for(Mesh::Face_index f : fresh.faces())
    ASSERT_EQ(face_vertices(shipped, f), face_vertices(fresh, f)) << "face " << f;
  expect_valid_closed_model(shipped, 7);
}

} // namespace

TEST(PaperModels, CurvedFacesStayCloseToTheirSurface)
{
  // The shield's levels are placed on z = height - f(x, y), f = (x^2 + y^2) / 840 - 0.15 y. An
  // edge within one level deviates from that surface by the sag of f along it; a fan of slivers
  // across the dome sagged up to 9 mm, crumpling the face. Exporters bound it: 0.1 mm between
  // grid points 18 mm apart, a little more on longer Delaunay edges near the outline.
  bm::Paper_model_parameters p;
  p.target_vertices = 13400;
  Mesh mesh;
  bm::make_paper_model(mesh, bm::Paper_model::shield, p);
  const auto f = [](double x, double y) { return (x * x + y * y) / 840. - 0.15 * y; };
  const auto height = [&](const Mesh::Point& q) { return q.z() + f(q.x(), q.y()); };
  double worst_sag = 0.;
  std::size_t within_levels = 0;
  for(auto e : mesh.edges())
  {
    const Mesh::Point a = mesh.point(mesh.source(mesh.halfedge(e))), b = mesh.point(mesh.target(mesh.halfedge(e)));
    if(std::abs(height(a) - height(b)) > 1e-9)
      continue; // a strip edge between two levels
    ++within_levels;
    worst_sag = (std::max)(worst_sag, std::abs(0.5 * (f(a.x(), a.y()) + f(b.x(), b.y())) - f(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y()))));
  }
  EXPECT_GT(within_levels, mesh.number_of_edges() / 2);
  EXPECT_LT(worst_sag, 0.3);
}
