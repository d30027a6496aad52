// mesh_report: the input checks, topology and quality of a mesh file, optionally compared with
// a reference mesh, as a readable summary, a JSON report and a Fig. 10-style SVG plot.
//
// Exit codes: 0 for a valid manifold triangle mesh, 1 for a mesh with defects (the reason on
// one line of standard error), 2 when the tool cannot run (bad arguments, unreadable file,
// output that cannot be written).

#include "atomic_file.h"
#include "quality_plot_svg.h"
#include "report_json.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iomanip>
#include <iostream>
#include <optional>
#include <string>

namespace CR = CGAL::Conformal_remeshing;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

const char* usage =
  "usage: mesh_report IN [--against REF] [--json FILE] [--svg FILE]\n"
  "  IN             a mesh file: .off, .obj, .ply or .stl (ASCII or binary)\n"
  "  --against REF  also compare IN with the reference mesh REF (Hausdorff distance both ways,\n"
  "                 area ratio, self-intersections of IN)\n"
  "  --json FILE    write the full report as JSON\n"
  "  --svg FILE     write the angle and skewness histograms (REF in blue, IN in orange)\n"
  "exit code: 0 valid triangle mesh, 1 mesh with defects, 2 the tool could not run\n";

struct Options
{
  std::string input, reference, json, svg;
};

// A mesh file with what the library says about it.
struct Analysed_mesh
{
  std::string path;
  Mesh mesh;
  CR::Mesh_check_report checks;
  std::optional<CR::Mesh_quality_report> quality;
};

Analysed_mesh analyse(const std::string& path)
{
  Analysed_mesh a;
  a.path = path;
  a.checks = CR::read_and_check_mesh(path, a.mesh);
  if(a.checks.topology_available && CGAL::is_triangle_mesh(a.mesh))
    a.quality = CR::mesh_quality(a.mesh);
  return a;
}

void print_checks(std::ostream& out, const Analysed_mesh& a)
{
  const CR::Mesh_check_report& r = a.checks;
  out << a.path << ": " << r.number_of_vertices << " vertices, " << r.number_of_faces << " faces\n";
  out << "  input checks: " << (r.is_valid() ? "valid manifold triangle mesh" : "DEFECTS FOUND") << "\n";
  for(const CR::Defect_summary& d : r.defects)
    out << "    " << d.count << " " << CR::defect_name(d.defect, d.count) << ", e.g. " << d.example << "\n";
  if(!r.topology_available)
  {
    out << "  topology: not available (the input is not a manifold, orientable polygon mesh)\n";
    return;
  }
  out << "  topology: " << r.components.size() << " component(s), total genus " << r.total_genus() << ", "
      << r.total_boundary_loops() << " boundary loop(s)\n";
  out << "    component   vertices      edges      faces  boundaries  euler  genus\n";
  for(std::size_t i = 0; i < r.components.size(); ++i)
  {
    const CR::Component_topology& c = r.components[i];
    out << "    " << std::setw(9) << i << std::setw(11) << c.vertices << std::setw(11) << c.edges << std::setw(11)
        << c.faces << std::setw(12) << c.boundary_loops << std::setw(7) << c.euler_characteristic << std::setw(7)
        << c.genus << "\n";
  }
}

void print_quality(std::ostream& out, const CR::Mesh_quality_report& q)
{
  out << std::setprecision(4);
  out << "  quality:\n";
  out << "    minimum angle     min " << q.minimum_angle.min << " deg, mean " << q.minimum_angle.mean << " deg\n";
  out << "    maximum angle     max " << q.maximum_angle.max << " deg, mean " << q.maximum_angle.mean << " deg\n";
  out << "    triangles with minimum angle below";
  for(std::size_t i = 0; i < q.angle_thresholds.size(); ++i)
    out << (i ? ", " : " ") << q.angle_thresholds[i] << " deg: " << 100. * q.share_below[i] << "%";
  out << "\n";
  out << "    equiangle skewness mean " << q.skewness.mean << ", max " << q.skewness.max << "\n";
  out << "    aspect ratio       mean " << q.aspect_ratio.mean << ", max " << q.aspect_ratio.max
      << " (" << q.number_of_degenerate_faces << " zero-area faces)\n";
  out << "    edge length        min " << q.edge_length.min << ", median " << q.median_edge_length << ", mean "
      << q.edge_length.mean << ", max " << q.edge_length.max << "\n";
  out << "    valence histogram ";
  for(std::size_t k = 0; k < q.valence_histogram.size(); ++k)
    if(q.valence_histogram[k] > 0)
      out << " " << k << ":" << q.valence_histogram[k];
  out << "\n";
}

void print_comparison(std::ostream& out, const std::string& reference, const CR::Reference_comparison& c)
{
  out << std::setprecision(4);
  out << "  against " << reference << " (bounding-box diagonal " << c.reference_diagonal << "):\n";
  out << "    Hausdorff distance to the reference   " << c.relative_distance_to_reference << " x diagonal\n";
  out << "    Hausdorff distance from the reference " << c.relative_distance_from_reference << " x diagonal\n";
  out << "    area ratio " << c.area_ratio << ", self-intersections: " << (c.self_intersects ? "YES" : "none") << "\n";
}

std::string json_report(const Analysed_mesh& input, const Analysed_mesh* reference,
                        const std::optional<CR::Reference_comparison>& comparison)
{
  tools::Json_writer json;
  json.begin_object();
  auto write_mesh = [&](const Analysed_mesh& a) {
    json.begin_object().field("file", a.path);
    json.key("checks");
    tools::write_json(json, a.checks);
    if(a.quality)
    {
      json.key("quality");
      tools::write_json(json, *a.quality);
    }
    json.end_object();
  };
  json.key("input");
  write_mesh(input);
  if(reference)
  {
    json.key("reference");
    write_mesh(*reference);
  }
  if(comparison)
  {
    json.key("comparison");
    tools::write_json(json, *comparison);
  }
  json.end_object();
  return json.str();
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& target) {
      if(i + 1 >= argc)
        return false;
      target = argv[++i];
      return true;
    };
    bool ok = true;
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      return 0;
    }
    else if(arg == "--against")
      ok = value(options.reference);
    else if(arg == "--json")
      ok = value(options.json);
    else if(arg == "--svg")
      ok = value(options.svg);
    else if(!arg.empty() && arg[0] == '-')
      ok = false;
    else if(options.input.empty())
      options.input = arg;
    else
      ok = false;
    if(!ok)
    {
      std::cerr << "mesh_report: bad argument '" << arg << "'\n" << usage;
      return 2;
    }
  }
  if(options.input.empty())
  {
    std::cerr << "mesh_report: no input file\n" << usage;
    return 2;
  }

  try
  {
    const Analysed_mesh input = analyse(options.input);
    print_checks(std::cout, input);
    if(input.quality)
      print_quality(std::cout, *input.quality);

    std::optional<Analysed_mesh> reference;
    std::optional<CR::Reference_comparison> comparison;
    if(!options.reference.empty())
    {
      reference = analyse(options.reference);
      std::cout << "reference ";
      print_checks(std::cout, *reference);
      if(!reference->checks.is_valid())
      {
        std::cerr << "mesh_report: invalid reference '" << options.reference << "': " << reference->checks.summary() << "\n";
        return 1;
      }
      if(input.quality)
      {
        comparison = CR::compare_to_reference(input.mesh, reference->mesh);
        print_comparison(std::cout, options.reference, *comparison);
      }
    }

    if(!options.json.empty())
    {
      tools::write_file_atomically(options.json, json_report(input, reference ? &*reference : nullptr, comparison));
      std::cout << "JSON report written to " << options.json << "\n";
    }
    if(!options.svg.empty())
    {
      if(!input.quality)
      {
        std::cerr << "mesh_report: no quality plot for '" << options.input
                  << "': it is not a triangle mesh that could be built (" << input.checks.summary() << ")\n";
        return 1;
      }
      std::vector<tools::Plot_series> series;
      if(reference && reference->quality)
        series.push_back({"reference: " + options.reference, *reference->quality});
      series.push_back({options.input, *input.quality});
      tools::write_file_atomically(options.svg, tools::quality_histograms_svg(series, "Mesh quality"));
      std::cout << "quality plot written to " << options.svg << "\n";
    }

    if(!input.checks.is_valid())
    {
      std::cerr << "mesh_report: invalid input '" << options.input << "': " << input.checks.summary() << "\n";
      return 1;
    }
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "mesh_report: " << e.what() << "\n";
    return 2;
  }
}
