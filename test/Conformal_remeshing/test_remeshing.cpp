// Tests of remesh_conformal() on single patches: quality, fidelity, boundaries, exact pull-back.

#include <CGAL/remesh_conformal.h>

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include "remeshing_checks.h"
#include "test_surfaces.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using remeshing_checks::check_remeshing;
using remeshing_checks::diagonal;


TEST(RemeshConformal, WavyConcaveStrip)
{
  Mesh mesh;
  bm::make_wavy_c_strip(mesh);
  check_remeshing(mesh, 20.);
}

TEST(RemeshConformal, SphericalCap)
{
  Mesh mesh;
  bm::make_spherical_cap(mesh, 120., 16, 48);
  check_remeshing(mesh, 20.);
}

TEST(RemeshConformal, CgalNefertiti)
{
  Mesh mesh;
  ASSERT_TRUE(CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/nefertiti.off", mesh).is_valid());
  check_remeshing(mesh, 20.);
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

TEST(RemeshConformal, PlanarStageWithExactConstructions)
{
  // The planar mesher is templated on the kernel: a square with a square hole over Epeck.
  namespace RM = CR::internal::remeshing;
  auto square = [](double half, bool clockwise) {
    std::vector<RM::Boundary_sample> loop;
    const double x[4] = {-half, half, half, -half}, y[4] = {-half, -half, half, half};
    for(int i = 0; i < 4; ++i)
    {
      const int k = clockwise ? 3 - i : i;
      loop.push_back(RM::Boundary_sample{CGAL::Epick::Point_2(x[k], y[k]), CGAL::Epick::Point_3(x[k], y[k], 0.)});
    }
    return loop;
  };
  const std::vector<std::vector<RM::Boundary_sample> > loops{square(1., false), square(0.3, true)};
  const RM::Planar_mesh exact = RM::mesh_planar_domain<CGAL::Epeck>(loops, 25., [](const CGAL::Epick::Point_2&) { return 0.2; }, 1);
  const RM::Planar_mesh inexact = RM::mesh_planar_domain<CGAL::Epick>(loops, 25., [](const CGAL::Epick::Point_2&) { return 0.2; }, 1);
  for(const RM::Planar_mesh* m : {&exact, &inexact})
  {
    ASSERT_GT(m->triangles.size(), 50u);
    double area = 0., smallest = 180.;
    for(const auto& t : m->triangles)
    {
      const CGAL::Epick::Point_2 &a = m->points[t[0]], &b = m->points[t[1]], &c = m->points[t[2]];
      EXPECT_EQ(CGAL::orientation(a, b, c), CGAL::POSITIVE);
      area += CGAL::area(a, b, c);
      const CR::Triangle_quality tq = CR::triangle_quality(K::Point_3(a.x(), a.y(), 0), K::Point_3(b.x(), b.y(), 0), K::Point_3(c.x(), c.y(), 0));
      smallest = (std::min)({smallest, tq.angles[0], tq.angles[1], tq.angles[2]});
    }
    EXPECT_NEAR(area, 4. - 0.36, 1e-12); // the square minus the hole, exactly covered
    EXPECT_GE(smallest, 20.);
  }
}

TEST(RemeshConformal, BadParametersAreRefused)
{
  Mesh patch;
  bm::make_spherical_cap(patch, 90., 8, 24);
  EXPECT_THROW(CR::remesh_conformal(patch, CR::parameters::minimum_angle(40.)), CR::Error);
  EXPECT_THROW(CR::remesh_conformal(patch, CR::parameters::target_edge_length(-1.)), CR::Error);
  EXPECT_THROW(CR::remesh_conformal(patch, CR::parameters::maximum_scale_ratio(0.5)), CR::Error);
}
