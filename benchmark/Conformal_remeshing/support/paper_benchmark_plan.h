// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The runs of the paper benchmark (run_paper_benchmark.sh): Table 1's five parts remeshed by
// remesh_conformal() and by each peer (CGAL's isotropic_remeshing(), Gmsh, MeshLab), and one part
// family at five sizes for the growth of every stage. One list, read by the script (what to generate and run) and by the summary (what to
// expect), so that the two cannot disagree.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_BENCHMARK_PLAN_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_BENCHMARK_PLAN_H

#include "paper_models.h"
#include "paper_table_1.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// `full`: Table 1's sizes and 10k to 1M vertices for the growth; `small`: a tenth of Table 1's
/// sizes and 10k to 100k, to rerun in minutes.
enum class Benchmark_scale { full, small };

inline Benchmark_scale benchmark_scale_from_name(const std::string& name)
{
  if(name == "full")
    return Benchmark_scale::full;
  if(name == "small")
    return Benchmark_scale::small;
  throw std::invalid_argument("unknown scale '" + name + "' (full or small)");
}

inline const char* benchmark_scale_name(Benchmark_scale scale) { return scale == Benchmark_scale::full ? "full" : "small"; }

struct Planned_run
{
  std::string id;    ///< the name of the run's files (`runs/<id>.json`)
  std::string part;  ///< "table" (Table 1) or "scaling"
  Paper_model model;
  std::size_t input_vertices;
  /// the output size the target edge length is chosen for (Table 1's ratio of output to input)
  std::size_t output_vertices;
  /// "conformal" (remesh_conformal), or a peer: "isotropic" (isotropic_remeshing), "gmsh", "meshlab"
  std::string method;
  bool mid_plane_cut;
  const Paper_table_1_row* row; ///< the Table 1 row of a "table" run, else null
};

/// The remeshers of Table 1's runs; the plan lists the first two unless asked for the others, which
/// need programs outside CGAL (`scripts/install_dependencies.sh --benchmarks`).
inline const std::vector<std::string>& paper_benchmark_methods()
{
  static const std::vector<std::string> methods{"conformal", "isotropic", "gmsh", "meshlab"};
  return methods;
}

inline bool is_default_paper_benchmark_method(const std::string& method)
{
  return method == "conformal" || method == "isotropic";
}

/// The family whose growth is measured, and the sizes.
constexpr Paper_model scaling_model = Paper_model::suspension_arm;

inline std::vector<std::size_t> scaling_sizes(Benchmark_scale scale)
{
  // Five sizes evenly spaced in log: 10^4 to 10^6 (full), 10^4 to 10^5 (small).
  const double decades = scale == Benchmark_scale::full ? 2. : 1.;
  std::vector<std::size_t> sizes;
  for(int i = 0; i < 5; ++i)
    sizes.push_back(std::size_t(std::lround(1e4 * std::pow(10., decades * i / 4.))));
  return sizes;
}

inline std::vector<Planned_run> paper_benchmark_plan(Benchmark_scale scale)
{
  const double factor = scale == Benchmark_scale::full ? 1. : 0.1;
  std::vector<Planned_run> runs;
  for(const Paper_table_1_row& row : paper_table_1())
    for(const std::string& method : paper_benchmark_methods())
    {
      const std::string name = paper_model_info(row.model).name;
      runs.push_back(Planned_run{"table_" + name + "_" + method, "table", row.model,
                                 std::size_t(std::lround(factor * double(row.input_vertices))),
                                 std::size_t(std::lround(factor * double(row.output_vertices))), method,
                                 row.mid_plane_cut, &row});
    }
  double ratio = 0.25;
  for(const Paper_table_1_row& row : paper_table_1())
    if(row.model == scaling_model)
      ratio = double(row.output_vertices) / double(row.input_vertices);
  for(std::size_t n : scaling_sizes(scale))
  {
    const std::string name = paper_model_info(scaling_model).name;
    runs.push_back(Planned_run{"scaling_" + name + "_" + std::to_string(n) + "_conformal", "scaling", scaling_model, n,
                               std::size_t(std::lround(ratio * double(n))), "conformal", false, nullptr});
  }
  return runs;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_BENCHMARK_PLAN_H
