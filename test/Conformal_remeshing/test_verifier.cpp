// Tests of verify_remesh() and verify_parameterization(): good remeshings pass, and every kind of
// broken output (self-intersection, vertex off the surface, changed genus, dropped boundary loop,
// invalid mesh, wrong locations) fails with its own flag and nothing else.

#include <CGAL/Conformal_remeshing/verify_remesh.h>
#include <CGAL/remesh_conformal.h>

#include "test_surfaces.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;

namespace {

// A torus of revolution (radii 2 and 1) as a grid of nu x nv quads, each split in two.
Mesh torus(int nu = 24, int nv = 12)
{
  Mesh m;
  std::vector<Vertex> vs;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double u = 2 * CGAL_PI * i / nu, v = 2 * CGAL_PI * j / nv;
      vs.push_back(m.add_vertex(Point((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v))));
    }
  auto at = [&](int i, int j) { return vs[(i % nu) * nv + (j % nv)]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

// An n x n grid of unit squares in the plane z = 0.
Mesh grid(int n = 8)
{
  Mesh m;
  std::vector<Vertex> v;
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

// A flat ring (radii 1 and 2) in the plane z = 0: genus 0, two boundary loops.
Mesh annulus(int sectors = 24, int rings = 3)
{
  Mesh m;
  std::vector<Vertex> v;
  for(int k = 0; k <= rings; ++k)
    for(int s = 0; s < sectors; ++s)
    {
      const double r = 1. + double(k) / rings, t = 2 * CGAL_PI * s / sectors;
      v.push_back(m.add_vertex(Point(r * std::cos(t), r * std::sin(t), 0)));
    }
  auto at = [&](int k, int s) { return v[k * sectors + (s % sectors)]; };
  for(int k = 0; k < rings; ++k)
    for(int s = 0; s < sectors; ++s)
    {
      m.add_face(at(k, s), at(k + 1, s), at(k + 1, s + 1));
      m.add_face(at(k, s), at(k + 1, s + 1), at(k, s + 1));
    }
  return m;
}

// Closes the hole along the border halfedge `h` by a fan of triangles from one of its vertices:
// no new vertex, so every vertex stays where it was.
void fill_by_fan(Mesh& m, Mesh::Halfedge_index h)
{
  std::vector<Vertex> loop;
  for(auto b : CGAL::halfedges_around_face(h, m))
    loop.push_back(m.source(b));
  for(std::size_t i = 1; i + 1 < loop.size(); ++i)
    ASSERT_NE(m.add_face(loop[0], loop[i], loop[i + 1]), Mesh::null_face());
}

Mesh::Halfedge_index some_border_halfedge(const Mesh& m)
{
  for(auto h : m.halfedges())
    if(m.is_border(h))
      return h;
  return Mesh::null_halfedge();
}

// Location of each vertex of `m` in `m` itself: a corner of one of its faces.
std::vector<CR::Surface_location> identity_locations(const Mesh& m)
{
  std::vector<CR::Surface_location> locations;
  for(Vertex v : m.vertices())
  {
    auto h = m.halfedge(v);
    if(m.is_border(h))
      h = m.opposite(h);
    const auto f = m.face(h);
    const auto hf = m.halfedge(f);
    CR::Surface_location l;
    l.input_face = f.idx();
    const Vertex corners[3] = {m.source(hf), m.target(hf), m.target(m.next(hf))};
    for(int c = 0; c < 3; ++c)
      l.coordinates[c] = corners[c] == v ? 1. : 0.;
    locations.push_back(l);
  }
  return locations;
}

// Expects every check but the named ones to hold.
void expect_only_failures(const CR::Remesh_verification& v, const std::vector<std::string>& failing)
{
  auto failed = [&](const std::string& name) { return std::find(failing.begin(), failing.end(), name) != failing.end(); };
  EXPECT_FALSE(v.is_valid()) << v.summary();
  EXPECT_EQ(v.valid_triangle_mesh, !failed("valid_triangle_mesh")) << v.summary();
  EXPECT_EQ(v.manifold, !failed("manifold")) << v.summary();
  EXPECT_EQ(v.self_intersection_free, !failed("self_intersection_free")) << v.summary();
  EXPECT_EQ(v.topology_kept, !failed("topology_kept")) << v.summary();
  EXPECT_EQ(v.on_input_surface, !failed("on_input_surface")) << v.summary();
  EXPECT_EQ(v.locations_match, !failed("locations_match")) << v.summary();
  EXPECT_EQ(v.summary().rfind("INVALID: ", 0), 0u) << v.summary();
}

} // namespace

TEST(VerifyRemesh, MeshAgainstItselfIsValid)
{
  for(const Mesh& m : {torus(), grid(), annulus()})
  {
    const std::vector<CR::Surface_location> locations = identity_locations(m);
    const CR::Remesh_verification v = CR::verify_remesh(m, m, CR::parameters::vertex_locations(std::cref(locations)));
    EXPECT_TRUE(v.is_valid()) << v.summary();
    EXPECT_TRUE(v.locations_checked);
    EXPECT_EQ(v.max_distance_to_input, 0.);
    EXPECT_LT(v.max_location_error, 1e-15); // p + 1 (q - p) is q up to rounding
    EXPECT_EQ(v.output_vertices, m.number_of_vertices());
    EXPECT_EQ(v.self_intersecting_face_pairs, 0u);
    EXPECT_EQ(v.summary().rfind("valid: ", 0), 0u) << v.summary();
    EXPECT_NEAR(v.tolerance, 1e-9 * v.input_diagonal, 1e-24);
  }
}

TEST(VerifyRemesh, IsotropicRemeshingIsValid)
{
  // CGAL's isotropic remeshing keeps the topology and projects its vertices onto the input.
  const Mesh input = torus(32, 16);
  Mesh output = input;
  PMP::isotropic_remeshing(faces(output), 0.15, output, CGAL::parameters::number_of_iterations(3));
  // The removed elements stay until the garbage is collected: the verifier must skip them.
  ASSERT_TRUE(output.has_garbage());
  ASSERT_GT(output.number_of_faces(), 2 * input.number_of_faces());
  const CR::Remesh_verification v = CR::verify_remesh(input, output);
  EXPECT_TRUE(v.is_valid()) << v.summary();
  EXPECT_EQ(v.output_vertices, output.number_of_vertices());
  EXPECT_EQ(v.output_faces, output.number_of_faces());
  EXPECT_GT(v.max_distance_to_input, 0.); // the vertices moved on the surface
  EXPECT_EQ(v.output_components.size(), 1u);
  EXPECT_EQ(v.output_components[0].genus, 1);

  // The locations found by PMP::locate() on the input agree with the vertices.
  std::vector<CR::Surface_location> locations;
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > tree;
  PMP::build_AABB_tree(input, tree);
  for(Vertex w : output.vertices())
  {
    const auto l = PMP::locate_with_AABB_tree(output.point(w), tree, input);
    locations.push_back(CR::Surface_location{l.first.idx(), {{l.second[0], l.second[1], l.second[2]}}});
  }
  const CR::Remesh_verification located =
    CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_TRUE(located.is_valid()) << located.summary();
  EXPECT_LT(located.max_location_error, located.tolerance);
}

TEST(VerifyRemesh, RemeshConformalOutputIsValid)
{
  // The package's own remesher, checked by the independent verifier, locations included.
  Mesh input;
  bm::make_spherical_cap(input, 100., 8, 24);
  Mesh output;
  std::vector<CR::Surface_location> locations;
  CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations), CR::parameters::relative_target_edge_length(0.05)));
  ASSERT_GT(output.number_of_faces(), 50u);
  const CR::Remesh_verification v =
    CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_TRUE(v.is_valid()) << v.summary();
}

TEST(VerifyRemesh, FoldedTriangleIsASelfIntersection)
{
  // Move an interior vertex of a planar grid across its neighbours, within the plane: every
  // vertex stays on the surface and the topology is the same, but triangles fold over.
  const Mesh input = grid(6);
  Mesh output = input;
  const Vertex v(3 * 7 + 3); // the vertex at (3, 3)
  ASSERT_EQ(output.point(v), Point(3, 3, 0));
  output.point(v) = Point(4.4, 3.6, 0); // not collinear with any two of its neighbours
  const CR::Remesh_verification r = CR::verify_remesh(input, output);
  expect_only_failures(r, {"self_intersection_free"});
  EXPECT_TRUE(r.self_intersections_checked);
  EXPECT_GT(r.self_intersecting_face_pairs, 0u);
  EXPECT_NE(r.summary().find("self-intersecting face pair"), std::string::npos) << r.summary();
}

TEST(VerifyRemesh, SelfIntersectionOfAClosedSurface)
{
  // Push one vertex of the torus through the opposite side of its tube.
  const Mesh input = torus();
  Mesh output = input;
  const Vertex v(0); // at (3, 0, 0), on the outer equator
  output.point(v) = Point(0.5, 0, 0);
  const CR::Remesh_verification r = CR::verify_remesh(input, output);
  EXPECT_FALSE(r.self_intersection_free) << r.summary();
  EXPECT_FALSE(r.on_input_surface) << r.summary();
  EXPECT_EQ(r.vertices_off_surface, 1u);
  EXPECT_TRUE(r.topology_kept) << r.summary();
}

TEST(VerifyRemesh, VertexOffTheSurface)
{
  const Mesh input = grid(8);
  Mesh output = input;
  const double diagonal = std::sqrt(2. * 64.);
  output.point(Vertex(4 * 9 + 4)) = Point(4, 4, 1e-6 * diagonal);
  const CR::Remesh_verification r = CR::verify_remesh(input, output);
  expect_only_failures(r, {"on_input_surface"});
  EXPECT_EQ(r.vertices_off_surface, 1u);
  EXPECT_NEAR(r.max_distance_to_input, 1e-6 * diagonal, 1e-15);
  EXPECT_NE(r.summary().find("1 of 81 vertices off the input surface"), std::string::npos) << r.summary();

  // The tolerance decides: relative 1e-5 or absolute 1e-4 accept the bump, 1e-7 does not.
  EXPECT_TRUE(CR::verify_remesh(input, output, CR::parameters::relative_distance_tolerance(1e-5)).is_valid());
  EXPECT_TRUE(CR::verify_remesh(input, output, CR::parameters::distance_tolerance(1e-4)).is_valid());
  EXPECT_FALSE(CR::verify_remesh(input, output, CR::parameters::relative_distance_tolerance(1e-7)).is_valid());

  // Just below and just above the default tolerance.
  Mesh close = input;
  close.point(Vertex(40)) = Point(4, 4, 0.5e-9 * diagonal);
  EXPECT_TRUE(CR::verify_remesh(input, close).is_valid());
  close.point(Vertex(40)) = Point(4, 4, 2e-9 * diagonal);
  EXPECT_FALSE(CR::verify_remesh(input, close).on_input_surface);
}

TEST(VerifyRemesh, ChangedGenus)
{
  // Cut the torus along one ring of faces and close both cuts with fans: a sphere made of input
  // vertices only, so only the genus changes (0 boundary loops before and after).
  const int nu = 24, nv = 12;
  const Mesh input = torus(nu, nv);
  Mesh output = input;
  std::vector<Mesh::Face_index> ring;
  for(int j = 0; j < 2 * nv; ++j)
    ring.push_back(Mesh::Face_index(j)); // the faces between meridians 0 and 1
  for(Mesh::Face_index f : ring)
    CGAL::Euler::remove_face(output.halfedge(f), output);
  output.collect_garbage();
  ASSERT_EQ(CR::check_mesh(output).total_boundary_loops(), 2u);
  fill_by_fan(output, some_border_halfedge(output));
  fill_by_fan(output, some_border_halfedge(output));
  ASSERT_EQ(some_border_halfedge(output), Mesh::null_halfedge());

  const CR::Remesh_verification r = CR::verify_remesh(input, output);
  expect_only_failures(r, {"topology_kept"});
  EXPECT_TRUE(r.same_number_of_components);
  EXPECT_TRUE(r.same_boundary_loops);
  EXPECT_FALSE(r.same_genera);
  EXPECT_EQ(r.output_components.at(0).genus, 0);
  EXPECT_NE(r.summary().find("topology changed: input 1 component (genus 1; boundary loops 0), output 1 component "
                             "(genus 0; boundary loops 0)"),
            std::string::npos)
    << r.summary();
}

TEST(VerifyRemesh, DroppedBoundaryLoop)
{
  // Close the inner hole of a flat ring: the fan lies in the ring's plane, on its own vertices.
  const Mesh input = annulus();
  Mesh output = input;
  Mesh::Halfedge_index inner = Mesh::null_halfedge();
  for(auto h : output.halfedges())
    if(output.is_border(h) && CGAL::squared_distance(output.point(output.target(h)), Point(0, 0, 0)) < 1.5)
      inner = h;
  ASSERT_NE(inner, Mesh::null_halfedge());
  fill_by_fan(output, inner);

  const CR::Remesh_verification r = CR::verify_remesh(input, output);
  expect_only_failures(r, {"topology_kept"});
  EXPECT_TRUE(r.same_genera);
  EXPECT_TRUE(r.same_number_of_components);
  EXPECT_FALSE(r.same_boundary_loops);
  EXPECT_EQ(r.output_components.at(0).boundary_loops, 1u);
}

TEST(VerifyRemesh, LostComponent)
{
  // Two tori in one input, one of them in the output.
  Mesh input = torus();
  const Mesh second = torus();
  Mesh shifted = second;
  for(Vertex v : shifted.vertices())
    shifted.point(v) = shifted.point(v) + K::Vector_3(10, 0, 0);
  input.join(shifted);
  const CR::Remesh_verification r = CR::verify_remesh(input, second);
  expect_only_failures(r, {"topology_kept"});
  EXPECT_FALSE(r.same_number_of_components);
  EXPECT_EQ(r.input_components.size(), 2u);
}

TEST(VerifyRemesh, InvalidOutputMeshes)
{
  const Mesh input = grid(4);

  const CR::Remesh_verification empty = CR::verify_remesh(input, Mesh());
  EXPECT_FALSE(empty.valid_triangle_mesh);
  EXPECT_FALSE(empty.self_intersections_checked);
  EXPECT_FALSE(empty.is_valid());
  EXPECT_NE(empty.summary().find("empty mesh"), std::string::npos) << empty.summary();

  // A quad where two triangles were: remove an interior edge of face 0.
  Mesh quads = input;
  Mesh::Halfedge_index interior = Mesh::null_halfedge();
  for(auto h : CGAL::halfedges_around_face(quads.halfedge(Mesh::Face_index(0)), quads))
    if(!quads.is_border(quads.opposite(h)))
      interior = h;
  ASSERT_NE(interior, Mesh::null_halfedge());
  CGAL::Euler::join_face(interior, quads);
  quads.collect_garbage();
  const CR::Remesh_verification q = CR::verify_remesh(input, quads);
  EXPECT_FALSE(q.valid_triangle_mesh) << q.summary();
  EXPECT_FALSE(q.self_intersections_checked);
  EXPECT_TRUE(q.on_input_surface);
  EXPECT_TRUE(q.topology_kept);
  EXPECT_NE(q.summary().find("1 non-triangle face"), std::string::npos) << q.summary();

  // A NaN vertex: off the surface and not a valid mesh.
  Mesh nan = input;
  nan.point(Vertex(6)) = Point(std::numeric_limits<double>::quiet_NaN(), 1, 0);
  const CR::Remesh_verification n = CR::verify_remesh(input, nan);
  EXPECT_FALSE(n.valid_triangle_mesh);
  EXPECT_EQ(n.vertices_off_surface, 1u);
  EXPECT_FALSE(n.is_valid());

  // A degenerate triangle: three collinear vertices, decided exactly.
  Mesh flat = input;
  flat.point(Vertex(6)) = Point(1.5, 0, 0); // (1, 1) onto the line of its face's edge (0, 0)-(1, 0)
  const CR::Remesh_verification d = CR::verify_remesh(input, flat);
  EXPECT_GT(d.output_checks.count(CR::Mesh_defect::DEGENERATE_FACE), 0u) << d.summary();
  EXPECT_FALSE(d.valid_triangle_mesh);

  // Two triangles sharing only a vertex: a non-manifold vertex.
  Mesh bow_tie;
  const Vertex a = bow_tie.add_vertex(Point(0, 0, 0));
  bow_tie.add_face(a, bow_tie.add_vertex(Point(1, 0, 0)), bow_tie.add_vertex(Point(1, 1, 0)));
  bow_tie.add_face(a, bow_tie.add_vertex(Point(0, 1, 0)), bow_tie.add_vertex(Point(0.5, 1, 0)));
  const CR::Remesh_verification b = CR::verify_remesh(input, bow_tie);
  EXPECT_FALSE(b.manifold) << b.summary();
  EXPECT_FALSE(b.topology_kept);
  EXPECT_TRUE(b.on_input_surface);
}

TEST(VerifyRemesh, WrongLocations)
{
  const Mesh m = grid(4);
  std::vector<CR::Surface_location> locations = identity_locations(m);
  auto check = [&](const std::vector<CR::Surface_location>& l) {
    return CR::verify_remesh(m, m, CR::parameters::vertex_locations(std::cref(l)));
  };
  ASSERT_TRUE(check(locations).is_valid());

  std::vector<CR::Surface_location> wrong_face = locations;
  wrong_face[12].input_face = 0; // vertex 12 is at (2, 2), face 0 at (0, 0), (1, 0), (1, 1)
  CR::Remesh_verification r = check(wrong_face);
  expect_only_failures(r, {"locations_match"});
  EXPECT_EQ(r.vertices_off_location, 1u);
  EXPECT_GT(r.max_location_error, 0.5);

  std::vector<CR::Surface_location> no_face = locations;
  no_face[3].input_face = m.number_of_faces() + 5;
  EXPECT_EQ(check(no_face).vertices_off_location, 1u);

  std::vector<CR::Surface_location> not_barycentric = locations;
  not_barycentric[5].coordinates = {{1.5, -0.5, 0.}};
  EXPECT_EQ(check(not_barycentric).vertices_off_location, 1u);

  std::vector<CR::Surface_location> nan = locations;
  nan[0].coordinates[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check(nan).vertices_off_location, 1u);

  std::vector<CR::Surface_location> too_few(locations.begin(), locations.end() - 2);
  r = check(too_few);
  EXPECT_FALSE(r.locations_match);
  EXPECT_EQ(r.vertices_off_location, 2u);
}

TEST(VerifyRemesh, RefusesInputsThatCannotBeAReference)
{
  const Mesh good = grid(2);
  auto expect_invalid_input = [](const auto& call) {
    try
    {
      call();
      ADD_FAILURE() << "no error";
    }
    catch(const CR::Error& e)
    {
      EXPECT_EQ(e.code(), CR::Error_code::INVALID_INPUT) << e.what();
    }
  };
  expect_invalid_input([&] { CR::verify_remesh(Mesh(), good); });
  Mesh quad;
  quad.add_face(quad.add_vertex(Point(0, 0, 0)), quad.add_vertex(Point(1, 0, 0)), quad.add_vertex(Point(1, 1, 0)),
                quad.add_vertex(Point(0, 1, 0)));
  expect_invalid_input([&] { CR::verify_remesh(quad, good); });
  Mesh huge = good;
  huge.point(Vertex(0)) = Point(-1e300, 0, 0);
  expect_invalid_input([&] { CR::verify_remesh(huge, good); });
  // A degenerate face is no reason to refuse: the input is compared through the copy that
  // remesh_conformal() repairs (the grid's faces stay in its plane). A face whose squared sizes
  // underflow is (found by fuzz/fuzz_check_soup: CGAL's closest-point query constructed NaN on
  // it and its exact fallback trapped).
  Mesh flat = good;
  flat.point(Vertex(4)) = Point(1.5, 0.5, 0); // (1, 1) onto the line of (1, 0) and (2, 1), its face's other corners
  ASSERT_EQ(CR::check_mesh(flat).count(CR::Mesh_defect::DEGENERATE_FACE), 1u);
  const CR::Remesh_verification repaired = CR::verify_remesh(flat, good);
  EXPECT_TRUE(repaired.topology_kept) << repaired.summary();
  Mesh sliver;
  sliver.add_face(sliver.add_vertex(Point(0, 3.13151306251402e-294, 0)), sliver.add_vertex(Point(0, 0, 1)),
                  sliver.add_vertex(Point(0, 0, 0)));
  ASSERT_TRUE(CR::check_mesh(sliver).is_valid()); // not degenerate by exact predicates
  expect_invalid_input([&] { CR::verify_remesh(sliver, sliver); });
  expect_invalid_input([&] { CR::verify_remesh(good, good, CR::parameters::distance_tolerance(-1.)); });
  expect_invalid_input([&] {
    CR::verify_remesh(good, good, CR::parameters::relative_distance_tolerance(std::numeric_limits<double>::infinity()));
  });
}

TEST(VerifyRemesh, FarAwayOutputVertex)
{
  // A vertex sent to 1e200 is off the surface, measured without overflowing.
  const Mesh input = grid(3);
  Mesh output = input;
  output.point(Vertex(5)) = Point(1e200, -1e200, 1e200);
  const CR::Remesh_verification v = CR::verify_remesh(input, output);
  EXPECT_EQ(v.vertices_off_surface, 1u);
  EXPECT_GT(v.max_distance_to_input, 1e199);
  EXPECT_FALSE(v.is_valid());
}

TEST(VerifyRemesh, SingleTriangleAndExtremeScales)
{
  // One triangle (a boundary loop of 3 edges), at the smallest and largest scales of the
  // hostile-input list, far from the origin: the checks are scale-free, and the default
  // tolerance never asks for more than the precision of a double at 1e6.
  for(double scale : {1e-6, 1., 1e6})
  {
    Mesh t;
    const K::Vector_3 offset(1e6, -1e6, 1e6);
    t.add_face(t.add_vertex(Point(0, 0, 0) + offset), t.add_vertex(Point(scale, 0, 0) + offset),
               t.add_vertex(Point(0, scale, scale) + offset));
    const CR::Remesh_verification v = CR::verify_remesh(t, t);
    EXPECT_TRUE(v.is_valid()) << scale << ": " << v.summary();
    EXPECT_EQ(v.output_components.at(0).boundary_loops, 1u);
  }
}

// --- parameterizations ---------------------------------------------------------------------------

TEST(VerifyParameterization, GridIsAnEmbedding)
{
  Mesh m = grid(5);
  auto uv = m.add_property_map<Vertex, CGAL::Epick::Point_2>("v:uv").first;
  for(Vertex v : m.vertices())
    uv[v] = CGAL::Epick::Point_2(m.point(v).x(), m.point(v).y());
  const CR::Parameterization_verification ok = CR::verify_parameterization(m, uv);
  EXPECT_TRUE(ok.is_valid()) << ok.summary();
  EXPECT_EQ(ok.summary(), "valid: embedding");

  // A vertex moved across its neighbours folds triangles over.
  uv[Vertex(2 * 6 + 2)] = CGAL::Epick::Point_2(3.5, 2.5);
  const CR::Parameterization_verification folded = CR::verify_parameterization(m, uv);
  EXPECT_FALSE(folded.is_valid());
  EXPECT_GT(folded.embedding.non_positive_faces, 0u) << folded.summary();
  EXPECT_GT(folded.embedding.overlapping_face_pairs, 0u) << folded.summary();

  // A vertex collapsed onto its neighbour makes degenerate triangles.
  uv[Vertex(2 * 6 + 2)] = uv[Vertex(2 * 6 + 3)];
  EXPECT_GT(CR::verify_parameterization(m, uv).embedding.non_positive_faces, 0u);

  // A non-finite uv is refused before any predicate sees it.
  uv[Vertex(2 * 6 + 2)] = CGAL::Epick::Point_2(std::numeric_limits<double>::quiet_NaN(), 0.);
  const CR::Parameterization_verification nan = CR::verify_parameterization(m, uv);
  EXPECT_FALSE(nan.is_valid());
  EXPECT_FALSE(nan.embedding_checked);
  EXPECT_EQ(nan.non_finite_vertices, 1u);
  EXPECT_NE(nan.summary().find("1 vertices with non-finite uv"), std::string::npos) << nan.summary();

  // So is a uv whose products would overflow the overlap test's interval filters (found by
  // fuzz/fuzz_check_soup: CGAL's lazy triangle intersection failed an assertion on it).
  uv[Vertex(2 * 6 + 2)] = CGAL::Epick::Point_2(-4.1855804968255423e+304, 2.);
  const CR::Parameterization_verification huge = CR::verify_parameterization(m, uv);
  EXPECT_FALSE(huge.is_valid());
  EXPECT_FALSE(huge.embedding_checked);
  EXPECT_EQ(huge.out_of_range_vertices, 1u);
}

TEST(VerifyParameterization, OverlapWithoutFold)
{
  // A ring of triangles that winds twice around the centre: every triangle is positively
  // oriented, yet the image overlaps itself (and so does its boundary).
  Mesh m;
  const int n = 10;
  std::vector<Vertex> outer;
  const Vertex centre = m.add_vertex(Point(0, 0, 0));
  for(int i = 0; i < n; ++i)
    outer.push_back(m.add_vertex(Point(std::cos(2 * CGAL_PI * i / n), std::sin(2 * CGAL_PI * i / n), i)));
  for(int i = 0; i < n; ++i)
    m.add_face(centre, outer[i], outer[(i + 1) % n]);
  auto uv = m.add_property_map<Vertex, CGAL::Epick::Point_2>("v:uv").first;
  uv[centre] = CGAL::Epick::Point_2(0, 0);
  for(int i = 0; i < n; ++i)
    uv[outer[i]] = CGAL::Epick::Point_2(std::cos(4 * CGAL_PI * i / n), std::sin(4 * CGAL_PI * i / n));
  const CR::Parameterization_verification v = CR::verify_parameterization(m, uv);
  EXPECT_FALSE(v.is_valid());
  EXPECT_EQ(v.embedding.non_positive_faces, 0u) << v.summary();
  EXPECT_GT(v.embedding.overlapping_face_pairs, 0u) << v.summary();
}
