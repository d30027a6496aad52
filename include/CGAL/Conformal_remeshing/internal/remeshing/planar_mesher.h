// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planar stage of the remesher (paper Sec. 4.5, Alg. 5): boundary loops resampled in 3D,
// then CGAL's constrained Delaunay refinement with a shape bound and a size field.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_MESHER_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_MESHER_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_sample.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/frontal_insertion.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_point_map.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/triangle_adjacency.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_2/Do_not_refine_edges.h>
#include <CGAL/Mesh_2/Refine_edges.h>
#include <CGAL/Mesh_2/Refine_faces.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// Mesh_2 criteria: CGAL's shape bound, and a size bound given by a size field on the plane:
/// a triangle is too big when its longest edge exceeds the field at its centroid, or when an
/// edge is longer than the field along it, integrated by the trapezoidal rule over its ends.
/// The field varies fast where the map's scale does: across the wall of a small hole, a narrow
/// conformal band, by a factor of 7 on a plate whose hole is about as deep as it is wide. With
/// the centroid alone, the triangles beside the rim where the scale is small grow to
/// 1.3 times the target on the surface and stand farthest from the input; the edge test bounds
/// them as well. (The smallest of the field at the centroid and the corners would bound
/// them more tightly, but makes smoothly graded meshes of smooth surfaces uneven.)
/// The field at the corners is remembered per point: the refinement judges every face it makes,
/// so each vertex comes back about 25 times, and each evaluation is a point location among the
/// slivers of the flattened input; remembering more than halves the evaluations.
/// A field that takes a hint (see `size_field_at()`) is asked about a face's new corner and its
/// centroid from where it found a corner known before: the refinement takes its bad faces by
/// quality, not by place, so the last query's place was anywhere.
template <typename CDT, typename Size_field>
class Size_field_criteria_2 : public CGAL::Delaunay_mesh_size_criteria_2<CDT>
{
  typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Base;

  struct Corner_size
  {
    double size;
    Size_field_hint hint;
  };
  typedef Planar_point_map<Corner_size> Corner_sizes;

public:
  typedef typename Base::Quality Quality;

  // `Delaunay_mesh_criteria_2`, which holds the shape bound, is a virtual base of `Base`: only the
  // most derived class constructs it, and `Base`'s initializer of it is skipped. Without it here,
  // the bound would be CGAL's default 0.125 (20.7 degrees) whatever the caller asks for.
  Size_field_criteria_2(double shape_bound, const Size_field& size)
    : CGAL::Delaunay_mesh_criteria_2<CDT>(shape_bound), Base(shape_bound, 0.), size_(size),
      corner_sizes_(std::make_shared<Corner_sizes>())
  {}

  class Is_bad : public Base::Is_bad
  {
  public:
    Is_bad(double shape_bound, const Size_field& size, const std::shared_ptr<Corner_sizes>& corner_sizes,
           const typename CDT::Geom_traits& traits)
      : Base::Is_bad(shape_bound, 0., traits), size_(size), corner_sizes_(corner_sizes)
    {}

    Mesh_2::Face_badness operator()(const Quality q) const { return Base::Is_bad::operator()(q); }

    Mesh_2::Face_badness operator()(const typename CDT::Face_handle& fh, Quality& q) const
    {
      Base::Is_bad::operator()(fh, q); // the shape part: q.first is the squared sine of the smallest angle
      const Epick::Point_2 a = to_epick(fh->vertex(0)->point()), b = to_epick(fh->vertex(1)->point()),
                           c = to_epick(fh->vertex(2)->point());
      const double longest = (std::max)({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c), CGAL::squared_distance(c, a)});
      Size_field_hint near = no_size_field_hint;
      const std::array<double, 3> size = corner_sizes({{a, b, c}}, near);
      const double size_a = size[0], size_b = size[1], size_c = size[2];
      const double target = size_field_at(size_, Epick::Point_2((a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3.), near);
      // Each edge's squared length in units of the field, by the trapezoidal rule on 1/size
      // along it: (L (1/s + 1/t) / 2)^2, written so that a constant field gives exactly the
      // centroid's bound (refinements are not to differ by rounding where the field is flat).
      const auto in_field_units = [](double squared_length, double s, double t) {
        return squared_length / (s * t) * (CGAL::square(s + t) / (4. * (s * t)));
      };
      const double along = (std::max)({in_field_units(CGAL::squared_distance(a, b), size_a, size_b),
                                       in_field_units(CGAL::squared_distance(b, c), size_b, size_c),
                                       in_field_units(CGAL::squared_distance(c, a), size_c, size_a)});
      q.second = (std::max)(longest / (target * target), along);
      return operator()(q);
    }

  private:
    template <typename P>
    static Epick::Point_2 to_epick(const P& p) { return Epick::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

    // The field at the corners, those known before first: a new corner is then searched for from
    // where a known one was found, and `near` becomes where the last corner was.
    std::array<double, 3> corner_sizes(const std::array<Epick::Point_2, 3>& corner, Size_field_hint& near) const
    {
      // One lookup per corner, with room for three new ones first: the pointers stay valid.
      std::array<Corner_size*, 3> entry;
      std::array<bool, 3> is_new;
      corner_sizes_->reserve(corner_sizes_->size() + 3);
      for(int c = 0; c < 3; ++c)
      {
        const auto inserted = corner_sizes_->try_emplace(corner[c], Corner_size{0., no_size_field_hint});
        entry[c] = inserted.first;
        is_new[c] = inserted.second;
        if(!is_new[c])
          near = entry[c]->hint;
      }
      std::array<double, 3> size;
      for(int c = 0; c < 3; ++c)
      {
        if(is_new[c])
        {
          entry[c]->hint = near;
          entry[c]->size = size_field_at(size_, corner[c], entry[c]->hint);
          near = entry[c]->hint;
        }
        size[c] = entry[c]->size;
      }
      return size;
    }

    Size_field size_;
    std::shared_ptr<Corner_sizes> corner_sizes_; // shared by the copies the mesher makes
  };

  Is_bad is_bad_object() const { return Is_bad(this->bound(), size_, corner_sizes_, this->traits); }

  /// Where the size field found `p`, if `p` was the corner of a face judged before (a search near
  /// `p` starts best there), else `no_size_field_hint`.
  Size_field_hint hint_at(const Epick::Point_2& p) const
  {
    const Corner_size* known = corner_sizes_->find(p);
    return known == nullptr ? no_size_field_hint : known->hint;
  }

private:
  Size_field size_;
  std::shared_ptr<Corner_sizes> corner_sizes_;
};

/// What the planar mesher keeps in each face of its triangulation.
struct Planar_face_info
{
  int depth = -1;      ///< nesting depth in the loops, for `mark_domain()`
  bool queued = false; ///< in the refinement's queue of bad faces (see `Bad_face_queue_2`)
  // The frontal insertion's state (see `Frontal_inserter_2`): the face's stamp when it was
  // classified (its queue entries with another stamp are stale), whether it is accepted, and
  // its circumradius over the target edge length.
  bool accepted = false;
  std::uint32_t stamp = 0;
  double radius_ratio = 0.;
};

/// The refinement's queue of bad faces: CGAL's `Mesh_2::Refine_faces_base`, the base of
/// `Mesh_2::Refine_faces`, with the same faces in the same order, at less cost. Its map orders
/// the faces by their corner points (`Double_map`: the queue's order among faces of equal quality
/// depends on that order, so it is kept), which CGAL's reads through the face and its vertices
/// at each comparison; here a key holds a copy of the corners. A face flags itself as queued
/// (`Planar_face_info`), so that only the faces of a conflict zone that are queued are searched
/// for, not all of them. The faces' info must be `Planar_face_info`; the corners of a queued face
/// must not change, which holds when insertions replace conflict zones (no flip), as the faces
/// level of `Fixed_boundary_mesher_2` does. Unlike CGAL's, it leaves out the faces whose
/// circumcentre cannot be computed (see `has_refinement_point()`). `Criteria` must be `Size_field_criteria_2`-like: its
/// `Is_bad` object is made once.
template <typename Tr, typename Criteria, typename Previous>
class Bad_face_queue_2 : public CGAL::Triangulation_mesher_level_traits_2<Tr>,
                         public CGAL::No_test_point_conflict,
                         public CGAL::No_after_no_insertion
{
  typedef CGAL::Triangulation_mesher_level_traits_2<Tr> Traits;
  typedef typename Tr::Face_handle Face_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Point Point;
  typedef typename Traits::Zone Zone;
  typedef typename Criteria::Quality Quality;

  struct Face_key
  {
    std::array<Point, 3> corner;
    Face_handle face;
    // one face per corners: a triangulation has no two faces with the same corners in order
    friend bool operator==(const Face_key& a, const Face_key& b) { return a.corner == b.corner; }
  };
  // `Refine_faces_base`'s order: lexicographic on the corners, each compared with `<` and `==`.
  struct Face_key_less
  {
    bool operator()(const Face_key& a, const Face_key& b) const
    {
      for(int i = 0; i < 3; ++i)
      {
        if(a.corner[i] < b.corner[i])
          return true;
        if(!(a.corner[i] == b.corner[i]))
          return false;
      }
      return false;
    }
  };

public:
  typedef CGAL::Double_map<Face_key, Quality, Face_key_less> Bad_faces;

  Bad_face_queue_2(Tr& t, Criteria& criteria, Previous& previous)
    : Traits(t), is_bad_(criteria.is_bad_object()), previous_(previous)
  {}

  // The Mesher_level functions (see `CGAL::Mesher_level`).

  void scan_triangulation_impl()
  {
    bad_faces_.clear();
    for(Face_handle f : this->triangulation_ref_impl().finite_face_handles())
    {
      f->info().queued = false;
      if(f->is_in_domain())
        queue_if_bad(f);
    }
  }

  Zone conflicts_zone_impl(const Point& p, Face_handle f)
  {
    Zone zone;
    zone.fh = this->triangulation_ref_impl().locate(p, zone.locate_type, zone.i, f);
    zone.parent_face = f;
    this->triangulation_ref_impl().get_conflicts_and_boundary(p, std::back_inserter(zone.faces),
                                                               std::back_inserter(zone.boundary_edges), f);
    return zone;
  }

  bool no_longer_element_to_refine_impl() const { return bad_faces_.empty(); }

  Face_handle get_next_element_impl()
  {
    current_badness_ = is_bad_(bad_faces_.front()->first);
    return bad_faces_.front()->second.face;
  }

  void pop_next_element_impl()
  {
    bad_faces_.front()->second.face->info().queued = false;
    bad_faces_.pop_front();
  }

  Point refinement_point_impl(const Face_handle& f) const { return this->triangulation_ref_impl().circumcenter(f); }

  void before_conflicts_impl(const Face_handle&, const Point&)
  {
    previous_.set_imperative_refinement(current_badness_ == Mesh_2::IMPERATIVELY_BAD);
  }

  // The conflict zone's faces leave the domain (and the queue): the new faces take their place.
  void before_insertion_impl(const Face_handle&, const Point&, Zone& zone)
  {
    for(const Face_handle f : zone.faces)
    {
      if(f->info().queued)
      {
        bad_faces_.erase(key(f));
        f->info().queued = false;
      }
      f->set_in_domain(false);
    }
  }

  void after_insertion_impl(const Vertex_handle& v)
  {
    auto f = this->triangulation_ref_impl().incident_faces(v), done = f;
    do
      f->set_in_domain(true);
    while(++f != done);
    do
      if(!this->triangulation_ref_impl().is_infinite(f))
        queue_if_bad(f);
    while(++f != done);
  }

private:
  static Face_key key(Face_handle f) { return Face_key{{{f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()}}, f}; }

  void queue_if_bad(Face_handle f)
  {
    Quality q;
    if(is_bad_(f, q) != Mesh_2::NOT_BAD && has_refinement_point(f) && bad_faces_.insert(key(f), q))
      f->info().queued = true;
  }

  // Faces without a computable circumcentre (see `has_computable_circumcentre()`) are left to the
  // optimization on the surface, which can move their inner corner. (With exact constructions the
  // test is a rounded one, as harmless.)
  static bool has_refinement_point(Face_handle f)
  {
    std::array<Epick::Point_2, 3> p;
    for(int i = 0; i < 3; ++i)
      p[i] = Epick::Point_2(CGAL::to_double(f->vertex(i)->point().x()), CGAL::to_double(f->vertex(i)->point().y()));
    return has_computable_circumcentre(p[0], p[1], p[2]);
  }

  typename Criteria::Is_bad is_bad_;
  Previous& previous_;
  Bad_faces bad_faces_;
  Mesh_2::Face_badness current_badness_ = Mesh_2::NOT_BAD;
};

/// Local Delaunay conformity of constrained edges, also for a point about to be inserted: the
/// rule by which `Fixed_boundary_mesher_2` and the frontal insertion refuse points. The conflict
/// zone reports its boundary edges from the face outside it, `f`: the edge stays locally Delaunay
/// if the point is not inside the circle through the edge and `f`'s far vertex. Across a
/// convex-hull edge (`f` infinite) the point must lie strictly inside: a circumcentre of a thin
/// triangle beside the hull would otherwise be inserted on the edge or beyond it, splitting a
/// boundary chord that the neighbouring patch shares.
template <typename CDT>
struct Fixed_boundary_conforming : CGAL::Mesh_2::Is_locally_conforming_Delaunay<CDT>
{
  using CGAL::Mesh_2::Is_locally_conforming_Delaunay<CDT>::operator();
  bool operator()(const CDT& cdt, const typename CDT::Face_handle& f, int i, const typename CDT::Point& p) const
  {
    if(cdt.is_infinite(f))
    {
      const int at_infinity = f->index(cdt.infinite_vertex());
      return CGAL::orientation(f->vertex(CDT::ccw(at_infinity))->point(), f->vertex(CDT::cw(at_infinity))->point(), p)
             == CGAL::RIGHT_TURN;
    }
    return CGAL::side_of_bounded_circle(f->vertex(CDT::cw(i))->point(), f->vertex(CDT::ccw(i))->point(),
                                        f->vertex(i)->point(), p) != CGAL::ON_BOUNDED_SIDE;
  }
};

/// Delaunay refinement of the faces only, for loops whose samples are shared with a neighbouring
/// patch: no point is ever added on a constrained edge, and a new point is refused only when it
/// would make a constrained edge non-Delaunay (`Fixed_boundary_conforming`). (CGAL's
/// `Delaunay_mesher_no_edge_refinement_2` refuses every point in a constrained edge's diametral
/// circle, which blocks all refinement of a domain whose boundary is sampled more coarsely than
/// its inside needs, like a long cylinder's annulus with a tiny inner circle.) The domain must be
/// marked before.
/// `Queue` is the faces level's base (the queue of bad faces): `Bad_face_queue_2`, or CGAL's
/// `Mesh_2::Refine_faces_base`, which refines in the same order (a test compares them).
template <typename CDT, typename Criteria, template <typename, typename, typename> class Queue = Bad_face_queue_2>
class Fixed_boundary_mesher_2
{
  typedef Fixed_boundary_conforming<CDT> Conforming;
  typedef CGAL::Mesh_2::Refine_edges<CDT, Conforming, CGAL::Mesh_2::Do_not_refine_edges<CDT, Conforming> > Edges_level;
  typedef CGAL::Mesh_2::Refine_faces<CDT, Criteria, Edges_level, Queue<CDT, Criteria, Edges_level> > Faces_level;

public:
  Fixed_boundary_mesher_2(CDT& cdt, const Criteria& criteria)
    : criteria_(criteria), edges_(cdt, null_level_), faces_(cdt, criteria_, edges_)
  {}

  void refine_mesh()
  {
    edges_.scan_triangulation();
    faces_.scan_triangulation();
    faces_.refine(visitor_);
  }

private:
  Criteria criteria_;
  CGAL::Null_mesher_level null_level_;
  CGAL::Null_mesh_visitor visitor_;
  Edges_level edges_;
  Faces_level faces_;
};


/// How many times each surface sample (`Boundary_sample::id`, other than `none`) appears in
/// `loops`: twice on the two sides of a slit.
inline std::map<std::size_t, int> images_per_sample(const std::vector<std::vector<Boundary_sample> >& loops)
{
  std::map<std::size_t, int> images;
  for(const auto& loop : loops)
    for(const Boundary_sample& s : loop)
      if(s.id != Boundary_sample::none)
        ++images[s.id];
  return images;
}

/// A point to insert before the refinement (see `mesh_planar_domain()`), unless a vertex lies
/// within `clearance` of it.
struct Planar_seed
{
  Epick::Point_2 point;
  double clearance;
};

/// The point `origin + t * direction` (`direction` of unit length, `t` > 0) whose surface image
/// is `distance` away from `from`, found by bisection after growing `t` from `guess` by half
/// until the image is far enough; the images' distance to `from` must grow with `t`. False when
/// the ray leaves the flattening first (`surface_point()` below) or `t` reaches `limit`.
/// Each trial point is a lift through the flow's flips, and the 16 steps of a plain bisection
/// can take a quarter of the planar stage of a CAD part whose feature curves are seeded. So the
/// answer is first bracketed closely by regula falsi (Illinois), in 3 to 5
/// lifts, and the bisection lifts only the trial points inside that bracket: the others are on
/// a known side, as the distance grows with `t`. The result is the bisection's, to the bit.
/// (Regula falsi alone, to a ten-thousandth of the distance, moves the seeds by about that much,
/// and the optimization after them amplifies it: on a scanned model the output's distance to
/// the input, set by a detail finer than the target, would vary by half.)
template <typename Surface_point>
bool point_at_surface_distance(const Epick::Point_2& origin, const Epick::Vector_2& direction, const Epick::Point_3& from,
                               double distance, double guess, double limit, const Surface_point& surface_point,
                               Epick::Point_2& uv, Epick::Point_3& point)
{
  bool inside = true;
  double excess = 0.; // of the last trial point's distance over `distance`, for the regula falsi
  auto too_close = [&](double t) {
    Epick::Point_3 x;
    inside = surface_point(origin + t * direction, x);
    const double squared = CGAL::squared_distance(x, from);
    excess = std::sqrt(squared) - distance;
    return squared < distance * distance;
  };
  // [close, far_enough]: the trial points up to `close` are too close, from `far_enough` on not.
  // The origin is taken as too close without a lift, its image as `from` for the interpolation.
  double close = 0., far_enough = guess, at_close = -distance, at_far_enough = 0.;
  while(too_close(far_enough) && inside && far_enough < limit)
  {
    close = far_enough;
    at_close = excess;
    far_enough *= 1.5;
  }
  if(!inside || !(far_enough < limit))
    return false;
  at_far_enough = excess;
  const double far = far_enough;
  // Illinois: an end kept twice in a row has its value halved, so that both ends move.
  int kept = 0; // +1: `close` was kept last time, -1: `far_enough`
  for(int step = 0; step < 40 && far_enough - close > 1e-7 * far; ++step)
  {
    double t = (close * at_far_enough - far_enough * at_close) / (at_far_enough - at_close);
    if(!(t > close && t < far_enough))
      t = 0.5 * (close + far_enough);
    if(too_close(t))
    {
      close = t;
      at_close = excess;
      if(kept == -1)
        at_far_enough *= 0.5;
      kept = -1;
    }
    else
    {
      far_enough = t;
      at_far_enough = excess;
      if(kept == +1)
        at_close *= 0.5;
      kept = +1;
    }
  }
  double near = 0., end = far;
  for(int step = 0; step < 16; ++step)
  {
    const double t = 0.5 * (near + end);
    bool closer = t <= close;
    if(!closer && t < far_enough)
    {
      closer = too_close(t);
      (closer ? close : far_enough) = t;
    }
    (closer ? near : end) = t;
  }
  uv = origin + 0.5 * (near + end) * direction;
  return surface_point(uv, point);
}

/// Seeds for the first `layers` rows of triangles along the loops (each with the domain on its
/// left). Over each chord from `a` to `b` with `seeded(a, b)`, unless `a` or `b` is on a slit (a
/// sample with two images; a slit is a feature chain that ends inside the patch, as a scan's false
/// features, whose seeds would cost a few percent of the edges near the target length and of
/// the distance to the input): the point of the chord's planar
/// bisector whose surface image is as far from the chord's first end as the two ends are from
/// each other, an equilateral triangle on the surface; then over the segment between each two
/// consecutive seeds of a row, the seed of the next row, the same way. `surface_point(p, x)` sets
/// `x` to the image of `p` and returns false when `p` is outside the flattening; such seeds, and
/// those farther than 8 chords, are left out (and the row's segments next to them), and so are
/// the first row's seeds closer than their clearance to one of the two chords of their loop
/// before theirs or after it: near the end of a strip a few tenths of a target wide, an apex
/// would stand a small fraction of the spacing off the strip's other side and leave triangles
/// of 5 to 15 degrees.
/// Why: the refinement cannot split a shared boundary chord, and inserts the circumcentres of the
/// triangles on it, close to it: over the chords of a tube such as the wall of a small hole,
/// whose scale grows by a factor of about 2 across a triangle, the apexes stand at about half
/// the height of an equilateral triangle's, even after the optimization, and these triangles are
/// badly skewed. On a tube, the refinement also makes about twice the points that
/// rows of equilateral triangles need. The optimization only moves points; rows of apexes first
/// let the refinement fill the rest.
template <typename Surface_point>
std::vector<Planar_seed> equilateral_seeds(const std::vector<std::vector<Boundary_sample> >& loops,
                                           const std::function<bool(const Boundary_sample&, const Boundary_sample&)>& seeded,
                                           const Surface_point& surface_point, int layers = 1)
{
  struct Front_point
  {
    Epick::Point_2 uv;
    Epick::Point_3 point;
    bool valid;
    double side; // of the triangle it is the apex of
  };
  std::vector<Planar_seed> seeds;
  // The apex over the chord from a to b, if found and clear of the `near_chords`.
  auto apex = [&](const Front_point& a, const Front_point& b, Front_point& result,
                  const std::vector<Epick::Segment_2>& near_chords = {}) {
    const Epick::Vector_2 chord = b.uv - a.uv;
    const double length = std::sqrt(chord.squared_length());
    if(!(length > 0.))
      return false;
    const Epick::Vector_2 inward(-chord.y() / length, chord.x() / length);
    const Epick::Point_2 middle = CGAL::midpoint(a.uv, b.uv);
    const double side = std::sqrt(CGAL::squared_distance(a.point, b.point));
    // A row's segment much longer or shorter than the triangles it joins (a zigzag boundary)
    // gets no apex: on a sphere cut along its edges, such apexes make triangles of 13 degrees.
    const double below = 0.5 * (a.side + b.side);
    if(below > 0. && (side > 1.33 * below || 1.33 * side < below))
      return false;
    // The surface distance to `a` from the bisector's point at `t` grows with `t`.
    if(!point_at_surface_distance(middle, inward, a.point, side, 0.866 * length, 8. * length, surface_point, result.uv,
                                  result.point))
      return false;
    const double clearance = 0.6 * std::sqrt((std::min)(CGAL::squared_distance(result.uv, a.uv), CGAL::squared_distance(result.uv, b.uv)));
    for(const Epick::Segment_2& chord : near_chords)
      if(CGAL::squared_distance(chord, result.uv) < clearance * clearance)
        return false;
    result.valid = true;
    result.side = side;
    seeds.push_back(Planar_seed{result.uv, clearance});
    return true;
  };
  const std::map<std::size_t, int> images = images_per_sample(loops);
  auto on_slit = [&](const Boundary_sample& s) { return s.id != Boundary_sample::none && images.at(s.id) > 1; };
  for(const auto& loop : loops)
  {
    std::vector<Front_point> front;
    for(const Boundary_sample& s : loop)
      front.push_back(Front_point{s.uv, s.point, true, 0.});
    for(int layer = 0; layer < layers; ++layer)
    {
      std::vector<Front_point> next(front.size(), Front_point{Epick::Point_2(), Epick::Point_3(), false, 0.});
      bool any = false;
      for(std::size_t i = 0; i < front.size(); ++i)
      {
        const std::size_t n = front.size();
        const Front_point &a = front[i], &b = front[(i + 1) % n];
        const Boundary_sample &s = loop[i], &t = loop[(i + 1) % n];
        if(layer > 0)
          any = (a.valid && b.valid && apex(a, b, next[i])) || any;
        else if(!on_slit(s) && !on_slit(t) && seeded(s, t))
        {
          std::vector<Epick::Segment_2> near_chords;
          for(std::size_t k : {n - 2, n - 1, std::size_t(1), std::size_t(2)}) // the chord from i + k
            if(n > 2 && (i + k) % n != i)
              near_chords.emplace_back(loop[(i + k) % n].uv, loop[(i + k + 1) % n].uv);
          any = apex(a, b, next[i], near_chords) || any;
        }
      }
      if(!any)
        break;
      front.swap(next);
    }
  }
  return seeds;
}

/// Seeds for the first ring of triangles around each of the `centres` (the fixed points, see
/// kept_input_vertices.h; each a planar point and its surface image): six points 60 degrees
/// apart in the plane, each a target length away from the centre on the surface.
/// `target_lengths(p)` gives the target edge length at `p` on the surface and in the plane (the
/// search's first guess); `surface_point()` is as for equilateral_seeds(). Why: a fixed point
/// pins the optimization, and the refinement's points around it are wherever its triangles'
/// circumcentres fall (on a coarse spherical cap with hundreds of kept tips, these rings take
/// back about a third of the mean skewness that the fixed points cost).
template <typename Target_lengths, typename Surface_point>
std::vector<Planar_seed> seeds_around_points(const std::vector<std::pair<Epick::Point_2, Epick::Point_3> >& centres,
                                             const Target_lengths& target_lengths, const Surface_point& surface_point)
{
  std::vector<Planar_seed> seeds;
  for(const auto& c : centres)
  {
    const Epick::Point_2& centre = c.first;
    const Epick::Point_3& centre_point = c.second;
    const std::pair<double, double> length = target_lengths(centre); // on the surface, in the plane
    for(int k = 0; k < 6; ++k)
    {
      const Epick::Vector_2 direction(std::cos(k * CGAL_PI / 3.), std::sin(k * CGAL_PI / 3.));
      Epick::Point_2 uv;
      Epick::Point_3 point;
      if(point_at_surface_distance(centre, direction, centre_point, length.first, length.second, 8. * length.second,
                                   surface_point, uv, point))
        seeds.push_back(Planar_seed{uv, 0.6 * std::sqrt(CGAL::squared_distance(uv, centre))});
    }
  }
  return seeds;
}

/// How `mesh_planar_domain()` smooths its refinement: Laplacian passes in the surface's metric,
/// then CGAL's Lloyd smoothing in the plane (`lloyd_optimize_mesh_2()`), each followed by a
/// refinement that restores the bounds. (Implicit from an `int`: that many Laplacian passes.)
struct Planar_smoothing
{
  Planar_smoothing(int laplacian = 1, int lloyd = 0, double lloyd_time_limit = 0.)
    : laplacian_iterations(laplacian), lloyd_iterations(lloyd), lloyd_seconds(lloyd_time_limit)
  {}

  int laplacian_iterations;
  int lloyd_iterations; ///< at most this many; CGAL stops earlier when the moves become small
  /// CGAL's time limit on the Lloyd smoothing (0: none), in CPU seconds of the process (all its
  /// threads: with patches meshed in parallel it stops earlier than the wall clock says)
  double lloyd_seconds;
};

/// A planar triangle mesh: the boundary samples first, in loop order, then the fixed interior
/// points in their order, then the points the refinement added.
struct Planar_mesh
{
  std::vector<Epick::Point_2> points;
  std::size_t number_of_samples = 0;
  std::size_t number_of_fixed_points = 0; ///< the samples and the fixed interior points
  std::vector<std::array<int, 3> > triangles; // counterclockwise
  /// wall seconds of the first refinement, and of the smoothing with the refinements after it
  double seconds_refinement = 0., seconds_smoothing = 0.;
};

/// The face base of the planar mesher's triangulations (and of any that `mark_domain()` marks):
/// CGAL's for Delaunay meshing, with `Planar_face_info` as the face's info.
template <typename Kernel>
using Planar_face_base_2 = CGAL::Delaunay_mesh_face_base_2<
  Kernel, CGAL::Constrained_Delaunay_triangulation_face_base_2<
            Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<Planar_face_info, Kernel> > > >;

/// The constrained Delaunay triangulation of the planar mesher: a vertex's info is its number in
/// the output (and a count in `separate_images_of_one_sample()`), a face's is `Planar_face_info`.
template <typename Kernel>
struct Planar_triangulation
{
  typedef CGAL::Delaunay_mesh_vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<int, Kernel> > Vb;
  typedef CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb, Planar_face_base_2<Kernel> >,
                                                     CGAL::Exact_predicates_tag>
    type;
};

// Marks the faces of `cdt` at odd nesting depth (counting constraints crossed from the
// infinite face) as the domain: the outer loop's inside minus the holes. The faces' info
// (`Planar_face_info`, see `Planar_face_base_2`) holds their depth while it runs (-1: not reached
// yet), rather than a hash map from face to depth, which would take as long as the walk itself.
template <typename CDT>
void mark_domain(CDT& cdt)
{
  typedef typename CDT::Face_handle Face_handle;
  for(Face_handle f : cdt.all_face_handles())
    f->info().depth = -1;
  std::vector<std::pair<Face_handle, int> > frontier{{cdt.infinite_face(), 0}}; // in order, from `next` on
  std::vector<Face_handle> stack;
  for(std::size_t next = 0; next < frontier.size(); ++next)
  {
    const std::pair<Face_handle, int> seed = frontier[next];
    if(seed.first->info().depth >= 0)
      continue;
    seed.first->info().depth = seed.second;
    stack.assign(1, seed.first);
    while(!stack.empty())
    {
      const Face_handle f = stack.back();
      stack.pop_back();
      f->set_in_domain(seed.second % 2 == 1);
      for(int i = 0; i < 3; ++i)
      {
        const Face_handle g = f->neighbor(i);
        if(g->info().depth >= 0)
          continue;
        if(cdt.is_constrained(std::make_pair(f, i)))
          frontier.emplace_back(g, seed.second + 1);
        else
        {
          g->info().depth = seed.second;
          stack.push_back(g);
        }
      }
    }
  }
}

// A point inside each hole of a domain that `mark_domain()` marked (a component of faces at an
// even nesting depth above 0): CGAL's Lloyd smoothing marks the domain again after each of its
// iterations from seeds of the outside, and without them would take the holes for the domain.
template <typename CDT>
std::vector<typename CDT::Point> hole_seeds(const CDT& cdt)
{
  typedef typename CDT::Face_handle Face_handle;
  std::vector<typename CDT::Point> seeds;
  std::set<Face_handle> reached;
  for(Face_handle f : cdt.finite_face_handles())
  {
    if(f->info().depth <= 0 || f->info().depth % 2 == 1 || !reached.insert(f).second)
      continue;
    seeds.push_back(CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    std::vector<Face_handle> stack{f};
    while(!stack.empty())
    {
      const Face_handle g = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
        if(!cdt.is_constrained(std::make_pair(g, i)) && reached.insert(g->neighbor(i)).second)
          stack.push_back(g->neighbor(i));
    }
  }
  return seeds;
}

// CGAL's Lloyd smoothing (`lloyd_optimize_mesh_2()`, at most `smoothing.lloyd_iterations`
// iterations, within `smoothing.lloyd_seconds` when positive) of the marked domain of `cdt`: it
// moves every vertex without a constraint, toward the centroid of its Voronoi cell with the
// density of the mesh's own edge lengths (so the grading stays). The
// `fixed` points then go back where they were, each in place of the free vertex nearest to it
// (the one that moved away: a Lloyd move stays in the vertex's Voronoi cell). Needs a kernel
// with floating-point constructions (CGAL's Lloyd smoothing takes square roots).
template <typename CDT>
void lloyd_smooth(CDT& cdt, const Planar_smoothing& smoothing, const std::set<typename CDT::Point>& fixed)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  if constexpr(!std::is_floating_point<typename CDT::Geom_traits::FT>::value)
    throw Error(Error_code::INVALID_INPUT, "Lloyd smoothing in the plane needs a kernel with floating-point constructions");
  else
  {
    mark_domain(cdt); // the refinement's new faces have no depth yet
    const std::vector<typename CDT::Point> seeds = hole_seeds(cdt);
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = smoothing.lloyd_iterations,
                                CGAL::parameters::time_limit = smoothing.lloyd_seconds,
                                CGAL::parameters::seeds_begin = seeds.begin(), CGAL::parameters::seeds_end = seeds.end(),
                                CGAL::parameters::mark = false);
    for(const typename CDT::Point& p : fixed)
    {
      typename CDT::Locate_type type;
      int i = 0;
      const typename CDT::Face_handle f = cdt.locate(p, type, i);
      if(type == CDT::VERTEX)
        continue;
      Vertex_handle nearest;
      const auto consider = [&](Vertex_handle w) {
        if(cdt.is_infinite(w) || cdt.are_there_incident_constraints(w) || fixed.count(w->point()))
          return;
        if(nearest == Vertex_handle() || CGAL::squared_distance(w->point(), p) < CGAL::squared_distance(nearest->point(), p))
          nearest = w;
      };
      for(int c = 0; c < 3; ++c)
      {
        consider(f->vertex(c));
        if(cdt.is_infinite(f->vertex(c)))
          continue;
        auto w = cdt.incident_vertices(f->vertex(c)), done = w;
        do
          consider(w);
        while(++w != done);
      }
      if(nearest != Vertex_handle())
        cdt.remove(nearest);
      cdt.insert(p);
    }
  }
}

// See `mesh_planar_domain()`. Bounded: splitting an edge at a slit's tip moves the problem away
// from the tip, and a few rounds clear it; the refinement is not run again (shapes near a slit's
// tip may fall below the angle bound). The vertices' info (an integer) is overwritten.
template <typename CDT, typename Vertex_at>
void separate_images_of_one_sample(CDT& cdt, const std::vector<std::vector<Boundary_sample> >& loops, const Vertex_at& vertex_at)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  std::map<Vertex_handle, std::size_t> id_of;
  std::map<std::size_t, int> images = images_per_sample(loops);
  for(const auto& loop : loops)
    for(const Boundary_sample& s : loop)
      if(s.id != Boundary_sample::none && images[s.id] > 1)
      {
        const Vertex_handle v = vertex_at(cdt, typename CDT::Point(s.uv.x(), s.uv.y()));
        if(v != Vertex_handle())
          id_of[v] = s.id;
      }
  if(id_of.empty())
    return;
  for(int round = 0; round < 8; ++round)
  {
    // Only a vertex joined to two images can join two images of one sample: the vertices' info
    // counts their neighbours among the images first, and the others are skipped.
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      v->info() = 0;
    for(const auto& image : id_of)
    {
      auto w = cdt.incident_vertices(image.first), done = w;
      do
        ++w->info();
      while(++w != done);
    }
    std::vector<typename CDT::Point> midpoints;
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    {
      if(v->info() < 2 || cdt.are_there_incident_constraints(v))
        continue; // a sample: two samples are kept apart by `diagonals_to_split`
      std::set<std::size_t> seen;
      auto w = cdt.incident_vertices(v), done = w;
      do
      {
        const Vertex_handle neighbour = w;
        const auto image = id_of.find(neighbour);
        if(image != id_of.end() && !seen.insert(image->second).second)
        {
          midpoints.push_back(CGAL::midpoint(v->point(), w->point()));
          break;
        }
      }
      while(++w != done);
    }
    if(midpoints.empty())
      return;
    cdt.insert(midpoints.begin(), midpoints.end());
  }
}

// The vertex of `cdt` at `p`, or a null handle if `p` is no vertex.
template <typename CDT>
typename CDT::Vertex_handle planar_vertex_at(const CDT& cdt, const typename CDT::Point& p)
{
  typename CDT::Locate_type type;
  int i = 0;
  const typename CDT::Face_handle f = cdt.locate(p, type, i);
  return type == CDT::VERTEX ? f->vertex(i) : typename CDT::Vertex_handle();
}

// Splits the edges of the domain of `cdt` that join the samples of a pair in `diagonals_to_split`
// (positions in `sample_points`, the samples in loop order) and are no constraint, at their
// midpoints. The midpoint of an edge lies inside the circumcircle of both its triangles: the edge
// goes. Returns whether it inserted a point.
template <typename CDT>
bool split_sample_diagonals(CDT& cdt, const std::vector<std::pair<std::size_t, std::size_t> >& diagonals_to_split,
                            const std::vector<typename CDT::Point>& sample_points)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  std::vector<typename CDT::Point> midpoints;
  for(const auto& pair : diagonals_to_split)
  {
    const Vertex_handle a = planar_vertex_at(cdt, sample_points.at(pair.first)), b = planar_vertex_at(cdt, sample_points.at(pair.second));
    typename CDT::Face_handle f;
    int i = 0;
    if(a != Vertex_handle() && b != Vertex_handle() && cdt.is_edge(a, b, f, i) && !cdt.is_constrained(std::make_pair(f, i))
       && f->is_in_domain())
      midpoints.push_back(CGAL::midpoint(a->point(), b->point()));
  }
  cdt.insert(midpoints.begin(), midpoints.end());
  return !midpoints.empty();
}

// A refinement of `mesh_planar_domain()`: the domain of `cdt` marked, the diagonals to split split
// (see `split_sample_diagonals()`), the frontal insertion when it is on, then CGAL's Delaunay
// refinement, which may split the loops' chords when `split_boundary` is on, else
// `Fixed_boundary_mesher_2`, which may not.
template <typename CDT, typename Criteria, typename Size_field>
void refine_planar_domain(CDT& cdt, const Criteria& criteria, const Size_field& size, bool split_boundary,
                          const Frontal_insertion& frontal,
                          const std::vector<std::pair<std::size_t, std::size_t> >& diagonals_to_split,
                          const std::vector<typename CDT::Point>& sample_points)
{
  mark_domain(cdt);
  if(split_sample_diagonals(cdt, diagonals_to_split, sample_points))
    mark_domain(cdt);
  if(frontal.is_on())
  {
    Frontal_inserter_2<CDT, Size_field, Fixed_boundary_conforming<CDT> > inserter(cdt, size, frontal);
    inserter.run();
  }
  if(split_boundary)
  {
    CGAL::Delaunay_mesher_2<CDT, Criteria> mesher(cdt, criteria);
    mesher.init(true);
    mesher.refine_mesh();
  }
  else
  {
    Fixed_boundary_mesher_2<CDT, Criteria> mesher(cdt, criteria);
    mesher.refine_mesh();
  }
}

// Inserts the samples of each of the `loops` into `cdt`, with the loop's chords as constraints.
template <typename CDT>
void insert_boundary_loops(CDT& cdt, const std::vector<std::vector<Boundary_sample> >& loops)
{
  typedef typename CDT::Point Point;
  for(const auto& loop : loops)
  {
    std::vector<typename CDT::Vertex_handle> handles;
    for(const Boundary_sample& s : loop)
      handles.push_back(cdt.insert(Point(s.uv.x(), s.uv.y())));
    for(std::size_t i = 0; i < handles.size(); ++i)
      cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
  }
}

// Inserts the `seeds` inside the domain of `cdt` (its loops and fixed points inserted), in order,
// each unless a vertex is closer than its clearance, and adds those inserted to `fixed`.
template <typename CDT>
void insert_planar_seeds(CDT& cdt, const std::vector<Planar_seed>& seeds, std::set<typename CDT::Point>& fixed)
{
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Point Point;
  if(seeds.empty())
    return;
  mark_domain(cdt);
  std::vector<Planar_seed> inside;
  for(const Planar_seed& seed : seeds)
  {
    typename CDT::Locate_type type;
    int i = 0;
    const Face_handle f = cdt.locate(Point(seed.point.x(), seed.point.y()), type, i);
    if(type == CDT::FACE && f->is_in_domain())
      inside.push_back(seed);
  }
  // Each seed is checked against the vertices of the face it falls in and their neighbours:
  // the seeds before it, the samples and the fixed points. (Located again: the domain marks
  // hold for the faces before the first seed's insertion only.)
  for(const Planar_seed& seed : inside)
  {
    const Point p(seed.point.x(), seed.point.y());
    const Face_handle f = cdt.locate(p);
    bool clear = true;
    for(int c = 0; c < 3 && clear; ++c)
    {
      auto n = cdt.incident_vertices(f->vertex(c)), done = n;
      do
        clear = cdt.is_infinite(n) || !(CGAL::squared_distance(n->point(), p) < CGAL::square(seed.clearance));
      while(clear && ++n != done);
    }
    if(clear)
      fixed.insert(cdt.insert(p, f)->point());
  }
}

// One pass of the Laplacian smoothing of `mesh_planar_domain()`: each vertex of `cdt` without a
// constraint and not in `fixed` moves to the mean of its neighbours in the surface's metric (the
// plane scaled by `size`) when its star stays positively oriented; the points are triangulated
// again with the same constraints, refined by `refine(t)`, and the result replaces `cdt`.
template <typename CDT, typename Criteria, typename Size_field, typename Refine>
void laplacian_smooth(CDT& cdt, const std::set<typename CDT::Point>& fixed, const Criteria& criteria, const Size_field& size,
                      const Refine& refine)
{
  typedef typename CDT::Point Point;
  std::vector<std::pair<Point, Point> > constraints;
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if(cdt.is_constrained(*e))
      constraints.emplace_back(e->first->vertex(CDT::cw(e->second))->point(), e->first->vertex(CDT::ccw(e->second))->point());
  std::vector<Point> free_points;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    if(cdt.are_there_incident_constraints(v))
      continue;
    if(fixed.count(v->point()))
    {
      free_points.push_back(v->point());
      continue;
    }
    // The mean of the neighbours in the surface's metric: the plane is scaled by the size field,
    // so each neighbour weighs 1 / size^2 at the edge's midpoint.
    // The field's searches start where the refinement found the vertex: the vertices come in
    // the order the refinement made them, worst face first, far from the last one.
    double x = 0., y = 0., n = 0.;
    const double vx = CGAL::to_double(v->point().x()), vy = CGAL::to_double(v->point().y());
    Size_field_hint near = criteria.hint_at(Epick::Point_2(vx, vy));
    auto c = cdt.incident_vertices(v), done = c;
    do
      if(!cdt.is_infinite(c))
      {
        const double cx = CGAL::to_double(c->point().x()), cy = CGAL::to_double(c->point().y());
        const double local = size_field_at(size, Epick::Point_2(0.5 * (vx + cx), 0.5 * (vy + cy)), near);
        const double w = 1. / (local * local);
        x += w * cx;
        y += w * cy;
        n += w;
      }
    while(++c != done);
    const Point moved(x / n, y / n);
    bool star_stays_positive = true;
    auto f = cdt.incident_faces(v), first = f;
    do
    {
      const int i = f->index(v);
      star_stays_positive = star_stays_positive && !cdt.is_infinite(f)
                            && CGAL::orientation(moved, f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point()) == CGAL::POSITIVE;
    }
    while(++f != first);
    free_points.push_back(star_stays_positive ? moved : v->point());
  }
  CDT smoothed;
  for(const auto& c : constraints)
    smoothed.insert_constraint(c.first, c.second);
  smoothed.insert(free_points.begin(), free_points.end());
  refine(smoothed);
  cdt.swap(smoothed);
}

// The output of `mesh_planar_domain()` from its last triangulation `cdt`: where a vertex joins two
// images of one sample, the edge to one of them split first (see
// `separate_images_of_one_sample()`); then the boundary samples in loop order, the
// `fixed_points` in their order and the other vertices, and the faces of the domain. Throws
// `Error` if a sample or a fixed point is no vertex. The vertices' info is overwritten.
template <typename CDT>
Planar_mesh planar_mesh_of_refinement(CDT& cdt, const std::vector<std::vector<Boundary_sample> >& loops,
                                      const std::vector<Epick::Point_2>& fixed_points)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Point Point;
  // The samples and the fixed points are found by their coordinates in one table of the vertices:
  // a location in the triangulation walks from the same face each time, across hundreds of faces.
  const auto to_epick = [](const Point& p) { return Epick::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); };
  Planar_point_map<Vertex_handle> vertex_of;
  vertex_of.reserve(cdt.number_of_vertices());
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    vertex_of.try_emplace(to_epick(v->point()), v);
  // (Two points of an exact kernel may round to one pair of doubles: then the triangulation's.)
  const auto final_vertex_at = [&](const CDT& t, const Point& p) {
    const Vertex_handle* v = vertex_of.find(to_epick(p));
    return v != nullptr && (*v)->point() == p ? *v : planar_vertex_at(t, p);
  };
  separate_images_of_one_sample(cdt, loops, final_vertex_at); // inserts points, moves none
  mark_domain(cdt);

  // Output: the boundary samples first, in loop order, then the other vertices.
  Planar_mesh result;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    v->info() = -1;
  const auto number = [&result](Vertex_handle v) {
    if(v->info() >= 0)
      return false;
    v->info() = int(result.points.size());
    return true;
  };
  for(const auto& loop : loops)
    for(const Boundary_sample& s : loop)
    {
      const Vertex_handle v = final_vertex_at(cdt, Point(s.uv.x(), s.uv.y()));
      if(v == Vertex_handle())
        throw Error(Error_code::INVALID_INPUT, "planar meshing lost a boundary sample (internal error)");
      if(number(v))
        result.points.push_back(s.uv);
    }
  result.number_of_samples = result.points.size();
  for(const Epick::Point_2& p : fixed_points)
  {
    const Vertex_handle v = final_vertex_at(cdt, Point(p.x(), p.y()));
    if(v == Vertex_handle() || !number(v))
      throw Error(Error_code::INVALID_INPUT, "planar meshing lost a fixed point (internal error)");
    result.points.push_back(p);
  }
  result.number_of_fixed_points = result.points.size();
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if(number(v))
      result.points.push_back(to_epick(v->point()));
  for(Face_handle f : cdt.finite_face_handles())
    if(f->is_in_domain())
      result.triangles.push_back({{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}});
  return result;
}

/// Meshes the domain bounded by `loops` (outer loop first) with CGAL's constrained Delaunay
/// refinement over `Kernel`: a minimum angle of `min_angle_degrees` (up to the refinement's
/// guarantees near small input angles) and a longest edge below `size(p)` at each triangle's
/// centroid, and every edge below `size` along it (see `Size_field_criteria_2`). When `frontal`
/// is on, each refinement starts from points placed by frontal insertion (see
/// `Frontal_inserter_2`), in rows of nearly equilateral triangles, and refines only where the
/// fronts met. Then
/// `smoothing.laplacian_iterations` passes of Laplacian smoothing of the free vertices: each moves
/// to the mean of its neighbours when its star stays positively oriented, the points are
/// triangulated again with the same constraints and refined again, so the bounds still hold. Then,
/// if `smoothing.lloyd_iterations` is positive, CGAL's Lloyd smoothing and one more refinement
/// (see `lloyd_smooth()`; over a kernel with exact constructions it throws `Error`).
/// With `split_boundary == false` no point is added on the loops (their samples are shared with
/// a neighbouring patch; see `Fixed_boundary_mesher_2`). No edge joins the samples of a pair in
/// `diagonals_to_split` (positions in the loops, taken one after the other) unless it is a loop
/// chord: where the triangulation of the samples has one, its midpoint is inserted first, and as
/// refinement only adds edges at new points, it never comes back. Last, a vertex joined to two
/// images of one sample (`Boundary_sample::id`: the sides of a slit, near its tip) would join
/// one surface point twice: the edge to one of them is split at its midpoint, until none is left.
/// The `fixed_points` (inside the domain, apart from the loops) are vertices of the mesh that no
/// smoothing moves. The `seeds` inside the domain are inserted before the refinement, in
/// order, each unless a vertex is closer than its clearance (see `equilateral_seeds()`); no
/// smoothing moves them either (the Laplacian mean in the plane pulls a seed toward the side where
/// the map's scale is smaller: on a flattened tube, it would about halve the first row's height
/// on the surface).
template <typename Kernel, typename Size_field>
Planar_mesh mesh_planar_domain(const std::vector<std::vector<Boundary_sample> >& loops, double min_angle_degrees,
                               const Size_field& size, const Planar_smoothing& smoothing, bool split_boundary = true,
                               const std::vector<std::pair<std::size_t, std::size_t> >& diagonals_to_split = {},
                               const std::vector<Epick::Point_2>& fixed_points = {},
                               const std::vector<Planar_seed>& seeds = {}, const Frontal_insertion& frontal = {})
{
  typedef typename Planar_triangulation<Kernel>::type CDT;
  typedef typename Kernel::Point_2 Point;
  typedef Size_field_criteria_2<CDT, Size_field> Criteria;
  const double sine = std::sin(min_angle_degrees * CGAL_PI / 180.);

  std::vector<Point> sample_points;
  for(const auto& loop : loops)
    for(const Boundary_sample& s : loop)
      sample_points.push_back(Point(s.uv.x(), s.uv.y()));

  // One criteria object for every refinement: the field at the corners it remembers still holds
  // after the smoothing, at the points the smoothing did not move.
  const Criteria criteria(sine * sine, size);
  const auto refine = [&](CDT& t) {
    refine_planar_domain(t, criteria, size, split_boundary, frontal, diagonals_to_split, sample_points);
  };

  CDT cdt;
  insert_boundary_loops(cdt, loops);
  std::set<Point> fixed;
  for(const Epick::Point_2& p : fixed_points)
    fixed.insert(cdt.insert(Point(p.x(), p.y()))->point());
  insert_planar_seeds(cdt, seeds, fixed);
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point refinement_start = Clock::now();
  refine(cdt);
  const Clock::time_point smoothing_start = Clock::now();

  for(int iteration = 0; iteration < smoothing.laplacian_iterations; ++iteration)
    laplacian_smooth(cdt, fixed, criteria, size, refine);
  if(smoothing.lloyd_iterations > 0)
  {
    lloyd_smooth(cdt, smoothing, fixed);
    refine(cdt);
  }
  const Clock::time_point smoothing_end = Clock::now();

  Planar_mesh result = planar_mesh_of_refinement(cdt, loops, fixed_points);
  result.seconds_refinement = std::chrono::duration<double>(smoothing_start - refinement_start).count();
  result.seconds_smoothing = std::chrono::duration<double>(smoothing_end - smoothing_start).count();
  return result;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_MESHER_H
