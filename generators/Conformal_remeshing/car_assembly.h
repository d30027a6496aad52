// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A car-scale assembly: many CAD-like parts in one multi-component mesh, the stand-in of the
// paper's whole car (its Fig. 4 and 5: 15,013k faces). First the five parts of Table 1 at their
// sizes, then, until the faces reach the wanted total, a cycle of other parts of the same
// families with other seeds and sizes: channels with flanges and holes (ribs and rails), open
// panels with flanged rims and holes, bent sheets with slots, forged brackets with lightening
// holes, drilled discs of genus 83, and perforated plates and bent perforated sheets tessellated
// as CAD exporters do (fans of slivers on planar faces, strips on cylinders). The parts are laid
// out in rows with gaps between their bounding boxes, so none touches another. The result
// depends only on the parameters.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_CAR_ASSEMBLY_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_CAR_ASSEMBLY_H

#include "cad_like_models.h"
#include "paper_models.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

struct Car_assembly_parameters
{
  std::size_t target_faces = 15000000; ///< parts are added until the assembly has at least this many faces
  std::uint64_t seed = 1;              ///< seed of the parts' random details (each part gets its own)
  /// the sizes of every part, as a share of the sizes below (Table 1's and the cycle's); 0.1 gives
  /// a tenth-scale car of the same parts, to rerun in minutes
  double part_scale = 1.;
};

/// One part of the assembly: what it is, its size and its place.
struct Car_part
{
  std::string name;            ///< the generator's model name
  std::size_t vertices = 0, faces = 0;
  std::size_t first_face = 0;  ///< its faces are [first_face, first_face + faces) of the assembly
  std::array<double, 3> offset{{0., 0., 0.}};
};

namespace internal {

// What a part of the cycle is: a paper model of `vertices` vertices, or a perforated plate
// (`sheet` false) or bent perforated sheet of `holes` holes.
struct Car_part_recipe
{
  bool paper = true;
  Paper_model model = Paper_model::suspension_arm;
  std::size_t vertices = 0;
  bool sheet = false;
  int holes = 0;
};

inline std::vector<Car_part_recipe> table_1_recipes()
{
  std::vector<Car_part_recipe> recipes;
  for(const Paper_model_info& m : paper_models())
    if(m.paper_vertices > 0)
      recipes.push_back({true, m.model, m.paper_vertices, false, 0});
  return recipes;
}

// The cycle of other parts: about 2.2M vertices (4.4M faces) per turn.
inline std::vector<Car_part_recipe> cycle_recipes()
{
  return {{true, Paper_model::chassis, 260000, false, 0},       {true, Paper_model::shield, 180000, false, 0},
          {false, Paper_model::suspension_arm, 0, false, 24},    {true, Paper_model::radiator_shell, 220000, false, 0},
          {true, Paper_model::suspension_arm, 120000, false, 0}, {false, Paper_model::suspension_arm, 0, true, 12},
          {true, Paper_model::chassis, 400000, false, 0},       {true, Paper_model::brake_disc, 500000, false, 0},
          {true, Paper_model::shield, 90000, false, 0},         {false, Paper_model::suspension_arm, 0, false, 40},
          {true, Paper_model::radiator_shell, 300000, false, 0}};
}

template <class Point_3>
void make_car_part(CGAL::Surface_mesh<Point_3>& part, const Car_part_recipe& r, double scale, std::uint64_t seed,
                   std::string& name)
{
  if(r.paper)
  {
    Paper_model_parameters p;
    p.target_vertices = std::max<std::size_t>(1000, std::size_t(scale * double(r.vertices)));
    p.seed = seed;
    make_paper_model(part, r.model, p);
    name = paper_model_info(r.model).name;
    return;
  }
  Perforated_plate_parameters p;
  p.length = 400.;
  p.width = 250.;
  p.thickness = 3.;
  p.number_of_random_holes = r.holes;
  p.seed = seed;
  p.min_hole_radius = 4.;
  p.max_hole_radius = 18.;
  if(r.sheet)
  {
    make_perforated_sheet(part, p, 0.15, true);
    name = "bent_perforated_sheet";
  }
  else
  {
    make_perforated_plate(part, p);
    name = "perforated_plate";
  }
}

// Appends `part`, translated by `offset`, to `mesh`.
template <class Point_3>
void append_translated(CGAL::Surface_mesh<Point_3>& mesh, const CGAL::Surface_mesh<Point_3>& part,
                       const std::array<double, 3>& offset)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  std::vector<typename Mesh::Vertex_index> vertex(part.number_of_vertices());
  for(typename Mesh::Vertex_index v : part.vertices())
  {
    const Point_3& p = part.point(v);
    vertex[v.idx()] = mesh.add_vertex(Point_3(p.x() + offset[0], p.y() + offset[1], p.z() + offset[2]));
  }
  for(typename Mesh::Face_index f : part.faces())
  {
    std::vector<typename Mesh::Vertex_index> corners;
    for(typename Mesh::Vertex_index v : CGAL::vertices_around_face(part.halfedge(f), part))
      corners.push_back(vertex[v.idx()]);
    mesh.add_face(corners);
  }
}

} // namespace internal

/// Builds the assembly of `p` into `mesh` (cleared first) and returns its parts in the order of
/// their faces. `progress(part)` is called after each part is added.
template <class Point_3, class Progress>
std::vector<Car_part> make_car_assembly(CGAL::Surface_mesh<Point_3>& mesh, const Car_assembly_parameters& p,
                                        const Progress& progress)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  mesh.clear();
  std::vector<Car_part> parts;
  const std::vector<internal::Car_part_recipe> first = internal::table_1_recipes(), cycle = internal::cycle_recipes();
  // Rows along x, up to `row_length` long; the next row starts past the deepest part of the row.
  const double row_length = 6000., gap = 50.;
  double x = 0., y = 0., row_depth = 0.;
  for(std::size_t k = 0; mesh.number_of_faces() < p.target_faces || k < first.size(); ++k)
  {
    const internal::Car_part_recipe& recipe = k < first.size() ? first[k] : cycle[(k - first.size()) % cycle.size()];
    Mesh part;
    Car_part record;
    internal::make_car_part(part, recipe, p.part_scale, p.seed * 1000003u + k, record.name);
    CGAL::Bbox_3 box;
    for(typename Mesh::Vertex_index v : part.vertices())
      box += part.point(v).bbox();
    if(x > 0. && x + (box.xmax() - box.xmin()) > row_length)
    {
      x = 0.;
      y += row_depth + gap;
      row_depth = 0.;
    }
    record.offset = {{x - box.xmin(), y - box.ymin(), -box.zmin()}};
    record.vertices = part.number_of_vertices();
    record.faces = part.number_of_faces();
    record.first_face = mesh.number_of_faces();
    internal::append_translated(mesh, part, record.offset);
    x += (box.xmax() - box.xmin()) + gap;
    row_depth = std::max(row_depth, box.ymax() - box.ymin());
    parts.push_back(record);
    progress(parts.back());
  }
  return parts;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_CAR_ASSEMBLY_H
