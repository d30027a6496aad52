// A mesh as OFF text with every digit of its coordinates: what the tests compare when they ask
// for the same output file byte for byte.
#ifndef CGAL_CONFORMAL_REMESHING_TEST_OFF_TEXT_H
#define CGAL_CONFORMAL_REMESHING_TEST_OFF_TEXT_H

#include <CGAL/boost/graph/IO/OFF.h>

#include <sstream>
#include <string>

template <typename TriangleMesh>
std::string off_text(const TriangleMesh& mesh)
{
  std::ostringstream out;
  out.precision(17);
  CGAL::IO::write_OFF(out, mesh);
  return out.str();
}

#endif // CGAL_CONFORMAL_REMESHING_TEST_OFF_TEXT_H
