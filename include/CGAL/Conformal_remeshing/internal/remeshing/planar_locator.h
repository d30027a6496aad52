// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point location in a planar triangulation given as indexed triangles: a walk from a hint
// triangle where the caller has one (the refinement's size queries and the optimization's trial
// moves come one after the other in a neighbourhood), else a uniform grid of buckets. The
// pull-back and the sizing field locate every planar point this way.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_LOCATOR_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_LOCATOR_H

#include <CGAL/Conformal_remeshing/internal/remeshing/triangle_adjacency.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

class Planar_locator
{
public:
  typedef CGAL::Epick::Point_2 Point_2;

  /// A triangle index and barycentric coordinates in it.
  struct Location
  {
    std::size_t triangle;
    std::array<double, 3> coordinates;
  };

  static constexpr std::size_t no_hint = std::size_t(-1);

  Planar_locator(const std::vector<Point_2>& points, const std::vector<std::array<int, 3> >& triangles)
    : points_(points), triangles_(triangles)
  {
    for(const auto& t : triangles)
      for(int v : t)
        box_ += points[v].bbox();
    // Cells of four times the triangles' mean area: the slivers of a CAD input cross many cells
    // (about 8 each at one mean area, 4 at four), and the grid serves only the searches whose
    // walk fails, so larger cells, faster to fill, make the planar stage faster.
    const double area = (box_.xmax() - box_.xmin()) * (box_.ymax() - box_.ymin());
    const double cell = 2. * std::sqrt((std::max)(area, 1e-300) / double((std::max<std::size_t>)(triangles.size(), 1)));
    nx_ = (std::max)(1, (std::min)(4096, int((box_.xmax() - box_.xmin()) / cell) + 1));
    ny_ = (std::max)(1, (std::min)(4096, int((box_.ymax() - box_.ymin()) / cell) + 1));
    // Buckets in one array, each cell's triangles in a range of it, in triangle order: the
    // (cell, triangle) pairs listed once (a sliver's cells are costly to find), then counted and
    // placed.
    std::vector<std::pair<std::uint32_t, std::uint32_t> > entries;
    entries.reserve(2 * triangles.size());
    for(std::size_t t = 0; t < triangles.size(); ++t)
      for_each_cell(t, [&](std::size_t cell) { entries.emplace_back(std::uint32_t(cell), std::uint32_t(t)); });
    bucket_start_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
    for(const auto& e : entries)
      ++bucket_start_[e.first + 1];
    for(std::size_t c = 1; c < bucket_start_.size(); ++c)
      bucket_start_[c] += bucket_start_[c - 1];
    bucket_triangles_.resize(entries.size());
    std::vector<std::size_t> filled(bucket_start_.begin(), bucket_start_.end() - 1);
    for(const auto& e : entries)
      bucket_triangles_[filled[e.first]++] = e.second;
    if(!link_triangles(triangles, neighbor_, [](int, int, bool) {}))
      neighbor_.clear(); // not a manifold triangulation: no walks, the grid alone
  }

  /// The same, walking from triangle `hint` toward `p` first (across the side whose barycentric
  /// coordinate is the most negative); falls back to the grid when the walk leaves the
  /// triangulation or is long. `hint` becomes the triangle found (`no_hint`: the grid alone).
  Location locate(const Point_2& p, std::size_t& hint) const
  {
    if(hint < neighbor_.size())
    {
      std::size_t t = hint;
      for(int step = 0; step < 16; ++step)
      {
        // The sides' signed areas with `p` lead the walk: the coordinates, which divide them by
        // the triangle's area, only where all are positive (about one step in six).
        std::array<double, 3> b = side_areas(t, p);
        int k = int(std::min_element(b.begin(), b.end()) - b.begin());
        if(b[k] >= 0.)
        {
          b = coordinates(t, b);
          k = int(std::min_element(b.begin(), b.end()) - b.begin());
          if(b[k] >= 0.)
          {
            hint = t;
            return Location{t, b};
          }
        }
        if(neighbor_[t][k] < 0)
          break;
        t = std::size_t(neighbor_[t][k]);
      }
    }
    const Location l = locate(p);
    hint = l.triangle;
    return l;
  }

  /// The triangle containing `p`, or, for a point outside every triangle (on the boundary up
  /// to rounding, or just beyond it), the nearest one with coordinates clamped onto it.
  Location locate(const Point_2& p) const
  {
    Location best{0, {{1., 0., 0.}}};
    double best_score = -std::numeric_limits<double>::infinity();
    const int ci = cell_x(p.x()), cj = cell_y(p.y());
    for(int ring = 0; ring <= (std::max)(nx_, ny_); ++ring)
    {
      for(int i = ci - ring; i <= ci + ring; ++i)
        for(int j = cj - ring; j <= cj + ring; ++j)
        {
          if(i < 0 || j < 0 || i >= nx_ || j >= ny_ || ((std::max)(std::abs(i - ci), std::abs(j - cj)) != ring))
            continue;
          const std::size_t cell = std::size_t(j) * std::size_t(nx_) + std::size_t(i);
          for(std::size_t k = bucket_start_[cell]; k < bucket_start_[cell + 1]; ++k)
          {
            const std::size_t t = bucket_triangles_[k];
            const std::array<double, 3> b = barycentric(t, p);
            const double score = (std::min)({b[0], b[1], b[2]});
            // Strictly inside: no other triangle of an embedding holds the point. (Scanning the
            // rest of the cell too would cost about 45% more barycentric tests on CAD parts, whose
            // cells along feature curves hold dozens of slivers.)
            if(score > 0.)
              return Location{t, b};
            if(score > best_score)
            {
              best_score = score;
              best = Location{t, b};
            }
          }
        }
      // Inside a triangle: done. Outside: one more ring may hold a nearer triangle.
      if(best_score >= 0. || (best_score > -std::numeric_limits<double>::infinity() && ring > 0))
        break;
    }
    if(best_score < 0.)
    {
      for(double& c : best.coordinates)
        c = (std::max)(c, 0.);
      const double sum = best.coordinates[0] + best.coordinates[1] + best.coordinates[2];
      for(double& c : best.coordinates)
        c /= sum;
    }
    return best;
  }

private:
  // Calls `f` with every cell that triangle `t` overlaps, row by row from the triangle's extent
  // within the row: its bounding box alone would put a long diagonal sliver (CAD cylinders are
  // strips of them) in a square of cells, which would take a quarter of a CAD part's meshing
  // stage to fill and another to search. A point rounded to a neighbouring row or column is still found:
  // `locate()` searches the ring of cells around its cell when its own holds no triangle with it.
  template <typename F>
  void for_each_cell(std::size_t t, const F& f) const
  {
    const std::array<Point_2, 3> corner{{points_[triangles_[t][0]], points_[triangles_[t][1]], points_[triangles_[t][2]]}};
    const double row_height = (box_.ymax() - box_.ymin() + 1e-300) / ny_;
    const double ymin = (std::min)({corner[0].y(), corner[1].y(), corner[2].y()});
    const double ymax = (std::max)({corner[0].y(), corner[1].y(), corner[2].y()});
    for(int j = cell_y(ymin); j <= cell_y(ymax); ++j)
    {
      // The triangle's x extent within the row [bottom, top]: its corners in the row and where
      // its sides cross the row's two lines.
      const double bottom = (std::max)(ymin, box_.ymin() + j * row_height), top = (std::min)(ymax, box_.ymin() + (j + 1) * row_height);
      double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
      auto extend = [&](double x) {
        xmin = (std::min)(xmin, x);
        xmax = (std::max)(xmax, x);
      };
      for(int c = 0; c < 3; ++c)
      {
        const Point_2 &p = corner[c], &q = corner[(c + 1) % 3];
        if(p.y() >= bottom && p.y() <= top)
          extend(p.x());
        for(double y : {bottom, top})
          if((p.y() - y) * (q.y() - y) < 0.)
            extend(p.x() + (y - p.y()) / (q.y() - p.y()) * (q.x() - p.x()));
      }
      if(!(xmin <= xmax)) // the row only grazes the triangle, by rounding: the bounding box's x extent
      {
        xmin = (std::min)({corner[0].x(), corner[1].x(), corner[2].x()});
        xmax = (std::max)({corner[0].x(), corner[1].x(), corner[2].x()});
      }
      for(int i = cell_x(xmin); i <= cell_x(xmax); ++i)
        f(std::size_t(j) * std::size_t(nx_) + std::size_t(i));
    }
  }

  int cell_x(double x) const
  {
    return (std::max)(0, (std::min)(nx_ - 1, int((x - box_.xmin()) / (box_.xmax() - box_.xmin() + 1e-300) * nx_)));
  }
  int cell_y(double y) const
  {
    return (std::max)(0, (std::min)(ny_ - 1, int((y - box_.ymin()) / (box_.ymax() - box_.ymin() + 1e-300) * ny_)));
  }

  // Twice the signed areas of `p` with each side of triangle `t`, opposite corners 0, 1, 2: the
  // barycentric coordinates times twice the triangle's area, which is positive in an embedding.
  std::array<double, 3> side_areas(std::size_t t, const Point_2& p) const
  {
    const Point_2 &a = points_[triangles_[t][0]], &b = points_[triangles_[t][1]], &c = points_[triangles_[t][2]];
    return {{(b.x() - p.x()) * (c.y() - p.y()) - (b.y() - p.y()) * (c.x() - p.x()),
             (c.x() - p.x()) * (a.y() - p.y()) - (c.y() - p.y()) * (a.x() - p.x()),
             (a.x() - p.x()) * (b.y() - p.y()) - (a.y() - p.y()) * (b.x() - p.x())}};
  }

  // The barycentric coordinates in triangle `t` of the point with these `side_areas()`.
  std::array<double, 3> coordinates(std::size_t t, const std::array<double, 3>& side) const
  {
    const Point_2 &a = points_[triangles_[t][0]], &b = points_[triangles_[t][1]], &c = points_[triangles_[t][2]];
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    const double wa = side[0] / area, wb = side[1] / area;
    return {{wa, wb, 1. - wa - wb}};
  }

  std::array<double, 3> barycentric(std::size_t t, const Point_2& p) const { return coordinates(t, side_areas(t, p)); }

  const std::vector<Point_2>& points_;
  const std::vector<std::array<int, 3> >& triangles_;
  CGAL::Bbox_2 box_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::size_t> bucket_start_;     // cell c's triangles are bucket_triangles_[bucket_start_[c], bucket_start_[c + 1])
  std::vector<std::size_t> bucket_triangles_;
  std::vector<std::array<int, 3> > neighbor_;
};

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_LOCATOR_H
