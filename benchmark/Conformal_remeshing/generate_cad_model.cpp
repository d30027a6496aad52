// generate_cad_model: writes a deterministic CAD-like triangle mesh (see generators/cad_like_models.h).
//
//   generate_cad_model perforated_plate OUT.off [options]
//
// The file is written to OUT.tmp first and renamed, so a reader never sees a half-written model.

#include <cad_like_models.h>
#include <model_tool.h>
#include <test_surfaces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace bm = CGAL::Conformal_remeshing::benchmarks;

void print_help(std::ostream& out)
{
  const bm::Perforated_plate_parameters d;
  out << "Usage: generate_cad_model MODEL OUT.off [options]\n"
         "Writes a deterministic CAD-like triangle mesh (OFF, 17 significant digits) and prints\n"
         "one summary line: vertices, faces, genus, minimum angle, share of triangles with\n"
         "minimum angle below 10 and 1 degrees.\n\n"
         "Models:\n"
         "  perforated_plate   plate with rounded corners and circular through-holes (closed, genus = holes)\n"
         "  sliver_fan_disc    flat disc fanned from one boundary vertex (open, one boundary)\n"
         "  wavy_c_strip       C-shaped wavy strip with a strongly concave boundary, where CGAL's LSCM\n"
         "                     overlaps (open, one boundary; no options)\n\n"
         "Options of perforated_plate (defaults in brackets):\n"
      << "  --length X          size along x [" << d.length << "]\n"
      << "  --width Y           size along y [" << d.width << "]\n"
      << "  --thickness Z       size along z [" << d.thickness << "]\n"
      << "  --corner-radius R   fillet radius, 0 for sharp corners [" << d.corner_radius << "]\n"
      << "  --segments K        segments per full circle, >= 8 [" << d.segments_per_circle << "]\n"
      << "  --holes N           number of randomly placed holes [" << d.number_of_random_holes << "]\n"
      << "  --seed S            seed of the hole placement [" << d.seed << "]\n"
      << "  --min-radius A      smallest random hole radius [" << d.min_hole_radius << "]\n"
      << "  --max-radius B      largest random hole radius [" << d.max_hole_radius << "]\n"
      << "  --clearance C       material left between holes and to the rim [" << d.min_clearance << "]\n"
      << "  --hole X,Y,R        explicit hole (repeatable; replaces the random holes)\n"
         "Options of sliver_fan_disc:\n"
         "  --segments K        boundary vertices [64]\n"
         "  --radius R          disc radius [1]\n"
         "  --help              this text\n";
}

int parse_int(const std::string& option, const std::string& text)
{
  const long long v = bm::parse_integer(option, text);
  if(v < -1000000000LL || v > 1000000000LL)
    throw std::invalid_argument(option + ": out of range: '" + text + "'");
  return int(v);
}

bm::Circular_hole parse_hole(const std::string& text)
{
  std::string parts[3];
  std::istringstream in(text);
  for(int i = 0; i < 3; ++i)
    if(!std::getline(in, parts[i], ','))
      throw std::invalid_argument("--hole: expected X,Y,R, got '" + text + "'");
  std::string rest;
  if(std::getline(in, rest))
    throw std::invalid_argument("--hole: expected X,Y,R, got '" + text + "'");
  bm::Circular_hole h;
  h.x = bm::parse_double("--hole", parts[0]);
  h.y = bm::parse_double("--hole", parts[1]);
  h.radius = bm::parse_double("--hole", parts[2]);
  return h;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    std::string model, output;
    bm::Perforated_plate_parameters plate;
    int disc_segments = 64;
    double disc_radius = 1.;
    bool segments_given = false;

    for(int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if(arg == "--help" || arg == "-h") {
        print_help(std::cout);
        return 0;
      }
      if(arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
        if(i + 1 >= argc)
          throw std::invalid_argument(arg + ": missing value");
        const std::string value = argv[++i];
        if(arg == "--length") plate.length = bm::parse_double(arg, value);
        else if(arg == "--width") plate.width = bm::parse_double(arg, value);
        else if(arg == "--thickness") plate.thickness = bm::parse_double(arg, value);
        else if(arg == "--corner-radius") plate.corner_radius = bm::parse_double(arg, value);
        else if(arg == "--segments") {
          plate.segments_per_circle = disc_segments = parse_int(arg, value);
          segments_given = true;
        }
        else if(arg == "--holes") plate.number_of_random_holes = parse_int(arg, value);
        else if(arg == "--seed") {
          const long long s = bm::parse_integer(arg, value);
          if(s < 0)
            throw std::invalid_argument("--seed: must be non-negative");
          plate.seed = static_cast<std::uint64_t>(s);
        }
        else if(arg == "--min-radius") plate.min_hole_radius = bm::parse_double(arg, value);
        else if(arg == "--max-radius") plate.max_hole_radius = bm::parse_double(arg, value);
        else if(arg == "--clearance") plate.min_clearance = bm::parse_double(arg, value);
        else if(arg == "--hole") plate.holes.push_back(parse_hole(value));
        else if(arg == "--radius") disc_radius = bm::parse_double(arg, value);
        else
          throw std::invalid_argument("unknown option '" + arg + "' (see --help)");
      }
      else if(model.empty()) model = arg;
      else if(output.empty()) output = arg;
      else
        throw std::invalid_argument("unexpected argument '" + arg + "' (see --help)");
    }
    if(model.empty() || output.empty())
      throw std::invalid_argument("expected MODEL and OUT.off (see --help)");

    Mesh mesh;
    if(model == "perforated_plate")
      bm::make_perforated_plate(mesh, plate);
    else if(model == "sliver_fan_disc")
      bm::make_sliver_fan_disc(mesh, segments_given ? disc_segments : 64, disc_radius);
    else if(model == "wavy_c_strip")
      bm::make_wavy_c_strip(mesh);
    else
      throw std::invalid_argument("unknown model '" + model + "' (known: perforated_plate, sliver_fan_disc, wavy_c_strip)");

    bm::write_off_atomically(mesh, output);
    bm::print_model_summary(std::cout, model, output, bm::cad_model_statistics(mesh));
    std::cout << std::endl;
    return 0;
  }
  catch(const std::exception& e) {
    std::cerr << "generate_cad_model: error: " << e.what() << std::endl;
    return 1;
  }
}
