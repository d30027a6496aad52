// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Frontal Delaunay point insertion in the plane (Rebay, "Efficient unstructured mesh generation
// by means of Delaunay triangulation and Bowyer-Watson algorithm", J. Comput. Phys. 106, 1993):
// points placed one by one where they make a triangle of the target size on a front that
// advances from the constraints, so that the triangulation grows in rows of nearly equilateral
// triangles. Delaunay refinement places its points at circumcentres, in the order of its queue of
// bad faces, and leaves meshes whose vertices mostly do not have six neighbours.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FRONTAL_INSERTION_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FRONTAL_INSERTION_H

#include <CGAL/Conformal_remeshing/internal/remeshing/planar_point_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// How the frontal insertion sizes its triangles (see `Frontal_inserter_2`). Off when
/// `target_ratio` is 0.
struct Frontal_insertion
{
  /// the target edge length over the size field (the refinement's bound on the longest edge)
  double target_ratio = 0.;
  /// a triangle is accepted when its circumradius is at most this times the target edge length
  /// (an equilateral triangle of the target size has 0.577, a right isosceles one with legs of
  /// the target size 0.707)
  double accepted_radius_ratio = 0.7;

  bool is_on() const { return target_ratio > 0.; }
};

/// Whether the circumcentre of the triangle `a`, `b`, `c` can be computed in floating point: not
/// when the sine of its largest angle is below 1e-12 (its corners collinear but for rounding,
/// which exact predicates allow for a face beside a constraint). Its circumradius then exceeds
/// 5e11 times its longest edge, and CGAL's construction divides by zero (an assertion in debug
/// builds, NaN in Release) or lands unboundedly far. Such faces occur beside boundary chords
/// (on CGAL's dino and femur, for example).
inline bool has_computable_circumcentre(const Epick::Point_2& a, const Epick::Point_2& b, const Epick::Point_2& c)
{
  const std::array<Epick::Point_2, 3> p{{a, b, c}};
  const auto squared_side = [&](int i) { return CGAL::squared_distance(p[(i + 1) % 3], p[(i + 2) % 3]); }; // opposite corner i
  int widest = 0; // the corner opposite the longest side: the largest angle
  for(int i = 1; i < 3; ++i)
    if(squared_side(i) > squared_side(widest))
      widest = i;
  const Epick::Vector_2 u = p[(widest + 1) % 3] - p[widest], v = p[(widest + 2) % 3] - p[widest];
  return std::abs(u.x() * v.y() - u.y() * v.x()) > 1e-12 * std::sqrt(u.squared_length() * v.squared_length());
}

/// The circumradius of the triangle `a`, `b`, `c`: infinite where its circumcentre cannot be
/// computed (see `has_computable_circumcentre()`).
inline double circumradius(const Epick::Point_2& a, const Epick::Point_2& b, const Epick::Point_2& c)
{
  if(!has_computable_circumcentre(a, b, c))
    return std::numeric_limits<double>::infinity();
  return std::sqrt(CGAL::squared_distance(CGAL::circumcenter(a, b, c), a));
}

/// How far the circumcentre of the counterclockwise triangle `a`, `b`, `apex` stands from the
/// midpoint of `a`-`b` along the edge's unit normal `inward` (toward the apex): infinite when the
/// apex is not strictly left of `a`-`b` in floating point or the circumcentre cannot be computed
/// (no circumcentre to bound a point by).
inline double circumcentre_offset(const Epick::Point_2& a, const Epick::Point_2& b, const Epick::Point_2& apex,
                                  const Epick::Vector_2& inward)
{
  const Epick::Vector_2 u = b - a, v = apex - a;
  if(!(u.x() * v.y() - u.y() * v.x() > 0.) || !has_computable_circumcentre(a, b, apex))
    return std::numeric_limits<double>::infinity();
  return (CGAL::circumcenter(a, b, apex) - CGAL::midpoint(a, b)) * inward;
}

/// Frontal Delaunay insertion in the marked domain of a constrained Delaunay triangulation `CDT`
/// whose faces' info has the members `accepted`, `stamp` and `radius_ratio` (see
/// `Planar_face_info`). A face is accepted when its circumradius is at most
/// `Frontal_insertion::accepted_radius_ratio` times the target edge length (the mean of its
/// corners' targets: `Frontal_insertion::target_ratio` times `size`, a size field as for
/// `size_field_at()`). A face that is not accepted is active when one of its edges (its front
/// edge) is a constraint or borders an accepted face. The active face with the largest ratio, which
/// stands farthest from the target, gets a point on its front edge's bisector, on its side: the
/// apex of the isosceles triangle on that edge whose circumradius is the target's (an equilateral
/// triangle for an edge of the target length), brought closer if it would leave the face's
/// circumcircle, so that the face is destroyed. Only the faces around a new vertex are new (or
/// flipped): they are classified again, under a new stamp that retires their stale queue entries.
/// A point that falls outside the domain, on a vertex or a constraint, or would make a constraint
/// non-Delaunay by `Conforming` (`conforming(cdt, face, index, point)` as in CGAL's
/// `Mesh_2::Is_locally_conforming_Delaunay`, on the conflict zone's constrained boundary edges) is
/// not inserted, nor one closer to a vertex than `min_spacing` times its target (so the points
/// stay apart and the insertion ends) or to a constraint than `min_constraint_distance` times
/// it; its face is then accepted as it is. No point is ever added
/// on a constraint. The
/// Delaunay refinement run after this enforces the shape and size bounds where the fronts met.
template <typename CDT, typename Size_field, typename Conforming>
class Frontal_inserter_2
{
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Edge Edge;
  typedef typename CDT::Point Point;

  struct Corner_target
  {
    double length;
    Size_field_hint hint;
  };
  struct Active_face
  {
    double radius_ratio;
    Face_handle face;
    std::uint32_t stamp;
    bool operator<(const Active_face& other) const { return radius_ratio < other.radius_ratio; }
  };

  // (The apex of an equilateral triangle on an edge of the target length is 0.87 targets from the
  // edge.) A point nearer a constraint than a tenth of its target makes a flat triangle on it,
  // which the refinement cannot mend (the constraint is never split; a point 1e-17 off a chord
  // makes one whose circumcentre divides by zero). A bound of 0.3 targets, as for vertices,
  // would refuse too many points near constraints (it moves the distance to the input by about
  // 12% on a scanned model); the optimization on the surface evens out the triangles of points
  // between the two bounds.
  static constexpr double min_spacing = 0.3, min_constraint_distance = 0.1;

public:
  Frontal_inserter_2(CDT& cdt, const Size_field& size, const Frontal_insertion& parameters)
    : cdt_(cdt), size_(size), parameters_(parameters)
  {}

  /// Inserts points until no face is active; returns their number.
  std::size_t run()
  {
    std::vector<Face_handle> domain;
    for(Face_handle f : cdt_.finite_face_handles())
      if(f->is_in_domain())
      {
        classify(f);
        domain.push_back(f);
      }
    for(Face_handle f : domain)
      queue_if_active(f);
    std::size_t inserted = 0;
    while(!active_.empty())
    {
      const Active_face a = active_.top();
      active_.pop();
      const Face_handle f = a.face;
      if(f->info().stamp != a.stamp || f->info().accepted)
        continue; // destroyed, classified again, or accepted since it was queued
      const int edge = front_edge(f);
      if(edge < 0)
        continue; // its accepted neighbour was destroyed: it comes back when a new one is accepted
      double target = 0.;
      const Point x = frontal_point(f, edge, target);
      if(insert(x, f, target))
        ++inserted;
      else
        accept(f);
    }
    return inserted;
  }

private:
  static Epick::Point_2 to_epick(const Point& p) { return Epick::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

  // The target edge length at a vertex, asked of the size field once (from `near`).
  double target_at(Vertex_handle v, Size_field_hint near)
  {
    const Epick::Point_2 p = to_epick(v->point());
    targets_.reserve(targets_.size() + 1); // the pointer stays valid
    const auto known = targets_.try_emplace(p, Corner_target{0., near});
    if(known.second)
      known.first->length = parameters_.target_ratio * size_field_at(size_, p, known.first->hint);
    return known.first->length;
  }

  // Where the size field found a vertex (a query nearby starts best there), if it was asked.
  Size_field_hint hint_at(Vertex_handle v)
  {
    const Corner_target* known = targets_.find(to_epick(v->point()));
    return known == nullptr ? no_size_field_hint : known->hint;
  }

  void classify(Face_handle f)
  {
    f->info().stamp = ++stamp_;
    Size_field_hint near = no_size_field_hint;
    for(int i = 0; i < 3 && near == no_size_field_hint; ++i)
      near = hint_at(f->vertex(i));
    const double target = (target_at(f->vertex(0), near) + target_at(f->vertex(1), near) + target_at(f->vertex(2), near)) / 3.;
    const Epick::Point_2 a = to_epick(f->vertex(0)->point()), b = to_epick(f->vertex(1)->point()),
                         c = to_epick(f->vertex(2)->point());
    const double radius = circumradius(a, b, c);
    f->info().radius_ratio = target > 0. ? radius / target : std::numeric_limits<double>::infinity();
    f->info().accepted = f->info().radius_ratio <= parameters_.accepted_radius_ratio;
  }

  void accept(Face_handle f)
  {
    f->info().accepted = true;
    for(int i = 0; i < 3; ++i)
      queue_neighbour_if_active(f, i);
  }

  // The first edge of `f` on a constraint or next to an accepted face, or -1.
  int front_edge(Face_handle f) const
  {
    for(int i = 0; i < 3; ++i)
    {
      if(cdt_.is_constrained(std::make_pair(f, i)))
        return i;
      const Face_handle g = f->neighbor(i);
      if(!cdt_.is_infinite(g) && g->is_in_domain() && g->info().accepted)
        return i;
    }
    return -1;
  }

  void queue_if_active(Face_handle f)
  {
    if(!f->info().accepted && front_edge(f) >= 0)
      active_.push(Active_face{f->info().radius_ratio, f, f->info().stamp});
  }

  void queue_neighbour_if_active(Face_handle f, int i)
  {
    const Face_handle g = f->neighbor(i);
    if(!cdt_.is_infinite(g) && g->is_in_domain())
      queue_if_active(g);
  }

  // The apex over edge `i` of `f` (see the class): at height `r + sqrt(r^2 - p^2)` over the
  // edge's midpoint, `p` its half length, `r` the target's circumradius, at least `p` (the
  // apex's angle at most 90 degrees), and at most the radius for which the apex reaches the
  // circumcentre of `f` when that lies on the apex's side.
  Point frontal_point(Face_handle f, int i, double& target)
  {
    const Vertex_handle va = f->vertex(CDT::ccw(i)), vb = f->vertex(CDT::cw(i));
    const Epick::Point_2 a = to_epick(va->point()), b = to_epick(vb->point()), apex = to_epick(f->vertex(i)->point());
    const Epick::Point_2 m = CGAL::midpoint(a, b);
    const Epick::Vector_2 chord = b - a;
    const double length = std::sqrt(chord.squared_length());
    const Epick::Vector_2 inward(-chord.y() / length, chord.x() / length); // toward f's third corner
    const double p = 0.5 * length, q = circumcentre_offset(a, b, apex, inward);
    const Size_field_hint near = hint_at(va);
    target = 0.5 * (target_at(va, near) + target_at(vb, near));
    double radius = (std::max)(target / std::sqrt(3.), p);
    if(q > 0. && q < std::numeric_limits<double>::infinity())
      radius = (std::min)(radius, (p * p + q * q) / (2. * q));
    const Epick::Point_2 x = m + (radius + std::sqrt((std::max)(0., radius * radius - p * p))) * inward;
    return Point(x.x(), x.y());
  }

  // Inserts `x` (see the class), then classifies the faces around the new vertex and queues those
  // that became active, and the neighbours of those accepted.
  bool insert(const Point& x, Face_handle start, double target)
  {
    typename CDT::Locate_type type;
    int li = 0;
    const Face_handle f = cdt_.locate(x, type, li, start);
    if((type != CDT::FACE && type != CDT::EDGE) || !f->is_in_domain()
       || (type == CDT::EDGE && cdt_.is_constrained(std::make_pair(f, li))))
      return false;
    zone_faces_.clear();
    zone_edges_.clear();
    cdt_.get_conflicts_and_boundary(x, std::back_inserter(zone_faces_), std::back_inserter(zone_edges_), f);
    // A constraint that x nearly touches bounds its conflict zone (the face holding x is on it).
    const Epick::Point_2 px = to_epick(x);
    const double spacing = min_spacing * target, clearance = min_constraint_distance * target;
    for(const Edge& e : zone_edges_)
      if(cdt_.is_constrained(e)
         && (!conforming_(cdt_, e.first, e.second, x)
             || CGAL::squared_distance(Epick::Segment_2(to_epick(e.first->vertex(CDT::ccw(e.second))->point()),
                                                        to_epick(e.first->vertex(CDT::cw(e.second))->point())),
                                       px) < clearance * clearance))
        return false;
    // The vertex nearest to x is a corner of the conflict zone (x's Delaunay neighbours).
    for(Face_handle g : zone_faces_)
      for(int i = 0; i < 3; ++i)
        if(CGAL::squared_distance(to_epick(g->vertex(i)->point()), px) < spacing * spacing)
          return false;
    const Vertex_handle v = cdt_.insert(x, type, f, li);
    star_.clear();
    auto c = cdt_.incident_faces(v), done = c;
    do
      if(!cdt_.is_infinite(c))
      {
        c->set_in_domain(true); // the conflict zone lay in the domain, bounded by constraints
        star_.push_back(c);
      }
    while(++c != done);
    for(Face_handle g : star_)
      classify(g);
    for(Face_handle g : star_)
    {
      queue_if_active(g);
      if(g->info().accepted)
        queue_neighbour_if_active(g, g->index(v));
    }
    return true;
  }

  CDT& cdt_;
  const Size_field& size_;
  Frontal_insertion parameters_;
  Conforming conforming_;
  Planar_point_map<Corner_target> targets_;
  std::priority_queue<Active_face> active_;
  std::uint32_t stamp_ = 0;
  std::vector<Face_handle> zone_faces_, star_;
  std::vector<Edge> zone_edges_;
};

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_FRONTAL_INSERTION_H
