// Benchmark of the dynamic discrete Ricci flow on generated disc-topology meshes.
//
// Usage: ricci_flow_benchmark [--sizes 10000,100000,1000000] [--runs 3] [--kinds smooth,cad]
//                             [--solvers ldlt,cholmod] [--json results.json]
//
// For each case (kind x size x solver) and run, a child process generates the mesh, builds the
// intrinsic triangulation, flattens it (targets 0 inside, 2 pi / n on the boundary, tolerance
// 1e-9) and lays it out; the parent reads the child's numbers from a pipe and its peak resident
// memory from wait4(). The table shows the median over the runs of every time.
//
// Kinds: "smooth" is a regular grid on a smooth bump over [0,1]^2; "cad" imitates CAD
// tessellations: rows of many points alternate with rows of 16 times fewer points over a
// 4:1 strip, so the rows are fanned by slivers (minimum angles well below 1 degree).
// The CHOLMOD solver exists when the program is compiled with
// CGAL_CONFORMAL_REMESHING_WITH_CHOLMOD and linked with SuiteSparse's cholmod.

#include <CGAL/Conformal_remeshing/Intrinsic_triangulation.h>
#include <CGAL/Conformal_remeshing/discrete_ricci_flow.h>

#include "timing.h"

#ifdef CGAL_CONFORMAL_REMESHING_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
typedef CR::Intrinsic_triangulation<double> Tri;

namespace {

const double pi = 3.14159265358979323846;

struct Generated
{
  std::size_t nv = 0;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<double, 3>> lengths;
};

void finish(const std::vector<std::array<double, 3>>& pts, Generated& g)
{
  g.nv = pts.size();
  g.lengths.resize(g.faces.size());
  for(std::size_t f = 0; f < g.faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const auto& a = pts[g.faces[f][c]];
      const auto& b = pts[g.faces[f][(c + 1) % 3]];
      g.lengths[f][c] = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
}

// n x n grid cells on z = 0.15 sin(2 pi x) sin(2 pi y), alternating diagonals.
Generated smooth_disc(std::size_t target_vertices)
{
  const int n = std::max(2, int(std::lround(std::sqrt(double(target_vertices)))) - 1);
  std::vector<std::array<double, 3>> pts;
  pts.reserve((n + 1) * (n + 1));
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const double x = double(i) / n, y = double(j) / n;
      pts.push_back({{x, y, 0.15 * std::sin(2 * pi * x) * std::sin(2 * pi * y)}});
    }
  Generated g;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      if((i + j) % 2 == 0)
      {
        g.faces.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
        g.faces.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
      }
      else
      {
        g.faces.push_back({{id(i, j), id(i + 1, j), id(i, j + 1)}});
        g.faces.push_back({{id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}});
      }
    }
  finish(pts, g);
  return g;
}

// Rows over the strip [0,1] x [0,0.25] on a gentle bump; even rows have m points at uneven
// spacing, odd rows m/16; consecutive rows are zipped by x.
Generated cad_disc(std::size_t target_vertices)
{
  // (R/2) m (1 + 1/16) ~ target, with m = 2 R
  const int R = std::max(2, 2 * int(std::lround(std::sqrt(double(target_vertices) / (1. + 1. / 16.)) / 2.)));
  const int m = std::max(17, 2 * R);
  const double height = 0.25;
  std::vector<std::array<double, 3>> pts;
  std::vector<std::vector<int>> row(R + 1);
  for(int r = 0; r <= R; ++r)
  {
    const int n = (r % 2 == 0) ? m : std::max(2, m / 16);
    const double y = height * r / R;
    for(int i = 0; i < n; ++i)
    {
      const double t = double(i) / (n - 1);
      const double x = t + 0.3 * t * (1 - t) * std::sin(7 * t + r); // increasing in t
      row[r].push_back(int(pts.size()));
      pts.push_back({{x, y, 0.1 * std::sin(pi * x) * std::sin(pi * y / height)}});
    }
  }
  Generated g;
  for(int r = 0; r < R; ++r)
  {
    const std::vector<int>& a = row[r];
    const std::vector<int>& b = row[r + 1];
    std::size_t i = 0, j = 0;
    while(i + 1 < a.size() || j + 1 < b.size())
    {
      const bool advance_a = (j + 1 == b.size()) || (i + 1 < a.size() && pts[a[i + 1]][0] <= pts[b[j + 1]][0]);
      if(advance_a) { g.faces.push_back({{a[i], a[i + 1], b[j]}}); ++i; }
      else { g.faces.push_back({{a[i], b[j + 1], b[j]}}); ++j; }
    }
  }
  finish(pts, g);
  return g;
}

struct Case_result
{
  std::size_t vertices = 0, faces = 0, flips = 0, splits = 0;
  int iterations = 0, factorizations = 0, converged = 0, negative_triangles = 0;
  double min_angle_degrees = 0, final_error = 0;
  double t_generate = 0, t_build = 0, t_flips = 0, t_assembly = 0, t_factor = 0, t_solve = 0, t_line = 0,
         t_flow = 0, t_layout = 0;
  double peak_mb = 0;
};

typedef std::chrono::steady_clock Clock;
double since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

template <typename Solver>
Case_result run_case(const std::string& kind, std::size_t size)
{
  Case_result res;
  Clock::time_point t0 = Clock::now();
  Generated g = kind == "cad" ? cad_disc(size) : smooth_disc(size);
  res.t_generate = since(t0);
  t0 = Clock::now();
  Tri tri(g.nv, g.faces, g.lengths);
  res.t_build = since(t0);
  res.vertices = g.nv;
  res.faces = g.faces.size();
  { Generated().faces.swap(g.faces); g.lengths.clear(); g.lengths.shrink_to_fit(); }
  double min_angle = 180;
  for(int f = 0; f < tri.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c)
      min_angle = std::min(min_angle, tri.corner_angle(f, c) * 180 / pi);
  res.min_angle_degrees = min_angle;

  auto r = CR::discrete_ricci_flow(tri, CR::disc_flattening_targets(tri),
                                   CR::parameters::curvature_tolerance(1e-9, CGAL::parameters::sparse_linear_solver(Solver())
                                                                                 .number_of_iterations(30)));
  res.converged = r.converged ? 1 : 0;
  res.iterations = r.iterations;
  res.flips = r.number_of_flips;
  res.splits = r.number_of_splits;
  res.factorizations = r.number_of_factorizations;
  res.final_error = r.max_curvature_error;
  res.t_flips = r.seconds_flips;
  res.t_assembly = r.seconds_assembly;
  res.t_factor = r.seconds_factorization;
  res.t_solve = r.seconds_solve;
  res.t_line = r.seconds_line_search;
  res.t_flow = r.seconds_total;
  t0 = Clock::now();
  std::vector<Tri::Point_2> corners;
  tri.layout(0, &corners);
  res.t_layout = since(t0);
  for(int f = 0; f < tri.number_of_faces(); ++f)
  {
    const auto& a = corners[3 * f];
    const auto& b = corners[3 * f + 1];
    const auto& c = corners[3 * f + 2];
    if((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0)
      ++res.negative_triangles;
  }
  return res;
}

Case_result run_in_child(const std::string& kind, std::size_t size, const std::string& solver)
{
  int fd[2];
  if(pipe(fd) != 0) { std::perror("pipe"); std::exit(1); }
  const pid_t pid = fork();
  if(pid == 0)
  {
    close(fd[0]);
    Case_result r;
    try
    {
      if(solver == "ldlt")
        r = run_case<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(kind, size);
#ifdef CGAL_CONFORMAL_REMESHING_WITH_CHOLMOD
      else if(solver == "cholmod")
        r = run_case<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>>(kind, size);
#endif
      else
        _exit(3);
    }
    catch(const std::exception& e)
    {
      std::cerr << "case " << kind << " " << size << " failed: " << e.what() << "\n";
      _exit(4);
    }
    const ssize_t w = write(fd[1], &r, sizeof(r));
    _exit(w == ssize_t(sizeof(r)) ? 0 : 5);
  }
  close(fd[1]);
  Case_result r;
  std::size_t got = 0;
  while(got < sizeof(r))
  {
    const ssize_t n = read(fd[0], reinterpret_cast<char*>(&r) + got, sizeof(r) - got);
    if(n <= 0) break;
    got += std::size_t(n);
  }
  close(fd[0]);
  int status = 0;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  if(got != sizeof(r) || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    std::cerr << "case " << kind << " " << size << " " << solver << ": child failed (status " << status << ")\n";
    r = Case_result();
    r.converged = -1;
  }
  r.peak_mb = usage.ru_maxrss / 1024.; // Linux: kilobytes
  return r;
}

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ','))
    if(!item.empty()) out.push_back(item);
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> sizes{"10000", "100000", "1000000"}, kinds{"smooth", "cad"}, solvers{"ldlt"};
  int runs = 3;
  std::string json = "ricci_flow_benchmark.json";
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(i + 1 >= argc) { std::cerr << "missing value after " << a << "\n"; return 2; }
    if(a == "--sizes") sizes = split(argv[++i]);
    else if(a == "--kinds") kinds = split(argv[++i]);
    else if(a == "--solvers") solvers = split(argv[++i]);
    else if(a == "--runs") runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--json") json = argv[++i];
    else { std::cerr << "unknown option " << a << "\n"; return 2; }
  }
#ifndef CGAL_CONFORMAL_REMESHING_WITH_CHOLMOD
  for(const std::string& s : solvers)
    if(s == "cholmod") { std::cerr << "this build has no CHOLMOD support\n"; return 2; }
#endif

  std::ostringstream js;
  js << "{\n  \"benchmark\": \"ricci_flow\",\n  \"tolerance\": 1e-9,\n  \"runs\": " << runs << ",\n  \"cases\": [";
  std::printf("%-6s %8s %8s %-7s %5s %4s %4s %9s %6s %8s %8s %8s %8s %8s %8s %8s %8s %9s %5s\n", "kind", "vertices", "minang",
              "solver", "conv", "it", "fact", "flips", "splits", "build", "flips_s", "assem", "factor", "solve", "lsearch", "flow",
              "layout", "peak_MB", "neg");
  bool first = true;
  for(const std::string& kind : kinds)
    for(const std::string& size : sizes)
      for(const std::string& solver : solvers)
      {
        std::vector<Case_result> rs;
        for(int k = 0; k < runs; ++k)
          rs.push_back(run_in_child(kind, std::stoul(size), solver));
        auto med = [&](double Case_result::*m) {
          std::vector<double> v;
          for(const auto& r : rs) v.push_back(r.*m);
          return CR::benchmarks::median(v);
        };
        const Case_result& r0 = rs.front();
        const double t_build = med(&Case_result::t_build), t_flips = med(&Case_result::t_flips),
                     t_as = med(&Case_result::t_assembly), t_fa = med(&Case_result::t_factor),
                     t_so = med(&Case_result::t_solve), t_ls = med(&Case_result::t_line),
                     t_flow = med(&Case_result::t_flow), t_lay = med(&Case_result::t_layout),
                     t_gen = med(&Case_result::t_generate), peak = med(&Case_result::peak_mb);
        std::printf("%-6s %8zu %8.4f %-7s %5d %4d %4d %9zu %6zu %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %9.1f %5d\n",
                    kind.c_str(), r0.vertices, r0.min_angle_degrees, solver.c_str(), r0.converged, r0.iterations,
                    r0.factorizations, r0.flips, r0.splits,
                    t_build, t_flips, t_as, t_fa, t_so, t_ls, t_flow, t_lay, peak, r0.negative_triangles);
        std::fflush(stdout);
        js << (first ? "\n" : ",\n") << "    {\"kind\": \"" << kind << "\", \"vertices\": " << r0.vertices
           << ", \"faces\": " << r0.faces << ", \"min_angle_degrees\": " << r0.min_angle_degrees << ", \"solver\": \""
           << solver << "\", \"converged\": " << (r0.converged == 1 ? "true" : "false")
           << ", \"newton_iterations\": " << r0.iterations << ", \"factorizations\": " << r0.factorizations
           << ", \"flips\": " << r0.flips << ", \"splits\": " << r0.splits
           << ", \"final_max_curvature_error\": " << r0.final_error
           << ", \"negative_layout_triangles\": " << r0.negative_triangles << ", \"median_seconds\": {\"generate\": " << t_gen
           << ", \"build\": " << t_build << ", \"flips\": " << t_flips << ", \"assembly\": " << t_as
           << ", \"factorization\": " << t_fa << ", \"solve\": " << t_so << ", \"line_search\": " << t_ls
           << ", \"flow_total\": " << t_flow << ", \"layout\": " << t_lay << "}, \"peak_memory_mb\": " << peak
           << ", \"runs\": " << rs.size() << "}";
        first = false;
      }
  js << "\n  ]\n}\n";
  std::ofstream out(json);
  out << js.str();
  if(!out) { std::cerr << "cannot write " << json << "\n"; return 1; }
  std::cout << "wrote " << json << "\n";
  return 0;
}
