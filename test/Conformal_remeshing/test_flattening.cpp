// Tests of the planar embedding check, and of flattenings of strongly concave patches.

#include <CGAL/Conformal_remeshing/check_planar_embedding.h>

#include "test_surfaces.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Epick K;
typedef K::Point_2 Point_2;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::vector<std::array<std::size_t, 3> > Faces;
typedef std::vector<std::vector<std::size_t> > Loops;

namespace {
// A unit square split into two positively oriented triangles.
std::vector<Point_2> square() { return {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)}; }
const Faces square_faces = {{{0, 1, 2}}, {{0, 2, 3}}};
const Loops square_loop = {{0, 1, 2, 3}};
} // namespace

TEST(PlanarEmbedding, SquareIsAnEmbedding)
{
  const CR::Planar_embedding_report r = CR::check_planar_embedding(square(), square_faces, square_loop, true);
  EXPECT_TRUE(r.is_embedding()) << r.summary();
  EXPECT_EQ(r.summary(), "embedding");
}

TEST(PlanarEmbedding, FoldedTriangle)
{
  // Vertex 3 dragged across the diagonal: triangle (0, 2, 3) turns negative and overlaps
  // (0, 1, 2), while the boundary polygon stays simple; only the orientation test sees it.
  std::vector<Point_2> uv = square();
  uv[3] = Point_2(0.9, 0.2);
  const CR::Planar_embedding_report r = CR::check_planar_embedding(uv, square_faces, square_loop, true);
  EXPECT_EQ(r.non_positive_faces, 1u);
  EXPECT_EQ(r.overlapping_face_pairs, 1u);
  EXPECT_EQ(r.boundary_intersections, 0u);
  EXPECT_FALSE(r.is_embedding());
}

TEST(PlanarEmbedding, DegenerateTriangleIsNotPositive)
{
  std::vector<Point_2> uv = square();
  uv[3] = Point_2(0.5, 0.5); // on the diagonal 0-2: triangle (0, 2, 3) is flat
  const CR::Planar_embedding_report r = CR::check_planar_embedding(uv, square_faces, square_loop);
  EXPECT_EQ(r.non_positive_faces, 1u);
}

TEST(PlanarEmbedding, GlobalOverlapWithPositiveTriangles)
{
  // Two separate positive triangles laid on top of each other: locally fine, globally not.
  const std::vector<Point_2> uv = {Point_2(0, 0), Point_2(2, 0), Point_2(0, 2), Point_2(0.5, 0.5), Point_2(3, 0.5), Point_2(0.5, 3)};
  const Faces faces = {{{0, 1, 2}}, {{3, 4, 5}}};
  const CR::Planar_embedding_report r = CR::check_planar_embedding(uv, faces, {{0, 1, 2}, {3, 4, 5}}, true);
  EXPECT_EQ(r.non_positive_faces, 0u);
  EXPECT_EQ(r.overlapping_face_pairs, 1u);
  EXPECT_EQ(r.boundary_intersections, 2u);
}

TEST(PlanarEmbedding, TouchingTrianglesDoNotOverlap)
{
  // Two triangles sharing only a vertex position but not an index: no area in common, but the
  // boundary touches itself, so this is not an embedding.
  const std::vector<Point_2> uv = {Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), Point_2(1, 0), Point_2(2, 0), Point_2(2, 1)};
  const CR::Planar_embedding_report r = CR::check_planar_embedding(uv, {{{0, 1, 2}}, {{3, 4, 5}}}, {{0, 1, 2}, {3, 4, 5}}, true);
  EXPECT_EQ(r.overlapping_face_pairs, 0u);
  EXPECT_GT(r.boundary_intersections, 0u);
}

TEST(PlanarEmbedding, HolesMustLieInsideTheOuterBoundary)
{
  // An outer square 0..3 with a hole 4-5-6 inside or outside it; triangles are irrelevant here.
  std::vector<Point_2> uv = {Point_2(0, 0), Point_2(4, 0), Point_2(4, 4), Point_2(0, 4),
                             Point_2(1, 1), Point_2(2, 1), Point_2(1, 2)};
  const Loops loops = {{0, 1, 2, 3}, {4, 6, 5}};
  EXPECT_EQ(CR::check_planar_embedding(uv, {}, loops).misplaced_holes, 0u);
  for(std::size_t v : {4, 5, 6})
    uv[v] = uv[v] + K::Vector_2(10, 0);
  EXPECT_EQ(CR::check_planar_embedding(uv, {}, loops).misplaced_holes, 1u);
}

TEST(PlanarEmbedding, LscmOverlapsOnAStronglyConcaveStrip)
{
  // The wavy C-shaped strip: CGAL's LSCM folds it over itself, counted with exact predicates.
  // The same strip without waves is planar, and LSCM reproduces it: an embedding (so the
  // check does not simply fail everything).
  for(double amplitude : {0., 0.6})
  {
    Mesh mesh;
    bm::Wavy_c_strip_parameters p;
    p.amplitude = amplitude;
    bm::make_wavy_c_strip(mesh, p);
    auto uv = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
    const auto border = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    ASSERT_EQ(SMP::parameterize(mesh, SMP::LSCM_parameterizer_3<Mesh>(), border, uv), SMP::OK);
    const CR::Planar_embedding_report r = CR::check_parameterization(mesh, uv, true);
    if(amplitude == 0.)
      EXPECT_TRUE(r.is_embedding()) << r.summary();
    else
    {
      EXPECT_GT(r.overlapping_face_pairs, 1000u) << r.summary();
      EXPECT_GT(r.boundary_intersections, 0u) << r.summary();
    }
  }
}
