// The input preparation of remesh_conformal(): coincident vertices kept as distinct points,
// non-manifold vertices split, degenerate faces removed, each repair reported; contacts at
// coincident vertices told apart from crossings.

#include "stage_tests.h"

#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cstdio>
#include <fstream>

namespace {

// A flat 10 x 10 grid of unit squares, triangulated, with the squares [3,4]x[3,4] and [4,5]x[4,5]
// removed: two holes that touch at the point (4, 4), a non-manifold vertex.
Mesh grid_with_touching_holes()
{
  Mesh mesh;
  CGAL::make_grid(10, 10, mesh, [](std::size_t i, std::size_t j) { return K::Point_3(double(i), double(j), 0.); }, true);
  std::vector<Mesh::Face_index> holes;
  for(Mesh::Face_index f : mesh.faces())
  {
    const K::Point_3 c = CGAL::centroid(mesh.point(mesh.target(mesh.halfedge(f))), mesh.point(mesh.target(mesh.next(mesh.halfedge(f)))),
                                        mesh.point(mesh.source(mesh.halfedge(f))));
    if((c.x() > 3. && c.x() < 4. && c.y() > 3. && c.y() < 4.) || (c.x() > 4. && c.x() < 5. && c.y() > 4. && c.y() < 5.))
      holes.push_back(f);
  }
  for(Mesh::Face_index f : holes)
    CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  mesh.collect_garbage();
  return mesh;
}

// The output is a valid manifold, with coincident vertices only where the input has them, no
// crossing faces, and every vertex on the input surface, as the verifier finds it.
void expect_valid_output(const Mesh& input, const Mesh& output, const std::vector<CR::Surface_location>& locations)
{
  const CR::Mesh_check_report out = CR::check_mesh(output);
  EXPECT_TRUE(out.is_manifold_surface()) << out.summary();
  EXPECT_FALSE(CR::internal::has_crossing_faces<CGAL::Sequential_tag>(output));
  const CR::Remesh_verification verification = CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_TRUE(verification.on_input_surface) << verification.summary();
  EXPECT_TRUE(verification.self_intersection_free) << verification.summary();
  ASSERT_EQ(locations.size(), output.number_of_vertices());
}

// `soup` written as an OFF file and read back with every repair.
Mesh read_repaired(const std::string& name, const std::vector<K::Point_3>& points,
                   const std::vector<std::vector<std::size_t> >& polygons, CR::Input_repair_report& repaired,
                   CR::Mesh_check_report& checks)
{
  const std::string file = testing::TempDir() + name + ".off";
  {
    std::ofstream out(file);
    out.precision(17);
    out << "OFF\n" << points.size() << " " << polygons.size() << " 0\n";
    for(const K::Point_3& p : points)
      out << p << "\n";
    for(const auto& polygon : polygons)
    {
      out << polygon.size();
      for(std::size_t v : polygon)
        out << " " << v;
      out << "\n";
    }
  }
  Mesh mesh;
  checks = CR::read_and_check_mesh(file, mesh, CR::Input_repairs::all(), repaired);
  std::remove(file.c_str());
  return mesh;
}

} // namespace

TEST(Contacts, FacesTouchingAtCoincidentCornersAreAContactNotACrossing)
{
  typedef std::array<K::Point_3, 3> Triangle;
  const Triangle a{{K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0)}};
  const Triangle touching{{K::Point_3(0, 0, 0), K::Point_3(-1, 0, 0), K::Point_3(0, -1, 0)}}; // at the origin only
  const Triangle through{{K::Point_3(0, 0, 0), K::Point_3(1, 1, -1), K::Point_3(1, 1, 1)}};   // from the origin through a
  const Triangle overlapping{{K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(1, 1, 0)}}; // a side and more in common
  EXPECT_TRUE(CR::internal::is_contact(a, touching));
  EXPECT_FALSE(CR::internal::is_contact(a, through));
  EXPECT_FALSE(CR::internal::is_contact(a, overlapping));
  EXPECT_FALSE(CR::internal::is_contact(a, a));
}

TEST(InputPreparation, CoincidentVerticesStayDistinct)
{
  // The touching holes' vertex split into two at one point: a valid manifold that CGAL's
  // self-intersection test sees as intersecting at that point.
  Mesh input = grid_with_touching_holes();
  ASSERT_EQ(CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(input), 1u);
  const CR::Mesh_check_report checks = CR::check_mesh(input);
  ASSERT_EQ(checks.count(CR::Mesh_defect::DUPLICATED_VERTEX), 1u) << checks.summary();
  ASSERT_TRUE(checks.is_manifold_surface());
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::does_self_intersect(input));
  EXPECT_FALSE(CR::internal::has_crossing_faces<CGAL::Sequential_tag>(input));

  Mesh output;
  std::vector<CR::Surface_location> locations;
  const CR::Remeshing_report report = CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations)));
  EXPECT_EQ(report.input.coincident_vertices, 1u);
  EXPECT_FALSE(report.input.repaired());
  EXPECT_FALSE(report.input_crosses_itself);
  expect_valid_output(input, output, locations);
  // The point where the holes touch is in the output twice, as two vertices.
  std::size_t at_contact = 0;
  for(Mesh::Vertex_index v : output.vertices())
    at_contact += output.point(v) == K::Point_3(4., 4., 0.);
  EXPECT_EQ(at_contact, 2u);
  EXPECT_EQ(CR::check_mesh(output).components.front().boundary_loops, checks.components.front().boundary_loops);
}

TEST(InputPreparation, NonManifoldVerticesAreSplit)
{
  const Mesh input = grid_with_touching_holes();
  ASSERT_EQ(CR::check_mesh(input).count(CR::Mesh_defect::NON_MANIFOLD_VERTEX), 1u);
  Mesh output;
  std::vector<CR::Surface_location> locations;
  const CR::Remeshing_report report = CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations)));
  EXPECT_EQ(report.input.split_non_manifold_vertices, 1u);
  EXPECT_TRUE(report.input.repaired());
  EXPECT_NE(report.input.summary().find("non-manifold"), std::string::npos) << report.input.summary();
  // The example names the vertex where the holes touch.
  EXPECT_NE(report.input.non_manifold_example.find("separate fans"), std::string::npos) << report.input.non_manifold_example;
  EXPECT_NE(report.input.summary().find(report.input.non_manifold_example), std::string::npos) << report.input.summary();
  expect_valid_output(input, output, locations);
  test_support::expect_error([&] { CR::remesh_conformal(input, output, CR::parameters::repair_input(false)); },
                             CR::Error_code::INVALID_INPUT, {"non-manifold vert", "repairs are off"});
}

TEST(InputPreparation, DegenerateFacesAreRemoved)
{
  // A closed cube with edges split at their midpoints: on one side of each, the triangle of the
  // edge's ends and its midpoint is left, of zero area (three collinear corners); the other side
  // is cut at the midpoint as a mesher would.
  Mesh input;
  CGAL::make_hexahedron(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(1, 1, 0), K::Point_3(0, 1, 0), K::Point_3(0, 1, 1),
                        K::Point_3(0, 0, 1), K::Point_3(1, 0, 1), K::Point_3(1, 1, 1), input);
  CGAL::Polygon_mesh_processing::triangulate_faces(input);
  std::set<Mesh::Face_index> touched;
  std::vector<Mesh::Halfedge_index> to_split;
  for(Mesh::Edge_index e : input.edges())
  {
    const Mesh::Halfedge_index h = input.halfedge(e);
    if(!touched.count(input.face(h)) && !touched.count(input.face(input.opposite(h))))
    {
      touched.insert(input.face(h));
      touched.insert(input.face(input.opposite(h)));
      to_split.push_back(h);
    }
  }
  ASSERT_GE(to_split.size(), 3u);
  for(Mesh::Halfedge_index h : to_split)
  {
    // h runs a -> b; after the split, into_mid runs a -> m and h runs m -> b.
    const K::Point_3 m = CGAL::midpoint(input.point(input.source(h)), input.point(input.target(h)));
    const Mesh::Halfedge_index into_mid = CGAL::Euler::split_edge(h, input);
    input.point(input.target(into_mid)) = m;
    CGAL::Euler::split_face(input.prev(into_mid), h, input); // (a, m, b), collinear, and (a, b, c)
    const Mesh::Halfedge_index back = input.opposite(h);    // b -> m, on the other side
    CGAL::Euler::split_face(back, input.next(input.next(back)), input); // m to the far corner
  }
  const CR::Mesh_check_report checks = CR::check_mesh(input);
  ASSERT_GT(checks.count(CR::Mesh_defect::DEGENERATE_FACE), 0u) << checks.summary();

  Mesh output;
  std::vector<CR::Surface_location> locations;
  const CR::Remeshing_report report = CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations)));
  EXPECT_GE(report.input.removed_degenerate_faces, checks.count(CR::Mesh_defect::DEGENERATE_FACE));
  expect_valid_output(input, output, locations);
  EXPECT_TRUE(CR::check_mesh(output).is_valid()) << CR::check_mesh(output).summary();
  EXPECT_EQ(CR::check_mesh(output).components.front().genus, 0);
  test_support::expect_error([&] { CR::remesh_conformal(input, output, CR::parameters::repair_input(false)); },
                             CR::Error_code::INVALID_INPUT, {"degenerate", "repairs are off"});
}

TEST(InputPreparation, ABowtieOfTwoTetrahedraIsCutApartOnReading)
{
  // Two tetrahedra sharing one vertex: no halfedge mesh holds the soup as it is.
  const std::vector<K::Point_3> points{K::Point_3(0, 0, 0),  K::Point_3(1, 0, 0),  K::Point_3(0, 1, 0),
                                       K::Point_3(0, 0, 1),  K::Point_3(-1, 0, 0), K::Point_3(0, -1, 0),
                                       K::Point_3(0, 0, -1)};
  const std::vector<std::vector<std::size_t> > polygons{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                                                        {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  CR::Input_repair_report repaired;
  CR::Mesh_check_report checks;
  const Mesh input = read_repaired("bowtie", points, polygons, repaired, checks);
  EXPECT_EQ(repaired.split_vertices, 1u) << repaired.summary();
  ASSERT_TRUE(checks.is_manifold_surface()) << checks.summary();
  ASSERT_EQ(checks.components.size(), 2u);
  Mesh output;
  std::vector<CR::Surface_location> locations;
  const CR::Remeshing_report report = CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations)));
  EXPECT_EQ(report.input.coincident_vertices, 1u);
  expect_valid_output(input, output, locations);
  EXPECT_EQ(CR::check_mesh(output).components.size(), 2u);
}

TEST(InputPreparation, ABookOfThreeSheetsIsCutApartOnReading)
{
  // Three squares on one edge (x = 0, z from 0 to 1), at 0, 120 and 240 degrees: the edge has
  // three faces on each of its two triangles' sides.
  std::vector<K::Point_3> points{K::Point_3(0, 0, 0), K::Point_3(0, 0, 1)};
  std::vector<std::vector<std::size_t> > polygons;
  for(int s = 0; s < 3; ++s)
  {
    const double a = 2. * CGAL_PI * s / 3.;
    points.push_back(K::Point_3(std::cos(a), std::sin(a), 0.));
    points.push_back(K::Point_3(std::cos(a), std::sin(a), 1.));
    const std::size_t p = points.size() - 2, q = points.size() - 1;
    polygons.push_back({0, p, q});
    polygons.push_back({0, q, 1});
  }
  CR::Input_repair_report repaired;
  CR::Mesh_check_report checks;
  const Mesh input = read_repaired("book", points, polygons, repaired, checks);
  EXPECT_GE(repaired.split_vertices, 2u) << repaired.summary();
  ASSERT_TRUE(checks.is_manifold_surface()) << checks.summary();
  Mesh output;
  std::vector<CR::Surface_location> locations;
  CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations)));
  expect_valid_output(input, output, locations);
  EXPECT_EQ(CR::check_mesh(output).components.size(), checks.components.size());
}
