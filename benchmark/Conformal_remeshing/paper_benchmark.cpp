// paper_benchmark: one run of the paper benchmark (run_paper_benchmark.sh) in this process, so
// that the peak memory measured is the run's own; and the list of the benchmark's runs.
//
//   paper_benchmark plan [--scale full|small] [--part table|scaling|all] [--models NAME,...]
//                        [--methods conformal,isotropic,gmsh,meshlab]
//   paper_benchmark run MESH OUT.json --method conformal|isotropic|gmsh|meshlab
//                   (--target-output-vertices N | --target-edge-length L) [--name NAME]
//                   [--mid-plane-cut] [--time-limit SECONDS] [--hausdorff-samples N] [--output OUT.off]
//
// plan prints one line per run: id, model, input vertices, method, output vertices the target
// edge length is chosen for, and "cut" when the paper cuts the part by its mid-plane. Without
// --methods it lists the runs of remesh_conformal() and isotropic_remeshing() only.
//
// run reads and checks MESH, then remeshes it with remesh_conformal() or with a peer (CGAL's
// isotropic_remeshing() with sharp edges and borders kept, support/isotropic_peer.h; Gmsh or
// MeshLab as a subprocess, support/external_peers.h) at one target edge length: given, or the one
// whose equilateral triangles cover the surface with N vertices. The peak memory of a Gmsh or
// MeshLab run is the larger of this process's and the largest subprocess's; a peer that is not
// installed or fails is a failed run (exit code 1), one that runs out of time a time limit. It records the wall seconds and the peak resident memory of every stage (the
// kernel's high-water mark, reset when a stage starts; remesh_conformal() says when its stages
// start through its progress callback), the library's own report (per-patch stage times, Newton
// iterations, flips), the process's peak memory (the largest of the stages'), the sizes, the
// quality of input and output and the Hausdorff distance both ways. OUT.json is rewritten whenever a stage starts
// (status "running"), so that a run that dies says where; past the time limit a watchdog writes
// it with status "time_limit" and the process exits with code 3.
// Exit codes: 0 done, 1 the method failed (status "failed" with the error), 2 bad arguments or
// unreadable input, 3 time limit.

#include "atomic_file.h"
#include "external_peers.h"
#include "isotropic_peer.h"
#include "json_writer.h"
#include "model_tool.h"
#include "paper_benchmark_plan.h"
#include "process_memory.h"
#include "report_json.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace tools = Conformal_remeshing_tools;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::chrono::steady_clock Clock;

namespace {

const char* usage =
  "usage: paper_benchmark plan [--scale full|small] [--part table|scaling|all] [--models NAME,...]\n"
  "                            [--methods conformal,isotropic,gmsh,meshlab]\n"
  "       paper_benchmark run MESH OUT.json --method conformal|isotropic|gmsh|meshlab\n"
  "                       (--target-output-vertices N | --target-edge-length L) [--name NAME]\n"
  "                       [--mid-plane-cut] [--time-limit SECONDS] [--hausdorff-samples N] [--output OUT.off]\n"
  "  --mid-plane-cut         cut by the plane z = middle of the bounding box first (the paper's brake)\n"
  "  --time-limit SECONDS    give up past it: OUT.json gets status \"time_limit\", exit code 3 (default 3600)\n"
  "  --hausdorff-samples N   points sampled on each mesh for the Hausdorff distances (default twice the\n"
  "                          input's faces, within [200000, 2000000])\n"
  "exit code: 0 done, 1 the method failed, 2 bad arguments or unreadable input, 3 time limit\n";

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string first_line_of(const std::string& path, const std::string& prefix)
{
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, prefix.size(), prefix) == 0)
      return line;
  return std::string();
}

// Where and when the run was made: the numbers are only comparable on the same machine and load.
struct Machine
{
  std::string date, cpu;
  unsigned int cores = std::thread::hardware_concurrency();
  double memory_mb = -1.;
  std::string load_at_start;

  Machine()
  {
    const std::time_t now = std::time(nullptr);
    char buffer[32];
    std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
    date = buffer;
    cpu = first_line_of("/proc/cpuinfo", "model name");
    const std::string::size_type colon = cpu.find(':');
    cpu = colon == std::string::npos ? std::string("unknown") : cpu.substr(colon + 2);
    std::istringstream total(first_line_of("/proc/meminfo", "MemTotal:").substr(9));
    double kilobytes = -1.;
    if(total >> kilobytes)
      memory_mb = kilobytes / 1024.;
    load_at_start = load_average();
  }

  static std::string load_average()
  {
    std::ifstream in("/proc/loadavg");
    double one = 0., five = 0., fifteen = 0.;
    std::ostringstream os;
    if(in >> one >> five >> fifteen)
      os << one << " " << five << " " << fifteen;
    return os.str();
  }
};

struct Stage
{
  std::string name;
  double seconds = 0.;
  double peak_mb = -1.; // resident high-water mark during the stage
  double resident_mb_at_end = -1.;
};

// Everything the run writes to OUT.json; filled as the run goes.
struct Record
{
  std::string name, method, input_file, status = "running", error, current_stage;
  Machine machine;
  double target_edge_length = 0., target_output_vertices = 0., time_limit = 0.;
  bool mid_plane_cut = false;
  CR::Mesh_check_report checks;
  bool checked = false;
  std::vector<Stage> stages;
  bool method_completed = false;
  double method_seconds = 0., peak_mb_method = -1.; // the process's peak up to the end of the method
  std::size_t output_vertices = 0, output_faces = 0;
  bool is_conformal = false;
  CR::Remeshing_report report;
  CR::Remeshing_statistics statistics;
  // after the method
  bool measured = false;
  CR::Mesh_quality_report input_quality, output_quality;
  CR::Reference_comparison fidelity;
  double edges_in_range = 0., measuring_seconds = 0., hausdorff_samples = 0.;
  double peak_mb_with_measuring = -1.;
};

void write_library_report(tools::Json_writer& json, const CR::Remeshing_report& r, const CR::Remeshing_statistics& s)
{
  double welding = 0., refinement = 0., layout = 0., check = 0., flips = 0., factorization = 0., solve = 0., line_search = 0.;
  std::size_t iterations = 0, not_converged = 0, edge_splits = 0, boundary_splits = 0, welded_vertices = 0, hole_fill_flips = 0;
  for(const CR::Flattening_report& p : s.patches)
  {
    welding += p.seconds_welding;
    refinement += p.seconds_refinement;
    layout += p.seconds_layout;
    check += p.seconds_check;
    flips += p.seconds_flips;
    factorization += p.seconds_factorization;
    solve += p.seconds_solve;
    line_search += p.seconds_line_search;
    iterations += std::size_t(p.iterations);
    not_converged += p.converged ? 0 : 1;
    edge_splits += p.edge_splits;
    boundary_splits += p.boundary_splits;
    welded_vertices += p.welded_vertices;
    hole_fill_flips += p.hole_fill_flips;
  }
  json.key("library_seconds").begin_object()
      .field("segmentation", s.seconds_segmentation).field("flattening", s.seconds_flattening)
      .field("meshing_stage", s.seconds_meshing_stage).field("gluing", s.seconds_gluing)
      .field("welding_thread_seconds", welding).field("refinement_thread_seconds", refinement) // part of welding
      .field("ricci_flow_thread_seconds", s.seconds_ricci_flow)
      // parts of the flow: flips and splits to Delaunay, Hessian factorizations, solves, line search
      .field("ricci_flow_flips_thread_seconds", flips).field("ricci_flow_factorization_thread_seconds", factorization)
      .field("ricci_flow_solve_thread_seconds", solve).field("ricci_flow_line_search_thread_seconds", line_search)
      .field("layout_thread_seconds", layout).field("embedding_check_thread_seconds", check)
      .field("planar_meshing_thread_seconds", s.seconds_planar_meshing)
      .field("optimization_thread_seconds", s.seconds_optimization)
      .field("pull_back_thread_seconds", s.seconds_pull_back).end_object();
  json.key("segmentation").begin_object().field("patches", r.number_of_patches).field("plane_cuts", r.plane_cuts)
      .field("patch_bisections", r.patch_bisections).field("feature_edges", r.feature_edges)
      .field("dangling_feature_edges", r.dangling_feature_edges).end_object();
  json.key("flattening").begin_object().field("newton_iterations_max", s.max_newton_iterations)
      .field("newton_iterations_total", iterations).field("flips", s.flips).field("hole_fill_flips", hole_fill_flips)
      .field("retriangulated_faces", s.retriangulated_faces).field("patches_not_converged", not_converged).field("max_curvature_error", s.max_curvature_error)
      .field("max_scale_ratio", s.max_scale_ratio).field("edge_splits", edge_splits)
      .field("boundary_splits", boundary_splits).field("welded_vertices", welded_vertices).end_object();
  json.key("meshing").begin_object().field("boundary_curves", s.boundary_curves).field("refined_boundary_curves", r.refined_boundary_curves)
      .field("split_diagonals", r.split_diagonals)
      .field("boundary_samples", s.boundary_samples).field("clamped_vertices", s.clamped_vertices).end_object();
}

std::string to_json(const Record& r)
{
  tools::Json_writer json;
  json.begin_object().field("name", r.name).field("method", r.method).field("input_file", r.input_file);
  json.field("status", r.status).field("error", r.error).field("stage_at_exit", r.current_stage);
  json.key("machine").begin_object().field("date", r.machine.date).field("cpu", r.machine.cpu)
      .field("cores", std::size_t(r.machine.cores)).field("memory_mb", r.machine.memory_mb)
      .field("load_average_at_start", r.machine.load_at_start).field("load_average_now", Machine::load_average())
      .end_object();
  json.field("target_edge_length", r.target_edge_length).field("target_output_vertices", r.target_output_vertices)
      .field("mid_plane_cut", r.mid_plane_cut).field("time_limit", r.time_limit);
  if(r.checked)
  {
    json.key("input").begin_object().field("vertices", r.checks.number_of_vertices).field("faces", r.checks.number_of_faces);
    if(r.checks.topology_available)
      json.field("components", r.checks.components.size()).field("genus", long(r.checks.total_genus()))
          .field("boundary_loops", r.checks.total_boundary_loops());
    json.end_object();
  }
  json.key("stages").begin_array();
  for(const Stage& s : r.stages)
    json.begin_object().field("name", s.name).field("seconds", s.seconds).field("peak_mb", s.peak_mb)
        .field("resident_mb_at_end", s.resident_mb_at_end).end_object();
  json.end_array();
  json.field("method_completed", r.method_completed);
  if(r.method_completed)
  {
    json.field("method_seconds", r.method_seconds).field("peak_mb", r.peak_mb_method);
    json.key("output").begin_object().field("vertices", r.output_vertices).field("faces", r.output_faces).end_object();
    if(r.is_conformal)
      write_library_report(json, r.report, r.statistics);
  }
  if(r.measured)
  {
    json.field("measuring_seconds", r.measuring_seconds).field("peak_mb_with_measuring", r.peak_mb_with_measuring)
        .field("hausdorff_samples", r.hausdorff_samples).field("share_of_edges_within_0_7_and_1_4_target", r.edges_in_range);
    json.key("input_quality");
    tools::write_json(json, r.input_quality);
    json.key("output_quality");
    tools::write_json(json, r.output_quality);
    json.key("fidelity");
    tools::write_json(json, r.fidelity);
  }
  json.end_object();
  return json.str();
}

// The record, its file, and the stage clock. Every change goes through the mutex, because the
// watchdog may write the file at any time.
class Recorder
{
public:
  Recorder(Record& record, const std::string& path) : record_(record), path_(path) {}

  template <typename Change>
  void update(const Change& change)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    change(record_);
    write();
  }

  // Ends the current stage (if any) and starts `name`; a repeated name continues the stage.
  void start_stage(const std::string& name)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if(name == record_.current_stage)
      return;
    end_stage_locked();
    record_.current_stage = name;
    peak_before_reset_mb_ = std::max(peak_before_reset_mb_, bm::peak_resident_megabytes_since_reset());
    bm::reset_peak_resident_memory();
    stage_start_ = Clock::now();
    write();
  }

  // The process's peak so far, in MB. Resetting the high-water mark for each stage also resets
  // what getrusage() reports (its maximum resident size is the same kernel counter while no
  // thread has exited), so the peaks from before each reset are kept here.
  double process_peak_megabytes()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::max({peak_before_reset_mb_, bm::peak_resident_megabytes_since_reset(), bm::peak_resident_megabytes()});
  }

  void end_stage()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    end_stage_locked();
    record_.current_stage.clear();
    write();
  }

  // What the watchdog does: the stage under way is recorded as far as it went.
  void give_up(const std::string& status, const std::string& error)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string stage = record_.current_stage;
    end_stage_locked();
    record_.current_stage = stage;
    record_.status = status;
    record_.error = error + (stage.empty() ? std::string() : " (during " + stage + ")");
    write();
  }

private:
  void end_stage_locked()
  {
    if(record_.current_stage.empty())
      return;
    Stage s;
    s.name = record_.current_stage;
    s.seconds = seconds_since(stage_start_);
    s.peak_mb = bm::peak_resident_megabytes_since_reset();
    s.resident_mb_at_end = bm::resident_megabytes();
    record_.stages.push_back(s);
  }

  void write()
  {
    try
    {
      tools::write_file_atomically(path_, to_json(record_));
    }
    catch(const std::exception& e)
    {
      std::cerr << "paper_benchmark: " << e.what() << std::endl;
    }
  }

  Record& record_;
  std::string path_;
  std::mutex mutex_;
  Clock::time_point stage_start_ = Clock::now();
  double peak_before_reset_mb_ = -1.;
};

// Calls `on_timeout` and ends the process with exit code 3 unless stopped within `seconds`:
// a run that hangs or crawls still leaves its record.
class Watchdog
{
public:
  Watchdog(double seconds, std::function<void()> on_timeout)
    : thread_([this, seconds, on_timeout] {
        std::unique_lock<std::mutex> lock(mutex_);
        if(!stopped_condition_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return stopped_; }))
        {
          on_timeout();
          std::_Exit(3);
        }
      })
  {}

  ~Watchdog()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopped_ = true;
    }
    stopped_condition_.notify_all();
    thread_.join();
  }

private:
  std::mutex mutex_;
  std::condition_variable stopped_condition_;
  bool stopped_ = false;
  std::thread thread_;
};

// The stage of remesh_conformal() a progress message starts; empty when it starts none.
std::string conformal_stage_of(const std::string& message)
{
  if(message.find("checking the distance") != std::string::npos)
    return "surface_distance";
  if(message.find("gaps between sheets") != std::string::npos)
    return "proximity";
  if(message.find("checking") != std::string::npos || message.find("segment") != std::string::npos)
    return "segmentation"; // the report counts the parameter checks with the segmentation
  if(message.find("flatten") != std::string::npos)
    return "flattening";
  if(message.find("meshing") != std::string::npos)
    return "meshing";
  if(message.find("glu") != std::string::npos)
    return "gluing";
  return std::string();
}

struct Run_options
{
  std::string mesh, json, method, name, output;
  double target_output_vertices = 0., target_edge_length = 0., time_limit = 3600., samples = 0.;
  bool mid_plane_cut = false;
};

// `text` as a positive finite number, else throws naming `option`.
double positive(const std::string& option, const std::string& text)
{
  const double x = bm::parse_double(option, text);
  if(!(x > 0.))
    throw std::invalid_argument(option + ": must be positive: '" + text + "'");
  return x;
}

Run_options parse_run(int argc, char** argv)
{
  Run_options o;
  std::vector<std::string> positional;
  for(int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(arg + ": missing value");
      return argv[++i];
    };
    if(arg == "--method")
      o.method = value();
    else if(arg == "--name")
      o.name = value();
    else if(arg == "--output")
      o.output = value();
    else if(arg == "--target-output-vertices")
      o.target_output_vertices = positive(arg, value());
    else if(arg == "--target-edge-length")
      o.target_edge_length = positive(arg, value());
    else if(arg == "--time-limit")
      o.time_limit = positive(arg, value());
    else if(arg == "--hausdorff-samples")
      o.samples = positive(arg, value());
    else if(arg == "--mid-plane-cut")
      o.mid_plane_cut = true;
    else if(!arg.empty() && arg[0] == '-')
      throw std::invalid_argument("unknown option '" + arg + "'");
    else
      positional.push_back(arg);
  }
  if(positional.size() != 2)
    throw std::invalid_argument("run needs MESH and OUT.json");
  o.mesh = positional[0];
  o.json = positional[1];
  const std::vector<std::string>& methods = bm::paper_benchmark_methods();
  if(std::find(methods.begin(), methods.end(), o.method) == methods.end())
    throw std::invalid_argument("--method must be conformal, isotropic, gmsh or meshlab");
  if((o.target_output_vertices > 0.) == (o.target_edge_length > 0.))
    throw std::invalid_argument("give one of --target-output-vertices and --target-edge-length");
  if(o.name.empty())
    o.name = o.mesh.substr(o.mesh.find_last_of('/') + 1);
  return o;
}

int run(int argc, char** argv)
{
  Run_options o;
  try
  {
    o = parse_run(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << "paper_benchmark: " << e.what() << "\n" << usage;
    return 2;
  }
  Record record;
  record.name = o.name;
  record.method = o.method;
  record.input_file = o.mesh;
  record.mid_plane_cut = o.mid_plane_cut;
  record.time_limit = o.time_limit;
  record.is_conformal = o.method == "conformal";
  Recorder recorder(record, o.json);
  auto progress_line = [&](const std::string& what) {
    std::cerr << "paper_benchmark: " << o.name << " (" << o.method << "): " << what << std::endl;
  };
  const Clock::time_point start = Clock::now();
  Watchdog watchdog(o.time_limit, [&] {
    std::ostringstream os;
    os << "time limit of " << o.time_limit << " s exceeded after " << seconds_since(start) << " s";
    recorder.give_up("time_limit", os.str());
    progress_line(os.str());
  });

  // --- input ---------------------------------------------------------------------------------
  Mesh input;
  try
  {
    progress_line("reading " + o.mesh);
    recorder.start_stage("read_and_check");
    const CR::Mesh_check_report checks = CR::read_and_check_mesh(o.mesh, input);
    recorder.end_stage();
    recorder.update([&](Record& r) {
      r.checks = checks;
      r.checked = true;
    });
    if(!checks.is_valid())
      throw std::runtime_error("invalid input: " + checks.summary());
  }
  catch(const std::exception& e)
  {
    recorder.update([&](Record& r) {
      r.status = "failed";
      r.error = e.what();
    });
    std::cerr << "paper_benchmark: " << e.what() << "\n";
    return 2;
  }
  double h = o.target_edge_length;
  if(h == 0.)
  {
    // Equilateral triangles of side h: a vertex per sqrt(3)/2 h^2 of area.
    const double area = CGAL::to_double(PMP::area(input));
    h = std::sqrt(2. * area / (std::sqrt(3.) * o.target_output_vertices));
  }
  std::vector<K::Plane_3> planes;
  if(o.mid_plane_cut)
  {
    const CGAL::Bbox_3 box = PMP::bbox(input);
    planes.emplace_back(0., 0., 1., -0.5 * (box.zmin() + box.zmax()));
  }
  recorder.update([&](Record& r) {
    r.target_edge_length = h;
    r.target_output_vertices = o.target_output_vertices;
  });

  // --- the method ------------------------------------------------------------------------------
  Mesh output;
  std::string error;
  double method_seconds = 0.;
  try
  {
    const Clock::time_point method_start = Clock::now();
    if(record.is_conformal)
    {
      progress_line("remesh_conformal at target edge length " + std::to_string(h));
      const std::function<void(const std::string&)> progress = [&](const std::string& message) {
        progress_line(message);
        const std::string stage = conformal_stage_of(message);
        if(!stage.empty())
          recorder.start_stage(stage);
      };
      CR::Remeshing_statistics statistics;
      const CR::Remeshing_report report = CR::remesh_conformal<CGAL::Parallel_if_available_tag>(
        input, output,
        CR::parameters::target_edge_length(
          h, CR::parameters::cut_planes(planes, CR::parameters::progress(progress, CR::parameters::statistics(std::ref(statistics))))));
      recorder.end_stage();
      recorder.update([&](Record& r) {
        r.report = report;
        r.statistics = statistics;
      });
    }
    else if(o.method == "gmsh" || o.method == "meshlab")
    {
      progress_line(o.method + " at target edge length " + std::to_string(h));
      recorder.start_stage("remeshing");
      // The subprocess ends before the watchdog would, so that its time-out is the one recorded.
      const double timeout = std::max(1., 0.95 * o.time_limit - seconds_since(start));
      bm::Peer_run<Mesh> peer = o.method == "gmsh" ? bm::run_gmsh_peer(input, h, timeout) : bm::run_meshlab_peer(input, h, timeout);
      recorder.end_stage();
      if(peer.status == bm::Peer_status::timed_out)
      {
        recorder.give_up("time_limit", o.method + " " + peer.reason + " (" + std::to_string(timeout) + " s)");
        progress_line(o.method + " timed out");
        return 3;
      }
      if(peer.status != bm::Peer_status::ok)
        throw std::runtime_error(o.method + " " + bm::peer_status_name(peer.status) + ": " + peer.reason);
      output = std::move(peer.mesh);
    }
    else
    {
      progress_line("isotropic_remeshing at target edge length " + std::to_string(h));
      recorder.start_stage("features");
      output = input;
      auto constrained = bm::constrain_sharp_edges_and_borders(output);
      recorder.start_stage("remeshing");
      bm::remesh_isotropically(output, h, constrained);
      recorder.end_stage();
    }
    method_seconds = seconds_since(method_start);
    const double peak_mb_method = std::max(recorder.process_peak_megabytes(), bm::largest_child_peak_megabytes());
    recorder.update([&](Record& r) {
      r.method_completed = true;
      r.method_seconds = method_seconds;
      r.peak_mb_method = peak_mb_method;
      r.output_vertices = output.number_of_vertices();
      r.output_faces = output.number_of_faces();
      r.status = "measuring";
    });
  }
  catch(const std::bad_alloc&)
  {
    error = "out of memory";
  }
  catch(const std::exception& e)
  {
    error = e.what();
  }
  if(!error.empty())
  {
    recorder.update([&](Record& r) {
      r.status = "failed";
      r.error = error + (r.current_stage.empty() ? std::string() : " (during " + r.current_stage + ")");
    });
    progress_line("failed: " + error);
    return 1;
  }

  // --- measurements (not timed as the method) ----------------------------------------------------
  progress_line("measuring quality and Hausdorff distances");
  const Clock::time_point measuring_start = Clock::now();
  recorder.update([&](Record& r) { r.current_stage = "measuring"; });
  const CR::Mesh_quality_report before = CR::mesh_quality(input), after = CR::mesh_quality(output);
  const double in_range = CR::share_of_edges_with_length_in(output, 0.7 * h, 1.4 * h);
  // Enough samples to hit every input face about twice, within what takes a minute at most.
  const double samples = o.samples > 0. ? o.samples : std::clamp(2. * double(input.number_of_faces()), 2e5, 2e6);
  const CR::Reference_comparison fidelity =
    CR::compare_to_reference(output, input, CGAL::parameters::number_of_points_on_faces(std::size_t(samples)));
  const double peak_mb_with_measuring = recorder.process_peak_megabytes();
  recorder.update([&](Record& r) {
    r.current_stage.clear();
    r.measured = true;
    r.input_quality = before;
    r.output_quality = after;
    r.fidelity = fidelity;
    r.edges_in_range = in_range;
    r.hausdorff_samples = samples;
    r.measuring_seconds = seconds_since(measuring_start);
    r.peak_mb_with_measuring = peak_mb_with_measuring;
    r.status = "ok";
  });
  if(!o.output.empty())
    tools::write_file_atomically_at(o.output, [&](const std::string& temporary) {
      return CGAL::IO::write_polygon_mesh(temporary, output, CGAL::parameters::stream_precision(17));
    });
  progress_line("done in " + std::to_string(method_seconds) + " s: " + std::to_string(output.number_of_vertices())
                + " vertices, minimum angle " + std::to_string(after.minimum_angle.min) + " deg");
  return 0;
}

int plan(int argc, char** argv)
{
  bm::Benchmark_scale scale = bm::Benchmark_scale::full;
  std::string part = "all", models, methods;
  for(int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(i + 1 >= argc)
    {
      std::cerr << "paper_benchmark: bad argument '" << arg << "'\n" << usage;
      return 2;
    }
    const std::string value = argv[++i];
    if(arg == "--scale")
      scale = bm::benchmark_scale_from_name(value);
    else if(arg == "--part" && (value == "table" || value == "scaling" || value == "all"))
      part = value;
    else if(arg == "--models")
      models = "," + value + ",";
    else if(arg == "--methods"
            && std::regex_match(value, std::regex("(conformal|isotropic|gmsh|meshlab)(,(conformal|isotropic|gmsh|meshlab))*")))
      methods = "," + value + ",";
    else
    {
      std::cerr << "paper_benchmark: bad argument '" << arg << " " << value << "'\n" << usage;
      return 2;
    }
  }
  const auto listed = [](const std::string& list, const std::string& name) {
    return list.empty() || list.find("," + name + ",") != std::string::npos;
  };
  for(const bm::Planned_run& r : bm::paper_benchmark_plan(scale))
  {
    const std::string model = bm::paper_model_info(r.model).name;
    const bool method_listed = methods.empty() ? bm::is_default_paper_benchmark_method(r.method) : listed(methods, r.method);
    if((part != "all" && part != r.part) || !listed(models, model) || !method_listed)
      continue;
    std::cout << r.id << " " << model << " " << r.input_vertices << " " << r.method << " " << r.output_vertices
              << (r.mid_plane_cut ? " cut" : "") << "\n";
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  try
  {
    if(command == "run")
      return run(argc, argv);
    if(command == "plan")
      return plan(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << "paper_benchmark: " << e.what() << "\n";
    return 2;
  }
  if(command == "--help" || command == "-h")
  {
    std::cout << usage;
    return 0;
  }
  std::cerr << usage;
  return 2;
}
