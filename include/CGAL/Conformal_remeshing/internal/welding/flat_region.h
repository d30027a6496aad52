// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A flat set of faces of a patch that was retriangulated (see
// retriangulate_flat_regions.h): its original faces are kept to locate points in them.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_FLAT_REGION_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_FLAT_REGION_H

#include <CGAL/Conformal_remeshing/internal/welding/corner_coordinates.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

/// A region of faces of a patch laid flat in the plane that was retriangulated (see
/// retriangulate_flat_regions.h): exactly coplanar faces projected exactly to a coordinate plane
/// (one coordinate dropped, the other two kept as they are, one of them negated if need be so
/// that the faces are counterclockwise), or a developable set of faces (a bend between planar
/// faces, a cylinder strip) unfolded isometrically. Locating a point among the original faces
/// walks along a straight line from a vertex, in exact predicates; the walk starts from the
/// corner of the query's new face that reaches the point through the fewest original faces (a
/// CAD fan is crossed by no walk from its apex and by many from elsewhere), tried with growing
/// step budgets.
struct Flat_region
{
  typedef Epick::Point_2 Point_2;

  std::vector<int> vertices;                 // patch vertex indices, sorted
  std::vector<Point_2> points;               // their projections or unfolded positions
  /// whether the region was unfolded rather than projected: its new faces are not in space
  /// where its original faces are, so a point of a new face is located in an original one
  bool developed = false;
  std::vector<std::array<int, 3> > faces;    // the original faces, as indices into `vertices`
  std::vector<std::array<int, 3> > neighbor; // the face across side (c, c+1), or -1
  std::vector<int> fan_start, fan;           // faces around each vertex, counterclockwise
  std::vector<int> input_face;               // the input face each original face lies in,
  Corner_coordinates input_coordinates;      // and its corners there
  /// for a vertex the retriangulation added inside the region, the original face holding it (it
  /// has no fan of original faces); -1 for the region's own vertices
  std::vector<int> containing_face;

  int local_vertex(int patch_vertex) const
  {
    return int(std::lower_bound(vertices.begin(), vertices.end(), patch_vertex) - vertices.begin());
  }

  /// The original face holding the point at barycentric coordinates `b` of the triangle with the
  /// patch vertices `corners` (a face of the retriangulation), and the point's barycentric
  /// coordinates there (clamped into the face should rounding put the point just outside).
  std::pair<int, std::array<double, 3> > locate(const std::array<int, 3>& corners, const std::array<double, 3>& b) const
  {
    std::array<int, 3> start;
    double x = 0., y = 0.;
    for(int c = 0; c < 3; ++c)
    {
      start[c] = local_vertex(corners[c]);
      x += b[c] * points[start[c]].x();
      y += b[c] * points[start[c]].y();
    }
    return locate_point(start, Point_2(x, y));
  }

  /// The original face holding `p` (in the projection), walking from the vertices `start` (local
  /// indices) of a triangle that holds it, and `p`'s barycentric coordinates there.
  std::pair<int, std::array<double, 3> > locate_point(const std::array<int, 3>& start, const Point_2& p) const
  {
    int face = -1;
    for(std::size_t budget = 16; face < 0 && budget < 4 * faces.size() + 64; budget *= 4)
      for(int c = 0; c < 3 && face < 0; ++c)
        face = is_added(start[c]) ? walk_from_inside(containing_face[start[c]], points[start[c]], p, budget)
                                  : walk(start[c], p, budget);
    if(face < 0)
      face = scan(p);
    return {face, coordinates(face, p)};
  }

  /// The original face holding `p`, walking from `s`, a point of original face `f` (a point
  /// located before, near `p`), and `p`'s barycentric coordinates there; face -1 if the walk
  /// fails (it runs through a vertex, or leaves the region: a hole lies between `s` and `p`).
  std::pair<int, std::array<double, 3> > locate_point_from(int f, const Point_2& s, const Point_2& p) const
  {
    const int face = walk_from_inside(f, s, p, 4 * faces.size() + 64);
    if(face < 0 || !holds(face, p))
      return {-1, {{0., 0., 0.}}};
    return {face, coordinates(face, p)};
  }

private:
  bool is_added(int v) const { return std::size_t(v) < containing_face.size() && containing_face[v] >= 0; }

  int third(int f, int a, int b) const
  {
    for(int v : faces[f])
      if(v != a && v != b)
        return v;
    return -1;
  }
  int side(int f, int a, int b) const // the side of f from a to b
  {
    for(int c = 0; c < 3; ++c)
      if(faces[f][c] == a && faces[f][(c + 1) % 3] == b)
        return c;
    return -1;
  }
  bool holds(int f, const Point_2& p) const // p in f or on its sides
  {
    for(int c = 0; c < 3; ++c)
      if(CGAL::orientation(points[faces[f][c]], points[faces[f][(c + 1) % 3]], p) == CGAL::NEGATIVE)
        return false;
    return true;
  }
  int corner(int f, int v) const { return int(std::find(faces[f].begin(), faces[f].end(), v) - faces[f].begin()); }

  // Whether direction `x` comes before direction `y` counterclockwise from direction `r`, all
  // three from point `o`: [r, r + pi) first, then [r + pi, r + 2 pi).
  static bool comes_before(const Point_2& o, const Point_2& r, const Point_2& x, const Point_2& y)
  {
    auto half = [&](const Point_2& q) {
      const CGAL::Orientation s = CGAL::orientation(o, r, q);
      return (s == CGAL::POSITIVE || (s == CGAL::COLLINEAR && CGAL::angle(r, o, q) == CGAL::ACUTE)) ? 0 : 1;
    };
    const int hx = half(x), hy = half(y);
    return hx != hy ? hx < hy : CGAL::orientation(o, x, y) == CGAL::POSITIVE;
  }

  // The face around `v` whose corner at `v` holds the direction to `p`. Past the fan of a
  // boundary vertex (rounding puts `p` just outside the region), the face at the nearer end.
  int wedge(int v, const Point_2& p) const
  {
    const int first = fan_start[v], last = fan_start[v + 1];
    auto ray = [&](int k) { // the first side of fan face k, leaving v
      const int f = fan[k];
      return points[faces[f][(corner(f, v) + 1) % 3]];
    };
    const Point_2 &o = points[v], r = ray(first);
    // the last face whose first side does not come after p
    int lo = first, hi = last;
    while(hi - lo > 1)
    {
      const int mid = (lo + hi) / 2;
      if(comes_before(o, r, p, ray(mid)))
        hi = mid;
      else
        lo = mid;
    }
    const int f = fan[lo];
    const int end = faces[f][(corner(f, v) + 2) % 3]; // the fan's other end when lo is the last face
    if(lo == last - 1 && neighbor[f][side(f, end, v)] < 0
       && comes_before(o, r, points[end], p))
    {
      auto angle_to = [&](const Point_2& q) {
        const double ax = q.x() - o.x(), ay = q.y() - o.y(), bx = p.x() - o.x(), by = p.y() - o.y();
        return std::abs(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
      };
      return angle_to(r) < angle_to(points[end]) ? fan[first] : f;
    }
    return f;
  }

  // Walks from vertex `v` to `p` along the segment between them; the face holding `p`, or -1
  // when `budget` faces were not enough. (When `p` is `v`, any face of its fan holds it.)
  int walk(int v, const Point_2& p, std::size_t budget) const
  {
    // f: the current face; right -> left: its side crossed next, seen from v towards p
    int f, right, left;
    auto start_at = [&](int vertex) {
      v = vertex;
      f = wedge(v, p);
      right = faces[f][(corner(f, v) + 1) % 3];
      left = faces[f][(corner(f, v) + 2) % 3];
    };
    start_at(v);
    for(std::size_t steps = 0; steps < budget; ++steps)
    {
      if(holds(f, p))
        return f;
      if(CGAL::orientation(points[right], points[left], p) != CGAL::NEGATIVE)
        return f; // p is outside f at a side through v, a boundary side: outside the region by rounding
      const int across = neighbor[f][side(f, right, left)];
      if(across < 0)
        return f; // p is outside the region by rounding: the last face is the nearest
      f = across;
      const int w = third(f, left, right);
      const CGAL::Orientation turn = CGAL::orientation(points[v], p, points[w]);
      if(turn == CGAL::LEFT_TURN)
        left = w;
      else if(turn == CGAL::RIGHT_TURN)
        right = w;
      else if(!holds(f, p)) // the line runs through w: go on from there
        start_at(w);
    }
    return -1;
  }

  // Walks from `s`, a point of face `f`, to `p` along the segment between them; the face holding
  // `p`, or -1 when `budget` faces were not enough or the segment runs through a vertex.
  int walk_from_inside(int f, const Point_2& s, const Point_2& p, std::size_t budget) const
  {
    int entered = -1; // the side f was entered by
    for(std::size_t steps = 0; steps < budget; ++steps)
    {
      if(holds(f, p))
        return f;
      int exit = -1; // the side p lies beyond whose ends lie on either side of the line from s to p
      for(int c = 0; c < 3 && exit < 0; ++c)
      {
        const Point_2 &a = points[faces[f][c]], &b = points[faces[f][(c + 1) % 3]];
        if(c == entered || CGAL::orientation(a, b, p) != CGAL::NEGATIVE)
          continue;
        const CGAL::Orientation at_a = CGAL::orientation(s, p, a), at_b = CGAL::orientation(s, p, b);
        if(at_a == CGAL::COLLINEAR || at_b == CGAL::COLLINEAR)
          return -1;
        if(at_a != at_b)
          exit = c;
      }
      if(exit < 0)
        return -1;
      const int across = neighbor[f][exit];
      if(across < 0)
        return f; // p is outside the region by rounding: the last face is the nearest
      entered = side(across, faces[f][(exit + 1) % 3], faces[f][exit]);
      f = across;
    }
    return -1;
  }

  // The face holding `p` by trying every face, or the nearest vertex's first face (for a point
  // that no walk reached: outside the region by rounding, past a boundary vertex's fan).
  int scan(const Point_2& p) const
  {
    for(std::size_t f = 0; f < faces.size(); ++f)
      if(holds(int(f), p))
        return int(f);
    std::size_t nearest = 0;
    for(std::size_t v = 1; v < points.size(); ++v)
      if(CGAL::compare_distance_to_point(p, points[v], points[nearest]) == CGAL::SMALLER)
        nearest = v;
    return is_added(int(nearest)) ? containing_face[nearest] : fan[fan_start[nearest]];
  }

  // Barycentric coordinates of `p` in face `f`, clamped to it (from the projected areas).
  std::array<double, 3> coordinates(int f, const Point_2& p) const
  {
    std::array<double, 3> b;
    double total = 0.;
    for(int c = 0; c < 3; ++c)
    {
      const Point_2 &q = points[faces[f][(c + 1) % 3]], &r = points[faces[f][(c + 2) % 3]];
      b[c] = (std::max)(0., (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()));
      total += b[c];
    }
    if(!(total > 0.)) // a sliver with no area in doubles: the corner nearest to p
    {
      int nearest = 0;
      for(int c = 1; c < 3; ++c)
        if(CGAL::squared_distance(points[faces[f][c]], p) < CGAL::squared_distance(points[faces[f][nearest]], p))
          nearest = c;
      b = {{0., 0., 0.}};
      b[nearest] = 1.;
      return b;
    }
    for(double& x : b)
      x /= total;
    return b;
  }
};

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_FLAT_REGION_H
