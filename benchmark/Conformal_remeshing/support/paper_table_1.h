// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's Table 1 (Robust Surface Remeshing Based on Conformal Welding): its five car parts,
// the generator that stands in for each (generators/paper_models.h), their sizes before and after
// remeshing and the paper's times of the parameterization and remeshing steps.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_TABLE_1_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_TABLE_1_H

#include "paper_models.h"

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

struct Paper_table_1_row
{
  Paper_model model;            ///< our generator for the part (same figure, same input size)
  const char* part;             ///< the part as Table 1 names it
  int figure;                   ///< the paper's figure showing it
  std::size_t input_vertices;   ///< "#Vertices" before the slash
  std::size_t output_vertices;  ///< ... and after it
  std::size_t input_faces;      ///< "#Faces" before the slash
  std::size_t output_faces;     ///< ... and after it
  double parameterization_seconds;
  double remeshing_seconds;
  /// whether the paper cuts the part by its mid-plane (Sec. 5: the genus-83 brake)
  bool mid_plane_cut;
};

/// Table 1, row by row (the paper's "Suspension 7" is the suspension part of Fig. 7, and so on).
inline const std::vector<Paper_table_1_row>& paper_table_1()
{
  static const std::vector<Paper_table_1_row> rows = {
    {Paper_model::suspension_arm, "Suspension", 7, 87000, 23000, 173000, 43000, 3 * 60 + 40, 6, false},
    {Paper_model::shield, "Shield", 2, 134000, 59000, 263000, 113000, 6 * 60 + 39, 18, false},
    {Paper_model::radiator_shell, "Shell", 8, 263000, 69000, 524000, 137000, 8 * 60 + 15, 36, false},
    {Paper_model::chassis, "Chassis", 6, 338000, 81000, 673000, 158000, 11 * 60 + 21, 25, false},
    {Paper_model::brake_disc, "Brake", 9, 804000, 175000, 1572000, 315000, 34 * 60 + 48, 5 * 60 + 31, true}};
  return rows;
}

/// The speed-up targets: each step at least this many times faster than Table 1 on the same
/// input size, and under this peak memory at the largest size.
constexpr double paper_speed_up_target = 20.;
constexpr double peak_memory_target_megabytes = 8192.;

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_PAPER_TABLE_1_H
