// Copyright (c) 2026 The CGAL Conformal Remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deterministic generators of CAD-like triangle meshes: planar faces triangulated without
// interior points (fans of slivers, the way CAD exporters tessellate), cylinders as long strips.
// They give the project its default model and test inputs with known topology.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_CAD_LIKE_MODELS_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_CAD_LIKE_MODELS_H

#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_mesher.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// A circular through-hole: centre (`x`, `y`) in the plate's plane and radius.
struct Circular_hole
{
  double x = 0.;
  double y = 0.;
  double radius = 1.;
};

/// Parameters of `make_perforated_plate()`. The plate is centred at the origin, spans
/// `[-length/2, length/2] x [-width/2, width/2]` in the xy-plane and `[0, thickness]` along z.
struct Perforated_plate_parameters
{
  double length = 120.;          ///< size along x
  double width = 80.;            ///< size along y
  double thickness = 6.;         ///< size along z
  double corner_radius = 10.;    ///< fillet radius of the four vertical edges (0: sharp corners)
  int segments_per_circle = 96;  ///< polygon segments of a full circle (holes; a fillet gets a quarter)

  /// Explicit holes. When empty, `number_of_random_holes` holes are placed from `seed`.
  std::vector<Circular_hole> holes;

  int number_of_random_holes = 7;  ///< used only when `holes` is empty
  std::uint64_t seed = 3;          ///< seed of the hole placement (std::mt19937_64)
  double min_hole_radius = 3.;     ///< radius range of the random holes
  double max_hole_radius = 10.;
  double min_clearance = 3.;       ///< minimum material between two holes and between a hole and the rim
  int max_placement_attempts = 100000;  ///< per hole, before the placement is declared impossible
};

/// Statistics of a generated model, as printed by `generate_cad_model`.
struct Cad_model_statistics
{
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t components = 0;
  std::size_t boundary_loops = 0;
  long euler_characteristic = 0;
  long genus = 0;                      ///< (2 - chi - boundary loops) / 2: meaningful for one connected component
  double min_angle_degrees = 0.;       ///< smallest triangle angle
  double share_min_angle_below_10 = 0.; ///< share of triangles whose minimum angle is below 10 degrees
  double share_min_angle_below_1 = 0.;  ///< same, below 1 degree
};

namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Planar_kernel;
typedef Planar_kernel::Point_2 Planar_point;

// cos and sin of a fraction of a full turn, exact at the quarter turns so that straight
// fillet ends and axis-aligned sides are exactly axis-aligned.
inline std::pair<double, double> unit_circle_point(long numerator, long denominator)
{
  long n = numerator % denominator;
  if(n < 0)
    n += denominator;
  if((4 * n) % denominator == 0) {
    switch((4 * n) / denominator) {
      case 0: return {1., 0.};
      case 1: return {0., 1.};
      case 2: return {-1., 0.};
      default: return {0., -1.};
    }
  }
  const double angle = 2. * CGAL_PI * double(n) / double(denominator);
  return {std::cos(angle), std::sin(angle)};
}

// Strictly inside the polygon's interior angle at `v` (interior on the left of prev -> v -> next)?
inline bool strictly_inside_interior_angle(const Planar_point& v, const Planar_point& next,
                                           const Planar_point& prev, const Planar_point& q)
{
  const CGAL::Orientation turn = CGAL::orientation(prev, v, next);
  if(turn == CGAL::LEFT_TURN)
    return CGAL::orientation(v, next, q) == CGAL::LEFT_TURN &&
           CGAL::orientation(v, q, prev) == CGAL::LEFT_TURN;
  if(turn == CGAL::RIGHT_TURN) // reflex: the complement of the closed convex exterior angle
    return !(CGAL::orientation(v, prev, q) != CGAL::RIGHT_TURN &&
             CGAL::orientation(v, q, next) != CGAL::RIGHT_TURN);
  // Straight vertex: the open half-plane on the left. A spike (prev and next in the same
  // direction) cannot occur in the polygons built here; treat it like a straight vertex.
  return CGAL::orientation(v, next, q) == CGAL::LEFT_TURN;
}

/// Triangulates a polygon with holes using only its vertices, the way CAD exporters do:
/// each hole is bridged to the nearest visible vertex of the boundary built so far, and the
/// resulting weakly simple polygon is ear-clipped, continuing from the last ear so that the
/// triangles come in fans. All decisions use exact predicates, so no triangle is flat.
///
/// `points` holds every vertex; `outer` lists the outer loop counterclockwise and each of
/// `holes` a hole clockwise (indices into `points`); `start` picks where the ear clipping
/// begins (modulo the polygon size). Returns counterclockwise triangles.
/// Throws `std::runtime_error` if the input is not a valid polygon with holes.
///
/// The ear test looks for blocking vertices in a uniform grid instead of walking the whole
/// chain: same answers (the grid query is conservative and the exact tests are unchanged), but
/// close to linear time on the large faces of the paper-scale models.
class Fan_triangulator
{
public:
  Fan_triangulator(const std::vector<Planar_point>& points,
                   const std::vector<std::size_t>& outer,
                   const std::vector<std::vector<std::size_t> >& holes)
    : pts_(points), holes_(holes)
  {
    for(std::size_t i = 0; i < outer.size(); ++i)
      push_position(outer[i]);
    link_loop(0, outer.size());
  }

  std::vector<std::array<std::size_t, 3> > run(std::size_t start)
  {
    bridge_holes();
    return clip_ears(start);
  }

private:
  const std::vector<Planar_point>& pts_;
  std::vector<std::vector<std::size_t> > holes_;
  // The chain: a doubly linked list of positions, each naming a vertex (bridge vertices
  // appear twice).
  std::vector<std::size_t> vertex_, next_, prev_;
  std::size_t head_ = 0;
  // During the ear clipping: which positions are still in the chain, the other positions of
  // the same vertex (a cyclic list), and the positions bucketed by a grid over their points.
  std::vector<char> alive_;
  std::vector<std::size_t> twin_next_, twin_prev_;
  double grid_x_ = 0., grid_y_ = 0., cell_ = 1.;
  long columns_ = 1, rows_ = 1;
  std::vector<std::size_t> cell_start_, cell_positions_;

  std::size_t push_position(std::size_t v)
  {
    vertex_.push_back(v);
    next_.push_back(0);
    prev_.push_back(0);
    return vertex_.size() - 1;
  }

  void link_loop(std::size_t first, std::size_t count)
  {
    for(std::size_t i = 0; i < count; ++i) {
      next_[first + i] = first + (i + 1) % count;
      prev_[first + (i + 1) % count] = first + i;
    }
  }

  const Planar_point& at(std::size_t position) const { return pts_[vertex_[position]]; }

  // Chain positions, in chain order from head_.
  std::vector<std::size_t> chain() const
  {
    std::vector<std::size_t> result;
    std::size_t p = head_;
    do {
      result.push_back(p);
      p = next_[p];
    } while(p != head_);
    return result;
  }

  // Does the open segment m-p meet the edge u-w (vertex indices) anywhere but at shared ends?
  bool blocks(std::size_t m, std::size_t p, std::size_t u, std::size_t w) const
  {
    const bool u_shared = (u == m || u == p), w_shared = (w == m || w == p);
    if(u_shared && w_shared)
      return true; // the edge is m-p itself or degenerate: never a valid bridge
    if(u_shared || w_shared) {
      const std::size_t shared = u_shared ? u : w, other = u_shared ? w : u;
      const std::size_t far = (shared == m) ? p : m;
      const Planar_point &s = pts_[shared], &o = pts_[other], &f = pts_[far];
      // Only an overlap along the same ray can hit the segment elsewhere than at `shared`.
      return CGAL::collinear(s, o, f) && (o - s) * (f - s) > 0;
    }
    return CGAL::do_intersect(Planar_kernel::Segment_2(pts_[m], pts_[p]),
                              Planar_kernel::Segment_2(pts_[u], pts_[w]));
  }

  void bridge_holes()
  {
    // Bridging in decreasing order of the holes' largest x guarantees a visible vertex: the
    // ray to +x from a hole's rightmost vertex can only meet already bridged holes.
    std::vector<std::size_t> order(holes_.size());
    for(std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    auto rightmost = [&](std::size_t h) {
      std::size_t best = 0;
      for(std::size_t k = 1; k < holes_[h].size(); ++k) {
        const Planar_point &a = pts_[holes_[h][k]], &b = pts_[holes_[h][best]];
        if(a.x() > b.x() || (a.x() == b.x() && a.y() > b.y()))
          best = k;
      }
      return best;
    };
    std::vector<std::size_t> rightmost_of(holes_.size());
    for(std::size_t h = 0; h < holes_.size(); ++h)
      rightmost_of[h] = rightmost(h);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return pts_[holes_[a][rightmost_of[a]]].x() > pts_[holes_[b][rightmost_of[b]]].x();
    });
    std::vector<bool> bridged(holes_.size(), false);

    for(std::size_t h : order) {
      const std::vector<std::size_t>& hole = holes_[h];
      const std::size_t n = hole.size(), k = rightmost_of[h];
      const std::size_t m = hole[k];
      const Planar_point& M = pts_[m];
      const Planar_point& hole_next = pts_[hole[(k + 1) % n]];
      const Planar_point& hole_prev = pts_[hole[(k + n - 1) % n]];

      // Candidates by increasing distance, ties in chain order: a heap on (distance, rank)
      // pops them in the order of a stable sort, without sorting the whole chain.
      const std::vector<std::size_t> positions = chain();
      std::vector<std::pair<double, std::size_t> > candidates(positions.size());
      for(std::size_t i = 0; i < positions.size(); ++i)
        candidates[i] = {CGAL::to_double(CGAL::squared_distance(M, at(positions[i]))), i};
      const std::greater<std::pair<double, std::size_t> > farther;
      std::make_heap(candidates.begin(), candidates.end(), farther);

      std::size_t chosen = vertex_.size();
      while(!candidates.empty()) {
        std::pop_heap(candidates.begin(), candidates.end(), farther);
        const std::size_t p = positions[candidates.back().second];
        candidates.pop_back();
        if(vertex_[p] == m || at(p) == M)
          continue;
        if(!strictly_inside_interior_angle(at(p), at(next_[p]), at(prev_[p]), M) ||
           !strictly_inside_interior_angle(M, hole_next, hole_prev, at(p)))
          continue;
        bool visible = true;
        for(std::size_t q : positions)
          if(blocks(m, vertex_[p], vertex_[q], vertex_[next_[q]])) { visible = false; break; }
        for(std::size_t g = 0; visible && g < holes_.size(); ++g) {
          if(bridged[g])
            continue;
          for(std::size_t i = 0; i < holes_[g].size(); ++i)
            if(blocks(m, vertex_[p], holes_[g][i], holes_[g][(i + 1) % holes_[g].size()])) {
              visible = false;
              break;
            }
        }
        if(visible) { chosen = p; break; }
      }
      if(chosen == vertex_.size())
        throw std::runtime_error("Fan_triangulator: no visible vertex to bridge a hole");

      // Splice chosen -> m -> (hole loop) -> m -> chosen' -> old next of chosen.
      const std::size_t after = next_[chosen];
      std::size_t last = chosen;
      for(std::size_t i = 0; i <= n; ++i) {
        const std::size_t p = push_position(hole[(k + i) % n]);
        next_[last] = p;
        prev_[p] = last;
        last = p;
      }
      const std::size_t chosen_copy = push_position(vertex_[chosen]);
      next_[last] = chosen_copy;
      prev_[chosen_copy] = last;
      next_[chosen_copy] = after;
      prev_[after] = chosen_copy;
      bridged[h] = true;
    }
  }

  long column_of(double x) const { return std::min(columns_ - 1, std::max(0L, long(std::floor((x - grid_x_) / cell_)))); }
  long row_of(double y) const { return std::min(rows_ - 1, std::max(0L, long(std::floor((y - grid_y_) / cell_)))); }

  // Buckets the chain's positions by a grid of about two cells per position, and links the
  // positions of each vertex.
  void prepare_clipping(const std::vector<std::size_t>& positions)
  {
    alive_.assign(vertex_.size(), 0);
    twin_next_.assign(vertex_.size(), 0);
    twin_prev_.assign(vertex_.size(), 0);
    std::vector<std::size_t> last_of_vertex(pts_.size(), vertex_.size());
    double x_min = at(positions[0]).x(), x_max = x_min, y_min = at(positions[0]).y(), y_max = y_min;
    for(std::size_t p : positions) {
      alive_[p] = 1;
      const std::size_t v = vertex_[p];
      if(last_of_vertex[v] == vertex_.size())
        twin_next_[p] = twin_prev_[p] = p;
      else { // insert after the previous position of v
        const std::size_t q = last_of_vertex[v];
        twin_next_[p] = twin_next_[q];
        twin_prev_[twin_next_[q]] = p;
        twin_next_[q] = p;
        twin_prev_[p] = q;
      }
      last_of_vertex[v] = p;
      x_min = std::min(x_min, at(p).x());
      x_max = std::max(x_max, at(p).x());
      y_min = std::min(y_min, at(p).y());
      y_max = std::max(y_max, at(p).y());
    }
    const double width = x_max - x_min, height = y_max - y_min, count = double(positions.size());
    cell_ = std::max({std::sqrt(width * height / (2. * count)), std::max(width, height) / (2. * count),
                      std::numeric_limits<double>::min()});
    grid_x_ = x_min;
    grid_y_ = y_min;
    columns_ = long(width / cell_) + 1;
    rows_ = long(height / cell_) + 1;
    cell_start_.assign(std::size_t(columns_ * rows_) + 1, 0);
    auto cell_of = [&](std::size_t p) { return std::size_t(row_of(at(p).y()) * columns_ + column_of(at(p).x())); };
    for(std::size_t p : positions)
      ++cell_start_[cell_of(p) + 1];
    for(std::size_t c = 1; c < cell_start_.size(); ++c)
      cell_start_[c] += cell_start_[c - 1];
    cell_positions_.resize(positions.size());
    std::vector<std::size_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for(std::size_t p : positions)
      cell_positions_[fill[cell_of(p)]++] = p;
  }

  void remove_position(std::size_t p)
  {
    alive_[p] = 0;
    twin_next_[twin_prev_[p]] = twin_next_[p];
    twin_prev_[twin_next_[p]] = twin_prev_[p];
  }

  // Calls `stop(position)` on every position bucketed in a cell that the closed triangle ABC
  // may touch, until it returns true; returns whether it did. Each row's x-range is taken over
  // the triangle's part in that row widened by one cell on every side, so rounding cannot miss
  // a cell.
  template <class Stop>
  bool any_position_near(const Planar_point& A, const Planar_point& B, const Planar_point& C, Stop stop) const
  {
    const Planar_point* corner[3] = {&A, &B, &C};
    const long first_row = row_of(std::min({A.y(), B.y(), C.y()}));
    const long last_row = row_of(std::max({A.y(), B.y(), C.y()}));
    for(long r = first_row; r <= last_row; ++r) {
      const double low = grid_y_ + double(r - 1) * cell_, high = grid_y_ + double(r + 2) * cell_;
      double x_low = std::numeric_limits<double>::infinity(), x_high = -x_low;
      for(int e = 0; e < 3; ++e) {
        const Planar_point &P = *corner[e], &Q = *corner[(e + 1) % 3];
        if(std::max(P.y(), Q.y()) < low || std::min(P.y(), Q.y()) > high)
          continue;
        double t0 = 0., t1 = 1.;
        if(P.y() != Q.y()) {
          t0 = std::min(1., std::max(0., (low - P.y()) / (Q.y() - P.y())));
          t1 = std::min(1., std::max(0., (high - P.y()) / (Q.y() - P.y())));
        }
        for(double t : {t0, t1}) {
          const double x = P.x() + t * (Q.x() - P.x());
          x_low = std::min(x_low, x);
          x_high = std::max(x_high, x);
        }
      }
      if(!(x_low <= x_high))
        continue;
      const long first_column = column_of(x_low - cell_), last_column = column_of(x_high + cell_);
      for(long c = first_column; c <= last_column; ++c) {
        const std::size_t cell = std::size_t(r * columns_ + c);
        for(std::size_t i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i)
          if(stop(cell_positions_[i]))
            return true;
      }
    }
    return false;
  }

  // Is the triangle (prev, p, next) an ear of the current chain?
  bool is_ear(std::size_t p) const
  {
    const std::size_t pa = prev_[p], pc = next_[p];
    const std::size_t a = vertex_[pa], b = vertex_[p], c = vertex_[pc];
    const Planar_point &A = pts_[a], &B = pts_[b], &C = pts_[c];
    if(CGAL::orientation(A, B, C) != CGAL::LEFT_TURN)
      return false;
    auto is_corner = [&](std::size_t v) { return v == a || v == b || v == c; };
    // The triangle's angle at each corner, counterclockwise from the first to the second ray.
    auto enters = [&](std::size_t corner, const Planar_point& q) {
      const Planar_point& X = pts_[corner];
      const Planar_point& Y = (corner == a) ? B : (corner == b) ? C : A;
      const Planar_point& Z = (corner == a) ? C : (corner == b) ? A : B;
      return CGAL::orientation(X, Y, q) == CGAL::LEFT_TURN &&
             CGAL::orientation(X, q, Z) == CGAL::LEFT_TURN;
    };
    // Another occurrence of a corner (a bridge end) must not send an edge into the ear.
    for(std::size_t start : {pa, p, pc}) {
      std::size_t q = start;
      do {
        for(std::size_t r : {prev_[q], next_[q]}) {
          const bool ear_edge = (q == pa && r == p) || (q == p && (r == pa || r == pc)) ||
                                (q == pc && r == p);
          if(!ear_edge && !is_corner(vertex_[r]) && enters(vertex_[q], pts_[vertex_[r]]))
            return false;
        }
        q = twin_next_[q];
      } while(q != start);
    }
    // No other vertex in the closed triangle.
    return !any_position_near(A, B, C, [&](std::size_t q) {
      if(!alive_[q] || is_corner(vertex_[q]))
        return false;
      const Planar_point& Q = pts_[vertex_[q]];
      return CGAL::orientation(A, B, Q) != CGAL::RIGHT_TURN &&
             CGAL::orientation(B, C, Q) != CGAL::RIGHT_TURN &&
             CGAL::orientation(C, A, Q) != CGAL::RIGHT_TURN;
    });
  }

  std::vector<std::array<std::size_t, 3> > clip_ears(std::size_t start)
  {
    std::vector<std::array<std::size_t, 3> > triangles;
    std::vector<std::size_t> positions = chain();
    prepare_clipping(positions);
    std::size_t count = positions.size();
    std::size_t p = positions[start % count];
    std::size_t failures = 0;
    while(count > 3) {
      if(is_ear(p)) {
        triangles.push_back({vertex_[prev_[p]], vertex_[p], vertex_[next_[p]]});
        const std::size_t c = next_[p];
        next_[prev_[p]] = c;
        prev_[c] = prev_[p];
        remove_position(p);
        --count;
        p = c; // the next ear shares the previous corner: fans, as CAD exporters make
        failures = 0;
      } else {
        p = next_[p];
        if(++failures > count)
          throw std::runtime_error("Fan_triangulator: no ear found (invalid polygon?)");
      }
    }
    const std::array<std::size_t, 3> last = {vertex_[prev_[p]], vertex_[p], vertex_[next_[p]]};
    if(CGAL::orientation(pts_[last[0]], pts_[last[1]], pts_[last[2]]) != CGAL::LEFT_TURN)
      throw std::runtime_error("Fan_triangulator: degenerate last triangle");
    triangles.push_back(last);
    return triangles;
  }
};

// Uniform double in [0, 1) from the raw 64-bit output: unlike std::uniform_real_distribution,
// the same on every standard library.
inline double unit_random(std::mt19937_64& generator)
{
  return double(generator() >> 11) * (1.0 / 9007199254740992.0);
}

// Material between the circle (centre, radius) and the rounded rectangle's rim: >= 0 if inside.
inline double rim_clearance(const Perforated_plate_parameters& p, const Circular_hole& h)
{
  const double hx = p.length / 2., hy = p.width / 2., r = p.corner_radius;
  const double ax = std::abs(h.x), ay = std::abs(h.y);
  double distance_to_rim;
  if(ax > hx - r && ay > hy - r)
    distance_to_rim = r - std::hypot(ax - (hx - r), ay - (hy - r));
  else
    distance_to_rim = std::min(hx - ax, hy - ay);
  return distance_to_rim - h.radius;
}

} // namespace internal

/// Returns the holes of a perforated plate: `p.holes` when given, otherwise
/// `p.number_of_random_holes` holes placed by rejection sampling from `p.seed`, each at least
/// `p.min_clearance` away from the rim and from the other holes.
/// Throws `std::invalid_argument` for invalid parameters and `std::runtime_error` when the
/// random holes cannot be placed.
inline std::vector<Circular_hole> perforated_plate_holes(const Perforated_plate_parameters& p)
{
  for(double value : {p.length, p.width, p.thickness, p.corner_radius, p.min_clearance,
                       p.min_hole_radius, p.max_hole_radius})
    if(!std::isfinite(value))
      throw std::invalid_argument("perforated plate: sizes must be finite");
  if(!(p.length > 0.) || !(p.width > 0.) || !(p.thickness > 0.))
    throw std::invalid_argument("perforated plate: length, width and thickness must be positive");
  if(!(p.corner_radius >= 0.) || !(p.corner_radius < std::min(p.length, p.width) / 2.))
    throw std::invalid_argument("perforated plate: the corner radius must be in [0, min(length, width)/2)");
  if(p.segments_per_circle < 8 || p.segments_per_circle > 1000000)
    throw std::invalid_argument("perforated plate: segments per circle must be in [8, 1000000]");
  if(!(p.min_clearance > 0.))
    throw std::invalid_argument("perforated plate: the clearance must be positive");

  auto fits = [&](const Circular_hole& h, const std::vector<Circular_hole>& others) {
    if(internal::rim_clearance(p, h) < p.min_clearance)
      return false;
    for(const Circular_hole& o : others)
      if(std::hypot(h.x - o.x, h.y - o.y) < h.radius + o.radius + p.min_clearance)
        return false;
    return true;
  };

  if(!p.holes.empty()) {
    std::vector<Circular_hole> accepted;
    for(const Circular_hole& h : p.holes) {
      if(!(h.radius > 0.) || !std::isfinite(h.radius) || !std::isfinite(h.x) || !std::isfinite(h.y))
        throw std::invalid_argument("perforated plate: a hole needs a finite centre and a positive radius");
      if(!fits(h, accepted))
        throw std::invalid_argument("perforated plate: a hole overlaps another one or the rim "
                                    "(closer than the clearance)");
      accepted.push_back(h);
    }
    return accepted;
  }

  if(p.number_of_random_holes < 0)
    throw std::invalid_argument("perforated plate: negative number of holes");
  if(!(p.min_hole_radius > 0.) || !(p.max_hole_radius >= p.min_hole_radius))
    throw std::invalid_argument("perforated plate: need 0 < min hole radius <= max hole radius");

  std::mt19937_64 generator(p.seed);
  std::vector<Circular_hole> holes;
  for(int i = 0; i < p.number_of_random_holes; ++i) {
    bool placed = false;
    for(int attempt = 0; attempt < p.max_placement_attempts && !placed; ++attempt) {
      Circular_hole h;
      h.radius = p.min_hole_radius + (p.max_hole_radius - p.min_hole_radius) * internal::unit_random(generator);
      h.x = (internal::unit_random(generator) - 0.5) * p.length;
      h.y = (internal::unit_random(generator) - 0.5) * p.width;
      if(fits(h, holes)) {
        holes.push_back(h);
        placed = true;
      }
    }
    if(!placed)
      throw std::runtime_error("perforated plate: could not place hole " + std::to_string(i + 1) + " of " +
                               std::to_string(p.number_of_random_holes) +
                               " without overlap; use fewer or smaller holes, or a larger plate");
  }
  return holes;
}

/// A planar polygon with holes given by its boundary vertices: the outer loop counterclockwise,
/// then each hole clockwise, so that the material is on the left of every boundary edge
/// (indices into `points`). The outline of a perforated plate, and of every face and level of
/// the paper-scale models (`paper_models.h`).
struct Plate_outline
{
  std::vector<internal::Planar_point> points;
  std::vector<std::size_t> outer;
  std::vector<std::vector<std::size_t> > hole_loops;
};

/// Builds the outline of the plate of `p` (throws like `perforated_plate_holes()`).
inline Plate_outline perforated_plate_outline(const Perforated_plate_parameters& p)
{
  typedef internal::Planar_point Planar_point;
  const std::vector<Circular_hole> holes = perforated_plate_holes(p);
  const long segments = p.segments_per_circle;

  // Planar boundary: outer loop counterclockwise, then each hole clockwise, so that the plate's
  // material is on the left of every boundary edge.
  Plate_outline outline;
  std::vector<Planar_point>& points = outline.points;
  std::vector<std::size_t>& outer = outline.outer;
  const double hx = p.length / 2., hy = p.width / 2., r = p.corner_radius;
  const long quarter = (segments + 3) / 4;
  const double corner_x[4] = {hx - r, hx - r, -hx + r, -hx + r};
  const double corner_y[4] = {-hy + r, hy - r, hy - r, -hy + r};
  for(long c = 0; c < 4; ++c) {
    if(r == 0.) { // sharp corner
      outer.push_back(points.size());
      points.push_back(Planar_point(c < 2 ? hx : -hx, (c == 0 || c == 3) ? -hy : hy));
      continue;
    }
    // Fillet c spans the quarter turn from (c-1)/4 to c/4 of a full turn.
    for(long k = 0; k <= quarter; ++k) {
      const std::pair<double, double> u = internal::unit_circle_point((c - 1) * quarter + k, 4 * quarter);
      outer.push_back(points.size());
      points.push_back(Planar_point(corner_x[c] + r * u.first, corner_y[c] + r * u.second));
    }
  }
  std::vector<std::vector<std::size_t> >& hole_loops = outline.hole_loops;
  for(const Circular_hole& h : holes) {
    std::vector<std::size_t> loop;
    for(long k = 0; k < segments; ++k) {
      const std::pair<double, double> u = internal::unit_circle_point(-k, segments);
      loop.push_back(points.size());
      points.push_back(Planar_point(h.x + h.radius * u.first, h.y + h.radius * u.second));
    }
    hole_loops.push_back(loop);
  }

  return outline;
}

namespace internal {

// Adds the triangle abc; a refusal (non-manifold) is a bug of the generator.
template <class Point_3>
void add_triangle(CGAL::Surface_mesh<Point_3>& mesh, typename CGAL::Surface_mesh<Point_3>::Vertex_index a,
                  typename CGAL::Surface_mesh<Point_3>::Vertex_index b,
                  typename CGAL::Surface_mesh<Point_3>::Vertex_index c)
{
  if(mesh.add_face(a, b, c) == CGAL::Surface_mesh<Point_3>::null_face())
    throw std::runtime_error("CAD-like model: non-manifold triangle (internal error)");
}

// Triangulates the planar face bounded by `outline` with fans from its boundary vertices
// (`Fan_triangulator`, ear clipping from `start`); `vertex[i]` is the mesh vertex of
// `outline.points[i]`. The triangles are counterclockwise in the outline's plane, clockwise
// when `reversed` (a face seen from its other side).
template <class Point_3>
void add_fan_face(CGAL::Surface_mesh<Point_3>& mesh, const Plate_outline& outline,
                  const std::vector<typename CGAL::Surface_mesh<Point_3>::Vertex_index>& vertex,
                  std::size_t start, bool reversed)
{
  for(const std::array<std::size_t, 3>& t : Fan_triangulator(outline.points, outline.outer, outline.hole_loops).run(start)) {
    if(reversed)
      add_triangle(mesh, vertex[t[2]], vertex[t[1]], vertex[t[0]]);
    else
      add_triangle(mesh, vertex[t[0]], vertex[t[1]], vertex[t[2]]);
  }
}

// Triangulates a curved face as CAD exporters do (they fan only planar faces; a curved face gets
// interior points so that its chord error stays bounded): the outline's points and the points of
// a square grid of step `spacing` inside it, by a constrained Delaunay triangulation. Appends the
// grid points to `interior` and returns counterclockwise triangles indexing `outline.points`,
// then `interior`.
inline std::vector<std::array<std::size_t, 3> > grid_face_triangles(const Plate_outline& outline, double spacing,
                                                                     std::vector<Planar_point>& interior)
{
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Planar_kernel> Vb;
  typedef CGAL::Conformal_remeshing::internal::remeshing::Planar_face_base_2<Planar_kernel> Fb; // for mark_domain()
  typedef CGAL::Constrained_Delaunay_triangulation_2<Planar_kernel, CGAL::Triangulation_data_structure_2<Vb, Fb>,
                                                     CGAL::Exact_predicates_tag> CDT;
  CDT cdt;
  std::vector<CDT::Vertex_handle> handle;
  for(std::size_t i = 0; i < outline.points.size(); ++i) {
    handle.push_back(cdt.insert(outline.points[i]));
    handle.back()->info() = i;
  }
  auto constrain = [&](const std::vector<std::size_t>& loop) {
    for(std::size_t i = 0; i < loop.size(); ++i)
      cdt.insert_constraint(handle[loop[i]], handle[loop[(i + 1) % loop.size()]]);
  };
  constrain(outline.outer);
  for(const std::vector<std::size_t>& loop : outline.hole_loops)
    constrain(loop);
  CGAL::Conformal_remeshing::internal::remeshing::mark_domain(cdt);

  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for(const Planar_point& q : outline.points) {
    x0 = (std::min)(x0, q.x()), y0 = (std::min)(y0, q.y()), x1 = (std::max)(x1, q.x()), y1 = (std::max)(y1, q.y());
  }
  std::vector<Planar_point> grid;
  for(double y = y0 + 0.5 * spacing; y < y1; y += spacing)
    for(double x = x0 + 0.5 * spacing; x < x1; x += spacing) {
      CDT::Locate_type type;
      int i = 0;
      const CDT::Face_handle f = cdt.locate(Planar_point(x, y), type, i);
      if(type == CDT::FACE && f->is_in_domain())
        grid.emplace_back(x, y);
    }
  for(const Planar_point& q : grid) {
    const CDT::Vertex_handle v = cdt.insert(q);
    v->info() = outline.points.size() + interior.size();
    interior.push_back(q);
  }
  CGAL::Conformal_remeshing::internal::remeshing::mark_domain(cdt);
  std::vector<std::array<std::size_t, 3> > triangles;
  for(CDT::Face_handle f : cdt.finite_face_handles())
    if(f->is_in_domain())
      triangles.push_back({{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}});
  return triangles;
}

// One quad, two triangles, of a strip joining two copies of a boundary edge i -> j (material on
// its left): it faces away from the material when the `upper` copy is on the side of the face
// that the edge bounds counterclockwise.
template <class Point_3>
void add_strip_quad(CGAL::Surface_mesh<Point_3>& mesh, typename CGAL::Surface_mesh<Point_3>::Vertex_index upper_i,
                    typename CGAL::Surface_mesh<Point_3>::Vertex_index upper_j,
                    typename CGAL::Surface_mesh<Point_3>::Vertex_index lower_i,
                    typename CGAL::Surface_mesh<Point_3>::Vertex_index lower_j)
{
  add_triangle(mesh, lower_i, lower_j, upper_j);
  add_triangle(mesh, lower_i, upper_j, upper_i);
}

// Joins two copies of a boundary loop (point indices, material on the left) by one quad per
// edge, as CAD exporters tessellate walls and fillets; `upper[i]` and `lower[i]` are the
// vertices of point i in each copy (see add_strip_quad()).
template <class Point_3>
void add_strip(CGAL::Surface_mesh<Point_3>& mesh, const std::vector<std::size_t>& loop,
               const std::vector<typename CGAL::Surface_mesh<Point_3>::Vertex_index>& upper,
               const std::vector<typename CGAL::Surface_mesh<Point_3>::Vertex_index>& lower)
{
  for(std::size_t k = 0; k < loop.size(); ++k) {
    const std::size_t i = loop[k], j = loop[(k + 1) % loop.size()];
    add_strip_quad(mesh, upper[i], upper[j], lower[i], lower[j]);
  }
}

// The grid spacing of a curved face of radius of curvature `radius` (mm) whose chords deviate
// from it by at most 0.1 mm, a common exporter tolerance: a chord of length L sags L^2 / 8R.
inline double cad_curved_face_spacing(double radius) { return std::sqrt(8. * radius * 0.1); }

} // namespace internal

/// Adds to `mesh` a part swept by a planar outline through levels, top to bottom: level k is
/// `levels[k]` (every level has the same loops with the same numbers of points, e.g. one
/// outline moved into the material for fillets) at height `heights[k]`, placed in space by
/// `place(x, y, height)`. Each loop's copies in consecutive levels are joined by strips (walls,
/// fillets); the first level is closed by a face triangulated in fans when `cap_first`, the
/// last one, seen from below, when `cap_last`; with `curved_cap_spacing > 0` (for a `place`
/// that bends the caps) by a Delaunay triangulation with interior grid points at that spacing
/// instead, as exporters tessellate curved faces. With both caps and `place` the identity, the
/// part is closed and outward oriented, of genus the number of holes; with one cap, an open
/// surface of genus 0 with one boundary loop per loop of the outline.
///
/// Vertices are added level by level; faces are the first cap, the last cap, then the strips
/// loop by loop, band by band. Throws `std::runtime_error` if a triangulation fails.
template <class Point_3, class Place>
void add_layered_part(CGAL::Surface_mesh<Point_3>& mesh, const std::vector<Plate_outline>& levels,
                      const std::vector<double>& heights, bool cap_first, bool cap_last, Place place,
                      double curved_cap_spacing = 0.)
{
  typedef typename CGAL::Surface_mesh<Point_3>::Vertex_index Vertex_index;
  if(levels.empty() || levels.size() != heights.size())
    throw std::invalid_argument("layered part: need one height per level, and at least one level");
  for(const Plate_outline& level : levels)
    if(level.points.size() != levels[0].points.size() || level.hole_loops.size() != levels[0].hole_loops.size())
      throw std::invalid_argument("layered part: the levels must have the same loops");

  std::vector<std::vector<Vertex_index> > vertex(levels.size());
  for(std::size_t k = 0; k < levels.size(); ++k)
    for(const internal::Planar_point& q : levels[k].points)
      vertex[k].push_back(mesh.add_vertex(place(q.x(), q.y(), heights[k])));

  // CAD exporters triangulate each face on its own: the last one starts its fans elsewhere. A
  // curved face (`place` bends it) gets grid points inside instead of fans.
  auto add_cap = [&](std::size_t k, std::size_t fan_start, bool reversed) {
    if(!(curved_cap_spacing > 0.)) {
      internal::add_fan_face(mesh, levels[k], vertex[k], fan_start, reversed);
      return;
    }
    std::vector<internal::Planar_point> interior;
    const auto triangles = internal::grid_face_triangles(levels[k], curved_cap_spacing, interior);
    std::vector<Vertex_index> corner = vertex[k];
    for(const internal::Planar_point& q : interior)
      corner.push_back(mesh.add_vertex(place(q.x(), q.y(), heights[k])));
    for(const std::array<std::size_t, 3>& t : triangles) {
      if(reversed)
        internal::add_triangle(mesh, corner[t[2]], corner[t[1]], corner[t[0]]);
      else
        internal::add_triangle(mesh, corner[t[0]], corner[t[1]], corner[t[2]]);
    }
  };
  if(cap_first)
    add_cap(0, 0, false);
  if(cap_last)
    add_cap(levels.size() - 1, levels.back().points.size() / 2, true);

  const Plate_outline& outline = levels[0];
  auto add_walls = [&](const std::vector<std::size_t>& loop) {
    for(std::size_t k = 0; k + 1 < levels.size(); ++k)
      internal::add_strip(mesh, loop, vertex[k], vertex[k + 1]);
  };
  add_walls(outline.outer);
  for(const std::vector<std::size_t>& loop : outline.hole_loops)
    add_walls(loop);
}

/// Builds a closed, outward-oriented triangle mesh of a plate with rounded vertical edges and
/// circular through-holes (genus = number of holes), tessellated as CAD exporters do:
/// - top and bottom faces triangulated from their boundary vertices only (bridged ear clipping
///   in fans), so they are full of long slivers;
/// - hole walls and fillets as strips, one quad (two triangles) per circle segment spanning the
///   whole thickness;
/// - straight sides as one long rectangle (two triangles) each.
///
/// `mesh` is cleared first. The result depends only on `p` (no time, no unordered containers).
/// Throws like `perforated_plate_holes()`, and `std::runtime_error` if the triangulation fails.
template <class Point_3>
void make_perforated_plate(CGAL::Surface_mesh<Point_3>& mesh, const Perforated_plate_parameters& p)
{
  const Plate_outline outline = perforated_plate_outline(p);
  mesh.clear();
  add_layered_part(mesh, std::vector<Plate_outline>(2, outline), {p.thickness, 0.}, true, true,
                   [](double x, double y, double z) { return Point_3(x, y, z); });
}

/// Builds the top face of the plate of `p` alone: an open sheet of genus 0 with one boundary
/// loop per hole plus the outer one, triangulated like `make_perforated_plate()`'s faces (fans of
/// slivers). With `bend != 0` the sheet is bent around the y axis, `z = bend * x^2 / (length / 2)`,
/// so that it is not flat: with `curved_face = false` its fans are bent along (a hostile input:
/// neighbouring slivers then meet at false sharp edges), with `true` it is tessellated as
/// exporters do curved faces, with interior grid points at the spacing whose chords stay within
/// 0.1 of the surface (`cad_curved_face_spacing()` of its radius of curvature at x = 0).
template <class Point_3>
void make_perforated_sheet(CGAL::Surface_mesh<Point_3>& mesh, const Perforated_plate_parameters& p, double bend = 0.,
                           bool curved_face = false)
{
  const Plate_outline outline = perforated_plate_outline(p);
  const double half = p.length / 2.;
  const double spacing = curved_face && bend != 0. ? internal::cad_curved_face_spacing(half / (2. * std::abs(bend))) : 0.;
  mesh.clear();
  add_layered_part(mesh, std::vector<Plate_outline>(1, outline), {0.}, true, false,
                   [&](double x, double y, double) { return Point_3(x, y, bend * x * x / half); }, spacing);
}

/// Builds an open flat disc (one boundary loop, genus 0) of radius `radius` in the plane z = 0,
/// triangulated as a single fan from one boundary vertex over `segments` boundary vertices:
/// the smallest input with CAD-like fans (by the inscribed angle theorem every triangle has the
/// angle pi/segments at the fan's apex; the two triangles next to the apex have two of them).
template <class Point_3>
void make_sliver_fan_disc(CGAL::Surface_mesh<Point_3>& mesh, int segments = 64, double radius = 1.)
{
  if(segments < 4 || segments > 10000000 || !(radius > 0.) || !std::isfinite(radius))
    throw std::invalid_argument("sliver fan disc: need 4 to 10^7 segments and a positive, finite radius");
  mesh.clear();
  typedef typename CGAL::Surface_mesh<Point_3>::Vertex_index Vertex_index;
  std::vector<Vertex_index> v;
  for(int k = 0; k < segments; ++k) {
    const std::pair<double, double> u = internal::unit_circle_point(k, segments);
    v.push_back(mesh.add_vertex(Point_3(radius * u.first, radius * u.second, 0.)));
  }
  for(int k = 1; k + 1 < segments; ++k)
    mesh.add_face(v[0], v[k], v[k + 1]);
}

/// Counts and angle statistics of a triangle mesh (see `Cad_model_statistics`), from the
/// package's own input checks and quality measures.
template <class Point_3>
Cad_model_statistics cad_model_statistics(const CGAL::Surface_mesh<Point_3>& mesh)
{
  const Mesh_check_report checks = check_mesh(mesh);
  const Mesh_quality_report quality = mesh_quality(mesh);
  Cad_model_statistics s;
  s.vertices = mesh.number_of_vertices();
  s.edges = mesh.number_of_edges();
  s.faces = mesh.number_of_faces();
  s.components = checks.components.size();
  for(const Component_topology& c : checks.components)
  {
    s.boundary_loops += c.boundary_loops;
    s.euler_characteristic += c.euler_characteristic;
  }
  s.genus = checks.total_genus();
  s.min_angle_degrees = quality.minimum_angle.min;
  s.share_min_angle_below_10 = quality.share_with_minimum_angle_below(10.);
  // The minimum-angle histogram has 1 degree bins: its first bin holds the angles below 1 degree.
  if(s.faces > 0)
    s.share_min_angle_below_1 = double(quality.minimum_angle_histogram.counts[0]) / double(s.faces);
  return s;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_CAD_LIKE_MODELS_H
