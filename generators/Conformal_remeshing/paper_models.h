// Copyright (c) 2026 The CGAL Conformal Remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CAD-like parts at the scales of the paper's Table 1 (suspension arm, shield, radiator shell,
// chassis, genus-83 brake disc and its two halves), tessellated as CAD exporters do with the
// building blocks of cad_like_models.h: planar faces fanned from their boundary vertices only,
// walls, bends and fillets as strips. Each family has a size knob (the target number of
// vertices, from about 10k to millions) and is deterministic from a seed.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_MODELS_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_MODELS_H

#include "cad_like_models.h"

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// A closed curve of circular arcs joined by their common tangent segments, running
/// counterclockwise around the region it bounds: the outlines of CAD parts (rounded polygons,
/// circles, slots, thickened polylines). Each corner is a circle: `radius > 0` an arc turning
/// left (convex), `radius < 0` an arc turning right (concave, centre outside the region),
/// `radius == 0` a sharp corner at the centre.
///
/// Moving the curve outward by `offset` adds `offset` to every radius and keeps the tangent
/// directions, hence the number of samples: copies of a loop at several offsets (the levels of
/// a fillet) can be joined point by point.
class Rounded_loop
{
public:
  struct Corner
  {
    double x = 0.;
    double y = 0.;
    double radius = 0.;
  };

  Rounded_loop() = default;

  /// Throws `std::invalid_argument` unless the corners make a counterclockwise loop whose
  /// consecutive circles have a common tangent (at least two corners; see `circle()`).
  explicit Rounded_loop(std::vector<Corner> corners) : corners_(std::move(corners))
  {
    const std::size_t n = corners_.size();
    if(n < 2)
      throw std::invalid_argument("rounded loop: needs two corners (or use circle())");
    for(const Corner& c : corners_)
      if(!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.radius))
        throw std::invalid_argument("rounded loop: non-finite corner");
    // Outward normal of the tangent segment from corner i to corner i + 1: with n that normal,
    // the segment runs from c_i + r_i n to c_j + r_j n, so (c_j - c_i) . n = r_i - r_j.
    for(std::size_t i = 0; i < n; ++i) {
      const Corner &a = corners_[i], &b = corners_[(i + 1) % n];
      const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy), k = a.radius - b.radius;
      if(!(length > std::abs(k) * (1. + 1e-12)))
        throw std::invalid_argument("rounded loop: corners " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                                    " have no common tangent (too close for their radii)");
      const double ux = dx / length, uy = dy / length, c = k / length, s = std::sqrt(1. - c * c);
      normal_.push_back({c * ux + s * uy, c * uy - s * ux});
    }
    double total = 0.;
    for(std::size_t i = 0; i < n; ++i) {
      const std::array<double, 2> &in = normal_[(i + n - 1) % n], &out = normal_[i];
      double turn = std::atan2(in[0] * out[1] - in[1] * out[0], in[0] * out[0] + in[1] * out[1]);
      if(corners_[i].radius > 0. && turn <= 0.)
        turn += 2. * CGAL_PI;
      else if(corners_[i].radius < 0. && turn >= 0.)
        turn -= 2. * CGAL_PI;
      if(std::abs(turn) < 1e-9 || (corners_[i].radius == 0. && std::abs(turn) > CGAL_PI - 1e-9))
        throw std::invalid_argument("rounded loop: corner " + std::to_string(i) + " does not turn (or is a spike)");
      turn_.push_back(turn);
      total += turn;
    }
    if(std::abs(total - 2. * CGAL_PI) > 1e-6)
      throw std::invalid_argument("rounded loop: the corners do not make one counterclockwise turn");
  }

  static Rounded_loop circle(double x, double y, double radius)
  {
    if(!(radius > 0.) || !std::isfinite(radius) || !std::isfinite(x) || !std::isfinite(y))
      throw std::invalid_argument("rounded loop: a circle needs a finite centre and a positive radius");
    Rounded_loop loop;
    loop.corners_.push_back({x, y, radius});
    loop.turn_.push_back(2. * CGAL_PI);
    return loop;
  }

  /// The stadium around the segment from (x0, y0) to (x1, y1), at distance `radius`.
  static Rounded_loop slot(double x0, double y0, double x1, double y1, double radius)
  {
    return Rounded_loop({{x0, y0, radius}, {x1, y1, radius}});
  }

  /// The corner rounding the polygon corner `v` (from `p` to `q`) by the arc of radius
  /// `radius` tangent to both sides: convex if the polygon turns left at `v`, concave if it
  /// turns right; sharp with radius 0.
  static Corner fillet(const std::array<double, 2>& p, const std::array<double, 2>& v, const std::array<double, 2>& q,
                       double radius)
  {
    const double l1 = std::hypot(v[0] - p[0], v[1] - p[1]), l2 = std::hypot(q[0] - v[0], q[1] - v[1]);
    const double u1x = (v[0] - p[0]) / l1, u1y = (v[1] - p[1]) / l1, u2x = (q[0] - v[0]) / l2, u2y = (q[1] - v[1]) / l2;
    const double cross = u1x * u2y - u1y * u2x;
    if(!(std::abs(cross) > 1e-9) || !(radius >= 0.))
      throw std::invalid_argument("rounded loop: straight or repeated polygon vertex, or negative radius");
    // The centre lies on the bisector of the corner's opening, at radius / sin(opening / 2).
    const double bx = u2x - u1x, by = u2y - u1y, b = std::hypot(bx, by);
    const double distance = radius / std::sqrt((1. + u1x * u2x + u1y * u2y) / 2.);
    return {v[0] + bx / b * distance, v[1] + by / b * distance, cross > 0. ? radius : -radius};
  }

  /// The counterclockwise polygon `vertices` with corner i rounded by `fillet()` with `radii[i]`.
  static Rounded_loop rounded_polygon(const std::vector<std::array<double, 2> >& vertices, const std::vector<double>& radii)
  {
    const std::size_t n = vertices.size();
    if(n < 3 || radii.size() != n)
      throw std::invalid_argument("rounded polygon: needs three vertices and one radius per vertex");
    std::vector<Corner> corners;
    for(std::size_t i = 0; i < n; ++i)
      corners.push_back(fillet(vertices[(i + n - 1) % n], vertices[i], vertices[(i + 1) % n], radii[i]));
    return Rounded_loop(std::move(corners));
  }

  const std::vector<Corner>& corners() const { return corners_; }

  /// Number of samples with `segments_per_turn` segments per full turn of the arcs.
  /// With `max_straight > 0`, straight parts are split into pieces no longer than that.
  std::size_t size(int segments_per_turn, double max_straight = 0.) const
  {
    if(corners_.size() == 1)
      return std::size_t(segments_per_turn);
    std::size_t count = 0;
    for(std::size_t i = 0; i < corners_.size(); ++i)
      count += (corners_[i].radius == 0. ? 1 : arc_segments(i, segments_per_turn) + 1) + straight_segments(i, max_straight) - 1;
    return count;
  }

  /// Appends the samples of the loop moved outward by `offset` to `points`, counterclockwise:
  /// each arc from its first to its last tangent point, a circle from angle 0; straight parts
  /// are single segments, or pieces no longer than `max_straight` when it is positive (for a
  /// loop placed on a curved surface). `first` (optional) receives each corner's first sample's
  /// index. Throws `std::invalid_argument` if the offset would flip an arc or move a sharp corner.
  void sample(double offset, int segments_per_turn, std::vector<internal::Planar_point>& points,
              std::vector<std::size_t>* first = nullptr, double max_straight = 0.) const
  {
    if(segments_per_turn < 3)
      throw std::invalid_argument("rounded loop: at least 3 segments per turn");
    for(std::size_t i = 0; i < corners_.size(); ++i) {
      const Corner& c = corners_[i];
      if(first)
        first->push_back(points.size());
      if(c.radius == 0.) {
        if(offset != 0.)
          throw std::invalid_argument("rounded loop: cannot offset a sharp corner");
        points.push_back(internal::Planar_point(c.x, c.y));
        add_straight_points(i, offset, max_straight, points);
        continue;
      }
      const double r = c.radius + offset;
      if(!(r * c.radius > 0.))
        throw std::invalid_argument("rounded loop: offset larger than an arc's radius");
      if(corners_.size() == 1) {
        for(int k = 0; k < segments_per_turn; ++k) {
          const std::pair<double, double> u = internal::unit_circle_point(k, segments_per_turn);
          points.push_back(internal::Planar_point(c.x + r * u.first, c.y + r * u.second));
        }
        return;
      }
      // The ends use the tangent normals themselves, so that they lie exactly on the segments.
      const std::array<double, 2> &in = normal_[(i + corners_.size() - 1) % corners_.size()], &out = normal_[i];
      const std::size_t segments = arc_segments(i, segments_per_turn);
      const double start = std::atan2(in[1], in[0]);
      for(std::size_t k = 0; k <= segments; ++k) {
        const double angle = start + turn_[i] * double(k) / double(segments);
        const double ux = k == 0 ? in[0] : k == segments ? out[0] : std::cos(angle);
        const double uy = k == 0 ? in[1] : k == segments ? out[1] : std::sin(angle);
        points.push_back(internal::Planar_point(c.x + r * ux, c.y + r * uy));
      }
      add_straight_points(i, offset, max_straight, points);
    }
  }

private:
  std::vector<Corner> corners_;
  std::vector<std::array<double, 2> > normal_; // of the tangent segment leaving corner i
  std::vector<double> turn_;                   // signed turn of corner i

  // The tangent segment leaving corner i, moved outward by `offset`: its ends.
  std::array<double, 4> straight_part(std::size_t i, double offset) const
  {
    const Corner &a = corners_[i], &b = corners_[(i + 1) % corners_.size()];
    const std::array<double, 2>& n = normal_[i];
    const double ra = a.radius == 0. ? 0. : a.radius + offset, rb = b.radius == 0. ? 0. : b.radius + offset;
    return {{a.x + ra * n[0], a.y + ra * n[1], b.x + rb * n[0], b.y + rb * n[1]}};
  }

  // Pieces of the straight part leaving corner i (its length does not depend on the offset).
  std::size_t straight_segments(std::size_t i, double max_straight) const
  {
    if(!(max_straight > 0.) || corners_.size() == 1)
      return 1;
    const std::array<double, 4> e = straight_part(i, 0.);
    return std::max<std::size_t>(1, std::size_t(std::ceil(std::hypot(e[2] - e[0], e[3] - e[1]) / max_straight - 1e-9)));
  }

  // The points inside the straight part leaving corner i.
  void add_straight_points(std::size_t i, double offset, double max_straight, std::vector<internal::Planar_point>& points) const
  {
    const std::size_t pieces = straight_segments(i, max_straight);
    const std::array<double, 4> e = straight_part(i, offset);
    for(std::size_t k = 1; k < pieces; ++k) {
      const double t = double(k) / double(pieces);
      points.push_back(internal::Planar_point(e[0] + t * (e[2] - e[0]), e[1] + t * (e[3] - e[1])));
    }
  }

  // Segments of arc i: angular tolerance, as CAD exporters use.
  std::size_t arc_segments(std::size_t i, int segments_per_turn) const
  {
    return std::max<std::size_t>(1, std::size_t(std::ceil(std::abs(turn_[i]) / (2. * CGAL_PI) * segments_per_turn - 1e-9)));
  }
};

/// The outline of the region inside `outer` and outside every loop of `holes` (all given
/// counterclockwise around what they bound), each moved by `inset` into the material (a level
/// of a fillet or of a collar) and sampled with `segments_per_turn` segments per full turn.
inline Plate_outline rounded_outline(const Rounded_loop& outer, const std::vector<Rounded_loop>& holes,
                                     double inset, int segments_per_turn, double max_straight = 0.)
{
  Plate_outline outline;
  outer.sample(-inset, segments_per_turn, outline.points, nullptr, max_straight);
  for(std::size_t i = 0; i < outline.points.size(); ++i)
    outline.outer.push_back(i);
  for(const Rounded_loop& hole : holes) {
    const std::size_t first = outline.points.size();
    hole.sample(inset, segments_per_turn, outline.points, nullptr, max_straight);
    std::vector<std::size_t> loop; // clockwise: material on the left
    for(std::size_t i = outline.points.size(); i > first; --i)
      loop.push_back(i - 1);
    outline.hole_loops.push_back(loop);
  }
  return outline;
}

/// What the paper-scale generators take: the size knob and the seed of the random details.
struct Paper_model_parameters
{
  std::size_t target_vertices = 100000; ///< the result has about this many vertices (at least the model's minimum)
  std::uint64_t seed = 1;               ///< seed of the random details (hole sizes, jitter, placement)
};

/// The paper-scale models, their sizes in the paper's Table 1 and their topology.
enum class Paper_model
{
  suspension_arm,
  shield,
  radiator_shell,
  chassis,
  brake_disc,
  brake_disc_upper_half,
  brake_disc_lower_half
};

struct Paper_model_info
{
  Paper_model model;
  const char* name;
  std::size_t paper_vertices; ///< input vertices of the paper's Table 1 (0: not in the table)
  bool closed;
  long genus;
  std::size_t boundary_loops;
  const char* description;
};

namespace internal {

// Shapes and hole counts fixed per model, so that the topology does not depend on the seed.
constexpr int arm_lightening_holes = 4;
constexpr int shield_holes = 15;
constexpr int radiator_columns = 8, radiator_rows = 14, radiator_mounting_holes = 14;
constexpr int chassis_web_holes = 36, chassis_wall_holes = 24, chassis_flange_holes = 40;
constexpr int brake_arms = 41; // two holes each: 82 through-holes plus the hub, genus 83

} // namespace internal

/// Every paper-scale model, in the order of the enum.
inline const std::vector<Paper_model_info>& paper_models()
{
  using namespace internal;
  static const std::vector<Paper_model_info> models = {
    {Paper_model::suspension_arm, "suspension_arm", 87000, true, 3 + arm_lightening_holes, 0,
     "forged wishbone: three bosses with through-holes, a web with lightening holes, filleted edges"},
    {Paper_model::shield, "shield", 134000, false, 0, 1 + shield_holes,
     "open curved shell, C-shaped with a scalloped rim, flanged rim and mounting holes"},
    {Paper_model::radiator_shell, "radiator_shell", 263000, false, 0,
     1 + radiator_columns * radiator_rows + radiator_mounting_holes,
     "open bent sheet with a grid of long louvre slots and mounting holes, edges drawn down"},
    {Paper_model::chassis, "chassis", 338000, true, chassis_web_holes + 2 * chassis_wall_holes + 2 * chassis_flange_holes, 0,
     "hat-section channel with flanges, bends as long strips, holes in every panel"},
    {Paper_model::brake_disc, "brake_disc", 804000, true, 2 * brake_arms + 1, 0,
     "thick annular disc with a hub hole and 82 cross-drilled holes, walls with a mid-plane ring"},
    {Paper_model::brake_disc_upper_half, "brake_disc_upper_half", 0, false, 0, 2 * brake_arms + 2,
     "the brake disc above its mid-plane (its faces are the disc's)"},
    {Paper_model::brake_disc_lower_half, "brake_disc_lower_half", 0, false, 0, 2 * brake_arms + 2,
     "the brake disc below its mid-plane (its faces are the disc's)"}};
  return models;
}

inline const Paper_model_info& paper_model_info(Paper_model model) { return paper_models()[std::size_t(model)]; }

/// The model called `name` (as in `Paper_model_info::name`); throws `std::invalid_argument`.
inline Paper_model paper_model_from_name(const std::string& name)
{
  for(const Paper_model_info& info : paper_models())
    if(name == info.name)
      return info.model;
  throw std::invalid_argument("unknown paper model '" + name + "'");
}

namespace internal {

// The smallest and largest number of segments per turn tried by the size search.
constexpr int min_segments_per_turn = 8, max_segments_per_turn = 1 << 22;

// The number of segments per full turn whose vertex count `count(s)` (non-decreasing in s) is
// closest to `target`, the smallest allowed one if `target` is below its count.
template <class Count>
int segments_for_target(std::size_t target, Count count)
{
  if(target > 100000000)
    throw std::invalid_argument("paper model: more than 10^8 vertices requested");
  int low = min_segments_per_turn, high = max_segments_per_turn;
  if(count(low) >= target)
    return low;
  while(high - low > 1) { // count(low) < target <= count(high)
    const int middle = low + (high - low) / 2;
    (count(middle) < target ? low : high) = middle;
  }
  return target - count(low) <= count(high) - target ? low : high;
}

// Insets and heights, top to bottom, of a fillet of radius `radius` between a face at height
// `top` and a wall below it (inset 0), with `rings` intermediate rings; a quarter circle.
inline void add_fillet_levels(double top, double radius, int rings, std::vector<double>& insets, std::vector<double>& heights)
{
  for(int k = 0; k <= rings + 1; ++k) {
    const std::pair<double, double> u = unit_circle_point(k, 4 * (rings + 1)); // from 0 to a quarter turn
    insets.push_back(radius * (1. - u.second));
    heights.push_back(top - radius * (1. - u.first));
  }
}

// A part described by its outline and levels (see add_layered_part()): `outer`, `holes`, and
// per level its inset into the material and its height.
struct Layered_design
{
  Rounded_loop outer;
  std::vector<Rounded_loop> holes;
  std::vector<double> insets, heights;
  /// > 0 when the part is placed on a curved surface: the first (top) level's face then gets
  /// grid points at this spacing (see add_layered_part()), and no straight part of the outline
  /// is longer
  double curved_cap_spacing = 0.;

  std::size_t vertices(int segments_per_turn) const
  {
    std::size_t per_level = outer.size(segments_per_turn, curved_cap_spacing);
    for(const Rounded_loop& hole : holes)
      per_level += hole.size(segments_per_turn, curved_cap_spacing);
    return per_level * insets.size();
  }

  // The grid points of the curved top face, counted once on a coarse outline: they do not
  // depend on the outline's resolution but near its border.
  std::size_t curved_cap_points() const
  {
    if(!(curved_cap_spacing > 0.))
      return 0;
    std::vector<internal::Planar_point> interior;
    grid_face_triangles(rounded_outline(outer, holes, insets.front(), 64, curved_cap_spacing), curved_cap_spacing, interior);
    return interior.size();
  }

  // Levels `first` to `last` (inclusive), at the size closest to `target_vertices` of the
  // whole design, placed by `place`.
  template <class Point_3, class Place>
  void build(CGAL::Surface_mesh<Point_3>& mesh, std::size_t target_vertices, std::size_t first, std::size_t last,
             bool cap_first, bool cap_last, Place place) const
  {
    const std::size_t grid = curved_cap_points();
    const int segments = segments_for_target(target_vertices, [&](int s) { return vertices(s) + grid; });
    std::vector<Plate_outline> levels;
    std::vector<double> z;
    for(std::size_t k = first; k <= last; ++k) {
      levels.push_back(rounded_outline(outer, holes, insets[k], segments, curved_cap_spacing));
      z.push_back(heights[k]);
    }
    mesh.clear();
    add_layered_part(mesh, levels, z, cap_first, cap_last, place, curved_cap_spacing);
  }

  template <class Point_3>
  void build_closed(CGAL::Surface_mesh<Point_3>& mesh, std::size_t target_vertices) const
  {
    build(mesh, target_vertices, 0, insets.size() - 1, true, true,
          [](double x, double y, double z) { return Point_3(x, y, z); });
  }
};

// A closed slab of thickness `thickness` whose top and bottom edges are filleted with radius
// `fillet` (`rings` intermediate rings each; sharp edges with 0); with `mid_ring`, every wall
// also has a ring at mid-thickness, so that the mid-plane is made of edges.
inline void set_filleted_slab_levels(Layered_design& design, double thickness, double fillet, int rings, bool mid_ring)
{
  if(fillet > 0.)
    add_fillet_levels(thickness, fillet, rings, design.insets, design.heights);
  else {
    design.insets.push_back(0.);
    design.heights.push_back(thickness);
  }
  if(mid_ring) {
    design.insets.push_back(0.);
    design.heights.push_back(thickness / 2.);
  }
  const std::size_t top = design.insets.size() - (mid_ring ? 1 : 0);
  for(std::size_t k = top; k-- > 0;) { // the bottom fillet mirrors the top one
    design.insets.push_back(design.insets[k]);
    design.heights.push_back(thickness - design.heights[k]);
  }
}

// Uniform double in [low, high) from the generator (see unit_random()).
inline double uniform(std::mt19937_64& generator, double low, double high)
{
  return low + (high - low) * unit_random(generator);
}

inline Layered_design suspension_arm_design(std::uint64_t seed)
{
  std::mt19937_64 generator(seed);
  Layered_design d;
  // Three bosses (two pivots and the ball joint) joined by slightly concave edges.
  d.outer = Rounded_loop({{0., 0., 32.},          // front pivot
                          {190., -285., -300.},   // lower edge
                          {380., 60., 26.},       // ball joint
                          {250., 330., -150.},    // upper edge
                          {70., 260., 30.},       // rear pivot
                          {-110., 130., -130.}}); // inner edge
  auto jitter = [&](double amplitude) { return uniform(generator, -amplitude, amplitude); };
  d.holes = {Rounded_loop::circle(0., 0., 15. + jitter(1.)), Rounded_loop::circle(380., 60., 11. + jitter(1.)),
             Rounded_loop::circle(70., 260., 14. + jitter(1.))};
  // Lightening holes in the web: two rounded triangles and two slots.
  d.holes.push_back(Rounded_loop::rounded_polygon({{{45. + jitter(3.), 40.}, {165. + jitter(3.), 40.}, {75., 150. + jitter(3.)}}},
                                                  {10., 10., 10.}));
  d.holes.push_back(Rounded_loop::rounded_polygon({{{200., 48. + jitter(3.)}, {300. + jitter(3.), 64.}, {215., 140. + jitter(3.)}}},
                                                  {9., 9., 9.}));
  d.holes.push_back(Rounded_loop::slot(60., 195., 80., 165., 7. + jitter(0.5)));
  d.holes.push_back(Rounded_loop::slot(100., 180., 150., 140., 6. + jitter(0.5)));
  set_filleted_slab_levels(d, 24., 3., 1, false);
  return d;
}

inline Layered_design brake_disc_design(std::uint64_t seed)
{
  std::mt19937_64 generator(seed);
  auto jitter = [&](double amplitude) { return uniform(generator, -amplitude, amplitude); };
  Layered_design d;
  d.outer = Rounded_loop::circle(0., 0., 170.);
  d.holes.push_back(Rounded_loop::circle(0., 0., 80.)); // the hub
  // Cross-drilled holes on two staggered rings, slightly irregular.
  for(int k = 0; k < brake_arms; ++k)
    for(int ring = 0; ring < 2; ++ring) {
      const double angle = 2. * CGAL_PI * (k + 0.5 * ring + jitter(0.04)) / brake_arms;
      const double radius = 112. + 30. * ring + jitter(1.5);
      d.holes.push_back(Rounded_loop::circle(radius * std::cos(angle), radius * std::sin(angle), 5. + jitter(0.3)));
    }
  set_filleted_slab_levels(d, 28., 0., 0, true); // drilled: sharp edges, walls of two bands
  return d;
}

inline Layered_design shield_design(std::uint64_t seed)
{
  std::mt19937_64 generator(seed);
  auto jitter = [&](double amplitude) { return uniform(generator, -amplitude, amplitude); };
  auto polar = [](double radius, double degrees) {
    const double a = degrees * CGAL_PI / 180.;
    return std::array<double, 2>{{radius * std::cos(a), radius * std::sin(a)}};
  };
  // A C around the wheel, open towards +x: the outer edge scalloped (alternate tips and
  // notches), the inner edge faceted, both strongly concave.
  std::vector<std::array<double, 2> > vertices;
  std::vector<double> radii;
  for(int k = 0; k <= 18; ++k) {
    vertices.push_back(polar(k % 2 == 0 ? 300. : 262., 45. + 15. * k));
    radii.push_back(k == 0 || k == 18 ? 10. : k % 2 == 0 ? 14. : 22.);
  }
  for(int k = 18; k >= 0; --k) {
    vertices.push_back(polar(170., 45. + 15. * k));
    radii.push_back(k == 0 || k == 18 ? 10. : 40.);
  }
  Layered_design d;
  d.outer = Rounded_loop::rounded_polygon(vertices, radii);
  for(int k = 0; k < 9; ++k) { // mounting holes
    const double radius = 205. + jitter(4.), angle = 60. + 30. * k + jitter(3.);
    const std::array<double, 2> c = polar(radius, angle);
    d.holes.push_back(Rounded_loop::circle(c[0], c[1], 7. + jitter(1.)));
  }
  for(int k = 0; k < 6; ++k) { // clip slots, across the radius
    const double angle = 75. + 45. * k + jitter(4.);
    const std::array<double, 2> a = polar(232., angle), b = polar(250., angle);
    d.holes.push_back(Rounded_loop::slot(a[0], a[1], b[0], b[1], 4. + jitter(0.5)));
  }
  add_fillet_levels(0., 4., 1, d.insets, d.heights); // every boundary ends in a collar bent down
  return d;
}

inline Layered_design radiator_shell_design(std::uint64_t seed)
{
  std::mt19937_64 generator(seed);
  auto jitter = [&](double amplitude) { return uniform(generator, -amplitude, amplitude); };
  Layered_design d;
  d.outer = Rounded_loop::rounded_polygon({{{-500., -280.}, {500., -280.}, {500., 280.}, {-500., 280.}}}, {40., 40., 40., 40.});
  for(int row = 0; row < radiator_rows; ++row) // louvres: a grid of long slots of random lengths
    for(int column = 0; column < radiator_columns; ++column) {
      const double x = -402.5 + 115. * column + jitter(2.), y = -221. + 34. * row, half = 42. + jitter(4.);
      d.holes.push_back(Rounded_loop::slot(x - half, y, x + half, y, 3.));
    }
  for(int k = 0; k < radiator_mounting_holes; ++k)
    d.holes.push_back(Rounded_loop::circle(-450. + 150. * (k % 7) + jitter(5.), k < 7 ? -255. : 255., 6.));
  add_fillet_levels(0., 3., 0, d.insets, d.heights); // edges drawn down by 45-degree collars
  return d;
}

// A thin-walled channel along x whose cross-section (in the yz-plane) is the polyline
// `midline` thickened by `thickness`, its inner points bent with radius `bend`; the straight
// part of each segment is a panel (two parallel faces) with `holes[j]`, circles in the panel's
// coordinates (centred; x along the segment, y along the channel).
struct Channel_design
{
  std::vector<std::array<double, 2> > midline;
  double bend = 6., thickness = 4., length = 1600.;
  Rounded_loop section;
  std::vector<double> panel_widths;
  std::vector<std::vector<Circular_hole> > holes;

  // The section's corners: the right side of the mid-line forward, tip to tip, then the left
  // side back. Panel j's faces lie between corners j and j + 1 (right side) and between
  // corners 2m - j and 2m + 1 - j (left side), m the number of segments.
  void make_section()
  {
    const std::size_t m = midline.size() - 1;
    std::vector<std::array<double, 2> > direction(m);
    for(std::size_t j = 0; j < m; ++j) {
      const double dx = midline[j + 1][0] - midline[j][0], dy = midline[j + 1][1] - midline[j][1], l = std::hypot(dx, dy);
      direction[j] = {{dx / l, dy / l}};
    }
    const double h = thickness / 2.;
    auto tip = [&](std::size_t point, std::size_t segment, double side) { // side +1: right
      const std::array<double, 2>& u = direction[segment];
      return Rounded_loop::Corner{midline[point][0] + side * h * u[1], midline[point][1] - side * h * u[0], 0.};
    };
    // Bend j, on the right side (its radius grows by h) or the left one (its turn reverses).
    auto bend_corner = [&](std::size_t j, double side) {
      Rounded_loop::Corner c = Rounded_loop::fillet(midline[j - 1], midline[j], midline[j + 1], bend);
      c.radius = side * c.radius + h;
      return c;
    };
    std::vector<Rounded_loop::Corner> corners{tip(0, 0, 1.)};
    for(std::size_t j = 1; j < m; ++j)
      corners.push_back(bend_corner(j, 1.));
    corners.push_back(tip(m, m - 1, 1.));
    corners.push_back(tip(m, m - 1, -1.));
    for(std::size_t j = m - 1; j >= 1; --j)
      corners.push_back(bend_corner(j, -1.));
    corners.push_back(tip(0, 0, -1.));
    section = Rounded_loop(std::move(corners));
  }

  // Panel j's face on one side: the section samples where it starts and ends (in the
  // direction of the mid-line), given each corner's first sample.
  std::pair<std::size_t, std::size_t> panel_ends(std::size_t j, bool right, const std::vector<std::size_t>& first,
                                                 std::size_t samples) const
  {
    const std::size_t m = midline.size() - 1;
    auto last = [&](std::size_t corner) { return (corner + 1 < first.size() ? first[corner + 1] : samples) - 1; };
    if(right)
      return {last(j), first[j + 1]};
    return {first[2 * m + 1 - j], last(2 * m - j)};
  }

  std::size_t vertices(int segments_per_turn) const
  {
    std::size_t count = 2 * section.size(segments_per_turn);
    for(const std::vector<Circular_hole>& panel : holes)
      count += 2 * panel.size() * std::size_t(segments_per_turn);
    return count;
  }

  Perforated_plate_parameters panel(std::size_t j, int segments_per_turn) const
  {
    Perforated_plate_parameters p;
    p.length = panel_widths[j];
    p.width = length;
    p.thickness = thickness;
    p.corner_radius = 0.;
    p.segments_per_circle = segments_per_turn;
    p.holes = holes[j];
    p.min_clearance = 2.; // only checked: the holes were placed with more
    return p;
  }
};

inline Channel_design chassis_design(std::uint64_t seed)
{
  Channel_design d;
  // A hat section: flange, wall, web, wall, flange.
  d.midline = {{{-95., 0.}}, {{-55., 0.}}, {{-40., 80.}}, {{40., 80.}}, {{55., 0.}}, {{95., 0.}}};
  d.make_section();
  std::vector<internal::Planar_point> samples; // the panels' ends do not depend on the sampling
  std::vector<std::size_t> first;
  d.section.sample(0., min_segments_per_turn, samples, &first);
  std::mt19937_64 generator(seed);
  for(std::size_t j = 0; j + 1 < d.midline.size(); ++j) {
    const std::pair<std::size_t, std::size_t> right = d.panel_ends(j, true, first, samples.size());
    d.panel_widths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(samples[right.first], samples[right.second]))));
    d.holes.emplace_back();
    Perforated_plate_parameters p = d.panel(j, min_segments_per_turn); // no holes yet: random ones
    const bool web = j == 2, flange = j == 0 || j == 4;
    p.number_of_random_holes = web ? chassis_web_holes : flange ? chassis_flange_holes : chassis_wall_holes;
    p.min_hole_radius = web ? 6. : flange ? 2.5 : 4.;
    p.max_hole_radius = web ? 20. : flange ? 4.5 : 12.;
    p.min_clearance = web ? 5. : 3.;
    p.seed = generator();
    d.holes.back() = perforated_plate_holes(p);
  }
  return d;
}

} // namespace internal

/// A forged suspension wishbone (the paper's Fig. 7, 87k vertices): three bosses with
/// through-holes joined by a web with four lightening holes, 24 mm thick, every edge filleted
/// (strips of two bands). Closed, genus 7. `mesh` is cleared first.
template <class Point_3>
void make_suspension_arm(CGAL::Surface_mesh<Point_3>& mesh, const Paper_model_parameters& p)
{
  internal::suspension_arm_design(p.seed).build_closed(mesh, p.target_vertices);
}

/// A cross-drilled brake disc (the paper's Fig. 9, 804k vertices): an annulus of radii 80 and
/// 170 mm, 28 mm thick, with 82 through-holes on two staggered rings, sharp edges. Closed,
/// genus 83. Every wall (rims and holes) has a vertex ring at mid-thickness, so that the
/// mid-plane cut is a set of edges: see `make_brake_disc_half()`. `mesh` is cleared first.
template <class Point_3>
void make_brake_disc(CGAL::Surface_mesh<Point_3>& mesh, const Paper_model_parameters& p)
{
  internal::brake_disc_design(p.seed).build_closed(mesh, p.target_vertices);
}

/// One half of `make_brake_disc()`'s disc cut by its mid-plane (the upper one with `upper`):
/// exactly the disc's triangles on that side, with the same vertex positions. It is sized like
/// the whole disc, so it has two thirds of its vertices (a face's ring and the mid ring of
/// every wall). Open, genus 0, 84 boundary loops (the mid-plane sections of the rim, the hub
/// and the 82 holes).
template <class Point_3>
void make_brake_disc_half(CGAL::Surface_mesh<Point_3>& mesh, const Paper_model_parameters& p, bool upper)
{
  const internal::Layered_design d = internal::brake_disc_design(p.seed);
  const std::size_t mid = d.insets.size() / 2;
  d.build(mesh, p.target_vertices, upper ? 0 : mid, upper ? mid : d.insets.size() - 1, upper, !upper,
          [](double x, double y, double z) { return Point_3(x, y, z); });
}

/// A tire shield (the paper's Fig. 2, 134k vertices): an open, curved thin shell shaped like a
/// C of 270 degrees around the wheel (radii 170 to 300 mm) with a scalloped outer edge and a
/// faceted inner edge, so strongly concave; 9 mounting holes and 6 clip slots; every boundary
/// ends in a collar bent down (strips of two bands). The face is a dome, a height field over
/// its triangulation, so the sheet cannot intersect itself; being curved, the face is not fanned
/// but has interior points every 18 mm (chords within 0.1 mm of the dome). Open, genus 0, 16 boundary
/// loops. `mesh` is cleared first.
template <class Point_3>
void make_shield(CGAL::Surface_mesh<Point_3>& mesh, const Paper_model_parameters& p)
{
  internal::Layered_design d = internal::shield_design(p.seed);
  d.curved_cap_spacing = internal::cad_curved_face_spacing(420.); // z'' = 2 / 840
  d.build(mesh, p.target_vertices, 0, d.insets.size() - 1, true, false, [](double x, double y, double z) {
    return Point_3(x, y, z - (x * x + y * y) / 840. + 0.15 * y);
  });
}

/// A radiator shell (the paper's Fig. 8, 263k vertices): an open 1000 x 560 mm sheet, bent
/// around the y axis, with a grid of 8 x 14 long louvre slots of random lengths and 14 mounting
/// holes, every boundary drawn down by a 3 mm collar at 45 degrees (a strip of one band). A
/// height field over its triangulation, so the sheet cannot intersect itself; being curved, the
/// face has interior points every 27 mm (chords within 0.1 mm). Open, genus 0,
/// 127 boundary loops. `mesh` is cleared first.
template <class Point_3>
void make_radiator_shell(CGAL::Surface_mesh<Point_3>& mesh, const Paper_model_parameters& p)
{
  internal::Layered_design d = internal::radiator_shell_design(p.seed);
  d.curved_cap_spacing = internal::cad_curved_face_spacing(900.); // z'' = 2 / 1800 along x
  d.build(mesh, p.target_vertices, 0, d.insets.size() - 1, true, false, [](double x, double y, double z) {
    return Point_3(x, y, z + x * x / 1800. + y * y / 8000.);
  });
}

/// A chassis rail (the paper's Fig. 6, 338k vertices): a 1600 mm channel of hat section
/// (flanges, walls and web, 4 mm thick, bent with radius 6 mm) with 36 holes in the web, 24 in
/// each wall and 40 in each flange, placed at random. Each panel face is one planar face
/// fanned from its four corners and its holes, bends are long strips spanning the whole length,
/// the two ends are the fanned cross-section. Closed, genus 164. `mesh` is cleared first.
template <class Point_3>
void make_chassis(CGAL::Surface_mesh<Point_3>& mesh, const Paper_model_parameters& p)
{
  typedef typename CGAL::Surface_mesh<Point_3>::Vertex_index Vertex_index;
  const internal::Channel_design d = internal::chassis_design(p.seed);
  const int segments = internal::segments_for_target(p.target_vertices, [&](int s) { return d.vertices(s); });

  Plate_outline section;
  std::vector<std::size_t> first;
  d.section.sample(0., segments, section.points, &first);
  const std::size_t n = section.points.size();
  for(std::size_t i = 0; i < n; ++i)
    section.outer.push_back(i);
  mesh.clear();
  std::vector<Vertex_index> start_vertex, end_vertex; // the section at x = 0 and x = length
  for(const internal::Planar_point& q : section.points)
    start_vertex.push_back(mesh.add_vertex(Point_3(0., q.x(), q.y())));
  for(const internal::Planar_point& q : section.points)
    end_vertex.push_back(mesh.add_vertex(Point_3(d.length, q.x(), q.y())));
  // The section is counterclockwise in the yz-plane, so seen from +x.
  internal::add_fan_face(mesh, section, end_vertex, 0, false);
  internal::add_fan_face(mesh, section, start_vertex, n / 2, true);

  std::vector<bool> is_panel(n, false); // section edge i -> i + 1 is a panel's face
  for(std::size_t j = 0; j + 1 < d.midline.size(); ++j) {
    is_panel[d.panel_ends(j, true, first, n).first] = true; // the left side runs backwards
    is_panel[d.panel_ends(j, false, first, n).second] = true;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(!is_panel[i])
      internal::add_strip_quad(mesh, end_vertex[i], end_vertex[(i + 1) % n], start_vertex[i], start_vertex[(i + 1) % n]);

  for(std::size_t j = 0; j + 1 < d.midline.size(); ++j) {
    // The panel's frame: its outline's x along the segment (from the mid-thickness point
    // (ay, az) of its start), its y along the channel, its z along the right side's normal.
    const std::pair<std::size_t, std::size_t> right = d.panel_ends(j, true, first, n), left = d.panel_ends(j, false, first, n);
    const internal::Planar_point &a_right = section.points[right.first], &a_left = section.points[left.first];
    const double ay = (a_right.x() + a_left.x()) / 2., az = (a_right.y() + a_left.y()) / 2.;
    const double half = d.thickness / 2., ny = (a_right.x() - ay) / half, nz = (a_right.y() - az) / half;
    const double dy = -nz, dz = ny; // the segment's direction: the normal turned left
    const Plate_outline outline = perforated_plate_outline(d.panel(j, segments));
    const double hx = d.panel_widths[j] / 2., hy = d.length / 2.;
    std::vector<Vertex_index> top(outline.points.size()), bottom(outline.points.size());
    // The outline's corners (hx, -hy), (hx, hy), (-hx, hy), (-hx, -hy) are the section's
    // samples at the segment's end and start, at both ends of the channel.
    for(bool is_top : {true, false}) {
      const std::pair<std::size_t, std::size_t>& ends = is_top ? right : left;
      std::vector<Vertex_index>& face = is_top ? top : bottom;
      face[0] = start_vertex[ends.second], face[1] = end_vertex[ends.second];
      face[2] = end_vertex[ends.first], face[3] = start_vertex[ends.first];
    }
    for(std::size_t i = 4; i < outline.points.size(); ++i) {
      const double s = outline.points[i].x() + hx, x = outline.points[i].y() + hy;
      for(double side : {1., -1.}) {
        const Point_3 q(x, ay + s * dy + side * half * ny, az + s * dz + side * half * nz);
        (side > 0. ? top : bottom)[i] = mesh.add_vertex(q);
      }
    }
    internal::add_fan_face(mesh, outline, top, 0, false);
    internal::add_fan_face(mesh, outline, bottom, outline.points.size() / 2, true);
    for(const std::vector<std::size_t>& loop : outline.hole_loops)
      internal::add_strip(mesh, loop, top, bottom);
  }
}

/// Builds `model` (see `paper_models()`) into `mesh`, which is cleared first.
template <class Point_3>
void make_paper_model(CGAL::Surface_mesh<Point_3>& mesh, Paper_model model, const Paper_model_parameters& p)
{
  switch(model) {
    case Paper_model::suspension_arm: make_suspension_arm(mesh, p); break;
    case Paper_model::shield: make_shield(mesh, p); break;
    case Paper_model::radiator_shell: make_radiator_shell(mesh, p); break;
    case Paper_model::chassis: make_chassis(mesh, p); break;
    case Paper_model::brake_disc: make_brake_disc(mesh, p); break;
    case Paper_model::brake_disc_upper_half: make_brake_disc_half(mesh, p, true); break;
    case Paper_model::brake_disc_lower_half: make_brake_disc_half(mesh, p, false); break;
  }
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_MODELS_H
