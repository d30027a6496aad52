// Sheets of the surface that come close to each other: parallel plates a fraction of the target
// apart, two boxes a hair apart, a pipe whose walls are closer than the target, a fin cut apart
// along its edge. Each is remeshed into a valid manifold that does not intersect itself, with
// every vertex on the input surface; the report gives the smallest gap between sheets. An
// assembly of parts remeshed in batches of components gives each part the mesh it has alone, and
// parts of different batches that come close are remeshed together.

#include "off_text.h"
#include "stage_tests.h"

#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/proximity.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>

#include <cstdio>
#include <sstream>
#include <fstream>
#include <map>

namespace {

// A grid of `n` x `n` squares, each cut into two triangles, mapped by `at` from [0,1]^2;
// `flip` reverses the orientation.
template <typename At>
void add_grid(Mesh& mesh, int n, const At& at, bool flip = false)
{
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
      v.push_back(mesh.add_vertex(at(double(i) / n, double(j) / n)));
  const auto id = [&](int i, int j) { return v[std::size_t(i * (n + 1) + j)]; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      std::array<Mesh::Vertex_index, 3> a{{id(i, j), id(i + 1, j), id(i + 1, j + 1)}}, b{{id(i, j), id(i + 1, j + 1), id(i, j + 1)}};
      if(flip)
      {
        std::swap(a[1], a[2]);
        std::swap(b[1], b[2]);
      }
      mesh.add_face(a[0], a[1], a[2]);
      mesh.add_face(b[0], b[1], b[2]);
    }
}

// A closed box [x0, x0 + 1] x [0, 1] x [0, 1], each side an `n` x `n` grid, stitched.
void add_box(Mesh& mesh, double x0, int n)
{
  Mesh box;
  const auto p = [&](double x, double y, double z) { return K::Point_3(x0 + x, y, z); };
  add_grid(box, n, [&](double s, double t) { return p(s, t, 0.); }, true);
  add_grid(box, n, [&](double s, double t) { return p(s, t, 1.); });
  add_grid(box, n, [&](double s, double t) { return p(s, 0., t); });
  add_grid(box, n, [&](double s, double t) { return p(s, 1., t); }, true);
  add_grid(box, n, [&](double s, double t) { return p(0., s, t); }, true);
  add_grid(box, n, [&](double s, double t) { return p(1., s, t); });
  CGAL::Polygon_mesh_processing::stitch_borders(box);
  CGAL::copy_face_graph(box, mesh);
}

// A closed pipe along z of inner radius `r`, walls `thickness` thick and `length` long, with
// `sectors` faces around, `rows` along and flat annular ends.
Mesh thick_pipe(double r, double thickness, double length, int sectors, int rows)
{
  Mesh pipe;
  const double R = r + thickness;
  const auto on = [&](double radius, double s, double z) {
    return K::Point_3(radius * std::cos(2. * CGAL_PI * s), radius * std::sin(2. * CGAL_PI * s), z);
  };
  const auto wall = [&](double radius, bool flip) {
    Mesh w;
    std::vector<Mesh::Vertex_index> v;
    for(int i = 0; i < sectors; ++i)
      for(int j = 0; j <= rows; ++j)
        v.push_back(w.add_vertex(on(radius, double(i) / sectors, length * j / rows)));
    const auto id = [&](int i, int j) { return v[std::size_t((i % sectors) * (rows + 1) + j)]; };
    for(int i = 0; i < sectors; ++i)
      for(int j = 0; j < rows; ++j)
      {
        if(flip)
        {
          w.add_face(id(i, j), id(i + 1, j + 1), id(i + 1, j));
          w.add_face(id(i, j), id(i, j + 1), id(i + 1, j + 1));
        }
        else
        {
          w.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
          w.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
        }
      }
    return w;
  };
  const auto end = [&](double z, bool flip) {
    Mesh e;
    std::vector<Mesh::Vertex_index> inner, outer;
    for(int i = 0; i < sectors; ++i)
    {
      inner.push_back(e.add_vertex(on(r, double(i) / sectors, z)));
      outer.push_back(e.add_vertex(on(R, double(i) / sectors, z)));
    }
    for(int i = 0; i < sectors; ++i)
    {
      const int k = (i + 1) % sectors;
      if(flip)
      {
        e.add_face(inner[i], inner[k], outer[k]);
        e.add_face(inner[i], outer[k], outer[i]);
      }
      else
      {
        e.add_face(inner[i], outer[k], inner[k]);
        e.add_face(inner[i], outer[i], outer[k]);
      }
    }
    return e;
  };
  for(const Mesh& part : {wall(R, false), wall(r, true), end(0., true), end(length, false)})
    CGAL::copy_face_graph(part, pipe);
  CGAL::Polygon_mesh_processing::stitch_borders(pipe);
  return pipe;
}

// Checks the output of `input`: a valid manifold, no crossing faces (contacts the input has are
// allowed), every vertex on the input surface at its place in `locations`.
void check_output(const Mesh& input, const Mesh& output, const std::vector<CR::Surface_location>& locations)
{
  const CR::Mesh_check_report checks = CR::check_mesh(output);
  EXPECT_TRUE(checks.is_manifold_surface()) << checks.summary();
  EXPECT_FALSE(CR::internal::has_crossing_faces<CGAL::Sequential_tag>(output));
  const CR::Remesh_verification verification = CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_TRUE(verification.on_input_surface) << verification.summary();
  EXPECT_TRUE(verification.self_intersection_free) << verification.summary();
}

// Remeshes `input` at `target`, with a chord error bound of a target (which bounds nothing on
// these models, whose curvature radii are a target or more: only the gaps bound the chords), and
// checks the output (`check_output()`).
CR::Remeshing_report remesh_and_check(const Mesh& input, double target, Mesh& output)
{
  std::vector<CR::Surface_location> locations;
  const CR::Remeshing_report report = CR::remesh_conformal(
    input, output,
    CR::parameters::vertex_locations(std::ref(locations), CR::parameters::maximum_chord_error(target, CR::parameters::target_edge_length(target))));
  check_output(input, output, locations);
  EXPECT_GT(output.number_of_faces(), 0u);
  return report;
}

} // namespace

TEST(Proximity, GapsAreMeasuredBetweenSheetsOnly)
{
  // Two parallel unit squares 0.01 apart: each vertex sees the other square at 0.01. A sheet
  // bent by a quarter turn sees no other sheet; bent by a half turn (a U of width 0.2), its
  // sides face each other across it: those whose normals are 120 degrees apart or more, at
  // least 0.2 sin(60 degrees) apart.
  Mesh plates;
  add_grid(plates, 10, [](double s, double t) { return K::Point_3(s, t, 0.); });
  add_grid(plates, 10, [](double s, double t) { return K::Point_3(s, t, 0.01); }, true);
  const RM::Surface_proximity between = RM::surface_proximity<CGAL::Sequential_tag>(plates, 0.5);
  for(Mesh::Vertex_index v : plates.vertices())
    EXPECT_NEAR(between.gap[v], 0.01, 1e-12);
  EXPECT_NEAR(between.smallest_gap, 0.01, 1e-12);

  const auto bent_sheet = [](double turns) {
    Mesh sheet;
    add_grid(sheet, 16, [&](double s, double t) {
      return K::Point_3(0.1 * std::cos(2. * CGAL_PI * turns * s), 0.1 * std::sin(2. * CGAL_PI * turns * s), t);
    });
    return sheet;
  };
  const RM::Surface_proximity quarter = RM::surface_proximity<CGAL::Sequential_tag>(bent_sheet(0.25), 0.5);
  EXPECT_TRUE(std::isinf(quarter.smallest_gap)) << quarter.smallest_gap;
  const RM::Surface_proximity half = RM::surface_proximity<CGAL::Sequential_tag>(bent_sheet(0.5), 0.5);
  EXPECT_GT(half.smallest_gap, 0.16);
  EXPECT_LT(half.smallest_gap, 0.2);

  // Sheets in contact (a fin of three squares on one edge, each with its own vertices there)
  // are no gap to each other.
  Mesh fin;
  for(double degrees : {0., 90., 180.})
  {
    const double a = degrees * CGAL_PI / 180.;
    add_grid(fin, 4, [&](double s, double t) { return K::Point_3(s * std::cos(a), s * std::sin(a), t); });
  }
  const RM::Surface_proximity contact = RM::surface_proximity<CGAL::Sequential_tag>(fin, 0.5);
  EXPECT_TRUE(std::isinf(contact.smallest_gap)) << contact.smallest_gap << " at " << contact.smallest_gap_point;

  // Beyond the radius, no gap.
  const RM::Surface_proximity far = RM::surface_proximity<CGAL::Sequential_tag>(plates, 0.005);
  EXPECT_TRUE(std::isinf(far.smallest_gap));
}

TEST(NearlyTouchingSheets, ParallelPlatesAtGapsDownToATenThousandthOfTheTarget)
{
  const double target = 0.05;
  for(double fraction : {1e-1, 1e-2, 1e-3, 1e-4})
  {
    SCOPED_TRACE("gap " + std::to_string(fraction) + " x target");
    const double gap = fraction * target;
    Mesh plates, output;
    add_grid(plates, 7, [](double s, double t) { return K::Point_3(s, t, 0.); });
    add_grid(plates, 7, [&](double s, double t) { return K::Point_3(s, t, gap); }, true);
    const CR::Remeshing_report report = remesh_and_check(plates, target, output);
    EXPECT_NEAR(report.smallest_gap, gap, 1e-9 * target);
  }
}

TEST(NearlyTouchingSheets, TwoBoxesAMillionthOfTheDiagonalApart)
{
  Mesh boxes, output;
  add_box(boxes, 0., 4);
  const double gap = 1e-6 * std::sqrt(4. + 1. + 1.);
  add_box(boxes, 1. + gap, 4);
  const CR::Remeshing_report report = remesh_and_check(boxes, 0.1, output);
  EXPECT_NEAR(report.smallest_gap, gap, 1e-9);
  EXPECT_EQ(CR::check_mesh(output).components.size(), 2u);
}

TEST(NearlyTouchingSheets, APipeWhoseWallsAreATenthOfTheTargetApart)
{
  // The outer wall's chords a target long stand 1/8.8 of the target inside it: more than the
  // gap, unless the size field shortens them there.
  const double target = 0.1;
  const Mesh pipe = thick_pipe(target, 0.1 * target, 0.5, 96, 10);
  ASSERT_TRUE(CR::check_mesh(pipe).is_valid()) << CR::check_mesh(pipe).summary();
  Mesh output;
  const CR::Remeshing_report report = remesh_and_check(pipe, target, output);
  EXPECT_NEAR(report.smallest_gap, 0.1 * target, 0.01 * target);
  EXPECT_GT(report.gap_bounded_vertices, 0u);
  EXPECT_EQ(report.self_intersection_refinements, 0u) << "the size field, not a retry, keeps the walls apart";
  // The chords stand off the walls by about half the gap, well short of the other wall (the
  // optimization's flips may lengthen edges up to the target, and the walls' facets, 1/96 of a
  // turn, bend a little between the input's vertices too). Without the bound: the whole gap.
  const double off = CR::compare_to_reference(output, pipe).relative_distance_to_reference * diagonal(pipe);
  EXPECT_LT(off, 0.75 * report.smallest_gap) << off / target << " target lengths";

  // Without a chord error bound, the gaps are not measured (nor bound the sizes).
  Mesh uniform;
  const CR::Remeshing_report unmeasured = CR::remesh_conformal(pipe, uniform, CR::parameters::target_edge_length(target));
  EXPECT_TRUE(std::isnan(unmeasured.smallest_gap));
  EXPECT_EQ(unmeasured.gap_bounded_vertices, 0u);
}

TEST(SheetsInContact, SheetsCutApartAlongAnEdgeShareTheirSamplesThere)
{
  // A fin: three unit squares on the edge x = y = 0, two of them in one plane (at 0 and 180
  // degrees) and one at 90, with a target of a fifth of the edge: each sheet has samples inside
  // the edge, and they must be the same points on all three, else the coplanar sheets cross.
  const std::string file = testing::TempDir() + "fin.off";
  {
    std::ofstream out(file);
    out << "OFF\n8 6 0\n0 0 0\n0 0 1\n1 0 0\n1 0 1\n-1 0 0\n-1 0 1\n0 1 0\n0 1 1\n"
        << "3 0 2 3\n3 0 3 1\n3 0 5 4\n3 0 1 5\n3 0 7 6\n3 0 1 7\n";
  }
  Mesh input;
  CR::Input_repair_report repaired;
  const CR::Mesh_check_report checks = CR::read_and_check_mesh(file, input, CR::Input_repairs::all(), repaired);
  std::remove(file.c_str());
  ASSERT_TRUE(checks.is_manifold_surface()) << checks.summary();
  ASSERT_EQ(checks.components.size(), 3u);
  Mesh output;
  std::vector<CR::Surface_location> locations;
  CR::remesh_conformal(input, output, CR::parameters::vertex_locations(std::ref(locations), CR::parameters::target_edge_length(0.2)));
  EXPECT_FALSE(CR::internal::has_crossing_faces<CGAL::Sequential_tag>(output));
  const CR::Remesh_verification verification = CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_TRUE(verification.self_intersection_free) << verification.summary();
  std::map<K::Point_3, int> on_edge; // output vertices on the edge, by point
  for(Mesh::Vertex_index v : output.vertices())
    if(output.point(v).x() == 0. && output.point(v).y() == 0.)
      ++on_edge[output.point(v)];
  EXPECT_GE(on_edge.size(), 5u);
  for(const auto& point : on_edge)
    EXPECT_EQ(point.second, 3) << "at z = " << point.first.z();
}

namespace {

// Remeshes `input` in batches of at most `batch_faces` faces at `target`, and checks the output
// (`check_output()`), with every vertex's place on the input.
CR::Remeshing_report remesh_in_batches_and_check(const Mesh& input, double target, std::size_t batch_faces, Mesh& output,
                                                 std::vector<CR::Surface_location>* places = nullptr)
{
  std::vector<CR::Surface_location> locations;
  CR::Remeshing_statistics statistics;
  const CR::Remeshing_report report = CR::remesh_conformal<CGAL::Sequential_tag>(
    input, output,
    CR::parameters::vertex_locations(
      std::ref(locations),
      CR::parameters::statistics(std::ref(statistics),
                                 CR::parameters::batch_faces(batch_faces, CR::parameters::target_edge_length(target)))));
  check_output(input, output, locations);
  EXPECT_EQ(statistics.patches.size(), report.number_of_patches);
  EXPECT_GT(statistics.peak_resident_mb_gluing, 0.);
  if(places != nullptr)
    *places = std::move(locations);
  return report;
}

} // namespace

TEST(ComponentBatches, EachBatchIsRemeshedAsItsComponentsAlone)
{
  const double target = 0.1;
  Mesh boxes;
  for(int b = 0; b < 3; ++b)
    add_box(boxes, 2. * b, 4 + b); // each box its own tessellation
  boxes.collect_garbage();
  // Batches of the first box's faces: one box each (the larger boxes exceed it alone).
  Mesh batched;
  std::vector<CR::Surface_location> locations;
  const CR::Remeshing_report report = remesh_in_batches_and_check(boxes, target, 6 * 2 * 4 * 4, batched, &locations);
  EXPECT_EQ(report.component_batches, 3u);
  EXPECT_EQ(report.merged_batches, 0u);
  EXPECT_EQ(CR::check_mesh(batched).components.size(), 3u);

  // Each box copied out (as a batch is: in the input's order) and remeshed alone, the outputs
  // joined in order: the same file.
  std::vector<std::size_t> face_component;
  const auto components = RM::component_batches(boxes, CGAL::parameters::default_values(), 1, face_component);
  ASSERT_EQ(components.size(), 3u);
  Mesh joined_alone;
  for(const std::vector<std::size_t>& component : components)
  {
    const RM::Prepared_input alone = RM::copy_of_components(boxes, CGAL::parameters::default_values(), face_component, component);
    Mesh remeshed;
    CR::remesh_conformal<CGAL::Sequential_tag>(alone.mesh, remeshed, CR::parameters::target_edge_length(target));
    CGAL::copy_face_graph(remeshed, joined_alone);
  }
  EXPECT_EQ(off_text(batched), off_text(joined_alone));

  // Every vertex's place names a face of the input and barycentric coordinates from the source
  // of its halfedge: they give the vertex back.
  ASSERT_EQ(locations.size(), batched.number_of_vertices());
  for(Mesh::Vertex_index v : batched.vertices())
  {
    const CR::Surface_location& at = locations[v];
    ASSERT_LT(at.input_face, boxes.number_of_faces());
    const Mesh::Halfedge_index h = boxes.halfedge(Mesh::Face_index(Mesh::size_type(at.input_face)));
    const K::Point_3 a = boxes.point(boxes.source(h)), b = boxes.point(boxes.target(h)), c = boxes.point(boxes.target(boxes.next(h)));
    const K::Point_3 p(at.coordinates[0] * a.x() + at.coordinates[1] * b.x() + at.coordinates[2] * c.x(),
                       at.coordinates[0] * a.y() + at.coordinates[1] * b.y() + at.coordinates[2] * c.y(),
                       at.coordinates[0] * a.z() + at.coordinates[1] * b.z() + at.coordinates[2] * c.z());
    EXPECT_LT(std::sqrt(CGAL::squared_distance(p, batched.point(v))), 1e-9) << "vertex " << std::size_t(v);
  }

  // Two boxes in a batch.
  Mesh two_batches;
  const CR::Remeshing_report two = remesh_in_batches_and_check(boxes, target, 6 * 2 * (16 + 25), two_batches);
  EXPECT_EQ(two.component_batches, 2u);
  EXPECT_EQ(CR::check_mesh(two_batches).components.size(), 3u);

  // In one piece (the default for an input this small): the same surface, meshed as a whole.
  Mesh whole;
  const CR::Remeshing_report one = remesh_in_batches_and_check(boxes, target, 0, whole);
  EXPECT_EQ(one.component_batches, 1u);
  EXPECT_EQ(one.number_of_patches, report.number_of_patches);
}

TEST(ComponentBatches, BatchesWhoseOutputsCrossAreRemeshedTogether)
{
  // A pipe inside another, a hundredth of the target apart: remeshed alone, the outer pipe's
  // inner wall cuts inward by about a tenth of the target, through the inner pipe's outer wall.
  const double target = 0.1;
  Mesh pipes;
  const Mesh inner = thick_pipe(0.1, 0.02, 0.5, 96, 10);
  CGAL::copy_face_graph(inner, pipes);
  CGAL::copy_face_graph(thick_pipe(0.12 + 0.01 * target, 0.02, 0.5, 96, 10), pipes);
  ASSERT_TRUE(CR::check_mesh(pipes).is_valid()) << CR::check_mesh(pipes).summary();
  Mesh output;
  const CR::Remeshing_report report = remesh_in_batches_and_check(pipes, target, inner.number_of_faces(), output);
  EXPECT_EQ(report.component_batches, 2u);
  EXPECT_EQ(report.merged_batches, 1u) << "the two pipes' outputs cross when each is remeshed alone";
  EXPECT_EQ(CR::check_mesh(output).components.size(), 2u);
}
