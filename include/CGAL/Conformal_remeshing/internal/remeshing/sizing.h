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

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

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

  /// `field` may be empty; `chord_error` 0 means no curvature bound.
  Sizing(const Poly_annulus_segmentation& s, double target, const Field& field, double chord_error, double gradation = 0.5)
    : s_(s), target_(target), field_(field), gradation_(gradation)
  {
    if(!field_ && !(chord_error > 0.))
      return;
    const Mesh& m = s.mesh;
    vertex_size_.assign(m.number_of_vertices(), target);
    if(field_)
      for(Vertex v : m.vertices())
        vertex_size_[v] = bounded(field_(m.point(v)));
    if(chord_error > 0.)
      bound_by_curvature(chord_error);
    grade(gradation);
    if(!field_ && std::all_of(vertex_size_.begin(), vertex_size_.end(), [&](double size) { return size == target_; }))
      vertex_size_.clear(); // uniform after all: the cheaper path, and the same result
  }

  double target() const { return target_; }
  bool is_uniform() const { return vertex_size_.empty(); }

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
    return (std::min)(target_, vertex_size_[corner] + gradation_ * std::sqrt(CGAL::squared_distance(p, s_.mesh.point(corner))));
  }

  double of_field(const Epick::Point_3& p) const { return field_ ? bounded(field_(p)) : target_; }

  double bounded(double size) const
  {
    return std::isfinite(size) ? (std::min)(target_, (std::max)(size, target_ / 16.)) : target_;
  }

  void bound_by_curvature(double chord_error)
  {
    const Mesh& m = s_.mesh;
    std::map<std::pair<Vertex, std::size_t>, Epick::Vector_3> normal; // per vertex and patch
    for(Face f : m.faces())
    {
      const auto h = m.halfedge(f);
      const Epick::Vector_3 n = CGAL::cross_product(m.point(m.target(h)) - m.point(m.source(h)),
                                                    m.point(m.target(m.next(h))) - m.point(m.source(h)));
      for(Vertex v : m.vertices_around_face(h))
      {
        auto inserted = normal.emplace(std::make_pair(v, s_.patch[f]), n);
        if(!inserted.second)
          inserted.first->second = inserted.first->second + n;
      }
    }
    auto unit = [](const Epick::Vector_3& n) {
      const double l = std::sqrt(n.squared_length());
      return l > 0. ? n / l : n;
    };
    for(Face f : m.faces())
      for(auto h : m.halfedges_around_face(m.halfedge(f)))
      {
        const Vertex a = m.source(h), b = m.target(h);
        const double length = std::sqrt(CGAL::squared_distance(m.point(a), m.point(b)));
        const Epick::Vector_3 na = unit(normal.at({a, s_.patch[f]})), nb = unit(normal.at({b, s_.patch[f]}));
        if(!(length > 0.) || na == CGAL::NULL_VECTOR || nb == CGAL::NULL_VECTOR)
          continue;
        const double turn = 2. * std::asin((std::min)(1., 0.5 * std::sqrt((na - nb).squared_length())));
        if(!(turn > 0.))
          continue;
        const double size = bounded(std::sqrt(8. * chord_error * length / turn));
        for(Vertex v : {a, b})
          vertex_size_[v] = (std::min)(vertex_size_[v], size);
      }
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
  double gradation_ = 0.5;
  std::vector<double> vertex_size_; // empty when uniform
};

/// A size field that is `size` at each of `points` and grows by `gradation` times the distance
/// to the nearest of them, bounded by `field` where that is given: the sizes for meshing again
/// near the places where an output intersected itself. (The places are few, a quarter target
/// apart: see `add_if_far()`.)
inline Sizing::Field shorter_near(const Sizing::Field& field, const std::vector<Epick::Point_3>& points, double size,
                                  double gradation = 0.5)
{
  return [=](const Epick::Point_3& p) {
    double nearest = std::numeric_limits<double>::infinity();
    for(const Epick::Point_3& q : points)
      nearest = (std::min)(nearest, CGAL::squared_distance(p, q));
    const double graded = size + gradation * std::sqrt(nearest);
    return field ? (std::min)(field(p), graded) : graded;
  };
}

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
