// Uses the installed package: checks a tetrahedron and reports its genus.
#include <CGAL/Conformal_remeshing/check_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <iostream>

int main()
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::make_tetrahedron(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, 0, 1), mesh);
  const auto report = CGAL::Conformal_remeshing::check_mesh(mesh);
  std::cout << "consumer: " << report.summary() << ", genus " << report.total_genus() << std::endl;
  return report.is_valid() && report.total_genus() == 0 ? 0 : 1;
}
