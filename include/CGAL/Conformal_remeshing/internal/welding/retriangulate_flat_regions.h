// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Replaces the faces of each large flat region of a patch by their constrained Delaunay
// triangulation in the plane, before the intrinsic Delaunay flips. A CAD exporter's fan of
// slivers on a planar face has all its vertices on the face's boundary, so the fan grows with
// the mesh and Lawson's flips from it grow with its square (about 90 million flips on a
// 300k-vertex CAD part); a bend between two such faces, tessellated as a strip of slivers
// spanning its length, is developable: unfolded, it joins the faces on either side in one plane
// region (otherwise the pull-back's walks take hundreds of millions of steps back through the
// flips between the bends and panels of a large CAD part). In the plane the intrinsic Delaunay
// triangulation is the constrained Delaunay one, which CGAL builds in O(n log n).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_RETRIANGULATE_FLAT_REGIONS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_RETRIANGULATE_FLAT_REGIONS_H

#include <CGAL/Conformal_remeshing/internal/constrained_domain.h>
#include <CGAL/Conformal_remeshing/internal/welding/flat_region.h>
#include <CGAL/Conformal_remeshing/internal/welding/weld.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

namespace flat {

// The faces around each vertex of `region`, counterclockwise from the one after a boundary side
// (`fan_start`, `fan`); false if the faces at a vertex do not form one fan (a pinched region).
inline bool make_fans(Flat_region& region)
{
  std::vector<int> count(region.vertices.size() + 1, 0);
  for(const auto& f : region.faces)
    for(int v : f)
      ++count[v + 1];
  region.fan_start.assign(region.vertices.size() + 1, 0);
  for(std::size_t v = 0; v < region.vertices.size(); ++v)
    region.fan_start[v + 1] = region.fan_start[v] + count[v + 1];
  region.fan.assign(region.fan_start.back(), -1);
  std::vector<int> first(region.vertices.size(), -1); // a face at v, the one after a boundary side if any
  for(std::size_t f = 0; f < region.faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const int v = region.faces[f][c];
      if(first[v] < 0 || region.neighbor[f][c] < 0) // side (c, c + 1) is the first side at v
        first[v] = int(f);
    }
  for(std::size_t v = 0; v < region.vertices.size(); ++v)
  {
    int f = first[v], k = region.fan_start[v];
    do
    {
      if(k == region.fan_start[v + 1])
        return false;
      region.fan[k++] = f;
      const int c = int(std::find(region.faces[f].begin(), region.faces[f].end(), int(v)) - region.faces[f].begin());
      f = region.neighbor[f][(c + 2) % 3]; // across the side from the previous corner to v
    } while(f >= 0 && f != first[v]);
    if(k != region.fan_start[v + 1])
      return false;
  }
  return true;
}

// Adds to `cdt`, the constrained Delaunay triangulation of `region` (vertex `info()`: local
// index; faces marked by `mark_constraint_depth()`), the points of a square grid of side
// `spacing` inside the region, but none within a third of `spacing` of its boundary: the
// intrinsic refinement would otherwise split the long edges of a planar CAD face's triangulation
// (its vertices all on its outline) one at a time, with a couple of dozen flips each on a CAD
// part, and every point pulled back later walks back through those flips. The new vertices
// join `region` (patch indices from `first_index` on, with the original faces holding them);
// returns their 3D points, on the original faces.
template <typename CDT>
std::vector<Vec3> add_interior_points(CDT& cdt, Flat_region& region, double spacing, int first_index,
                                      const std::vector<Vec3>& patch_points)
{
  const auto grid = grid_points_inside(cdt, spacing);
  // The original face holding each point, found before any is inserted: by a walk from the grid
  // point before, a few original faces away in the same row (from the new face's corners, a walk
  // may cross a CAD fan or a bend's strip of slivers lengthwise).
  std::vector<std::pair<int, std::array<double, 3> > > original(grid.size(), {-1, {}});
  std::vector<typename CDT::Point> points;
  points.reserve(grid.size());
  for(std::size_t k = 0; k < grid.size(); ++k)
  {
    if(k > 0)
      original[k] = region.locate_point_from(original[k - 1].first, grid[k - 1].first, grid[k].first);
    if(original[k].first < 0)
    {
      std::array<int, 3> corners;
      for(int c = 0; c < 3; ++c)
        corners[c] = grid[k].second->vertex(c)->info();
      original[k] = region.locate_point(corners, grid[k].first);
    }
    points.push_back(grid[k].first);
  }
  const auto vertex = insert_away_from_constraints(cdt, points, spacing);
  region.containing_face.assign(region.vertices.size(), -1);
  std::vector<Vec3> added;
  for(std::size_t k = 0; k < vertex.size(); ++k)
    if(vertex[k] != typename CDT::Vertex_handle())
    {
      vertex[k]->info() = int(region.vertices.size());
      region.vertices.push_back(first_index + int(added.size()));
      region.points.push_back(vertex[k]->point());
      region.containing_face.push_back(original[k].first);
      region.fan_start.push_back(region.fan_start.back()); // no original face has it as a corner
      Vec3 x{{0., 0., 0.}};
      for(int c = 0; c < 3; ++c)
        for(int d = 0; d < 3; ++d)
          x[d] += original[k].second[c] * patch_points[region.vertices[region.faces[original[k].first][c]]][d];
      added.push_back(x);
    }
  return added;
}

// A plane through a face of a patch and the exact projection of that plane to the coordinate
// plane most facing it (one coordinate dropped, one negated if need be so that the face is
// counterclockwise): a bijection on the plane when the face's projection is not flat, which
// `valid()` checks exactly.
class Plane_projection
{
public:
  Plane_projection(const Indexed_patch& patch, int face) : patch_(patch), a_(point(patch.faces[face][0])),
    b_(point(patch.faces[face][1])), c_(point(patch.faces[face][2])), dropped_(dominant_axis(face_normal(patch, patch.faces[face])))
  {
    if(CGAL::collinear(a_, b_, c_))
      return;
    const CGAL::Orientation side = raw_orientation(patch.faces[face]);
    valid_ = side != CGAL::COLLINEAR;
    mirrored_ = side == CGAL::NEGATIVE;
  }

  bool valid() const { return valid_; }
  /// whether face `f` lies in the plane and faces its way
  bool holds(const std::array<int, 3>& f) const
  {
    for(int v : f)
      if(!CGAL::coplanar(a_, b_, c_, point(v)))
        return false;
    const CGAL::Orientation side = raw_orientation(f);
    return side == (mirrored_ ? CGAL::NEGATIVE : CGAL::POSITIVE);
  }
  Epick::Point_2 operator()(int v) const
  {
    const Epick::Point_2 p = raw(v);
    return mirrored_ ? Epick::Point_2(-p.x(), p.y()) : p;
  }

private:
  Epick::Point_3 point(int v) const { return Epick::Point_3(patch_.points[v][0], patch_.points[v][1], patch_.points[v][2]); }
  // v with the dropped coordinate dropped, not mirrored
  Epick::Point_2 raw(int v) const { return Epick::Point_2(patch_.points[v][(dropped_ + 1) % 3], patch_.points[v][(dropped_ + 2) % 3]); }
  CGAL::Orientation raw_orientation(const std::array<int, 3>& f) const
  {
    return CGAL::orientation(raw(f[0]), raw(f[1]), raw(f[2]));
  }

  const Indexed_patch& patch_;
  Epick::Point_3 a_, b_, c_;
  int dropped_;
  bool valid_ = false, mirrored_ = false;
};

// Finds the flat regions of a patch and replaces each by its constrained Delaunay triangulation.
class Flat_region_retriangulation
{
  typedef Epick K;
  typedef K::Point_2 Point_2;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K> > Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;

public:
  // A bend is unfolded across edges whose faces turn by less than this (a feature of the default
  // segmentation turns by 60 degrees or more; a CAD cylinder's facets by a few).
  static constexpr double largest_unfolded_turn_degrees = 30.;

  Flat_region_retriangulation(Indexed_patch& patch, double spacing, std::size_t smallest_region)
    : patch_(patch), spacing_(spacing), smallest_region_(smallest_region), original_faces_(int(patch.faces.size())),
      grown_by_(patch.faces.size(), -1), position_(patch.faces.size(), -1), replaced_(patch.faces.size(), 0)
  {
    face_of_.reserve(3 * patch.faces.size());
    edges_.reserve(3 * patch.faces.size());
    for(int f = 0; f < original_faces_; ++f)
      for(int c = 0; c < 3; ++c)
      {
        face_of_.emplace(directed_key(patch.faces[f][c], patch.faces[f][(c + 1) % 3]), f);
        edges_.insert(undirected_key(patch.faces[f][c], patch.faces[f][(c + 1) % 3]));
      }
    unfolding_tolerance_ = 1e-9 * patch.diagonal();
  }

  // Developable regions first, unfolded (those that turn out exactly coplanar are projected),
  // then exactly coplanar regions among the faces left (a developable region can fail where
  // its unfolding rounds a CAD sliver flat, a projection cannot).
  std::size_t run()
  {
    for(int seed = 0; seed < original_faces_; ++seed)
      if(grown_by_[seed] < 0)
      {
        std::unordered_map<int, Point_2> unfolded;
        const std::vector<int> region = grow_developable_region(seed, unfolded);
        if(region.size() < smallest_region_)
          continue;
        const Plane_projection plane(patch_, seed);
        bool coplanar = plane.valid();
        for(std::size_t i = 0; i < region.size() && coplanar; ++i)
          coplanar = plane.holds(patch_.faces[region[i]]);
        if(coplanar)
          replace(region, plane, false);
        else
          replace(region, [&](int v) { return unfolded.at(v); }, true);
      }
    std::fill(grown_by_.begin(), grown_by_.end(), -1);
    for(int seed = 0; seed < original_faces_; ++seed)
      if(!replaced_[seed] && grown_by_[seed] < 0)
      {
        grown_by_[seed] = seed;
        const Plane_projection plane(patch_, seed);
        if(!plane.valid())
          continue;
        const std::vector<int> region = grow(seed, [&](int, int g) { return plane.holds(patch_.faces[g]); });
        if(region.size() >= smallest_region_)
          replace(region, plane, false);
      }
    return replaced_faces_;
  }

private:
  int across(int f, int c) const
  {
    const auto it = face_of_.find(directed_key(patch_.faces[f][(c + 1) % 3], patch_.faces[f][c]));
    return it == face_of_.end() || replaced_[it->second] ? -1 : it->second;
  }

  // The faces edge-connected to `seed` through faces `accept(f, g)` takes (g across a side of
  // f), not grown before in this pass; marks them grown.
  template <typename Accept>
  std::vector<int> grow(int seed, const Accept& accept)
  {
    grown_by_[seed] = seed;
    std::vector<int> region{seed};
    for(std::size_t i = 0; i < region.size(); ++i)
      for(int k = 0; k < 3; ++k)
      {
        const int g = across(region[i], k);
        if(g < 0 || grown_by_[g] >= 0 || !accept(region[i], g))
          continue;
        grown_by_[g] = seed;
        region.push_back(g);
      }
    return region;
  }

  // The faces around `seed` unfolded into the plane isometrically, across edges where the
  // surface turns by less than `largest_unfolded_turn_degrees`, and their vertices' positions
  // there; empty when a face cannot be unfolded consistently with the others (a vertex with an
  // angle deficit: curved, not developable) or would be folded over in the plane.
  std::vector<int> grow_developable_region(int seed, std::unordered_map<int, Point_2>& unfolded)
  {
    const double cos_turn = std::cos(largest_unfolded_turn_degrees * CGAL_PI / 180.);
    const std::array<int, 3>& s = patch_.faces[seed];
    unfolded[s[0]] = Point_2(0., 0.);
    unfolded[s[1]] = Point_2(distance(patch_.points[s[0]], patch_.points[s[1]]), 0.);
    unfolded[s[2]] = unfold_apex(unfolded[s[0]], unfolded[s[1]], s[0], s[1], s[2]);
    if(!is_finite(unfolded[s[1]]) || !is_finite(unfolded[s[2]])
       || CGAL::orientation(unfolded[s[0]], unfolded[s[1]], unfolded[s[2]]) != CGAL::POSITIVE)
    {
      grown_by_[seed] = seed;
      return {};
    }
    bool consistent = true;
    std::vector<int> region = grow(seed, [&](int f, int g) {
      if(!consistent)
        return false;
      const Vec3 n = face_normal(patch_, patch_.faces[f]), m = face_normal(patch_, patch_.faces[g]);
      if(!(dot(n, m) >= cos_turn * norm(n) * norm(m)))
        return false;
      const std::array<int, 3>& t = patch_.faces[g];
      int c = 0; // t[c] is the corner of g off the side shared with f
      while(c < 3 && std::find(patch_.faces[f].begin(), patch_.faces[f].end(), t[c]) != patch_.faces[f].end())
        ++c;
      if(c == 3) // g repeats f's corners
      {
        consistent = false;
        return false;
      }
      const int p = t[(c + 1) % 3], q = t[(c + 2) % 3], w = t[c];
      const Point_2 &at_p = unfolded.at(p), &at_q = unfolded.at(q); // g's side shared with f, unfolded with f
      const Point_2 at = unfold_apex(at_p, at_q, p, q, w);
      const auto known = unfolded.find(w);
      if(!is_finite(at)) // lengths whose squares overflow: left as they are
        consistent = false;
      else if(known != unfolded.end() && CGAL::squared_distance(known->second, at) > CGAL::square(unfolding_tolerance_))
        consistent = false;
      else if(CGAL::orientation(at_p, at_q, known != unfolded.end() ? known->second : at) != CGAL::POSITIVE)
        consistent = false;
      else if(known == unfolded.end())
        unfolded.emplace(w, at);
      return consistent;
    });
    if(!consistent)
      region.clear();
    return region;
  }

  static bool is_finite(const Point_2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

  // The position in the plane of vertex `w` of the face (p, q, w), p and q unfolded at `at_p` and
  // `at_q`: where its foot on the line pq and its distance from it put it, on the left. (From
  // the sides' lengths, the apex of a CAD sliver would round off its side.)
  Point_2 unfold_apex(const Point_2& at_p, const Point_2& at_q, int p, int q, int w) const
  {
    const Vec3 e = patch_.points[q] - patch_.points[p], x = patch_.points[w] - patch_.points[p];
    const double length = norm(e);
    const double along = dot(x, e) / (length * length), off = norm(cross(e, x)) / length;
    const double dx = at_q.x() - at_p.x(), dy = at_q.y() - at_p.y(), d = std::hypot(dx, dy);
    return Point_2(at_p.x() + along * dx - off * dy / d, at_p.y() + along * dy + off * dx / d);
  }

  // Replaces the faces `region` (`point(v)`: vertex v in the plane) by the constrained Delaunay
  // triangulation of their vertices with the region's boundary sides as constraints, if that
  // triangulates the same domain and doubles no edge of the patch; false if not.
  template <typename Point_of>
  bool replace(const std::vector<int>& region, const Point_of& point, bool developed)
  {
    struct Forget // the region's positions, whatever the outcome
    {
      std::vector<int>& position;
      const std::vector<int>& region;
      ~Forget() { for(int f : region) position[f] = -1; }
    } forget{position_, region};
    for(std::size_t i = 0; i < region.size(); ++i)
      position_[region[i]] = int(i);

    // The region with its old faces, in its own indices.
    Flat_region r;
    r.developed = developed;
    for(int f : region)
      r.vertices.insert(r.vertices.end(), patch_.faces[f].begin(), patch_.faces[f].end());
    std::sort(r.vertices.begin(), r.vertices.end());
    r.vertices.erase(std::unique(r.vertices.begin(), r.vertices.end()), r.vertices.end());
    for(int v : r.vertices)
      r.points.push_back(point(v));
    std::unordered_set<std::uint64_t> old_inner_edges;
    for(int f : region)
    {
      std::array<int, 3> local, neighbors;
      for(int k = 0; k < 3; ++k)
      {
        local[k] = r.local_vertex(patch_.faces[f][k]);
        const int g = across(f, k);
        neighbors[k] = g >= 0 ? position_[g] : -1;
        if(neighbors[k] >= 0)
          old_inner_edges.insert(undirected_key(patch_.faces[f][k], patch_.faces[f][(k + 1) % 3]));
      }
      r.faces.push_back(local);
      r.neighbor.push_back(neighbors);
      r.input_face.push_back(patch_.input_face[f]);
      r.input_coordinates.push_back(patch_.input_coordinates[f]);
    }
    if(!flat::make_fans(r))
      return false;

    // Its constrained Delaunay triangulation, faces inside by the parity of constraints crossed.
    CDT cdt;
    std::vector<std::pair<Point_2, int> > located;
    for(std::size_t v = 0; v < r.points.size(); ++v)
      located.emplace_back(r.points[v], int(v));
    cdt.insert(located.begin(), located.end());
    if(cdt.number_of_vertices() != r.points.size())
      return false; // two vertices at one point
    std::vector<CDT::Vertex_handle> handle(r.points.size());
    for(auto v : cdt.finite_vertex_handles())
      handle[v->info()] = v;
    std::vector<std::pair<int, int> > boundary;
    for(std::size_t f = 0; f < r.faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
        if(r.neighbor[f][k] < 0)
        {
          boundary.emplace_back(r.faces[f][k], r.faces[f][(k + 1) % 3]);
          cdt.insert_constraint(handle[boundary.back().first], handle[boundary.back().second]);
        }
    if(cdt.number_of_vertices() != r.points.size())
      return false; // sides cross
    std::sort(boundary.begin(), boundary.end());
    mark_constraint_depth(cdt);
    std::vector<std::array<int, 3> > made;
    std::vector<std::uint64_t> new_inner_edges;
    auto collect_faces = [&]() {
      made.clear();
      new_inner_edges.clear();
      for(auto fh : cdt.finite_face_handles())
        if(fh->info() % 2 == 1)
          made.push_back({{fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()}});
      for(const auto& f : made)
        for(int k = 0; k < 3; ++k)
          if(f[k] < f[(k + 1) % 3]) // once per inner edge: boundary sides are kept
          {
            const std::uint64_t e = undirected_key(r.vertices[f[k]], r.vertices[f[(k + 1) % 3]]);
            if(!std::binary_search(boundary.begin(), boundary.end(), std::make_pair(f[k], f[(k + 1) % 3]))
               && !std::binary_search(boundary.begin(), boundary.end(), std::make_pair(f[(k + 1) % 3], f[k])))
              new_inner_edges.push_back(e);
          }
    };
    // It would join two vertices joined outside the region already.
    auto doubles_an_edge = [&]() {
      for(std::uint64_t e : new_inner_edges)
        if(!old_inner_edges.count(e) && edges_.count(e))
          return true;
      return false;
    };
    collect_faces();
    bool same_domain = made.size() == region.size();
    for(std::size_t i = 0; i < boundary.size() && same_domain; ++i)
    {
      CDT::Face_handle fh;
      int k;
      const CDT::Vertex_handle from = handle[boundary[i].first], to = handle[boundary[i].second];
      if(!cdt.is_edge(from, to, fh, k))
        same_domain = false;
      else
      {
        const CDT::Face_handle left = fh->vertex(fh->ccw(k)) == from ? fh : fh->neighbor(k);
        same_domain = !cdt.is_infinite(left) && left->info() % 2 == 1;
      }
    }
    if(!same_domain || doubles_an_edge())
      return false;
    const std::vector<Vec3> added_points = flat::add_interior_points(cdt, r, spacing_, int(patch_.points.size()), patch_.points);
    if(!added_points.empty())
    {
      collect_faces();
      if(doubles_an_edge())
        return false;
    }

    for(std::uint64_t e : old_inner_edges)
      edges_.erase(e);
    edges_.insert(new_inner_edges.begin(), new_inner_edges.end());
    patch_.points.insert(patch_.points.end(), added_points.begin(), added_points.end());
    if(developed)
      for(std::uint64_t e : new_inner_edges)
      {
        const int a = int(e >> 32), b = int(e & 0xffffffffu);
        patch_.developed_lengths[e] = std::sqrt(CGAL::squared_distance(r.points[r.local_vertex(a)], r.points[r.local_vertex(b)]));
      }
    const int index = -1 - int(patch_.flat_regions.size());
    for(std::size_t i = 0; i < made.size(); ++i)
    {
      std::array<int, 3> corners;
      for(int k = 0; k < 3; ++k)
        corners[k] = r.vertices[made[i][k]];
      if(i < region.size())
      {
        patch_.faces[region[i]] = corners;
        patch_.input_face[region[i]] = index;
        patch_.input_coordinates.set(region[i], {});
      }
      else
      {
        patch_.faces.push_back(corners);
        patch_.input_face.push_back(index);
        patch_.input_coordinates.push_back({});
      }
    }
    for(int f : region)
      replaced_[f] = 1;
    patch_.flat_regions.push_back(std::move(r));
    replaced_faces_ += region.size();
    return true;
  }

  Indexed_patch& patch_;
  double spacing_;
  std::size_t smallest_region_;
  int original_faces_;
  double unfolding_tolerance_ = 0.;
  std::unordered_map<std::uint64_t, int> face_of_; // directed side -> face (of the original faces)
  std::unordered_set<std::uint64_t> edges_;        // the patch's edges
  std::vector<int> grown_by_, position_;           // the seed of each face's region in this pass; its index there
  std::vector<char> replaced_;
  std::size_t replaced_faces_ = 0;
};

} // namespace flat

/// Retriangulates the flat regions of `patch`: every edge-connected set of at least
/// `smallest_region` faces that unfolds into the plane isometrically (a bend between planar CAD
/// faces and the faces themselves; not across edges turning by 30 degrees or more) or, failing
/// that, that are exactly coplanar (exact predicates) and face the same way, by the constrained
/// Delaunay triangulation of its vertices in the plane with its boundary sides as constraints.
/// The region keeps its vertices and boundary; a region is left as it is when its points in the
/// plane are not a plane triangulation of the same domain (points that coincide, sides that
/// cross) or when a new edge would double an edge of the patch outside the region. The new
/// edges of an unfolded region have their lengths in the plane (`developed_lengths`). With a
/// `spacing`, points of a square grid of that side inside the region are added to its
/// triangulation first (see `flat::add_interior_points()`), appended to `patch.points`. The new
/// faces take the slots of the old ones, then the end of `patch.faces`, with `input_face`
/// `-1 - r` for region `r` of `patch.flat_regions`, which locates points among the old faces.
/// Returns the number of faces retriangulated.
inline std::size_t retriangulate_flat_regions(Indexed_patch& patch, double spacing = 0., std::size_t smallest_region = 16)
{
  return flat::Flat_region_retriangulation(patch, spacing, smallest_region).run();
}

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_RETRIANGULATE_FLAT_REGIONS_H
