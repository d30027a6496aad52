// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Peak memory of the running process, for the benchmarks that run each case in its own process:
// the peak of the whole process (getrusage) and the peak of one stage (Linux's resettable
// high-water mark of the resident set, /proc/self/clear_refs and VmHWM); and the peak of the
// largest subprocess, for the peers run as programs.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_PROCESS_MEMORY_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_PROCESS_MEMORY_H

#include <sys/resource.h>

#include <fstream>
#include <sstream>
#include <string>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// The peak resident memory of this process so far, in MB (getrusage's ru_maxrss).
inline double peak_resident_megabytes()
{
  struct rusage usage;
  if(getrusage(RUSAGE_SELF, &usage) != 0)
    return -1.;
  return double(usage.ru_maxrss) / 1024.; // Linux: kilobytes
}

/// The peak resident memory of the largest subprocess that has ended and been waited for (its
/// own subprocesses included), in MB; 0 when there was none.
inline double largest_child_peak_megabytes()
{
  struct rusage usage;
  if(getrusage(RUSAGE_CHILDREN, &usage) != 0)
    return -1.;
  return double(usage.ru_maxrss) / 1024.;
}

/// Reads a "Name:   N kB" line of /proc/self/status, in MB; -1 when absent (not Linux).
inline double proc_status_megabytes(const std::string& name)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, name.size() + 1, name + ":") == 0)
    {
      std::istringstream in(line.substr(name.size() + 1));
      double kilobytes = -1.;
      in >> kilobytes;
      return kilobytes < 0. ? -1. : kilobytes / 1024.;
    }
  return -1.;
}

/// The resident memory now, in MB (-1 when unknown).
inline double resident_megabytes() { return proc_status_megabytes("VmRSS"); }

/// The peak resident memory since the last `reset_peak_resident_memory()` (or since the start),
/// in MB; -1 when unknown.
inline double peak_resident_megabytes_since_reset() { return proc_status_megabytes("VmHWM"); }

/// Starts a new peak: the kernel sets the high-water mark to the current resident size (Linux
/// 4.0 and later). Returns false when that is not possible; the peaks are then since the start.
inline bool reset_peak_resident_memory()
{
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  clear_refs.flush();
  return bool(clear_refs);
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_PROCESS_MEMORY_H
