// The named parameters of `remesh_conformal()`: each value a user gives is honoured, whether it is
// built with the package's builders or CGAL's, and no default the package adds overrides it.
// (`features_fallback` is tested on CGAL's dino in test_remeshing.cpp, where the fallback is needed.)

#include <CGAL/remesh_conformal.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>

#include "expect_error.h"
#include "paper_models.h"
#include "test_surfaces.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// A spherical cap of 120 degrees, radius 1 (diagonal about 2.5), coarse enough to remesh fast.
Mesh cap()
{
  Mesh mesh;
  bm::make_spherical_cap(mesh, 120., 8, 24);
  return mesh;
}

double diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

double mean_edge_length(const Mesh& m)
{
  double sum = 0.;
  for(auto e : m.edges())
    sum += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return sum / double(m.number_of_edges());
}

// Whether two meshes have the same points and faces, in order.
bool same_mesh(const Mesh& a, const Mesh& b)
{
  if(a.number_of_vertices() != b.number_of_vertices() || a.number_of_faces() != b.number_of_faces())
    return false;
  for(auto v : a.vertices())
    if(a.point(v) != b.point(v))
      return false;
  return true;
}

template <typename NamedParameters>
Mesh remeshed(const Mesh& input, const NamedParameters& np, CR::Remeshing_report* report = nullptr)
{
  Mesh output;
  const CR::Remeshing_report r = CR::remesh_conformal(input, output, np);
  if(report != nullptr)
    *report = r;
  return output;
}

const double h = 0.08; // the target edge length of the tests below, about 3% of the cap's diagonal

} // namespace

TEST(Parameters, TargetEdgeLengths)
{
  const Mesh input = cap();
  CR::Remeshing_report report;
  const Mesh output = remeshed(input, CR::parameters::target_edge_length(h), &report);
  EXPECT_EQ(report.target_edge_length, h);
  EXPECT_NEAR(mean_edge_length(output), h, 0.15 * h);
  remeshed(input, CR::parameters::relative_target_edge_length(0.04), &report);
  EXPECT_DOUBLE_EQ(report.target_edge_length, 0.04 * diagonal(input));
  // An absolute length wins over a relative one.
  remeshed(input, CR::parameters::target_edge_length(h, CR::parameters::relative_target_edge_length(0.04)), &report);
  EXPECT_EQ(report.target_edge_length, h);
  test_support::expect_error([&] { remeshed(input, CR::parameters::target_edge_length(-1.)); }, CR::Error_code::INVALID_INPUT,
                             {"target edge length"});
}

TEST(Parameters, SizingFieldAndChordError)
{
  Mesh input; // finer than the target, so that its curvature is measured well
  bm::make_spherical_cap(input, 120., 32, 96);
  const Mesh uniform = remeshed(input, CR::parameters::target_edge_length(h));
  // Half the target on one side of the cap: more vertices, shorter edges there.
  const auto half_on_one_side = [](const K::Point_3& p) { return p.x() > 0. ? 0.5 * h : h; };
  const Mesh sized = remeshed(input, CR::parameters::sizing_field(half_on_one_side, CR::parameters::target_edge_length(h)));
  EXPECT_GT(sized.number_of_vertices(), 1.5 * uniform.number_of_vertices());
  // A chord error below the sag of a target-long chord on the unit sphere (h^2 / 8) shortens edges.
  const Mesh adaptive = remeshed(input, CR::parameters::maximum_chord_error(h * h / 32., CR::parameters::target_edge_length(h)));
  EXPECT_GT(adaptive.number_of_vertices(), 1.5 * uniform.number_of_vertices());
  test_support::expect_error([&] { remeshed(input, CR::parameters::maximum_chord_error(-1.)); }, CR::Error_code::INVALID_INPUT,
                             {"chord error"});
  test_support::expect_error([&] { remeshed(input, CR::parameters::maximum_surface_distance(-1.)); }, CR::Error_code::INVALID_INPUT,
                             {"surface distance"});
}

TEST(Parameters, AnglesAndPlanarMeshing)
{
  const Mesh input = cap();
  const Mesh reference = remeshed(input, CR::parameters::target_edge_length(h));
  // Each of these changes what the planar meshing or the optimization does, hence the output.
  EXPECT_FALSE(same_mesh(reference, remeshed(input, CR::parameters::minimum_angle(15., CR::parameters::target_edge_length(h)))));
  EXPECT_FALSE(same_mesh(reference, remeshed(input, CR::parameters::frontal_insertion(false, CR::parameters::target_edge_length(h)))));
  EXPECT_FALSE(same_mesh(reference, remeshed(input, CR::parameters::smoothing_iterations(2, CR::parameters::target_edge_length(h)))));
  EXPECT_FALSE(same_mesh(reference, remeshed(input, CR::parameters::lloyd_iterations(5, CR::parameters::target_edge_length(h)))));
  CR::Remeshing_statistics statistics;
  remeshed(input, CR::parameters::optimization_rounds(0, CR::parameters::target_edge_length(h, CR::parameters::statistics(std::ref(statistics)))));
  EXPECT_EQ(statistics.optimization_flips, 0u);
  EXPECT_EQ(statistics.optimization_splits, 0u);
  remeshed(input, CR::parameters::target_edge_length(h, CR::parameters::statistics(std::ref(statistics))));
  EXPECT_GT(statistics.optimization_flips, 0u);
  test_support::expect_error([&] { remeshed(input, CR::parameters::minimum_angle(40.)); }, CR::Error_code::INVALID_INPUT,
                             {"minimum angle"});
}

TEST(Parameters, CornerAngleKeepsTheBorderCorners)
{
  // The cap's border is a 24-gon: each of its vertices turns by 15 degrees.
  const Mesh input = cap();
  const auto corners_kept = [&](double corner_degrees) {
    const Mesh output = remeshed(input, CR::parameters::corner_angle(corner_degrees, CR::parameters::target_edge_length(0.5 * h)));
    std::size_t kept = 0;
    for(auto hd : input.halfedges())
      if(input.is_border(hd))
        for(auto v : output.vertices())
          if(output.point(v) == input.point(input.target(hd)))
            ++kept;
    return kept;
  };
  EXPECT_EQ(corners_kept(10.), 24u);
  EXPECT_LT(corners_kept(30.), 24u);
}

TEST(Parameters, SegmentationAndFlatteningParameters)
{
  const Mesh input = cap();
  CR::Remeshing_report reference, report;
  CR::Remeshing_statistics reference_statistics, statistics;
  const Mesh reference_output =
    remeshed(input, CR::parameters::target_edge_length(h, CR::parameters::statistics(std::ref(reference_statistics))), &reference);
  // The flow's resolution: the default is twice the target; shorter edges split more in the flow.
  remeshed(input,
           CR::parameters::maximum_edge_length(0.5 * h, CR::parameters::target_edge_length(h, CR::parameters::statistics(std::ref(statistics)))));
  ASSERT_EQ(statistics.patches.size(), reference_statistics.patches.size());
  EXPECT_GT(statistics.patches[0].edge_splits, reference_statistics.patches[0].edge_splits);
  // A scale ratio the cap's flattening exceeds bisects it.
  const double ratio = 0.8 * reference_statistics.max_scale_ratio;
  ASSERT_GT(ratio, 1.);
  remeshed(input, CR::parameters::maximum_scale_ratio(ratio, CR::parameters::target_edge_length(h)), &report);
  EXPECT_GT(report.patch_bisections, reference.patch_bisections);
  // A cutting plane a little off a ring of input vertices: within the snap distance it snaps to
  // them, a cut of other vertices than without snapping.
  const std::vector<K::Plane_3> planes{K::Plane_3(1., 0., 0., -0.013)};
  const Mesh cut = remeshed(input, CR::parameters::cut_planes(planes, CR::parameters::target_edge_length(h)));
  const Mesh snapped = remeshed(
    input, CR::parameters::snap_distance(0.2, CR::parameters::cut_planes(planes, CR::parameters::target_edge_length(h))));
  EXPECT_FALSE(same_mesh(cut, snapped));
  EXPECT_FALSE(same_mesh(cut, reference_output));
}

TEST(Parameters, ProgressAndVertexLocations)
{
  const Mesh input = cap();
  std::vector<std::string> stages;
  std::vector<CR::Surface_location> locations;
  Mesh output;
  CR::remesh_conformal(input, output,
                       CR::parameters::vertex_locations(
                         std::ref(locations), CR::parameters::progress([&](const std::string& stage) { stages.push_back(stage); },
                                                                       CR::parameters::target_edge_length(h))));
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front(), "checking the input");
  EXPECT_NE(std::find(stages.begin(), stages.end(), "gluing"), stages.end());
  ASSERT_EQ(locations.size(), output.number_of_vertices());
  const CR::Remesh_verification verification =
    CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_TRUE(verification.locations_checked);
  EXPECT_TRUE(verification.is_valid()) << verification.summary();
}

TEST(Parameters, VertexPointAndFaceIndexMaps)
{
  const Mesh input = cap();
  // Points twice as far from the origin: the output is the input's, scaled.
  Mesh scaled_input = input;
  auto scaled = scaled_input.add_property_map<Mesh::Vertex_index, K::Point_3>("v:scaled").first;
  for(auto v : scaled_input.vertices())
    scaled[v] = K::Point_3(2. * input.point(v).x(), 2. * input.point(v).y(), 2. * input.point(v).z());
  CR::Remeshing_report report;
  const Mesh output = remeshed(scaled_input, CR::parameters::relative_target_edge_length(0.04).vertex_point_map(scaled), &report);
  EXPECT_DOUBLE_EQ(report.target_edge_length, 0.04 * 2. * diagonal(input));
  const Mesh unscaled = remeshed(input, CR::parameters::relative_target_edge_length(0.04));
  EXPECT_NEAR(diagonal(output), 2. * diagonal(unscaled), 0.01 * diagonal(unscaled));

  // Face indices in reverse order: the locations name faces by them.
  Mesh indexed = input;
  auto reversed = indexed.add_property_map<Mesh::Face_index, std::size_t>("f:reversed").first;
  for(auto f : indexed.faces())
    reversed[f] = indexed.number_of_faces() - 1 - std::size_t(f);
  std::vector<CR::Surface_location> locations;
  Mesh by_index;
  CR::remesh_conformal(indexed, by_index,
                       CR::parameters::vertex_locations(std::ref(locations), CGAL::parameters::face_index_map(reversed)));
  const CR::Remesh_verification verification = CR::verify_remesh(
    indexed, by_index, CR::parameters::vertex_locations(std::cref(locations), CGAL::parameters::face_index_map(reversed)));
  EXPECT_TRUE(verification.is_valid()) << verification.summary();
  // The same locations read with the internal indices do not match.
  const CR::Remesh_verification mismatched =
    CR::verify_remesh(indexed, by_index, CR::parameters::vertex_locations(std::cref(locations)));
  EXPECT_FALSE(mismatched.locations_match);
}

TEST(Parameters, MaximumRunningTimeIsCgalsParameter)
{
  const Mesh input = cap();
  Mesh output;
  const std::vector<std::string> fragments{"remesh_conformal: stopped", "(maximum_running_time) was exceeded"};
  test_support::expect_error([&] { CR::remesh_conformal(input, output, CGAL::parameters::maximum_running_time(1e-9)); },
                             CR::Error_code::TIME_LIMIT_EXCEEDED, {fragments[0], fragments[1]});
  test_support::expect_error([&] { CR::remesh_conformal(input, output, CR::parameters::maximum_running_time(1e-9)); },
                             CR::Error_code::TIME_LIMIT_EXCEEDED, {fragments[0], fragments[1]});
  // Chained either way with the package's parameters.
  test_support::expect_error(
    [&] { CR::remesh_conformal(input, output, CR::parameters::target_edge_length(h).maximum_running_time(1e-9)); },
    CR::Error_code::TIME_LIMIT_EXCEEDED);
  test_support::expect_error(
    [&] { CR::remesh_conformal(input, output, CR::parameters::target_edge_length(h, CGAL::parameters::maximum_running_time(1e-9))); },
    CR::Error_code::TIME_LIMIT_EXCEEDED);
  EXPECT_EQ(output.number_of_faces(), 0u); // untouched
}

TEST(Parameters, MaximumRunningTimeStopsA100kVertexPart)
{
  Mesh arm;
  bm::Paper_model_parameters p;
  p.target_vertices = 100000;
  bm::make_suspension_arm(arm, p);
  ASSERT_GE(arm.number_of_vertices(), 95000u);
  Mesh output;
  const auto start = std::chrono::steady_clock::now();
  test_support::expect_error([&] { CGAL::remesh_conformal(arm, output, CGAL::parameters::maximum_running_time(0.05)); },
                             CR::Error_code::TIME_LIMIT_EXCEEDED, {"time limit of 0.05 s"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "stopped after " << seconds << " s" << std::endl; // said, not asserted: the machine's pace varies
  EXPECT_EQ(output.number_of_faces(), 0u);
}
