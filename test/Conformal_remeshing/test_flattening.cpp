// Tests of the planar embedding check, and of flattenings of strongly concave patches.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_planar_embedding.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>

#include "cad_like_models.h"
#include "paper_models.h"
#include "test_surfaces.h"
#include "expect_error.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <gtest/gtest.h>

#include <array>
#include <complex>
#include <cstring>
#include <iostream>
#include <map>
#include <string>
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

TEST(PlanarEmbedding, OverlapsAreAreasInCommon)
{
  // A triangle inside another overlaps it although no edges cross; triangles on both sides of a
  // shared edge do not, even a sliver 1e-12 thick (as in a fuzzed folded grid), which does
  // overlap a triangle on its own side.
  const std::vector<Point_2> uv = {Point_2(0, 0), Point_2(4, 0), Point_2(0, 4), Point_2(1, 1), Point_2(2, 1), Point_2(1, 2),
                                   Point_2(4, 4), Point_2(2 + 1e-12, 2 + 1e-12)};
  auto overlaps = [&uv](const Faces& faces) {
    return CR::check_planar_embedding(uv, faces, Loops{}, true).overlapping_face_pairs;
  };
  EXPECT_EQ(overlaps({{{0, 1, 2}}, {{3, 4, 5}}}), 1u);
  EXPECT_EQ(overlaps({{{0, 1, 2}}, {{1, 6, 2}}}), 0u);
  EXPECT_EQ(overlaps({{{0, 1, 2}}, {{1, 7, 2}}}), 0u);
  EXPECT_EQ(overlaps({{{1, 6, 2}}, {{1, 7, 2}}}), 1u);
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

// --- conformal_flatten ------------------------------------------------------------------------

namespace {

// Expects a successful flattening whose final triangulation is an embedding, counting
// overlapping triangle pairs too.
void expect_embedding(const CR::Conformal_flattening& f, std::size_t expected_holes)
{
  EXPECT_EQ(f.report.status, CR::Error_code::SUCCESS) << CR::error_message(f.report.status);
  EXPECT_TRUE(f.report.converged);
  EXPECT_LT(f.report.curvature_error, 1e-9);
  EXPECT_TRUE(f.report.embedding.is_embedding()) << f.report.embedding.summary();
  EXPECT_EQ(f.holes.size(), expected_holes);

  std::vector<std::array<std::size_t, 3> > triangles;
  for(const auto& t : f.triangles)
    triangles.push_back({{std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])}});
  const CR::Planar_embedding_report full = CR::check_planar_embedding(f.layout, triangles, {}, true);
  EXPECT_EQ(full.non_positive_faces, 0u);
  EXPECT_EQ(full.overlapping_face_pairs, 0u);
}

// The largest distance between uv and the best similarity image of the planar input points
// (least squares in complex numbers: w = a z + b), relative to the input's diameter.
double similarity_error(const std::vector<std::complex<double> >& z, const std::vector<std::complex<double> >& w)
{
  std::complex<double> mz(0), mw(0);
  for(std::size_t i = 0; i < z.size(); ++i)
  {
    mz += z[i];
    mw += w[i];
  }
  mz /= double(z.size());
  mw /= double(z.size());
  std::complex<double> num(0);
  double den = 0.;
  for(std::size_t i = 0; i < z.size(); ++i)
  {
    num += std::conj(z[i] - mz) * (w[i] - mw);
    den += std::norm(z[i] - mz);
  }
  const std::complex<double> a = num / den;
  double error = 0., diameter = 0.;
  for(std::size_t i = 0; i < z.size(); ++i)
  {
    error = (std::max)(error, std::abs(a * (z[i] - mz) + mw - w[i]) / std::abs(a));
    diameter = (std::max)(diameter, 2. * std::abs(z[i] - mz));
  }
  return error / diameter;
}

} // namespace

TEST(ConformalFlatten, ConcaveStripIsEmbeddedWhereLscmOverlaps)
{
  Mesh mesh;
  bm::make_wavy_c_strip(mesh);
  const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
  expect_embedding(f, 0);
  // The uv of the input vertices, as a parameterization of the input triangles, has no overlap either.
  auto uv = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
  for(auto v : mesh.vertices())
    uv[v] = f.uv[v.idx()];
  const CR::Planar_embedding_report input = CR::check_parameterization(mesh, uv, true);
  EXPECT_TRUE(input.is_embedding()) << input.summary();
  EXPECT_EQ(input.overlapping_face_pairs, 0u);
}

TEST(ConformalFlatten, PlanarRoundDiscIsASimilarity)
{
  // A disc whose boundary vertices lie on a circle, triangulated badly: Delaunay on random
  // points, then every other flippable edge flipped. Welding to the annulus changes nothing
  // there, so the flattening must be a similarity up to rounding.
  typedef CGAL::Delaunay_triangulation_2<K> DT;
  CGAL::Random random(7);
  DT dt;
  for(int i = 0; i < 64; ++i)
    dt.insert(K::Point_2(std::cos(2 * CGAL_PI * i / 64), std::sin(2 * CGAL_PI * i / 64)));
  for(int i = 0; i < 300; ++i)
  {
    const double r = 0.95 * std::sqrt(random.get_double()), t = 2 * CGAL_PI * random.get_double();
    dt.insert(K::Point_2(r * std::cos(t), r * std::sin(t)));
  }
  int flipped = 0;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
  {
    const DT::Face_handle f = e->first, g = f->neighbor(e->second);
    if(dt.is_infinite(f) || dt.is_infinite(g) || (flipped++ % 2))
      continue;
    const K::Point_2 &a = f->vertex(e->second)->point(), &b = f->vertex(f->cw(e->second))->point(),
                     &c = g->vertex(g->index(f))->point(), &d = f->vertex(f->ccw(e->second))->point();
    if(CGAL::orientation(a, b, c) == CGAL::POSITIVE && CGAL::orientation(c, d, a) == CGAL::POSITIVE)
      dt.flip(f, e->second);
  }
  Mesh mesh;
  std::map<DT::Vertex_handle, Mesh::Vertex_index> vertex;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    vertex[v] = mesh.add_vertex(K::Point_3(v->point().x(), v->point().y(), 0.));
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    mesh.add_face(vertex[f->vertex(0)], vertex[f->vertex(1)], vertex[f->vertex(2)]);
  ASSERT_LT(CR::mesh_quality(mesh).minimum_angle.min, 5.); // the triangulation is bad indeed

  const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
  expect_embedding(f, 0);
  std::vector<std::complex<double> > z, w;
  for(auto v : mesh.vertices())
  {
    z.emplace_back(mesh.point(v).x(), mesh.point(v).y());
    w.emplace_back(f.uv[v.idx()].x(), f.uv[v.idx()].y());
  }
  EXPECT_LT(similarity_error(z, w), 1e-9);

  // A similarity has one scale: the conformal factor is constant, the log of that scale.
  const auto range = std::minmax_element(f.conformal_factor.begin(), f.conformal_factor.end());
  EXPECT_LT(*range.second - *range.first, 1e-8);
  const double layout_scale = std::abs(w[1] - w[0]) / std::abs(z[1] - z[0]);
  EXPECT_NEAR(std::exp(f.conformal_factor[0]), layout_scale, 1e-8 * layout_scale);
}

TEST(ConformalFlatten, SphericalCapIsCloseToTheStereographicProjection)
{
  // Stereographic projection maps the cap conformally onto a disc, and the vertex-scaling
  // conformal equivalence of a mesh inscribed in a sphere is Moebius invariant, so with the
  // cap's own (Delaunay) triangulation the discrete flattening would be the stereographic
  // projection exactly. The flow's Euclidean flips during Newton steps make the result depend
  // on the path (Ptolemy flips would not): measured errors range from 1e-13 to 1.6e-3 relative
  // to the diameter, depending on the resolution. The bound below is that measurement.
  for(int level : {1, 2, 4})
  {
    Mesh mesh;
    bm::make_spherical_cap(mesh, 120., 8 * level, 24 * level);
    const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
    expect_embedding(f, 0);
    std::vector<std::complex<double> > z, w;
    for(auto v : mesh.vertices())
    {
      const K::Point_3& p = mesh.point(v);
      z.emplace_back(p.x() / (1 + p.z()), p.y() / (1 + p.z()));
      w.emplace_back(f.uv[v.idx()].x(), f.uv[v.idx()].y());
    }
    EXPECT_LT(similarity_error(z, w), 5e-3) << "level " << level;
  }
}

TEST(ConformalFlatten, ConformalDistortionShrinksUnderRefinement)
{
  // On a non-spherical surface (an ellipsoidal cap), the piecewise linear map from the input
  // triangles to their uv images is only approximately conformal; its mean quasi-conformal
  // distortion (ratio of the singular values of each triangle's affine map, minus 1) must go
  // to zero at least linearly in the mesh size.
  std::vector<double> distortion;
  for(int level : {1, 2, 4})
  {
    Mesh mesh;
    bm::make_spherical_cap(mesh, 100., 8 * level, 24 * level);
    for(auto v : mesh.vertices())
      mesh.point(v) = K::Point_3(1.5 * mesh.point(v).x(), mesh.point(v).y(), 0.7 * mesh.point(v).z());
    const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
    expect_embedding(f, 0);
    double sum = 0.;
    for(auto face : mesh.faces())
    {
      const auto h = mesh.halfedge(face);
      const Mesh::Vertex_index v[3] = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
      const K::Vector_3 e1 = mesh.point(v[1]) - mesh.point(v[0]), e2 = mesh.point(v[2]) - mesh.point(v[0]);
      const K::Vector_3 x = e1 / std::sqrt(e1.squared_length());
      const K::Vector_3 n = CGAL::cross_product(e1, e2);
      K::Vector_3 y = CGAL::cross_product(n, x);
      y = y / std::sqrt(y.squared_length());
      // J maps the triangle in its own plane (columns q1, q2) onto its uv image (columns w1, w2).
      const double q11 = e1 * x, q12 = e2 * x, q21 = 0., q22 = e2 * y;
      const K::Vector_2 w1 = f.uv[v[1].idx()] - f.uv[v[0].idx()], w2 = f.uv[v[2].idx()] - f.uv[v[0].idx()];
      const double det_q = q11 * q22 - q12 * q21;
      const double a = (w1.x() * q22 - w2.x() * q21) / det_q, b = (w2.x() * q11 - w1.x() * q12) / det_q;
      const double c = (w1.y() * q22 - w2.y() * q21) / det_q, d = (w2.y() * q11 - w1.y() * q12) / det_q;
      const double frobenius = a * a + b * b + c * c + d * d, det = a * d - b * c;
      const double root = std::sqrt((std::max)(0., frobenius * frobenius - 4 * det * det));
      sum += std::sqrt((frobenius + root) / (frobenius - root)) - 1.;
    }
    distortion.push_back(sum / double(mesh.number_of_faces()));
  }
  EXPECT_LT(distortion[1], 0.6 * distortion[0]) << distortion[0] << " " << distortion[1];
  EXPECT_LT(distortion[2], 0.6 * distortion[1]) << distortion[1] << " " << distortion[2];
}

TEST(ConformalFlatten, CadLikeSheetsWithManyHoles)
{
  // Sheets tessellated like CAD faces (fans of slivers), flat and bent, with 1, 10 and 100 holes.
  for(int holes : {1, 10, 100})
    for(double bend : {0., 0.3})
    {
      bm::Perforated_plate_parameters p;
      p.number_of_random_holes = holes;
      if(holes == 100)
      {
        p.length = 400;
        p.width = 300;
        p.min_hole_radius = 2;
        p.max_hole_radius = 6;
        p.min_clearance = 2;
        p.segments_per_circle = 32;
      }
      Mesh mesh;
      bm::make_perforated_sheet(mesh, p, bend);
      ASSERT_LT(CR::mesh_quality(mesh).minimum_angle.min, 1.);
      SCOPED_TRACE(std::to_string(holes) + " holes, bend " + std::to_string(bend));
      const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
      expect_embedding(f, std::size_t(holes));
    }
}

TEST(ConformalFlatten, CgalMeshesWithBoundaries)
{
  const std::string meshes = std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/";
  for(const auto& m : std::vector<std::pair<std::string, std::size_t> >{
        {"mech-holes-shark.off", 3}, {"pig.off", 6}, {"holes.off", 6}, {"lion.off", 4}, {"nefertiti.off", 0}})
  {
    SCOPED_TRACE(m.first);
    Mesh mesh;
    ASSERT_TRUE(CR::read_and_check_mesh(meshes + m.first, mesh).is_valid());
    expect_embedding(CR::conformal_flatten(mesh), m.second);
  }
}

TEST(ConformalFlatten, ABladeWhoseSliversShearTheFlowIsFlattenedAgainFiner)
{
  // CGAL's blade.off: the flow on the input's own edges converges, yet its strips of long
  // slivers shear the map until a triangle folds; the flattening is done again on a flow whose
  // edges are split to a fiftieth of the diagonal.
  Mesh mesh;
  ASSERT_TRUE(CR::read_and_check_mesh(std::string(CONFORMAL_REMESHING_CGAL_DATA) + "/meshes/blade.off", mesh).is_valid());
  const CR::Conformal_flattening once = CR::conformal_flatten(mesh, CR::parameters::maximum_edge_length(1e30));
  EXPECT_FALSE(once.report.embedding.is_embedding()) << "the case this test is about is gone";
  const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
  EXPECT_GT(f.report.refined_edge_length, 0.);
  expect_embedding(f, 1);
}

TEST(ConformalFlatten, SliversFlatInDoubleLengthsAreOpened)
{
  // A grid sheet, flat and curved (bent along y only, it would be developable and
  // retriangulated), with a CAD sliver on each edge of its straight border y = 0: its apex lies
  // 1e-13 off the border, so its largest angle is pi - 4e-13, a valid triangle for exact
  // predicates whose double lengths violate the triangle inequality (the full-scale chassis of
  // the paper benchmark's arm has 93 such faces in one patch).
  for(double bend : {0., 0.3})
  {
    SCOPED_TRACE("bend " + std::to_string(bend));
    Mesh mesh;
    const int n = 8;
    auto point = [&](double x, double y) { return K::Point_3(x, y, bend * y * y * (1. + 0.1 * x * x)); };
    std::vector<Mesh::Vertex_index> grid;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
        grid.push_back(mesh.add_vertex(point(i, j)));
    auto at = [&](int i, int j) { return grid[std::size_t(j * (n + 1) + i)]; };
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
    std::vector<Mesh::Vertex_index> apex;
    for(int i = 0; i < n; ++i)
    {
      apex.push_back(mesh.add_vertex(point(i + 0.5, -1e-13)));
      ASSERT_NE(mesh.add_face(at(i + 1, 0), at(i, 0), apex.back()), Mesh::null_face());
    }
    ASSERT_TRUE(CR::check_mesh(mesh).is_valid()); // no degenerate face for exact predicates

    const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
    EXPECT_GE(f.report.flat_sides_shortened, std::size_t(n));
    expect_embedding(f, 0);
    if(bend == 0.)
    {
      // A planar patch is laid out at its own coordinates: each apex stays 1e-13 off the border
      // line, not the 1e-7 of the opened lengths (which folded CAD slivers of the full-scale
      // brake disc's flat faces).
      const K::Vector_2 axis = f.uv[at(n, 0)] - f.uv[at(0, 0)];
      for(Mesh::Vertex_index v : apex)
      {
        const double offset = CGAL::determinant(axis, f.uv[v] - f.uv[at(0, 0)]) / std::sqrt(axis.squared_length());
        EXPECT_NEAR(offset, -1e-13, 1e-14);
      }
    }
  }
}

TEST(ConformalFlatten, WeldedBoundaryCanBeChosen)
{
  Mesh mesh;
  bm::Perforated_plate_parameters p;
  p.number_of_random_holes = 3;
  bm::make_perforated_sheet(mesh, p, 0.3);
  // Weld a hole instead of the outer rim: the rim becomes one of the holes of the domain.
  Mesh::Halfedge_index hole_border;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h) && std::abs(mesh.point(mesh.source(h)).x()) < 50)
      hole_border = h;
  const CR::Conformal_flattening f = CR::conformal_flatten(mesh, CR::parameters::welded_boundary(hole_border));
  expect_embedding(f, 3);
  bool rim_is_a_hole = false;
  for(const auto& hole : f.holes)
    for(const CR::Domain_point& q : hole)
      rim_is_a_hole = rim_is_a_hole || std::abs(q.point.x()) > 59.9;
  EXPECT_TRUE(rim_is_a_hole);
}

TEST(ConformalFlatten, DomainBoundaryPointsLieOnTheInputBoundary)
{
  Mesh mesh;
  bm::make_wavy_c_strip(mesh);
  const CR::Conformal_flattening f = CR::conformal_flatten(mesh);
  ASSERT_FALSE(f.outer_boundary.empty());
  for(const CR::Domain_point& q : f.outer_boundary)
  {
    // The surface point is the input face's point at the given barycentric coordinates.
    const auto h = mesh.halfedge(Mesh::Face_index(Mesh::size_type(q.input_face)));
    const K::Point_3 x = CGAL::barycenter(mesh.point(mesh.source(h)), q.input_coordinates[0], mesh.point(mesh.target(h)),
                                          q.input_coordinates[1], mesh.point(mesh.target(mesh.next(h))), q.input_coordinates[2]);
    EXPECT_LT(std::sqrt(CGAL::squared_distance(x, q.point)), 1e-12);
  }
}

TEST(ConformalFlatten, BadInputIsRefusedWithTheReason)
{
  auto expect_error = [](const Mesh& mesh, const std::string& reason) {
    try
    {
      CR::conformal_flatten(mesh);
      ADD_FAILURE() << "no error, expected: " << reason;
    }
    catch(const CR::Error& e)
    {
      EXPECT_EQ(e.code(), CR::Error_code::INVALID_INPUT);
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  };
  Mesh closed;
  CGAL::make_tetrahedron(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, 0, 1), closed);
  expect_error(closed, "closed");

  Mesh plate; // a closed plate with 7 holes: genus 7
  bm::make_perforated_plate(plate, bm::Perforated_plate_parameters());
  expect_error(plate, "genus 7");

  Mesh two; // two separate triangles
  two.add_face(two.add_vertex(K::Point_3(0, 0, 0)), two.add_vertex(K::Point_3(1, 0, 0)), two.add_vertex(K::Point_3(0, 1, 0)));
  two.add_face(two.add_vertex(K::Point_3(5, 0, 0)), two.add_vertex(K::Point_3(6, 0, 0)), two.add_vertex(K::Point_3(5, 1, 0)));
  expect_error(two, "2 connected components");

  Mesh bowtie; // two triangles sharing one vertex
  const auto c = bowtie.add_vertex(K::Point_3(0, 0, 0));
  bowtie.add_face(c, bowtie.add_vertex(K::Point_3(1, 0, 0)), bowtie.add_vertex(K::Point_3(1, 1, 0)));
  bowtie.add_face(c, bowtie.add_vertex(K::Point_3(-1, 0, 0)), bowtie.add_vertex(K::Point_3(-1, -1, 0)));
  expect_error(bowtie, "non-manifold vertex");
}

// A maximum edge length meant for another scale (1e-4 on a unit tetrahedron: some 10^8 splits)
// is refused once a million splits have not sufficed, not worked on until memory runs out.
TEST(ConformalFlatten, LongEdgesAreSplitToTheSurfacesAreaNotToItsFans)
{
  // A bent sheet of CAD fans: splitting every long edge of a round at once placed the midpoints
  // of a fan's edges as close together as its slivers and refined from there (32 times the
  // splits the area needs on the 87k suspension arm). A triangulation whose edges are at most
  // L and whose angles are not too small has a few vertices per L^2 of area: split points, and
  // grid points where the sheet unfolds into flat regions (here the whole bent sheet does).
  bm::Perforated_plate_parameters p;
  p.number_of_random_holes = 10;
  Mesh mesh;
  bm::make_perforated_sheet(mesh, p, 0.3);
  const double area = CGAL::Polygon_mesh_processing::area(mesh);
  const double length = std::sqrt(area / 2000.);
  const CR::Conformal_flattening f = CR::conformal_flatten(mesh, CR::parameters::maximum_edge_length(length));
  expect_embedding(f, 10);
  const std::size_t added = f.report.edge_splits + f.number_of_patch_points() - num_vertices(mesh);
  EXPECT_GT(added, std::size_t(1000));
  EXPECT_LT(added, std::size_t(4 * 2000)) << "over-refined: " << f.report.edge_splits << " splits";
}

TEST(ConformalFlatten, AMaximumEdgeLengthFarTooSmallIsRefused)
{
  Mesh open_tetrahedron;
  CGAL::make_tetrahedron(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, 0, 1), open_tetrahedron);
  CGAL::Euler::remove_face(halfedge(*open_tetrahedron.faces().begin(), open_tetrahedron), open_tetrahedron);
  open_tetrahedron.collect_garbage();
  test_support::expect_error([&] { CR::conformal_flatten(open_tetrahedron, CR::parameters::maximum_edge_length(1e-4)); },
                             CR::Error_code::INVALID_INPUT,
                             {"a maximum_edge_length of 0.0001 needs more than 1000000 edge splits"});
  // A sensible length is accepted.
  EXPECT_EQ(CR::conformal_flatten(open_tetrahedron, CR::parameters::maximum_edge_length(0.1)).report.status,
            CR::Error_code::SUCCESS);
}

namespace {
// A point of `mesh` given by an input face and barycentric coordinates.
K::Point_3 input_point(const Mesh& mesh, std::size_t face, const std::array<double, 3>& b)
{
  const auto h = mesh.halfedge(Mesh::Face_index(Mesh::size_type(face)));
  return CGAL::barycenter(mesh.point(mesh.source(h)), b[0], mesh.point(mesh.target(h)), b[1],
                          mesh.point(mesh.target(mesh.next(h))), b[2]);
}

// How far the point at `b` in face `f` of `patch` lies from the point of the input face it is
// located in, at the coordinates found there.
double distance_to_located_input_point(const Mesh& input, const CR::internal::welding::Indexed_patch& patch, std::size_t f,
                                       const std::array<double, 3>& b)
{
  const auto location = patch.input_location(int(f), b);
  const CR::internal::welding::Vec3 x = patch.point_in_face(int(f), b);
  return std::sqrt(CGAL::squared_distance(input_point(input, std::size_t(location.first), location.second), K::Point_3(x[0], x[1], x[2])));
}

// The whole of `mesh` as an indexed patch (its faces not retriangulated yet).
CR::internal::welding::Indexed_patch indexed_patch_of(const Mesh& mesh)
{
  return CR::internal::welding::make_indexed_patch(mesh, get(CGAL::vertex_point, mesh), get(CGAL::vertex_index, mesh),
                                                   get(CGAL::face_index, mesh));
}

// A model of the paper benchmark at a test's size.
Mesh small_paper_model(bm::Paper_model model, std::size_t vertices)
{
  Mesh mesh;
  bm::Paper_model_parameters p;
  p.target_vertices = vertices;
  bm::make_paper_model(mesh, model, p);
  return mesh;
}

// The intrinsic triangulation of a patch's faces with the lengths of their edges on the surface
// (`developed`) or of their chords in space.
CR::Intrinsic_triangulation<double> intrinsic_triangulation_of(const CR::internal::welding::Indexed_patch& patch,
                                                                bool developed = true)
{
  auto length = [&](int a, int b) {
    return developed ? patch.edge_length(a, b) : CR::internal::welding::distance(patch.points[a], patch.points[b]);
  };
  std::vector<std::array<double, 3> > lengths;
  for(const auto& f : patch.faces)
    lengths.push_back({{length(f[0], f[1]), length(f[1], f[2]), length(f[2], f[0])}});
  return CR::Intrinsic_triangulation<double>(int(patch.points.size()), patch.faces, lengths);
}
} // namespace

TEST(ConformalFlatten, CornerCoordinatesAreGivenBackBitForBitAndStoredOnlyWhenNeitherIdentityNorZero)
{
  typedef CR::internal::welding::Corner_coordinates Coordinates;
  const auto same_bits = [](const Coordinates::Value& a, const Coordinates::Value& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  const Coordinates::Value split{{{{1., 0., 0.}}, {{0.5, 0.5, 0.}}, {{0., 0., 1.}}}};
  const Coordinates::Value negative_zero{{{{-0., 0., 0.}}, {{0., 0., 0.}}, {{0., 0., 0.}}}};
  Coordinates c;
  c.assign_identity(4);
  c.set(1, split);
  c.set(2, Coordinates::Value{});
  c.push_back(negative_zero); // compares equal to zeros, but is not them bit for bit
  c.push_back(Coordinates::identity());
  ASSERT_EQ(c.size(), 6u);
  EXPECT_TRUE(same_bits(c[0], Coordinates::identity()));
  EXPECT_TRUE(same_bits(c[1], split));
  EXPECT_TRUE(same_bits(c[2], Coordinates::Value{}));
  EXPECT_TRUE(same_bits(c[3], Coordinates::identity()));
  EXPECT_TRUE(same_bits(c[4], negative_zero));
  EXPECT_FALSE(same_bits(c[4], Coordinates::Value{}));
  EXPECT_TRUE(same_bits(c[5], Coordinates::identity()));
  EXPECT_EQ(c.stored.size(), 2u); // the split face's and the negative zero's
  // Set again: a stored face keeps its place, an identity face is stored no more.
  c.set(1, negative_zero);
  c.set(4, Coordinates::identity());
  EXPECT_TRUE(same_bits(c[1], negative_zero));
  EXPECT_TRUE(same_bits(c[4], Coordinates::identity()));
  EXPECT_EQ(c.stored.size(), 2u);

  // The patch of a mesh: every face an input face, nothing stored.
  Mesh square;
  const auto a = square.add_vertex(K::Point_3(0, 0, 0)), b = square.add_vertex(K::Point_3(1, 0, 0));
  const auto d = square.add_vertex(K::Point_3(1, 1, 0)), e = square.add_vertex(K::Point_3(0, 1, 0));
  square.add_face(a, b, d);
  square.add_face(a, d, e);
  const CR::internal::welding::Indexed_patch patch = indexed_patch_of(square);
  EXPECT_EQ(patch.input_coordinates.size(), 2u);
  EXPECT_TRUE(patch.input_coordinates.stored.empty());
}

TEST(ConformalFlatten, FlatFansAreRetriangulatedAndPointsLocatedInTheirInputFaces)
{
  // A disc of 800 slivers fanned from one boundary vertex, bent up away from the apex. With no
  // inner vertex, it unfolds into the plane: along a cylinder, the whole disc is one region; a
  // corrugated bend (every other rim vertex higher) turns too much from sliver to sliver where
  // it rises, and only the faces left in the plane (about 500 slivers) and the first of the
  // bend are. Their constrained Delaunay triangulation replaces them (the flips saved are
  // measured on a CAD part below).
  for(const bool developable : {true, false})
  {
    SCOPED_TRACE(developable ? "cylinder bend" : "corrugated bend");
    Mesh mesh;
    bm::make_sliver_fan_disc(mesh, 800);
    for(auto v : mesh.vertices())
    {
      const double x = -mesh.point(v).x(), y = mesh.point(v).y(); // apex at (-1, 0)
      const double rise = x > 0.3 ? (x - 0.3) * (x - 0.3) : 0.;
      mesh.point(v) = K::Point_3(x, y, developable || std::size_t(v) % 2 == 0 ? rise : 1.5 * rise);
    }
    const CR::Conformal_flattening f = CR::conformal_flatten(mesh, CR::parameters::maximum_edge_length(0.2));
    expect_embedding(f, 0);
    if(developable)
    {
      ASSERT_EQ(CR::internal::flattening::Patch_access::of(f).flat_regions.size(), std::size_t(1));
      EXPECT_TRUE(CR::internal::flattening::Patch_access::of(f).flat_regions.front().developed);
      EXPECT_EQ(f.report.retriangulated_faces, num_faces(mesh));
      // The new edges have their lengths in the unfolding, so the region stays flat: the
      // angles at every inner vertex of the new triangulation add up to 2 pi (with the chords
      // across the bend, they would not: the patch's vertices are on the cylinder, off its
      // unfolding's straight lines).
      CR::Intrinsic_triangulation<double> developed = intrinsic_triangulation_of(CR::internal::flattening::Patch_access::of(f), true),
                                          chords = intrinsic_triangulation_of(CR::internal::flattening::Patch_access::of(f), false);
      const std::vector<double> curvature = developed.vertex_curvatures(), chord_curvature = chords.vertex_curvatures();
      double largest_deficit = 0., largest_chord_deficit = 0.;
      std::size_t inner = 0;
      for(int v = 0; v < developed.number_of_vertices(); ++v)
        if(!developed.is_border_vertex(v))
        {
          largest_deficit = (std::max)(largest_deficit, std::abs(curvature[v]));
          largest_chord_deficit = (std::max)(largest_chord_deficit, std::abs(chord_curvature[v]));
          ++inner;
        }
      EXPECT_GT(inner, std::size_t(50)); // the grid points
      EXPECT_LT(largest_deficit, 1e-9);
      EXPECT_GT(largest_chord_deficit, 1e-4);
    }
    else
    {
      EXPECT_GT(f.report.retriangulated_faces, std::size_t(400));
      EXPECT_LT(f.report.retriangulated_faces, num_faces(mesh));
    }
    // Every surface point through the map lies in the input face it is located in: points in
    // every flat triangle, and the domain's boundary points.
    CGAL::Random random(7);
    std::size_t checked = 0;
    for(std::size_t t = 0; t < f.triangles.size(); ++t)
      for(int k = 0; k < 4; ++k)
      {
        const double u = random.get_double(), w = random.get_double() * (1. - u);
        const std::array<double, 3> b = k == 0 ? std::array<double, 3>{{1., 0., 0.}} : std::array<double, 3>{{u, w, 1. - u - w}};
        const CR::Domain_point q = f.to_surface(t, b);
        ASSERT_LT(q.input_face, num_faces(mesh));
        for(double c : q.input_coordinates)
          EXPECT_GE(c, -1e-12);
        EXPECT_LT(std::sqrt(CGAL::squared_distance(input_point(mesh, q.input_face, q.input_coordinates), q.point)), 1e-12)
          << "triangle " << t;
        ++checked;
      }
    for(const CR::Domain_point& q : f.outer_boundary)
      EXPECT_LT(std::sqrt(CGAL::squared_distance(input_point(mesh, q.input_face, q.input_coordinates), q.point)), 1e-12);
    EXPECT_GT(checked, std::size_t(3000));
  }
}

TEST(ConformalFlatten, CoplanarRegionsOfACadPartNeedFewFlips)
{
  // The 10k suspension arm: its planar faces are fans whose Delaunay flips are most of the
  // flattening's time at scale (92 million at 316k vertices on the paper benchmark's arm).
  const Mesh arm = small_paper_model(bm::Paper_model::suspension_arm, 10000);
  CR::internal::welding::Indexed_patch patch = indexed_patch_of(arm);
  auto flips = [&] {
    return intrinsic_triangulation_of(patch).make_delaunay();
  };
  const std::size_t before = flips();
  const std::size_t replaced = CR::internal::welding::retriangulate_flat_regions(patch);
  EXPECT_GT(replaced, num_faces(arm) / 10);
  EXPECT_EQ(patch.faces.size(), num_faces(arm));
  const std::size_t after = flips();
  EXPECT_LT(10 * after, before) << "flips before: " << before << ", after: " << after;
  // Each new face's centroid lies in the input face it is located in, at those coordinates.
  for(std::size_t f = 0; f < patch.faces.size(); ++f)
  {
    const std::array<double, 3> centroid{{1. / 3, 1. / 3, 1. / 3}};
    ASSERT_LT(distance_to_located_input_point(arm, patch, f, centroid), 1e-9) << "face " << f;
  }
}

TEST(ConformalFlatten, BendsUnfoldWithThePlanarFacesAroundThemIntoOneRegion)
{
  // A small chassis rail of the paper benchmark: each side of its hat section (flanges, walls and web,
  // joined by bends tessellated as strips of slivers spanning the rail's length) is developable.
  // Retriangulating the planar faces alone left the flips between them and the bends, 17.8
  // million on the full-scale rail.
  const Mesh rail = small_paper_model(bm::Paper_model::chassis, 20000);
  CR::internal::welding::Indexed_patch patch = indexed_patch_of(rail);
  const std::size_t before = intrinsic_triangulation_of(patch).make_delaunay();
  CR::internal::welding::retriangulate_flat_regions(patch);
  // The two sides of the section, each one region unfolded across its four bends.
  std::size_t developed = 0, largest_coplanar = 0;
  for(const auto& region : patch.flat_regions)
    if(region.developed)
      ++developed;
    else
      largest_coplanar = (std::max)(largest_coplanar, region.faces.size());
  EXPECT_EQ(developed, std::size_t(2));
  for(const auto& region : patch.flat_regions)
    if(region.developed)
      EXPECT_GT(region.faces.size(), 2 * largest_coplanar);
  const std::size_t after = intrinsic_triangulation_of(patch).make_delaunay();
  // (Measured: 156293 flips before, 11213 after.)
  EXPECT_LT(10 * after, before) << "flips before: " << before << ", after: " << after;
  // With grid points (every 3 mm in a 1600 mm rail), as the flattening adds them, every corner
  // and centroid of the new faces lies in the input face it is located in (in a developed
  // region, the point is placed in the original face holding it in the unfolding).
  patch = indexed_patch_of(rail);
  CR::internal::welding::retriangulate_flat_regions(patch, 3.);
  EXPECT_GT(patch.points.size(), num_vertices(rail) + 10000);
  for(std::size_t f = 0; f < patch.faces.size(); ++f)
    for(const std::array<double, 3>& b : {std::array<double, 3>{{1. / 3, 1. / 3, 1. / 3}}, std::array<double, 3>{{1., 0., 0.}},
                                         std::array<double, 3>{{0., 1., 0.}}, std::array<double, 3>{{0., 0., 1.}}})
    {
      ASSERT_LT(distance_to_located_input_point(rail, patch, f, b), 1e-9) << "face " << f;
    }
}

TEST(ConformalFlatten, GridPointsInCoplanarRegionsSpareTheRefinementItsFlips)
{
  // The refinement to a maximum edge length split the long edges of a planar face's
  // triangulation (its vertices all on its outline) one at a time, with two dozen flips each on
  // the paper benchmark's arm, and every point pulled back walked back through them. Grid points added in
  // the plane leave it little to do there, and lie on the input faces they are located in.
  const Mesh arm = small_paper_model(bm::Paper_model::suspension_arm, 10000);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(arm);
  const double maximum_length = 0.02 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                                 + CGAL::square(box.zmax() - box.zmin()));
  auto refinement = [&](double spacing, CR::internal::welding::Indexed_patch& patch) {
    patch = indexed_patch_of(arm);
    CR::internal::welding::retriangulate_flat_regions(patch, spacing);
    CR::Intrinsic_triangulation<double> tri = intrinsic_triangulation_of(patch);
    std::size_t splits = 0;
    EXPECT_TRUE(CR::internal::split_long_patch_edges(tri, patch.faces.size(), maximum_length, 1000000, splits));
    return std::make_pair(tri.number_of_flips(), splits);
  };
  CR::internal::welding::Indexed_patch without, with;
  const auto plain = refinement(0., without), gridded = refinement(maximum_length / 1.5, with);
  EXPECT_EQ(without.points.size(), num_vertices(arm));
  EXPECT_GT(with.points.size(), without.points.size() + 100);
  // (Measured: 20601 flips and 2735 splits without, 7661 and 922 with 1682 grid points.)
  EXPECT_LT(2 * gridded.first, plain.first) << "flips without grid points: " << plain.first << ", with: " << gridded.first;
  EXPECT_LT(2 * gridded.second, plain.second) << "splits without grid points: " << plain.second << ", with: " << gridded.second;
  // Every corner and centroid of the new faces lies in the input face it is located in.
  for(std::size_t f = 0; f < with.faces.size(); ++f)
    for(const std::array<double, 3>& b : {std::array<double, 3>{{1. / 3, 1. / 3, 1. / 3}}, std::array<double, 3>{{1., 0., 0.}},
                                         std::array<double, 3>{{0., 1., 0.}}, std::array<double, 3>{{0., 0., 1.}}})
    {
      ASSERT_LT(distance_to_located_input_point(arm, with, f, b), 1e-9) << "face " << f;
    }
}

// The side wall of a plate with a rounded rectangular outline (`per_corner` edges on each
// quarter circle, `per_side` on each straight side): a band of two boundary loops of the
// outline's length, each of which a cone would fill with a non-Delaunay fan (straight sides).
Mesh rounded_rectangle_band(double width, double depth, double radius, double height, int per_corner, int per_side)
{
  Mesh band;
  std::vector<std::pair<double, double> > outline;
  const double cx[4] = {width / 2 - radius, -width / 2 + radius, -width / 2 + radius, width / 2 - radius};
  const double cy[4] = {depth / 2 - radius, depth / 2 - radius, -depth / 2 + radius, -depth / 2 + radius};
  for(int corner = 0; corner < 4; ++corner)
  {
    for(int k = 0; k <= per_corner; ++k)
    {
      const double a = CGAL_PI / 2 * (corner + double(k) / per_corner);
      outline.emplace_back(cx[corner] + radius * std::cos(a), cy[corner] + radius * std::sin(a));
    }
    const int next = (corner + 1) % 4;
    const double a = CGAL_PI / 2 * (corner + 1);
    for(int k = 1; k < per_side; ++k) // the straight side to the next corner
    {
      const double s = double(k) / per_side;
      outline.emplace_back((1 - s) * (cx[corner] + radius * std::cos(a)) + s * (cx[next] + radius * std::cos(a)),
                           (1 - s) * (cy[corner] + radius * std::sin(a)) + s * (cy[next] + radius * std::sin(a)));
    }
  }
  std::vector<Mesh::Vertex_index> bottom, top;
  for(const auto& p : outline)
    bottom.push_back(band.add_vertex(K::Point_3(p.first, p.second, 0.)));
  for(const auto& p : outline)
    top.push_back(band.add_vertex(K::Point_3(p.first, p.second, height)));
  const std::size_t n = outline.size();
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    band.add_face(bottom[i], bottom[j], top[j]);
    band.add_face(bottom[i], top[j], top[i]);
  }
  return band;
}

TEST(ConformalFlatten, HolesFilledByTheirPolygonMapBackContinuously)
{
  // The band's bottom loop is filled by the triangulation of its polygon, with chords across the
  // whole outline. A point of the wall next to the seam can come back from the correspondence in
  // a fill face with a rounding weight on a far loop vertex: it was once moved there (81 units
  // away on the default plate's wall), and the refinement split the fill's chords as if they
  // were the patch's.
  const double width = 100., depth = 80., height = 6.;
  const Mesh band = rounded_rectangle_band(width, depth, 10., height, 16, 12);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(band));
  const CR::Conformal_flattening f = CR::conformal_flatten(band, CR::parameters::maximum_edge_length(2.8));
  expect_embedding(f, 1);
  EXPECT_GT(f.report.edge_splits, std::size_t(100));
  // The refinement resolves the wall, not the fill: the wall's area at that length.
  EXPECT_LT(f.report.edge_splits, std::size_t(4 * (2 * (width + depth) * height) / (2.8 * 2.8)));
  CGAL::Random random(3);
  for(std::size_t t = 0; t < f.triangles.size(); ++t)
  {
    std::array<K::Point_3, 3> corner;
    double longest = 0.;
    for(int c = 0; c < 3; ++c)
      corner[c] = f.corner_to_surface(t, c).point;
    for(int c = 0; c < 3; ++c)
      longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(corner[c], corner[(c + 1) % 3])));
    const double u = random.get_double(), w = random.get_double() * (1. - u);
    const CR::Domain_point q = f.to_surface(t, {{u, w, 1. - u - w}});
    for(int c = 0; c < 3; ++c)
      ASSERT_LE(std::sqrt(CGAL::squared_distance(q.point, corner[c])), longest + 1e-9) << "triangle " << t;
    EXPECT_LT(std::sqrt(CGAL::squared_distance(input_point(band, q.input_face, q.input_coordinates), q.point)), 1e-9);
  }
}

TEST(ConformalFlatten, PolygonFillsOfLongLoopsHaveInteriorPointsAndFewFlips)
{
  // A pocket's loop: a long narrow outline with dense straight sides. Filled by its polygon
  // alone, the fill is all slivers between loop vertices, and the flow flipped them with the
  // square of the loop's size as the conformal factors along it changed (0.87 million of a
  // 100k suspension arm patch's 1.0 million flips; 1782 of 2277 here). Grid points inside the
  // polygon (at the spacing of the flat regions' grid) leave the fill 252 flips.
  const Mesh band = rounded_rectangle_band(400., 12., 4., 3., 8, 150);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(band));
  const double maximum_length = 4.;
  const CR::internal::welding::Indexed_patch patch = indexed_patch_of(band);
  const CR::internal::welding::Welded_disc disc = CR::internal::welding::weld(patch, 0, 0.3, maximum_length / 1.5);
  const std::size_t loop = patch.boundary_loops[1].size(), fill_faces = disc.fill_faces;
  // A disc: one more face per loop vertex (minus 2) and two per interior point.
  ASSERT_GT(fill_faces, loop);
  EXPECT_EQ((fill_faces + 2 - loop) % 2, 0u);
  std::map<std::pair<int, int>, int> sides;
  for(std::size_t f = disc.patch_faces; f < disc.patch_faces + disc.fill_faces; ++f)
    for(int c = 0; c < 3; ++c)
    {
      ++sides[{disc.faces[f][c], disc.faces[f][(c + 1) % 3]}];
      // lengths of a triangle in space (the interior points lie on the loop's plane)
      const std::array<double, 3>& l = disc.lengths[f];
      EXPECT_LT(l[c], l[(c + 1) % 3] + l[(c + 2) % 3]);
    }
  for(const auto& side : sides) // every side once, and every loop edge a side of the fill
    EXPECT_EQ(side.second, 1);
  for(std::size_t i = 0; i < loop; ++i)
  {
    const int a = patch.boundary_loops[1][i], b = patch.boundary_loops[1][(i + 1) % loop];
    EXPECT_EQ(sides.count({b, a}) + sides.count({a, b}), 1u) << "loop edge " << i;
  }

  const CR::Conformal_flattening f = CR::conformal_flatten(band, CR::parameters::maximum_edge_length(maximum_length));
  expect_embedding(f, 1);
  EXPECT_LT(f.report.hole_fill_flips, loop / 2) << "flips in the fill: " << f.report.hole_fill_flips << " of " << f.report.flips;
}
