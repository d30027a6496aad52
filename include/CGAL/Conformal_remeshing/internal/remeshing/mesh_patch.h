// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One patch job run (`mesh_patch()`): the patch's flattened domain meshed in the plane on its
// fixed boundary samples (frontal insertion, then Delaunay refinement), optimized on the surface,
// and pulled back onto the input surface through the flow's correspondence. It reads its job
// (patch_job.h) and nothing else.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCH_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCH_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/kept_input_vertices.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_locator.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/planar_mesher.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/surface_optimization.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

// One patch, remeshed: its boundary samples (indices into the curve samples), its interior
// points on the surface, and triangles whose corners index the boundary samples first, then
// the interior points.
struct Remeshed_patch
{
  std::vector<std::size_t> boundary_ids;
  std::vector<Epick::Point_3> interior_points;
  std::vector<Poly_annulus_segmentation::Face> interior_faces; // the segmented face of each
  std::vector<std::array<std::size_t, 3> > triangles;
  /// boundary chords (pairs of sample indices) the triangles would not glue at (see `check_glue()`):
  /// the triangles are not valid then
  std::vector<std::pair<std::size_t, std::size_t> > chords_not_glued;
  /// other edges between two samples (smaller index first, once per planar edge), which no other
  /// patch, nor another edge of this one, may join
  std::vector<std::pair<std::size_t, std::size_t> > sample_diagonals;
  std::size_t clamped_vertices = 0;
  Surface_optimization_report optimization;
  double seconds_planar_meshing = 0., seconds_optimization = 0., seconds_pull_back = 0.;
  Meshing_phase_seconds phases; // of the planar meshing and the optimization
  bool kept_from_earlier_sizes = false; ///< meshed in an earlier round of the stage, and counted there
};

// The glue's preconditions, for one patch: every chord between consecutive samples of a loop is
// an edge of one planar triangle, traversed in the loop's direction, so that the neighbour, which
// traverses it the other way, closes the surface there; and no other edge joins the two samples
// of a chord (a diagonal between two samples that the patch touches elsewhere would make a third
// triangle on that chord). Where a patch is thinner than the sample spacing, a chord of one side
// can cross the other side in the plane. The offending chords are returned, as pairs of sample
// indices, for their curves to be sampled more densely. Also returned: the other edges between
// two samples, diagonals across the patch, which no second patch may have (four triangles on one
// edge): see `patches_to_split_shared_diagonals()`.
struct Glue_check
{
  std::vector<std::pair<std::size_t, std::size_t> > chords_not_glued, sample_diagonals;
};

inline Glue_check check_glue(const Patch_boundary& boundary, const Planar_mesh& planar)
{
  const std::vector<std::vector<Boundary_sample> >& loops = boundary.loops;
  const std::vector<std::size_t>& boundary_ids = boundary.sample_ids;
  std::set<std::pair<std::size_t, std::size_t> > loop_chords;
  std::size_t first = 0;
  for(const auto& loop : loops)
  {
    for(std::size_t i = 0; i < loop.size(); ++i)
      loop_chords.emplace(first + i, first + (i + 1) % loop.size());
    first += loop.size();
  }
  std::set<std::pair<std::size_t, std::size_t> > followed, not_glued, local_diagonals;
  for(const auto& t : planar.triangles)
    for(int c = 0; c < 3; ++c)
    {
      const std::pair<std::size_t, std::size_t> edge(t[c], t[(c + 1) % 3]);
      if(loop_chords.count(edge))
        followed.insert(edge);
      else if(edge.first < planar.number_of_samples && edge.second < planar.number_of_samples
              && !loop_chords.count({edge.second, edge.first}))
      {
        const auto pair = std::minmax(boundary_ids[edge.first], boundary_ids[edge.second]);
        if(boundary.is_chord(pair))
          not_glued.insert(pair);
        else
          local_diagonals.insert(std::minmax(edge.first, edge.second));
      }
    }
  for(const auto& chord : loop_chords)
    if(!followed.count(chord))
      not_glued.insert(std::minmax(boundary_ids[chord.first], boundary_ids[chord.second]));
  Glue_check result;
  result.chords_not_glued.assign(not_glued.begin(), not_glued.end());
  // Once per planar edge: a patch that meets itself (at a slit) can have the same pair twice.
  for(const auto& d : local_diagonals)
    result.sample_diagonals.push_back(std::minmax(boundary_ids[d.first], boundary_ids[d.second]));
  return result;
}

// The plane-to-surface map of a flattened patch. Each lift locates its point among the flat
// triangles by a walk, from where a point lifted before close by was found, then carries it back
// through the flow's flips. Where points were found is remembered in a small direct-mapped
// table of the last lifts (a point whose entry was overwritten starts from the last point's
// triangle: a longer walk, the same answer); a memory of every lift costs more in lookups than
// it saves in walks. (The optimizer keeps a hint per vertex instead of this table: see its lift
// in optimize_patch_on_surface().)
class Surface_map_with_hints
{
public:
  struct Lifted
  {
    Conformal_flattening::Patch_location on_patch;
    bool clamped;         // outside every flat triangle by rounding, moved onto the nearest one
    std::size_t triangle; // the flat triangle it was found in
  };

  Surface_map_with_hints(const Conformal_flattening& flat, const Planar_locator& locator)
    : flat_(flat), locator_(locator), found_(std::size_t(1) << found_bits)
  {}

  /// The lift of `p`; `near` (optional) is a point lifted before close to `p`.
  Lifted lift(const Epick::Point_2& p, const Epick::Point_2* near = nullptr)
  {
    if(near != nullptr)
    {
      const Found& f = found_[slot(*near)];
      if(f.x == near->x() && f.y == near->y())
        hint_ = f.triangle;
    }
    const Planar_locator::Location l = locator_.locate(p, hint_);
    found_[slot(p)] = Found{p.x(), p.y(), l.triangle};
    return Lifted{flat_.patch_location_of_triangle(l.triangle, l.coordinates),
                  (std::min)({l.coordinates[0], l.coordinates[1], l.coordinates[2]}) == 0., l.triangle};
  }

private:
  struct Found
  {
    double x = std::numeric_limits<double>::quiet_NaN(), y = 0.; // NaN: no point yet
    std::size_t triangle = 0;
  };
  static constexpr int found_bits = 12; // 4096 entries, 96 kB
  static std::size_t slot(const Epick::Point_2& p) { return std::size_t(planar_point_hash(p.x(), p.y()) >> (64 - found_bits)); }

  const Conformal_flattening& flat_;
  const Planar_locator& locator_;
  std::vector<Found> found_;
  std::size_t hint_ = Planar_locator::no_hint; // the last point's triangle: lifts come in neighbourhoods
};

// The refinement's size bound at a planar point: `longest_edge_factor` times the target edge
// length on the surface there times the map's scale there. Takes a hint, the flat triangle to
// search from (see `size_field_at()`); asked without one, it searches from where the last such
// query was found.
class Planar_size_field
{
public:
  Planar_size_field(const Conformal_flattening& flat, const std::vector<double>& scale, const Patch_size_field& size,
                    const Planar_locator& locator)
    : flat_(flat), scale_(scale), size_(size), locator_(locator)
  {}

  /// The target edge length at `p` on the surface, and the map's scale there.
  std::pair<double, double> size_and_scale(const Epick::Point_2& p, Size_field_hint& hint) const
  {
    const Planar_locator::Location l = locator_.locate(p, hint);
    double s = 0.;
    for(int c = 0; c < 3; ++c)
      s += l.coordinates[c] * scale_[flat_.triangles[l.triangle][c]];
    double size = size_.target();
    if(!size_.is_uniform())
    {
      const Domain_point q = flat_.to_surface(l.triangle, l.coordinates);
      size = size_.at(q.point, q.input_face);
    }
    return std::make_pair(size, s);
  }

  double operator()(const Epick::Point_2& p, Size_field_hint& hint) const
  {
    const std::pair<double, double> size = size_and_scale(p, hint);
    return longest_edge_factor * size.first * size.second;
  }

  double operator()(const Epick::Point_2& p) const { return (*this)(p, last_hint_); }

private:
  const Conformal_flattening& flat_;
  const std::vector<double>& scale_;
  const Patch_size_field& size_;
  const Planar_locator& locator_;
  mutable Size_field_hint last_hint_ = no_size_field_hint;
};

// The pairs of loop positions that must not be joined: `diagonals_to_split` (shared sample
// indices) mapped to every position of each sample (a slit's samples are on two sides).
inline std::vector<std::pair<std::size_t, std::size_t> > local_diagonals_to_split(const Patch_boundary& boundary,
                                                                                   const Sample_pairs& diagonals_to_split)
{
  std::vector<std::pair<std::size_t, std::size_t> > result;
  if(diagonals_to_split.empty())
    return result;
  std::map<std::size_t, std::vector<std::size_t> > positions;
  for(std::size_t i = 0; i < boundary.sample_ids.size(); ++i)
    positions[boundary.sample_ids[i]].push_back(i);
  for(const auto& pair : diagonals_to_split)
    if(positions.count(pair.first) && positions.count(pair.second))
      for(std::size_t i : positions[pair.first])
        for(std::size_t j : positions[pair.second])
          result.emplace_back(i, j);
  return result;
}

// The planar mesh of a patch: the tips of a coarse input kept as vertices (see
// kept_input_vertices.h), the first rows of triangles along features, borders and user patch
// borders seeded (see equilateral_seeds(); along cuts the points move after gluing instead, see
// moves_after_gluing.h), and so is the first ring around each kept tip (see
// seeds_around_points()); then frontal insertion and Delaunay refinement.
inline Planar_mesh mesh_patch_in_plane(const Patch_job& job, const Planar_size_field& planar_size, Surface_map_with_hints& surface_map)
{
  const Conformal_flattening& flat = job.surface->flattening;
  const Patch_boundary& boundary = job.boundary;
  std::vector<Epick::Point_2> fixed_points;
  std::vector<std::pair<Epick::Point_2, Epick::Point_3> > tips;
  for(const Tip_candidate& tip : kept_tips(job.surface->tips, job.surface->tip_length, boundary.sample_points))
  {
    fixed_points.push_back(flat.uv[tip.vertex]);
    tips.emplace_back(flat.uv[tip.vertex], tip.point);
  }
  const auto on_kept_curve = [&](const Boundary_sample& a, const Boundary_sample& b) { return boundary.is_kept_chord(a.id, b.id); };
  const auto surface_point = [&](const Epick::Point_2& p, Epick::Point_3& x) {
    const Surface_map_with_hints::Lifted lifted = surface_map.lift(p);
    x = flat.surface_point(lifted.on_patch);
    return !lifted.clamped;
  };
  std::vector<Planar_seed> seeds = equilateral_seeds(boundary.loops, on_kept_curve, surface_point, seed_layers);
  Size_field_hint tip_hint = no_size_field_hint;
  const auto target_lengths = [&](const Epick::Point_2& p) {
    const std::pair<double, double> size = planar_size.size_and_scale(p, tip_hint);
    return std::make_pair(size.first, size.first * size.second);
  };
  for(const Planar_seed& seed : seeds_around_points(tips, target_lengths, surface_point))
    seeds.push_back(seed);
  const Patch_meshing& meshing = job.meshing;
  return mesh_planar_domain<Epick>(boundary.loops, (std::min)(meshing.minimum_angle, planar_refinement_angle_bound), planar_size,
                                   meshing.smoothing, false, local_diagonals_to_split(boundary, job.diagonals_to_split),
                                   fixed_points, seeds, meshing.frontal);
}

// The interior points of `planar` in spatial order. The refinement numbers its points in the
// order it inserted them, worst triangle first: lifted in that order, each walk would start far
// from its point.
inline std::vector<std::size_t> interior_points_in_space_order(const Planar_mesh& planar)
{
  std::vector<std::size_t> order(planar.points.size() - planar.number_of_samples);
  std::iota(order.begin(), order.end(), planar.number_of_samples);
  const auto point_of_index = CGAL::make_property_map(planar.points);
  CGAL::spatial_sort(order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_2<Epick, decltype(point_of_index)>(point_of_index));
  return order;
}

// Flips and moves judged on the surface (see surface_optimization.h). The surface positions are
// the optimizer's working state only: the pull-back finds the final points' input faces.
inline Surface_optimization_report optimize_patch_on_surface(const Patch_job& job, const Planar_locator& locator,
                                                             const Planar_size_field& planar_size,
                                                             Surface_map_with_hints& surface_map, Planar_mesh& planar)
{
  const Conformal_flattening& flat = job.surface->flattening;
  const Patch_meshing& meshing = job.meshing;
  // No state but the hint, which each vertex keeps (see Surface_mesh_optimizer): the moves of a
  // pass may call it from several threads at once.
  const auto lift = [&](const Epick::Point_2& p, std::size_t& hint) {
    const Planar_locator::Location l = locator.locate(p, hint);
    return flat.surface_point(l.triangle, l.coordinates);
  };
  std::vector<Epick::Point_3> positions(job.boundary.sample_points); // the samples, in loop order, first
  positions.resize(planar.points.size());
  std::vector<std::size_t> hints(planar.points.size(), Planar_locator::no_hint); // where each was found
  for(std::size_t i : interior_points_in_space_order(planar))
  {
    const Surface_map_with_hints::Lifted lifted = surface_map.lift(planar.points[i]);
    positions[i] = flat.surface_point(lifted.on_patch);
    hints[i] = lifted.triangle;
  }
  const double h = job.size.target();
  Edge_split_bounds split_bounds;
  split_bounds.longest = split_edge_factor * h;
  split_bounds.across_bend = {shortest_off_surface_split_factor * h, off_surface_split_factor * h};
  split_bounds.tight_curve = {shortest_tight_curve_split_factor * h, tight_curve_split_factor * h};
  // Short edges are collapsed below their share of the local size, into edges no longer than
  // it allows (the collapse pass runs alone, so the size field's hint may be shared).
  Size_field_hint collapse_hint = no_size_field_hint;
  const std::function<double(const Epick::Point_2&)> local_ratio = [&](const Epick::Point_2& p) {
    return planar_size.size_and_scale(p, collapse_hint).first / h;
  };
  // No flip may join two samples of a chord of the shared curves, this patch's or not: where the
  // input touches itself, a patch can have both samples of another patch's chord, and an edge
  // between them would be a third triangle on that chord once glued.
  Sample_pairs forbidden = job.diagonals_to_split;
  for(const auto& chord : job.boundary.chords)
    forbidden.insert(chord.first);
  return optimize_on_surface(planar.points, positions, planar.triangles, planar.number_of_fixed_points, lift, meshing.minimum_angle,
                             longest_edge_factor * h, split_bounds, meshing.optimization_rounds, job.boundary.sample_ids,
                             forbidden, meshing.moves_in_parallel, collapse_edge_factor * h, hints,
                             job.size.is_uniform() ? nullptr : local_ratio);
}

inline void record_optimization_phases(Remeshed_patch& result)
{
  const Surface_optimization_report& o = result.optimization;
  Meshing_phase_seconds& phases = result.phases;
  phases.first_rounds = o.seconds_first_rounds;
  phases.splits = o.seconds_splits;
  phases.collapses = o.seconds_collapses;
  phases.skewness_passes = o.seconds_skewness_passes;
  phases.angle_passes = o.seconds_angle_passes;
  phases.optimization_setup = result.seconds_optimization - (phases.first_rounds + phases.splits + phases.collapses
                                                             + phases.skewness_passes + phases.angle_passes);
}

// The interior points of `planar` pulled back onto the surface (sorted again: the optimization
// moves points and adds some), and the triangles numbered as the glue wants them: the samples by
// their shared index, then the interior points.
inline void pull_back(const Patch_job& job, Surface_map_with_hints& surface_map, const Planar_mesh& planar, Remeshed_patch& result)
{
  const Conformal_flattening& flat = job.surface->flattening;
  const Extracted_patch& patch = job.surface->patch;
  result.interior_points.resize(planar.points.size() - planar.number_of_samples);
  result.interior_faces.resize(result.interior_points.size());
  for(std::size_t i : interior_points_in_space_order(planar))
  {
    const Surface_map_with_hints::Lifted lifted = surface_map.lift(planar.points[i]);
    const Domain_point q = flat.to_surface(lifted.on_patch);
    result.clamped_vertices += lifted.clamped;
    result.interior_points[i - planar.number_of_samples] = q.point;
    result.interior_faces[i - planar.number_of_samples] = patch.segmented_face[q.input_face];
  }
  for(const auto& t : planar.triangles)
  {
    std::array<std::size_t, 3> corners;
    for(int c = 0; c < 3; ++c)
      corners[c] = std::size_t(t[c]) < planar.number_of_samples ? result.boundary_ids[t[c]]
                                                                  : job.boundary.number_of_shared_samples + (t[c] - planar.number_of_samples);
    result.triangles.push_back(corners);
  }
}

/// The patch of `job` meshed: planar meshing of its flattening on its boundary samples, the
/// optimization on the surface, and the pull-back of the new points onto the surface through the
/// flow's correspondence. No edge joins the two samples of a pair in `job.diagonals_to_split`.
/// The optimization's vertex moves run in parallel with `job.meshing.moves_in_parallel`, with
/// the same result. Where chords would not glue (`chords_not_glued`), the result stops after the
/// planar meshing.
/// \throws Error with `Error_code::NOT_AN_EMBEDDING` when the boundary samples overlap in the plane.
inline Remeshed_patch mesh_patch(const Patch_job& job)
{
  typedef std::chrono::steady_clock Clock;
  const auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  Clock::time_point start = Clock::now();
  const Conformal_flattening& flat = job.surface->flattening;
  Remeshed_patch result;
  result.boundary_ids = job.boundary.sample_ids;
  const Planar_locator locator(flat.layout, flat.triangles);
  const Planar_size_field planar_size(flat, job.surface->scale, job.size, locator);
  Surface_map_with_hints surface_map(flat, locator);
  Planar_mesh planar = mesh_patch_in_plane(job, planar_size, surface_map);
  if(planar.number_of_samples != result.boundary_ids.size())
    throw Error(Error_code::NOT_AN_EMBEDDING, "remesh_conformal: the boundary samples of a patch overlap in the plane");
  result.seconds_planar_meshing = seconds_since(start);
  result.phases.planar_refinement = planar.seconds_refinement;
  result.phases.planar_smoothing = planar.seconds_smoothing;
  result.phases.planar_setup = result.seconds_planar_meshing - planar.seconds_refinement - planar.seconds_smoothing;
  result.chords_not_glued = check_glue(job.boundary, planar).chords_not_glued;
  if(!result.chords_not_glued.empty())
    return result;

  start = Clock::now();
  if(job.meshing.optimization_rounds > 0)
    result.optimization = optimize_patch_on_surface(job, locator, planar_size, surface_map, planar);
  result.seconds_optimization = seconds_since(start);
  record_optimization_phases(result);
  // The optimizer keeps every chord (it never flips a boundary edge) and makes none of the
  // diagonals to split, but it may have made or removed others.
  result.sample_diagonals = check_glue(job.boundary, planar).sample_diagonals;

  start = Clock::now();
  pull_back(job, surface_map, planar, result);
  result.seconds_pull_back = seconds_since(start);
  return result;
}

/// The result of a job run on boundary `before`, for an equal job on boundary `after` (see
/// `same_meshing_inputs()`): the same mesh, its shared samples renamed.
inline Remeshed_patch renumbered(Remeshed_patch result, const Patch_boundary& before, const Patch_boundary& after)
{
  std::map<std::size_t, std::size_t> name;
  for(std::size_t i = 0; i < before.sample_ids.size(); ++i)
    name.emplace(before.sample_ids[i], after.sample_ids[i]);
  const auto rename = [&](std::size_t i) {
    return i < before.number_of_shared_samples ? name.at(i) : i - before.number_of_shared_samples + after.number_of_shared_samples;
  };
  const auto rename_pair = [&](std::pair<std::size_t, std::size_t>& pair) { pair = std::minmax(rename(pair.first), rename(pair.second)); };
  result.boundary_ids = after.sample_ids;
  for(std::array<std::size_t, 3>& t : result.triangles)
    for(std::size_t& c : t)
      c = rename(c);
  for(auto& chord : result.chords_not_glued)
    rename_pair(chord);
  std::sort(result.chords_not_glued.begin(), result.chords_not_glued.end());
  for(auto& diagonal : result.sample_diagonals)
    rename_pair(diagonal);
  return result;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_MESH_PATCH_H
