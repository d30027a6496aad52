// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The meshing stage of `remesh_conformal()`: every patch boundary curve sampled once, in 3D,
// then every patch meshed on those shared samples (`remesh_flattened_patch()`), in parallel.
// The stage also mends what one patch's mesh alone cannot show: chords that do not glue (the
// curves are sampled more densely) and diagonals that two patches share (all but one patch split
// them).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCHES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCHES_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_curves.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/mesh_patch.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/segment_and_flatten.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// How each patch is meshed in the plane and optimized on the surface.
struct Patch_meshing
{
  double minimum_angle = 28.;
  Planar_smoothing smoothing;
  Frontal_insertion frontal;
  int optimization_rounds = 5;
  bool moves_in_parallel = false;
};

/// The boundary samples shared by the patches, and each patch remeshed on them.
struct Meshed_patches
{
  Curve_samples samples;
  std::vector<Remeshed_patch> remeshed;
};

typedef std::set<std::pair<std::size_t, std::size_t> > Sample_pairs;

/// Meshes the patches `to_mesh` of `surface` on `samples` into `remeshed`, in parallel.
/// \throws Error with `Error_code::NOT_AN_EMBEDDING` naming the first patch that failed.
template <typename ConcurrencyTag>
void mesh_patches_in_list(const std::vector<std::size_t>& to_mesh, const Flattened_surface& surface, const Curve_samples& samples,
                          const Sizing& sizing, const Patch_meshing& meshing, const std::vector<Sample_pairs>& diagonals_to_split,
                          const Time_limit& time_limit, std::vector<Remeshed_patch>& remeshed)
{
  const std::vector<Extracted_patch>& patches = surface.flattened.patches;
  std::vector<std::string> failures(patches.size());
  for_each_index<ConcurrencyTag>(to_mesh.size(), [&](std::size_t i) {
    const std::size_t p = to_mesh[i];
    try
    {
      time_limit.check("while meshing the patches");
      // The Lloyd iterations, which may take longer than the rest of a patch's meshing, stop at
      // the time limit too (the next check then throws).
      Planar_smoothing patch_smoothing = meshing.smoothing;
      if(time_limit.is_limited())
        patch_smoothing.lloyd_seconds = (std::max)(time_limit.remaining(), 1e-6); // 0 would be none
      remeshed[p] = remesh_flattened_patch(surface.flattened.flattenings[p], surface.scales[p], patches[p], samples, sizing,
                                           meshing.minimum_angle, patch_smoothing, meshing.frontal, meshing.optimization_rounds,
                                           diagonals_to_split[p], meshing.moves_in_parallel);
    }
    catch(const Error& e)
    {
      failures[p] = e.what();
    }
  });
  time_limit.check("while meshing the patches");
  for(std::size_t p = 0; p < patches.size(); ++p)
    if(!failures[p].empty())
      throw Error(Error_code::NOT_AN_EMBEDDING, "remesh_conformal: patch " + std::to_string(p) + ": " + failures[p]);
}

/// The boundary curves to sample twice as densely because chords of theirs do not glue (see
/// `check_glue()`): a patch thinner than the sample spacing can have a chord that crosses its
/// other side in the plane. The chords that fail may not be the ones at fault (a coarse outer loop
/// of a tiny annulus can cut its hole off in the plane, and then every chord of the hole fails
/// however dense): once a failing curve cannot be refined further, the failing patches' other
/// curves are taken instead. Empty when every chord glues.
/// \throws Error with `Error_code::NOT_AN_EMBEDDING` when chords fail and no curve can be refined.
inline std::set<std::size_t> curves_to_sample_again(const Meshed_patches& meshed, const std::vector<int>& halvings)
{
  const std::vector<Remeshed_patch>& remeshed = meshed.remeshed;
  const Curve_samples& samples = meshed.samples;
  std::set<std::size_t> curves;
  std::size_t first_failing = remeshed.size();
  for(std::size_t p = 0; p < remeshed.size(); ++p)
    for(const auto& chord : remeshed[p].chords_not_glued)
    {
      first_failing = (std::min)(first_failing, p);
      curves.insert(samples.curve_of_chord.at(chord));
    }
  if(curves.empty())
    return curves;
  const auto refinable = [&](std::size_t c) { return halvings[c] < max_curve_halvings; };
  if(!std::all_of(curves.begin(), curves.end(), refinable))
  {
    curves.clear();
    for(const Remeshed_patch& patch : remeshed)
      if(!patch.chords_not_glued.empty())
      {
        const std::set<std::size_t> own(patch.boundary_ids.begin(), patch.boundary_ids.end());
        for(const auto& chord : samples.curve_of_chord)
          if(own.count(chord.first.first) && own.count(chord.first.second) && refinable(chord.second))
            curves.insert(chord.second);
      }
  }
  if(curves.empty())
    throw Error(Error_code::NOT_AN_EMBEDDING,
                "remesh_conformal: patch " + std::to_string(first_failing) + ": its planar mesh does not glue to its neighbours at "
                  + std::to_string(remeshed[first_failing].chords_not_glued.size())
                  + " boundary chords (not triangle edges in the loop's direction, or joined twice) even with boundary samples "
                  + std::to_string(1 << max_curve_halvings) + " times denser");
  return curves;
}

/// The patches that must split a diagonal between two samples because an earlier patch has the
/// same diagonal (four triangles on one edge once glued); adds the diagonals to
/// `diagonals_to_split`.
inline std::set<std::size_t> patches_to_split_shared_diagonals(const std::vector<Remeshed_patch>& remeshed,
                                                               std::vector<Sample_pairs>& diagonals_to_split)
{
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t> > patches_of_diagonal;
  for(std::size_t p = 0; p < remeshed.size(); ++p)
    for(const auto& diagonal : remeshed[p].sample_diagonals)
      patches_of_diagonal[diagonal].push_back(p);
  std::set<std::size_t> to_split;
  for(const auto& d : patches_of_diagonal)
    for(std::size_t i = 1; i < d.second.size(); ++i)
    {
      diagonals_to_split[d.second[i]].insert(d.first);
      to_split.insert(d.second[i]);
    }
  return to_split;
}

/// Every patch meshed and pulled back on boundary samples shared with its neighbours. Where
/// chords do not glue, their curves are sampled twice as densely and every patch is meshed again
/// (resampling renumbers the samples), up to `max_curve_halvings` times per curve. Where two
/// patches join the same two samples by a diagonal (both flattenings nearly straight along a short
/// curve between junctions), all but the first of them split it and are meshed again, up to
/// `max_diagonal_rounds` rounds: splitting adds no edge between samples, so this ends unless
/// smoothing brings new ones.
template <typename ConcurrencyTag, typename Progress>
Meshed_patches mesh_patches_on_shared_samples(const Flattened_surface& surface, const Sizing& sizing, double corner_angle,
                                              const Patch_meshing& meshing, const Time_limit& time_limit, const Progress& progress,
                                              Remeshing_report& report)
{
  const std::size_t n = surface.flattened.patches.size();
  Meshed_patches result;
  result.remeshed.resize(n);
  std::vector<int> halvings;
  std::vector<Sample_pairs> diagonals_to_split;
  std::vector<std::size_t> to_mesh;
  bool resample = true;
  for(int diagonal_round = 0;;)
  {
    if(resample)
    {
      result.samples = sample_boundary_curves(surface.segmentation, sizing, corner_angle, halvings);
      halvings.resize(result.samples.number_of_curves, 0);
      diagonals_to_split.assign(n, {});
      to_mesh.resize(n);
      std::iota(to_mesh.begin(), to_mesh.end(), std::size_t(0));
    }
    mesh_patches_in_list<ConcurrencyTag>(to_mesh, surface, result.samples, sizing, meshing, diagonals_to_split, time_limit,
                                         result.remeshed);
    const std::set<std::size_t> curves = curves_to_sample_again(result, halvings);
    resample = !curves.empty();
    if(resample)
    {
      progress("sampling " + std::to_string(curves.size()) + " boundary curves of thin patches more densely");
      for(std::size_t c : curves)
        ++halvings[c];
      report.refined_boundary_curves += curves.size();
      continue;
    }
    const std::set<std::size_t> to_split = patches_to_split_shared_diagonals(result.remeshed, diagonals_to_split);
    if(to_split.empty())
      break;
    if(++diagonal_round > max_diagonal_rounds)
      throw Error(Error_code::NOT_AN_EMBEDDING, "remesh_conformal: patch " + std::to_string(*to_split.begin())
                                                  + " still joins two boundary samples that another triangle edge joins "
                                                    "(four triangles on one edge) after "
                                                  + std::to_string(max_diagonal_rounds) + " rounds of splitting such diagonals");
    progress("splitting diagonals shared by " + std::to_string(to_split.size() + 1) + " patches or more");
    report.split_diagonals += to_split.size();
    to_mesh.assign(to_split.begin(), to_split.end());
  }
  return result;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCHES_H
