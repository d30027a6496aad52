// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmarks that read mesh files and write a report share: both checks run before
// minutes of runs, not after them.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_BENCHMARK_IO_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_BENCHMARK_IO_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/IO/read_mesh.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// Throws `std::runtime_error` with the reason when `path` cannot be written.
inline void check_writable(const std::string& path)
{
  if(std::filesystem::is_directory(path))
    throw std::runtime_error("cannot write '" + path + "': it is a directory");
  const std::string probe = path + ".probe";
  std::ofstream out(probe);
  if(!out)
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  out.close();
  std::remove(probe.c_str());
}

/// The mesh in the file `path`; throws `std::runtime_error` with the reason when it cannot be
/// read or is not a valid mesh.
template <typename Mesh>
Mesh read_model(const std::string& path)
{
  Mesh mesh;
  try
  {
    const Mesh_check_report check = read_and_check_mesh(path, mesh);
    if(!check.is_valid())
      throw std::runtime_error("invalid mesh '" + path + "': " + check.summary());
  }
  catch(const Error& e)
  {
    throw std::runtime_error(e.what());
  }
  return mesh;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_BENCHMARK_IO_H
