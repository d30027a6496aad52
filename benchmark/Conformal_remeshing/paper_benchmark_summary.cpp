// paper_benchmark_summary: the tables of the paper benchmark (run_paper_benchmark.sh) from the
// records its runs left in DIR/runs/ (paper_benchmark run), beside the paper's Table 1.
//
//   paper_benchmark_summary DIR [--scale full|small]
//
// Writes DIR/summary.md (printed too), DIR/summary.json, and Fig. 10-style angle and skewness
// histograms: DIR/fig10_<model>.svg per part (input, remesh_conformal, each peer run) and
// DIR/fig10_all_parts.svg over the five parts together, like the paper's figure for the whole car.
// A run that did not finish is reported with its status, stage and error, never left out. The
// speed-up targets are checked at full scale only: Table 1's times are for its full sizes.
// Exit code: 0 when the summary was written (whatever the runs' outcome), 2 when it could not be.

#include "atomic_file.h"
#include "json_writer.h"
#include "paper_benchmark_plan.h"
#include "power_law_fit.h"
#include "quality_plot_svg.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace tools = Conformal_remeshing_tools;
typedef boost::property_tree::ptree Tree;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// What a missing child reads as (get_child() returns a reference to its default).
const Tree& no_child()
{
  static const Tree empty;
  return empty;
}

// One run's record (runs/<id>.json), as far as the run went, and its exit code (runs/<id>.exit,
// written by the script) when it has one.
struct Run
{
  const bm::Planned_run* plan = nullptr;
  bool present = false;
  Tree json;
  std::string exit_code;

  std::string text(const std::string& path) const { return json.get<std::string>(path, ""); }

  // NaN when missing or null (a non-finite number is written as null).
  double number(const std::string& path) const
  {
    const std::string t = text(path);
    if(t.empty() || t == "null")
      return nan;
    try
    {
      return std::stod(t);
    }
    catch(const std::exception&)
    {
      return nan;
    }
  }

  bool completed() const { return present && text("method_completed") == "true"; }
  bool measured() const { return present && text("status") == "ok"; }

  // A stage's figure: its seconds summed, its peak the largest, over the times it started (the
  // meshing stage starts again for each round of the surface-distance bound).
  double stage(const std::string& name, const std::string& field) const
  {
    if(!present)
      return nan;
    double value = nan;
    for(const auto& s : json.get_child("stages", no_child()))
      if(s.second.get<std::string>("name", "") == name)
      {
        const double x = s.second.get<double>(field, nan);
        value = std::isnan(value) ? x : field == "seconds" ? value + x : (std::max)(value, x);
      }
    return value;
  }

  // The process's peak resident MB up to the end of the method: the largest of the recorded peak
  // and the stages' (records written before paper_benchmark kept the stages' peaks across its
  // resets of the high-water mark hold a smaller "peak_mb", the last stages' peak).
  double process_peak_megabytes() const
  {
    if(!present)
      return nan;
    double peak = number("peak_mb");
    for(const auto& s : json.get_child("stages", no_child()))
    {
      const double stage_peak = s.second.get<double>("peak_mb", nan);
      if(!std::isnan(stage_peak) && !(stage_peak <= peak))
        peak = stage_peak;
    }
    return peak;
  }

  // What became of a run that did not finish (empty for one that did).
  std::string failure() const
  {
    if(!present)
      return "not run";
    if(measured())
      return std::string();
    const std::string status = text("status"), error = text("error"), stage = text("stage_at_exit");
    std::string why;
    if(status == "time_limit" || status == "failed")
      why = status == "failed" ? "failed: " + error : error;
    else
      why = "process ended during " + (stage.empty() ? std::string("start-up") : stage)
            + (exit_code.empty() ? std::string() : " (exit status " + exit_code + ")");
    return why;
  }

  // Table 1's two steps, from the library's report (wall seconds): parameterization =
  // segmentation + flattening (welding, Ricci flow, layout, check); remeshing = planar meshing
  // and pull-back + gluing.
  double parameterization_seconds() const
  {
    return number("library_seconds.segmentation") + number("library_seconds.flattening");
  }
  double remeshing_seconds() const { return number("library_seconds.meshing_stage") + number("library_seconds.gluing"); }
};

std::map<std::string, Run> load_runs(const std::string& directory, const std::vector<bm::Planned_run>& plan)
{
  std::map<std::string, Run> runs;
  for(const bm::Planned_run& p : plan)
  {
    Run& r = runs[p.id];
    r.plan = &p;
    const std::string path = directory + "/runs/" + p.id + ".json";
    if(std::ifstream(path))
    {
      try
      {
        boost::property_tree::read_json(path, r.json);
        r.present = true;
      }
      catch(const std::exception& e)
      {
        std::cerr << "paper_benchmark_summary: cannot read " << path << ": " << e.what() << " (counted as not run)\n";
      }
    }
    std::ifstream exit_file(directory + "/runs/" + p.id + ".exit");
    exit_file >> r.exit_code;
  }
  return runs;
}

// The remeshers of Table 1's runs with the names the tables and figures give them: ours, then the
// peers, CGAL's first.
struct Peer_name
{
  std::string method, label;
};

const std::vector<Peer_name>& remeshers()
{
  static const std::vector<Peer_name> names{
    {"conformal", "remesh_conformal"}, {"isotropic", "isotropic_remeshing"}, {"gmsh", "Gmsh"}, {"meshlab", "MeshLab"}};
  return names;
}

// The peers outside CGAL, whose runs are listed only where they were asked for.
std::vector<Peer_name> external_peers() { return {remeshers()[2], remeshers()[3]}; }

// --- formatting --------------------------------------------------------------------------------

// Three significant digits at most, no exponent for the magnitudes of these tables.
std::string fmt(double x, int decimals = -1)
{
  if(!std::isfinite(x))
    return "–";
  char buffer[64];
  if(decimals < 0)
    decimals = std::abs(x) >= 100. ? 0 : std::abs(x) >= 10. ? 1 : std::abs(x) >= 1. ? 2 : 3;
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, x);
  return buffer;
}

std::string fmt_count(double x)
{
  if(!std::isfinite(x))
    return "–";
  if(x >= 1e6)
    return fmt(x / 1e6, 2) + "M";
  if(x >= 1e4)
    return fmt(x / 1e3, 0) + "k";
  if(x >= 1e3)
    return fmt(x / 1e3, 1) + "k";
  return fmt(x, 0);
}

std::string fmt_scientific(double x)
{
  if(!std::isfinite(x))
    return "–";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2e", x);
  return buffer;
}

std::string fmt_percent(double share) { return std::isfinite(share) ? fmt(100. * share, 2) + "%" : "–"; }

std::string model_name(const bm::Planned_run& p) { return bm::paper_model_info(p.model).name; }

// --- Fig. 10 -----------------------------------------------------------------------------------

CR::Histogram histogram_of(const Tree& t)
{
  CR::Histogram h;
  h.lower = t.get<double>("lower", 0.);
  h.bin_width = t.get<double>("bin_width", 1.);
  for(const auto& c : t.get_child("counts", no_child()))
    h.counts.push_back(c.second.get_value<std::size_t>());
  return h;
}

// Adds the histograms of `quality` (a mesh_quality JSON object) to `sum`.
void accumulate(CR::Mesh_quality_report& sum, const Tree& quality)
{
  auto add = [](CR::Histogram& total, const CR::Histogram& h) {
    if(total.counts.size() != h.counts.size())
      total = CR::Histogram(h.lower, h.lower + h.bin_width * double(h.counts.size()), h.counts.size());
    for(std::size_t i = 0; i < h.counts.size(); ++i)
      total.counts[i] += h.counts[i];
  };
  add(sum.angle_histogram, histogram_of(quality.get_child("angle_histogram", Tree())));
  add(sum.skewness_histogram, histogram_of(quality.get_child("skewness_histogram", Tree())));
}

struct Summary
{
  std::string directory;
  bm::Benchmark_scale scale;
  std::vector<bm::Planned_run> plan;
  std::map<std::string, Run> runs;
  std::ostringstream md;
  tools::Json_writer json;
  std::vector<std::string> targets_md;

  const Run& run(const std::string& id) const { return runs.at(id); }

  const Run* any_run() const
  {
    for(const auto& r : runs)
      if(r.second.present)
        return &r.second;
    return nullptr;
  }

  void target(const std::string& what, bool checked, bool met, const std::string& detail)
  {
    targets_md.push_back("- " + what + ": **" + (checked ? (met ? "met" : "missed") : "not checked") + "** — " + detail);
    json.begin_object().field("target", what).field("checked", checked).field("met", checked && met)
        .field("detail", detail).end_object();
  }

  void header()
  {
    const Run* r = any_run();
    md << "# Paper benchmark: Table 1 and Fig. 10 (" << bm::benchmark_scale_name(scale) << " scale)\n\n";
    if(r != nullptr)
      md << "Measured " << r->text("machine.date") << " on " << r->text("machine.cores") << " cores ("
         << r->text("machine.cpu") << ", " << fmt(r->number("machine.memory_mb") / 1024., 0)
         << " GB), load average at the start of a run " << r->text("machine.load_average_at_start") << ".\n\n";
    if(scale == bm::Benchmark_scale::small)
      md << "Small scale: inputs and outputs a tenth of Table 1's; the paper's columns are its full-size "
            "figures, for reference only.\n\n";
  }

  void table_1()
  {
    md << "## Table 1\n\n"
          "Param. = segmentation + flattening (welding, Ricci flow, layout, embedding check); Remesh = "
          "planar meshing and pull-back + gluing; wall seconds. Sizes as paper / ours (our output: "
          "remesh_conformal / isotropic_remeshing at the same target edge length, chosen for the "
          "paper's output size).\n\n"
          "| part (Fig.) | model | input V | input F | output V | output F | Param. s paper / ours | speed-up "
          "| Remesh s paper / ours | speed-up | peak MB ours / peer | status |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    json.key("table_1").begin_array();
    for(const bm::Paper_table_1_row& row : bm::paper_table_1())
    {
      const std::string name = bm::paper_model_info(row.model).name;
      const Run &ours = run("table_" + name + "_conformal"), &peer = run("table_" + name + "_isotropic");
      const double param = ours.parameterization_seconds(), remesh = ours.remeshing_seconds();
      const bool full = scale == bm::Benchmark_scale::full;
      const std::string status = ours.failure().empty() && peer.failure().empty()
                                 ? "ok"
                                 : "ours: " + (ours.failure().empty() ? "ok" : ours.failure()) + "; peer: "
                                     + (peer.failure().empty() ? "ok" : peer.failure());
      md << "| " << row.part << " (" << row.figure << ") | " << name << " | " << fmt_count(double(row.input_vertices))
         << " / " << fmt_count(ours.number("input.vertices")) << " | " << fmt_count(double(row.input_faces)) << " / "
         << fmt_count(ours.number("input.faces")) << " | " << fmt_count(double(row.output_vertices)) << " / "
         << fmt_count(ours.number("output.vertices")) << " / " << fmt_count(peer.number("output.vertices")) << " | "
         << fmt_count(double(row.output_faces)) << " / " << fmt_count(ours.number("output.faces")) << " / "
         << fmt_count(peer.number("output.faces")) << " | " << fmt(row.parameterization_seconds) << " / " << fmt(param)
         << " | " << (full ? fmt(row.parameterization_seconds / param, 1) + "x" : "–") << " | "
         << fmt(row.remeshing_seconds) << " / " << fmt(remesh) << " | "
         << (full ? fmt(row.remeshing_seconds / remesh, 1) + "x" : "–") << " | " << fmt(ours.process_peak_megabytes(), 0)
         << " / " << fmt(peer.process_peak_megabytes(), 0) << " | " << status << " |\n";
      json.begin_object().field("part", row.part).field("figure", row.figure).field("model", name);
      json.key("paper").begin_object().field("input_vertices", row.input_vertices).field("input_faces", row.input_faces)
          .field("output_vertices", row.output_vertices).field("output_faces", row.output_faces)
          .field("parameterization_seconds", row.parameterization_seconds)
          .field("remeshing_seconds", row.remeshing_seconds).end_object();
      json.key("ours").begin_object().field("status", ours.failure().empty() ? std::string("ok") : ours.failure())
          .field("input_vertices", ours.number("input.vertices")).field("input_faces", ours.number("input.faces"))
          .field("output_vertices", ours.number("output.vertices")).field("output_faces", ours.number("output.faces"))
          .field("target_edge_length", ours.number("target_edge_length"))
          .field("parameterization_seconds", param).field("remeshing_seconds", remesh)
          .field("total_seconds", ours.number("method_seconds")).field("peak_mb", ours.process_peak_megabytes());
      if(full)
        json.field("parameterization_speed_up", row.parameterization_seconds / param)
            .field("remeshing_speed_up", row.remeshing_seconds / remesh);
      json.end_object();
      json.key("peer").begin_object().field("status", peer.failure().empty() ? std::string("ok") : peer.failure())
          .field("output_vertices", peer.number("output.vertices")).field("output_faces", peer.number("output.faces"))
          .field("total_seconds", peer.number("method_seconds")).field("peak_mb", peer.process_peak_megabytes()).end_object();
      json.end_object();
    }
    json.end_array();
    md << "\n";
  }

  void stages()
  {
    md << "## Stages of remesh_conformal\n\n"
          "Wall seconds; * marks thread seconds summed over the patches (they run 2 at a time); "
          "peak MB is the resident high-water mark during the stage.\n\n"
          "| model | read + checks | segmentation | flattening | welding* | Ricci flow* | layout* | check* "
          "| Newton it. max / sum | flips | patches (cuts) | meshing | planar meshing* | pull-back* | gluing "
          "| total | peak MB: seg. / flat. / mesh. / glue |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for(const bm::Planned_run& p : plan)
      if(p.method == "conformal")
        stage_row(p.part == "table" ? model_name(p) : model_name(p) + " " + fmt_count(double(p.input_vertices)), run(p.id));
    md << "\n";
  }

  void stage_row(const std::string& label, const Run& r)
  {
    md << "| " << label << " | " << fmt(r.stage("read_and_check", "seconds")) << " | "
       << fmt(r.number("library_seconds.segmentation")) << " | " << fmt(r.number("library_seconds.flattening")) << " | "
       << fmt(r.number("library_seconds.welding_thread_seconds")) << " | "
       << fmt(r.number("library_seconds.ricci_flow_thread_seconds")) << " | "
       << fmt(r.number("library_seconds.layout_thread_seconds")) << " | "
       << fmt(r.number("library_seconds.embedding_check_thread_seconds")) << " | "
       << fmt(r.number("flattening.newton_iterations_max"), 0) << " / "
       << fmt(r.number("flattening.newton_iterations_total"), 0) << " | " << fmt_count(r.number("flattening.flips"))
       << " | " << fmt(r.number("segmentation.patches"), 0) << " (" << fmt(r.number("segmentation.plane_cuts"), 0) << ") | "
       << fmt(r.number("library_seconds.meshing_stage")) << " | "
       << fmt(r.number("library_seconds.planar_meshing_thread_seconds")) << " | "
       << fmt(r.number("library_seconds.pull_back_thread_seconds")) << " | " << fmt(r.number("library_seconds.gluing"))
       << " | " << fmt(r.number("method_seconds")) << " | " << fmt(r.stage("segmentation", "peak_mb"), 0) << " / "
       << fmt(r.stage("flattening", "peak_mb"), 0) << " / " << fmt(r.stage("meshing", "peak_mb"), 0) << " / "
       << fmt(r.stage("gluing", "peak_mb"), 0);
    if(!r.failure().empty())
      md << " (" << r.failure() << ")";
    md << " |\n";
  }

  void quality()
  {
    md << "## Quality and fidelity against the peers (Fig. 10)\n\n"
          "Min angle: smallest angle of the mesh; < 30°: share of triangles whose smallest angle is below "
          "30 degrees; skewness: mean equiangle skewness; near h: share of edges within [0.7, 1.4] x the "
          "target; Hausdorff distances to and from the input over its bounding-box diagonal; self-int.: "
          "self-intersections (exact predicates). Ratio: conformal / isotropic. Gmsh and MeshLab appear "
          "where their runs were asked for (`--methods`).\n\n"
          "| model | mesh | seconds | vertices | min angle | < 30° | skewness | near h | H to input | H from input "
          "| self-int. |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    json.key("quality").begin_array();
    CR::Mesh_quality_report all_input, all_ours;
    std::map<std::string, CR::Mesh_quality_report> all_peers;
    bool all_complete = true;
    for(const bm::Paper_table_1_row& row : bm::paper_table_1())
    {
      const std::string name = bm::paper_model_info(row.model).name;
      const Run &ours = run("table_" + name + "_conformal"), &peer = run("table_" + name + "_isotropic");
      const Run& input = ours.measured() ? ours : peer;
      auto line = [&](const std::string& mesh, const Run& r, const std::string& prefix, bool with_method) {
        md << "| " << (mesh == "input" ? name : std::string()) << " | " << mesh << " | "
           << (with_method ? fmt(r.number("method_seconds")) : std::string()) << " | "
           << fmt_count(r.number(prefix + ".vertices")) << " | " << fmt(r.number(prefix + ".minimum_angle.min"), 2)
           << " | " << fmt_percent(r.number(prefix + ".share_with_minimum_angle_below.30")) << " | "
           << fmt(r.number(prefix + ".equiangle_skewness.mean"), 3) << " | ";
        if(with_method)
          md << fmt_percent(r.number("share_of_edges_within_0_7_and_1_4_target")) << " | "
             << fmt_scientific(r.number("fidelity.relative_hausdorff_to_reference")) << " | "
             << fmt_scientific(r.number("fidelity.relative_hausdorff_from_reference")) << " | "
             << (r.measured() ? (r.text("fidelity.self_intersects") == "true" ? "yes" : "no") : "–");
        else
          md << " | | | ";
        if(with_method && !r.failure().empty())
          md << " (" << r.failure() << ")";
        md << " |\n";
      };
      line("input", input, "input_quality", false);
      line("conformal", ours, "output_quality", true);
      line("isotropic", peer, "output_quality", true);
      for(const Peer_name& p : external_peers())
        if(run("table_" + name + "_" + p.method).present)
          line(p.method, run("table_" + name + "_" + p.method), "output_quality", true);
      auto ratio = [&](const std::string& path) { return ours.number(path) / peer.number(path); };
      md << "| | ratio | " << fmt(ratio("method_seconds")) << " | | " << fmt(ratio("output_quality.minimum_angle.min"))
         << " | " << fmt(ratio("output_quality.share_with_minimum_angle_below.30")) << " | "
         << fmt(ratio("output_quality.equiangle_skewness.mean")) << " | | "
         << fmt(ratio("fidelity.relative_hausdorff_to_reference")) << " | "
         << fmt(ratio("fidelity.relative_hausdorff_from_reference")) << " | |\n";

      json.begin_object().field("model", name);
      auto quality_json = [&](const std::string& key, const Run& r, const std::string& prefix, bool with_method) {
        json.key(key).begin_object().field("vertices", r.number(prefix + ".vertices"))
            .field("min_angle", r.number(prefix + ".minimum_angle.min"))
            .field("share_min_angle_below_30", r.number(prefix + ".share_with_minimum_angle_below.30"))
            .field("mean_skewness", r.number(prefix + ".equiangle_skewness.mean"));
        if(with_method)
          json.field("seconds", r.number("method_seconds"))
              .field("share_of_edges_near_target", r.number("share_of_edges_within_0_7_and_1_4_target"))
              .field("relative_hausdorff_to_input", r.number("fidelity.relative_hausdorff_to_reference"))
              .field("relative_hausdorff_from_input", r.number("fidelity.relative_hausdorff_from_reference"))
              .field("self_intersects", r.measured() ? r.text("fidelity.self_intersects") : std::string("unknown"));
        json.end_object();
      };
      quality_json("input", input, "input_quality", false);
      quality_json("conformal", ours, "output_quality", true);
      quality_json("isotropic", peer, "output_quality", true);
      for(const Peer_name& p : external_peers())
        if(run("table_" + name + "_" + p.method).present)
          quality_json(p.method, run("table_" + name + "_" + p.method), "output_quality", true);
      json.end_object();

      // Fig. 10 for this part, and the sums over the parts for the whole "car".
      if(!input.measured())
      {
        all_complete = false;
        continue;
      }
      std::vector<tools::Plot_series> series;
      CR::Mesh_quality_report q;
      accumulate(q, input.json.get_child("input_quality"));
      accumulate(all_input, input.json.get_child("input_quality"));
      series.push_back({"original: " + name + " (" + fmt_count(input.number("input.vertices")) + " vertices)", q});
      for(const Peer_name& p : remeshers())
      {
        const Run& r = run("table_" + name + "_" + p.method);
        if(!r.measured())
        {
          all_complete = all_complete && !r.present && p.method != "conformal" && p.method != "isotropic";
          continue;
        }
        CR::Mesh_quality_report o;
        accumulate(o, r.json.get_child("output_quality"));
        accumulate(p.method == "conformal" ? all_ours : all_peers[p.label], r.json.get_child("output_quality"));
        series.push_back({p.label + " (" + fmt_count(r.number("output.vertices")) + " vertices)", o});
      }
      tools::write_file_atomically(directory + "/fig10_" + name + ".svg",
                                   tools::quality_histograms_svg(series, "Mesh quality of " + name + " before and after remeshing"));
    }
    json.end_array();
    if(!all_input.angle_histogram.counts.empty())
    {
      std::vector<tools::Plot_series> all = {{"original (the five parts)", all_input}, {"remesh_conformal", all_ours}};
      for(const Peer_name& p : remeshers())
        if(all_peers.count(p.label))
          all.push_back({p.label, all_peers[p.label]});
      tools::write_file_atomically(directory + "/fig10_all_parts.svg",
                                   tools::quality_histograms_svg(all, std::string("Mesh quality of the five parts before and after remeshing")
                                                                        + (all_complete ? "" : " (runs that did not finish left out)")));
    }
    md << "\nHistograms: `fig10_<model>.svg` per part, `fig10_all_parts.svg` over the five parts (the "
          "original first, then remesh_conformal and each peer, in the order of the table).\n\n";
  }

  // Time and peak memory of every stage against the input size, with the fitted exponents.
  void scaling()
  {
    const std::vector<std::string> stage_names = {"read_and_check", "segmentation", "flattening", "meshing", "gluing",
                                                  "surface_distance"};
    md << "## Growth with the input size (" << bm::paper_model_info(bm::scaling_model).name << ")\n\n"
          "Wall seconds and peak resident MB of every stage; exponent k of the least-squares fit "
          "y = c n^k on log-log over the runs that finished (n log n gives the exponent in the last column "
          "on these sizes).\n\n"
          "| input V | output V | read + checks s | segmentation s | flattening s | meshing s | gluing s | "
          "surface distance s | total s | peak MB: read / seg. / flat. / mesh. / glue / dist. | process peak MB | status |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<double> n;
    std::map<std::string, std::vector<double> > seconds, peaks;
    json.key("scaling").begin_object().field("model", bm::paper_model_info(bm::scaling_model).name);
    json.key("runs").begin_array();
    for(const bm::Planned_run& p : plan)
    {
      if(p.part != "scaling")
        continue;
      const Run& r = run(p.id);
      const bool ok = r.completed();
      n.push_back(r.number("input.vertices"));
      md << "| " << fmt_count(r.number("input.vertices")) << " | " << fmt_count(r.number("output.vertices"));
      json.begin_object().field("input_vertices", r.number("input.vertices"))
          .field("output_vertices", r.number("output.vertices"))
          .field("status", r.failure().empty() ? std::string("ok") : r.failure());
      json.key("stage_seconds").begin_object();
      for(const std::string& s : stage_names)
      {
        const double t = ok ? r.stage(s, "seconds") : nan;
        seconds[s].push_back(t);
        md << " | " << fmt(t);
        json.field(s, t);
      }
      const double total = ok ? r.number("method_seconds") : nan;
      seconds["total"].push_back(total);
      md << " | " << fmt(total) << " | ";
      json.end_object().field("total_seconds", total).key("stage_peak_mb").begin_object();
      for(const std::string& s : stage_names)
      {
        const double m = ok ? r.stage(s, "peak_mb") : nan;
        peaks[s].push_back(m);
        md << (s == stage_names.front() ? "" : " / ") << fmt(m, 0);
        json.field(s, m);
      }
      const double peak = ok ? r.process_peak_megabytes() : nan;
      peaks["total"].push_back(peak);
      json.end_object().field("peak_mb", peak).end_object();
      md << " | " << fmt(peak, 0) << " | " << (r.failure().empty() ? std::string("ok") : r.failure()) << " |\n";
    }
    json.end_array();
    const double reference = bm::n_log_n_exponent(n);
    md << "| **exponent** | | ";
    json.key("time_exponents").begin_object();
    std::string worst_stage;
    double worst = -std::numeric_limits<double>::infinity();
    std::size_t fitted = 0;
    for(const std::string& s : stage_names)
    {
      const bm::Power_law_fit fit = bm::fit_power_law(n, seconds[s]);
      md << (fit.is_valid() ? fmt(fit.exponent, 2) : std::string("–")) << " | ";
      json.field(s, fit.is_valid() ? fit.exponent : nan);
      // The reading and checks are the input's, not the method's; the gluing is too quick to time at 10k.
      if(fit.is_valid() && fit.points >= 3 && s != "read_and_check")
      {
        ++fitted;
        if(fit.exponent > worst)
        {
          worst = fit.exponent;
          worst_stage = s;
        }
      }
    }
    const bm::Power_law_fit total_fit = bm::fit_power_law(n, seconds["total"]);
    json.field("total", total_fit.is_valid() ? total_fit.exponent : nan).end_object();
    md << (total_fit.is_valid() ? fmt(total_fit.exponent, 2) : std::string("–")) << " | ";
    json.key("peak_memory_exponents").begin_object();
    for(const std::string& s : stage_names)
    {
      const bm::Power_law_fit fit = bm::fit_power_law(n, peaks[s]);
      md << (s == stage_names.front() ? "" : " / ") << (fit.is_valid() ? fmt(fit.exponent, 2) : std::string("–"));
      json.field(s, fit.is_valid() ? fit.exponent : nan);
    }
    const bm::Power_law_fit peak_fit = bm::fit_power_law(n, peaks["total"]);
    json.field("total", peak_fit.is_valid() ? peak_fit.exponent : nan).end_object();
    json.field("n_log_n_exponent", reference).end_object();
    md << " | " << (peak_fit.is_valid() ? fmt(peak_fit.exponent, 2) : std::string("–")) << " | n log n: "
       << fmt(reference, 2) << " |\n\n";
    growth_ = {fitted > 0, worst <= reference + growth_tolerance,
               fitted > 0 ? "steepest stage " + worst_stage + ": exponent " + fmt(worst, 2) + " against " + fmt(reference, 2)
                              + " for n log n (met within " + fmt(growth_tolerance, 2) + ")"
                          : std::string("fewer than 3 sizes finished")};
  }

  void targets()
  {
    const bool full = scale == bm::Benchmark_scale::full;
    json.key("targets").begin_array();
    std::string why_not = full ? std::string() : "Table 1's figures are for the full sizes: rerun with --scale full";
    for(const bm::Paper_table_1_row& row : bm::paper_table_1())
    {
      const std::string name = bm::paper_model_info(row.model).name;
      const Run& ours = run("table_" + name + "_conformal");
      const double param = ours.parameterization_seconds(), remesh = ours.remeshing_seconds();
      const double param_target = row.parameterization_seconds / bm::paper_speed_up_target;
      const double remesh_target = row.remeshing_seconds / bm::paper_speed_up_target;
      const bool done = ours.completed();
      target("parameterization of " + name + " (" + fmt_count(double(row.input_vertices)) + ") under " + fmt(param_target)
               + " s (20x Table 1)",
             full, done && param <= param_target,
             !full ? why_not : done ? fmt(param) + " s, " + fmt(row.parameterization_seconds / param, 1) + "x" : ours.failure());
      target("remeshing of " + name + " under " + fmt(remesh_target) + " s (20x Table 1)", full, done && remesh <= remesh_target,
             !full ? why_not : done ? fmt(remesh) + " s, " + fmt(row.remeshing_seconds / remesh, 1) + "x" : ours.failure());
    }
    const bm::Paper_table_1_row& largest = bm::paper_table_1().back();
    const Run& big = run("table_" + std::string(bm::paper_model_info(largest.model).name) + "_conformal");
    target("peak memory under 8 GB at " + fmt_count(double(largest.input_vertices)), full,
           big.completed() && big.process_peak_megabytes() < bm::peak_memory_target_megabytes,
           !full ? why_not : big.completed() ? fmt(big.process_peak_megabytes(), 0) + " MB" : big.failure());
    target("growth close to n log n in every stage", growth_.checked, growth_.met, growth_.detail);
    for(const bm::Paper_table_1_row& row : bm::paper_table_1())
    {
      const std::string name = bm::paper_model_info(row.model).name;
      const Run &ours = run("table_" + name + "_conformal"), &peer = run("table_" + name + "_isotropic");
      const bool both = ours.measured() && peer.measured();
      const double a = ours.number("output_quality.minimum_angle.min"), b = peer.number("output_quality.minimum_angle.min");
      const double sa = ours.number("output_quality.share_with_minimum_angle_below.30"),
                   sb = peer.number("output_quality.share_with_minimum_angle_below.30");
      const double ka = ours.number("output_quality.equiangle_skewness.mean"),
                   kb = peer.number("output_quality.equiangle_skewness.mean");
      target("quality of " + name + " at least the peer's, better on min angle and share below 30 degrees", both,
             a > b && sa < sb && ka <= kb,
             both ? "min angle " + fmt(a, 2) + " vs " + fmt(b, 2) + ", below 30° " + fmt_percent(sa) + " vs " + fmt_percent(sb)
                      + ", mean skewness " + fmt(ka, 3) + " vs " + fmt(kb, 3)
                  : "ours: " + (ours.failure().empty() ? std::string("ok") : ours.failure()) + "; peer: "
                      + (peer.failure().empty() ? std::string("ok") : peer.failure()));
    }
    json.end_array();
    md << "## Targets: speed, memory, growth and quality\n\n";
    for(const std::string& t : targets_md)
      md << t << "\n";
  }

  struct Growth
  {
    bool checked = false, met = false;
    std::string detail;
  } growth_;
  static constexpr double growth_tolerance = 0.15;
};

} // namespace

int main(int argc, char** argv)
{
  try
  {
    Summary s;
    s.scale = bm::Benchmark_scale::full;
    for(int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if(arg == "--scale" && i + 1 < argc)
        s.scale = bm::benchmark_scale_from_name(argv[++i]);
      else if(!arg.empty() && arg[0] != '-' && s.directory.empty())
        s.directory = arg;
      else
        throw std::invalid_argument("bad argument '" + arg + "'");
    }
    if(s.directory.empty())
      throw std::invalid_argument("usage: paper_benchmark_summary DIR [--scale full|small]");
    s.plan = bm::paper_benchmark_plan(s.scale);
    s.runs = load_runs(s.directory, s.plan);
    s.json.begin_object().field("scale", std::string(bm::benchmark_scale_name(s.scale)));
    if(const Run* r = s.any_run())
      s.json.field("date", r->text("machine.date")).field("cores", r->number("machine.cores")).field("cpu", r->text("machine.cpu"));
    s.header();
    s.table_1();
    s.stages();
    s.quality();
    s.scaling();
    s.targets();
    s.json.end_object();
    tools::write_file_atomically(s.directory + "/summary.md", s.md.str());
    tools::write_file_atomically(s.directory + "/summary.json", s.json.str());
    std::cout << s.md.str();
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "paper_benchmark_summary: " << e.what() << "\n";
    return 2;
  }
}
