// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Patch jobs and their results as bytes, so that another process can run a job (the MPI tool,
// remesh_conformal_mpi): `mesh_patch()` on a job read back from its bytes gives the result it
// gives on the original, bit for bit, because every number is copied as it is in memory and
// every container keeps its order. The bytes are those of this machine's layout: writer and
// reader must be the same build on the same kind of machine, as the ranks of one MPI run are. A
// job with a user sizing field (a function) cannot be written.
//
// The flattened surface of a patch is most of a job's bytes and the same in every job of that
// patch: `write_patch_job()` leaves it out when asked, and `read_patch_job()` then takes it from
// the surfaces the reader kept (`Patch_surfaces`).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PATCH_JOB_IO_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PATCH_JOB_IO_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/mesh_patch.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// Appends values to a byte string.
class Byte_writer
{
public:
  static constexpr bool reading = false;
  template <typename T>
  void raw(T* data, std::size_t n)
  {
    static_assert(std::is_trivially_copyable<T>::value, "only plain values are copied as bytes");
    bytes.append(reinterpret_cast<const char*>(data), n * sizeof(T));
  }
  std::string bytes;
};

/// Reads values back from bytes that a `Byte_writer` wrote.
/// \throws Error with `Error_code::INVALID_INPUT` on reading past the end.
class Byte_reader
{
public:
  static constexpr bool reading = true;
  Byte_reader(const char* data, std::size_t size) : at_(data), end_(data + size) {}
  template <typename T>
  void raw(T* data, std::size_t n)
  {
    static_assert(std::is_trivially_copyable<T>::value, "only plain values are copied as bytes");
    if(std::size_t(end_ - at_) / sizeof(T) < n)
      throw Error(Error_code::INVALID_INPUT, "read_patch_job: the message ends too early");
    if(n > 0)
      std::memcpy(static_cast<void*>(data), at_, n * sizeof(T));
    at_ += n * sizeof(T);
  }
  std::size_t remaining() const { return std::size_t(end_ - at_); }

private:
  const char* at_;
  const char* end_;
};

/// Whether `T` is copied as its bytes.
template <typename T>
struct Is_plain_value
  : std::integral_constant<bool, std::is_arithmetic<T>::value || std::is_enum<T>::value>
{};
template <typename T, std::size_t N>
struct Is_plain_value<std::array<T, N> > : Is_plain_value<T>
{};
template <> struct Is_plain_value<Epick::Point_2> : std::true_type {};
template <> struct Is_plain_value<Epick::Point_3> : std::true_type {};
template <> struct Is_plain_value<Boundary_sample> : std::true_type {};
template <> struct Is_plain_value<Domain_point> : std::true_type {};
template <> struct Is_plain_value<Tip_candidate> : std::true_type {};
template <> struct Is_plain_value<Planar_embedding_report> : std::true_type {};
template <> struct Is_plain_value<Planar_smoothing> : std::true_type {};
template <> struct Is_plain_value<Frontal_insertion> : std::true_type {};
template <> struct Is_plain_value<Surface_optimization_report> : std::true_type {};
template <> struct Is_plain_value<Meshing_phase_seconds> : std::true_type {};
template <> struct Is_plain_value<Patch_size_field::Corner> : std::true_type {};
template <> struct Is_plain_value<Poly_annulus_segmentation::Vertex> : std::true_type {};
template <> struct Is_plain_value<Poly_annulus_segmentation::Face> : std::true_type {};

template <typename Archive, typename T>
typename std::enable_if<Is_plain_value<T>::value>::type transfer(Archive& a, T& x)
{
  a.raw(&x, 1);
}

// An upper bound on the elements a reader can still hold (every element takes a byte at least,
// except in containers of empty containers, which the jobs do not nest deeply).
inline std::size_t remaining_bound(const Byte_reader& r) { return 8 * r.remaining() + 8; }
inline std::size_t remaining_bound(const Byte_writer&) { return std::size_t(-1); }

template <typename Archive>
std::size_t transfer_size(Archive& a, std::size_t n)
{
  std::uint64_t size = n;
  a.raw(&size, 1);
  if(Archive::reading && size > remaining_bound(a))
    throw Error(Error_code::INVALID_INPUT, "read_patch_job: a container is larger than the message");
  return std::size_t(size);
}

template <typename Archive, typename T, typename U>
void transfer(Archive& a, std::pair<T, U>& x)
{
  transfer(a, x.first);
  transfer(a, x.second);
}

template <typename Archive, typename T, std::size_t N>
typename std::enable_if<!Is_plain_value<T>::value>::type transfer(Archive& a, std::array<T, N>& x)
{
  for(T& e : x)
    transfer(a, e);
}

template <typename Archive>
void transfer(Archive& a, std::string& s)
{
  const std::size_t n = transfer_size(a, s.size());
  s.resize(n);
  a.raw(&s[0], n);
}

template <typename Archive, typename T, typename Allocator>
void transfer(Archive& a, std::vector<T, Allocator>& v)
{
  const std::size_t n = transfer_size(a, v.size());
  v.resize(n);
  if constexpr(Is_plain_value<T>::value)
    a.raw(v.data(), n);
  else
    for(T& e : v)
      transfer(a, e);
}

template <typename Archive>
void transfer(Archive& a, std::vector<bool>& v)
{
  const std::size_t n = transfer_size(a, v.size());
  v.resize(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    char b = v[i];
    a.raw(&b, 1);
    v[i] = b != 0;
  }
}

// Ordered and hashed containers: their elements in their order; the reader inserts them back.
template <typename Archive, typename Container>
void transfer_elements(Archive& a, Container& c)
{
  const std::size_t n = transfer_size(a, c.size());
  if(!Archive::reading)
  {
    for(const auto& e : c)
    {
      auto copy = e; // the writer only reads it
      transfer(a, copy);
    }
    return;
  }
  c.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    typename Container::value_type e;
    transfer(a, e);
    c.insert(c.end(), std::move(e));
  }
}

template <typename Archive, typename T>
void transfer(Archive& a, std::set<T>& s)
{
  transfer_elements(a, s);
}

template <typename Archive, typename K, typename V>
void transfer(Archive& a, std::map<K, V>& m)
{
  std::vector<std::pair<K, V> > elements(m.begin(), m.end());
  transfer(a, elements);
  if(Archive::reading)
    m = std::map<K, V>(elements.begin(), elements.end());
}

template <typename Archive, typename K, typename V>
void transfer(Archive& a, std::unordered_map<K, V>& m)
{
  std::vector<std::pair<K, V> > elements(m.begin(), m.end());
  transfer(a, elements);
  if(Archive::reading)
  {
    m.clear();
    m.reserve(elements.size());
    m.insert(elements.begin(), elements.end());
  }
}

/// The members of the package's types that a job holds, private ones included.
struct Patch_job_serialization
{
  template <typename Archive>
  static void transfer_triangulation(Archive& a, Intrinsic_triangulation<double>& t)
  {
    a.raw(&t.nv_, 1);
    transfer(a, t.he_vertex_);
    transfer(a, t.he_twin_);
    transfer(a, t.he_edge_);
    transfer(a, t.edge_he_);
    transfer(a, t.length_);
    transfer(a, t.unflippable_);
    transfer(a, t.vertex_on_border_);
    transfer(a, t.queued_);
    const std::size_t flips = transfer_size(a, t.flips_.size());
    if(Archive::reading)
      t.flips_.assign(flips, typename Intrinsic_triangulation<double>::Flip_record(std::array<std::array<double, 2>, 4>()));
    a.raw(t.flips_.data(), flips);
    const std::size_t splits = transfer_size(a, t.splits_.size());
    t.splits_.resize(splits);
    a.raw(t.splits_.data(), splits);
    transfer(a, t.timeline_);
    transfer(a, t.face_events_);
    transfer(a, t.compact_event_start_);
    transfer(a, t.compact_events_);
    a.raw(&t.history_is_compact_, 1);
    a.raw(&t.record_history_, 1);
  }

  template <typename Archive>
  static void transfer_size_field(Archive& a, Patch_size_field& s)
  {
    if(!Archive::reading && s.field_)
      throw Error(Error_code::INVALID_INPUT, "write_patch_job: a user sizing field (a function) cannot be written");
    transfer(a, s.target_);
    transfer(a, s.gradation_);
    transfer(a, s.refinement_.points);
    transfer(a, s.refinement_.sizes);
    transfer(a, s.refinement_.gradation);
    if(Archive::reading)
      s.places_ = Local_refinement_lookup(s.refinement_, s.target_);
    transfer(a, s.face_corners_);
  }
};

template <typename Archive>
void transfer(Archive& a, Flattening_report& r)
{
  transfer(a, r.status);
  transfer(a, r.converged);
  transfer(a, r.iterations);
  transfer(a, r.curvature_error);
  for(std::size_t* n : {&r.flips, &r.hole_fill_flips, &r.boundary_loops, &r.boundary_splits, &r.edge_splits,
                        &r.retriangulated_faces, &r.welded_vertices, &r.flat_sides_shortened, &r.folded_input_triangles_in_uv})
    transfer(a, *n);
  for(double* x : {&r.refined_edge_length, &r.min_scale, &r.max_scale, &r.seconds_welding, &r.seconds_flow, &r.seconds_layout,
                   &r.seconds_check, &r.seconds_refinement, &r.seconds_flips, &r.seconds_factorization, &r.seconds_solve,
                   &r.seconds_line_search})
    transfer(a, *x);
  transfer(a, r.embedding);
  transfer(a, r.flow_message);
}

template <typename Archive>
void transfer(Archive& a, welding::Corner_coordinates& c)
{
  transfer(a, c.slot);
  transfer(a, c.stored);
}

template <typename Archive>
void transfer(Archive& a, welding::Flat_region& r)
{
  transfer(a, r.vertices);
  transfer(a, r.points);
  transfer(a, r.developed);
  transfer(a, r.faces);
  transfer(a, r.neighbor);
  transfer(a, r.fan_start);
  transfer(a, r.fan);
  transfer(a, r.input_face);
  transfer(a, r.input_coordinates);
  transfer(a, r.containing_face);
}

template <typename Archive>
void transfer(Archive& a, welding::Indexed_patch& p)
{
  transfer(a, p.points);
  transfer(a, p.number_of_input_vertices);
  transfer(a, p.faces);
  transfer(a, p.input_face);
  transfer(a, p.input_coordinates);
  transfer(a, p.flat_regions);
  transfer(a, p.developed_lengths);
  transfer(a, p.boundary_loops);
}

template <typename Archive>
void transfer(Archive& a, Conformal_flattening& f)
{
  transfer(a, f.uv);
  transfer(a, f.conformal_factor);
  transfer(a, f.outer_boundary);
  transfer(a, f.holes);
  transfer(a, f.report);
  transfer(a, f.layout);
  transfer(a, f.triangles);
  transfer(a, f.triangle_face);
  transfer(a, f.face_region);
  Patch_job_serialization::transfer_triangulation(a, f.triangulation);
  transfer(a, f.welded_faces);
  transfer(a, f.faces_of_vertex_start);
  transfer(a, f.faces_of_vertex);
  transfer(a, flattening::Patch_access::of(f));
}

template <typename Archive>
void transfer(Archive& a, Flattened_patch& p)
{
  // Not the patch's mesh: it is freed once the patch is flattened (see `Flattened_patch`).
  transfer(a, p.patch.segmented_vertex);
  transfer(a, p.patch.segmented_face);
  transfer(a, p.patch.boundary_loops);
  transfer(a, p.patch.genus);
  transfer(a, p.flattening);
  transfer(a, p.scale);
  transfer(a, p.tips);
  transfer(a, p.tip_length);
}

template <typename Archive>
void transfer(Archive& a, Patch_boundary& b)
{
  transfer(a, b.loops);
  transfer(a, b.sample_ids);
  transfer(a, b.sample_points);
  transfer(a, b.chords);
  transfer(a, b.number_of_shared_samples);
}

template <typename Archive>
void transfer(Archive& a, Patch_meshing& m)
{
  transfer(a, m.minimum_angle);
  transfer(a, m.smoothing);
  transfer(a, m.frontal);
  transfer(a, m.optimization_rounds);
  transfer(a, m.moves_in_parallel);
}

template <typename Archive>
void transfer(Archive& a, Remeshed_patch& r)
{
  transfer(a, r.boundary_ids);
  transfer(a, r.interior_points);
  transfer(a, r.interior_faces);
  transfer(a, r.triangles);
  transfer(a, r.chords_not_glued);
  transfer(a, r.sample_diagonals);
  transfer(a, r.clamped_vertices);
  transfer(a, r.optimization);
  transfer(a, r.seconds_planar_meshing);
  transfer(a, r.seconds_optimization);
  transfer(a, r.seconds_pull_back);
  transfer(a, r.phases);
  transfer(a, r.kept_from_earlier_sizes);
}

// What a job holds besides its patch index and surface, in the order of its bytes.
template <typename Archive>
void transfer_job_after_surface(Archive& a, Patch_job& job)
{
  transfer(a, job.boundary);
  Patch_job_serialization::transfer_size_field(a, job.size);
  transfer(a, job.meshing);
  transfer(a, job.diagonals_to_split);
}

/// The flattened surfaces a reader of jobs has received, by patch index.
typedef std::map<std::size_t, std::shared_ptr<const Flattened_patch> > Patch_surfaces;

/// `job` as bytes; without its flattened surface unless `with_surface` (the reader must then
/// have it already).
/// \throws Error with `Error_code::INVALID_INPUT` for a job with a user sizing field.
inline std::string write_patch_job(const Patch_job& job, bool with_surface)
{
  Byte_writer w;
  Patch_job& j = const_cast<Patch_job&>(job); // the writer reads only
  transfer(w, j.patch);
  transfer(w, with_surface);
  if(with_surface)
    transfer(w, const_cast<Flattened_patch&>(*job.surface));
  transfer_job_after_surface(w, j);
  return std::move(w.bytes);
}

/// The job of `bytes`; its surface is taken from, or added to, `surfaces`.
/// \throws Error with `Error_code::INVALID_INPUT` for bytes that are not a job, or a job without
/// its surface whose surface the reader does not have.
inline Patch_job read_patch_job(const char* bytes, std::size_t size, Patch_surfaces& surfaces)
{
  Byte_reader r(bytes, size);
  Patch_job job;
  transfer(r, job.patch);
  bool with_surface = false;
  transfer(r, with_surface);
  if(with_surface)
  {
    std::shared_ptr<Flattened_patch> surface = std::make_shared<Flattened_patch>();
    transfer(r, *surface);
    surfaces[job.patch] = surface;
  }
  const auto known = surfaces.find(job.patch);
  if(known == surfaces.end())
    throw Error(Error_code::INVALID_INPUT, "read_patch_job: the job of patch " + std::to_string(job.patch) + " comes without its surface");
  job.surface = known->second;
  transfer_job_after_surface(r, job);
  if(r.remaining() != 0)
    throw Error(Error_code::INVALID_INPUT, "read_patch_job: bytes left after the job");
  return job;
}

/// The outcome of a job as bytes: its result, or the message of the error it ended with.
inline std::string write_patch_result(std::size_t patch, const Remeshed_patch& result, const std::string& failure)
{
  Byte_writer w;
  std::size_t p = patch;
  std::string message = failure;
  transfer(w, p);
  transfer(w, message);
  if(failure.empty())
    transfer(w, const_cast<Remeshed_patch&>(result));
  return std::move(w.bytes);
}

/// Reads what `write_patch_result()` wrote; returns the patch index.
inline std::size_t read_patch_result(const char* bytes, std::size_t size, Remeshed_patch& result, std::string& failure)
{
  Byte_reader r(bytes, size);
  std::size_t patch = 0;
  transfer(r, patch);
  transfer(r, failure);
  if(failure.empty())
    transfer(r, result);
  if(r.remaining() != 0)
    throw Error(Error_code::INVALID_INPUT, "read_patch_result: bytes left after the result");
  return patch;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PATCH_JOB_IO_H
