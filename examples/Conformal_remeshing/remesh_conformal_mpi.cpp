// remesh_conformal_mpi: remesh_conformal with its patch jobs spread over MPI processes.
//
//   mpirun -np N remesh_conformal_mpi IN OUT [the options of remesh_conformal]
//
// Rank 0 is the tool remesh_conformal: it reads and repairs the input, segments and flattens it,
// samples the patches' shared boundaries, glues and writes the output. The meshing of the patches
// (planar meshing, optimization on the surface, pull-back) runs on the other ranks: rank 0 hands
// each free rank the largest job left, as bytes (patch_job_io.h), and gathers the results. A rank
// keeps the flattened surface of every patch it has meshed, so a patch meshed again (denser
// boundary samples, split diagonals, finer sizes where the output intersected itself) travels
// without it. The output file is byte for byte that of remesh_conformal with the same options;
// with one process (no workers), the jobs run in rank 0's threads. Rank 0 prints, at the end, the
// jobs each rank ran, the bytes sent and received, how long rank 0 waited for the workers and the
// peak resident memory of every rank.
// Exit codes: those of remesh_conformal.

#include "remesh_conformal_tool.h"

#include <CGAL/Conformal_remeshing/internal/process_memory.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job_io.h>

#include <mpi.h>
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace RM = CGAL::Conformal_remeshing::internal::remeshing;

namespace {

enum Tag { job_tag = 1, result_tag = 2, stop_tag = 3 };

using CGAL::Conformal_remeshing::internal::peak_resident_megabytes;

void send_bytes(const std::string& bytes, int rank, int tag)
{
  if(bytes.size() > std::size_t(INT_MAX))
    throw CR::Error(CR::Error_code::INVALID_INPUT, "remesh_conformal_mpi: a message of " + std::to_string(bytes.size())
                                                     + " bytes is larger than MPI's largest (2 GB)");
  MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, rank, tag, MPI_COMM_WORLD);
}

// The next message from `rank` (or any rank) with `tag`; `status` says whose it was.
std::string receive_bytes(int rank, int tag, MPI_Status& status)
{
  MPI_Probe(rank, tag, MPI_COMM_WORLD, &status);
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  std::string bytes(std::size_t(size), '\0');
  MPI_Recv(&bytes[0], size, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return bytes;
}

// Rank 0's runner of the patch jobs: the largest job left to each rank that becomes free.
class Job_dispatcher
{
public:
  explicit Job_dispatcher(int ranks) : surfaces_sent_(std::size_t(ranks)), jobs_run_(std::size_t(ranks), 0) {}

  void operator()(const std::vector<std::size_t>& to_run, const std::vector<RM::Patch_job>& jobs,
                  std::vector<RM::Remeshed_patch>& remeshed, std::vector<std::string>& failures)
  {
    // Largest first, by the faces of the flat triangulation each job meshes.
    std::vector<std::size_t> order = to_run;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return jobs[a].surface->flattening.triangles.size() > jobs[b].surface->flattening.triangles.size();
    });
    std::size_t next = 0, busy = 0;
    const auto hand_out = [&](int rank) {
      const std::size_t p = order[next++];
      // A rank has the surface when it got this very one: the patch numbers start again with
      // each batch of components (and each run), the surfaces do not.
      std::weak_ptr<const RM::Flattened_patch>& sent = surfaces_sent_[std::size_t(rank)][p];
      const bool with_surface = sent.lock() != jobs[p].surface;
      if(with_surface)
        sent = jobs[p].surface;
      const std::string bytes = RM::write_patch_job(jobs[p], with_surface);
      bytes_sent_ += bytes.size();
      send_bytes(bytes, rank, job_tag);
      ++jobs_run_[std::size_t(rank)];
      ++busy;
    };
    try
    {
      for(int rank = 1; rank < int(surfaces_sent_.size()) && next < order.size(); ++rank)
        hand_out(rank);
      gather(order, next, busy, hand_out, remeshed, failures);
    }
    catch(...)
    {
      // The workers still meshing send their results: take them, so that they are free to stop.
      for(; busy > 0; --busy)
      {
        MPI_Status status;
        receive_bytes(MPI_ANY_SOURCE, result_tag, status);
      }
      throw;
    }
  }

  // Takes each result as it comes and hands its rank the next job.
  template <typename Hand_out>
  void gather(const std::vector<std::size_t>& order, std::size_t& next, std::size_t& busy, const Hand_out& hand_out,
              std::vector<RM::Remeshed_patch>& remeshed, std::vector<std::string>& failures)
  {
    while(busy > 0)
    {
      const auto start = std::chrono::steady_clock::now();
      MPI_Status status;
      const std::string bytes = receive_bytes(MPI_ANY_SOURCE, result_tag, status);
      seconds_waiting_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      bytes_received_ += bytes.size();
      --busy;
      RM::Remeshed_patch result;
      std::string failure;
      const std::size_t p = RM::read_patch_result(bytes.data(), bytes.size(), result, failure);
      if(p >= remeshed.size())
        throw CR::Error(CR::Error_code::INVALID_INPUT, "remesh_conformal_mpi: a result for patch " + std::to_string(p)
                                                         + ", which does not exist");
      remeshed[p] = std::move(result);
      failures[p] = failure;
      if(next < order.size())
        hand_out(status.MPI_SOURCE);
    }
  }

  void print_summary(std::ostream& out) const
  {
    out << "remesh_conformal_mpi: " << surfaces_sent_.size() - 1 << " worker ranks ran "
        << std::accumulate(jobs_run_.begin(), jobs_run_.end(), std::size_t(0)) << " patch jobs (";
    for(std::size_t rank = 1; rank < jobs_run_.size(); ++rank)
      out << (rank > 1 ? ", " : "") << "rank " << rank << ": " << jobs_run_[rank];
    out << "); " << double(bytes_sent_) / 1e6 << " MB sent, " << double(bytes_received_) / 1e6
        << " MB received; rank 0 waited " << seconds_waiting_ << " s for the workers\n";
  }

private:
  // per rank, the surface it has of each patch
  std::vector<std::map<std::size_t, std::weak_ptr<const RM::Flattened_patch> > > surfaces_sent_;
  std::vector<std::size_t> jobs_run_;                 // per rank
  std::size_t bytes_sent_ = 0, bytes_received_ = 0;
  double seconds_waiting_ = 0.;
};

// A worker rank: meshes the jobs rank 0 sends until it says stop.
void work()
{
  RM::Patch_surfaces surfaces;
  for(;;)
  {
    MPI_Status status;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if(status.MPI_TAG == stop_tag)
    {
      MPI_Recv(nullptr, 0, MPI_BYTE, 0, stop_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return;
    }
    const std::string bytes = receive_bytes(0, job_tag, status);
    std::size_t patch = 0;
    RM::Remeshed_patch result;
    std::string failure;
    try
    {
      const RM::Patch_job job = RM::read_patch_job(bytes.data(), bytes.size(), surfaces);
      patch = job.patch;
      result = RM::mesh_patch(job);
    }
    catch(const std::exception& e)
    {
      failure = e.what();
    }
    send_bytes(RM::write_patch_result(patch, result, failure), 0, result_tag);
  }
}

// The usage of remesh_conformal under this tool's name, and how it runs.
std::string usage()
{
  std::string text = Conformal_remeshing_tools::remesh_conformal_tool::usage;
  const std::string name = "usage: remesh_conformal ";
  text.replace(0, name.size(), "usage: remesh_conformal_mpi ");
  for(std::size_t at = text.find("\n                        ["); at != std::string::npos;
      at = text.find("\n                        [", at + 1))
    text.insert(at + 1, "    ");
  return text
         + "run as: mpirun -np N remesh_conformal_mpi IN OUT [OPTIONS] (on a cluster with a hostfile): rank 0 reads,\n"
           "segments, flattens, glues and writes OUT (the same file as remesh_conformal's); the N - 1 other ranks mesh\n"
           "the patches\n";
}

} // namespace

int main(int argc, char** argv)
{
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int exit_code = 0;
  if(rank != 0)
    work();
  else
  {
    bool help = false;
    for(int i = 1; i < argc; ++i)
      help = help || std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h";
    Job_dispatcher dispatcher(ranks);
    RM::Patch_job_runner runner;
    if(ranks > 1)
      runner = std::ref(dispatcher);
    try
    {
      if(help)
        std::cout << usage();
      else
        exit_code = Conformal_remeshing_tools::remesh_conformal_main(argc, argv, runner);
    }
    catch(const std::exception& e)
    {
      std::cerr << "remesh_conformal_mpi: " << e.what() << "\n";
      exit_code = 2;
    }
    if(ranks > 1 && !help && exit_code != 2)
      dispatcher.print_summary(std::cerr);
    for(int worker = 1; worker < ranks; ++worker)
      MPI_Send(nullptr, 0, MPI_BYTE, worker, stop_tag, MPI_COMM_WORLD);
  }
  // Every rank's peak memory, printed by rank 0.
  const double peak = peak_resident_megabytes();
  std::vector<double> peaks(std::size_t(ranks), 0.);
  MPI_Gather(&peak, 1, MPI_DOUBLE, peaks.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if(rank == 0 && ranks > 1 && exit_code == 0)
  {
    std::cerr << "remesh_conformal_mpi: peak resident MB per rank: ";
    for(int r = 0; r < ranks; ++r)
      std::cerr << (r ? ", " : "") << std::lround(peaks[std::size_t(r)]);
    std::cerr << "\n";
  }
  MPI_Finalize();
  return exit_code;
}
