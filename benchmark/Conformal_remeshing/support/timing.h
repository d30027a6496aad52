// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Timing for the benchmarks: the median wall time of a few runs.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_TIMING_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_TIMING_H

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// The median wall time in seconds of `runs` calls of `run`.
inline double median_seconds(const std::function<void()>& run, int runs = 3)
{
  std::vector<double> t;
  for(int i = 0; i < runs; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_TIMING_H
