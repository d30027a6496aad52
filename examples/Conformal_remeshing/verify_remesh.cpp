// verify_remesh: checks that a remeshed file is a faithful remeshing of its input, independently
// of the program that made it: a valid manifold triangle mesh, no self-intersection, the input's
// topology, every vertex on the input surface (exact predicates where they decide).
//
// Exit codes: 0 when every check holds, 1 when one fails (the failed checks with their counts
// on one line of standard error), 2 when the tool cannot run (bad arguments, unreadable file,
// an input that cannot serve as a reference, output that cannot be written).

#include "atomic_file.h"
#include "report_json.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace CR = CGAL::Conformal_remeshing;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

const char* usage =
  "usage: verify_remesh IN OUT [--tolerance T] [--json FILE]\n"
  "  IN             the input mesh (.off, .obj, .ply or .stl): a manifold triangle mesh\n"
  "  OUT            its remeshing, checked against IN\n"
  "  --tolerance T  the largest distance allowed between an OUT vertex and the surface of IN,\n"
  "                 as a fraction of IN's bounding-box diagonal (default 1e-9)\n"
  "  --json FILE    write every check and count as JSON\n"
  "exit code: 0 every check holds, 1 a check fails, 2 the tool could not run\n";

void write_topology(tools::Json_writer& json, const std::string& name, const std::vector<CR::Component_topology>& components)
{
  json.key(name).begin_array();
  for(const CR::Component_topology& c : components)
    json.begin_object().field("genus", c.genus).field("boundary_loops", c.boundary_loops)
        .field("vertices", c.vertices).field("faces", c.faces).end_object();
  json.end_array();
}

std::string json_report(const std::string& input, const std::string& output, const CR::Remesh_verification& v)
{
  tools::Json_writer json;
  json.begin_object();
  json.field("input", input).field("output", output);
  json.field("valid", v.is_valid()).field("summary", v.summary());
  json.field("output_vertices", v.output_vertices).field("output_faces", v.output_faces);
  json.key("checks").begin_object();
  json.field("valid_triangle_mesh", v.valid_triangle_mesh).field("manifold", v.manifold);
  json.field("self_intersections_checked", v.self_intersections_checked)
      .field("self_intersecting_face_pairs", v.self_intersecting_face_pairs)
      .field("self_intersection_free", v.self_intersection_free);
  json.field("same_number_of_components", v.same_number_of_components).field("same_genera", v.same_genera)
      .field("same_boundary_loops", v.same_boundary_loops).field("topology_kept", v.topology_kept);
  json.field("on_input_surface", v.on_input_surface).field("vertices_off_surface", v.vertices_off_surface)
      .field("max_distance_to_input", v.max_distance_to_input)
      .field("relative_max_distance_to_input", v.input_diagonal > 0. ? v.max_distance_to_input / v.input_diagonal : 0.)
      .field("tolerance", v.tolerance).field("input_diagonal", v.input_diagonal);
  json.end_object();
  write_topology(json, "input_topology", v.input_components);
  write_topology(json, "output_topology", v.output_components);
  json.key("output_checks");
  tools::write_json(json, v.output_checks);
  json.end_object();
  return json.str();
}

} // namespace

int main(int argc, char** argv)
{
  std::string input, output, json, tolerance_text;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    bool ok = true;
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      return 0;
    }
    else if(arg == "--tolerance" || arg == "--json")
    {
      ok = i + 1 < argc;
      if(ok)
        (arg == "--json" ? json : tolerance_text) = argv[++i];
    }
    else if(!arg.empty() && arg[0] == '-')
      ok = false;
    else if(input.empty())
      input = arg;
    else if(output.empty())
      output = arg;
    else
      ok = false;
    if(!ok)
    {
      std::cerr << "verify_remesh: bad argument '" << arg << "'\n" << usage;
      return 2;
    }
  }
  if(input.empty() || output.empty())
  {
    std::cerr << "verify_remesh: needs IN and OUT\n" << usage;
    return 2;
  }
  double relative_tolerance = 1e-9;
  if(!tolerance_text.empty())
  {
    char* end = nullptr;
    relative_tolerance = std::strtod(tolerance_text.c_str(), &end);
    if(end != tolerance_text.c_str() + tolerance_text.size() || !std::isfinite(relative_tolerance) || relative_tolerance < 0.)
    {
      std::cerr << "verify_remesh: bad argument '--tolerance " << tolerance_text
                << "': a non-negative number is expected\n" << usage;
      return 2;
    }
  }

  try
  {
    Mesh in, out;
    const CR::Mesh_check_report in_checks = CR::read_and_check_mesh(input, in);
    if(!in_checks.topology_available)
    {
      std::cerr << "verify_remesh: cannot verify against '" << input << "': not a manifold polygon mesh ("
                << in_checks.summary() << ")\n";
      return 2;
    }
    const CR::Mesh_check_report out_checks = CR::read_and_check_mesh(output, out);

    CR::Remesh_verification v;
    if(out_checks.topology_available)
      v = CR::verify_remesh(in, out, CR::parameters::relative_distance_tolerance(relative_tolerance));
    else
    {
      // The file holds what no halfedge structure can: every check that needs one fails.
      v.output_checks = out_checks;
      v.output_vertices = out_checks.number_of_vertices;
      v.output_faces = out_checks.number_of_faces;
      v.input_components = in_checks.components;
      v.locations_match = true;
    }

    if(!json.empty())
    {
      tools::write_file_atomically(json, json_report(input, output, v));
    }
    if(!v.is_valid())
    {
      std::cerr << "verify_remesh: '" << output << "' against '" << input << "': " << v.summary() << "\n";
      return 1;
    }
    std::cout << "verify_remesh: '" << output << "' against '" << input << "': " << v.summary() << "\n";
    return 0;
  }
  catch(const std::exception& e)
  {
    // The library's messages already start with the function's name.
    const std::string message = e.what();
    std::cerr << (message.rfind("verify_remesh: ", 0) == 0 ? "" : "verify_remesh: ") << message << "\n";
    return 2;
  }
}
