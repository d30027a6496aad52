// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Strips between sharp features narrower than the smallest detail the output keeps: a small
// chamfer, bevel or step of a CAD part, tessellated as one row of slivers. The output keeps every
// sharp feature as a chain of its edges, sampled about a target length apart, so the triangles
// across such a strip join samples a target apart on both sides of a gap of a small fraction of
// it: needles and caps, however the strip is meshed (the sizes are at least a sixteenth of the
// target, so shorter ones there would only make more of them). One side of the strip stops being
// a feature instead: the strip joins the surface beyond that side, and the output passes within a
// few strip widths of the crease it leaves out.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_SEGMENTATION_NARROW_FEATURE_STRIPS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_SEGMENTATION_NARROW_FEATURE_STRIPS_H

#include <CGAL/Conformal_remeshing/internal/segmentation/grid_cells.h>
#include <CGAL/Conformal_remeshing/internal/shortest_ways.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace segmentation {

/// Seen from a curve point, a point of a curve is across a strip when the way to it along the
/// curves is more than this times its distance: the far side of the strip, but not the next
/// stretch of the same curve, nor a curve meeting it at a corner wider than about 28 degrees.
constexpr double strip_detour = 4.;

namespace narrow_strips_detail {

typedef CGAL::Surface_mesh<Epick::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Edge_index Edge;
typedef Mesh::Halfedge_index Halfedge;

// The lengths of the shortest ways along the curve edges (`outgoing` halfedges of each vertex)
// from `source` to the vertices within `radius`.
inline std::unordered_map<std::size_t, double> ways_along_curves(const Mesh& m, const std::vector<std::vector<Halfedge> >& outgoing,
                                                                 Vertex source, double radius)
{
  return shortest_ways_within(source, radius, [&](Vertex v, const auto& step) {
    for(Halfedge h : outgoing[v])
      step(m.target(h), std::sqrt(CGAL::squared_distance(m.point(v), m.point(m.target(h)))));
  });
}

// The curve edges in cells: each cell lists the edges with a point in it, the edges being
// sampled closer than the cell's side.
class Curve_edge_grid
{
public:
  Curve_edge_grid(const Mesh& m, const std::vector<Edge>& edges, double spacing) : cells_(1.5 * spacing)
  {
    for(std::size_t i = 0; i < edges.size(); ++i)
    {
      const Epick::Point_3 &a = m.point(m.vertex(edges[i], 0)), &b = m.point(m.vertex(edges[i], 1));
      const std::size_t n = std::size_t(std::ceil(std::sqrt(CGAL::squared_distance(a, b)) / spacing));
      for(std::size_t k = 0; k <= n; ++k)
      {
        std::vector<std::size_t>& in_cell = cells_.cell_of(a + (n == 0 ? 0. : double(k) / double(n)) * (b - a));
        if(in_cell.empty() || in_cell.back() != i)
          in_cell.push_back(i);
      }
    }
  }

  // The edges with a point in the cell of `p` or in one of the 26 around it, each once: every
  // edge within `spacing` of `p`, and others.
  std::vector<std::size_t> edges_near(const Epick::Point_3& p) const
  {
    std::vector<std::size_t> near;
    cells_.any_near(p, [&](std::size_t i) {
      near.push_back(i);
      return false;
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
  }

private:
  Grid_cells<std::size_t> cells_;
};

// The directions from edge `e` into its faces, across it in their planes (none on the border).
inline std::vector<Epick::Vector_3> inward_directions(const Mesh& m, Edge e)
{
  std::vector<Epick::Vector_3> inward;
  for(Halfedge h : {m.halfedge(e), m.opposite(m.halfedge(e))})
    if(!m.is_border(h))
    {
      const Epick::Point_3 &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
      inward.push_back(CGAL::cross_product(CGAL::cross_product(b - a, c - a), b - a));
    }
  return inward;
}

// The feature chains of `m`: maximal paths of feature edges through vertices where exactly two
// feature edges meet, as chain indices per edge (-1 for edges that are no feature).
inline std::vector<long> feature_chains(const Mesh& m, const Mesh::Property_map<Edge, bool>& is_feature, std::size_t& count)
{
  std::vector<std::size_t> degree(m.number_of_vertices(), 0);
  for(Edge e : m.edges())
    if(is_feature[e])
      ++degree[m.vertex(e, 0)], ++degree[m.vertex(e, 1)];
  std::vector<long> chain(m.number_of_edges(), -1);
  count = 0;
  for(Edge seed : m.edges())
  {
    if(!is_feature[seed] || chain[seed] >= 0)
      continue;
    std::vector<Edge> stack{seed};
    chain[seed] = long(count);
    while(!stack.empty())
    {
      const Edge e = stack.back();
      stack.pop_back();
      for(int k = 0; k < 2; ++k)
      {
        const Vertex v = m.vertex(e, k);
        if(degree[v] != 2)
          continue;
        for(Halfedge h : CGAL::halfedges_around_target(m.halfedge(v), m))
          if(is_feature[m.edge(h)] && chain[m.edge(h)] < 0)
          {
            chain[m.edge(h)] = long(count);
            stack.push_back(m.edge(h));
          }
      }
    }
    ++count;
  }
  return chain;
}

// The curve edges of a mesh (its sharp features and its border), and which of them lie across a
// strip narrower than `width` from a feature edge.
class Strip_sides
{
public:
  Strip_sides(const Mesh& m, const Mesh::Property_map<Edge, bool>& is_feature, double width)
    : m_(m), width_(width), outgoing_(m.number_of_vertices())
  {
    for(Edge e : m.edges())
      if(is_feature[e] || m.is_border(e))
      {
        edges_.push_back(e);
        for(Halfedge h : {m.halfedge(e), m.opposite(m.halfedge(e))})
          outgoing_[m.source(h)].push_back(h);
      }
    grid_ = std::make_unique<Curve_edge_grid>(m, edges_, width);
  }

  const std::vector<Edge>& curve_edges() const { return edges_; }

  // The curve edges (indices into `curve_edges()`) across a narrow strip from curve edge `i`:
  // from its points at a quarter, half and three quarters of its length, none if one of them has
  // none (a long CAD edge that runs on beyond the strip is no side of it).
  std::vector<std::size_t> across(std::size_t i) const
  {
    std::array<std::unordered_map<std::size_t, double>, 2> way_from; // from the ends of edge i, when needed
    std::vector<std::size_t> all;
    for(double t : {0.5, 0.25, 0.75})
    {
      const std::vector<std::size_t> found = across_from(i, t, way_from);
      if(found.empty())
        return found;
      all.insert(all.end(), found.begin(), found.end());
    }
    return all;
  }

private:
  Epick::Segment_3 segment(std::size_t i) const
  {
    return Epick::Segment_3(m_.point(m_.vertex(edges_[i], 0)), m_.point(m_.vertex(edges_[i], 1)));
  }

  // The curve edges closer than the width to the point at `t` of edge `i`, towards a face of it,
  // and more than `strip_detour` times as far along the curves.
  std::vector<std::size_t> across_from(std::size_t i, double t, std::array<std::unordered_map<std::size_t, double>, 2>& way_from) const
  {
    const Edge e = edges_[i];
    const Epick::Segment_3 s = segment(i);
    const double length = std::sqrt(s.squared_length());
    const Epick::Point_3 q = s.source() + t * (s.target() - s.source());
    const std::vector<Epick::Vector_3> inward = inward_directions(m_, e);
    std::vector<std::size_t> found;
    for(std::size_t j : grid_->edges_near(q))
    {
      const Epick::Point_3 p = Epick().construct_projected_point_3_object()(segment(j), q);
      const double d = std::sqrt(CGAL::squared_distance(q, p));
      if(j == i || !(d < width_) || std::none_of(inward.begin(), inward.end(), [&](const Epick::Vector_3& in) { return (p - q) * in > 0.; }))
        continue;
      if(way_from[0].empty())
        for(int k = 0; k < 2; ++k)
          way_from[k] = ways_along_curves(m_, outgoing_, m_.vertex(e, k), strip_detour * width_ + length);
      double way = std::numeric_limits<double>::infinity();
      for(int k = 0; k < 2; ++k)
        for(int l = 0; l < 2; ++l)
        {
          const auto reached = way_from[k].find(std::size_t(m_.vertex(edges_[j], l)));
          if(reached != way_from[k].end())
            way = (std::min)(way, (k == 0 ? t : 1. - t) * length + reached->second
                                    + std::sqrt(CGAL::squared_distance(p, m_.point(m_.vertex(edges_[j], l)))));
        }
      if(way > strip_detour * d)
        found.push_back(j);
    }
    return found;
  }

  const Mesh& m_;
  double width_;
  std::vector<Edge> edges_;
  std::vector<std::vector<Halfedge> > outgoing_;
  std::unique_ptr<Curve_edge_grid> grid_;
};

// One pass of `drop_narrow_strip_features()`: the feature edges across a narrow strip from a
// curve edge that stays, taken in the order of their chains' mean turn, least first.
inline std::size_t drop_one_side_of_narrow_strips(const Mesh& m, Mesh::Property_map<Edge, bool>& is_feature, double width,
                                                  double min_length, const std::function<double(Edge)>& turn)
{
  const auto length_of = [&](Edge e) { return std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)))); };
  const auto is_inner_feature = [&](Edge e) { return is_feature[e] && !m.is_border(e); };
  if(std::none_of(m.edges().begin(), m.edges().end(), [&](Edge e) { return is_inner_feature(e) && length_of(e) >= min_length; }))
    return 0;
  std::size_t number_of_chains = 0;
  const std::vector<long> chain = feature_chains(m, is_feature, number_of_chains);
  const Strip_sides sides(m, is_feature, width);
  const std::vector<Edge>& edges = sides.curve_edges();
  std::vector<double> chain_length(number_of_chains, 0.), chain_turn(number_of_chains, 0.);
  std::vector<std::vector<std::size_t> > across(edges.size());
  std::vector<std::size_t> order; // the long feature edges with a curve edge across a narrow strip
  for(std::size_t i = 0; i < edges.size(); ++i)
    if(is_inner_feature(edges[i]))
    {
      const double length = length_of(edges[i]);
      chain_length[chain[edges[i]]] += length;
      chain_turn[chain[edges[i]]] += length * turn(edges[i]);
      if(length >= min_length)
        across[i] = sides.across(i);
      if(!across[i].empty())
        order.push_back(i);
    }
  const auto mean_turn = [&](std::size_t i) { return chain_turn[chain[edges[i]]] / chain_length[chain[edges[i]]]; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mean_turn(a) < mean_turn(b); });
  std::vector<char> dropped(edges.size(), 0);
  std::size_t count = 0;
  for(std::size_t i : order)
    if(std::any_of(across[i].begin(), across[i].end(), [&](std::size_t j) { return !dropped[j]; }))
    {
      dropped[i] = 1;
      is_feature[edges[i]] = false;
      ++count;
    }
  return count;
}

} // namespace narrow_strips_detail

/// Drops one side of every strip between sharp features (`is_feature`) or borders narrower than
/// `width`: its feature edges no longer set. An edge is a side of a narrow strip when at a
/// quarter, half and three quarters of its length another feature or border edge is closer than
/// `width` across one of its faces (`strip_detour`). Of the two sides, the edges of the feature
/// chain (between vertices where other than two features meet) that turns less on average
/// (`turn`, in degrees) go, while an edge across from them stays; a border always stays. Only
/// edges at least `min_length` long go: the long sides of a row of slivers, as CAD tessellations
/// make of a small chamfer or bevel. The creases of a scan are chains of short edges, and
/// dropping a few of them leaves loose ends beside other curves, which make the needles this
/// avoids. Passes repeat while one drops an edge: two strips side by side (a step) become one
/// strip, which may still be narrow. Returns the number of feature edges dropped.
inline std::size_t drop_narrow_strip_features(const narrow_strips_detail::Mesh& m,
                                              narrow_strips_detail::Mesh::Property_map<narrow_strips_detail::Edge, bool>& is_feature,
                                              double width, double min_length,
                                              const std::function<double(narrow_strips_detail::Edge)>& turn)
{
  std::size_t dropped = 0;
  if(width > 0.)
    while(const std::size_t count = narrow_strips_detail::drop_one_side_of_narrow_strips(m, is_feature, width, min_length, turn))
      dropped += count;
  return dropped;
}

} // namespace segmentation
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_SEGMENTATION_NARROW_FEATURE_STRIPS_H
