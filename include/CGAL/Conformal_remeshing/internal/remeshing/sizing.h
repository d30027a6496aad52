// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The target edge length on the surface, in 3D units (uniform, a user field, or adaptive to
// curvature with a chord-error bound). The planar mesher turns it into a planar size: the 3D
// target length times the local scale of the map (planar length over surface length). The
// boundary sampler spaces samples by it.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SIZING_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SIZING_H

#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// Where another sheet of the surface is a gap away (proximity.h), the chords of the output may
/// stand off the surface by at most this times the gap: the chords of both sheets may bend
/// towards each other.
constexpr double gap_chord_error = 0.5;

/// A size bounded to [1/16, 1] times `target`; `target` where it is not finite.
inline double bounded_size(double size, double target)
{
  return std::isfinite(size) ? (std::min)(target, (std::max)(size, target / 16.)) : target;
}

/// The size at `p` graded from a corner of size `corner_size` at `corner`: the corner's size plus
/// `gradation` times the distance to it, at most `target`.
inline double graded_size(const Epick::Point_3& p, const Epick::Point_3& corner, double corner_size, double target, double gradation)
{
  return (std::min)(target, corner_size + gradation * std::sqrt(CGAL::squared_distance(p, corner)));
}

/// Sizes bounded near a few places: `sizes[i]` at `points[i]`, growing by `gradation` times the
/// distance to it; the bound at a point is the smallest over the places. These are the sizes for
/// meshing again near the places where an output intersected itself or strayed farther from the
/// surface than the distance bound (a few, thinned: see `add_if_far()` and surface_distance.h).
/// Kept as data, not as a function, so that a patch job can tell whether they reach its patch.
struct Local_refinement
{
  std::vector<Epick::Point_3> points;
  std::vector<double> sizes; ///< one per point
  double gradation = 0.5;

  bool empty() const { return points.empty(); }

  /// Adds the places `at`, each of size `size`.
  void add(const std::vector<Epick::Point_3>& at, double size)
  {
    points.insert(points.end(), at.begin(), at.end());
    sizes.insert(sizes.end(), at.size(), size);
  }

  /// The bound at `p`; infinite when there are no places.
  double at(const Epick::Point_3& p) const
  {
    double bound = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < points.size(); ++i)
      bound = (std::min)(bound, sizes[i] + gradation * std::sqrt(CGAL::squared_distance(p, points[i])));
    return bound;
  }

  /// The places whose bound can be below `target` somewhere in `box`.
  Local_refinement within(const Bbox_3& box, double target) const
  {
    Local_refinement result;
    result.gradation = gradation;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const Epick::Point_3& q = points[i];
      double squared = 0.;
      for(int k = 0; k < 3; ++k)
      {
        const double gap = (std::max)((std::max)(box.min(k) - q[k], q[k] - box.max(k)), 0.);
        squared += gap * gap;
      }
      if(sizes[i] + gradation * std::sqrt(squared) * (1. - 1e-12) < target) // a margin for the rounding of the distance
      {
        result.points.push_back(q);
        result.sizes.push_back(sizes[i]);
      }
    }
    return result;
  }

  friend bool operator==(const Local_refinement& a, const Local_refinement& b)
  {
    return a.points == b.points && a.sizes == b.sizes && (a.points.empty() || a.gradation == b.gradation);
  }
};

/// `Local_refinement::at()` for many points, in a time that does not grow with the number of
/// places: only the bound below `cap` matters (the sizes are bounded to the target), and a place
/// of size `s` bounds nothing below `cap` farther than its reach `(cap - s) / gradation`. The
/// places are hashed into cells of the largest reach; a query looks at its cell and the 26 around
/// it. Below `cap`, `at()` is exactly `Local_refinement::at()` (the same expression, place by
/// place, and the smallest of them); at or above it, some value at or above `cap`. Few places
/// are scanned as they are.
class Local_refinement_lookup
{
public:
  Local_refinement_lookup() = default;
  Local_refinement_lookup(const Local_refinement& refinement, double cap) : gradation_(refinement.gradation)
  {
    const std::vector<double>& sizes = refinement.sizes;
    const double smallest = sizes.empty() ? 0. : *std::min_element(sizes.begin(), sizes.end());
    if(sizes.size() < minimum_places_for_cells || !(refinement.gradation > 0.) || !(smallest < 0.999 * cap))
    {
      points_ = refinement.points; // scanned: few, or reaching about as far as the cap
      sizes_ = sizes;
      return;
    }
    cell_ = (cap - smallest) / refinement.gradation * (1. + 1e-9); // a margin for the rounding of the distances
    std::vector<std::pair<Key, std::size_t> > keyed(sizes.size());
    for(std::size_t i = 0; i < sizes.size(); ++i)
      keyed[i] = {key(cell_of(refinement.points[i])), i};
    std::sort(keyed.begin(), keyed.end());
    for(std::size_t k = 0; k < keyed.size(); ++k)
    {
      if(k == 0 || keyed[k].first != keyed[k - 1].first)
        cells_.emplace(keyed[k].first, std::make_pair(k, k));
      ++cells_[keyed[k].first].second;
      points_.push_back(refinement.points[keyed[k].second]);
      sizes_.push_back(sizes[keyed[k].second]);
    }
  }

  double at(const Epick::Point_3& p) const
  {
    if(cells_.empty())
      return smallest_bound(p, 0, points_.size());
    const std::array<long, 3> c = cell_of(p);
    double bound = std::numeric_limits<double>::infinity();
    for(long dx = -1; dx <= 1; ++dx)
      for(long dy = -1; dy <= 1; ++dy)
        for(long dz = -1; dz <= 1; ++dz)
        {
          const auto found = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if(found != cells_.end())
            bound = (std::min)(bound, smallest_bound(p, found->second.first, found->second.second));
        }
    // The places of the other cells are more than a cell, a reach, away: their bounds are above
    // the cap.
    return bound;
  }

private:
  typedef unsigned long long Key;
  static constexpr std::size_t minimum_places_for_cells = 64;

  // The expression of `Local_refinement::at()`, over places `first` to `last`.
  double smallest_bound(const Epick::Point_3& p, std::size_t first, std::size_t last) const
  {
    double bound = std::numeric_limits<double>::infinity();
    for(std::size_t i = first; i < last; ++i)
      bound = (std::min)(bound, sizes_[i] + gradation_ * std::sqrt(CGAL::squared_distance(p, points_[i])));
    return bound;
  }
  std::array<long, 3> cell_of(const Epick::Point_3& p) const
  {
    const auto index = [&](double x) { return long((std::max)(-1e15, (std::min)(1e15, std::floor(x / cell_)))); };
    return {index(p.x()), index(p.y()), index(p.z())};
  }
  // 21 bits a coordinate: cells that differ by a multiple of 2^21 share a key, which costs
  // distance computations, never a place.
  static Key key(const std::array<long, 3>& c)
  {
    const Key mask = (Key(1) << 21) - 1;
    return (Key(c[0]) & mask) | ((Key(c[1]) & mask) << 21) | ((Key(c[2]) & mask) << 42);
  }

  double gradation_ = 0.5;
  double cell_ = 0.;
  std::vector<Epick::Point_3> points_; // by cell when there are cells
  std::vector<double> sizes_;
  std::unordered_map<Key, std::pair<std::size_t, std::size_t> > cells_; // ranges of `points_`
};

/// The size the user's `field` and `refinement` give at `p`, before bounding (see
/// `bounded_size()`): the smaller of the two, infinite where neither is given.
inline double field_size(const std::function<double(const Epick::Point_3&)>& field, const Local_refinement& refinement,
                         const Epick::Point_3& p)
{
  if(refinement.empty())
    return field ? field(p) : std::numeric_limits<double>::infinity();
  const double local = refinement.at(p);
  return field ? (std::min)(field(p), local) : local;
}

/// `field_size()` with the refinement's places looked up in `places` (capped at the target: what
/// `bounded_size()` makes of it is the same).
inline double field_size(const std::function<double(const Epick::Point_3&)>& field, const Local_refinement_lookup& places,
                         const Epick::Point_3& p)
{
  const double local = places.at(p);
  return field ? (std::min)(field(p), local) : local;
}

struct Patch_job_serialization;

/// The size field of `Sizing` on one patch, as a value of its own: the sizes at the corners of
/// each patch face, the user's field and the local refinements that reach the patch. A patch job
/// carries it (see patch_job.h) instead of the segmentation it was computed on. Two fields of the
/// same call compare equal (`same_sizes()`) when they give the same sizes: the user's field is
/// one function for the whole call.
class Patch_size_field
{
public:
  typedef std::function<double(const Epick::Point_3&)> Field;
  struct Corner
  {
    Epick::Point_3 point;
    double size;
  };

  explicit Patch_size_field(double target = 0.) : target_(target) {}
  Patch_size_field(double target, double gradation, const Field& field, const Local_refinement& refinement,
                   std::vector<std::array<Corner, 3> > face_corners)
    : target_(target), gradation_(gradation), field_(field), refinement_(refinement), places_(refinement_, target),
      face_corners_(std::move(face_corners))
  {}

  double target() const { return target_; }
  bool is_uniform() const { return face_corners_.empty(); }

  /// The size at `p`, a point of face `f` of the patch (see `Sizing::at()`).
  double at(const Epick::Point_3& p, std::size_t f) const
  {
    if(is_uniform())
      return target_;
    const std::array<Corner, 3>& c = face_corners_[f];
    return (std::min)(graded(p, c[0]), (std::min)(graded(p, c[1]), (std::min)(graded(p, c[2]), of_field(p))));
  }

private:
  double graded(const Epick::Point_3& p, const Corner& c) const { return graded_size(p, c.point, c.size, target_, gradation_); }
  double of_field(const Epick::Point_3& p) const
  {
    return field_ || !refinement_.empty() ? bounded_size(field_size(field_, places_, p), target_) : target_;
  }

  friend bool same_sizes(const Patch_size_field& a, const Patch_size_field& b)
  {
    if(a.target_ != b.target_ || a.is_uniform() != b.is_uniform())
      return false;
    if(a.is_uniform())
      return true;
    if(a.gradation_ != b.gradation_ || !(a.refinement_ == b.refinement_) || bool(a.field_) != bool(b.field_)
       || a.face_corners_.size() != b.face_corners_.size())
      return false;
    for(std::size_t f = 0; f < a.face_corners_.size(); ++f)
      for(int c = 0; c < 3; ++c)
        if(a.face_corners_[f][c].point != b.face_corners_[f][c].point || a.face_corners_[f][c].size != b.face_corners_[f][c].size)
          return false;
    return true;
  }

  double target_;
  double gradation_ = 0.5;
  Field field_;
  Local_refinement refinement_;
  Local_refinement_lookup places_; // of `refinement_`
  std::vector<std::array<Corner, 3> > face_corners_; // empty when uniform

  friend struct Patch_job_serialization; // writes the field as bytes (patch_job_io.h)
};

/// The size at a surface point: the smallest of the uniform target, the user's field at the
/// point, and the graded sizes of the corners of its face (each corner's size plus the gradation
/// times the distance to it: a long CAD sliver whose corners all lie on a curved rim still
/// coarsens away from them, which a linear interpolation would not). The curvature size
/// at a vertex is the length of a chord of a circle of the surface's largest normal curvature
/// there whose sagitta is the chord error (sqrt(8 error / curvature)), graded so that it grows by
/// at most `gradation` times the distance, and never below 1/16 of the target (noisy normals of
/// degenerate CAD triangles must not make the output explode). The curvature along an edge of a
/// patch is the turn of the patch's vertex normals (area-weighted, so slivers weigh little) over
/// the edge's length; normals are per patch, so sharp features between patches do not count.
class Sizing
{
public:
  typedef Poly_annulus_segmentation::Mesh Mesh;
  typedef Poly_annulus_segmentation::Vertex Vertex;
  typedef Poly_annulus_segmentation::Face Face;
  typedef std::function<double(const Epick::Point_3&)> Field;

  /// Uniform sizing.
  Sizing(const Poly_annulus_segmentation& s, double target) : s_(s), target_(target) {}

  /// `field` may be empty; `chord_error` 0 means no curvature bound; `refinement` bounds the
  /// sizes further near its places; `gaps` (per vertex of the segmented mesh, see proximity.h;
  /// empty: none) bound the chord error to `gap_chord_error` times the gap.
  Sizing(const Poly_annulus_segmentation& s, double target, const Field& field, double chord_error,
         const Local_refinement& refinement = Local_refinement(), const std::vector<double>& gaps = std::vector<double>(),
         double gradation = 0.5)
    : s_(s), target_(target), field_(field), refinement_(refinement), places_(refinement_, target), gradation_(gradation)
  {
    const bool has_gaps = std::any_of(gaps.begin(), gaps.end(), [](double gap) { return std::isfinite(gap); });
    if(!has_field() && !(chord_error > 0.) && !has_gaps)
      return;
    const Mesh& m = s.mesh;
    vertex_size_.assign(m.number_of_vertices(), target);
    if(has_field())
      for(Vertex v : m.vertices())
        vertex_size_[v] = bounded(field_size(field_, places_, m.point(v)));
    if(chord_error > 0. || has_gaps)
      bound_by_curvature(chord_error, has_gaps ? gaps : std::vector<double>());
    grade(gradation);
    if(!has_field() && std::all_of(vertex_size_.begin(), vertex_size_.end(), [&](double size) { return size == target_; }))
      vertex_size_.clear(); // uniform after all: the cheaper path, and the same result
  }

  double target() const { return target_; }
  bool is_uniform() const { return vertex_size_.empty(); }
  /// The vertices of the segmented mesh whose size the gaps bound below the target.
  std::size_t gap_bounded_vertices() const { return gap_bounded_vertices_; }

  /// The size at a vertex of the segmented mesh.
  double at(Vertex v) const { return is_uniform() ? target_ : vertex_size_[v]; }

  /// The size at `p`, a point of face `f` of the segmented mesh.
  double at(const Epick::Point_3& p, Face f) const
  {
    if(is_uniform())
      return target_;
    const Mesh& m = s_.mesh;
    std::array<Vertex, 3> v;
    int c = 0;
    for(Vertex w : m.vertices_around_face(m.halfedge(f)))
      if(c < 3)
        v[c++] = w;
    return (std::min)(graded(p, v[0]), (std::min)(graded(p, v[1]), (std::min)(graded(p, v[2]), of_field(p))));
  }

  /// The sizes on `patch`, whose faces are faces of the segmented mesh (see `Extracted_patch`).
  Patch_size_field restricted_to(const Extracted_patch& patch) const
  {
    if(is_uniform())
      return Patch_size_field(target_);
    const Mesh& m = s_.mesh;
    std::vector<std::array<Patch_size_field::Corner, 3> > corners(patch.segmented_face.size());
    Bbox_3 box;
    for(std::size_t f = 0; f < corners.size(); ++f)
    {
      int c = 0;
      for(Vertex w : m.vertices_around_face(m.halfedge(patch.segmented_face[f])))
        if(c < 3)
        {
          corners[f][c++] = Patch_size_field::Corner{m.point(w), vertex_size_[w]};
          box += m.point(w).bbox();
        }
    }
    Local_refinement near = refinement_.within(box, target_);
    // A patch that no smaller size reaches is uniform, as it would be without them: its job then
    // equals the one of a call without the local refinements, whose mesh is kept.
    const bool all_at_target = std::all_of(corners.begin(), corners.end(), [&](const std::array<Patch_size_field::Corner, 3>& c) {
      return c[0].size == target_ && c[1].size == target_ && c[2].size == target_;
    });
    if(all_at_target && near.empty() && !field_)
      return Patch_size_field(target_);
    return Patch_size_field(target_, gradation_, field_, std::move(near), std::move(corners));
  }

  /// The size at the point at parameter `t` in [0, 1] of the edge from `a` to `b`.
  double at(Vertex a, Vertex b, double t) const
  {
    if(is_uniform())
      return target_;
    const Epick::Point_3 &pa = s_.mesh.point(a), &pb = s_.mesh.point(b);
    const Epick::Point_3 p(pa.x() + t * (pb.x() - pa.x()), pa.y() + t * (pb.y() - pa.y()), pa.z() + t * (pb.z() - pa.z()));
    return (std::min)(graded(p, a), (std::min)(graded(p, b), of_field(p)));
  }

private:
  double graded(const Epick::Point_3& p, Vertex corner) const
  {
    return graded_size(p, s_.mesh.point(corner), vertex_size_[corner], target_, gradation_);
  }

  bool has_field() const { return field_ || !refinement_.empty(); }
  double of_field(const Epick::Point_3& p) const { return has_field() ? bounded(field_size(field_, places_, p)) : target_; }
  double bounded(double size) const { return bounded_size(size, target_); }

  // Whether the normals of the faces on the two sides of `e` are kept apart: a sharp feature
  // (also inside a patch, where the patch is slit open), a border, or a patch border.
  bool separates_normals(typename Mesh::Edge_index e) const
  {
    const Mesh& m = s_.mesh;
    return m.is_border(e) || s_.is_feature[e] || s_.patch[m.face(m.halfedge(e))] != s_.patch[m.face(m.opposite(m.halfedge(e)))];
  }

  // The normal (area-weighted, not unit) of each fan of faces around a vertex between the edges
  // that separate normals: per halfedge `h` of a face, the normal of the fan of `face(h)` at
  // `target(h)`.
  std::vector<Epick::Vector_3> fan_normals() const
  {
    const Mesh& m = s_.mesh;
    std::vector<Epick::Vector_3> fan(m.number_of_halfedges(), CGAL::NULL_VECTOR);
    std::vector<typename Mesh::Halfedge_index> around;
    for(Vertex v : m.vertices())
    {
      if(m.is_isolated(v))
        continue;
      around.clear();
      for(auto h : CGAL::halfedges_around_target(m.halfedge(v), m))
        around.push_back(h);
      // Consecutive halfedges `around[i]` and `around[i + 1]` have their faces on either side
      // of `next(around[i])`; a fan starts after a separating edge, or anywhere if there is none.
      const std::size_t n = around.size();
      std::size_t start = 0;
      for(std::size_t i = 0; i < n; ++i)
        if(m.is_border(around[i]) || separates_normals(m.edge(m.next(around[i]))))
        {
          start = (i + 1) % n;
          break;
        }
      std::vector<std::size_t> members;
      Epick::Vector_3 sum = CGAL::NULL_VECTOR;
      for(std::size_t k = 0; k < n; ++k)
      {
        const auto h = around[(start + k) % n];
        if(!m.is_border(h))
        {
          const Epick::Point_3 &a = m.point(m.source(h)), &b = m.point(v), &c = m.point(m.target(m.next(h)));
          sum = sum + CGAL::cross_product(b - a, c - a);
          members.push_back(std::size_t(h));
        }
        if(k + 1 == n || m.is_border(h) || separates_normals(m.edge(m.next(h))))
        {
          for(std::size_t g : members)
            fan[g] = sum;
          members.clear();
          sum = CGAL::NULL_VECTOR;
        }
      }
    }
    return fan;
  }

  // The chord error at each edge is the smaller of `chord_error` (none if 0) and
  // `gap_chord_error` times the gap at either end (`gaps`, none if empty). The surface's turn
  // along an edge is that of the normals of its face's fans at its ends (`fan_normals()`), so
  // that sharp features, also those inside a patch, do not count as curvature.
  void bound_by_curvature(double chord_error, const std::vector<double>& gaps)
  {
    const Mesh& m = s_.mesh;
    std::vector<Vertex> gap_bounded;
    const std::vector<Epick::Vector_3> fan = fan_normals();
    auto unit = [](const Epick::Vector_3& n) {
      const double l = std::sqrt(n.squared_length());
      return l > 0. ? n / l : n;
    };
    for(Face f : m.faces())
      for(auto h : m.halfedges_around_face(m.halfedge(f)))
      {
        const Vertex a = m.source(h), b = m.target(h);
        const double length = std::sqrt(CGAL::squared_distance(m.point(a), m.point(b)));
        const Epick::Vector_3 na = unit(fan[std::size_t(m.prev(h))]), nb = unit(fan[std::size_t(h)]);
        if(!(length > 0.) || na == CGAL::NULL_VECTOR || nb == CGAL::NULL_VECTOR)
          continue;
        const double turn = 2. * std::asin((std::min)(1., 0.5 * std::sqrt((na - nb).squared_length())));
        if(!(turn > 0.))
          continue;
        const double by_gap = gaps.empty() ? std::numeric_limits<double>::infinity()
                                           : gap_chord_error * (std::min)(gaps[std::size_t(a)], gaps[std::size_t(b)]);
        const double error = (std::min)(chord_error > 0. ? chord_error : std::numeric_limits<double>::infinity(), by_gap);
        if(!std::isfinite(error))
          continue;
        const double size = bounded(std::sqrt(8. * error * length / turn));
        const bool bounded_by_gap = by_gap == error && size < target_;
        for(Vertex v : {a, b})
        {
          if(bounded_by_gap)
            gap_bounded.push_back(v);
          vertex_size_[v] = (std::min)(vertex_size_[v], size);
        }
      }
    std::sort(gap_bounded.begin(), gap_bounded.end());
    gap_bounded_vertices_ = std::size_t(std::unique(gap_bounded.begin(), gap_bounded.end()) - gap_bounded.begin());
  }

  // Smallest sizes first (Dijkstra): each vertex is bounded by its neighbours' size plus the
  // gradation times the distance.
  void grade(double gradation)
  {
    const Mesh& m = s_.mesh;
    typedef std::pair<double, Vertex> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
    for(Vertex v : m.vertices())
      if(vertex_size_[v] < target_)
        queue.emplace(vertex_size_[v], v);
    while(!queue.empty())
    {
      const Entry e = queue.top();
      queue.pop();
      if(e.first > vertex_size_[e.second])
        continue;
      for(Vertex w : m.vertices_around_target(m.halfedge(e.second)))
      {
        const double bound = e.first + gradation * std::sqrt(CGAL::squared_distance(m.point(e.second), m.point(w)));
        if(bound < vertex_size_[w])
        {
          vertex_size_[w] = bound;
          queue.emplace(bound, w);
        }
      }
    }
  }

  const Poly_annulus_segmentation& s_;
  double target_;
  Field field_;
  Local_refinement refinement_;
  Local_refinement_lookup places_; // of `refinement_`
  double gradation_ = 0.5;
  std::vector<double> vertex_size_; // empty when uniform
  std::size_t gap_bounded_vertices_ = 0;
};

/// Appends `p` to `points` unless one of them is within `spacing` of it.
inline void add_if_far(std::vector<Epick::Point_3>& points, const Epick::Point_3& p, double spacing)
{
  if(std::none_of(points.begin(), points.end(), [&](const Epick::Point_3& q) { return CGAL::squared_distance(p, q) < spacing * spacing; }))
    points.push_back(p);
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_SIZING_H
