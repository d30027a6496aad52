// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Distances from points to a triangle mesh's surface, in plain double arithmetic, for the
// quality measures (mesh_quality.h) and the remesher's surface-distance bound alike.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_DISTANCE_TO_SURFACE_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_DISTANCE_TO_SURFACE_H

#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/well_shaped_cover.h>

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

/// Closest points on a reference surface, as `approximate_Hausdorff_distance()` finds them, but
/// with the queries in plain double arithmetic: the samples of a remeshing lie on the reference,
/// at distance 0, and CAD tessellations have flat bounding boxes, so the filtered sphere-box tests
/// of the exact-predicates kernel are undecided for many nodes and fall back to exact arithmetic
/// (a third of the time on a large CAD part). A distance needs no exact predicate: rounding moves
/// it by a few units in the last place. The tree holds the triangles of
/// `well_shaped_indexed_cover(reference)`, not the faces: the bounding boxes of a CAD fan's long
/// slivers cover their whole face, and every query there would open all of them. Its primitives
/// are the triangles' indices, whose coordinates are read from the cover's shared points when
/// the tree asks for them: three indices a triangle are held, not nine coordinates. The queries'
/// first guesses come from a search structure over one vertex of every `hint_stride`-th triangle
/// of the cover: a guess only needs to lie near the closest point, and CGAL's structure over
/// every triangle (`accelerate_distance_queries()`) takes about as much memory as the cover's
/// triangles themselves.
class Distance_to_surface
{
public:
  typedef CGAL::Simple_cartesian<double> Fast;

  /// A cover triangle's coordinates by its index, built when the tree asks (the tree's
  /// primitives are the indices).
  struct Triangle_of_index
  {
    typedef std::uint32_t key_type;
    typedef Fast::Triangle_3 value_type;
    typedef value_type reference;
    typedef boost::readable_property_map_tag category;
    const Indexed_cover* cover = nullptr;
    friend value_type get(const Triangle_of_index& map, key_type t) { return map.cover->triangle(t); }
  };
  /// A cover triangle's first corner by its index: the primitive's reference point.
  struct First_corner_of_index
  {
    typedef std::uint32_t key_type;
    typedef Fast::Point_3 value_type;
    typedef const value_type& reference;
    typedef boost::readable_property_map_tag category;
    const Indexed_cover* cover = nullptr;
    friend reference get(const First_corner_of_index& map, key_type t) { return map.cover->points[map.cover->triangles[t][0]]; }
  };
  typedef CGAL::AABB_primitive<std::uint32_t, Triangle_of_index, First_corner_of_index, CGAL::Tag_true, CGAL::Tag_false> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Fast, Primitive> > Tree;

  static constexpr std::size_t hint_stride = 8; ///< one first guess for this many triangles of the cover

  /// The cover of `reference` is built in parallel when `ConcurrencyTag` is `Parallel_tag`.
  template <typename TriangleMesh, typename ConcurrencyTag = CGAL::Sequential_tag>
  explicit Distance_to_surface(const TriangleMesh& reference, ConcurrencyTag = ConcurrencyTag())
    : cover_(well_shaped_indexed_cover<ConcurrencyTag>(reference)),
      tree_(boost::counting_iterator<std::uint32_t>(0), boost::counting_iterator<std::uint32_t>(std::uint32_t(cover_.triangles.size())),
            Triangle_of_index{&cover_}, First_corner_of_index{&cover_})
  {
    const First_corner_of_index reference_point{&cover_};
    std::vector<Tree::Point_and_primitive_id> hints;
    hints.reserve(cover_.triangles.size() / hint_stride + 1);
    for(std::size_t t = 0; t < cover_.triangles.size(); t += hint_stride)
      hints.emplace_back(get(reference_point, std::uint32_t(t)), std::uint32_t(t));
    tree_.accelerate_distance_queries(hints.begin(), hints.end());
  }
  Distance_to_surface(const Distance_to_surface&) = delete;
  Distance_to_surface& operator=(const Distance_to_surface&) = delete;

  const Tree& tree() const { return tree_; }

  /// The squared distance of each of `points` to the surface. The points are visited in spatial
  /// order, and each query starts from the nearer of the previous point's closest point and the
  /// nearest of the guesses (CGAL 5.5's parallel loop starts every TBB range from one vertex of
  /// the mesh): on a large CAD part about 40% less time than `approximate_Hausdorff_distance()`.
  /// A guess changes how much of the tree a query opens, not the distance found (but for its
  /// rounding, where two triangles are equally close).
  template <typename Concurrency_tag>
  std::vector<double> squared_distances(const std::vector<Fast::Point_3>& points) const
  {
    if(points.empty()) // (CGAL's property map over a vector takes its first element's address)
      return {};
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    const auto point_of_index = CGAL::make_property_map(points);
    CGAL::spatial_sort(order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_3<Fast, decltype(point_of_index)>(point_of_index));
    constexpr std::size_t block_size = 4096;
    const std::size_t blocks = (points.size() + block_size - 1) / block_size;
    std::vector<double> squared_distance(points.size(), 0.);
    for_each_index<Concurrency_tag>(blocks, [&](std::size_t b) {
      const std::size_t begin = b * block_size, end = (std::min)(points.size(), begin + block_size);
      Fast::Point_3 closest = tree_.best_hint(points[order[begin]]).first;
      for(std::size_t i = begin; i < end; ++i)
      {
        const Fast::Point_3& p = points[order[i]];
        const Fast::Point_3 hint = tree_.best_hint(p).first;
        if(CGAL::squared_distance(p, hint) < CGAL::squared_distance(p, closest))
          closest = hint;
        closest = tree_.closest_point(p, closest);
        squared_distance[order[i]] = CGAL::squared_distance(p, closest);
      }
    });
    return squared_distance;
  }

private:
  Indexed_cover cover_;
  Tree tree_;
};

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_DISTANCE_TO_SURFACE_H
