// remeshing_benchmark: remesh_conformal() against CGAL's isotropic_remeshing() at the same target
// edge length (1% of the bounding-box diagonal by default), in the same run, on generated patches
// and on any mesh files given. For each: times (median of 3 runs), output size, minimum angle,
// share of triangles below 25 degrees, mean equiangle skewness, share of edges within
// [0.7, 1.4] x target, Hausdorff distance both ways relative to the diagonal, self-intersection.
// Prints a table and writes JSON (atomically, at the end); then, against output size, the
// meshing stage's speed (the goal is 100k output vertices per second for meshing plus
// pull-back), and where its time goes, phase by phase. With --save-meshes DIR, also writes
// each model's two outputs as OFF files (and the input of the generated models) into DIR. With
// --lloyd N, remesh_conformal() runs with lloyd_iterations(N) (CGAL's Lloyd smoothing in the plane);
// with --surface-distance R, with a surface-distance bound of R target lengths.
// With --peers, also the peers named (isotropic_remeshing(), Gmsh, MeshLab; support/external_peers.h)
// at the same target length and, with --same-size, at the target length that gives each peer's
// output the number of vertices of ours (within 5%); a peer that fails, times out or is not
// installed is recorded as such, in a fourth table and in each model's "peers" record.
//
//   remeshing_benchmark OUT.json [--relative R] [--lloyd N] [--rounds N] [--surface-distance R]
//                      [--save-meshes DIR] [--peers LIST] [--same-size] [--peer-timeout S] [--no-generated] [MESH ...]
//
// Exit code: 0, 1 when a model is refused, 2 for bad arguments or input, or an output that cannot
// be written.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/angles_at_sharp_corners.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>

#include "atomic_file.h"
#include "benchmark_io.h"
#include "cad_like_models.h"
#include "external_peers.h"
#include "test_surfaces.h"
#include "generated_patches.h"
#include "isotropic_peer.h"
#include "json_writer.h"
#include "model_tool.h"
#include "timing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

struct Measure
{
  double seconds = 0.;
  std::size_t vertices = 0;
  double min_angle = 0., below_25 = 0., below_25_away_from_sharp_corners = 0., below_30 = 0., skewness = 0., edges_in_range = 0., hausdorff_to = 0., hausdorff_from = 0.;
  bool self_intersects = false;
};

Measure measure(const Mesh& input, const Mesh& output, double h, double seconds)
{
  Measure m;
  m.seconds = seconds;
  m.vertices = output.number_of_vertices();
  const CR::Mesh_quality_report q = CR::mesh_quality(output);
  m.min_angle = q.minimum_angle.min;
  m.below_25 = q.share_with_minimum_angle_below(25.);
  m.below_30 = q.share_with_minimum_angle_below(30.);
  m.below_25_away_from_sharp_corners = CR::angles_at_sharp_corners(output, input, 25.).share_below_away_from_sharp_corners();
  m.skewness = q.skewness.mean;
  m.edges_in_range = CR::share_of_edges_with_length_in(output, 0.7 * h, 1.4 * h);
  const CR::Reference_comparison c = CR::compare_to_reference(output, input);
  m.hausdorff_to = c.relative_distance_to_reference;
  m.hausdorff_from = c.relative_distance_from_reference;
  m.self_intersects = c.self_intersects;
  return m;
}

void print_row(const std::string& model, const std::string& method, const Measure& m)
{
  std::cout << std::left << std::setw(22) << model << std::setw(12) << method << std::right << std::setprecision(3)
            << std::setw(8) << m.seconds << std::setw(8) << m.vertices << std::setw(8) << m.min_angle << std::setw(8)
            << 100. * m.below_25 << std::setw(8) << m.skewness << std::setw(8) << 100. * m.edges_in_range << std::setw(10)
            << m.hausdorff_to << std::setw(10) << m.hausdorff_from << std::setw(6) << (m.self_intersects ? "yes" : "no") << "\n";
}

void write_json(std::ostream& out, const Measure& m)
{
  out << "{\"median_seconds\": " << m.seconds << ", \"vertices\": " << m.vertices << ", \"min_angle\": " << m.min_angle
      << ", \"share_below_25\": " << m.below_25
      << ", \"share_below_25_away_from_sharp_corners\": " << m.below_25_away_from_sharp_corners << ", \"mean_skewness\": " << m.skewness
      << ", \"edges_in_range\": " << m.edges_in_range << ", \"hausdorff_to_input\": " << m.hausdorff_to
      << ", \"hausdorff_from_input\": " << m.hausdorff_from << ", \"self_intersects\": " << (m.self_intersects ? "true" : "false") << "}";
}

std::string usage()
{
  return "usage: remeshing_benchmark OUT.json [--relative R] [--lloyd N] [--rounds N] [--surface-distance R]\n"
         "                           [--save-meshes DIR]\n"
         "                           [--peers LIST] [--same-size] [--peer-timeout S] [--no-generated] [MESH ...]\n"
         "  --relative R        target edge length over the bounding-box diagonal, 0 < R < 1 (default 0.01)\n"
         "  --lloyd N           remesh_conformal() with N Lloyd iterations in the plane, 0 to 1000 (default 0)\n"
         "  --rounds N          remesh_conformal() with N optimization rounds on the surface, 0 to 100 (default 5)\n"
         "  --surface-distance R  remesh_conformal() with a surface-distance bound of R times the target edge length,\n"
         "                      R >= 0 (default 0.25, the library's; 0: none)\n"
         "  --save-meshes DIR   write DIR/<model>_conformal.off and DIR/<model>_isotropic.off for each model,\n"
         "                      and DIR/<model>_input.off for the generated ones; DIR is created if missing\n"
         "  --peers LIST        the peers compared in the \"peers\" records, of isotropic, gmsh and meshlab, comma-separated\n"
         "                      (default: isotropic alone, in the \"isotropic\" record only)\n"
         "  --same-size         also compare each peer at the target length that gives it our number of vertices, within 5%\n"
         "  --peer-timeout S    seconds each run of gmsh or meshlabserver may take (default 600)\n"
         "  --no-generated      only the mesh files given, not the generated patches";
}

// A model's name as the start of a file name: lowercase, each run of spaces and commas (and of any
// other character but letters, digits, '-' and '.') one '_'; a mesh file's extension is dropped
// ("spherical cap, fine" -> "spherical_cap_fine", "nefertiti.off" -> "nefertiti").
std::string file_safe_name(std::string name, bool is_file)
{
  if(is_file)
  {
    const std::string::size_type dot = name.find_last_of('.');
    if(dot != std::string::npos && dot > 0)
      name.erase(dot);
  }
  std::string safe;
  for(unsigned char c : name)
  {
    if(std::isalnum(c) || c == '-' || c == '.')
      safe += char(std::tolower(c));
    else if(safe.empty() || safe.back() != '_')
      safe += '_';
  }
  return safe.empty() ? std::string("model") : safe;
}

// `s` as a JSON string, quotes included (model names come from file names).
std::string json_string(const std::string& s)
{
  tools::Json_writer w;
  w.value(s);
  std::string text = w.str();
  text.pop_back(); // its final newline
  return text;
}

// The peers of the "peers" records and how they run.
struct Peer_options
{
  std::vector<std::string> peers;  // of "isotropic", "gmsh", "meshlab", in the order given
  bool same_size = false;          // also the comparison at our output size
  double timeout_seconds = 600.;   // per run of an external peer
  bool requested() const { return !peers.empty() || same_size; }
};

const std::vector<std::string>& known_peers()
{
  static const std::vector<std::string> names{"isotropic", "gmsh", "meshlab"};
  return names;
}

// The comma-separated list of --peers, each name known and given once.
std::vector<std::string> parse_peers(const std::string& list)
{
  std::vector<std::string> peers;
  std::istringstream in(list);
  for(std::string name; std::getline(in, name, ',');)
  {
    if(std::find(known_peers().begin(), known_peers().end(), name) == known_peers().end())
      throw std::invalid_argument("--peers: unknown peer '" + name + "' (isotropic, gmsh, meshlab)");
    if(std::find(peers.begin(), peers.end(), name) == peers.end())
      peers.push_back(name);
  }
  if(peers.empty())
    throw std::invalid_argument("--peers: no peer in '" + list + "'");
  return peers;
}

// One peer in one comparison: how its run ended, at which target length, and its measures.
struct Peer_record
{
  std::string peer;
  bm::Peer_status status = bm::Peer_status::failed;
  std::string reason;
  double target_edge_length = 0.;
  int runs = 0;                 // of the tuning, for the comparison at the same size
  bool within_tolerance = true; // the output size within 5% of ours (same size only)
  Measure measure;
};

// A run of `peer` on `input` at target length h: isotropic_remeshing() in this process, the others
// as subprocesses.
bm::Peer_runner<Mesh> peer_runner(const std::string& peer, const Mesh& input, double timeout_seconds)
{
  if(peer == "gmsh")
    return [&input, timeout_seconds](double h) { return bm::run_gmsh_peer(input, h, timeout_seconds); };
  if(peer == "meshlab")
    return [&input, timeout_seconds](double h) { return bm::run_meshlab_peer(input, h, timeout_seconds); };
  return [&input](double h) {
    bm::Peer_run<Mesh> run;
    run.mesh = input;
    run.seconds = bm::wall_seconds([&] { bm::run_isotropic_peer(run.mesh, h); });
    run.status = bm::Peer_status::ok;
    return run;
  };
}

// The record of a finished run: its measures, or a failure when they cannot be taken.
Peer_record record_of(const std::string& peer, bm::Peer_run<Mesh>& run, const Mesh& input, double h, double seconds)
{
  Peer_record r;
  r.peer = peer;
  r.status = run.status;
  r.reason = run.reason;
  r.target_edge_length = h;
  if(run.status != bm::Peer_status::ok)
  {
    r.measure.seconds = run.seconds;
    return r;
  }
  try
  {
    r.measure = measure(input, run.mesh, h, seconds);
  }
  catch(const std::exception& e)
  {
    r.status = bm::Peer_status::failed;
    r.reason = std::string("output not measurable: ") + e.what();
  }
  return r;
}

// Each peer at our target length h, timed as isotropic_remeshing() is (median of 3 runs; one run
// when the first fails). The isotropic record is the one measured for the "isotropic" field.
std::vector<Peer_record> compare_at_same_length(const Mesh& input, double h, const Measure& isotropic, const Peer_options& options)
{
  std::vector<Peer_record> records;
  for(const std::string& peer : options.peers)
  {
    if(peer == "isotropic")
    {
      records.push_back(Peer_record{peer, bm::Peer_status::ok, "", h, 1, true, isotropic});
      continue;
    }
    const bm::Peer_runner<Mesh> run_peer = peer_runner(peer, input, options.timeout_seconds);
    bm::Peer_run<Mesh> run = run_peer(h);
    std::vector<double> seconds{run.seconds};
    for(int k = 1; k < 3 && run.status == bm::Peer_status::ok; ++k)
      seconds.push_back(run_peer(h).seconds);
    records.push_back(record_of(peer, run, input, h, bm::median(seconds)));
  }
  return records;
}

// Each peer at the target length tuned until its output has our number of vertices within 5%,
// timed by the run whose output is measured.
std::vector<Peer_record> compare_at_same_size(const Mesh& input, double h, std::size_t vertices, const Peer_options& options)
{
  std::vector<Peer_record> records;
  for(const std::string& peer : options.peers)
  {
    bm::Tuned_run<Mesh> tuned = bm::tune_to_vertex_count(peer_runner(peer, input, options.timeout_seconds), h, vertices);
    Peer_record r = record_of(peer, tuned.run, input, tuned.target_edge_length, tuned.run.seconds);
    r.runs = tuned.runs;
    r.within_tolerance = tuned.within_tolerance;
    records.push_back(std::move(r));
  }
  return records;
}

// The JSON object of one comparison: one field per peer.
void write_peer_records(std::ostream& out, const std::vector<Peer_record>& records, bool same_size)
{
  out << "{";
  for(std::size_t i = 0; i < records.size(); ++i)
  {
    const Peer_record& r = records[i];
    out << (i ? ", " : "") << json_string(r.peer) << ": {\"status\": " << json_string(bm::peer_status_name(r.status));
    if(!r.reason.empty())
      out << ", \"reason\": " << json_string(r.reason);
    out << ", \"target_edge_length\": " << r.target_edge_length;
    if(same_size)
      out << ", \"runs\": " << r.runs << ", \"within_5_percent\": " << (r.within_tolerance ? "true" : "false");
    out << ", \"seconds\": " << r.measure.seconds;
    if(r.status == bm::Peer_status::ok)
    {
      out << ", \"share_below_30\": " << r.measure.below_30 << ", \"measures\": ";
      write_json(out, r.measure);
    }
    out << "}";
  }
  out << "}";
}

// A row of the peers table.
void print_peer_row(const std::string& model, const std::string& comparison, const Peer_record& r)
{
  std::cout << std::left << std::setw(22) << model << std::setw(10) << r.peer << std::setw(12) << comparison << std::right
            << std::setprecision(3) << std::setw(10) << r.target_edge_length << std::setw(8) << r.measure.seconds;
  if(r.status != bm::Peer_status::ok)
  {
    std::cout << "  " << bm::peer_status_name(r.status) << (r.reason.empty() ? "" : ": ") << r.reason << "\n";
    return;
  }
  const Measure& m = r.measure;
  std::cout << std::setw(8) << m.vertices << std::setw(9) << m.min_angle << std::setw(8) << 100. * m.below_30 << std::setw(8)
            << m.skewness << std::setw(10) << m.hausdorff_to << std::setw(10) << m.hausdorff_from << std::setw(6)
            << (m.self_intersects ? "yes" : "no") << (r.within_tolerance ? "" : "  (size not within 5%)") << "\n";
}

// The comparisons of one model, for the fourth table.
struct Peer_comparison
{
  std::string model;
  Peer_record ours;
  std::vector<Peer_record> same_length, same_size;
};

// Ours beside each peer at the same length, then at the same size when asked.
Peer_comparison compare_with_peers(const std::string& model, const Mesh& input, double h, const Measure& ours,
                                   const Measure& isotropic, const Peer_options& options)
{
  Peer_comparison c{model, Peer_record{"conformal", bm::Peer_status::ok, "", h, 1, true, ours}, {}, {}};
  c.same_length = compare_at_same_length(input, h, isotropic, options);
  if(options.same_size)
    c.same_size = compare_at_same_size(input, h, ours.vertices, options);
  return c;
}

// The "peers" record of a model: ours (with the share below 30 degrees), then each comparison.
void write_peer_comparison(std::ostream& out, const Peer_comparison& c, bool same_size)
{
  out << "{\"conformal\": {\"share_below_30\": " << c.ours.measure.below_30 << ", \"measures\": ";
  write_json(out, c.ours.measure);
  out << "}, \"same_length\": ";
  write_peer_records(out, c.same_length, false);
  if(same_size)
  {
    out << ", \"same_size\": ";
    write_peer_records(out, c.same_size, true);
  }
  out << "}";
}

void print_peer_table(const std::vector<Peer_comparison>& comparisons)
{
  std::cout << "\n" << std::left << std::setw(22) << "model" << std::setw(10) << "method" << std::setw(12) << "comparison"
            << std::right << std::setw(10) << "target" << std::setw(8) << "sec" << std::setw(8) << "verts" << std::setw(9)
            << "minang" << std::setw(8) << "%<30" << std::setw(8) << "skew" << std::setw(10) << "H to" << std::setw(10)
            << "H from" << std::setw(6) << "self" << "\n";
  for(const Peer_comparison& c : comparisons)
  {
    print_peer_row(c.model, "", c.ours);
    for(const Peer_record& r : c.same_length)
      print_peer_row("", "same length", r);
    for(const Peer_record& r : c.same_size)
      print_peer_row("", "same size", r);
  }
  std::cout << "(peers: target = the peer's target edge length; sec: median of 3 runs at the same length, the measured "
               "run at the same size, of the subprocess for gmsh and meshlab; %<30: share of triangles with an angle "
               "below 30 degrees; H: Hausdorff distance to and from the input over its diagonal)\n";
}

struct Model
{
  std::string name;      // as printed and recorded in the JSON
  std::string file_stem; // DIR/<file_stem>_conformal.off, ... with --save-meshes
  bool generated = false;
  Mesh mesh;
};

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
  double relative = 0.01;
  int lloyd = 0;
  int rounds = 5; // remesh_conformal()'s default
  double surface_distance = 0.25; // times the target; remesh_conformal()'s default
  std::string mesh_directory; // empty: no --save-meshes
  Peer_options peer_options;
  bool with_generated = true;
  std::vector<Model> models;
  try
  {
    if(out_path.empty() || out_path[0] == '-')
      throw std::invalid_argument("the first argument must be the output file OUT.json, not '" + out_path + "'");
    // Every file is read before the first run, so that a bad one fails at once.
    std::vector<Model> files;
    for(int i = 2; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if(arg == "--relative")
      {
        if(i + 1 >= argc)
          throw std::invalid_argument("--relative: missing value");
        relative = bm::parse_double(arg, argv[++i]);
        if(!(relative > 0. && relative < 1.))
          throw std::invalid_argument("--relative: must be greater than 0 and less than 1: '" + std::string(argv[i]) + "'");
        continue;
      }
      // A whole-number option from 0 to `largest`.
      const auto whole_number = [&](int largest) {
        if(i + 1 >= argc)
          throw std::invalid_argument(arg + ": missing value");
        const double n = bm::parse_double(arg, argv[++i]);
        if(!(n >= 0. && n <= largest && n == std::floor(n)))
          throw std::invalid_argument(arg + ": must be a whole number from 0 to " + std::to_string(largest) + ": '" + std::string(argv[i]) + "'");
        return int(n);
      };
      if(arg == "--surface-distance")
      {
        if(i + 1 >= argc)
          throw std::invalid_argument("--surface-distance: missing value");
        surface_distance = bm::parse_double(arg, argv[++i]);
        if(!(surface_distance >= 0.) || !std::isfinite(surface_distance))
          throw std::invalid_argument("--surface-distance: must be 0 or more: '" + std::string(argv[i]) + "'");
        continue;
      }
      if(arg == "--lloyd")
      {
        lloyd = whole_number(1000);
        continue;
      }
      if(arg == "--rounds")
      {
        rounds = whole_number(100);
        continue;
      }
      if(arg == "--save-meshes")
      {
        if(i + 1 >= argc || argv[i + 1][0] == '\0')
          throw std::invalid_argument("--save-meshes: missing directory");
        mesh_directory = argv[++i];
        continue;
      }
      if(arg == "--peers")
      {
        if(i + 1 >= argc)
          throw std::invalid_argument("--peers: missing list");
        peer_options.peers = parse_peers(argv[++i]);
        continue;
      }
      if(arg == "--peer-timeout")
      {
        if(i + 1 >= argc)
          throw std::invalid_argument("--peer-timeout: missing value");
        peer_options.timeout_seconds = bm::parse_double(arg, argv[++i]);
        if(!(peer_options.timeout_seconds > 0.))
          throw std::invalid_argument("--peer-timeout: must be greater than 0: '" + std::string(argv[i]) + "'");
        continue;
      }
      if(arg == "--same-size")
      {
        peer_options.same_size = true;
        continue;
      }
      if(arg == "--no-generated")
      {
        with_generated = false;
        continue;
      }
      if(!arg.empty() && arg[0] == '-')
        throw std::invalid_argument("unknown option '" + arg + "'");
      Model m;
      m.name = arg.substr(arg.find_last_of('/') + 1);
      m.mesh = bm::read_model<Mesh>(arg);
      files.push_back(std::move(m));
    }
    bm::check_writable(out_path);
    if(peer_options.same_size && peer_options.peers.empty())
      peer_options.peers = {"isotropic"};
    for(std::pair<std::string, Mesh>& g : with_generated ? bm::generated_patches<Mesh>(true) : std::vector<std::pair<std::string, Mesh> >())
    {
      Model m;
      m.name = g.first;
      m.generated = true;
      m.mesh = std::move(g.second);
      models.push_back(std::move(m));
    }
    for(Model& m : files)
      models.push_back(std::move(m));
    if(!mesh_directory.empty())
    {
      // Distinct file names, even for two files of the same name in different directories.
      std::set<std::string> taken;
      for(Model& m : models)
      {
        const std::string stem = file_safe_name(m.name, !m.generated);
        m.file_stem = stem;
        for(int n = 2; !taken.insert(m.file_stem).second; ++n)
          m.file_stem = stem + "_" + std::to_string(n);
      }
      tools::prepare_output_directory(mesh_directory);
      for(const Model& m : models)
        for(const char* kind : {"_conformal.off", "_isotropic.off", "_input.off"})
          if(m.generated || std::string(kind) != "_input.off")
            bm::check_writable(mesh_directory + "/" + m.file_stem + kind);
    }
  }
  catch(const std::invalid_argument& e)
  {
    std::cerr << "remeshing_benchmark: " << e.what() << "\n" << usage() << "\n";
    return 2;
  }
  catch(const std::exception& e)
  {
    std::cerr << "remeshing_benchmark: " << e.what() << "\n";
    return 2;
  }

  // Writes one mesh of --save-meshes; a failure is reported, the run goes on (its measures are
  // still worth their JSON) and the exit code is 2.
  std::size_t unsaved = 0;
  const auto save = [&](const Mesh& mesh, const Model& m, const char* kind) {
    if(mesh_directory.empty())
      return;
    const std::string path = mesh_directory + "/" + m.file_stem + kind;
    try
    {
      bm::write_off_atomically(mesh, path);
    }
    catch(const std::exception& e)
    {
      ++unsaved;
      std::cerr << "remeshing_benchmark: " << e.what() << "\n";
    }
  };

  std::ostringstream json;
  json << "[\n";
  std::cout << std::left << std::setw(22) << "model" << std::setw(12) << "method" << std::right << std::setw(8) << "sec"
            << std::setw(8) << "verts" << std::setw(8) << "minang" << std::setw(8) << "%<25" << std::setw(8) << "skew"
            << std::setw(8) << "%edges" << std::setw(10) << "H to" << std::setw(10) << "H from" << std::setw(6) << "self" << "\n";
  std::size_t failures = 0;
  // The meshing stage of each model (medians over its runs: one run's times moved by 20% from
  // run to run on the 2-core machine), against its output size.
  struct Speed
  {
    std::string model;
    std::size_t vertices;
    double stage, planar, optimization, pull_back; // wall seconds, then thread seconds
    double peer_rate; // isotropic_remeshing's output vertices per wall second on the model (median run)
    CR::Meshing_phase_seconds phases; // each the median over the runs

    // `count` per second of a duration (0 for none measured: no infinity in the JSON)
    static double per_second(std::size_t count, double seconds) { return seconds > 0. ? double(count) / seconds : 0.; }
    // output vertices per second of a duration
    double rate(double seconds) const { return per_second(vertices, seconds); }
  };
  std::vector<Speed> speeds;
  std::vector<Peer_comparison> comparisons; // with --peers or --same-size
  // The phases of the planar meshing and of the optimization, visited in the third table's order.
  typedef double CR::Meshing_phase_seconds::*Phase;
  for(std::size_t k = 0; k < models.size(); ++k)
  {
    const Model& model = models[k];
    const Mesh& input = model.mesh;
    if(model.generated) // a generated input exists nowhere else
      save(input, model, "_input.off");
    Mesh ours;
    CR::Remeshing_report report;
    CR::Remeshing_statistics statistics;
    double ours_seconds = 0.;
    std::vector<double> stage_seconds, planar_seconds, optimization_seconds, pull_back_seconds; // per run
    std::vector<CR::Meshing_phase_seconds> phase_seconds;
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
    const double bound = surface_distance * relative
                         * std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                     + CGAL::square(box.zmax() - box.zmin()));
    try
    {
      ours_seconds = bm::median_seconds([&] {
        report = CR::remesh_conformal(input, ours,
                                      CR::parameters::statistics(std::ref(statistics), CR::parameters::maximum_surface_distance(bound, CR::parameters::lloyd_iterations(lloyd, CR::parameters::optimization_rounds(rounds, CR::parameters::relative_target_edge_length(relative))))));
        stage_seconds.push_back(statistics.seconds_meshing_stage);
        planar_seconds.push_back(statistics.seconds_planar_meshing);
        optimization_seconds.push_back(statistics.seconds_optimization);
        pull_back_seconds.push_back(statistics.seconds_pull_back);
        phase_seconds.push_back(statistics.meshing_phases);
      });
    }
    catch(const CR::Error& e)
    {
      // A model the remesher refuses is a result too: recorded, and the run goes on.
      ++failures;
      std::cout << std::left << std::setw(22) << model.name << std::setw(12) << "conformal" << "FAILED: " << e.what() << "\n";
      Conformal_remeshing_tools::Json_writer record; // escapes the message
      record.begin_object().field("model", model.name).field("failed", std::string(e.what())).end_object();
      std::string text = record.str();
      text.pop_back(); // its final newline
      json << (k ? ",\n" : "") << "  " << text;
      if(!mesh_directory.empty())
      {
        // No outputs for this model: an earlier run's must not pass for this one's.
        std::error_code ignored;
        std::filesystem::remove(mesh_directory + "/" + model.file_stem + "_conformal.off", ignored);
        std::filesystem::remove(mesh_directory + "/" + model.file_stem + "_isotropic.off", ignored);
      }
      continue;
    }
    save(ours, model, "_conformal.off");
    const double h = report.target_edge_length;
    Mesh peer;
    const double peer_seconds = bm::median_seconds([&] {
      peer = input;
      bm::run_isotropic_peer(peer, h);
    });
    save(peer, model, "_isotropic.off");
    const Measure a = measure(input, ours, h, ours_seconds), b = measure(input, peer, h, peer_seconds);
    print_row(model.name, "conformal", a);
    print_row("", "isotropic", b);
    std::cout << std::left << std::setw(22) << "" << std::setw(12) << "ratio" << std::right << std::setw(8)
              << std::setprecision(3) << a.seconds / b.seconds << std::setw(8) << "" << std::setw(8) << a.min_angle / b.min_angle
              << std::setw(8) << "" << std::setw(8) << a.skewness / b.skewness << std::setw(8) << "" << std::setw(10)
              << a.hausdorff_to / b.hausdorff_to << std::setw(10) << a.hausdorff_from / b.hausdorff_from << "\n";
    json << (k ? ",\n" : "") << "  {\"model\": " << json_string(model.name) << ", \"target_edge_length\": " << h
         << ", \"lloyd_iterations\": " << lloyd << ", \"optimization_rounds\": " << rounds
         << ", \"surface_distance\": " << surface_distance << ", \"surface_distance_refinements\": " << report.surface_distance_refinements
         << ", \"patches\": " << report.number_of_patches << ", \"stage_seconds\": {\"segmentation\": "
         << statistics.seconds_segmentation << ", \"flattening\": " << statistics.seconds_flattening
         << ", \"meshing_and_pull_back\": " << statistics.seconds_meshing_stage << ", \"gluing\": " << statistics.seconds_gluing
         << ", \"planar_meshing_thread_seconds\": " << statistics.seconds_planar_meshing
         << ", \"optimization_thread_seconds\": " << statistics.seconds_optimization
         << ", \"pull_back_thread_seconds\": " << statistics.seconds_pull_back << "}, \"conformal\": ";
    write_json(json, a);
    speeds.push_back(Speed{model.name, a.vertices, bm::median(stage_seconds), bm::median(planar_seconds),
                           bm::median(optimization_seconds), bm::median(pull_back_seconds),
                           Speed::per_second(b.vertices, b.seconds), CR::Meshing_phase_seconds()});
    Speed& speed = speeds.back();
    CR::Meshing_phase_seconds::for_each_phase([&](const char*, Phase phase) {
      std::vector<double> runs;
      for(const CR::Meshing_phase_seconds& run : phase_seconds)
        runs.push_back(run.*phase);
      speed.phases.*phase = bm::median(runs);
    });
    json << ", \"output_vertices_per_second\": {\"meshing_stage\": " << speed.rate(speed.stage)
         << ", \"planar_meshing_and_pull_back\": " << speed.rate(speed.planar + speed.pull_back)
         << ", \"isotropic_remeshing\": " << speed.peer_rate << "}";
    json << ", \"meshing_phase_thread_seconds\": {";
    const char* separator = "";
    CR::Meshing_phase_seconds::for_each_phase([&](const char* name, Phase phase) {
      json << separator << json_string(name) << ": " << speed.phases.*phase;
      separator = ", ";
    });
    json << "}";
    json << ", \"isotropic\": ";
    write_json(json, b);
    if(peer_options.requested())
    {
      comparisons.push_back(compare_with_peers(model.name, input, h, a, b, peer_options));
      json << ", \"peers\": ";
      write_peer_comparison(json, comparisons.back(), peer_options.same_size);
    }
    json << "}";
  }
  json << "\n]\n";
  std::cout << "(sec: median of 3 runs; %edges: edges within [0.7, 1.4] x target; H: Hausdorff distance to and from "
               "the input over its diagonal; ratio: conformal / isotropic)\n";
  std::cout << "\n" << std::left << std::setw(22) << "model" << std::right << std::setw(8) << "verts" << std::setw(9)
            << "stage" << std::setw(9) << "k/s" << std::setw(9) << "planar" << std::setw(9) << "optim" << std::setw(9)
            << "pull" << std::setw(12) << "k/s p+pull" << std::setw(9) << "iso k/s" << "\n";
  for(const Speed& speed : speeds)
    std::cout << std::left << std::setw(22) << speed.model << std::right << std::setprecision(3) << std::setw(8)
              << speed.vertices << std::setw(9) << speed.stage << std::setw(9) << 1e-3 * speed.rate(speed.stage)
              << std::setw(9) << speed.planar << std::setw(9) << speed.optimization << std::setw(9) << speed.pull_back
              << std::setw(12) << 1e-3 * speed.rate(speed.planar + speed.pull_back) << std::setw(9) << 1e-3 * speed.peer_rate
              << "\n";
  std::cout << "(meshing stage, medians of the 3 runs: stage = meshing, optimization and pull-back of all patches, wall seconds, "
               "and its thousands of output vertices per second; planar, optim, pull: thread seconds of the planar "
               "meshing, the optimization on the surface and the pull-back, summed over patches; k/s p+pull: output "
               "vertices per thread second of planar meshing and pull-back alone; iso k/s: isotropic_remeshing's thousands of "
               "output vertices per wall second on the model, to compare runs as the machine's pace drifts)\n";
  std::cout << "\n" << std::left << std::setw(22) << "model" << std::right;
  for(const char* column : {"p:setup", "p:refine", "p:smooth", "o:setup", "o:rounds", "o:splits", "o:collap", "o:skew", "o:angle"})
    std::cout << std::setw(9) << column;
  std::cout << "\n";
  for(const Speed& speed : speeds)
  {
    std::cout << std::left << std::setw(22) << speed.model << std::right << std::setprecision(3);
    CR::Meshing_phase_seconds::for_each_phase([&](const char*, Phase phase) { std::cout << std::setw(9) << speed.phases.*phase; });
    std::cout << "\n";
  }
  std::cout << "(where the planar meshing's thread seconds (p:) and the optimization's seconds (o:, as in optim) go, "
               "medians of the 3 runs, summed over patches: p: the set-up (point locator, kept input vertices, seeds) and output, the frontal "
               "insertion and CGAL's refinement, the smoothing in the plane with its refinement; o: the lifts and adjacency, the first rounds "
               "of flips and smoothing, the split passes with their rounds, the collapses with their round, the skewness "
               "passes, the angle passes)\n";
  if(peer_options.requested())
    print_peer_table(comparisons);
  if(!mesh_directory.empty())
    std::cout << "meshes: " << mesh_directory << "\n";
  try
  {
    tools::write_file_atomically(out_path, json.str());
  }
  catch(const std::exception& e)
  {
    std::cerr << "remeshing_benchmark: " << e.what() << "\n";
    return 2;
  }
  if(unsaved > 0)
  {
    std::cerr << "remeshing_benchmark: " << unsaved << " mesh(es) could not be saved in '" << mesh_directory << "'\n";
    return 2;
  }
  return failures == 0 ? 0 : 1;
}
