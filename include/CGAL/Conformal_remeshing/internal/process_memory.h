// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The process's peak resident memory so far, which the statistics record at the end of each
// stage of `remesh_conformal()`, so that the stage that raises it shows; and the release of the
// heap's free pages after a stage that frees large structures.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_PROCESS_MEMORY_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_PROCESS_MEMORY_H

#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

/// The peak resident memory of this process so far, in MB; -1 where the platform does not tell.
inline double peak_resident_megabytes()
{
#if defined(__unix__) || defined(__APPLE__)
  struct rusage usage;
  if(getrusage(RUSAGE_SELF, &usage) != 0)
    return -1.;
#if defined(__APPLE__)
  return double(usage.ru_maxrss) / (1024. * 1024.); // bytes
#else
  return double(usage.ru_maxrss) / 1024.; // kilobytes
#endif
#else
  return -1.;
#endif
}

/// Gives the heap's free pages back to the operating system where the C library can (glibc's
/// `malloc_trim()`). Freed arrays amid the heap otherwise stay resident, and the next stage's
/// large arrays, mapped afresh rather than placed in those holes, add to them. Nothing changes
/// but the resident memory.
inline void release_free_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_PROCESS_MEMORY_H
