// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The generated patches the flattening and remeshing benchmarks run on, before any mesh files
// given on their command lines.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_GENERATED_PATCHES_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_GENERATED_PATCHES_H

#include "cad_like_models.h"
#include "test_surfaces.h"

#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// The wavy C strip, optionally a spherical cap (coarse and fine), and CAD-like bent sheets (10 holes, and also 1
/// hole with `with_cap`), with their names. The bent sheets are tessellated as exporters do
/// curved faces (grid points inside at a 0.1 chord tolerance; bending fans of slivers instead
/// crumples them into false sharp edges, a generator defect rather than a CAD input); with
/// `with_cap`, a flat sheet of fans of slivers with 10 holes too.
template <typename Mesh>
std::vector<std::pair<std::string, Mesh> > generated_patches(bool with_cap)
{
  std::vector<std::pair<std::string, Mesh> > models;
  Mesh strip;
  make_wavy_c_strip(strip);
  models.emplace_back("wavy C strip", strip);
  if(with_cap)
  {
    Mesh cap, fine_cap;
    make_spherical_cap(cap, 120., 16, 48);
    models.emplace_back("spherical cap", cap);
    // The same cap with edges 0.6 times the target instead of 5.7 times: a remesher that starts
    // from the input's faces (the peer) no longer lies on them, and the distances compare shapes.
    make_spherical_cap(fine_cap, 120., 160, 480);
    models.emplace_back("spherical cap, fine", fine_cap);
  }
  for(int holes : with_cap ? std::vector<int>{1, 10} : std::vector<int>{10})
  {
    Mesh sheet;
    Perforated_plate_parameters p;
    p.number_of_random_holes = holes;
    make_perforated_sheet(sheet, p, 0.3, true);
    models.emplace_back("CAD sheet, " + std::to_string(holes) + " holes", sheet);
  }
  if(with_cap)
  {
    Mesh flat;
    Perforated_plate_parameters p;
    p.number_of_random_holes = 10;
    make_perforated_sheet(flat, p);
    models.emplace_back("flat sheet, 10 holes", flat);
  }
  return models;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_GENERATED_PATCHES_H
