// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Values in the cells of a uniform grid over space, to find those near a point: the creases or
// the curve edges near another one, in the segmentation's searches.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_SEGMENTATION_GRID_CELLS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_SEGMENTATION_GRID_CELLS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace segmentation {

/// Values of type `T` filed by the cube of side `side` that holds a point of theirs.
template <typename T>
class Grid_cells
{
public:
  explicit Grid_cells(double side) : side_(side) {}

  double side() const { return side_; }

  /// The values of the cell that holds `p`.
  std::vector<T>& cell_of(const Epick::Point_3& p) { return cells_[key(p)]; }

  /// Calls `visit(value)` for the values of the cell that holds `p` and of the 26 around it,
  /// until it returns `true`; returns whether it did. Every value filed at a point within
  /// `side()` of `p` is visited (and others).
  template <typename Visit>
  bool any_near(const Epick::Point_3& p, const Visit& visit) const
  {
    const std::array<long, 3> c = key(p);
    for(long dx = -1; dx <= 1; ++dx)
      for(long dy = -1; dy <= 1; ++dy)
        for(long dz = -1; dz <= 1; ++dz)
        {
          const auto found = cells_.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
          if(found != cells_.end() && std::any_of(found->second.begin(), found->second.end(), visit))
            return true;
        }
    return false;
  }

private:
  // Cells far beyond any coordinate a mesh has are clamped rather than overflow.
  std::array<long, 3> key(const Epick::Point_3& p) const
  {
    const auto cell = [&](double x) { return long((std::max)(-1e15, (std::min)(1e15, std::floor(x / side_)))); };
    return {{cell(p.x()), cell(p.y()), cell(p.z())}};
  }

  struct Key_hash
  {
    std::size_t operator()(const std::array<long, 3>& c) const
    {
      return std::hash<long>()(c[0]) ^ (std::hash<long>()(c[1]) * 1000003u) ^ (std::hash<long>()(c[2]) * 998244353u);
    }
  };

  double side_;
  std::unordered_map<std::array<long, 3>, std::vector<T>, Key_hash> cells_;
};

} // namespace segmentation
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_SEGMENTATION_GRID_CELLS_H
