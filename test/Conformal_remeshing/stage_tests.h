// What the tests of remesh_conformal() and of its stages share: includes, the shorthand names of
// the package, the kernel and the mesh, and the checks of remeshing_checks.h.

#ifndef CGAL_CONFORMAL_REMESHING_TEST_STAGE_TESTS_H
#define CGAL_CONFORMAL_REMESHING_TEST_STAGE_TESTS_H

#include <CGAL/remesh_conformal.h>

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include "cad_like_models.h"
#include "remeshing_checks.h"
#include "test_surfaces.h"
#include "expect_error.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using remeshing_checks::check_remeshing;
using remeshing_checks::diagonal;
using remeshing_checks::check_topology_and_fidelity;

namespace RM = CR::internal::remeshing;

#endif // CGAL_CONFORMAL_REMESHING_TEST_STAGE_TESTS_H
