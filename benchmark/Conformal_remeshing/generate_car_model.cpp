// generate_car_model: writes the car-scale assembly (generators/car_assembly.h), the stand-in of
// the paper's whole car, as one multi-component OFF file.
//
//   generate_car_model OUT.off [--faces N] [--part-scale S] [--seed S] [--parts FILE.json]
//
// Prints one line per part (its model, vertices, faces) and a summary line (parts, vertices,
// faces, area); --parts writes the
// same as JSON (name, vertices, faces, first_face, offset per part). The file is written to
// OUT.off.tmp first and renamed. Exit codes: 0 written, 2 bad arguments or unwritable output.

#include <car_assembly.h>
#include <model_tool.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace bm = CGAL::Conformal_remeshing::benchmarks;

const char* usage =
  "usage: generate_car_model OUT.off [--faces N] [--part-scale S] [--seed S] [--parts FILE.json]\n"
  "  --faces N        add parts until the assembly has at least N faces (default 15000000; k and M suffixes)\n"
  "  --part-scale S   every part at S times its size (default 1: Table 1's sizes; 0.1: a tenth-scale car)\n"
  "  --seed S         seed of the parts' random details (default 1)\n"
  "  --parts FILE     the parts as JSON: model, vertices, faces, first face, offset\n";

std::size_t parse_count(const std::string& option, std::string text)
{
  double factor = 1.;
  if(!text.empty() && (text.back() == 'k' || text.back() == 'M'))
  {
    factor = text.back() == 'k' ? 1e3 : 1e6;
    text.pop_back();
  }
  const double n = bm::parse_double(option, text) * factor;
  if(!(n >= 1.) || n > 1e10)
    throw std::invalid_argument(option + ": out of range: '" + text + "'");
  return std::size_t(n);
}

} // namespace

int main(int argc, char** argv)
{
  bm::Car_assembly_parameters p;
  std::string out, parts_file;
  try
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if(arg == "--help" || arg == "-h")
      {
        std::cout << usage;
        return 0;
      }
      auto value = [&]() -> std::string {
        if(i + 1 >= argc)
          throw std::invalid_argument(arg + ": missing value");
        return argv[++i];
      };
      if(arg == "--faces")
        p.target_faces = parse_count(arg, value());
      else if(arg == "--part-scale")
      {
        p.part_scale = bm::parse_double(arg, value());
        if(!(p.part_scale > 0. && p.part_scale <= 10.))
          throw std::invalid_argument("--part-scale: must be in (0, 10]");
      }
      else if(arg == "--seed")
        p.seed = std::uint64_t(bm::parse_integer(arg, value()));
      else if(arg == "--parts")
        parts_file = value();
      else if(!arg.empty() && arg[0] == '-')
        throw std::invalid_argument("unknown option '" + arg + "'");
      else if(out.empty())
        out = arg;
      else
        throw std::invalid_argument("unexpected argument '" + arg + "'");
    }
    if(out.empty())
      throw std::invalid_argument("needs OUT.off");
  }
  catch(const std::exception& e)
  {
    std::cerr << "generate_car_model: " << e.what() << "\n" << usage;
    return 2;
  }
  try
  {
    const auto start = std::chrono::steady_clock::now();
    Mesh car;
    const std::vector<bm::Car_part> parts = bm::make_car_assembly(car, p, [](const bm::Car_part& part) {
      std::cout << "  " << part.name << ": " << part.vertices << " vertices, " << part.faces << " faces\n";
    });
    bm::write_off_atomically(car, out);
    if(!parts_file.empty())
    {
      std::ofstream json(parts_file);
      json << "[\n";
      for(std::size_t k = 0; k < parts.size(); ++k)
        json << "  {\"name\": \"" << parts[k].name << "\", \"vertices\": " << parts[k].vertices << ", \"faces\": " << parts[k].faces
             << ", \"first_face\": " << parts[k].first_face << ", \"offset\": [" << parts[k].offset[0] << ", "
             << parts[k].offset[1] << ", " << parts[k].offset[2] << "]}" << (k + 1 < parts.size() ? "," : "") << "\n";
      json << "]\n";
      if(!json.flush())
        throw std::runtime_error("cannot write '" + parts_file + "'");
    }
    std::cout << "car: " << out << ": " << parts.size() << " parts, " << car.number_of_vertices() << " vertices, "
              << car.number_of_faces() << " faces, area " << CGAL::to_double(CGAL::Polygon_mesh_processing::area(car))
              << ", generated and written in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "generate_car_model: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
