// generate_paper_model: writes one of the CAD-like parts at the scales of the paper's Table 1
// (see generators/paper_models.h).
//
//   generate_paper_model MODEL VERTICES OUT.off [--seed S] [--check]
//
// The file is written to OUT.tmp first and renamed, so a reader never sees a half-written model.

#include <model_tool.h>
#include <paper_models.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
namespace PMP = CGAL::Polygon_mesh_processing;

void print_help(std::ostream& out)
{
  out << "Usage: generate_paper_model MODEL VERTICES OUT.off [--seed S] [--check]\n"
         "Writes a deterministic CAD-like part of about VERTICES vertices (an integer, optionally\n"
         "with a k or M suffix: 87k, 1M) as OFF with 17 significant digits, and prints one summary\n"
         "line: vertices, faces, genus, boundary loops, minimum angle, share of triangles with\n"
         "minimum angle below 10 and 1 degrees, generation time.\n\n"
         "  --seed S   seed of the random details (hole sizes and positions) [1]\n"
         "  --check    also check the model: valid, closed or open as expected, one component of\n"
         "             the expected genus and boundary loops, no degenerate triangle, outward\n"
         "             oriented (closed ones), no self-intersection (slow: 10 s at 100k vertices,\n"
         "             20 min at 800k); exit code 1 if a check fails\n\n"
         "Models (paper's Table 1 size; topology):\n";
  for(const bm::Paper_model_info& m : bm::paper_models()) {
    out << "  " << m.name << std::string(23 - std::string(m.name).size(), ' ');
    if(m.paper_vertices > 0)
      out << m.paper_vertices / 1000 << "k; ";
    out << (m.closed ? "closed" : "open") << ", genus " << m.genus;
    if(!m.closed)
      out << ", " << m.boundary_loops << " boundary loops";
    out << "\n      " << m.description << "\n";
  }
}

std::size_t parse_vertices(const std::string& text)
{
  std::string digits = text;
  long long factor = 1;
  if(!digits.empty() && (digits.back() == 'k' || digits.back() == 'M')) {
    factor = digits.back() == 'k' ? 1000 : 1000000;
    digits.pop_back();
  }
  const long long value = bm::parse_integer("VERTICES", digits);
  if(value <= 0 || value > 100000000 / factor)
    throw std::invalid_argument("VERTICES: must be in [1, 10^8]: '" + text + "'");
  return std::size_t(value * factor);
}

// Prints the checks of --check; returns whether all passed.
bool check_model(const Mesh& mesh, const bm::Paper_model_info& info, const bm::Cad_model_statistics& s)
{
  bool ok = true;
  auto report = [&](bool passed, const std::string& what) {
    std::cout << "  " << (passed ? "ok      " : "FAILED  ") << what << std::endl;
    ok = ok && passed;
  };
  report(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh), "valid triangle mesh");
  report(CGAL::is_closed(mesh) == info.closed, info.closed ? "closed" : "open");
  report(s.components == 1 && s.genus == info.genus && s.boundary_loops == info.boundary_loops,
         "one component of genus " + std::to_string(info.genus) +
           (info.closed ? std::string() : ", " + std::to_string(info.boundary_loops) + " boundary loops"));
  std::size_t degenerate = 0;
  for(Mesh::Face_index f : mesh.faces()) {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    degenerate += CGAL::collinear(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                  mesh.point(mesh.target(mesh.next(h))));
  }
  report(degenerate == 0, "no degenerate triangle (" + std::to_string(degenerate) + ")");
  if(info.closed)
    report(PMP::is_outward_oriented(mesh), "outward oriented");
  const auto start = std::chrono::steady_clock::now();
  const bool self_intersects = PMP::does_self_intersect(mesh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report(!self_intersects, "no self-intersection (" + std::to_string(seconds) + " s)");
  return ok;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    std::string positional[3];
    int count = 0;
    bm::Paper_model_parameters p;
    bool check = false;
    for(int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if(arg == "--help" || arg == "-h") {
        print_help(std::cout);
        return 0;
      }
      if(arg == "--check")
        check = true;
      else if(arg == "--seed") {
        if(i + 1 >= argc)
          throw std::invalid_argument("--seed: missing value");
        const long long s = bm::parse_integer(arg, argv[++i]);
        if(s < 0)
          throw std::invalid_argument("--seed: must be non-negative");
        p.seed = static_cast<std::uint64_t>(s);
      }
      else if(arg.size() > 1 && arg[0] == '-')
        throw std::invalid_argument("unknown option '" + arg + "' (see --help)");
      else if(count < 3)
        positional[count++] = arg;
      else
        throw std::invalid_argument("unexpected argument '" + arg + "' (see --help)");
    }
    if(count < 3)
      throw std::invalid_argument("expected MODEL VERTICES OUT.off (see --help)");
    const bm::Paper_model_info& info = bm::paper_model_info(bm::paper_model_from_name(positional[0]));
    p.target_vertices = parse_vertices(positional[1]);

    Mesh mesh;
    const auto start = std::chrono::steady_clock::now();
    bm::make_paper_model(mesh, info.model, p);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bm::write_off_atomically(mesh, positional[2]);
    const bm::Cad_model_statistics s = bm::cad_model_statistics(mesh);
    bm::print_model_summary(std::cout, info.name, positional[2], s);
    std::cout << ", generated in " << seconds << " s" << std::endl;
    return check && !check_model(mesh, info, s) ? 1 : 0;
  }
  catch(const std::exception& e) {
    std::cerr << "generate_paper_model: error: " << e.what() << std::endl;
    return 1;
  }
}
