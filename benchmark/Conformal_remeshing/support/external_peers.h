// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The remeshing benchmark's peers outside CGAL, each run as a subprocess on a file written into a
// temporary directory, under the `timeout` command: Gmsh (the input merged as STL, its surfaces
// classified at 40 degrees and reparametrized, meshed with Mesh.Algorithm 6, "Frontal-Delaunay")
// and MeshLab's "Remeshing: Isotropic Explicit Remeshing" through meshlabserver under xvfb-run (a
// generated .mlx filter script, OFF files in and out). Each run returns its output mesh, its wall
// seconds and a status, so that a failure, a time-out or a missing program is a result of the
// benchmark, never the end of it. Also: tuning a peer's target length until its output has a given
// number of vertices (the benchmark's comparison at the same output size).

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_EXTERNAL_PEERS_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_EXTERNAL_PEERS_H

#include "timing.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// How a peer's run ended; `peer_status_name()` gives the word the benchmark records.
enum class Peer_status { ok, failed, timed_out, not_installed };

inline const char* peer_status_name(Peer_status s)
{
  switch(s)
  {
  case Peer_status::ok: return "ok";
  case Peer_status::failed: return "failed";
  case Peer_status::timed_out: return "timed out";
  default: return "not installed";
  }
}

/// One run of a peer: its output (empty unless `status` is ok), the wall seconds of the run (of
/// the subprocess, for the external peers) and why it failed.
template <typename Mesh>
struct Peer_run
{
  Peer_status status = Peer_status::failed;
  std::string reason;
  double seconds = 0.;
  Mesh mesh;
};

/// Whether `program` is an executable file in a directory of `PATH`.
inline bool program_on_path(const std::string& program)
{
  const char* path = std::getenv("PATH");
  std::istringstream directories(path ? path : "");
  for(std::string directory; std::getline(directories, directory, ':');)
  {
    const std::filesystem::path candidate = std::filesystem::path(directory.empty() ? "." : directory) / program;
    std::error_code error;
    const auto permissions = std::filesystem::status(candidate, error).permissions();
    if(!error && std::filesystem::is_regular_file(candidate, error)
       && (permissions & std::filesystem::perms::owner_exec) != std::filesystem::perms::none)
      return true;
  }
  return false;
}

/// A fresh directory under the system's temporary directory, removed with its files at the end of
/// the object's life.
class Temporary_directory
{
public:
  Temporary_directory()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "remeshing_peer_XXXXXX").string();
    if(::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create a temporary directory in " + std::filesystem::temp_directory_path().string());
    path_ = pattern;
  }
  ~Temporary_directory()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  Temporary_directory(const Temporary_directory&) = delete;
  Temporary_directory& operator=(const Temporary_directory&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

/// `s` quoted for the shell.
inline std::string shell_quoted(const std::string& s)
{
  std::string quoted = "'";
  for(char c : s)
    quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// The end of a subprocess: its exit code (or 128 + the signal that ended it) and its wall seconds.
struct Command_result
{
  int exit_code = -1;
  double seconds = 0.;
  bool timed_out() const { return exit_code == 124 || exit_code == 128 + 9; } // `timeout`'s codes
};

/// Runs `arguments` under `timeout` (TERM after `timeout_seconds`, KILL 5 s later; `timeout`
/// signals the whole process group, so xvfb-run's children end too), its output into `log`.
inline Command_result run_command(const std::vector<std::string>& arguments, const std::string& log, double timeout_seconds)
{
  std::ostringstream command;
  command << "timeout --kill-after=5 " << std::fixed << std::setprecision(1) << timeout_seconds;
  for(const std::string& a : arguments)
    command << " " << shell_quoted(a);
  command << " </dev/null >" << shell_quoted(log) << " 2>&1";
  Command_result result;
  int status = 0;
  result.seconds = wall_seconds([&] { status = std::system(command.str().c_str()); });
  if(status == -1)
    result.exit_code = -1;
  else if(WIFEXITED(status))
    result.exit_code = WEXITSTATUS(status);
  else if(WIFSIGNALED(status))
    result.exit_code = 128 + WTERMSIG(status);
  return result;
}

/// The last line of `log` that contains `word` (or its last line when none does), for a reason.
inline std::string log_line(const std::string& log, const std::string& word)
{
  std::ifstream in(log);
  std::string line, last, found;
  while(std::getline(in, line))
  {
    if(line.empty())
      continue;
    last = line;
    if(line.find(word) != std::string::npos)
      found = line;
  }
  std::string text = found.empty() ? last : found;
  if(text.size() > 200)
    text = text.substr(0, 200) + "...";
  return text;
}

/// Writes `mesh` as ASCII STL with full precision (binary STL would round to floats).
template <typename Point_3>
void write_ascii_stl(const CGAL::Surface_mesh<Point_3>& mesh, const std::string& path)
{
  std::ofstream out(path);
  out << std::setprecision(17) << "solid input\n";
  for(auto f : mesh.faces())
  {
    out << " facet normal 0 0 0\n  outer loop\n";
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh))
      out << "   vertex " << mesh.point(v) << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid input\n";
  if(!out)
    throw std::runtime_error("cannot write '" + path + "'");
}

/// A triangle soup as a mesh: duplicate points merged, isolated points and degenerate polygons
/// dropped, oriented (a non-manifold vertex is duplicated). False when no triangle is left.
template <typename Point_3>
bool soup_to_mesh(std::vector<Point_3>& points, std::vector<std::vector<std::size_t> >& triangles,
                  CGAL::Surface_mesh<Point_3>& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::repair_polygon_soup(points, triangles);
  if(triangles.empty())
    return false;
  PMP::orient_polygon_soup(points, triangles);
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return !faces(mesh).empty();
}

/// Reads the triangles of a Gmsh mesh file in the ASCII format 2.2 (nodes, then elements of type
/// 2); the points and lines of the geometry's vertices and curves are skipped.
template <typename Point_3>
bool read_gmsh_triangles(const std::string& path, std::vector<Point_3>& points, std::vector<std::vector<std::size_t> >& triangles)
{
  std::ifstream in(path);
  std::unordered_map<long, std::size_t> index_of_node;
  for(std::string section; in >> section;)
  {
    long count = 0;
    if(section == "$Nodes" && (in >> count))
      for(long i = 0; i < count; ++i)
      {
        long id;
        double x, y, z;
        if(!(in >> id >> x >> y >> z))
          return false;
        index_of_node[id] = points.size();
        points.emplace_back(x, y, z);
      }
    else if(section == "$Elements" && (in >> count))
      for(long i = 0; i < count; ++i)
      {
        std::string line;
        std::getline(in >> std::ws, line);
        std::istringstream fields(line);
        long id, type, tags;
        fields >> id >> type >> tags;
        for(long t = 0; t < tags; ++t)
          fields >> id;
        std::array<long, 3> nodes;
        if(type != 2 || !(fields >> nodes[0] >> nodes[1] >> nodes[2]))
          continue;
        std::vector<std::size_t> triangle;
        for(long n : nodes)
          if(index_of_node.count(n))
            triangle.push_back(index_of_node[n]);
        if(triangle.size() == 3)
          triangles.push_back(triangle);
      }
  }
  return true;
}

/// The Gmsh script: the input's surfaces classified at 40-degree features (boundaries kept,
/// reparametrizable patches, curves split at 180 degrees), geometry created, then the mesh
/// options at target length `h`; the mesher is run with `-2`.
inline std::string gmsh_script(const std::string& stl, double h)
{
  std::ostringstream s;
  s << std::setprecision(17) << "Merge \"" << stl << "\";\n"
    << "ClassifySurfaces{40 * Pi / 180, 1, 1, Pi};\n"
    << "CreateGeometry;\n"
    << "Mesh.Algorithm = 6;\n"
    << "Mesh.CharacteristicLengthMin = " << h << ";\n"
    << "Mesh.CharacteristicLengthMax = " << h << ";\n"
    << "Mesh.MshFileVersion = 2.2;\n";
  return s.str();
}

/// The MeshLab filter script: isotropic explicit remeshing at the absolute target length `h`,
/// MeshLab's default 10 iterations and steps, crease angle 60 degrees, each local operation kept
/// within h / 10 of the input.
inline std::string meshlab_script(double h)
{
  std::ostringstream s;
  const auto absolute = [&](const char* name, double value) {
    s << "  <Param type=\"RichAbsPerc\" value=\"" << value << "\" min=\"0\" max=\"" << 100. * h << "\" name=\"" << name << "\"/>\n";
  };
  const auto flag = [&](const char* name, bool value) {
    s << "  <Param type=\"RichBool\" value=\"" << (value ? "true" : "false") << "\" name=\"" << name << "\"/>\n";
  };
  s << std::setprecision(17) << "<!DOCTYPE FilterScript>\n<FilterScript>\n"
    << " <filter name=\"Remeshing: Isotropic Explicit Remeshing\">\n"
    << "  <Param type=\"RichInt\" value=\"10\" name=\"Iterations\"/>\n";
  flag("Adaptive", false);
  flag("SelectedOnly", false);
  absolute("TargetLen", h);
  s << "  <Param type=\"RichFloat\" value=\"60\" name=\"FeatureDeg\"/>\n";
  flag("CheckSurfDist", true);
  absolute("MaxSurfDist", 0.1 * h);
  for(const char* step : {"SplitFlag", "CollapseFlag", "SwapFlag", "SmoothFlag", "ReprojectFlag"})
    flag(step, true);
  s << " </filter>\n</FilterScript>\n";
  return s.str();
}

/// A run that did not start or did not finish: the status and reason from the command's end.
template <typename Mesh>
bool command_failed(const Command_result& c, const std::string& log, const char* word, Peer_run<Mesh>& run)
{
  run.seconds = c.seconds;
  if(c.timed_out())
  {
    run.status = Peer_status::timed_out;
    run.reason = "no output after the time-out";
    return true;
  }
  if(c.exit_code != 0)
  {
    run.status = Peer_status::failed;
    run.reason = "exit code " + std::to_string(c.exit_code) + ": " + log_line(log, word);
    return true;
  }
  return false;
}

/// Gmsh on `input` at target length `h`, `timeout_seconds` at most.
template <typename Point_3>
Peer_run<CGAL::Surface_mesh<Point_3> > run_gmsh_peer(const CGAL::Surface_mesh<Point_3>& input, double h, double timeout_seconds)
{
  Peer_run<CGAL::Surface_mesh<Point_3> > run;
  if(!program_on_path("gmsh") || !program_on_path("timeout"))
  {
    run.status = Peer_status::not_installed;
    run.reason = "gmsh (or timeout) is not on PATH";
    return run;
  }
  const Temporary_directory directory;
  const std::string stl = directory.file("input.stl"), geo = directory.file("remesh.geo"), msh = directory.file("output.msh"),
                    log = directory.file("gmsh.log");
  write_ascii_stl(input, stl);
  std::ofstream(geo) << gmsh_script(stl, h);
  const Command_result c = run_command({"gmsh", geo, "-2", "-o", msh}, log, timeout_seconds);
  if(command_failed(c, log, "Error", run))
    return run;
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > triangles;
  if(!read_gmsh_triangles(msh, points, triangles) || !soup_to_mesh(points, triangles, run.mesh))
  {
    run.reason = "no triangles in the output: " + log_line(log, "Error");
    return run;
  }
  run.status = Peer_status::ok;
  return run;
}

/// MeshLab's isotropic explicit remeshing on `input` at target length `h`, `timeout_seconds` at most.
template <typename Point_3>
Peer_run<CGAL::Surface_mesh<Point_3> > run_meshlab_peer(const CGAL::Surface_mesh<Point_3>& input, double h, double timeout_seconds)
{
  Peer_run<CGAL::Surface_mesh<Point_3> > run;
  for(const char* program : {"meshlabserver", "xvfb-run", "xauth", "timeout"})
    if(!program_on_path(program))
    {
      run.status = Peer_status::not_installed;
      run.reason = std::string(program) + " is not on PATH";
      return run;
    }
  const Temporary_directory directory;
  const std::string in = directory.file("input.off"), mlx = directory.file("remesh.mlx"), out = directory.file("output.off"),
                    log = directory.file("meshlab.log");
  {
    std::ofstream off(in);
    off << std::setprecision(17);
    if(!CGAL::IO::write_OFF(off, input))
      throw std::runtime_error("cannot write '" + in + "'");
  }
  std::ofstream(mlx) << meshlab_script(h);
  const Command_result c = run_command({"xvfb-run", "-a", "meshlabserver", "-i", in, "-o", out, "-s", mlx}, log, timeout_seconds);
  if(command_failed(c, log, "ailed", run))
    return run;
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > triangles;
  if(!CGAL::IO::read_polygon_soup(out, points, triangles) || !soup_to_mesh(points, triangles, run.mesh))
  {
    run.reason = "no triangles in the output: " + log_line(log, "ailed");
    return run;
  }
  run.status = Peer_status::ok;
  return run;
}

/// A peer's run at a target length.
template <typename Mesh>
using Peer_runner = std::function<Peer_run<Mesh>(double h)>;

/// The outcome of tuning a peer's target length to an output size.
template <typename Mesh>
struct Tuned_run
{
  Peer_run<Mesh> run;          // the run closest to the wanted size (or the first that failed)
  double target_edge_length = 0.;
  int runs = 0;
  bool within_tolerance = false;
};

/// Runs `peer` at target lengths tuned until its output has `wanted` vertices within `tolerance`
/// (a share of `wanted`), `max_runs` runs at most: first at `h`, then by the secant of
/// log(vertices) against log(length) through the last two runs (the first step assumes vertices
/// proportional to 1 / length^2), by bisection (of the logarithms) between the longest length
/// known to give too many vertices and the shortest known to give too few when the secant leaves
/// that bracket, as counts that jump with the length make it do. A failed run ends the tuning
/// with that run.
template <typename Mesh>
Tuned_run<Mesh> tune_to_vertex_count(const Peer_runner<Mesh>& peer, double h, std::size_t wanted,
                                     double tolerance = 0.05, int max_runs = 8)
{
  Tuned_run<Mesh> best;
  double best_error = std::numeric_limits<double>::infinity();
  double previous_log_h = 0., previous_log_n = 0., slope = -2.;
  double too_many = 0., too_few = std::numeric_limits<double>::infinity(); // the bracket's lengths
  for(int k = 0; k < max_runs; ++k)
  {
    Peer_run<Mesh> run = peer(h);
    ++best.runs;
    if(run.status != Peer_status::ok)
    {
      best.run = std::move(run);
      best.target_edge_length = h;
      return best;
    }
    const double n = double(run.mesh.number_of_vertices());
    const double error = std::abs(n - double(wanted)) / double(wanted);
    if(error < best_error)
    {
      best_error = error;
      best.run = std::move(run);
      best.target_edge_length = h;
    }
    if(error <= tolerance || n < 1.)
      break;
    if(n > double(wanted))
      too_many = std::max(too_many, h);
    else
      too_few = std::min(too_few, h);
    if(k > 0 && std::abs(std::log(h) - previous_log_h) > 1e-12)
    {
      const double secant = (std::log(n) - previous_log_n) / (std::log(h) - previous_log_h);
      if(secant < -0.5 && secant > -8.) // a count that falls as the length grows; else keep the slope
        slope = secant;
    }
    previous_log_h = std::log(h);
    previous_log_n = std::log(n);
    h = std::exp(previous_log_h + (std::log(double(wanted)) - previous_log_n) / slope);
    if(too_many > 0. && too_few < std::numeric_limits<double>::infinity() && !(h > too_many && h < too_few))
      h = std::sqrt(too_many * too_few);
  }
  best.within_tolerance = best_error <= tolerance;
  return best;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_EXTERNAL_PEERS_H
