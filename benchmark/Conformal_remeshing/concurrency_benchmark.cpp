// concurrency_benchmark: remesh_conformal() with CGAL::Sequential_tag against
// CGAL::Parallel_if_available_tag (patches flattened and meshed in parallel with TBB), in the same
// run, on the generated perforated plate and on any mesh files given. For each: the number of
// patches, and the median seconds of the whole call and of its stages, sequential and parallel,
// with the speed-up (sequential / parallel). Both must give the same output size (the library is
// deterministic). Prints a table and writes JSON.
//
//   concurrency_benchmark OUT.json [--runs N] [MESH ...]
//
// Exit code: 0, 1 when a model is refused or the two outputs differ, 2 for bad arguments or input.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/remesh_conformal.h>

#include "atomic_file.h"
#include "benchmark_io.h"
#include "cad_like_models.h"
#include "json_writer.h"
#include "model_tool.h"
#include "timing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <functional>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

// The stages of Remeshing_report that are timed; the flattening and meshing stages are the ones
// that run patches in parallel.
const char* const stage_names[] = {"total", "segmentation", "flattening", "meshing", "gluing"};
const std::size_t number_of_stages = sizeof(stage_names) / sizeof(stage_names[0]);

// Seconds of every run, per stage (indexed like `stage_names`), and the seconds of the two
// parallel stages summed over the patches (thread time: what parallelism can spread).
struct Timings
{
  std::vector<double> seconds[number_of_stages];
  std::vector<double> flattening_patch_seconds, meshing_patch_seconds;
  std::vector<double> largest_flattening_share; // the share of the slowest patch in the flattening's thread time

  double median(std::size_t stage) const { return bm::median(seconds[stage]); }
};

struct Result
{
  std::string model;
  std::size_t input_vertices = 0, patches = 0, output_vertices = 0, output_faces = 0;
  Timings sequential, parallel;
  double others_share = -1.; // the share of the cores other processes used during the runs; -1: unknown
  std::string failure;       // the message of a refused model
};

// CPU seconds used so far by the whole machine (/proc/stat, Linux; -1 when unreadable) and by this
// process. A speed-up measured while another process holds one of two cores means nothing, and on
// a shared machine that is easy to miss.
struct Cpu_seconds
{
  double machine = -1., self = 0.;
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
};

Cpu_seconds cpu_seconds()
{
  Cpu_seconds c;
  std::ifstream stat("/proc/stat");
  std::string label;
  // user nice system idle iowait irq softirq steal: all but idle and iowait are busy (steal: the
  // hypervisor's other guests)
  double t[8];
  if(stat >> label >> t[0] >> t[1] >> t[2] >> t[3] >> t[4] >> t[5] >> t[6] >> t[7] && label == "cpu")
    c.machine = (t[0] + t[1] + t[2] + t[5] + t[6] + t[7]) / double(sysconf(_SC_CLK_TCK));
  rusage usage;
  if(getrusage(RUSAGE_SELF, &usage) == 0)
    c.self = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return c;
}

// The share of the machine's cores that other processes used between `start` and now.
double others_share_since(const Cpu_seconds& start, unsigned int cores)
{
  const Cpu_seconds end = cpu_seconds();
  const double wall = std::chrono::duration<double>(end.wall - start.wall).count();
  if(start.machine < 0. || end.machine < 0. || cores == 0 || !(wall > 0.))
    return -1.;
  return (std::max)(0., ((end.machine - start.machine) - (end.self - start.self)) / (wall * cores));
}

// One call of remesh_conformal() with `ConcurrencyTag`, its times appended to `t`.
template <typename ConcurrencyTag>
CR::Remeshing_report run_once(const Mesh& input, Timings& t)
{
  Mesh output;
  CR::Remeshing_report report;
  CR::Remeshing_statistics statistics;
  t.seconds[0].push_back(bm::wall_seconds(
    [&] { report = CR::remesh_conformal<ConcurrencyTag>(input, output, CR::parameters::statistics(std::ref(statistics))); }));
  t.seconds[1].push_back(statistics.seconds_segmentation);
  t.seconds[2].push_back(statistics.seconds_flattening);
  t.seconds[3].push_back(statistics.seconds_meshing_stage);
  t.seconds[4].push_back(statistics.seconds_gluing);
  double sum = 0., largest = 0.;
  for(const CR::Flattening_report& p : statistics.patches)
  {
    const double seconds = p.seconds_welding + p.seconds_flow + p.seconds_layout + p.seconds_check;
    sum += seconds;
    largest = (std::max)(largest, seconds);
  }
  t.flattening_patch_seconds.push_back(sum);
  t.largest_flattening_share.push_back(sum > 0. ? largest / sum : 0.);
  t.meshing_patch_seconds.push_back(statistics.seconds_planar_meshing + statistics.seconds_optimization + statistics.seconds_pull_back);
  return report;
}

// The threads the parallel runs may use: TBB's default arena, or 1 without TBB (the parallel tag
// then runs sequentially).
int parallel_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  return tbb::this_task_arena::max_concurrency();
#else
  return 1;
#endif
}

std::string usage() { return "usage: concurrency_benchmark OUT.json [--runs N] [MESH ...]"; }

void print_rows(const Result& r)
{
  for(std::size_t s = 0; s < number_of_stages; ++s)
  {
    const double a = r.sequential.median(s), b = r.parallel.median(s);
    std::cout << std::left << std::setw(26) << (s == 0 ? r.model : "") << std::right << std::setw(8)
              << (s == 0 ? std::to_string(r.patches) : "") << "  " << std::left << std::setw(13) << stage_names[s]
              << std::right << std::fixed << std::setprecision(3) << std::setw(9) << a << std::setw(9) << b
              << std::setprecision(2) << std::setw(10) << a / b << std::defaultfloat << "\n";
  }
  // What bounds the speed-up: the slowest patch, and the thread time summed over the patches.
  std::cout << std::setw(36) << "" << std::setprecision(3) << "slowest patch: "
            << 100. * bm::median(r.sequential.largest_flattening_share) << "% of the flattening; patch thread s seq/par: flattening "
            << bm::median(r.sequential.flattening_patch_seconds) << "/" << bm::median(r.parallel.flattening_patch_seconds)
            << ", meshing " << bm::median(r.sequential.meshing_patch_seconds) << "/"
            << bm::median(r.parallel.meshing_patch_seconds) << "\n";
  if(r.others_share > 0.1)
    std::cout << std::setw(36) << "" << "WARNING: other processes used " << std::setprecision(2) << 100. * r.others_share
              << "% of the cores during these runs: the machine was not idle, the speed-up is not meaningful\n";
}

void write_json(tools::Json_writer& json, const Result& r)
{
  json.begin_object().field("model", r.model).field("input_vertices", r.input_vertices);
  if(r.others_share >= 0.)
    json.field("other_processes_cpu_share", r.others_share);
  if(!r.failure.empty())
  {
    json.field("failed", r.failure).end_object();
    return;
  }
  json.field("patches", r.patches).field("output_vertices", r.output_vertices).field("output_faces", r.output_faces);
  const std::pair<const char*, const Timings*> sides[] = {{"sequential", &r.sequential}, {"parallel", &r.parallel}};
  for(const auto& side : sides)
  {
    json.key(std::string("median_seconds_") + side.first).begin_object();
    for(std::size_t s = 0; s < number_of_stages; ++s)
      json.field(stage_names[s], side.second->median(s));
    json.key("patch_thread_seconds")
      .begin_object()
      .field("flattening", bm::median(side.second->flattening_patch_seconds))
      .field("meshing", bm::median(side.second->meshing_patch_seconds))
      .end_object();
    json.end_object();
  }
  // With P threads the flattening stage cannot be faster than its slowest patch.
  json.field("largest_patch_share_of_flattening", bm::median(r.sequential.largest_flattening_share));
  json.key("speed_up").begin_object();
  for(std::size_t s = 0; s < number_of_stages; ++s)
    json.field(stage_names[s], r.sequential.median(s) / r.parallel.median(s));
  json.end_object();
  // Every run's total, to show the spread behind the medians.
  json.array("total_seconds_sequential", r.sequential.seconds[0]).array("total_seconds_parallel", r.parallel.seconds[0]);
  json.end_object();
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << usage() << "\n";
    return 2;
  }
  if(std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")
  {
    std::cout << usage() << "\n";
    return 0;
  }
  const std::string out_path = argv[1];
  int runs = 3;
  std::vector<Result> results;
  std::vector<Mesh> inputs;
  try
  {
    if(out_path.empty() || out_path[0] == '-')
      throw std::invalid_argument("the first argument must be the output file OUT.json, not '" + out_path + "'");
    {
      Mesh plate;
      bm::make_perforated_plate(plate, bm::Perforated_plate_parameters());
      inputs.push_back(plate);
      results.emplace_back();
      results.back().model = "perforated plate";
    }
    // Every file is read before the first run, so that a bad one fails at once.
    for(int i = 2; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if(arg == "--runs")
      {
        if(i + 1 >= argc)
          throw std::invalid_argument("--runs: missing value");
        const long long n = bm::parse_integer(arg, argv[++i]);
        if(n < 1 || n > 1000)
          throw std::invalid_argument("--runs: must be between 1 and 1000: '" + std::string(argv[i]) + "'");
        runs = int(n);
        continue;
      }
      if(!arg.empty() && arg[0] == '-')
        throw std::invalid_argument("unknown option '" + arg + "'");
      inputs.push_back(bm::read_model<Mesh>(arg));
      results.emplace_back();
      results.back().model = arg.substr(arg.find_last_of('/') + 1);
    }
    bm::check_writable(out_path);
  }
  catch(const std::invalid_argument& e)
  {
    std::cerr << "concurrency_benchmark: " << e.what() << "\n" << usage() << "\n";
    return 2;
  }
  catch(const std::exception& e)
  {
    std::cerr << "concurrency_benchmark: " << e.what() << "\n";
    return 2;
  }

  const int threads = parallel_threads();
#ifdef CGAL_LINKED_WITH_TBB
  const bool with_tbb = true;
#else
  const bool with_tbb = false;
  std::cout << "(built without TBB: the parallel runs are sequential too)\n";
#endif
  std::cout << "TBB threads: " << threads << ", hardware threads: " << std::thread::hardware_concurrency()
            << ", runs: " << runs << "\n";
  std::cout << std::left << std::setw(26) << "model" << std::right << std::setw(8) << "patches" << "  " << std::left
            << std::setw(13) << "stage" << std::right << std::setw(9) << "seq s" << std::setw(9) << "par s"
            << std::setw(10) << "speed-up" << "\n";
  std::size_t failures = 0;
  for(std::size_t k = 0; k < inputs.size(); ++k)
  {
    Result& r = results[k];
    r.input_vertices = inputs[k].number_of_vertices();
    try
    {
      // An untimed run first, so that neither side pays for cold caches or for starting TBB's
      // threads; then sequential and parallel runs alternate, so that a change of the machine's
      // load falls on both.
      Timings warm_up;
      run_once<CGAL::Parallel_if_available_tag>(inputs[k], warm_up);
      const Cpu_seconds start = cpu_seconds();
      for(int i = 0; i < runs; ++i)
      {
        const CR::Remeshing_report a = run_once<CGAL::Sequential_tag>(inputs[k], r.sequential);
        const CR::Remeshing_report b = run_once<CGAL::Parallel_if_available_tag>(inputs[k], r.parallel);
        if(i == 0)
        {
          r.patches = a.number_of_patches;
          r.output_vertices = a.output_vertices;
          r.output_faces = a.output_faces;
        }
        const CR::Remeshing_report* const reports[] = {&a, &b};
        for(const CR::Remeshing_report* c : reports)
          if(c->output_vertices != r.output_vertices || c->output_faces != r.output_faces
             || c->number_of_patches != r.patches)
          {
            std::cerr << "concurrency_benchmark: " << r.model << ": the outputs differ (run " << i + 1 << ", "
                      << (c == &a ? "sequential" : "parallel") << ": " << c->number_of_patches << " patches, "
                      << c->output_vertices << " vertices, " << c->output_faces << " faces; first sequential run: "
                      << r.patches << " patches, " << r.output_vertices << " vertices, " << r.output_faces
                      << " faces); remesh_conformal() must not depend on the concurrency tag. No JSON written.\n";
            return 1;
          }
      }
      r.others_share = others_share_since(start, std::thread::hardware_concurrency());
    }
    catch(const CR::Error& e)
    {
      // A model the remesher refuses is a result too: recorded, and the run goes on.
      ++failures;
      r.failure = e.what();
      std::cout << std::left << std::setw(26) << r.model << "FAILED: " << r.failure << "\n";
      continue;
    }
    print_rows(r);
  }
  std::cout << "(seconds: median of " << runs << " runs each, after one untimed run, sequential and parallel "
               "alternating; speed-up: sequential / parallel; total: the whole call, with the input checks)\n";

  tools::Json_writer json;
  json.begin_object()
    .field("benchmark", "concurrency")
    .field("runs", runs)
    .field("tbb", with_tbb)
    .field("tbb_threads", threads)
    .field("hardware_threads", std::size_t(std::thread::hardware_concurrency()));
  json.key("models").begin_array();
  for(const Result& r : results)
    write_json(json, r);
  json.end_array().end_object();
  try
  {
    tools::write_file_atomically(out_path, json.str());
  }
  catch(const std::exception& e)
  {
    std::cerr << "concurrency_benchmark: " << e.what() << "\n";
    return 2;
  }
  return failures == 0 ? 0 : 1;
}
