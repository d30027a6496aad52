// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The meshing stage of `remesh_conformal()`: every patch boundary curve sampled once, in 3D,
// then one job per patch (patch_job.h) run on those shared samples (`mesh_patch()`), in
// parallel. The stage also mends what one patch's mesh alone cannot show: chords that do not glue
// (the curves are sampled more densely) and diagonals that two patches share (all but one patch
// split them). Only the jobs whose inputs changed are run again.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCHES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCHES_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/internal/parallel_for_each_index.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_curves.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/mesh_patch.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job.h>
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

/// The boundary samples shared by the patches, the job of each patch and its result, and how
/// many times each boundary curve was sampled twice as densely.
struct Meshed_patches
{
  Curve_samples samples;
  std::vector<Patch_job> jobs;
  std::vector<Remeshed_patch> remeshed;
  std::vector<int> halvings;
  std::size_t jobs_run = 0, jobs_kept = 0;
};

/// Runs the jobs `to_run` of `jobs` into `remeshed`, in parallel, or by `runner` when it is set.
/// The Lloyd iterations, which may take longer than the rest of a patch's meshing, stop at the
/// time limit too.
/// \throws Error with `Error_code::NOT_AN_EMBEDDING` naming the first patch that failed.
template <typename ConcurrencyTag>
void run_patch_jobs(const std::vector<std::size_t>& to_run, std::vector<Patch_job>& jobs, const Time_limit& time_limit,
                    const Patch_job_runner& runner, std::vector<Remeshed_patch>& remeshed)
{
  std::vector<std::string> failures(jobs.size());
  const auto limit_lloyd = [&time_limit](Patch_job& job) {
    if(time_limit.is_limited())
      job.meshing.smoothing.lloyd_seconds = (std::max)(time_limit.remaining(), 1e-6); // 0 would be none
  };
  if(runner)
  {
    time_limit.check("while meshing the patches");
    for(std::size_t p : to_run)
      limit_lloyd(jobs[p]);
    runner(to_run, jobs, remeshed, failures);
  }
  else
    for_each_index<ConcurrencyTag>(to_run.size(), [&](std::size_t i) {
      Patch_job& job = jobs[to_run[i]];
      try
      {
        time_limit.check("while meshing the patches");
        limit_lloyd(job);
        remeshed[job.patch] = mesh_patch(job);
      }
      catch(const Error& e)
      {
        failures[job.patch] = e.what();
      }
    });
  time_limit.check("while meshing the patches");
  for(std::size_t p = 0; p < jobs.size(); ++p)
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

/// `patches` and the patches that share a boundary sample with one of them in `meshed`.
inline std::set<std::size_t> with_neighbours(const std::set<std::size_t>& patches, const Meshed_patches& meshed)
{
  std::set<std::size_t> samples;
  for(std::size_t p : patches)
    samples.insert(meshed.jobs[p].boundary.sample_ids.begin(), meshed.jobs[p].boundary.sample_ids.end());
  std::set<std::size_t> result = patches;
  for(const Patch_job& job : meshed.jobs)
    if(std::any_of(job.boundary.sample_ids.begin(), job.boundary.sample_ids.end(), [&](std::size_t s) { return samples.count(s) > 0; }))
      result.insert(job.patch);
  return result;
}

/// The jobs of every patch on newly sampled curves. A job whose inputs equal those of a job
/// already run (in `earlier`, unless its patch is in `to_run_again`) takes that job's result,
/// renumbered; the others are returned to be run.
inline std::vector<std::size_t> jobs_on_new_samples(const Flattened_surface& surface, const Sizing& sizing,
                                                    const Patch_meshing& meshing, const Meshed_patches* earlier,
                                                    const std::set<std::size_t>& to_run_again, Meshed_patches& result)
{
  const std::size_t n = surface.patches.size();
  const std::vector<std::vector<std::size_t> > neighbours = chord_neighbours(result.samples);
  std::vector<Patch_job> jobs(n);
  std::vector<Remeshed_patch> remeshed(n);
  std::vector<std::size_t> to_run;
  for(std::size_t p = 0; p < n; ++p)
  {
    jobs[p] = patch_job(p, surface.patches, result.samples, neighbours, sizing, meshing, Sample_pairs());
    if(earlier != nullptr && !to_run_again.count(p) && p < earlier->jobs.size()
       && same_meshing_inputs(earlier->jobs[p], jobs[p]))
      remeshed[p] = renumbered(earlier->remeshed[p], earlier->jobs[p].boundary, jobs[p].boundary);
    else
      to_run.push_back(p);
  }
  result.jobs = std::move(jobs);
  result.remeshed = std::move(remeshed);
  return to_run;
}

/// Every patch meshed and pulled back on boundary samples shared with its neighbours. Where
/// chords do not glue, their curves are sampled twice as densely, up to `max_curve_halvings`
/// times per curve, and the jobs of the patches whose boundary changed are run again. Where two
/// patches join the same two samples by a diagonal (both flattenings nearly straight along a short
/// curve between junctions), all but the first of them split it and are run again, up to
/// `max_diagonal_rounds` rounds: splitting adds no edge between samples, so this ends unless
/// smoothing brings new ones.
///
/// The jobs run in this process's threads, or by `runner` when it is set.
///
/// With `earlier`, the stage's result for the same surface with other sizes, the patches not in
/// `to_run_again` whose boundary is unchanged keep their earlier meshes, and each curve starts as
/// densely as it ended there.
template <typename ConcurrencyTag, typename Progress>
Meshed_patches mesh_patches_on_shared_samples(const Flattened_surface& surface, const Sizing& sizing, double corner_angle,
                                              const Patch_meshing& meshing, const Patch_job_runner& runner,
                                              const Time_limit& time_limit, const Progress& progress,
                                              Remeshing_report& report, const Meshed_patches* earlier = nullptr,
                                              const std::set<std::size_t>& to_run_again = {})
{
  const std::size_t n = surface.patches.size();
  Meshed_patches result;
  if(earlier != nullptr)
    result.halvings = earlier->halvings;
  std::vector<Sample_pairs> diagonals_to_split;
  std::vector<std::size_t> to_run;
  bool resample = true;
  for(int diagonal_round = 0;;)
  {
    if(resample)
    {
      Meshed_patches before = std::move(result);
      result = Meshed_patches();
      result.halvings = before.halvings;
      result.samples = sample_boundary_curves(surface.segmentation, sizing, corner_angle, result.halvings);
      result.halvings.resize(result.samples.number_of_curves, 0);
      if(before.jobs.empty())
      {
        to_run = jobs_on_new_samples(surface, sizing, meshing, earlier, to_run_again, result);
        for(Remeshed_patch& r : result.remeshed)
          r.kept_from_earlier_sizes = true;
        for(std::size_t p : to_run)
          result.remeshed[p].kept_from_earlier_sizes = false;
      }
      else
        to_run = jobs_on_new_samples(surface, sizing, meshing, &before, {}, result);
      result.jobs_run = before.jobs_run;
      result.jobs_kept = before.jobs_kept + (n - to_run.size());
      diagonals_to_split.assign(n, {});
    }
    run_patch_jobs<ConcurrencyTag>(to_run, result.jobs, time_limit, runner, result.remeshed);
    result.jobs_run += to_run.size();
    const std::set<std::size_t> curves = curves_to_sample_again(result, result.halvings);
    resample = !curves.empty();
    if(resample)
    {
      progress("sampling " + std::to_string(curves.size()) + " boundary curves of thin patches more densely");
      for(std::size_t c : curves)
        ++result.halvings[c];
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
    to_run.assign(to_split.begin(), to_split.end());
    for(std::size_t p : to_run)
      result.jobs[p].diagonals_to_split = diagonals_to_split[p];
  }
  return result;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCHES_H
