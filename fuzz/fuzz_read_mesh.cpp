// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the mesh file readers, the input repairs and the input checks. The first
// byte of the input picks the file extension (OFF, OBJ, PLY, STL; ASCII or binary is up to the
// content) with its two lowest bits, and with the next one whether every repair of
// Input_repairs is made (as the remesh_conformal tool does); the rest is written to a file that
// read_and_check_mesh() reads.
//
// The defined outcomes are: a report, or a CGAL::Conformal_remeshing::Error. Anything else (a
// crash, a sanitizer report, another exception, an inconsistent report) is a bug.

#include "fuzz_support.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace CR = CGAL::Conformal_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

void fail(const char* what) { fuzz::fail("fuzz_read_mesh", what); }

std::string scratch_file(const char* extension)
{
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir != nullptr ? dir : "/tmp") + "/fuzz_read_mesh_" + std::to_string(::getpid()) + "." + extension;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  static const char* const extensions[] = {"off", "obj", "ply", "stl"};
  const std::string file = scratch_file(extensions[data[0] % 4]);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }

  const bool repair = (data[0] >> 2) & 1;
  Mesh mesh;
  CR::Mesh_check_report report;
  CR::Input_repair_report repaired;
  try
  {
    report = CR::read_and_check_mesh(file, mesh, repair ? CR::Input_repairs::all() : CR::Input_repairs(), repaired);
  }
  catch(const CR::Error& e)
  {
    if(e.code() != CR::Error_code::FILE_NOT_READABLE || std::string(e.what()).find(file) == std::string::npos)
      fail("an error without the file name or with the wrong code");
    return 0;
  }

  // The report and the mesh must agree with each other, and with what was repaired.
  if(report.summary().empty())
    fail("empty summary");
  if(!repair && repaired.any())
    fail("a repair that was not asked for");
  if(report.number_of_faces != repaired.file_face.size())
    fail("not one file face per face");
  for(std::size_t f : repaired.file_face)
    if(f >= repaired.file_faces)
      fail("a face mapped to no face of the file");
  if(report.topology_available)
  {
    // CGAL counts an isolated vertex as a broken halfedge structure; the checks report it.
    if(report.count(CR::Mesh_defect::ISOLATED_VERTEX) == 0 && !CGAL::is_valid_polygon_mesh(mesh))
      fail("the reader built an invalid halfedge data structure");
    const CR::Mesh_check_report again = CR::check_mesh(mesh);
    if(report.is_valid() && !again.is_valid())
      fail("a valid soup became an invalid mesh");
    if(!again.topology_available || again.components.size() != report.components.size()
       || again.total_genus() != report.total_genus()
       || again.total_boundary_loops() != report.total_boundary_loops())
      fail("check_mesh() disagrees with the reader on the topology");
    if(report.is_valid())
    {
      // A valid mesh must be measurable without trouble.
      const CR::Mesh_quality_report q = CR::mesh_quality(mesh);
      if(q.number_of_faces != num_faces(mesh))
        fail("mesh_quality() lost faces");
    }
  }
  else if(report.is_valid())
    fail("a valid soup was not built into a mesh");
  else if(!mesh.is_empty())
    fail("a mesh was built but the report has no topology");
  return 0;
}
