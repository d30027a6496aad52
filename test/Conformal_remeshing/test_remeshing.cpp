// Tests of remesh_conformal() on single patches: quality, fidelity, boundaries, exact pull-back.

#include <CGAL/remesh_conformal.h>

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include "cad_like_models.h"
#include "remeshing_checks.h"
#include "test_surfaces.h"
#include "expect_error.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using remeshing_checks::check_remeshing;
using remeshing_checks::diagonal;
using remeshing_checks::check_topology_and_fidelity;


TEST(RemeshConformal, WavyConcaveStrip)
{
  Mesh mesh;
  bm::make_wavy_c_strip(mesh);
  check_remeshing(mesh, 20.);
}

TEST(RemeshConformal, WavyConcaveStripWithLloydSmoothing)
{
  // The optional Lloyd iterations in the plane: the same bars, and a mesh of its own.
  Mesh mesh, plain, lloyd;
  bm::make_wavy_c_strip(mesh);
  CR::remesh_conformal(mesh, plain);
  check_remeshing(mesh, 20., CR::parameters::lloyd_iterations(10), &lloyd);
  EXPECT_NE(CR::mesh_quality(plain).skewness.mean, CR::mesh_quality(lloyd).skewness.mean);
}

TEST(RemeshConformal, SphericalCap)
{
  // The benchmark's coarse cap (input edges 5.7 times the target). Its vertices are kept as
  // output vertices, each in a seeded ring (kept_input_vertices.h, seeds_around_points()): the
  // distances both ways are below isotropic_remeshing's 0.000415 of the diagonal (measured
  // 0.000352; 0.000516 when its vertices were cut off).
  Mesh mesh, output;
  bm::make_spherical_cap(mesh, 120., 16, 48);
  check_remeshing(mesh, 20., CGAL::parameters::default_values(), &output);
  const auto fidelity = CR::compare_to_reference(output, mesh);
  EXPECT_LT(fidelity.relative_distance_to_reference, 0.0004);
  EXPECT_LT(fidelity.relative_distance_from_reference, 0.0004);
}

TEST(RemeshConformal, FineSphericalCapHasItsEdgesWithinTheRange)
{
  // The benchmark's fine cap (76801 vertices, slivers fanned around the pole). The refinement
  // grows a lattice of one planar spacing from the middle, whose surface edges shrink with the
  // map's scale toward the border (1.08 to 0.85 times the target), and where it meets the mesh
  // grown from the border the splits of the long edges pile up: 94.6% of the edges were within
  // [0.7, 1.4] times the target until the short ones were collapsed after the splits, 99.4% with
  // the collapses (2026-11-27).
  Mesh mesh;
  bm::make_spherical_cap(mesh, 120., 160, 480);
  CR::Remeshing_statistics statistics;
  check_remeshing(mesh, remeshing_checks::Quality_bars(30.).edge_share_above(0.98), CR::parameters::statistics(std::ref(statistics)));
  EXPECT_GT(statistics.optimization_collapses, 100u);
}

TEST(RemeshConformal, CgalNefertiti)
{
  // A coarse scan (299 vertices, edges 5 times the target): its tips are kept as output
  // vertices, and no point of the input is farther than 0.003 of the diagonal from the output
  // (measured 0.0024; 0.0040 when the tips were cut off, isotropic_remeshing 0.0024).
  Mesh mesh, output;
  ASSERT_TRUE(CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/nefertiti.off", mesh).is_valid());
  check_remeshing(mesh, 20., CGAL::parameters::default_values(), &output);
  EXPECT_LT(CR::compare_to_reference(output, mesh).relative_distance_from_reference, 0.003);
}

TEST(RemeshConformal, CgalBladeWithTinyCurvesAtTheEndsOfAThinStrip)
{
  // A flat strip 0.033 wide (a fortieth of the target) along the trailing edge: its ends are
  // curves of one chord that tiny, and the curves that meet them are sampled graded from it (see
  // `tiny_curve`). With chords a target long beside them, a triangle had 0.034 degrees; 16.6 now,
  // with 94% of the edges within the range (the graded ones are shorter).
  Mesh mesh;
  ASSERT_TRUE(CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/blade.off", mesh).is_valid());
  check_remeshing(mesh, remeshing_checks::Quality_bars(15.).edge_share_above(0.93));
}

TEST(RemeshConformal, CgalDinoScanDropsTheFeaturesItsNoiseMakes)
{
  // A scan: at the default features angle its noise makes hundreds of sharp edges, between which
  // a patch's conformal scale varies by a factor of 5522 even after 8 bisections.
  // The remesher then segments it again without features (`features_fallback`): smallest angle
  // 30 degrees, but 91% of the edges within [0.7, 1.4] times the target (47 patches, 36 of the
  // cuts between them by planes; which edges fall outside is not analysed yet).
  Mesh mesh;
  ASSERT_TRUE(CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/dino.off", mesh).is_valid());
  const CR::Remeshing_report report = check_remeshing(mesh, remeshing_checks::Quality_bars(25.).edge_share_above(0.9));
  EXPECT_TRUE(report.features_dropped);
  EXPECT_EQ(report.feature_edges, 0u);
  EXPECT_NE(report.features_fallback_reason.find("cannot be flattened after 8 bisections"), std::string::npos)
    << report.features_fallback_reason;
  // Told to keep its features, the remesher fails as it did before, saying why.
  Mesh output;
  try
  {
    CR::remesh_conformal(mesh, output, CR::parameters::features_fallback(false));
    ADD_FAILURE() << "no error without the fallback";
  }
  catch(const CR::Error& e)
  {
    EXPECT_EQ(e.code(), CR::Error_code::NOT_CONVERGED);
    EXPECT_NE(std::string(e.what()).find("scale ratio"), std::string::npos) << e.what();
  }
}

TEST(RemeshConformal, CgalFemurTinyAnnulusWhoseOuterLoopCutOffItsHole)
{
  // Without features (as the fallback segments it), one of the femur's 48 patches is an annulus
  // of 20 faces whose loops are 1 and 2 targets long. Its outer loop, sampled with 4 chords, cut
  // the hole off in the plane: every chord of the hole failed to glue, however dense (up to 64
  // times), and the remesher gave up. The failing patch's other curves are now sampled more
  // densely too. The femur's mesh: smallest angle 17.7 degrees, mean skewness 0.123, 88% of the
  // edges within [0.7, 1.4] times the target by refinement alone (not analysed yet; the issue's
  // bars are for its models).
  Mesh mesh;
  ASSERT_TRUE(CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/femur.off", mesh).is_valid());
  const CR::Remeshing_report report
    = check_remeshing(mesh, remeshing_checks::Quality_bars(15.).mean_skewness_at_most(0.12).edge_share_above(0.8),
                      CR::parameters::features_angle(0.));
  EXPECT_GT(report.refined_boundary_curves, 0u);
  // With frontally placed points, a patch whose loop passes one sample twice got a flip that
  // joined the other image of that sample to its chord's other end (a second edge on the chord),
  // and the surface was meshed again by refinement alone; no flip makes such an edge since
  // (test `SurfaceOptimization.NoFlipMakesASecondEdgeOnAChordOfAPatchThatTouchesItself`). Then,
  // meshed again finer where the output intersected itself, a frontal point 1e-17 off a chord
  // made a flat triangle whose circumcentre CGAL's refinement divided by zero (an assertion in
  // this build, which keeps them): frontal points keep a tenth of their target off constraints
  // since (`Frontal_inserter_2::min_constraint_distance`), and the refinement leaves such
  // faces alone (`Bad_face_queue_2::has_refinement_point()`). Measured: smallest angle 19.0
  // degrees, mean skewness 0.110, after three rounds of meshing again finer, which leave 82.5% of
  // the edges within [0.7, 1.4] times the target (the shorter edges near the crossings).
  EXPECT_FALSE(report.frontal_dropped) << report.frontal_fallback_reason;
}

TEST(RemeshConformal, FrontalInsertionAgainstRefinementAlone)
{
  // The benchmark's CAD sheet with one hole (sliver fans on a bent sheet): from frontally
  // inserted points (the default) and by Delaunay refinement alone with one Laplacian pass (the
  // planar stage until 2026-12-01), both meet the issue's bars; the frontal mesh is much more
  // regular (measured: mean skewness 0.043 against 0.102).
  Mesh mesh, fronted, refined;
  bm::Perforated_plate_parameters p;
  p.number_of_random_holes = 1;
  bm::make_perforated_sheet(mesh, p, 0.3, true);
  const CR::Remeshing_report with = check_remeshing(mesh, 25., CGAL::parameters::default_values(), &fronted);
  const CR::Remeshing_report without = check_remeshing(mesh, 25., CR::parameters::frontal_insertion(false), &refined);
  EXPECT_FALSE(with.frontal_dropped);
  EXPECT_FALSE(without.frontal_dropped);
  const double a = CR::mesh_quality(fronted).skewness.mean, b = CR::mesh_quality(refined).skewness.mean;
  std::cout << "mean skewness: frontal " << a << ", refinement alone " << b << std::endl;
  EXPECT_LT(a, 0.06);
  EXPECT_LT(a, 0.6 * b);
}

TEST(RemeshConformal, InPlaceEqualsSeparateOutput)
{
  Mesh mesh;
  bm::make_spherical_cap(mesh, 90., 8, 24);
  Mesh output;
  CR::remesh_conformal(mesh, output, CR::parameters::relative_target_edge_length(0.05));
  Mesh in_place = mesh;
  CGAL::remesh_conformal(in_place, CR::parameters::relative_target_edge_length(0.05)); // found in namespace CGAL
  EXPECT_EQ(in_place.number_of_vertices(), output.number_of_vertices());
  EXPECT_EQ(in_place.number_of_faces(), output.number_of_faces());
  EXPECT_NE(in_place.number_of_vertices(), mesh.number_of_vertices());
}

TEST(RemeshConformal, TargetEdgeLengthControlsTheSize)
{
  Mesh mesh;
  bm::make_spherical_cap(mesh, 90., 8, 24);
  Mesh coarse, fine;
  const CR::Remeshing_report a = CR::remesh_conformal(mesh, coarse, CR::parameters::target_edge_length(0.1));
  const CR::Remeshing_report b = CR::remesh_conformal(mesh, fine, CR::parameters::target_edge_length(0.05));
  EXPECT_EQ(a.target_edge_length, 0.1);
  // Half the edge length, about four times the faces.
  const double ratio = double(fine.number_of_faces()) / double(coarse.number_of_faces());
  EXPECT_GT(ratio, 3.);
  EXPECT_LT(ratio, 5.);
  (void)b;
}

TEST(RemeshConformal, ReportsWhereTheMeshingStageTimeGoes)
{
  // The set-up phases are what the timed phases leave of their stage's time: a phase timed
  // outside its stage could make them negative. One timed over another shows below, where the
  // smoothing and the optimization do not run.
  Mesh mesh;
  bm::make_spherical_cap(mesh, 90., 8, 24);
  const auto planar_sum = [](const CR::Meshing_phase_seconds& p) { return p.planar_setup + p.planar_refinement + p.planar_smoothing; };
  const auto optimization_sum = [](const CR::Meshing_phase_seconds& p) {
    return p.optimization_setup + p.first_rounds + p.splits + p.collapses + p.skewness_passes + p.angle_passes;
  };
  Mesh output;
  // One Laplacian pass in the plane, which frontal insertion (the default) does without.
  CR::Remeshing_statistics report;
  CR::remesh_conformal(mesh, output,
                       CR::parameters::statistics(std::ref(report),
                                                  CR::parameters::smoothing_iterations(1, CR::parameters::relative_target_edge_length(0.02))));
  const CR::Meshing_phase_seconds& phases = report.meshing_phases;
  for(double seconds : {phases.planar_setup, phases.optimization_setup, phases.collapses, phases.angle_passes})
    EXPECT_GE(seconds, 0.);
  for(double seconds : {phases.planar_refinement, phases.planar_smoothing, phases.first_rounds, phases.splits, phases.skewness_passes})
    EXPECT_GT(seconds, 0.);
  EXPECT_NEAR(planar_sum(phases), report.seconds_planar_meshing, 1e-9);
  EXPECT_NEAR(optimization_sum(phases), report.seconds_optimization, 1e-9);
  // (No bound on the phases' shares of the stage: on a loaded machine the set-up took 54% of a
  // 0.02-second planar stage. Speed is measured in the benchmarks, not asserted here.)

  // Without the smoothing and the optimization, their phases take no time (the smoothing's, two
  // clock readings apart; a preemption there could add a little).
  CR::Remeshing_statistics refinement_only;
  CR::remesh_conformal(mesh, output,
                       CR::parameters::statistics(std::ref(refinement_only),
                                                  CR::parameters::smoothing_iterations(
                                                    0, CR::parameters::optimization_rounds(0, CR::parameters::relative_target_edge_length(0.02)))));
  const CR::Meshing_phase_seconds& refined = refinement_only.meshing_phases;
  EXPECT_GT(refined.planar_refinement, 0.);
  EXPECT_LT(refined.planar_smoothing, 0.5 * refined.planar_refinement);
  EXPECT_EQ(refined.first_rounds + refined.splits + refined.collapses + refined.skewness_passes + refined.angle_passes, 0.);
  EXPECT_GE(refined.optimization_setup, 0.);
}

// Mean length of the output edges whose midpoint satisfies `where`.
template <typename Where>
double mean_edge_length(const Mesh& m, const Where& where)
{
  double sum = 0.;
  std::size_t n = 0;
  for(auto e : m.edges())
  {
    const K::Point_3 a = m.point(m.source(m.halfedge(e))), b = m.point(m.target(m.halfedge(e)));
    if(where(CGAL::midpoint(a, b)))
    {
      sum += std::sqrt(CGAL::squared_distance(a, b));
      ++n;
    }
  }
  return n > 0 ? sum / double(n) : 0.;
}

TEST(Sizing, AChordErrorBoundShortensTheEdgesOnCurvedParts)
{
  // A unit hemisphere on a flat annulus around it, the target length 0.25: a chord error of 0.002
  // asks for sqrt(8 * 0.002 * 1) = 0.126 on the sphere (a chord's sagitta is L^2 / 8R); the flat
  // annulus, farther than the gradation reaches, keeps the target. The rim is a sharp feature (90
  // degrees), which does not count as curvature.
  Mesh mesh;
  bm::make_spherical_cap(mesh, 90., 16, 48);
  std::vector<Mesh::Halfedge_index> rim;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h))
      rim.push_back(h);
  Mesh flat;
  {
    // The annulus from radius 1 to 4, in the plane z = 0, sharing the hemisphere's rim.
    std::map<Mesh::Vertex_index, Mesh::Vertex_index> copy;
    for(auto v : mesh.vertices())
      copy[v] = flat.add_vertex(mesh.point(v));
    for(auto f : mesh.faces())
    {
      std::vector<Mesh::Vertex_index> corners;
      for(auto v : mesh.vertices_around_face(mesh.halfedge(f)))
        corners.push_back(copy[v]);
      flat.add_face(corners);
    }
    for(auto h : rim)
    {
      const K::Point_3 a = mesh.point(mesh.source(h)), b = mesh.point(mesh.target(h));
      const Mesh::Vertex_index a_out = flat.add_vertex(K::Point_3(4. * a.x(), 4. * a.y(), 0.)),
                               b_out = flat.add_vertex(K::Point_3(4. * b.x(), 4. * b.y(), 0.));
      // The cap lies right of the border halfedge a -> b, the annulus left of it.
      flat.add_face(copy[mesh.source(h)], copy[mesh.target(h)], b_out);
      flat.add_face(copy[mesh.source(h)], b_out, a_out);
    }
    CGAL::Polygon_mesh_processing::stitch_borders(flat);
  }
  ASSERT_TRUE(CR::check_mesh(flat).is_valid()) << CR::check_mesh(flat).summary();

  Mesh uniform, adaptive;
  std::vector<CR::Surface_location> locations;
  CR::remesh_conformal(flat, uniform, CR::parameters::target_edge_length(0.25));
  CR::remesh_conformal(flat, adaptive,
                       CR::parameters::vertex_locations(
                         std::ref(locations), CR::parameters::maximum_chord_error(0.002, CR::parameters::target_edge_length(0.25))));
  check_topology_and_fidelity(flat, adaptive, locations);
  const auto on_sphere = [](const K::Point_3& p) { return p.z() > 0.2; };
  const auto far_out = [](const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() > 9.; };
  const double expected = std::sqrt(8. * 0.002);
  EXPECT_NEAR(mean_edge_length(uniform, on_sphere), 0.25, 0.25 * 0.3);
  EXPECT_GT(mean_edge_length(adaptive, on_sphere), 0.7 * expected);
  EXPECT_LT(mean_edge_length(adaptive, on_sphere), 1.3 * expected);
  EXPECT_NEAR(mean_edge_length(adaptive, far_out), mean_edge_length(uniform, far_out), 0.25 * 0.15);
  // No bend, no change: a chord error the target length already meets.
  Mesh loose;
  CR::remesh_conformal(flat, loose, CR::parameters::maximum_chord_error(1., CR::parameters::target_edge_length(0.25)));
  EXPECT_EQ(loose.number_of_vertices(), uniform.number_of_vertices());
}

TEST(Sizing, AUserFieldSetsTheLengthWhereItIsSmaller)
{
  Mesh mesh;
  bm::make_spherical_cap(mesh, 90., 16, 48);
  Mesh output;
  std::vector<CR::Surface_location> locations;
  const auto field = [](const K::Point_3& p) { return p.x() > 0. ? 0.05 : 1.; };
  CR::remesh_conformal(mesh, output, CR::parameters::vertex_locations(std::ref(locations), CR::parameters::sizing_field(field, CR::parameters::target_edge_length(0.15))));
  check_topology_and_fidelity(mesh, output, locations);
  const double fine = mean_edge_length(output, [](const K::Point_3& p) { return p.x() > 0.2; });
  const double coarse = mean_edge_length(output, [](const K::Point_3& p) { return p.x() < -0.5; });
  EXPECT_NEAR(fine, 0.05, 0.05 * 0.3);
  EXPECT_NEAR(coarse, 0.15, 0.15 * 0.3); // the target length bounds the field
  test_support::expect_error([&] { CR::remesh_conformal(mesh, CR::parameters::maximum_chord_error(-1.)); },
                             CR::Error_code::INVALID_INPUT, {"chord error"});
}

TEST(Sizing, ShorterNearThePlacesToMeshAgain)
{
  // The field for meshing again where an output intersected itself: the given size at the
  // places, growing by half the distance to the nearest, never above the user's field.
  namespace RM = CR::internal::remeshing;
  std::vector<K::Point_3> places;
  RM::add_if_far(places, K::Point_3(0., 0., 0.), 0.25);
  RM::add_if_far(places, K::Point_3(0.2, 0., 0.), 0.25); // within a quarter: the same place
  RM::add_if_far(places, K::Point_3(4., 0., 0.), 0.25);
  ASSERT_EQ(places.size(), 2u);
  const RM::Sizing::Field none, user = [](const K::Point_3& p) { return p.y() > 0. ? 0.1 : 10.; };
  const RM::Sizing::Field near = RM::shorter_near(none, places, 0.5), both = RM::shorter_near(user, places, 0.5);
  EXPECT_DOUBLE_EQ(near(K::Point_3(0., 0., 0.)), 0.5);
  EXPECT_DOUBLE_EQ(near(K::Point_3(4., 0., 1.)), 1.);   // 0.5 + 0.5 * 1 from the second place
  EXPECT_DOUBLE_EQ(near(K::Point_3(2., 0., 0.)), 1.5);  // halfway: 2 from both
  EXPECT_DOUBLE_EQ(both(K::Point_3(2., 1., 0.)), 0.1);  // the user's field where it is smaller
  EXPECT_NEAR(both(K::Point_3(2., -1., 0.)), 0.5 + 0.5 * std::sqrt(5.), 1e-12);
}

namespace {

namespace RM = CR::internal::remeshing;

// The loops of the square [-1, 1]^2 with the hole [-0.3, 0.3]^2, their corners as samples.
std::vector<std::vector<RM::Boundary_sample> > square_with_square_hole()
{
  std::vector<RM::Boundary_sample> outer, hole;
  const double x[4] = {-1, 1, 1, -1}, y[4] = {-1, -1, 1, 1};
  for(int i = 0; i < 4; ++i)
  {
    outer.push_back(RM::Boundary_sample{CGAL::Epick::Point_2(x[i], y[i]), CGAL::Epick::Point_3(x[i], y[i], 0.)});
    hole.push_back(RM::Boundary_sample{CGAL::Epick::Point_2(0.3 * x[3 - i], 0.3 * y[3 - i]), CGAL::Epick::Point_3(0.3 * x[3 - i], 0.3 * y[3 - i], 0.)});
  }
  return {outer, hole};
}

// What the planar tests check of a planar mesh: whether every triangle is counterclockwise, the
// vertices the triangles use, the area covered, the smallest angle, the mean equiangle skewness,
// and the mean length of the edges (counted once per triangle side) where x < -0.5 and x > 0.5.
struct Planar_mesh_measures
{
  bool counterclockwise = true;
  std::set<int> used_vertices;
  double area = 0., smallest_angle = 180., mean_skewness = 0., coarse_side = 0., fine_side = 0.;
  explicit Planar_mesh_measures(const RM::Planar_mesh& m)
  {
    double coarse = 0., fine = 0.;
    std::size_t n_coarse = 0, n_fine = 0;
    for(const auto& t : m.triangles)
    {
      const CGAL::Epick::Point_2 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
      counterclockwise = counterclockwise && CGAL::orientation(a, b, c) == CGAL::POSITIVE;
      used_vertices.insert(t.begin(), t.end());
      area += CGAL::area(a, b, c);
      const CR::Triangle_quality q = CR::triangle_quality(K::Point_3(a.x(), a.y(), 0), K::Point_3(b.x(), b.y(), 0), K::Point_3(c.x(), c.y(), 0));
      smallest_angle = (std::min)({smallest_angle, q.angles[0], q.angles[1], q.angles[2]});
      mean_skewness += q.skewness / double(m.triangles.size());
      for(int i = 0; i < 3; ++i)
      {
        const CGAL::Epick::Point_2 &p = m.points[t[i]], &r = m.points[t[(i + 1) % 3]];
        const double x = 0.5 * (p.x() + r.x()), length = std::sqrt(CGAL::squared_distance(p, r));
        if(x < -0.5)
          coarse += length, ++n_coarse;
        else if(x > 0.5)
          fine += length, ++n_fine;
      }
    }
    coarse_side = n_coarse > 0 ? coarse / double(n_coarse) : 0.;
    fine_side = n_fine > 0 ? fine / double(n_fine) : 0.;
  }
};

} // namespace

TEST(RemeshConformal, PlanarStageWithExactConstructions)
{
  // The planar mesher is templated on the kernel: a square with a square hole over Epeck.
  const std::vector<std::vector<RM::Boundary_sample> > loops = square_with_square_hole();
  const RM::Planar_mesh exact = RM::mesh_planar_domain<CGAL::Epeck>(loops, 25., [](const CGAL::Epick::Point_2&) { return 0.2; }, 1);
  const RM::Planar_mesh inexact = RM::mesh_planar_domain<CGAL::Epick>(loops, 25., [](const CGAL::Epick::Point_2&) { return 0.2; }, 1);
  for(const RM::Planar_mesh* m : {&exact, &inexact})
  {
    ASSERT_GT(m->triangles.size(), 50u);
    const Planar_mesh_measures measures(*m);
    EXPECT_TRUE(measures.counterclockwise);
    EXPECT_NEAR(measures.area, 4. - 0.36, 1e-12); // the square minus the hole, exactly covered
    // The bound asked for, not CGAL's default of 20.7 degrees (which the criteria fell back to
    // when their virtual base was left to its default constructor).
    EXPECT_GE(measures.smallest_angle, 25.);
  }
}

namespace {

// The surface z = 0.2 sin(3x) over the plane: its map from the plane is not conformal, so the
// optimization has to judge shapes on the surface, not in the plane.
CGAL::Epick::Point_3 wavy_lift(const CGAL::Epick::Point_2& p) { return CGAL::Epick::Point_3(p.x(), p.y(), 0.2 * std::sin(3. * p.x())); }
// The same as the optimizer calls it (with a search hint, unused here)
CGAL::Epick::Point_3 wavy_lift_near(const CGAL::Epick::Point_2& p, std::size_t&) { return wavy_lift(p); }

// A square loop of side 2 `half`, sampled every `spacing`, counterclockwise or clockwise.
std::vector<RM::Boundary_sample> sampled_square(double half, double spacing, bool clockwise)
{
  std::vector<CGAL::Epick::Point_2> corners{{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  if(clockwise)
    std::reverse(corners.begin(), corners.end());
  const int pieces = int(std::lround(2. * half / spacing));
  std::vector<RM::Boundary_sample> loop;
  for(int side = 0; side < 4; ++side)
    for(int i = 0; i < pieces; ++i)
    {
      const CGAL::Epick::Point_2 p = CGAL::barycenter(corners[side], double(pieces - i), corners[(side + 1) % 4], double(i));
      loop.push_back(RM::Boundary_sample{p, wavy_lift(p)});
    }
  return loop;
}

struct Optimized_mesh_statistics
{
  double planar_area = 0., smallest_angle = 180., mean_skewness = 0.;
  std::size_t folded = 0, regular = 0, irregular = 0;
  std::set<std::pair<int, int> > boundary_edges; // directed
  bool manifold = true;
};

Optimized_mesh_statistics statistics(const std::vector<CGAL::Epick::Point_2>& points, const std::vector<CGAL::Epick::Point_3>& positions,
                                     const std::vector<std::array<int, 3> >& triangles)
{
  Optimized_mesh_statistics s;
  std::map<std::pair<int, int>, int> directed;
  for(const auto& t : triangles)
  {
    s.folded += CGAL::orientation(points[t[0]], points[t[1]], points[t[2]]) != CGAL::POSITIVE;
    s.planar_area += CGAL::area(points[t[0]], points[t[1]], points[t[2]]);
    const CR::Triangle_quality q = CR::triangle_quality(positions[t[0]], positions[t[1]], positions[t[2]]);
    s.smallest_angle = (std::min)({s.smallest_angle, q.angles[0], q.angles[1], q.angles[2]});
    s.mean_skewness += q.skewness / double(triangles.size());
    for(int k = 0; k < 3; ++k)
      s.manifold = s.manifold && ++directed[std::make_pair(t[k], t[(k + 1) % 3])] == 1;
  }
  std::vector<std::set<int> > neighbours(points.size());
  std::set<int> on_boundary;
  for(const auto& e : directed)
  {
    neighbours[e.first.first].insert(e.first.second);
    if(directed.count(std::make_pair(e.first.second, e.first.first)) == 0)
    {
      s.boundary_edges.insert(e.first);
      on_boundary.insert(e.first.first);
      on_boundary.insert(e.first.second);
    }
  }
  for(std::size_t v = 0; v < points.size(); ++v)
    if(on_boundary.count(int(v)) == 0)
      (neighbours[v].size() == 6 ? s.regular : s.irregular) += 1;
  return s;
}

// A square with a square hole, refined and smoothed as remesh_conformal() does it, on the wavy
// surface; the boundary samples are shared with a neighbour (fixed).
struct Optimization_case
{
  RM::Planar_mesh raw;
  std::vector<CGAL::Epick::Point_2> points;
  std::vector<CGAL::Epick::Point_3> positions;
  std::vector<std::array<int, 3> > triangles;
  std::function<CGAL::Epick::Point_3(const CGAL::Epick::Point_2&)> lift;
  // as the optimizer calls it
  CGAL::Epick::Point_3 operator()(const CGAL::Epick::Point_2& p, std::size_t&) const { return lift(p); }
};

Optimization_case square_with_hole(double size, std::function<CGAL::Epick::Point_3(const CGAL::Epick::Point_2&)> lift = wavy_lift)
{
  const std::vector<std::vector<RM::Boundary_sample> > loops{sampled_square(1., 0.05, false), sampled_square(0.3, 0.05, true)};
  Optimization_case c;
  c.raw = RM::mesh_planar_domain<CGAL::Epick>(loops, 28., [size](const CGAL::Epick::Point_2&) { return size; }, 3, false);
  c.points = c.raw.points;
  c.triangles = c.raw.triangles;
  c.lift = lift;
  for(const auto& p : c.points)
    c.positions.push_back(lift(p));
  return c;
}

// The rounds of flips and smoothing that optimize_on_surface() runs before its splits.
template <typename Optimizer>
void run_rounds(Optimizer& optimizer, int rounds)
{
  for(int round = 0; round < rounds; ++round)
  {
    optimizer.flip_pass(Optimizer::VALENCE);
    optimizer.flip_pass(Optimizer::SHAPE);
    optimizer.smoothing_pass();
    optimizer.smoothing_pass();
  }
}

RM::Edge_split_bounds longer_than(double length)
{
  RM::Edge_split_bounds bounds;
  bounds.longest = length;
  return bounds;
}

double longest_edge(const std::vector<std::array<int, 3> >& triangles, const std::vector<CGAL::Epick::Point_3>& at)
{
  double longest = 0.;
  for(const auto& t : triangles)
    for(int c = 0; c < 3; ++c)
      longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(at[t[c]], at[t[(c + 1) % 3]])));
  return longest;
}

// Triangle sides (an inner edge counted twice) whose surface length is longer than `length`, or
// shorter.
std::size_t count_sides(const std::vector<std::array<int, 3> >& triangles, const std::vector<CGAL::Epick::Point_3>& at,
                        const std::function<bool(double)>& counts_squared_length)
{
  std::size_t n = 0;
  for(const auto& t : triangles)
    for(int c = 0; c < 3; ++c)
      n += counts_squared_length(CGAL::squared_distance(at[t[c]], at[t[(c + 1) % 3]]));
  return n;
}

std::size_t sides_longer_than(double length, const std::vector<std::array<int, 3> >& triangles, const std::vector<CGAL::Epick::Point_3>& at)
{
  return count_sides(triangles, at, [length](double squared) { return squared > length * length; });
}

std::size_t sides_shorter_than(double length, const std::vector<std::array<int, 3> >& triangles, const std::vector<CGAL::Epick::Point_3>& at)
{
  return count_sides(triangles, at, [length](double squared) { return squared < length * length; });
}

// What every optimization keeps: the domain exactly covered and unfolded, its boundary and samples,
// the vertices on the surface, and no angle below the bound that was not there before.
void expect_domain_and_bounds_kept(const Optimization_case& c, const Optimized_mesh_statistics& before, const Optimized_mesh_statistics& after)
{
  EXPECT_TRUE(after.manifold);
  EXPECT_EQ(after.folded, 0u);
  EXPECT_NEAR(after.planar_area, 4. - 0.36, 1e-12);
  EXPECT_EQ(after.boundary_edges, before.boundary_edges);
  for(std::size_t v = 0; v < c.raw.number_of_samples; ++v)
    EXPECT_EQ(c.points[v], c.raw.points[v]);
  for(std::size_t v = 0; v < c.points.size(); ++v)
    EXPECT_EQ(c.positions[v], c.lift(c.points[v]));
  EXPECT_GE(after.smallest_angle, (std::min)(28., before.smallest_angle) - 1e-9);
}

} // namespace

TEST(SurfaceOptimization, KeepsTheDomainAndImprovesTheShapesOnTheSurface)
{
  Optimization_case c = square_with_hole(0.07);
  ASSERT_GT(c.raw.triangles.size(), 1000u);
  const Optimized_mesh_statistics before = statistics(c.points, c.positions, c.triangles);
  const double longest_before = longest_edge(c.triangles, c.positions);

  const RM::Surface_optimization_report report =
    RM::optimize_on_surface(c.points, c.positions, c.triangles, c.raw.number_of_samples, c, 28., 0.07, RM::Edge_split_bounds(), 5);
  EXPECT_TRUE(report.optimized);
  EXPECT_GT(report.flips, 0u);
  EXPECT_GT(report.moves, 0u);
  EXPECT_EQ(report.splits, 0u);
  ASSERT_EQ(c.points.size(), c.raw.points.size());
  ASSERT_EQ(c.triangles.size(), c.raw.triangles.size());
  const Optimized_mesh_statistics after = statistics(c.points, c.positions, c.triangles);
  expect_domain_and_bounds_kept(c, before, after);
  // No edge on the surface longer than the bound given (0.07), or than the longest one before.
  EXPECT_LE(longest_edge(c.triangles, c.positions), (std::max)(0.07, longest_before) * (1. + 1e-12));
  EXPECT_GT(after.regular, before.regular);
  EXPECT_LT(after.mean_skewness, before.mean_skewness - 0.02);
  // Issue #5's bar of 0.12 is for whole remeshings (checked in remeshing_checks.h); on this small
  // domain a large share of the triangles touch the fixed boundary samples.
  EXPECT_LT(after.mean_skewness, 0.125);
}

TEST(SurfaceOptimization, MovesInParallelGiveTheSameMeshAsInOrder)
{
  // The moves of a class of vertices, no two of them neighbours, run at once (with TBB): the
  // result must not depend on it. Fine enough for classes of hundreds of vertices, that TBB
  // cuts into blocks; with splits, so that the classes change between passes.
  Optimization_case in_order = square_with_hole(0.035), in_parallel = square_with_hole(0.035);
  ASSERT_GT(in_order.raw.points.size(), 3000u);
  const RM::Surface_optimization_report a = RM::optimize_on_surface(
    in_order.points, in_order.positions, in_order.triangles, in_order.raw.number_of_samples, in_order, 28., 0.035, longer_than(0.032), 5, {}, {}, false);
  const RM::Surface_optimization_report b = RM::optimize_on_surface(
    in_parallel.points, in_parallel.positions, in_parallel.triangles, in_parallel.raw.number_of_samples, in_parallel, 28., 0.035, longer_than(0.032), 5, {}, {}, true);
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << "moves in parallel with TBB: ";
#else
  std::cout << "no TBB, moves in order both times: ";
#endif
  std::cout << a.moves << " moves, " << a.flips << " flips, " << a.splits << " splits" << std::endl;
  EXPECT_GT(a.moves, 1000u);
  EXPECT_GT(a.splits, 0u);
  EXPECT_EQ(a.moves, b.moves);
  EXPECT_EQ(a.flips, b.flips);
  EXPECT_EQ(a.splits, b.splits);
  EXPECT_EQ(a.angle_changes, b.angle_changes);
  EXPECT_EQ(in_order.triangles, in_parallel.triangles);
  EXPECT_EQ(in_order.points, in_parallel.points);
  EXPECT_EQ(in_order.positions, in_parallel.positions);
}

TEST(SurfaceOptimization, SplitsTheLongInnerEdgesAndKeepsTheEdgesShorterAfterwards)
{
  // Refined to 0.07 as above; without splits, the optimization leaves edges up to 0.07 long.
  Optimization_case plain = square_with_hole(0.07), split = square_with_hole(0.07);
  const double split_length = 0.064; // about 1.28 / 1.4 of the longest edge bound, as remesh_conformal() splits
  RM::optimize_on_surface(plain.points, plain.positions, plain.triangles, plain.raw.number_of_samples, plain, 28., 0.07, RM::Edge_split_bounds(), 5);
  const std::size_t long_without_splits = sides_longer_than(split_length, plain.triangles, plain.positions);
  ASSERT_GT(long_without_splits, 100u);

  const Optimized_mesh_statistics before = statistics(split.points, split.positions, split.triangles);
  const RM::Surface_optimization_report report = RM::optimize_on_surface(
    split.points, split.positions, split.triangles, split.raw.number_of_samples, split, 28., 0.07, longer_than(split_length), 5);
  EXPECT_TRUE(report.optimized);
  EXPECT_GT(report.splits, 0u);
  EXPECT_EQ(report.chord_splits, 0u);
  // Each split adds one vertex and two triangles.
  EXPECT_EQ(split.points.size(), split.raw.points.size() + report.splits);
  EXPECT_EQ(split.triangles.size(), split.raw.triangles.size() + 2 * report.splits);
  const Optimized_mesh_statistics after = statistics(split.points, split.positions, split.triangles);
  expect_domain_and_bounds_kept(split, before, after);
  const std::size_t long_with_splits = sides_longer_than(split_length, split.triangles, split.positions);
  std::cout << "sides longer than the split length: " << long_without_splits << " without splits, " << long_with_splits
            << " with " << report.splits << " splits" << std::endl;
  EXPECT_LT(long_with_splits, long_without_splits / 10);
  EXPECT_LE(longest_edge(split.triangles, split.positions), longest_edge(plain.triangles, plain.positions) * (1. + 1e-12));
  // The new vertices' valence-4 stars are flipped and smoothed out.
  EXPECT_LT(after.mean_skewness, before.mean_skewness - 0.02);
  EXPECT_LT(after.mean_skewness, statistics(plain.points, plain.positions, plain.triangles).mean_skewness + 0.005);
}

TEST(SurfaceOptimization, CollapsesTheShortInnerEdgesAndKeepsTheDomainAndBounds)
{
  // As remesh_conformal() runs it, for a target h = 0.05: the refinement and the optimization
  // bound the edges by 1.4 h, the splits from 1.26 h leave halves of 0.63 h, and the edges under
  // 0.7 h are collapsed after the splits.
  const double h = 0.05;
  Optimization_case plain = square_with_hole(1.4 * h), collapsed = square_with_hole(1.4 * h);
  const RM::Surface_optimization_report without = RM::optimize_on_surface(
    plain.points, plain.positions, plain.triangles, plain.raw.number_of_samples, plain, 28., 1.4 * h, longer_than(1.26 * h), 5);
  const std::size_t short_without = sides_shorter_than(0.7 * h, plain.triangles, plain.positions);
  ASSERT_GT(short_without, 50u);
  EXPECT_EQ(without.collapses, 0u);

  const Optimized_mesh_statistics before = statistics(collapsed.points, collapsed.positions, collapsed.triangles);
  const RM::Surface_optimization_report report =
    RM::optimize_on_surface(collapsed.points, collapsed.positions, collapsed.triangles, collapsed.raw.number_of_samples, collapsed, 28.,
                            1.4 * h, longer_than(1.26 * h), 5, {}, {}, false, 0.7 * h);
  EXPECT_GT(report.collapses, 0u);
  // Each collapse removes one vertex and two triangles; the vertices left are numbered in order,
  // and each is a corner of some triangle.
  EXPECT_EQ(collapsed.points.size() + report.collapses, collapsed.raw.points.size() + report.splits);
  EXPECT_EQ(collapsed.triangles.size() + 2 * report.collapses, collapsed.raw.triangles.size() + 2 * report.splits);
  std::vector<char> used(collapsed.points.size(), 0);
  for(const auto& t : collapsed.triangles)
    for(int v : t)
    {
      ASSERT_GE(v, 0);
      ASSERT_LT(std::size_t(v), used.size());
      used[std::size_t(v)] = 1;
    }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  const Optimized_mesh_statistics after = statistics(collapsed.points, collapsed.positions, collapsed.triangles);
  expect_domain_and_bounds_kept(collapsed, before, after);
  const std::size_t short_with = sides_shorter_than(0.7 * h, collapsed.triangles, collapsed.positions);
  std::cout << "sides shorter than 0.7 h: " << short_without << " without collapses, " << short_with << " after "
            << report.collapses << " collapses (" << report.splits << " splits)" << std::endl;
  // (298 and 124 when written: on this small domain many short edges end on the boundary
  // samples, whose edges are not collapsed.)
  EXPECT_LT(short_with, short_without / 2);
  // No longer edge than the bound the splits set (or than without the collapses), and no worse
  // shapes.
  EXPECT_LE(longest_edge(collapsed.triangles, collapsed.positions), (std::max)(1.26 * h, longest_edge(plain.triangles, plain.positions)) * (1. + 1e-12));
  EXPECT_LT(after.mean_skewness, statistics(plain.points, plain.positions, plain.triangles).mean_skewness + 0.002);
}

namespace {

// A surface folded at right angles (slopes of -1 and 1) along the lines x = 0.2 k, and how far
// the chords of the inner edges at least `shortest` long cut under its creases: the distance
// from each chord's midpoint to the surface point of the planar midpoint.
CGAL::Epick::Point_3 creased_lift(const CGAL::Epick::Point_2& p)
{
  return CGAL::Epick::Point_3(p.x(), p.y(), std::abs(p.x() - 0.4 * std::round(p.x() / 0.4)));
}

std::vector<double> chord_gaps(const Optimization_case& c, double shortest)
{
  std::map<std::pair<int, int>, int> sides;
  for(const auto& t : c.triangles)
    for(int k = 0; k < 3; ++k)
      ++sides[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<double> gaps;
  for(const auto& side : sides)
  {
    const int a = side.first.first, b = side.first.second;
    if(side.second == 2 && CGAL::squared_distance(c.positions[a], c.positions[b]) >= shortest * shortest)
      gaps.push_back(std::sqrt(CGAL::squared_distance(CGAL::midpoint(c.positions[a], c.positions[b]),
                                                      c.lift(CGAL::midpoint(c.points[a], c.points[b])))));
  }
  return gaps;
}

} // namespace

TEST(SurfaceOptimization, SplitsTheEdgesThatCutUnderABend)
{
  // Refined to h = 0.07 in the plane and optimized as remesh_conformal() does before its splits.
  const double h = 0.07, bound = 0.15 * h, shortest = 0.9 * h;
  Optimization_case c = square_with_hole(h, creased_lift);
  typedef RM::Surface_mesh_optimizer<Optimization_case> Optimizer;
  Optimizer optimizer(c.points, c.positions, c.triangles, c, 28., 1.4 * h);
  ASSERT_TRUE(optimizer.initialize(c.raw.number_of_samples));
  run_rounds(optimizer, 5);
  const auto cut_deep = [&](const std::vector<double>& gaps) { return std::count_if(gaps.begin(), gaps.end(), [&](double g) { return g > bound; }); };
  const std::vector<double> gaps_before = chord_gaps(c, shortest);
  ASSERT_GT(cut_deep(gaps_before), 20);
  const Optimized_mesh_statistics before = statistics(c.points, c.positions, c.triangles);
  const std::size_t points_before = c.points.size();

  RM::Edge_split_bounds bounds;
  bounds.across_bend = {shortest, bound};
  std::size_t chord_splits = 0;
  const std::size_t splits = optimizer.split_pass(bounds, chord_splits);
  EXPECT_GT(splits, 0u);
  EXPECT_EQ(chord_splits, splits); // no edge was split for its length
  EXPECT_EQ(c.points.size(), points_before + splits);
  const Optimized_mesh_statistics after = statistics(c.points, c.positions, c.triangles);
  expect_domain_and_bounds_kept(c, before, after);
  const std::vector<double> gaps_after = chord_gaps(c, shortest);
  std::cout << "inner chords cutting more than 0.15 h under a crease: " << cut_deep(gaps_before) << " before, "
            << cut_deep(gaps_after) << " after " << splits << " splits; deepest "
            << *std::max_element(gaps_before.begin(), gaps_before.end()) / h << " h, "
            << *std::max_element(gaps_after.begin(), gaps_after.end()) / h << " h" << std::endl;
  // Only a split refused for the angle bound leaves one.
  EXPECT_LT(cut_deep(gaps_after), cut_deep(gaps_before) / 4);
  EXPECT_LE(*std::max_element(gaps_after.begin(), gaps_after.end()), *std::max_element(gaps_before.begin(), gaps_before.end()));
}

TEST(SurfaceOptimization, SplitPassesLiftAMidpointAgainOnlyWhenAnEndMoved)
{
  // Split passes with a bound that names no chord: they lift the midpoints and split nothing.
  const double h = 0.07, shortest = 0.9 * h;
  Optimization_case c = square_with_hole(h, creased_lift);
  std::size_t lifts = 0;
  c.lift = [&lifts](const CGAL::Epick::Point_2& p) { ++lifts; return creased_lift(p); };
  typedef RM::Surface_mesh_optimizer<Optimization_case> Optimizer;
  Optimizer optimizer(c.points, c.positions, c.triangles, c, 28., 1.4 * h);
  ASSERT_TRUE(optimizer.initialize(c.raw.number_of_samples));
  run_rounds(optimizer, 2);
  std::set<std::pair<int, int> > sides, inner_long_enough;
  for(const auto& t : c.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const auto side = std::minmax(t[k], t[(k + 1) % 3]);
      if(!sides.insert(side).second && CGAL::squared_distance(c.positions[side.first], c.positions[side.second]) > shortest * shortest)
        inner_long_enough.insert(side);
    }
  RM::Edge_split_bounds bounds;
  bounds.across_bend = {shortest, 10.}; // no chord stands 10 off
  std::size_t chord_splits = 0;
  lifts = 0;
  ASSERT_EQ(optimizer.split_pass(bounds, chord_splits), 0u);
  const std::size_t first = lifts;
  EXPECT_GT(first, inner_long_enough.size() / 2);
  EXPECT_LE(first, inner_long_enough.size()); // once per edge, not from both sides
  lifts = 0;
  optimizer.split_pass(bounds, chord_splits);
  EXPECT_EQ(lifts, 0u); // nothing moved
  const std::vector<CGAL::Epick::Point_2> before = c.points;
  const std::size_t moves = optimizer.smoothing_pass();
  ASSERT_GT(moves, 0u);
  lifts = 0;
  optimizer.split_pass(bounds, chord_splits);
  std::set<std::pair<int, int> > edges_of_moved; // every edge with a moved end
  for(const auto& t : c.triangles)
    for(int k = 0; k < 3; ++k)
      if(c.points[t[k]] != before[t[k]] || c.points[t[(k + 1) % 3]] != before[t[(k + 1) % 3]])
        edges_of_moved.insert(std::minmax(t[k], t[(k + 1) % 3]));
  EXPECT_GT(lifts, 0u);
  EXPECT_LE(lifts, edges_of_moved.size());
  EXPECT_LT(lifts, first) << moves << " moves";
}

// A cylinder of radius 2.5 h (h = 0.07) around the y axis, unrolled isometrically onto the plane:
// the chord of an edge of length L across it stands about L^2 / (20 h) under the surface, 0.066 h
// at 1.15 h, and nothing along it.
CGAL::Epick::Point_3 cylinder_lift(const CGAL::Epick::Point_2& p)
{
  const double radius = 2.5 * 0.07;
  return CGAL::Epick::Point_3(radius * std::sin(p.x() / radius), p.y(), radius * (1. - std::cos(p.x() / radius)));
}

TEST(SurfaceOptimization, SplitsTheLongChordsOnATightCurveAndKeepsThemOffAfterwards)
{
  const double h = 0.07, bound = 0.045 * h, shortest = 1.15 * h;
  Optimization_case c = square_with_hole(1.3 * h, cylinder_lift); // edges up to the optimizer's 1.4 h
  typedef RM::Surface_mesh_optimizer<Optimization_case> Optimizer;
  Optimizer optimizer(c.points, c.positions, c.triangles, c, 28., 1.4 * h);
  ASSERT_TRUE(optimizer.initialize(c.raw.number_of_samples));
  run_rounds(optimizer, 5);
  const auto sagging = [&]() {
    const std::vector<double> gaps = chord_gaps(c, shortest);
    return std::count_if(gaps.begin(), gaps.end(), [&](double g) { return g > bound; });
  };
  const auto before_split = sagging();
  ASSERT_GT(before_split, 20);
  const Optimized_mesh_statistics before = statistics(c.points, c.positions, c.triangles);

  RM::Edge_split_bounds bounds;
  bounds.tight_curve = {shortest, bound};
  std::size_t chord_splits = 0;
  const std::size_t splits = optimizer.split_pass(bounds, chord_splits);
  EXPECT_EQ(chord_splits, splits);
  const auto after_split = sagging();
  EXPECT_LT(after_split, before_split / 4);

  // The passes that end optimize_on_surface(), with the chords kept: they make none the bound
  // names (a move or flip could only replace one with a shallower one). Without keep_chords(),
  // the same passes left 35.
  optimizer.keep_chords(bounds);
  run_rounds(optimizer, 2);
  for(int pass = 0; pass < 3; ++pass)
    optimizer.skewness_pass(0.12);
  for(int pass = 0; pass < 3; ++pass)
    optimizer.angle_pass(30.);
  const auto at_end = sagging();
  std::cout << "long chords sagging more than 0.045 h on a cylinder of radius 2.5 h: " << before_split << " before, " << after_split
            << " after " << splits << " splits, " << at_end << " after the passes that follow" << std::endl;
  EXPECT_LE(at_end, after_split);
  expect_domain_and_bounds_kept(c, before, statistics(c.points, c.positions, c.triangles));
}

TEST(RemeshConformal, LocationsInSliversAreExact)
{
  // The output locations are barycentric coordinates in input faces; on a CAD sliver the Gram
  // determinant cancels to 0 (here: 0.25 + 1e-18 - 0.25) and the point came back elsewhere.
  const std::array<K::Point_3, 3> sliver{{K::Point_3(0., 0., 0.), K::Point_3(1., 0., 0.), K::Point_3(0.5, 1e-9, 0.)}};
  const K::Point_3 p(0.5, 0.5e-9, 0.);
  const std::array<double, 3> b = CR::internal::remeshing::barycentric(p, sliver);
  EXPECT_NEAR(b[0], 0.25, 1e-6);
  EXPECT_NEAR(b[1], 0.25, 1e-6);
  EXPECT_NEAR(b[2], 0.5, 1e-6);
  const K::Point_3 back = CGAL::barycenter(sliver[0], b[0], sliver[1], b[1], sliver[2], b[2]);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(back, p)), 1e-15);
  // A face without area: the place on its longest side.
  const std::array<K::Point_3, 3> flat{{K::Point_3(0., 0., 0.), K::Point_3(1., 0., 0.), K::Point_3(0.25, 0., 0.)}};
  const std::array<double, 3> c = CR::internal::remeshing::barycentric(K::Point_3(0.75, 0., 0.), flat);
  const K::Point_3 on_side = CGAL::barycenter(flat[0], c[0], flat[1], c[1], flat[2], c[2]);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(on_side, K::Point_3(0.75, 0., 0.))), 1e-15);
}

TEST(SurfaceOptimization, SkewnessAgreesWithTheAnglesOfTheTriangle)
{
  // The optimizer's skewness takes a polynomial arc cosine (within 2e-8) of the smallest angle
  // alone (the largest angle's term is never the larger): against both terms of the angles from
  // std::atan2 on random triangles, from needles to obtuse ones, and the degenerate cases.
  typedef CGAL::Epick::Point_3 P3;
  auto reference = [](const P3& p, const P3& q, const P3& r) {
    const double a = RM::Triangle_shape::angle(p, q, r), b = RM::Triangle_shape::angle(q, r, p), c = RM::Triangle_shape::angle(r, p, q);
    const double largest = (std::max)({a, b, c}), smallest = (std::min)({a, b, c});
    return (std::max)((largest - CGAL_PI / 3.) / (2. * CGAL_PI / 3.), (CGAL_PI / 3. - smallest) / (CGAL_PI / 3.));
  };
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1., 1.), flatness(1e-6, 1.);
  double largest_error = 0.;
  for(int k = 0; k < 100000; ++k)
  {
    const double squash = flatness(random);
    const P3 p(coordinate(random), squash * coordinate(random), 0.), q(coordinate(random), squash * coordinate(random), 0.),
        r(coordinate(random), squash * coordinate(random), squash * coordinate(random));
    largest_error = (std::max)(largest_error, std::abs(RM::Triangle_shape::skewness(p, q, r) - reference(p, q, r)));
  }
  EXPECT_LT(largest_error, 2e-7);
  EXPECT_NEAR(RM::Triangle_shape::skewness(P3(0., 0., 0.), P3(1., 0., 0.), P3(0.5, std::sqrt(3.) / 2., 0.)), 0., 1e-7);
  EXPECT_NEAR(RM::Triangle_shape::skewness(P3(0., 0., 0.), P3(1., 0., 0.), P3(0., 1., 0.)), 0.25, 1e-7); // 90 degrees
  EXPECT_EQ(RM::Triangle_shape::skewness(P3(0., 0., 0.), P3(1., 0., 0.), P3(1., 0., 0.)), 1.);       // two corners at one point
  EXPECT_NEAR(RM::Triangle_shape::skewness(P3(0., 0., 0.), P3(1., 0., 0.), P3(2., 0., 0.)), 1., 1e-7); // collinear: 180 degrees
}

TEST(SurfaceOptimization, AMovingStarSumsTheSkewnessOfItsTrianglesToTheBit)
{
  // The moves' searches evaluate stars through Moving_star, which shares each squared distance
  // between two triangles: the same sums and largest values as triangle by triangle, bit for bit
  // (the optimizer's meshes must not depend on it), on random stars of 3 to 64 triangles.
  typedef CGAL::Epick::Point_3 P3;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-1., 1.);
  std::uniform_int_distribution<int> ring_size(3, int(RM::Moving_star::max_ring_size));
  for(int k = 0; k < 2000; ++k)
  {
    std::vector<P3> positions(std::size_t(ring_size(random)));
    for(P3& p : positions)
      p = P3(coordinate(random), coordinate(random), 0.1 * coordinate(random));
    std::vector<int> ring(positions.size());
    std::iota(ring.begin(), ring.end(), 0);
    std::shuffle(ring.begin(), ring.end(), random);
    const RM::Moving_star star(positions, ring);
    for(int trial = 0; trial < 3; ++trial)
    {
      const P3 x(coordinate(random), coordinate(random), coordinate(random));
      double sum = 0., worst = 0.;
      for(std::size_t i = 0; i < ring.size(); ++i)
      {
        const double s = RM::Triangle_shape::skewness(x, positions[std::size_t(ring[i])], positions[std::size_t(ring[(i + 1) % ring.size()])]);
        sum += s;
        worst = (std::max)(worst, s);
      }
      double star_worst = 0.;
      ASSERT_EQ(star.skewness_sum(x, &star_worst), sum);
      ASSERT_EQ(star_worst, worst);
      ASSERT_EQ(star.skewness_sum(x), sum);
    }
  }
}

TEST(SurfaceOptimization, AnglePassesRaiseTheTrianglesBelowThirtyDegrees)
{
  // The optimization of remesh_conformal() before its angle passes, on a wavy sheet whose
  // refinement bound is 28 degrees: it leaves triangles between 28 and 30 degrees on the surface.
  const std::vector<std::vector<RM::Boundary_sample> > loops{sampled_square(1., 0.05, false), sampled_square(0.3, 0.05, true)};
  const RM::Planar_mesh raw = RM::mesh_planar_domain<CGAL::Epick>(loops, 28., [](const CGAL::Epick::Point_2&) { return 0.07; }, 1, false);
  std::vector<CGAL::Epick::Point_2> points = raw.points;
  std::vector<std::array<int, 3> > triangles = raw.triangles;
  std::vector<CGAL::Epick::Point_3> positions;
  for(const auto& p : points)
    positions.push_back(wavy_lift(p));
  const auto lift = &wavy_lift_near; // the optimizer keeps a reference to it
  typedef RM::Surface_mesh_optimizer<decltype(lift)> Optimizer;
  Optimizer optimizer(points, positions, triangles, lift, 28., 0.07);
  ASSERT_TRUE(optimizer.initialize(raw.number_of_samples));
  run_rounds(optimizer, 5);
  for(int pass = 0; pass < 3; ++pass)
    optimizer.skewness_pass(0.12);
  auto below_30 = [&]() {
    std::size_t below = 0;
    for(const auto& t : triangles)
    {
      const std::array<double, 3> a = CR::triangle_quality(positions[t[0]], positions[t[1]], positions[t[2]]).angles;
      below += (std::min)({a[0], a[1], a[2]}) < 30.;
    }
    return below;
  };
  const std::size_t before = below_30();
  const Optimized_mesh_statistics shapes_before = statistics(points, positions, triangles);
  ASSERT_GT(before, 5u) << "nothing for the angle passes to do";

  std::size_t changes = 0;
  for(int pass = 0; pass < 3; ++pass)
    changes += optimizer.angle_pass(30.);
  const std::size_t after = below_30();
  const Optimized_mesh_statistics shapes_after = statistics(points, positions, triangles);
  EXPECT_GT(changes, 0u);
  EXPECT_LT(2 * after, before) << "below 30 degrees: " << before << " -> " << after;
  EXPECT_GE(shapes_after.smallest_angle, shapes_before.smallest_angle - 1e-9);
  EXPECT_TRUE(shapes_after.manifold);
  EXPECT_EQ(shapes_after.folded, 0u);
  EXPECT_NEAR(shapes_after.planar_area, 4. - 0.36, 1e-12);
  EXPECT_EQ(shapes_after.boundary_edges, shapes_before.boundary_edges);
  EXPECT_LT(shapes_after.mean_skewness, shapes_before.mean_skewness + 0.005);
  for(std::size_t v = 0; v < points.size(); ++v)
    EXPECT_EQ(positions[v], wavy_lift(points[v]));
}

TEST(FlipsAfterGluing, FlipAThinPairUnlessItsEdgeIsKeptOrTheQuadFolds)
{
  // (c, a, b) is a sliver (smallest angle 5.7 degrees) on the edge a-b; flipping a-b into c-d
  // makes two good triangles.
  typedef CGAL::Epick::Point_3 P;
  typedef std::array<std::size_t, 3> T;
  const std::size_t a = 0, b = 1, c = 2, d = 3;
  std::vector<P> points{P(0, 0, 0), P(1, 0, 0), P(0.5, -0.05, 0), P(0.5, 0.8, 0.1)};
  const std::vector<T> pair{T{{c, a, b}}, T{{d, b, a}}};
  auto smallest_angle = [&](const std::vector<T>& triangles) {
    double smallest = 180.;
    for(const T& t : triangles)
    {
      const std::array<double, 3> angles = CR::triangle_quality(points[t[0]], points[t[1]], points[t[2]]).angles;
      smallest = (std::min)(smallest, *std::min_element(angles.begin(), angles.end()));
    }
    return smallest;
  };
  auto no_edge_is_kept = [](std::size_t, std::size_t) { return false; };

  std::vector<T> triangles = pair;
  const RM::Soup_flips flips = RM::flip_small_angles_after_gluing(points, triangles, no_edge_is_kept, 30.);
  EXPECT_EQ(flips.flips, 1u);
  EXPECT_EQ(triangles, (std::vector<T>{T{{c, a, d}}, T{{c, d, b}}}));
  EXPECT_LT(smallest_angle(pair), 6.);
  EXPECT_GT(smallest_angle(triangles), 20.);
  flips.undo(triangles);
  EXPECT_EQ(triangles, pair);

  // A kept edge (a feature's or a border's chord) stays.
  triangles = pair;
  auto ab_is_kept = [&](std::size_t i, std::size_t j) { return std::minmax(i, j) == std::minmax(a, b); };
  EXPECT_EQ(RM::flip_small_angles_after_gluing(points, triangles, ab_is_kept, 30.).flips, 0u);
  EXPECT_EQ(triangles, pair);

  // A concave quad (c and d both beyond b): the flipped triangles would overlap, though their
  // unsigned angles (28 degrees against 10.6) would be better. Refused.
  points[c] = P(1.28, -0.24, 0);
  points[d] = P(1.49, 0.51, 0);
  triangles = pair;
  EXPECT_EQ(RM::flip_small_angles_after_gluing(points, triangles, no_edge_is_kept, 30.).flips, 0u);
  EXPECT_EQ(triangles, pair);

  // A pair bent by 76 degrees whose flip would raise the smallest angle from 27.5 to 35.5 degrees
  // but bend the new pair by 100: a sharper crease than the surface had. Refused.
  points[c] = P(0.08, -0.57, 0);
  points[d] = P(0.03, 0.12, -0.49);
  triangles = pair;
  EXPECT_EQ(RM::flip_small_angles_after_gluing(points, triangles, no_edge_is_kept, 30.).flips, 0u);
  EXPECT_EQ(triangles, pair);
}

TEST(FlipsAfterGluing, ShapePassesFlipTheChosenEdgesOnly)
{
  // Two triangles with an angle of 118 degrees at c and d (skewness 0.48), none below 30: the
  // angle passes leave them; the shape passes flip a-b into c-d (skewness 0.02) where asked.
  typedef CGAL::Epick::Point_3 P;
  typedef std::array<std::size_t, 3> T;
  const std::size_t a = 0, b = 1, c = 2, d = 3;
  const std::vector<P> points{P(0, 0, 0), P(1, 0, 0), P(0.5, -0.3, 0), P(0.5, 0.3, 0)};
  const std::vector<T> pair{T{{c, a, b}}, T{{d, b, a}}};
  auto no_edge_is_kept = [](std::size_t, std::size_t) { return false; };
  auto every_edge = [](std::size_t, std::size_t) { return true; };
  auto no_edge = [](std::size_t, std::size_t) { return false; };

  std::vector<T> triangles = pair;
  RM::Glued_soup_flipper angles_only(points, triangles, no_edge_is_kept, 30.);
  angles_only.angle_passes();
  EXPECT_EQ(angles_only.result().flips, 0u);
  RM::Glued_soup_flipper not_chosen(points, triangles, no_edge_is_kept, 30.);
  not_chosen.shape_passes(no_edge, 3);
  EXPECT_EQ(not_chosen.result().flips, 0u);
  EXPECT_EQ(triangles, pair);

  RM::Glued_soup_flipper chosen(points, triangles, no_edge_is_kept, 30.);
  chosen.shape_passes(every_edge, 3);
  EXPECT_EQ(chosen.result().flips, 1u);
  EXPECT_EQ(triangles, (std::vector<T>{T{{c, a, d}}, T{{c, d, b}}}));
  EXPECT_LT(RM::Triangle_shape::skewness(points[c], points[a], points[d]), 0.05);
  EXPECT_GT(RM::Triangle_shape::skewness(points[c], points[a], points[b]), 0.45);
}

TEST(MovesAfterGluing, AStarWithAnAngleBelowTheTargetHasItRaised)
{
  // A flat star of three triangles around point 0 inside the triangle (-1, -0.5), (1, -0.5),
  // (0.6, 1), whose corner of 43.2 degrees is split in two: no place gives the star 30 degrees.
  // Where the summed skewness is smallest (about (0, 0.036), found by a scan at 0.004), its
  // smallest angle is 14.9 degrees; the largest smallest angle, 21.6 degrees, is at about
  // (0.224, -0.016). Started at the first, the skewness moves stay; the angle moves go toward the second.
  typedef CGAL::Epick::Point_3 P;
  typedef std::array<std::size_t, 3> T;
  CR::Poly_annulus_segmentation s;
  std::vector<std::vector<CR::Poly_annulus_segmentation::Vertex> > grid(17);
  for(int i = 0; i <= 16; ++i)
    for(int j = 0; j <= 16; ++j)
      grid[i].push_back(s.mesh.add_vertex(P(-2. + 0.25 * i, -2. + 0.25 * j, 0.)));
  for(int i = 0; i < 16; ++i)
    for(int j = 0; j < 16; ++j)
    {
      s.mesh.add_face(grid[i][j], grid[i + 1][j], grid[i + 1][j + 1]);
      s.mesh.add_face(grid[i][j], grid[i + 1][j + 1], grid[i][j + 1]);
    }
  std::vector<P> points{P(0., 0.036, 0.), P(-1., -0.5, 0.), P(1., -0.5, 0.), P(0.6, 1., 0.)};
  const std::vector<T> star{T{{0, 1, 2}}, T{{0, 2, 3}}, T{{0, 3, 1}}};
  auto smallest_angle = [&](const P& x) {
    double smallest = 180.;
    for(const T& t : star)
    {
      const std::array<double, 3> a = CR::triangle_quality(x, points[t[1]], points[t[2]]).angles;
      smallest = (std::min)({smallest, a[0], a[1], a[2]});
    }
    return smallest;
  };
  const double before = smallest_angle(points[0]);
  ASSERT_NEAR(before, 14.95, 0.05);
  std::vector<CR::Poly_annulus_segmentation::Face> point_face(points.size());
  for(auto f : s.mesh.faces())
  {
    const auto h = s.mesh.halfedge(f);
    if(CGAL::squared_distance(points[0], K::Triangle_3(s.mesh.point(s.mesh.source(h)), s.mesh.point(s.mesh.target(h)),
                                                       s.mesh.point(s.mesh.target(s.mesh.next(h))))) == 0.)
      point_face[0] = f;
  }
  const std::size_t moves = RM::move_points_after_gluing(s, points, point_face, star, {1, 0, 0, 0}, 30., 10., 5);
  const double after = smallest_angle(points[0]);
  std::cout << "smallest angle of the star: " << before << " -> " << after << " degrees (the best: 21.6) in " << moves
            << " moves; the point at " << points[0] << std::endl;
  EXPECT_GT(moves, 0u);
  EXPECT_GT(after, 20.5);
  EXPECT_LE(after, 21.6);
  EXPECT_EQ(points[0].z(), 0.);
}

TEST(MovesAfterGluing, AStarRelaxesOnTheSurfaceButDoesNotCutACreaseOff)
{
  // A roof z = -slope |x| over [-2, 2]^2 (a crease along x = 0 when the slope is not 0) as the
  // segmented surface, and on it a glued star: point 0, movable, with six neighbours around
  // (shift, 0) at distance 1, two of them at (shift, +-1): on the crease when shift is 0.
  typedef CGAL::Epick::Point_3 P;
  typedef std::array<std::size_t, 3> T;
  auto relax = [](double slope, double shift, double start_x, double start_y) {
    CR::Poly_annulus_segmentation s;
    const auto roof = [&](double x, double y) { return P(x, y, -slope * std::abs(x)); };
    std::vector<std::vector<CR::Poly_annulus_segmentation::Vertex> > grid(17);
    for(int i = 0; i <= 16; ++i)
      for(int j = 0; j <= 16; ++j)
        grid[i].push_back(s.mesh.add_vertex(roof(-2. + 0.25 * i, -2. + 0.25 * j)));
    for(int i = 0; i < 16; ++i)
      for(int j = 0; j < 16; ++j)
      {
        s.mesh.add_face(grid[i][j], grid[i + 1][j], grid[i + 1][j + 1]);
        s.mesh.add_face(grid[i][j], grid[i + 1][j + 1], grid[i][j + 1]);
      }
    std::vector<P> points{roof(start_x, start_y)};
    std::vector<T> star;
    for(int k = 0; k < 6; ++k)
    {
      points.push_back(roof(shift + std::cos(CGAL_PI / 2. + k * CGAL_PI / 3.), std::sin(CGAL_PI / 2. + k * CGAL_PI / 3.)));
      star.push_back(T{{0, std::size_t(1 + k), std::size_t(1 + (k + 1) % 6)}});
    }
    // The face under the start point, found by its distance.
    std::vector<CR::Poly_annulus_segmentation::Face> point_face(points.size());
    double nearest = 1e300;
    for(auto f : s.mesh.faces())
    {
      const auto h = s.mesh.halfedge(f);
      const double d = CGAL::squared_distance(points[0], K::Triangle_3(s.mesh.point(s.mesh.source(h)), s.mesh.point(s.mesh.target(h)),
                                                                       s.mesh.point(s.mesh.target(s.mesh.next(h)))));
      if(d < nearest)
        nearest = d, point_face[0] = f;
    }
    const std::vector<char> movable{1, 0, 0, 0, 0, 0, 0};
    const std::vector<P> before = points;
    const std::size_t moves = RM::move_points_after_gluing(s, points, point_face, star, movable, 30., 1.4, 5);
    // Only point 0 moved, onto the roof, and its face holds it.
    EXPECT_TRUE(std::equal(points.begin() + 1, points.end(), before.begin() + 1));
    EXPECT_NEAR(points[0].z(), -slope * std::abs(points[0].x()), 1e-12);
    const auto h = s.mesh.halfedge(point_face[0]);
    EXPECT_LT(CGAL::squared_distance(points[0], K::Triangle_3(s.mesh.point(s.mesh.source(h)), s.mesh.point(s.mesh.target(h)),
                                                               s.mesh.point(s.mesh.target(s.mesh.next(h))))), 1e-24);
    double skewness_before = 0., skewness_after = 0.;
    for(const T& t : star)
    {
      skewness_before += RM::Triangle_shape::skewness(before[t[0]], before[t[1]], before[t[2]]);
      skewness_after += RM::Triangle_shape::skewness(points[t[0]], points[t[1]], points[t[2]]);
    }
    EXPECT_LE(skewness_after, skewness_before);
    EXPECT_EQ(moves > 0, skewness_after < skewness_before);
    return points[0];
  };
  // Flat: from off the centre to the centre.
  const P flat = relax(0., 0., 0.3, 0.2);
  EXPECT_LT(std::hypot(flat.x(), flat.y()), 0.02) << flat;
  // On the crease, around a centre on it: along the crease to near the centre (the star's edges
  // to (0, +-1) follow the crease, and the point leaves it only a little).
  const P along = relax(1., 0., 0., 0.3);
  EXPECT_LT(std::abs(along.y()), 0.05) << along;
  EXPECT_LT(std::abs(along.x()), 0.1) << along; // measured: 0.06 off the crease
  // On the crease, around a centre 0.3 off it: flat, the point goes there; on the roof it may
  // leave the crease only as far as the moved star stays within 0.05 mean edges of it.
  const P off_flat = relax(0., 0.3, 0., 0.);
  EXPECT_NEAR(off_flat.x(), 0.3, 0.02) << off_flat;
  const P off_roof = relax(1., 0.3, 0., 0.);
  EXPECT_LT(off_roof.x(), 0.1) << off_roof; // measured: 0.04
}

TEST(KeptInputVertices, TheTipOfASharpConeOrACoarseDomeNotACreaseAFlatVertexOrATinyTip)
{
  // A fan of 8 triangles around a centre vertex on a ring of radius `radius`, at height `z(x, y)`.
  auto fan = [](double radius, const std::function<double(double, double)>& z) {
    CR::Extracted_patch patch;
    std::vector<CR::Extracted_patch::Mesh::Vertex_index> ring;
    const auto centre = patch.mesh.add_vertex(CGAL::Epick::Point_3(0, 0, z(0, 0)));
    for(int i = 0; i < 8; ++i)
    {
      const double x = radius * std::cos(i * CGAL_PI / 4.), y = radius * std::sin(i * CGAL_PI / 4.);
      ring.push_back(patch.mesh.add_vertex(CGAL::Epick::Point_3(x, y, z(x, y))));
    }
    for(int i = 0; i < 8; ++i)
      patch.mesh.add_face(centre, ring[i], ring[(i + 1) % 8]);
    return patch;
  };
  const double h = 0.5;
  auto kept = [&](const CR::Extracted_patch& patch) { return RM::kept_input_vertices(patch, h, RM::kept_tip_tolerance, {}); };
  // A cone of height 0.5 over the unit disc: its tip (angle deficit 0.7 radian) is kept.
  EXPECT_EQ(kept(fan(1., [](double x, double y) { return 0.5 * (1. - std::sqrt(x * x + y * y)); })), (std::vector<std::size_t>{0}));
  // A coarse fan on a sphere of radius 10 (ring radius 3 h, angle deficit 0.03 radian): its
  // centre stands 0.045 h over the output (0.6 h around it) and is kept. On a ring of 2 h and a
  // sphere of radius 5 it would stand higher, 0.06 h, but the ring is not coarse: not kept.
  const auto dome = [](double radius) { return [radius](double x, double y) { return -(x * x + y * y) / (2. * radius); }; };
  EXPECT_EQ(kept(fan(1.5, dome(10.))), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(kept(fan(1., dome(5.))).empty());
  // A roof's ridge (no angle deficit, a ring of 2 h), a flat fan and the same cone a hundred times
  // smaller are not.
  EXPECT_TRUE(kept(fan(1., [](double, double y) { return -0.5 * std::abs(y); })).empty());
  EXPECT_TRUE(kept(fan(1., [](double, double) { return 0.; })).empty());
  EXPECT_TRUE(kept(fan(0.01, [](double x, double y) { return 0.005 - 0.5 * std::sqrt(x * x + y * y); })).empty());
  // Nor is a tip closer than h to a point to avoid (a boundary sample).
  const CR::Extracted_patch cone = fan(1., [](double x, double y) { return 0.5 * (1. - std::sqrt(x * x + y * y)); });
  EXPECT_TRUE(RM::kept_input_vertices(cone, h, RM::kept_tip_tolerance, {CGAL::Epick::Point_3(0.3, 0, 0.5)}).empty());
}

TEST(PlanarMesher, FixedPointsAreVerticesThatStayPut)
{
  // A square with a square hole, two fixed points inside: they come right after the samples,
  // where they were, through the refinement and the smoothing.
  const std::vector<CGAL::Epick::Point_2> fixed{CGAL::Epick::Point_2(0.61, 0.57), CGAL::Epick::Point_2(-0.55, 0.63)};
  const RM::Planar_mesh m = RM::mesh_planar_domain<CGAL::Epick>(square_with_square_hole(), 25., [](const CGAL::Epick::Point_2&) { return 0.2; },
                                                                2, true, {}, fixed);
  ASSERT_EQ(m.number_of_fixed_points, m.number_of_samples + 2);
  EXPECT_EQ(m.points[m.number_of_samples], fixed[0]);
  EXPECT_EQ(m.points[m.number_of_samples + 1], fixed[1]);
  const Planar_mesh_measures measures(m);
  EXPECT_TRUE(measures.used_vertices.count(int(m.number_of_samples)) && measures.used_vertices.count(int(m.number_of_samples) + 1));
  EXPECT_GE(measures.smallest_angle, 20.);
}

TEST(PlanarMesher, LloydSmoothingKeepsTheDomainTheFixedPointsTheBoundsAndTheGrading)
{
  // A square with a square hole and two fixed points, with edges three times shorter toward
  // x = 1 than toward x = -1; refined, then smoothed by CGAL's Lloyd iterations only.
  const std::vector<std::vector<RM::Boundary_sample> > loops = square_with_square_hole();
  const std::vector<CGAL::Epick::Point_2> fixed{CGAL::Epick::Point_2(0.61, 0.57), CGAL::Epick::Point_2(-0.55, 0.63)};
  const auto size = [](const CGAL::Epick::Point_2& p) { return 0.05 + 0.05 * (1. - p.x()); };
  const RM::Planar_mesh refined = RM::mesh_planar_domain<CGAL::Epick>(loops, 25., size, RM::Planar_smoothing(0, 0), true, {}, fixed);
  const RM::Planar_mesh lloyd = RM::mesh_planar_domain<CGAL::Epick>(loops, 25., size, RM::Planar_smoothing(0, 20), true, {}, fixed);
  const Planar_mesh_measures before(refined), after(lloyd);
  const auto check = [&](const RM::Planar_mesh& m, const Planar_mesh_measures& measures) {
    ASSERT_EQ(m.number_of_fixed_points, m.number_of_samples + 2);
    EXPECT_EQ(m.points[m.number_of_samples], fixed[0]);
    EXPECT_EQ(m.points[m.number_of_samples + 1], fixed[1]);
    EXPECT_TRUE(measures.counterclockwise);
    EXPECT_NEAR(measures.area, 4. - 0.36, 1e-12); // the hole stays empty and the rest is covered once
    EXPECT_EQ(measures.used_vertices.size(), m.points.size());
    EXPECT_GE(measures.smallest_angle, 25.); // the refinement after the smoothing restores the bound
  };
  check(refined, before);
  check(lloyd, after);
  // The Lloyd iterations moved the points and evened out the shapes, and kept the grading: the
  // refinement's edges are 2.4 times longer on the coarse side than on the fine side.
  EXPECT_NE(std::vector<CGAL::Epick::Point_2>(refined.points.begin() + std::ptrdiff_t(refined.number_of_fixed_points), refined.points.end()),
            std::vector<CGAL::Epick::Point_2>(lloyd.points.begin() + std::ptrdiff_t(lloyd.number_of_fixed_points), lloyd.points.end()));
  EXPECT_LT(after.mean_skewness, before.mean_skewness - 0.02);
  EXPECT_NEAR(after.coarse_side / after.fine_side, before.coarse_side / before.fine_side, 0.15 * before.coarse_side / before.fine_side);
  // A time limit stops it: one of a nanosecond, before any move (CGAL checks it once it has
  // tagged the Voronoi diagram's blind faces and computed a vertex's move, milliseconds of work on
  // this finer mesh), leaves the refinement's mesh.
  const auto fine = [](const CGAL::Epick::Point_2&) { return 0.03; };
  const RM::Planar_mesh fine_refined = RM::mesh_planar_domain<CGAL::Epick>(loops, 25., fine, RM::Planar_smoothing(0, 0), true, {}, fixed);
  const RM::Planar_mesh stopped = RM::mesh_planar_domain<CGAL::Epick>(loops, 25., fine, RM::Planar_smoothing(0, 20, 1e-9), true, {}, fixed);
  EXPECT_GT(fine_refined.points.size(), 3000u);
  EXPECT_EQ(stopped.points, fine_refined.points);
  EXPECT_EQ(stopped.triangles, fine_refined.triangles);
  // CGAL's Lloyd smoothing takes square roots: not over a kernel with exact constructions. (Coarse:
  // the exact refinement before the refusal took seconds at the sizes above.)
  test_support::expect_error(
    [&] { RM::mesh_planar_domain<CGAL::Epeck>(loops, 25., [](const CGAL::Epick::Point_2&) { return 0.4; }, RM::Planar_smoothing(0, 1)); },
    CR::Error_code::INVALID_INPUT, {"Lloyd", "floating-point"});
}

// A size field on the square [-1, 1]^2, finer toward x = 1, that also takes a hint: the index
// of the point it was last asked about with that hint. It records how far from the point asked
// about each query started, in units of the field there, and how far the query before was.
struct Hinted_size_field
{
  struct Record
  {
    std::vector<CGAL::Epick::Point_2> points;
    std::vector<double> from_hint, from_last; // distances of the hinted queries
    std::size_t without_hint = 0;
  };
  std::shared_ptr<Record> record = std::make_shared<Record>();

  static double at(const CGAL::Epick::Point_2& p) { return 0.05 + 0.1 * (1. - p.x()); }
  double operator()(const CGAL::Epick::Point_2& p) const { return at(p); }
  double operator()(const CGAL::Epick::Point_2& p, RM::Size_field_hint& hint) const
  {
    Record& r = *record;
    if(hint == RM::no_size_field_hint)
      ++r.without_hint;
    else
    {
      r.from_hint.push_back(std::sqrt(CGAL::squared_distance(r.points.at(hint), p)) / at(p));
      r.from_last.push_back(std::sqrt(CGAL::squared_distance(r.points.back(), p)) / at(p));
    }
    hint = r.points.size();
    r.points.push_back(p);
    return at(p);
  }
};

TEST(PlanarMesher, AHintedSizeFieldGivesTheSameMeshAndIsAskedFromNearby)
{
  // The refinement's size queries come with the place of a corner known before (a new corner's,
  // then the centroid's), where the remesher's field starts its point location, not the last
  // query's, which was anywhere; the mesh is the one the same field gives without hints.
  std::vector<RM::Boundary_sample> square;
  const double x[4] = {-1, 1, 1, -1}, y[4] = {-1, -1, 1, 1};
  for(int i = 0; i < 4; ++i)
    square.push_back(RM::Boundary_sample{CGAL::Epick::Point_2(x[i], y[i]), CGAL::Epick::Point_3(x[i], y[i], 0.)});
  const Hinted_size_field hinted;
  const RM::Planar_mesh with_hints = RM::mesh_planar_domain<CGAL::Epick>({square}, 25., hinted, 0);
  const RM::Planar_mesh plain = RM::mesh_planar_domain<CGAL::Epick>(
    {square}, 25., [](const CGAL::Epick::Point_2& p) { return Hinted_size_field::at(p); }, 0);
  EXPECT_GT(with_hints.points.size(), 500u);
  EXPECT_EQ(with_hints.points, plain.points);
  EXPECT_EQ(with_hints.triangles, plain.triangles);
  Hinted_size_field::Record& r = *hinted.record;
  EXPECT_LT(r.without_hint, 10u); // the first faces, of the corners only
  ASSERT_GT(r.from_hint.size(), 2000u);
  const auto quantile = [](std::vector<double> d, double q) {
    std::sort(d.begin(), d.end());
    return d[std::size_t(q * double(d.size() - 1))];
  };
  // Nine in ten within 1.5 times the size (1.32 when written), the last query's place then at
  // more than four times that distance (7.4).
  EXPECT_LT(quantile(r.from_hint, 0.9), 1.5);
  EXPECT_GT(quantile(r.from_last, 0.9), 4. * quantile(r.from_hint, 0.9));
}

TEST(PlanarMesher, TheQueueOfBadFacesRefinesInCgalsOrder)
{
  // Bad_face_queue_2 keeps the corners of each queued face in its key and skips the faces of a
  // conflict zone that are not queued: the refinement must insert the same points in the same
  // order as with CGAL's own queue (Mesh_2::Refine_faces_base), whose order among faces of equal
  // quality comes from its map of faces by corners. A square with a round hole, sampled evenly
  // (many faces of equal quality), and a size field that varies.
  typedef RM::Planar_triangulation<CGAL::Epick>::type CDT;
  const auto size = [](const CGAL::Epick::Point_2& p) { return 0.03 + 0.05 * std::abs(p.x() + 0.5 * p.y()); };
  typedef RM::Size_field_criteria_2<CDT, decltype(size)> Criteria;
  const auto refined = [&](auto mesher_tag) {
    CDT cdt;
    const auto loop = [&cdt](const std::vector<CGAL::Epick::Point_2>& points) {
      std::vector<CDT::Vertex_handle> v;
      for(const auto& p : points)
        v.push_back(cdt.insert(p));
      for(std::size_t i = 0; i < v.size(); ++i)
        cdt.insert_constraint(v[i], v[(i + 1) % v.size()]);
    };
    std::vector<CGAL::Epick::Point_2> square, hole;
    for(int i = 0; i < 40; ++i)
    {
      const double t = -1. + i / 20.;
      for(const CGAL::Epick::Point_2& p : {CGAL::Epick::Point_2(t, -1.), CGAL::Epick::Point_2(1., t), CGAL::Epick::Point_2(-t, 1.),
                                           CGAL::Epick::Point_2(-1., -t)})
        square.push_back(p);
      hole.push_back(CGAL::Epick::Point_2(0.3 + 0.2 * std::cos(-i * CGAL_PI / 20.), 0.2 * std::sin(-i * CGAL_PI / 20.)));
    }
    loop(square);
    loop(hole);
    RM::mark_domain(cdt);
    typename decltype(mesher_tag)::type mesher(cdt, Criteria(CGAL::square(std::sin(20.7 * CGAL_PI / 180.)), size));
    mesher.refine_mesh();
    std::vector<CGAL::Epick::Point_2> points; // in the order of insertion: the refinement removes none
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      points.push_back(v->point());
    return points;
  };
  struct Ours { typedef RM::Fixed_boundary_mesher_2<CDT, Criteria> type; };
  struct Cgals { typedef RM::Fixed_boundary_mesher_2<CDT, Criteria, CGAL::Mesh_2::Refine_faces_base> type; };
  const std::vector<CGAL::Epick::Point_2> ours = refined(Ours()), cgals = refined(Cgals());
  EXPECT_GT(ours.size(), 2000u);
  EXPECT_EQ(ours, cgals);
}

// The map from the plane to a unit cylinder that is conformal, (r, theta) -> (cos theta,
// sin theta, log r): the scale grows like exp(z) along it, as on a flattened tube.
bool onto_unit_cylinder(const CGAL::Epick::Point_2& p, CGAL::Epick::Point_3& x)
{
  const double r = std::sqrt(CGAL::square(p.x()) + CGAL::square(p.y()));
  x = CGAL::Epick::Point_3(p.x() / r, p.y() / r, std::log(r));
  return r >= 1. - 1e-9 && r <= std::exp(4.) + 1e-9;
}

TEST(PlanarMesher, PointAtSurfaceDistanceIsTheBisectionsPointInFewerLifts)
{
  // On the flattened tube of onto_unit_cylinder(), from points of the annulus in many directions
  // and for many distances: point_at_surface_distance() returns, to the bit, the point of the
  // plain search it replaced (growth of t by half from the guess, then 16 halvings of [0, t]),
  // and lifts at most half as many points.
  typedef CGAL::Epick::Point_2 P2;
  typedef CGAL::Epick::Point_3 P3;
  std::size_t lifts = 0;
  const auto counted = [&](const P2& p, P3& x) {
    ++lifts;
    return onto_unit_cylinder(p, x);
  };
  const auto plain_search = [&](const P2& origin, const CGAL::Epick::Vector_2& direction, const P3& from, double distance,
                                double guess, double limit, P2& uv) {
    bool inside = true;
    auto too_close = [&](double t) {
      P3 x;
      inside = counted(origin + t * direction, x);
      return CGAL::squared_distance(x, from) < distance * distance;
    };
    double near = 0., far = guess;
    while(too_close(far) && inside && far < limit)
      far *= 1.5;
    if(!inside || !(far < limit))
      return false;
    for(int step = 0; step < 16; ++step)
    {
      const double t = 0.5 * (near + far);
      (too_close(t) ? near : far) = t;
    }
    uv = origin + 0.5 * (near + far) * direction;
    P3 x;
    return counted(uv, x);
  };
  std::size_t found = 0, refused = 0, plain_lifts = 0, new_lifts = 0;
  for(int k = 0; k < 400; ++k)
  {
    const double radius = 1.5 + 0.1 * (k % 40), angle = 0.37 * k, heading = 2.1 * k;
    const P2 origin(radius * std::cos(angle), radius * std::sin(angle));
    const CGAL::Epick::Vector_2 direction(std::cos(heading), std::sin(heading));
    P3 from;
    ASSERT_TRUE(onto_unit_cylinder(origin, from));
    const double distance = 0.05 + 0.02 * (k % 31), guess = distance * radius * (0.5 + 0.1 * (k % 13));
    P2 expected, uv;
    P3 point;
    lifts = 0;
    const bool plain = plain_search(origin, direction, from, distance, guess, 8. * guess, expected);
    plain_lifts += lifts;
    lifts = 0;
    const bool fast = RM::point_at_surface_distance(origin, direction, from, distance, guess, 8. * guess, counted, uv, point);
    new_lifts += lifts;
    ASSERT_EQ(fast, plain) << k;
    if(!fast)
    {
      ++refused;
      continue;
    }
    ++found;
    EXPECT_EQ(uv.x(), expected.x()) << k;
    EXPECT_EQ(uv.y(), expected.y()) << k;
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(point, from)), distance, 1e-3 * distance) << k;
  }
  EXPECT_GT(found, 300u);
  EXPECT_GT(refused, 0u); // rays that leave the annulus or outrun the limit
  EXPECT_LT(2 * new_lifts, plain_lifts) << new_lifts << " lifts against " << plain_lifts;
}

TEST(PlanarPointMap, FindsEveryPointItWasGivenAndNoOther)
{
  // 200k points on a grid and at random, in three rounds of growth from the 16 initial slots;
  // then the values of the first ones, a point never inserted, and -0. against 0.
  typedef CGAL::Epick::Point_2 P;
  RM::Planar_point_map<std::size_t> map;
  std::vector<P> points;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-1., 1.);
  for(int i = 0; i < 300; ++i)
    for(int j = 0; j < 300; ++j)
      points.emplace_back(i * 0.01, j * 0.01); // rows of equal x and columns of equal y
  while(points.size() < 200000)
    points.emplace_back(coordinate(random), coordinate(random));
  std::size_t inserted = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const auto r = map.try_emplace(points[i], i);
    inserted += r.second;
    if(r.second)
      ASSERT_EQ(*r.first, i);
    else
      ASSERT_EQ(points[*r.first], points[i]); // the value of the same point, inserted before
  }
  EXPECT_EQ(inserted, map.size());
  EXPECT_GT(inserted, 199000u); // random points rarely repeat
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const std::size_t* value = map.find(points[i]);
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(points[*value], points[i]); // the first insertion of that point kept its value
    EXPECT_LE(*value, i);
  }
  EXPECT_EQ(map.find(P(-3., 7.)), nullptr);
  EXPECT_EQ(map.find(P(0.005, 0.)), nullptr);
  EXPECT_FALSE(map.try_emplace(P(-0., 0.), 7).second); // the grid's (0, 0)
  EXPECT_EQ(*map.find(P(0., -0.)), 0u);
  // After reserve(), pointers stay valid over that many insertions.
  map.reserve(map.size() + 3);
  std::size_t* first = map.try_emplace(P(3., 3.), 1).first;
  map.try_emplace(P(4., 4.), 2);
  map.try_emplace(P(5., 5.), 3);
  EXPECT_EQ(first, map.find(P(3., 3.)));
}

TEST(TriangleAdjacency, LinksTwinsVisitsEachEdgeOnceInOrderAndRefusesNonManifoldEdges)
{
  // A 9 x 7 grid of squares cut into triangles, its vertex indices shuffled: every interior edge
  // links its two triangles, edges are visited once each in increasing (smaller, larger) vertex
  // order; a third triangle on an edge, or a twin running the edge the same way, is refused.
  const int nx = 9, ny = 7;
  std::vector<int> label((nx + 1) * (ny + 1));
  for(std::size_t i = 0; i < label.size(); ++i)
    label[i] = int(i);
  std::shuffle(label.begin(), label.end(), std::mt19937(3));
  auto at = [&](int i, int j) { return label[std::size_t(j * (nx + 1) + i)]; };
  std::vector<std::array<int, 3> > triangles;
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      triangles.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
      triangles.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
  std::vector<std::array<int, 3> > neighbor;
  std::vector<std::pair<int, int> > visited;
  std::size_t interior = 0;
  ASSERT_TRUE(RM::link_triangles(triangles, neighbor, [&](int a, int b, bool inner) {
    visited.emplace_back(a, b);
    interior += inner;
  }));
  // The expected adjacency, from a map of directed edges.
  std::map<std::pair<int, int>, int> triangle_of;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
      triangle_of[{triangles[t][(k + 1) % 3], triangles[t][(k + 2) % 3]}] = int(t);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
    {
      const auto twin = triangle_of.find({triangles[t][(k + 2) % 3], triangles[t][(k + 1) % 3]});
      EXPECT_EQ(neighbor[t][k], twin == triangle_of.end() ? -1 : twin->second) << t << " " << k;
    }
  const std::size_t edges = std::size_t(nx * (ny + 1) + ny * (nx + 1) + nx * ny);
  EXPECT_EQ(visited.size(), edges);
  EXPECT_EQ(interior, edges - std::size_t(2 * (nx + ny)));
  for(std::size_t e = 0; e < visited.size(); ++e)
  {
    EXPECT_LT(visited[e].first, visited[e].second);
    if(e > 0)
      EXPECT_LT(visited[e - 1], visited[e]);
  }
  auto third = triangles;
  third.push_back({{at(0, 0), at(1, 1), at(5, 5)}}); // on the diagonal of the first square
  EXPECT_FALSE(RM::link_triangles(third, neighbor, [](int, int, bool) {}));
  auto flipped = triangles;
  std::swap(flipped[1][1], flipped[1][2]); // runs the first square's diagonal the same way as its twin
  EXPECT_FALSE(RM::link_triangles(flipped, neighbor, [](int, int, bool) {}));
}

TEST(PlanarMesher, EquilateralSeedsStartTheFirstRowsAlongATube)
{
  // A tube of height 4 around the unit cylinder, flattened to the annulus between radii 1 and
  // e^4, each loop with 8 samples: the scale varies by e^0.66 across one triangle of a row.
  const double pi = 3.14159265358979323846;
  std::vector<RM::Boundary_sample> outer, hole;
  for(int i = 0; i < 8; ++i)
  {
    const double a = 2. * pi * i / 8., b = -a;
    outer.push_back(RM::Boundary_sample{CGAL::Epick::Point_2(std::exp(4.) * std::cos(a), std::exp(4.) * std::sin(a)),
                                        CGAL::Epick::Point_3(std::cos(a), std::sin(a), 4.)});
    hole.push_back(RM::Boundary_sample{CGAL::Epick::Point_2(std::cos(b), std::sin(b)), CGAL::Epick::Point_3(std::cos(b), std::sin(b), 0.)});
  }
  const std::vector<std::vector<RM::Boundary_sample> > loops{outer, hole};
  const auto all = [](const RM::Boundary_sample&, const RM::Boundary_sample&) { return true; };
  auto lifted = [](const CGAL::Epick::Point_2& p) {
    CGAL::Epick::Point_3 x;
    EXPECT_TRUE(onto_unit_cylinder(p, x));
    return x;
  };
  // Row 1 (per loop) over the chords, row 2 over the segments between consecutive seeds of row 1:
  // equilateral on the cylinder, inside the tube; the planar equilateral apex is not.
  const std::vector<RM::Planar_seed> seeds = RM::equilateral_seeds(loops, all, onto_unit_cylinder, 2);
  ASSERT_EQ(seeds.size(), 32u);
  for(std::size_t k = 0; k < 32; ++k)
  {
    const std::size_t loop = k / 16, row = (k / 8) % 2, i = k % 8;
    const CGAL::Epick::Point_2 a = row == 0 ? loops[loop][i].uv : seeds[k - 8].point,
                               b = row == 0 ? loops[loop][(i + 1) % 8].uv : seeds[k - 8 - i + (i + 1) % 8].point;
    const CGAL::Epick::Point_3 x = lifted(seeds[k].point), p = lifted(a), q = lifted(b);
    const double side = std::sqrt(CGAL::squared_distance(p, q));
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(x, p)), side, 1e-3 * side);
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(x, q)), side, 1e-2 * side);
    const double height = loop == 0 ? 4. - x.z() : x.z();
    EXPECT_NEAR(height, (row + 1) * 0.866 * 2. * std::sin(pi / 8.), 0.05);
    const CGAL::Epick::Point_2 planar_apex = CGAL::midpoint(a, b) + 0.866 * (b - a).perpendicular(CGAL::COUNTERCLOCKWISE);
    EXPECT_GT(std::sqrt(CGAL::squared_distance(planar_apex, seeds[k].point)), 0.1 * std::sqrt(CGAL::squared_distance(a, b)));
  }
  EXPECT_EQ(RM::equilateral_seeds(loops, all, onto_unit_cylinder).size(), 16u);
  const auto first_three_outer_chords = [&](const RM::Boundary_sample& a, const RM::Boundary_sample&) {
    return a.uv == outer[0].uv || a.uv == outer[1].uv || a.uv == outer[2].uv;
  };
  EXPECT_EQ(RM::equilateral_seeds(loops, first_three_outer_chords, onto_unit_cylinder, 2).size(), 5u);

  // Meshed with a size of 1.4 chords on the cylinder, with and without the seeds, smoothed once:
  // the triangles on the 16 chords, judged on the cylinder, and the points inside (rows of
  // equilateral triangles need 5 rows of 8).
  const auto size = [&](const CGAL::Epick::Point_2& p) { return 1.4 * 2. * std::sin(pi / 8.) * std::sqrt(p.x() * p.x() + p.y() * p.y()); };
  struct Result
  {
    double median_height = 0., mean_skewness = 0.; // of the triangles on the chords, over the chords
    std::size_t inner_points = 0;
  };
  auto mesh = [&](const std::vector<RM::Planar_seed>& with) {
    const RM::Planar_mesh m = RM::mesh_planar_domain<CGAL::Epick>(loops, 20.7, size, 1, false, {}, {}, with);
    Result result;
    result.inner_points = m.points.size() - m.number_of_samples;
    std::vector<double> heights;
    for(const auto& t : m.triangles)
      for(int c = 0; c < 3; ++c)
      {
        const int i = t[(c + 1) % 3], j = t[(c + 2) % 3];
        if(i >= int(m.number_of_samples) || j >= int(m.number_of_samples) || i / 8 != j / 8
           || (std::abs(i - j) != 1 && std::abs(i - j) != 7))
          continue;
        const CGAL::Epick::Point_3 p = lifted(m.points[i]), q = lifted(m.points[j]), r = lifted(m.points[t[c]]);
        heights.push_back(std::sqrt(CGAL::squared_distance(r, K::Line_3(p, q)) / CGAL::squared_distance(p, q)));
        result.mean_skewness += CR::triangle_quality(p, q, r).skewness / 16.;
      }
    EXPECT_EQ(heights.size(), 16u);
    std::sort(heights.begin(), heights.end());
    result.median_height = heights.at(heights.size() / 2);
    return result;
  };
  const Result seeded = mesh(seeds), unseeded = mesh({});
  std::cout << "first row: median height " << seeded.median_height << " (without seeds " << unseeded.median_height
            << "), mean skewness " << seeded.mean_skewness << " (" << unseeded.mean_skewness << "); inner points "
            << seeded.inner_points << " (" << unseeded.inner_points << ")" << std::endl;
  EXPECT_GT(seeded.median_height, 0.8);
  EXPECT_LT(seeded.mean_skewness, 0.1);
  EXPECT_LT(seeded.mean_skewness, 0.5 * unseeded.mean_skewness);
  EXPECT_LE(seeded.inner_points, 52u);
  EXPECT_GE(unseeded.inner_points, 60u);

  // A seed nearer a sample than its clearance is left out.
  const RM::Planar_mesh m = RM::mesh_planar_domain<CGAL::Epick>(
    loops, 20.7, size, 0, false, {}, {}, {RM::Planar_seed{CGAL::Epick::Point_2(1.05, 0.), 0.1}, RM::Planar_seed{CGAL::Epick::Point_2(1.5, 1.5), 0.1}});
  EXPECT_EQ(std::count(m.points.begin(), m.points.end(), CGAL::Epick::Point_2(1.05, 0.)), 0);
  EXPECT_EQ(std::count(m.points.begin(), m.points.end(), CGAL::Epick::Point_2(1.5, 1.5)), 1);
}

namespace {

// A closed polygon's corners, sampled every `spacing` along its sides (each side cut into equal
// pieces), as boundary samples on the plane z = 0.
std::vector<RM::Boundary_sample> sampled_loop(const std::vector<CGAL::Epick::Point_2>& corners, double spacing)
{
  std::vector<RM::Boundary_sample> loop;
  for(std::size_t i = 0; i < corners.size(); ++i)
  {
    const CGAL::Epick::Point_2 &a = corners[i], &b = corners[(i + 1) % corners.size()];
    const int pieces = (std::max)(1, int(std::lround(std::sqrt(CGAL::squared_distance(a, b)) / spacing)));
    for(int k = 0; k < pieces; ++k)
    {
      const CGAL::Epick::Point_2 p = a + (double(k) / pieces) * (b - a);
      loop.push_back(RM::Boundary_sample{p, CGAL::Epick::Point_3(p.x(), p.y(), 0.)});
    }
  }
  return loop;
}

// The share of the inner vertices (on no boundary edge) with six neighbours, and their number.
std::pair<double, std::size_t> share_of_valence_six(const RM::Planar_mesh& m)
{
  std::vector<std::array<int, 3> > neighbor;
  std::vector<int> valence(m.points.size(), 0);
  std::vector<char> on_boundary(m.points.size(), 0);
  RM::link_triangles(m.triangles, neighbor, [&](int a, int b, bool interior) {
    ++valence[a];
    ++valence[b];
    if(!interior)
      on_boundary[a] = on_boundary[b] = 1;
  });
  std::size_t inner = 0, six = 0;
  for(std::size_t v = 0; v < m.points.size(); ++v)
    if(!on_boundary[v] && valence[v] > 0)
    {
      ++inner;
      six += valence[v] == 6;
    }
  return {inner > 0 ? double(six) / double(inner) : 0., inner};
}

// The longest edge of a planar mesh over the size field at its midpoint.
template <typename Size>
double longest_edge_over_size(const RM::Planar_mesh& m, const Size& size)
{
  double worst = 0.;
  for(const auto& t : m.triangles)
    for(int c = 0; c < 3; ++c)
    {
      const CGAL::Epick::Point_2 &p = m.points[t[c]], &q = m.points[t[(c + 1) % 3]];
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(p, q)) / size(CGAL::midpoint(p, q)));
    }
  return worst;
}

} // namespace

TEST(PlanarMesher, FrontalInsertionGrowsRowsOfEquilateralTriangles)
{
  // The square [-1, 1]^2 with the hole [-0.3, 0.3]^2, its loops sampled every 0.1 and kept (as
  // the remesher's shared samples are), refined with a longest edge of 1.4 times that (the
  // remesher's bound): by Delaunay refinement alone, and from frontally inserted points.
  const double target = 0.1;
  const std::vector<std::vector<RM::Boundary_sample> > loops{
    sampled_loop({{-1., -1.}, {1., -1.}, {1., 1.}, {-1., 1.}}, target), sampled_loop({{-0.3, -0.3}, {-0.3, 0.3}, {0.3, 0.3}, {0.3, -0.3}}, target)};
  const auto size = [&](const CGAL::Epick::Point_2&) { return 1.4 * target; };
  RM::Frontal_insertion frontal;
  frontal.target_ratio = 1. / 1.4;
  const RM::Planar_mesh refined = RM::mesh_planar_domain<CGAL::Epick>(loops, 20.7, size, 0, false);
  const RM::Planar_mesh fronted = RM::mesh_planar_domain<CGAL::Epick>(loops, 20.7, size, 0, false, {}, {}, {}, frontal);
  for(const RM::Planar_mesh* m : {&refined, &fronted})
  {
    const Planar_mesh_measures measures(*m);
    EXPECT_TRUE(measures.counterclockwise);
    EXPECT_NEAR(measures.area, 4. - 0.36, 1e-12); // the hole stays empty, the rest is covered once
    EXPECT_EQ(measures.used_vertices.size(), m->points.size());
    EXPECT_GE(measures.smallest_angle, 20.7 - 1e-9); // the refinement's bound holds either way
    EXPECT_LE(longest_edge_over_size(*m, size), 1.);
    // The samples first, in loop order, and no point added on the loops.
    std::vector<CGAL::Epick::Point_2> samples;
    for(const auto& loop : loops)
      for(const RM::Boundary_sample& s : loop)
        samples.push_back(s.uv);
    ASSERT_EQ(m->number_of_samples, samples.size());
    EXPECT_TRUE(std::equal(samples.begin(), samples.end(), m->points.begin()));
  }
  // Rows of nearly equilateral triangles: a third of the mean skewness, and three in four inner
  // vertices with six neighbours, against one in two after refinement alone (measured: 0.076 and
  // 77% of 382 inner vertices, against 0.229 and 49% of 413).
  const Planar_mesh_measures a(refined), b(fronted);
  const std::pair<double, std::size_t> six_refined = share_of_valence_six(refined), six_fronted = share_of_valence_six(fronted);
  std::cout << "refinement: mean skewness " << a.mean_skewness << ", valence 6 " << six_refined.first << " of " << six_refined.second
            << " inner vertices; frontal: " << b.mean_skewness << ", " << six_fronted.first << " of " << six_fronted.second << std::endl;
  EXPECT_LT(b.mean_skewness, 0.1);
  EXPECT_GT(a.mean_skewness, 0.18);
  EXPECT_GT(six_fronted.first, 0.7);
  EXPECT_LT(six_refined.first, 0.55);
}

TEST(PlanarMesher, FrontalInsertionFollowsAGradedFieldAndEndsInASharpCorner)
{
  // A size field three times finer toward x = 1 than toward x = -1, over the square with its
  // loops sampled at the finest size: the edges follow the field.
  const auto size = [](const CGAL::Epick::Point_2& p) { return 1.4 * (0.05 + 0.05 * (1. - p.x())); };
  RM::Frontal_insertion frontal;
  frontal.target_ratio = 1. / 1.4;
  const std::vector<std::vector<RM::Boundary_sample> > square{sampled_loop({{-1., -1.}, {1., -1.}, {1., 1.}, {-1., 1.}}, 0.05)};
  const RM::Planar_mesh graded = RM::mesh_planar_domain<CGAL::Epick>(square, 20.7, size, 0, false, {}, {}, {}, frontal);
  const RM::Planar_mesh refined = RM::mesh_planar_domain<CGAL::Epick>(square, 20.7, size, 0, false);
  const Planar_mesh_measures measures(graded), refined_measures(refined);
  EXPECT_TRUE(measures.counterclockwise);
  EXPECT_NEAR(measures.area, 4., 1e-12);
  EXPECT_GE(measures.smallest_angle, 20.7 - 1e-9);
  EXPECT_LE(longest_edge_over_size(graded, size), 1.);
  std::cout << "graded: coarse / fine side " << measures.coarse_side / measures.fine_side << " (refinement alone "
            << refined_measures.coarse_side / refined_measures.fine_side << "), mean skewness " << measures.mean_skewness << " ("
            << refined_measures.mean_skewness << ")" << std::endl;
  // Measured: 1.86 (refinement alone 1.85; the field's ratio there is 2.6), mean skewness 0.151
  // (0.236): the boundary's fine samples start rows of small triangles on the coarse side too.
  EXPECT_GT(measures.coarse_side / measures.fine_side, 1.7);
  EXPECT_LT(measures.mean_skewness, 0.8 * refined_measures.mean_skewness);
  // A wedge of 5 degrees, its sides sampled every 0.05: the fronts from both sides meet in the
  // corner, where no triangle of the target size fits; the insertion ends and the domain is
  // covered (the refinement cannot raise the corner's angle, nor the triangles next to it).
  const double a = 5. * CGAL_PI / 180.;
  const std::vector<std::vector<RM::Boundary_sample> > wedge{
    sampled_loop({{0., 0.}, {2. * std::cos(a / 2.), -2. * std::sin(a / 2.)}, {2. * std::cos(a / 2.), 2. * std::sin(a / 2.)}}, 0.05)};
  const auto uniform = [](const CGAL::Epick::Point_2&) { return 0.07; };
  const RM::Planar_mesh sharp = RM::mesh_planar_domain<CGAL::Epick>(wedge, 20.7, uniform, 0, false, {}, {}, {}, frontal);
  const Planar_mesh_measures wedge_measures(sharp);
  EXPECT_TRUE(wedge_measures.counterclockwise);
  EXPECT_NEAR(wedge_measures.area, 4. * std::cos(a / 2.) * std::sin(a / 2.), 1e-12);
  EXPECT_EQ(wedge_measures.used_vertices.size(), sharp.points.size());
}

TEST(PlanarMesher, FrontalInsertionMeasuresFacesWithoutDividingByZero)
{
  typedef CGAL::Epick::Point_2 P;
  typedef CGAL::Epick::Vector_2 V;
  // A right triangle with legs 3 and 4: circumradius 2.5, circumcentre at the hypotenuse's midpoint.
  EXPECT_NEAR(RM::circumradius(P(0., 0.), P(4., 0.), P(0., 3.)), 2.5, 1e-15);
  EXPECT_NEAR(RM::circumcentre_offset(P(4., 0.), P(0., 3.), P(0., 0.), V(-0.6, -0.8)), 0., 1e-15);
  // Over the edge (-1, 0)-(1, 0): the circumcentre of the apex (0, 2) is at (0, 0.75); of the
  // apex (0, 0.5) at (0, -0.75), under the edge.
  EXPECT_NEAR(RM::circumcentre_offset(P(-1., 0.), P(1., 0.), P(0., 2.), V(0., 1.)), 0.75, 1e-15);
  EXPECT_NEAR(RM::circumcentre_offset(P(-1., 0.), P(1., 0.), P(0., 0.5), V(0., 1.)), -0.75, 1e-15);
  // Corners collinear in floating point but not exactly (exact predicates allow such a face, as
  // beside CGAL's femur's chords): their cross product, -2^-104, rounds to 0. The measure is
  // infinite, not NaN, so the face is never accepted.
  const double e = std::ldexp(1., -52);
  const P a(0., 0.), b(1. + e, 1.), c(1., 1. - e);
  ASSERT_EQ(CGAL::orientation(a, b, c), CGAL::RIGHT_TURN);
  EXPECT_EQ(RM::circumradius(a, b, c), std::numeric_limits<double>::infinity());
  // An apex on the edge's line, or right of it, puts no bound on the frontal point over it.
  EXPECT_EQ(RM::circumcentre_offset(P(-1., 0.), P(1., 0.), P(0.3, 0.), V(0., 1.)), std::numeric_limits<double>::infinity());
  EXPECT_EQ(RM::circumcentre_offset(P(-1., 0.), P(1., 0.), P(0.3, -1.), V(0., 1.)), std::numeric_limits<double>::infinity());
  EXPECT_EQ(RM::circumcentre_offset(a, b, c, V(-std::sqrt(0.5), std::sqrt(0.5))), std::numeric_limits<double>::infinity());
}

TEST(SurfaceOptimization, LeavesANonManifoldInputAsIs)
{
  // Three triangles on the edge (0, 1).
  std::vector<CGAL::Epick::Point_2> points{{0., 0.}, {1., 0.}, {0.5, 1.}, {0.5, -1.}, {0.5, 2.}};
  std::vector<std::array<int, 3> > triangles{{{0, 1, 2}}, {{1, 0, 3}}, {{0, 1, 4}}};
  std::vector<CGAL::Epick::Point_3> positions;
  for(const auto& p : points)
    positions.push_back(wavy_lift(p));
  const auto points_before = points;
  const auto triangles_before = triangles;
  EXPECT_FALSE(RM::optimize_on_surface(points, positions, triangles, 0, wavy_lift_near, 28., 1., longer_than(0.9), 3).optimized);
  EXPECT_EQ(points, points_before);
  EXPECT_EQ(triangles, triangles_before);
}

namespace {
CGAL::Epick::Point_3 flat_lift_near(const CGAL::Epick::Point_2& p, std::size_t&) { return CGAL::Epick::Point_3(p.x(), p.y(), 0.); }
} // namespace

TEST(SurfaceOptimization, NoFlipMakesASecondEdgeOnAChordOfAPatchThatTouchesItself)
{
  // The pentagon A B C D E, fanned from A; its corners are images of boundary samples. Flipping
  // A-C to B-D brings every valence to its target. When E is a second image of B's sample (the
  // patch touches itself there, as one of CGAL's femur's did), B-D would join the samples of the
  // chord D-E: two edges on one chord once glued. No flip may make it; with five distinct
  // samples it is made.
  const std::vector<CGAL::Epick::Point_2> pentagon{{0., 0.}, {1., -0.3}, {2., 0.}, {1., 0.3}, {0., 0.5}};
  const auto lift = &flat_lift_near; // the optimizer keeps a reference to it
  typedef RM::Surface_mesh_optimizer<decltype(lift)> Optimizer;
  auto flips_with_samples = [&](const std::vector<std::size_t>& sample_ids) {
    std::vector<CGAL::Epick::Point_2> points = pentagon;
    std::vector<CGAL::Epick::Point_3> positions;
    std::size_t hint = 0;
    for(const auto& p : points)
      positions.push_back(flat_lift_near(p, hint));
    std::vector<std::array<int, 3> > triangles{{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 4}}};
    Optimizer optimizer(points, positions, triangles, lift, 20., 10.);
    EXPECT_TRUE(optimizer.initialize(points.size(), sample_ids));
    return optimizer.flip_pass(Optimizer::VALENCE);
  };
  EXPECT_EQ(flips_with_samples({10, 11, 12, 13, 14}), 1u);
  EXPECT_EQ(flips_with_samples({10, 11, 12, 13, 11}), 0u);
}

TEST(PlanarLocator, FindsPointsInDiagonalSliverFansByGridAndByWalks)
{
  // A regular 400-gon fanned from one corner (CAD's slivers: 0.45 degrees at the fan's apex),
  // turned by 37 degrees so that the slivers run diagonally across the grid's cells, which now
  // hold only the triangles they overlap. Every point inside is found in a triangle that holds
  // it, by the grid and by walks from any hint; a point outside gets the clamped coordinates of
  // a nearby triangle.
  typedef CGAL::Epick::Point_2 P2;
  const int n = 400;
  const double turn = 37. * CGAL_PI / 180.;
  std::vector<P2> points;
  for(int i = 0; i < n; ++i)
    points.emplace_back(std::cos(turn + 2. * CGAL_PI * i / n), std::sin(turn + 2. * CGAL_PI * i / n));
  std::vector<std::array<int, 3> > triangles;
  for(int i = 1; i + 1 < n; ++i)
    triangles.push_back({{0, i, i + 1}});
  const RM::Planar_locator locator(points, triangles);
  auto holds = [&](const RM::Planar_locator::Location& l, const P2& p) {
    const std::array<int, 3>& t = triangles[l.triangle];
    double x = 0., y = 0.;
    for(int c = 0; c < 3; ++c)
    {
      x += l.coordinates[c] * points[t[c]].x();
      y += l.coordinates[c] * points[t[c]].y();
    }
    return *std::min_element(l.coordinates.begin(), l.coordinates.end()) >= -1e-12 && std::hypot(x - p.x(), y - p.y()) < 1e-12;
  };
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1., 1.);
  std::uniform_int_distribution<std::size_t> any_triangle(0, triangles.size() - 1);
  std::size_t walked_home = 0, inside = 0;
  for(int k = 0; k < 20000; ++k)
  {
    const P2 p(coordinate(random), coordinate(random));
    if(std::hypot(p.x(), p.y()) > 0.999) // outside the polygon or close to its sides
      continue;
    ++inside;
    const RM::Planar_locator::Location by_grid = locator.locate(p);
    EXPECT_TRUE(holds(by_grid, p)) << p;
    std::size_t hint = k % 2 == 0 ? any_triangle(random) : std::size_t(RM::Planar_locator::no_hint);
    const RM::Planar_locator::Location by_walk = locator.locate(p, hint);
    EXPECT_TRUE(holds(by_walk, p)) << p;
    EXPECT_EQ(hint, by_walk.triangle);
    // From a neighbour's triangle the walk is short and ends where the grid's search ended.
    std::size_t near = by_grid.triangle + (by_grid.triangle + 1 < triangles.size() ? 1 : -1);
    walked_home += locator.locate(p, near).triangle == by_grid.triangle;
  }
  EXPECT_GT(inside, 14000u);
  EXPECT_GT(walked_home, inside * 99 / 100);
  const RM::Planar_locator::Location outside = locator.locate(P2(1.5, 1.5));
  EXPECT_DOUBLE_EQ(outside.coordinates[0] + outside.coordinates[1] + outside.coordinates[2], 1.);
  EXPECT_EQ(*std::min_element(outside.coordinates.begin(), outside.coordinates.end()), 0.);
}

TEST(RemeshConformal, AMillionFacesWithOneBadFaceAreRefusedAtOnce)
{
  // Issue #8's hostile input: a flat grid of 708 x 707 unit squares (1,001,112 faces) in which
  // one vertex sits exactly on the diagonal of its square, making one face of zero area and no
  // other. The remesher names that face and stops before any work (time printed, not asserted).
  const int nx = 708, ny = 707;
  Mesh grid;
  std::vector<Mesh::Vertex_index> v;
  v.reserve(std::size_t(nx + 1) * std::size_t(ny + 1));
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      v.push_back(grid.add_vertex(K::Point_3(i, j, 0)));
  auto at = [&](int i, int j) { return v[std::size_t(j) * std::size_t(nx + 1) + std::size_t(i)]; };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      grid.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      grid.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  ASSERT_EQ(grid.number_of_faces(), 1001112u);
  const int bi = nx / 2, bj = ny / 2;
  grid.point(at(bi + 1, bj)) = K::Point_3(bi + 0.5, bj + 0.5, 0); // onto the diagonal (bi, bj)-(bi+1, bj+1)
  Mesh output;
  const auto start = std::chrono::steady_clock::now();
  test_support::expect_error([&] { CR::remesh_conformal(grid, output); }, CR::Error_code::INVALID_INPUT,
                             {"1 degenerate (zero-area) face", "has collinear vertices"});
  std::cout << "  refused in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s" << std::endl;
  EXPECT_EQ(output.number_of_faces(), 0u);
}

TEST(RemeshConformal, BadParametersAreRefused)
{
  Mesh patch;
  bm::make_spherical_cap(patch, 90., 8, 24);
  EXPECT_THROW(CR::remesh_conformal(patch, CR::parameters::minimum_angle(40.)), CR::Error);
  EXPECT_THROW(CR::remesh_conformal(patch, CR::parameters::target_edge_length(-1.)), CR::Error);
  EXPECT_THROW(CR::remesh_conformal(patch, CR::parameters::maximum_scale_ratio(0.5)), CR::Error);
  test_support::expect_error([&] { CR::remesh_conformal(patch, CR::parameters::optimization_rounds(-1)); },
                             CR::Error_code::INVALID_INPUT, {"optimization rounds"});
  test_support::expect_error([&] { CR::remesh_conformal(patch, CR::parameters::lloyd_iterations(-1)); },
                             CR::Error_code::INVALID_INPUT, {"Lloyd iterations"});
}

// Issue #8: maximum_running_time stops remesh_conformal() and conformal_flatten() with
// TIME_LIMIT_EXCEEDED, a message that says where, and the output untouched.
TEST(RemeshConformal, TimeLimit)
{
  Mesh mesh;
  bm::make_spherical_cap(mesh, 90., 8, 24);
  auto expect_time_limit = [](const auto& run, const std::string& message) {
    test_support::expect_error(run, CR::Error_code::TIME_LIMIT_EXCEEDED, {message, "(maximum_running_time) was exceeded"});
  };
  Mesh output;
  CGAL::make_triangle(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), output);
  expect_time_limit([&] { CR::remesh_conformal(mesh, output, CR::parameters::maximum_running_time(1e-9)); },
                    "remesh_conformal: stopped after the segmentation: the time limit of 1e-09 s");
  EXPECT_EQ(output.number_of_faces(), 1u); // untouched
  expect_time_limit([&] { CR::conformal_flatten(mesh, CR::parameters::maximum_running_time(1e-9)); },
                    "conformal_flatten: stopped after the input checks");

  // The limit passes while a stage starts (made slow): the patches stop, none is bisected.
  for(const std::string stage : {"flattening", "meshing"})
  {
    const auto slow = [&](const std::string& s) {
      if(s.compare(0, stage.size(), stage) == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(600));
    };
    expect_time_limit([&] {
      CR::remesh_conformal<CGAL::Sequential_tag>(mesh, output, CR::parameters::maximum_running_time(0.5, CR::parameters::progress(slow)));
    }, "remesh_conformal: stopped while " + stage + " the patches");
  }
  EXPECT_EQ(output.number_of_faces(), 1u);

  // A generous limit changes nothing; a negative one is refused.
  Mesh limited, unlimited;
  CR::remesh_conformal(mesh, limited, CR::parameters::maximum_running_time(3600., CR::parameters::relative_target_edge_length(0.05)));
  CR::remesh_conformal(mesh, unlimited, CR::parameters::relative_target_edge_length(0.05));
  EXPECT_EQ(limited.number_of_faces(), unlimited.number_of_faces());
  test_support::expect_error([&] { CR::remesh_conformal(mesh, output, CR::parameters::maximum_running_time(-1.)); },
                             CR::Error_code::INVALID_INPUT);
}
