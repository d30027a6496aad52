// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Timing for the benchmarks: wall times and their medians over a few runs.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_TIMING_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_TIMING_H

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// The median of `v` (the mean of the two middle values for an even count; 0 when empty).
inline double median(std::vector<double> v)
{
  if(v.empty())
    return 0.;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// The wall time in seconds of one call of `run`.
inline double wall_seconds(const std::function<void()>& run)
{
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The median wall time in seconds of `runs` calls of `run`.
inline double median_seconds(const std::function<void()>& run, int runs = 3)
{
  std::vector<double> t;
  for(int i = 0; i < runs; ++i)
    t.push_back(wall_seconds(run));
  return median(t);
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_TIMING_H
