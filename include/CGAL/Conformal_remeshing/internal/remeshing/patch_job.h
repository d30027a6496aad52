// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A patch job: everything the meshing of one patch reads, as one value. The meshing of a patch
// (`mesh_patch()`, mesh_patch.h) reads its job and nothing else: no segmentation, no shared
// boundary samples, no size field of the whole surface. So jobs can be run in any order, on any
// thread, and compared: a job equal to one already run (`same_meshing_inputs()`) has the same
// result, up to the numbering of the shared samples (see `renumbered()` in mesh_patch.h).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PATCH_JOB_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PATCH_JOB_H

#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_curves.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/boundary_sample.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/flattened_patch.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/frontal_insertion.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_mesher.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/sizing.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

typedef std::set<std::pair<std::size_t, std::size_t> > Sample_pairs;

/// How each patch is meshed in the plane and optimized on the surface.
struct Patch_meshing
{
  double minimum_angle = 28.;
  Planar_smoothing smoothing;
  Frontal_insertion frontal;
  int optimization_rounds = 5;
  bool moves_in_parallel = false;
};

/// The boundary of a patch on the shared samples: its loops as planar images of the samples
/// (outer loop first), and the chords of the shared curves that join two of its samples.
/// Samples are named by their index among all shared samples, so that the patches' meshes glue.
struct Patch_boundary
{
  std::vector<std::vector<Boundary_sample> > loops;
  std::vector<std::size_t> sample_ids;       ///< the shared index of each loop position, in loop order
  std::vector<Epick::Point_3> sample_points; ///< in loop order
  /// the chords between two samples of the patch (smaller index first), and whether each is a
  /// chord of a kept curve (a feature, border or user patch border) rather than of a cut
  std::map<std::pair<std::size_t, std::size_t>, bool> chords;
  /// how many samples are shared: the patch's new points are numbered after them
  std::size_t number_of_shared_samples = 0;

  bool is_chord(const std::pair<std::size_t, std::size_t>& samples) const { return chords.count(samples) > 0; }
  bool is_kept_chord(std::size_t i, std::size_t j) const
  {
    const auto found = chords.find(std::minmax(i, j));
    return found != chords.end() && found->second;
  }
};

/// One patch to mesh: its surface and flattening, its fixed boundary, its sizes, how to mesh it,
/// and the diagonals between samples it must not have (another patch has them).
struct Patch_job
{
  std::size_t patch = 0; ///< its index among the patches
  std::shared_ptr<const Flattened_patch> surface;
  Patch_boundary boundary;
  Patch_size_field size;
  Patch_meshing meshing;
  Sample_pairs diagonals_to_split; ///< shared sample indices, smaller first
};

struct Remeshed_patch;

/// Runs the jobs `to_run` of `jobs` elsewhere than in this process's threads (the MPI tool hands
/// them to other processes, patch_job_io.h): sets `remeshed[p]` for the job of patch `p`, or
/// `failures[p]` to the message of the error it ended with. Empty: the jobs run here.
typedef std::function<void(const std::vector<std::size_t>& to_run, const std::vector<Patch_job>& jobs,
                           std::vector<Remeshed_patch>& remeshed, std::vector<std::string>& failures)>
  Patch_job_runner;

/// For each shared sample, the samples it shares a chord with.
inline std::vector<std::vector<std::size_t> > chord_neighbours(const Curve_samples& samples)
{
  std::vector<std::vector<std::size_t> > neighbours(samples.points.size());
  for(const auto& chord : samples.curve_of_chord)
  {
    neighbours[chord.first.first].push_back(chord.first.second);
    neighbours[chord.first.second].push_back(chord.first.first);
  }
  return neighbours;
}

/// The boundary of `flattened` on `samples`; `neighbours` is `chord_neighbours(samples)`.
inline Patch_boundary patch_boundary(const Flattened_patch& flattened, const Curve_samples& samples,
                                     const std::vector<std::vector<std::size_t> >& neighbours)
{
  const Conformal_flattening& flat = flattened.flattening;
  Patch_boundary result;
  result.loops.push_back(loop_samples(flat.outer_boundary, flattened.patch, samples, result.sample_ids));
  for(const auto& hole : flat.holes)
    result.loops.push_back(loop_samples(hole, flattened.patch, samples, result.sample_ids));
  for(const auto& loop : result.loops)
    for(const Boundary_sample& s : loop)
      result.sample_points.push_back(s.point);
  const std::set<std::size_t> own(result.sample_ids.begin(), result.sample_ids.end());
  for(std::size_t i : own)
    for(std::size_t j : neighbours[i])
      if(i < j && own.count(j))
        result.chords.emplace(std::make_pair(i, j), samples.is_kept_chord(i, j));
  result.number_of_shared_samples = samples.points.size();
  return result;
}

/// The job of patch `p` of `patches`.
inline Patch_job patch_job(std::size_t p, const std::vector<std::shared_ptr<const Flattened_patch> >& patches,
                           const Curve_samples& samples, const std::vector<std::vector<std::size_t> >& neighbours,
                           const Sizing& sizing, const Patch_meshing& meshing, const Sample_pairs& diagonals_to_split)
{
  Patch_job job;
  job.patch = p;
  job.surface = patches[p];
  job.boundary = patch_boundary(*patches[p], samples, neighbours);
  job.size = sizing.restricted_to(patches[p]->patch);
  job.meshing = meshing;
  job.diagonals_to_split = diagonals_to_split;
  return job;
}

// The local name of each loop position: the first position with the same shared sample.
inline std::vector<std::size_t> local_sample_names(const Patch_boundary& b)
{
  std::map<std::size_t, std::size_t> first;
  std::vector<std::size_t> names;
  for(std::size_t i = 0; i < b.sample_ids.size(); ++i)
    names.push_back(first.emplace(b.sample_ids[i], i).first->second);
  return names;
}

// Pairs of shared samples with a flag, in local names; pairs whose samples are not both on the
// patch are left out (the meshing never sees them).
inline std::map<std::pair<std::size_t, std::size_t>, bool>
in_local_names(const Patch_boundary& b, const std::map<std::pair<std::size_t, std::size_t>, bool>& pairs)
{
  std::map<std::size_t, std::size_t> name;
  for(std::size_t i = 0; i < b.sample_ids.size(); ++i)
    name.emplace(b.sample_ids[i], i);
  std::map<std::pair<std::size_t, std::size_t>, bool> result;
  for(const auto& pair : pairs)
  {
    const auto first = name.find(pair.first.first), second = name.find(pair.first.second);
    if(first != name.end() && second != name.end())
      result.emplace(std::minmax(first->second, second->second), pair.second);
  }
  return result;
}

inline std::map<std::pair<std::size_t, std::size_t>, bool> in_local_names(const Patch_boundary& b, const Sample_pairs& pairs)
{
  std::map<std::pair<std::size_t, std::size_t>, bool> flagged;
  for(const auto& pair : pairs)
    flagged.emplace(pair, true);
  return in_local_names(b, flagged);
}

/// Whether `mesh_patch()` gives `a` and `b` the same result up to the numbering of the shared
/// samples: the same patch, loops, chords and diagonals to split in local names, and the same
/// sizes (`same_sizes()`: jobs of one call, whose user size field is one function). Their
/// meshing settings are the caller's to compare.
inline bool same_meshing_inputs(const Patch_job& a, const Patch_job& b)
{
  if(a.surface != b.surface || a.boundary.loops.size() != b.boundary.loops.size() || !same_sizes(a.size, b.size))
    return false;
  for(std::size_t l = 0; l < a.boundary.loops.size(); ++l)
  {
    const std::vector<Boundary_sample>&x = a.boundary.loops[l], &y = b.boundary.loops[l];
    if(x.size() != y.size())
      return false;
    for(std::size_t i = 0; i < x.size(); ++i)
      if(x[i].uv != y[i].uv || x[i].point != y[i].point)
        return false;
  }
  if(local_sample_names(a.boundary) != local_sample_names(b.boundary))
    return false;
  return in_local_names(a.boundary, a.boundary.chords) == in_local_names(b.boundary, b.boundary.chords)
         && in_local_names(a.boundary, a.diagonals_to_split) == in_local_names(b.boundary, b.diagonals_to_split);
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PATCH_JOB_H
