// Tests of the input checks (check_polygon_soup, check_mesh) and of the readers.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::vector<std::vector<std::size_t> > Polygons;

namespace {

// A closed, outward-oriented tetrahedron.
std::vector<Point> tetrahedron_points()
{
  return {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
}
Polygons tetrahedron_faces() { return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}; }

CR::Mesh_check_report check(const std::vector<Point>& points, const Polygons& polygons)
{
  return CR::check_polygon_soup<K>(points, polygons);
}

// Expects `report` to hold exactly the defect `d`, `count` times.
void expect_only(const CR::Mesh_check_report& report, CR::Mesh_defect d, std::size_t count)
{
  ASSERT_EQ(report.defects.size(), 1u) << report.summary();
  EXPECT_EQ(report.defects[0].defect, d) << report.summary();
  EXPECT_EQ(report.defects[0].count, count) << report.summary();
  EXPECT_FALSE(report.defects[0].example.empty());
  EXPECT_FALSE(report.is_valid());
  EXPECT_NE(report.summary().find(CR::defect_name(d, count)), std::string::npos) << report.summary();
}

std::filesystem::path scratch_dir()
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "conformal_remeshing_test_input_checks";
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
}

} // namespace

TEST(SoupChecks, ValidTetrahedron)
{
  const CR::Mesh_check_report r = check(tetrahedron_points(), tetrahedron_faces());
  EXPECT_TRUE(r.is_valid()) << r.summary();
  EXPECT_EQ(r.summary(), "valid");
  EXPECT_EQ(r.number_of_vertices, 4u);
  EXPECT_EQ(r.number_of_faces, 4u);
}

TEST(SoupChecks, EmptyMesh)
{
  expect_only(check({}, {}), CR::Mesh_defect::EMPTY_MESH, 1);
}

TEST(SoupChecks, NonFiniteCoordinates)
{
  std::vector<Point> points = tetrahedron_points();
  points[2] = Point(0, std::numeric_limits<double>::quiet_NaN(), 0);
  points[3] = Point(0, 0, std::numeric_limits<double>::infinity());
  expect_only(check(points, tetrahedron_faces()), CR::Mesh_defect::NON_FINITE_COORDINATES, 2);
}

TEST(SoupChecks, InvalidVertexIndex)
{
  Polygons faces = tetrahedron_faces();
  faces[1][2] = 7;
  const CR::Mesh_check_report r = check(tetrahedron_points(), faces);
  EXPECT_EQ(r.count(CR::Mesh_defect::INVALID_VERTEX_INDEX), 1u) << r.summary();
  EXPECT_NE(r.summary().find("refers to vertex 7"), std::string::npos) << r.summary();
}

TEST(SoupChecks, NonTriangleFaces)
{
  // A closed cube made of six quads: manifold and oriented, only the face size is wrong.
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                                     Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), Point(0, 1, 1)};
  const Polygons quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  expect_only(check(points, quads), CR::Mesh_defect::NON_TRIANGLE_FACE, 6);
}

TEST(SoupChecks, DegenerateFaceByExactPredicate)
{
  // A flat tetrahedron whose face (0, 1, 2) has three exactly collinear vertices.
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(0, 1, 0)};
  expect_only(check(points, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}), CR::Mesh_defect::DEGENERATE_FACE, 1);

  // Nearly collinear is not collinear: exact predicates tell the difference.
  const std::vector<Point> almost = {Point(0, 0, 0), Point(1, 1e-300, 0), Point(2, 0, 0), Point(0, 1, 0)};
  EXPECT_EQ(check(almost, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}).count(CR::Mesh_defect::DEGENERATE_FACE), 0u);
}

TEST(SoupChecks, RepeatedVertexInFace)
{
  const CR::Mesh_check_report r = check(tetrahedron_points(), {{0, 1, 1}});
  EXPECT_EQ(r.count(CR::Mesh_defect::DEGENERATE_FACE), 1u) << r.summary();
  EXPECT_NE(r.summary().find("repeats a vertex"), std::string::npos) << r.summary();
}

TEST(SoupChecks, DuplicatedVertices)
{
  // Two triangles of a square with the shared diagonal's vertices duplicated: a crack.
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0),
                                     Point(0, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  expect_only(check(points, {{0, 1, 2}, {3, 4, 5}}), CR::Mesh_defect::DUPLICATED_VERTEX, 2);
}

TEST(SoupChecks, IsolatedVertex)
{
  std::vector<Point> points = tetrahedron_points();
  points.push_back(Point(5, 5, 5));
  const CR::Mesh_check_report r = check(points, tetrahedron_faces());
  expect_only(r, CR::Mesh_defect::ISOLATED_VERTEX, 1);
  EXPECT_NE(r.summary().find("vertex 4"), std::string::npos);
}

TEST(SoupChecks, NonManifoldEdge)
{
  // Three triangles around the edge 0-1.
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1)};
  const CR::Mesh_check_report r = check(points, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_EQ(r.count(CR::Mesh_defect::NON_MANIFOLD_EDGE), 1u) << r.summary();
  EXPECT_NE(r.summary().find("shared by 3 faces"), std::string::npos) << r.summary();
}

TEST(SoupChecks, NonManifoldVertex)
{
  // Two triangles touching at vertex 0 only (a bow tie).
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(-1, 0, 0), Point(-1, -1, 0)};
  const CR::Mesh_check_report r = check(points, {{0, 1, 2}, {0, 3, 4}});
  expect_only(r, CR::Mesh_defect::NON_MANIFOLD_VERTEX, 1);
  EXPECT_NE(r.summary().find("vertex 0 joins 2"), std::string::npos) << r.summary();

  // The same two triangles joined by a third one across vertex 0 form a single fan.
  const CR::Mesh_check_report joined = check(points, {{0, 1, 2}, {0, 3, 4}, {0, 2, 3}});
  EXPECT_TRUE(joined.is_valid()) << joined.summary();
}

TEST(SoupChecks, InconsistentOrientation)
{
  Polygons faces = tetrahedron_faces();
  std::swap(faces[2][0], faces[2][1]); // flip one face of a closed surface: its 3 edges disagree
  expect_only(check(tetrahedron_points(), faces), CR::Mesh_defect::INCONSISTENT_ORIENTATION, 3);
}

TEST(SoupChecks, MoebiusStripIsNonOrientable)
{
  // A strip of n quads (two triangles each) whose ends are glued with a half twist.
  const int n = 12;
  std::vector<Point> points;
  for(int i = 0; i < n; ++i)
  {
    const double t = 2 * CGAL_PI * i / n;
    for(int side : {-1, 1})
    {
      const double s = 0.3 * side;
      points.emplace_back((1 + s * std::cos(t / 2)) * std::cos(t), (1 + s * std::cos(t / 2)) * std::sin(t), s * std::sin(t / 2));
    }
  }
  Polygons faces;
  for(int i = 0; i < n; ++i)
  {
    const std::size_t a = 2 * i, b = 2 * i + 1;
    // After a full turn the two sides are swapped.
    const std::size_t c = (i + 1 < n) ? 2 * (i + 1) : 1;
    const std::size_t d = (i + 1 < n) ? 2 * (i + 1) + 1 : 0;
    faces.push_back({a, c, b});
    faces.push_back({b, c, d});
  }
  const CR::Mesh_check_report r = check(points, faces);
  expect_only(r, CR::Mesh_defect::NON_ORIENTABLE, 1);

  // Without the twist, the same construction is an orientable annulus.
  Polygons annulus;
  for(int i = 0; i < n; ++i)
  {
    const std::size_t a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % n), d = 2 * ((i + 1) % n) + 1;
    annulus.push_back({a, c, b});
    annulus.push_back({b, c, d});
  }
  EXPECT_TRUE(check(points, annulus).is_valid()) << check(points, annulus).summary();
}

TEST(MeshChecks, TopologyOfTorusAndDisc)
{
  // A torus from a grid: genus 1, closed.
  Mesh torus;
  const int nu = 24, nv = 12;
  std::vector<Mesh::Vertex_index> vs;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double u = 2 * CGAL_PI * i / nu, v = 2 * CGAL_PI * j / nv;
      vs.push_back(torus.add_vertex(Point((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v))));
    }
  auto at = [&](int i, int j) { return vs[(i % nu) * nv + (j % nv)]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      torus.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      torus.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  const CR::Mesh_check_report r = CR::check_mesh(torus);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  ASSERT_TRUE(r.topology_available);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].euler_characteristic, 0);
  EXPECT_EQ(r.components[0].genus, 1);
  EXPECT_EQ(r.components[0].boundary_loops, 0u);
  EXPECT_EQ(r.components[0].faces, std::size_t(2 * nu * nv));

  // Add a separate disc (a single triangle): a second component with one boundary loop.
  const auto a = torus.add_vertex(Point(10, 0, 0)), b = torus.add_vertex(Point(11, 0, 0)), c = torus.add_vertex(Point(10, 1, 0));
  torus.add_face(a, b, c);
  const CR::Mesh_check_report two = CR::check_mesh(torus);
  ASSERT_EQ(two.components.size(), 2u);
  EXPECT_EQ(two.total_genus(), 1);
  EXPECT_EQ(two.total_boundary_loops(), 1u);
}

TEST(MeshChecks, DefectsInASurfaceMesh)
{
  Mesh mesh;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), mesh);
  EXPECT_TRUE(CR::check_mesh(mesh).is_valid());

  mesh.add_vertex(Point(0, 0, 0)); // isolated, and a duplicate of vertex 0
  const CR::Mesh_check_report r = CR::check_mesh(mesh);
  EXPECT_EQ(r.count(CR::Mesh_defect::ISOLATED_VERTEX), 1u) << r.summary();
  EXPECT_EQ(r.count(CR::Mesh_defect::DUPLICATED_VERTEX), 1u) << r.summary();

  Mesh empty;
  EXPECT_EQ(CR::check_mesh(empty).count(CR::Mesh_defect::EMPTY_MESH), 1u);
}


TEST(MeshChecks, RemeshingRefusesWhatItCannotRepair)
{
  CR::Mesh_check_report r;
  for(CR::Mesh_defect d : {CR::Mesh_defect::DUPLICATED_VERTEX, CR::Mesh_defect::NON_MANIFOLD_VERTEX,
                           CR::Mesh_defect::DEGENERATE_FACE, CR::Mesh_defect::NON_MANIFOLD_EDGE})
    r.defects.push_back(CR::Defect_summary{d, 2, "an example"});
  const CR::Mesh_check_report repaired = r.refused_by_remeshing(true), as_it_is = r.refused_by_remeshing(false);
  ASSERT_EQ(repaired.defects.size(), 1u) << repaired.summary();
  EXPECT_EQ(repaired.count(CR::Mesh_defect::NON_MANIFOLD_EDGE), 2u);
  EXPECT_EQ(as_it_is.defects.size(), 3u) << as_it_is.summary();
  EXPECT_EQ(as_it_is.count(CR::Mesh_defect::DUPLICATED_VERTEX), 0u) << "coincident vertices are never refused";
  EXPECT_EQ(as_it_is.count(CR::Mesh_defect::DEGENERATE_FACE), 2u);
}
// --- readers --------------------------------------------------------------------------------

class Readers : public ::testing::TestWithParam<std::string> {};

TEST_P(Readers, RoundTripOfEveryFormat)
{
  // GetParam(): "<extension>" or "<extension>-binary".
  const std::string name = GetParam();
  const bool binary = name.find("-binary") != std::string::npos;
  const std::string extension = name.substr(0, name.find('-'));
  const std::filesystem::path file = scratch_dir() / ("tetrahedron_" + name + "." + extension);

  ASSERT_TRUE(CGAL::IO::write_polygon_soup(file.string(), tetrahedron_points(), tetrahedron_faces(),
                                           CGAL::parameters::use_binary_mode(binary).stream_precision(17)));
  Mesh mesh;
  const CR::Mesh_check_report r = CR::read_and_check_mesh(file.string(), mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  ASSERT_TRUE(r.topology_available);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].genus, 0);
  EXPECT_EQ(r.components[0].euler_characteristic, 2);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, Readers,
                         ::testing::Values("off", "obj", "ply", "ply-binary", "stl", "stl-binary"));

TEST(Readers, StlTriangleSoupIsMergedIntoAMesh)
{
  // ASCII STL stores every triangle with its own three corners.
  std::string stl = "solid tetra\n";
  const std::vector<Point> p = tetrahedron_points();
  for(const auto& f : tetrahedron_faces())
  {
    stl += "facet normal 0 0 0\nouter loop\n";
    for(std::size_t v : f)
      stl += "vertex " + std::to_string(p[v].x()) + " " + std::to_string(p[v].y()) + " " + std::to_string(p[v].z()) + "\n";
    stl += "endloop\nendfacet\n";
  }
  stl += "endsolid tetra\n";
  const std::filesystem::path file = scratch_dir() / "soup.stl";
  write_text(file, stl);
  Mesh mesh;
  const CR::Mesh_check_report r = CR::read_and_check_mesh(file.string(), mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(r.components.at(0).genus, 0);
  EXPECT_EQ(r.components.at(0).boundary_loops, 0u);
}

TEST(Readers, DefectiveSoupIsReportedNotBuilt)
{
  const std::filesystem::path file = scratch_dir() / "non_manifold_edge.off";
  write_text(file, "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  Mesh mesh;
  const CR::Mesh_check_report r = CR::read_and_check_mesh(file.string(), mesh);
  EXPECT_EQ(r.count(CR::Mesh_defect::NON_MANIFOLD_EDGE), 1u) << r.summary();
  EXPECT_FALSE(r.topology_available);
  EXPECT_EQ(mesh.number_of_faces(), 0u);
}

// --- repairs (Input_repairs) ------------------------------------------------------------------

namespace {
// A file read with every repair: the mesh, what was repaired, and the checks after.
struct Repaired_read
{
  Mesh mesh;
  CR::Input_repair_report repaired;
  CR::Mesh_check_report checks;
};

Repaired_read read_repaired(const std::filesystem::path& file)
{
  Repaired_read r;
  r.checks = CR::read_and_check_mesh(file.string(), r.mesh, CR::Input_repairs::all(), r.repaired);
  return r;
}

std::filesystem::path test_data(const std::string& name) { return std::filesystem::path(CONFORMAL_REMESHING_TEST_DATA) / name; }
} // namespace

TEST(InputRepairs, QuadCubeIsTriangulatedWithTheSameSurface)
{
  const Repaired_read r = read_repaired(test_data("non_triangle_cube.off"));
  ASSERT_TRUE(r.checks.is_valid()) << r.checks.summary();
  EXPECT_EQ(r.repaired.file_faces, 6u);
  EXPECT_EQ(r.repaired.triangulated_polygons, 6u);
  EXPECT_EQ(r.repaired.triangles_from_polygons, 12u);
  EXPECT_EQ(r.repaired.summary(), "6 polygons triangulated into 12 triangles");
  ASSERT_EQ(r.mesh.number_of_faces(), 12u);
  EXPECT_EQ(r.mesh.number_of_vertices(), 8u); // no vertex added
  EXPECT_TRUE(CGAL::is_closed(r.mesh));
  EXPECT_EQ(r.checks.components.at(0).genus, 0);
  // The same surface: the unit cube's area and volume, outward like the file's quads.
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::area(r.mesh), 6., 1e-12);
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::volume(r.mesh), 1., 1e-12);
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::is_outward_oriented(r.mesh));
  // Each quad became two triangles, and each triangle says which quad it is part of.
  ASSERT_EQ(r.repaired.file_face.size(), 12u);
  std::vector<int> triangles_of(6, 0);
  for(std::size_t f : r.repaired.file_face)
    ++triangles_of.at(f);
  EXPECT_EQ(triangles_of, std::vector<int>(6, 2));
  // Without the repair, the same file is refused.
  Mesh strict;
  EXPECT_EQ(CR::read_and_check_mesh(test_data("non_triangle_cube.off").string(), strict).count(CR::Mesh_defect::NON_TRIANGLE_FACE),
            6u);
}

TEST(InputRepairs, InconsistentFacesTakeTheOrientationOfMostOfTheirComponent)
{
  // The tetrahedron of `inconsistent_orientation.off` has one face flipped: that face is
  // reoriented, not the three others.
  const Repaired_read one = read_repaired(test_data("inconsistent_orientation.off"));
  ASSERT_TRUE(one.checks.is_valid()) << one.checks.summary();
  EXPECT_EQ(one.repaired.reoriented_faces, 1u);
  EXPECT_EQ(one.repaired.summary(), "1 face reoriented");
  EXPECT_TRUE(CGAL::is_closed(one.mesh));
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::is_outward_oriented(one.mesh));

  // Three of four faces flipped: the whole component follows the three.
  Polygons faces = tetrahedron_faces();
  for(std::size_t f : {0, 1, 2})
    std::reverse(faces[f].begin(), faces[f].end());
  const std::filesystem::path file = scratch_dir() / "mostly_inward.off";
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(file.string(), tetrahedron_points(), faces));
  const Repaired_read three = read_repaired(file);
  ASSERT_TRUE(three.checks.is_valid()) << three.checks.summary();
  EXPECT_EQ(three.repaired.reoriented_faces, 1u);
  EXPECT_FALSE(CGAL::Polygon_mesh_processing::is_outward_oriented(three.mesh));
}

TEST(InputRepairs, IsolatedVertexIsRemoved)
{
  const Repaired_read r = read_repaired(test_data("isolated_vertex.off"));
  ASSERT_TRUE(r.checks.is_valid()) << r.checks.summary();
  EXPECT_EQ(r.repaired.removed_isolated_vertices, 1u);
  EXPECT_EQ(r.mesh.number_of_vertices(), 4u);
  EXPECT_EQ(r.mesh.number_of_faces(), 4u);
}

TEST(InputRepairs, BordersAlongTheSamePointsAreStitched)
{
  // A square in two triangles whose diagonal's vertices are written twice: a crack, stitched.
  const std::filesystem::path crack = scratch_dir() / "square_crack.off";
  write_text(crack, "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 3 4 5\n");
  const Repaired_read stitched = read_repaired(crack);
  ASSERT_TRUE(stitched.checks.is_valid()) << stitched.checks.summary();
  EXPECT_EQ(stitched.repaired.stitched_vertices, 2u);
  EXPECT_EQ(stitched.repaired.summary(), "2 vertices stitched along borders");
  EXPECT_EQ(stitched.mesh.number_of_vertices(), 4u);
  EXPECT_EQ(stitched.checks.total_boundary_loops(), 1u);
  EXPECT_EQ(stitched.repaired.file_face, (std::vector<std::size_t>{0, 1}));

  // Two triangles that touch at one point written twice: no border edge to join, so the
  // duplicated vertex is still reported (merging it would pinch two sheets together).
  const std::filesystem::path pinch = scratch_dir() / "touching_triangles.off";
  write_text(pinch, "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 3 4 5\n");
  const Repaired_read touching = read_repaired(pinch);
  EXPECT_EQ(touching.repaired.stitched_vertices, 0u);
  EXPECT_EQ(touching.checks.count(CR::Mesh_defect::DUPLICATED_VERTEX), 1u) << touching.checks.summary();
}

TEST(InputRepairs, WhatCannotBeRepairedIsStillReported)
{
  // A Moebius strip cannot be oriented without cutting it: it stays as it is, refused.
  const Repaired_read moebius = read_repaired(test_data("moebius.off"));
  EXPECT_EQ(moebius.checks.count(CR::Mesh_defect::NON_ORIENTABLE), 1u) << moebius.checks.summary();
  EXPECT_FALSE(moebius.repaired.any()) << moebius.repaired.summary();
  EXPECT_EQ(moebius.repaired.summary(), "nothing repaired");
  // A non-manifold edge is cut apart: each of its three faces gets its own copy of it, and the
  // copies are not stitched back.
  const Repaired_read fin = read_repaired(test_data("non_manifold_edge.off"));
  EXPECT_EQ(fin.checks.count(CR::Mesh_defect::NON_MANIFOLD_EDGE), 0u) << fin.checks.summary();
  EXPECT_EQ(fin.repaired.split_vertices, 4u) << fin.repaired.summary();
  EXPECT_EQ(fin.repaired.stitched_vertices, 0u);
  EXPECT_TRUE(fin.checks.is_manifold_surface()) << fin.checks.summary();

  // Polygons CGAL's triangulation cannot cut are left as they are: one with a corner at NaN,
  // one whose corners are collinear, one that visits a vertex twice; a good square is cut.
  const std::filesystem::path file = scratch_dir() / "uncuttable_polygons.off";
  write_text(file, "OFF\n9 4 0\n0 0 0\n1 0 0\n1 1 0\nnan 1 0\n2 0 0\n3 0 0\n4 0 0\n0 -1 0\n1 -1 0\n"
                   "4 0 1 2 3\n4 1 4 5 6\n5 0 1 8 1 7\n4 0 7 8 1\n");
  const Repaired_read polygons = read_repaired(file);
  EXPECT_EQ(polygons.repaired.triangulated_polygons, 1u) << polygons.repaired.summary();
  EXPECT_EQ(polygons.checks.count(CR::Mesh_defect::NON_TRIANGLE_FACE), 3u) << polygons.checks.summary();
  EXPECT_EQ(polygons.repaired.file_face, (std::vector<std::size_t>{0, 1, 2, 3, 3}));

  // Inconsistent orientation beside a triangle with two equal corners: CGAL's orienter never
  // returned on such a soup (found by fuzzing), so it is not oriented, and both are reported.
  const std::filesystem::path twice = scratch_dir() / "corner_twice.off";
  write_text(twice, "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 2 2 3\n");
  const Repaired_read corner_twice = read_repaired(twice);
  EXPECT_EQ(corner_twice.repaired.reoriented_faces, 0u);
  EXPECT_GT(corner_twice.checks.count(CR::Mesh_defect::INCONSISTENT_ORIENTATION), 0u) << corner_twice.checks.summary();
  EXPECT_GT(corner_twice.checks.count(CR::Mesh_defect::DEGENERATE_FACE), 0u) << corner_twice.checks.summary();
}

namespace {
// Expects read_and_check_mesh to throw an Error with `code` whose message names the file
// and contains `reason`.
void expect_read_error(const std::filesystem::path& file, CR::Error_code code, const std::string& reason)
{
  Mesh mesh;
  try
  {
    CR::read_and_check_mesh(file.string(), mesh);
    ADD_FAILURE() << "no error for " << file;
  }
  catch(const CR::Error& e)
  {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
  }
}
} // namespace

TEST(Readers, UnreadableFilesNameTheFileAndTheReason)
{
  const std::filesystem::path dir = scratch_dir();
  expect_read_error(dir / "does_not_exist.off", CR::Error_code::FILE_NOT_READABLE, "No such file");
  expect_read_error(dir / "mesh.xyz", CR::Error_code::UNSUPPORTED_FORMAT, "unsupported file extension '.xyz'");

  write_text(dir / "empty_file.off", "");
  expect_read_error(dir / "empty_file.off", CR::Error_code::FILE_NOT_READABLE, "empty");

  const std::vector<std::pair<std::string, std::string> > garbage = {
    {"garbage.off", "this is not a mesh\n"},
    {"truncated.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n"},
    {"garbage.obj", "v 0 0 0\nv 1 0 0\nf 1 2 x\n"},
    {"garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\nnot numbers\n"},
    {"truncated.stl", std::string("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0")},
  };
  for(const auto& g : garbage)
  {
    write_text(dir / g.first, g.second);
    expect_read_error(dir / g.first, CR::Error_code::FILE_NOT_READABLE, "not a valid");
  }
}

// --- hostile inputs -----------------------------------------------------------------------------
// Every crafted file of data/hostile has a defined outcome: an Error naming the file and the
// reason, or a report of its defects and topology (with a mesh when the soup is one).

namespace {

std::filesystem::path hostile(const std::string& name)
{
  return std::filesystem::path(CONFORMAL_REMESHING_TEST_DATA) / "hostile" / name;
}

// Reads a hostile file that holds a polygon soup, and checks that the reader's report and
// check_mesh() on the mesh it built agree.
CR::Mesh_check_report read_hostile(const std::string& name, Mesh& mesh)
{
  const CR::Mesh_check_report r = CR::read_and_check_mesh(hostile(name).string(), mesh);
  if(r.topology_available)
  {
    const CR::Mesh_check_report again = CR::check_mesh(mesh);
    EXPECT_EQ(again.summary(), r.summary()) << name;
    EXPECT_EQ(again.components.size(), r.components.size()) << name;
    EXPECT_EQ(again.total_genus(), r.total_genus()) << name;
    EXPECT_EQ(again.total_boundary_loops(), r.total_boundary_loops()) << name;
  }
  else
    EXPECT_EQ(mesh.number_of_faces(), 0u) << name;
  return r;
}

} // namespace

TEST(HostileInputs, TruncatedAndGarbageFilesOfEveryFormat)
{
  for(const char* name : {"truncated_binary.off", "truncated.obj", "truncated_ascii.ply", "truncated_binary.ply",
                          "truncated_binary.stl", "garbage.obj", "garbage.stl", "garbage_binary.ply"})
    expect_read_error(hostile(name), CR::Error_code::FILE_NOT_READABLE, "not a valid");
  // A face cut short is named.
  expect_read_error(hostile("truncated.obj"), CR::Error_code::FILE_NOT_READABLE, "face 2 has fewer than 3 vertices");
}

TEST(HostileInputs, CountsTheFileCannotHoldAreRefusedAtOnce)
{
  // Each of these made CGAL 5.5's readers ask for gigabytes, read billions of records past the
  // end of the file, or convert a negative number to an index (found by fuzz/fuzz_read_mesh).
  for(const char* name : {"huge_counts.off", "huge_face.off", "huge_face_binary.off", "negative_index.off",
                          "huge_count.ply", "huge_list.ply", "property_before_element.ply"})
  {
    const auto start = std::chrono::steady_clock::now();
    expect_read_error(hostile(name), CR::Error_code::FILE_NOT_READABLE, "not a valid");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.) << name;
  }
}

TEST(HostileInputs, NonFiniteCoordinates)
{
  // OFF, PLY (ASCII and binary) and binary STL readers keep NaN and infinity for the checks ...
  for(const char* name : {"nan.off", "nan_ascii.ply", "nan_binary.ply"})
  {
    Mesh mesh;
    const CR::Mesh_check_report r = read_hostile(name, mesh);
    expect_only(r, CR::Mesh_defect::NON_FINITE_COORDINATES, 1);
    EXPECT_NE(r.summary().find("vertex 2 at (0, nan, 0)"), std::string::npos) << name << ": " << r.summary();
  }
  // ... while CGAL's OBJ and ASCII STL readers refuse the spellings "nan" and "inf".
  expect_read_error(hostile("nan.obj"), CR::Error_code::FILE_NOT_READABLE, "not a valid OBJ file");
  expect_read_error(hostile("inf_ascii.stl"), CR::Error_code::FILE_NOT_READABLE, "not a valid STL file");
}

TEST(HostileInputs, ZeroAreaAndCollinearFaces)
{
  Mesh mesh;
  // Collinear by exact predicates at coordinates around 1e6, where a floating-point orientation
  // test would be at the mercy of rounding.
  CR::Mesh_check_report r = read_hostile("collinear_face_1e6.off", mesh);
  expect_only(r, CR::Mesh_defect::DEGENERATE_FACE, 1);
  EXPECT_TRUE(r.topology_available);

  // 1e-9 off the line over a length of 2e6: a sliver, not a degenerate face, and measurable.
  r = read_hostile("near_collinear_face.off", mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  const CR::Mesh_quality_report q = CR::mesh_quality(mesh);
  EXPECT_GT(q.minimum_angle.min, 0.);
  EXPECT_LT(q.minimum_angle.min, 1e-9);
  EXPECT_EQ(q.number_of_degenerate_faces, 0u);

  // A face through one vertex twice is one degenerate face, and nothing else.
  r = read_hostile("repeated_index_face.off", mesh);
  expect_only(r, CR::Mesh_defect::DEGENERATE_FACE, 1);
  EXPECT_NE(r.summary().find("repeats a vertex"), std::string::npos) << r.summary();
  EXPECT_FALSE(r.topology_available);
}

TEST(HostileInputs, NearDuplicatedVerticesAreDistinct)
{
  // Only exactly equal positions are duplicates; corners 1e-12 apart leave a crack, which the
  // topology shows: two triangles, two components, two boundary loops.
  Mesh mesh;
  const CR::Mesh_check_report r = read_hostile("near_duplicated_vertices.off", mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  ASSERT_EQ(r.components.size(), 2u);
  EXPECT_EQ(r.total_boundary_loops(), 2u);
  EXPECT_EQ(mesh.number_of_vertices(), 6u);
}

TEST(HostileInputs, CoordinatesFrom1eMinus6To1e6)
{
  // A unit-shaped tetrahedron scaled to 1e-6 at 1e6 from the origin, and scaled to 1e6: valid,
  // and the same angles as the unit tetrahedron (90, 45, 45 and 60 degrees).
  for(const char* name : {"tiny_far_tetrahedron.off", "huge_tetrahedron.off"})
  {
    Mesh mesh;
    const CR::Mesh_check_report r = read_hostile(name, mesh);
    EXPECT_TRUE(r.is_valid()) << name << ": " << r.summary();
    EXPECT_EQ(r.total_genus(), 0) << name;
    const CR::Mesh_quality_report q = CR::mesh_quality(mesh);
    EXPECT_NEAR(q.minimum_angle.min, 45., 0.01) << name;
    EXPECT_NEAR(q.maximum_angle.max, 90., 0.01) << name;
  }
}

TEST(HostileInputs, SmallestBoundaries)
{
  // A single triangle, and a tetrahedron missing one face: boundary loops of 3 edges.
  Mesh mesh;
  CR::Mesh_check_report r = CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_TEST_DATA) + "/single_triangle.off", mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].boundary_loops, 1u);
  EXPECT_EQ(r.components[0].edges, 3u);
  EXPECT_EQ(r.components[0].euler_characteristic, 1);
  EXPECT_EQ(r.components[0].genus, 0);

  r = read_hostile("open_tetrahedron.off", mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].boundary_loops, 1u);
  EXPECT_EQ(r.components[0].edges, 6u);
  EXPECT_EQ(r.components[0].genus, 0);
}

TEST(HostileInputs, PolygonsAreReportedAsNonTriangleFaces)
{
  // Quads and polygons are read and reported; the remesher refuses them (it needs triangles).
  Mesh mesh;
  CR::Mesh_check_report r = read_hostile("pentagon.obj", mesh);
  expect_only(r, CR::Mesh_defect::NON_TRIANGLE_FACE, 1);
  EXPECT_NE(r.summary().find("face 0 has 5 vertices"), std::string::npos) << r.summary();
  r = read_hostile("quad_and_triangle.ply", mesh);
  expect_only(r, CR::Mesh_defect::NON_TRIANGLE_FACE, 1);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
}

TEST(HostileInputs, OffVariantsAndBinaryOff)
{
  // The header prefixes of OFF: colours and normals after the coordinates, homogeneous
  // coordinates, comments, counts on the keyword's line, and big-endian binary OFF.
  const std::filesystem::path dir = scratch_dir();
  const std::vector<std::pair<std::string, std::string> > variants = {
    {"colors.off", "COFF\n# comment\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n"
                   "3 0 2 1 255 0 0\n3 0 1 3\n3 1 2 3\n3 0 3 2 # last face\n"},
    {"normals.off", "NOFF 4 4 6\n0 0 0 -1 -1 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
    {"homogeneous.off", "4OFF\n4 4 0\n0 0 0 2\n2 0 0 2\n0 1 0 1\n0 0 3 3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
    {"dimension.off", "nOFF\n3\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"}};
  for(const auto& v : variants)
  {
    write_text(dir / v.first, v.second);
    Mesh mesh;
    const CR::Mesh_check_report r = CR::read_and_check_mesh((dir / v.first).string(), mesh);
    EXPECT_TRUE(r.is_valid()) << v.first << ": " << r.summary();
    ASSERT_EQ(mesh.number_of_vertices(), 4u) << v.first;
    EXPECT_EQ(mesh.point(Mesh::Vertex_index(3)), Point(0, 0, 1)) << v.first;
  }
  // Binary OFF, as Geomview defines it: big-endian int32 counts and float32 coordinates, and
  // each face followed by its number of colour components (here 0).
  std::string binary = "OFF BINARY\n";
  auto put32 = [&](std::uint32_t x) {
    for(int shift = 24; shift >= 0; shift -= 8)
      binary += char((x >> shift) & 0xff);
  };
  auto put_float = [&](float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put32(bits);
  };
  put32(4); put32(4); put32(0);
  for(const Point& p : tetrahedron_points())
  {
    put_float(float(p.x())); put_float(float(p.y())); put_float(float(p.z()));
  }
  for(const auto& f : tetrahedron_faces())
  {
    put32(3);
    for(std::size_t v : f)
      put32(std::uint32_t(v));
    put32(0);
  }
  write_text(dir / "binary.off", binary);
  Mesh mesh;
  const CR::Mesh_check_report r = CR::read_and_check_mesh((dir / "binary.off").string(), mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  // Cut one byte short, it is refused.
  write_text(dir / "binary_cut.off", binary.substr(0, binary.size() - 1));
  expect_read_error(dir / "binary_cut.off", CR::Error_code::FILE_NOT_READABLE, "not a valid OFF file");
}

TEST(HostileInputs, PlyWithOtherElementsAndTypes)
{
  // Faces before vertices, an extra element, double and short properties, big-endian lists.
  const std::filesystem::path dir = scratch_dir();
  write_text(dir / "reordered.ply",
             "ply\nformat ascii 1.0\ncomment faces first\nelement face 4\nproperty list uchar uint vertex_index\n"
             "element material 1\nproperty uchar red\nproperty list uchar float weights\n"
             "element vertex 4\nproperty short x\nproperty double y\nproperty float z\nproperty uchar alpha\nend_header\n"
             "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n255 2 0.5 0.5\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n");
  Mesh mesh;
  CR::Mesh_check_report r = CR::read_and_check_mesh((dir / "reordered.ply").string(), mesh);
  EXPECT_TRUE(r.is_valid()) << r.summary();
  EXPECT_EQ(mesh.number_of_faces(), 4u);

  // A face index beyond the vertices, or a fractional index, is refused.
  write_text(dir / "bad_index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expect_read_error(dir / "bad_index.ply", CR::Error_code::FILE_NOT_READABLE, "not a valid PLY file");
  write_text(dir / "fraction.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                   "property float z\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n"
                                   "0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n");
  expect_read_error(dir / "fraction.ply", CR::Error_code::FILE_NOT_READABLE, "not a valid PLY file");
}
