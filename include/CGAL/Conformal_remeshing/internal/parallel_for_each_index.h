// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A loop over indices that runs in parallel with TBB when the concurrency tag asks for it and
// TBB is available, and in order otherwise.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_PARALLEL_FOR_EACH_INDEX_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_PARALLEL_FOR_EACH_INDEX_H

#include <CGAL/tags.h>

#include <cstddef>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

/// Runs `task(i)` for i in [0, n), in parallel with TBB when `ConcurrencyTag` is
/// `Parallel_tag` (or `Parallel_if_available_tag` with TBB present), one index per TBB task.
template <typename ConcurrencyTag, typename Task>
void for_each_index(std::size_t n, const Task& task)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i)
        task(i);
    });
    return;
  }
#endif
  for(std::size_t i = 0; i < n; ++i)
    task(i);
}

/// Runs `task(begin, end)` on blocks that cover [0, n) once: in parallel with TBB when
/// `parallel` is true and TBB is available (blocks of at most `grain` indices), else on the
/// whole range at once. For loops whose iterations are short and need scratch space per block.
template <typename Task>
void for_each_block(bool parallel, std::size_t n, std::size_t grain, const Task& task)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && n > grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { task(r.begin(), r.end()); });
    return;
  }
#else
  (void)parallel;
  (void)grain;
#endif
  if(n > 0)
    task(std::size_t(0), n);
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_PARALLEL_FOR_EACH_INDEX_H
