// After gluing: flips and moves across the cuts between patches, on the glued soup.

#include "stage_tests.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <limits>
#include <memory>

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

TEST(CollapsesAfterGluing, ASampleBesideACurveEndGoesIntoItAlongItsFeature)
{
  // A feature along y = 0 sampled at s0 (a curve end), s1 (inside the curve, a twentieth from
  // s0) and s2 (a curve end); p and q above and below. The triangles at s0-s1 are needles (2.6
  // degrees). s1 goes into s0; the feature's chord is then s0-s2.
  typedef CGAL::Epick::Point_3 P;
  typedef std::array<std::size_t, 3> T;
  typedef CR::Poly_annulus_segmentation::Vertex V;
  const std::size_t s0 = 0, s1 = 1, s2 = 2, p = 3, q = 4;
  const std::vector<P> points{P(0, 0, 0), P(0.05, 0, 0), P(1, 0, 0), P(0.5, 0.8, 0), P(0.5, -0.8, 0)};
  RM::Curve_samples samples;
  samples.points.assign(points.begin(), points.begin() + 3);
  samples.at_vertex[V(10)] = s0;
  samples.at_vertex[V(12)] = s2;
  samples.curve_of_chord[{s0, s1}] = 0;
  samples.curve_of_chord[{s1, s2}] = 0;
  samples.is_kept_curve = {1};
  samples.number_of_curves = 1;
  const std::vector<T> glued{T{{s0, s1, p}}, T{{s1, s2, p}}, T{{s1, s0, q}}, T{{s2, s1, q}}};
  const auto size = [](std::size_t, std::size_t) { return 1.; }; // edges under a quarter collapse

  std::vector<T> triangles = glued;
  std::vector<std::size_t> patch_of_triangle{0, 0, 1, 1};
  RM::Glued_soup_collapser collapser(points, triangles, patch_of_triangle, samples, 30.);
  EXPECT_EQ(collapser.collapse_short_edges(size, 1.), 1u);
  EXPECT_EQ(triangles, (std::vector<T>{T{{s0, s2, p}}, T{{s2, s0, q}}}));
  EXPECT_EQ(patch_of_triangle, (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(collapser.is_kept_chord(s2, s0));
  EXPECT_FALSE(collapser.is_kept_chord(s0, p));

  // The feature turning at s1, 0.02 off the chord s0-s2 (beyond 0.008 times the size): s1 stays,
  // so that the turn is not cut off.
  std::vector<P> turning = points;
  turning[s1] = P(0.05, 0.02, 0);
  samples.points[s1] = turning[s1];
  triangles = glued;
  patch_of_triangle = {0, 0, 1, 1};
  RM::Glued_soup_collapser turn(turning, triangles, patch_of_triangle, samples, 30.);
  EXPECT_EQ(turn.collapse_short_edges(size, 1.), 0u);
  EXPECT_EQ(triangles, glued);
  samples.points[s1] = points[s1];

  // Both ends of the short edge curve ends (s1 at a vertex of the segmented mesh too): nothing goes.
  samples.at_vertex[V(11)] = s1;
  triangles = glued;
  patch_of_triangle = {0, 0, 1, 1};
  RM::Glued_soup_collapser ends(points, triangles, patch_of_triangle, samples, 30.);
  EXPECT_EQ(ends.collapse_short_edges(size, 1.), 0u);
  EXPECT_EQ(triangles, glued);

  // s1 on the feature, the short edge off it (to a point r beside s1): s1 does not leave its
  // feature; r, an inner point, goes into s1 instead.
  samples.at_vertex.erase(V(11));
  std::vector<P> with_r = points;
  with_r.push_back(P(0.5, 0.04, 0)); // r = 5, beside the middle of the feature
  std::vector<P> moved = with_r;
  moved[s1] = P(0.48, 0, 0);
  const std::size_t r = 5;
  const std::vector<T> around_r{T{{s0, s1, r}}, T{{s1, s2, r}}, T{{s2, p, r}}, T{{p, s0, r}}, T{{s1, s0, q}}, T{{s2, s1, q}}};
  triangles = around_r;
  patch_of_triangle.assign(6, 0);
  RM::Glued_soup_collapser inner(moved, triangles, patch_of_triangle, samples, 30.);
  EXPECT_EQ(inner.collapse_short_edges(size, 1.), 1u);
  for(const T& t : triangles)
    EXPECT_TRUE(std::find(t.begin(), t.end(), r) == t.end()) << "r is gone";
  EXPECT_TRUE(std::any_of(triangles.begin(), triangles.end(), [&](const T& t) { return std::find(t.begin(), t.end(), s1) != t.end(); }));
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

TEST(SurfaceDistance, PlacesBeyondTheBoundBothWays)
{
  // The input: a 2 x 1 rectangle folded along x = 1 into a ridge of height d (4 triangles). The
  // output: the flat rectangle under it (2 triangles). The ridge's vertices stand d from the
  // output, the output's face centroids about 2d/3 from the input.
  typedef K::Point_3 P;
  const double d = 0.1;
  Mesh ridge, flat;
  const auto r00 = ridge.add_vertex(P(0, 0, 0)), r10 = ridge.add_vertex(P(1, 0, d)), r20 = ridge.add_vertex(P(2, 0, 0));
  const auto r01 = ridge.add_vertex(P(0, 1, 0)), r11 = ridge.add_vertex(P(1, 1, d)), r21 = ridge.add_vertex(P(2, 1, 0));
  ridge.add_face(r00, r10, r11);
  ridge.add_face(r00, r11, r01);
  ridge.add_face(r10, r20, r21);
  ridge.add_face(r10, r21, r11);
  const auto f00 = flat.add_vertex(P(0, 0, 0)), f20 = flat.add_vertex(P(2, 0, 0));
  const auto f21 = flat.add_vertex(P(2, 1, 0)), f01 = flat.add_vertex(P(0, 1, 0));
  flat.add_face(f00, f20, f21);
  flat.add_face(f00, f21, f01);
  const CR::internal::Distance_to_surface to_ridge(ridge);

  const RM::Places_beyond_distance far = RM::places_beyond_distance<CGAL::Sequential_tag>(ridge, to_ridge, flat, 0.06, 0.25);
  EXPECT_NEAR(far.largest, d, 1e-12);
  EXPECT_NEAR(far.farthest.x(), 1., 1e-12) << far.farthest; // on the ridge
  EXPECT_NEAR(far.farthest.z(), d, 1e-12) << far.farthest;
  EXPECT_EQ(far.output_faces, 2u);
  EXPECT_EQ(far.input_vertices, 2u);  // the ridge's
  EXPECT_EQ(far.input_faces, 4u);     // each has a corner on the ridge
  EXPECT_GE(far.input_edges, 3u);     // the ridge and the sides along the x axis, at least
  // The places: where the distance exceeds 0.06 (within 0.4 of the ridge), and along the whole of
  // each input edge beyond the bound, so all along the ridge.
  ASSERT_FALSE(far.places.empty());
  const auto on_an_edge_to_the_ridge = [&](const P& p) {
    for(const P& r : {P(1, 0, d), P(1, 1, d)})
      for(const P& q : {P(0, 0, 0), P(2, 0, 0), P(0, 1, 0), P(2, 1, 0), P(1, 0, d), P(1, 1, d)})
        if(q != r && CGAL::squared_distance(K::Segment_3(r, q), p) < 1e-20)
          return true;
    return false;
  };
  for(const P& p : far.places)
    EXPECT_TRUE(std::abs(p.x() - 1.) < 0.4 || on_an_edge_to_the_ridge(p)) << p;
  // Thinned to one per cell a quarter wide, they cover the ridge from end to end.
  for(double y = 0.; y <= 1.; y += 0.125)
  {
    double nearest = 1.;
    for(const P& p : far.places)
      nearest = (std::min)(nearest, CGAL::squared_distance(p, P(1, y, d)));
    EXPECT_LT(nearest, 0.75 * 0.25 * 0.25) << y; // within a cell's diagonal
  }
  for(std::size_t i = 0; i < far.places.size(); ++i)
    for(std::size_t j = 0; j < i; ++j)
      EXPECT_GT(CGAL::squared_distance(far.places[i], far.places[j]), 0.) << "thinned to one per cell";

  // A bound above the ridge's height: nothing beyond, the largest distance still found.
  const RM::Places_beyond_distance none = RM::places_beyond_distance<CGAL::Sequential_tag>(ridge, to_ridge, flat, 0.11, 0.25);
  EXPECT_TRUE(none.places.empty());
  EXPECT_EQ(none.output_faces + none.input_vertices + none.input_edges + none.input_faces, 0u);
  EXPECT_NEAR(none.largest, d, 1e-12);

  // The same surface both ways: nothing beyond any bound.
  const CR::internal::Distance_to_surface to_flat(flat);
  const RM::Places_beyond_distance same = RM::places_beyond_distance<CGAL::Sequential_tag>(flat, to_flat, flat, 1e-9, 0.25);
  EXPECT_TRUE(same.places.empty());
  EXPECT_LT(same.largest, 1e-12);
}

TEST(SurfaceDistance, TheInputsSurfaceIsAskedForOnceAndGivesWhatAPrebuiltOneGives)
{
  // A bumpy input (a grid with every other vertex raised) over the same grid flat, the output:
  // places both ways.
  typedef K::Point_3 P;
  const int n = 6;
  const auto grid = [&](double bump) {
    Mesh m;
    std::vector<Mesh::Vertex_index> v;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
        v.push_back(m.add_vertex(P(i, j, (i + j) % 2 == 0 ? 0. : bump * (1. + 0.01 * i))));
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        const Mesh::Vertex_index a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1];
        const Mesh::Vertex_index c = v[(j + 1) * (n + 1) + i], d = v[(j + 1) * (n + 1) + i + 1];
        m.add_face(a, b, d);
        m.add_face(a, d, c);
      }
    return m;
  };
  const Mesh bumpy = grid(0.6), flat = grid(0.);

  const CR::internal::Distance_to_surface prebuilt(bumpy);
  const RM::Places_beyond_distance expected = RM::places_beyond_distance<CGAL::Sequential_tag>(bumpy, prebuilt, flat, 0.1, 0.5);
  int asked = 0;
  std::unique_ptr<CR::internal::Distance_to_surface> built;
  const auto on_demand = [&]() -> const CR::internal::Distance_to_surface& {
    ++asked;
    built = std::make_unique<CR::internal::Distance_to_surface>(bumpy);
    return *built;
  };
  const RM::Places_beyond_distance found = RM::places_beyond_distance<CGAL::Sequential_tag>(bumpy, on_demand, flat, 0.1, 0.5);
  EXPECT_EQ(asked, 1);
  ASSERT_FALSE(expected.places.empty());
  EXPECT_GT(expected.output_faces, 0u);
  EXPECT_GT(expected.input_vertices, 0u);
  EXPECT_EQ(found.places, expected.places); // the same places in the same order
  EXPECT_EQ(found.largest, expected.largest);
  EXPECT_EQ(found.farthest, expected.farthest);
  EXPECT_EQ(found.output_faces, expected.output_faces);
  EXPECT_EQ(found.input_vertices, expected.input_vertices);
  EXPECT_EQ(found.input_edges, expected.input_edges);
  EXPECT_EQ(found.input_faces, expected.input_faces);
}

TEST(SurfaceDistance, HintsFromEveryEighthCoverTriangleFindTheClosestPointsOfAllFaces)
{
  // A CAD-like plate (fans of slivers) and, far from it, a disc of slivers: the queries in spatial
  // order jump from one to the other, and start from hints taken on an eighth of the cover.
  Mesh surface;
  bm::make_perforated_plate(surface, bm::Perforated_plate_parameters());
  Mesh disc;
  bm::make_sliver_fan_disc(disc, 64, 3.);
  for(Mesh::Vertex_index v : disc.vertices())
    disc.point(v) = disc.point(v) + K::Vector_3(40., -25., 7.);
  CGAL::copy_face_graph(disc, surface);
  ASSERT_EQ(CGAL::Polygon_mesh_processing::connected_components(
              surface, surface.add_property_map<Mesh::Face_index, std::size_t>("f:component").first),
            2u);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(surface);
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> x(box.xmin() - 5., box.xmax() + 5.), y(box.ymin() - 5., box.ymax() + 5.),
    z(box.zmin() - 5., box.zmax() + 5.);
  std::vector<CR::internal::Distance_to_surface::Fast::Point_3> queries;
  for(int i = 0; i < 3000; ++i)
    queries.emplace_back(x(generator), y(generator), z(generator));
  for(Mesh::Vertex_index v : surface.vertices()) // and points on the surface, at distance 0
    queries.emplace_back(surface.point(v).x(), surface.point(v).y(), surface.point(v).z());

  const CR::internal::Distance_to_surface to_surface(surface);
  const std::vector<double> found = to_surface.squared_distances<CGAL::Sequential_tag>(queries);
  ASSERT_EQ(found.size(), queries.size());
  for(std::size_t i = 0; i < queries.size(); ++i)
  {
    const K::Point_3 q(queries[i].x(), queries[i].y(), queries[i].z());
    double nearest = std::numeric_limits<double>::infinity();
    for(Mesh::Face_index f : surface.faces())
    {
      const Mesh::Halfedge_index h = surface.halfedge(f);
      const K::Triangle_3 t(surface.point(surface.source(h)), surface.point(surface.target(h)),
                            surface.point(surface.target(surface.next(h))));
      nearest = (std::min)(nearest, CGAL::squared_distance(q, t));
    }
    EXPECT_NEAR(std::sqrt(found[i]), std::sqrt(nearest), 1e-9 * (1. + std::sqrt(nearest))) << q;
  }
}

TEST(SurfaceDistance, ARoundIsKeptWhenItsLargestDistanceOrItsCountBeyondFalls)
{
  // The output before the round: largest distance 2, three elements beyond the bound.
  CGAL::Conformal_remeshing::Remeshing_report before;
  before.largest_surface_distance = 2.;
  before.output_faces_beyond_surface_distance = 1;
  before.input_edges_beyond_surface_distance = 2;
  RM::Places_beyond_distance after;
  after.largest = 1.5; // closer at its farthest, though with more elements beyond
  after.input_faces = 5;
  EXPECT_TRUE(RM::brought_closer(after, before));
  after.largest = 3.; // farther at its farthest, but only two elements beyond
  after.input_faces = 0;
  after.input_vertices = 2;
  EXPECT_TRUE(RM::brought_closer(after, before));
  after.input_vertices = 3; // as far and as many: no closer
  after.largest = 2.;
  EXPECT_FALSE(RM::brought_closer(after, before));
  after.largest = 2.5; // farther, and as many
  EXPECT_FALSE(RM::brought_closer(after, before));
}

TEST(SurfaceDistance, PlacesStillTooFarAreRefinedFurther)
{
  // A place near an earlier one gets half its size; a place far from all earlier ones, half the
  // target.
  typedef K::Point_3 P;
  RM::Distance_refinement refinement(1., 0.5);
  refinement.add({P(0, 0, 0), P(10, 0, 0)});
  refinement.add({P(0.3, 0, 0), P(5, 0, 0)});
  refinement.add({P(0.1, 0, 0)});
  const RM::Local_refinement& places = refinement.places();
  ASSERT_EQ(places.points.size(), 5u);
  EXPECT_EQ(places.sizes, (std::vector<double>{0.5, 0.5, 0.25, 0.5, 0.125}));
  EXPECT_DOUBLE_EQ(places.at(P(0.1, 0, 0)), 0.125);
  EXPECT_DOUBLE_EQ(places.at(P(10, 2, 0)), 0.5 + 0.5 * 2.);
}
