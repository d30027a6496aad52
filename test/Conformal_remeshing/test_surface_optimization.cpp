// The optimization of a patch on the surface: flips, moves, splits, collapses and angle passes
// judged on the surface, not in the plane.

#include "stage_tests.h"

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
  // The bar of 0.12 is for whole remeshings (checked in remeshing_checks.h); on this small
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
