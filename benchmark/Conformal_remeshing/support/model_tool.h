// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the model generators' command lines share: strict number parsing, the atomic OFF
// writer and the one-line summary of a model.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_MODEL_TOOL_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_MODEL_TOOL_H

#include "cad_like_models.h"

#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/Surface_mesh.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// `text` as a finite number; throws `std::invalid_argument` naming `option` otherwise.
inline double parse_double(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value))
    throw std::invalid_argument(option + ": not a number: '" + text + "'");
  return value;
}

/// `text` as an integer; throws `std::invalid_argument` naming `option` otherwise.
inline long long parse_integer(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if(text.empty() || *end != '\0' || errno != 0)
    throw std::invalid_argument(option + ": not an integer: '" + text + "'");
  return value;
}

/// Writes `mesh` as OFF with 17 significant digits to `path` + ".tmp", then renames it, so
/// that a reader never sees a half-written model. Throws `std::runtime_error` on failure.
template <class Point_3>
void write_off_atomically(const CGAL::Surface_mesh<Point_3>& mesh, const std::string& path)
{
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary);
    if(!out)
      throw std::runtime_error("cannot open '" + temporary + "' for writing: " + std::strerror(errno));
    if(!CGAL::IO::write_OFF(out, mesh, CGAL::parameters::stream_precision(17)) || !out.flush()) {
      out.close();
      std::remove(temporary.c_str());
      throw std::runtime_error("cannot write '" + temporary + "'");
    }
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot rename '" + temporary + "' to '" + path + "': " + reason);
  }
}

/// The summary of a written model, without the end of line: its name and file, counts, genus,
/// boundary loops and the share of triangles with a minimum angle below 10 and 1 degrees.
inline void print_model_summary(std::ostream& out, const std::string& model, const std::string& path,
                                const Cad_model_statistics& s)
{
  out << model << ": " << path << ": " << s.vertices << " vertices, " << s.faces << " faces, genus " << s.genus;
  if(s.boundary_loops > 0)
    out << ", " << s.boundary_loops << " boundary loops";
  out << ", min angle " << s.min_angle_degrees << " deg, " << 100. * s.share_min_angle_below_10
      << "% of triangles below 10 deg, " << 100. * s.share_min_angle_below_1 << "% below 1 deg";
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_MODEL_TOOL_H
