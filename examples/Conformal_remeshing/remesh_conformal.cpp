// remesh_conformal: remeshes a surface by conformal flattening (CGAL::remesh_conformal()).
//
//   remesh_conformal IN OUT [--target-edge-length L | --relative-edge-length R] [--min-angle DEG]
//                    [--features-angle DEG] [--crease-angle DEG] [--patches FILE] [--cut-plane a,b,c,d]...
//                    [--save-patches DIR] [--sequential] [--report FILE.json] [--plots DIR] [--quiet]
//                    [--time-limit SECONDS] [--optimization-rounds N] [--lloyd-iterations N] [--chord-error E]
//                    [--no-frontal] [--no-repair] [--deviation-map PREFIX] [--batch-faces N]
//                    [--no-fidelity] [--surface-distance D | --relative-surface-distance R]
//
// The input's polygons are triangulated, its faces oriented consistently, its isolated vertices
// removed and its borders along the same points stitched first (CR::Input_repairs), unless
// --no-repair. Progress goes to standard error; OUT is written completely or not at all. Exit
// codes: 0 success, 1 the input cannot be remeshed (defects, unsupported topology, failed
// flattening), 2 the tool could not run (bad arguments, unreadable input, unwritable output, out
// of memory), 3 the time limit was exceeded (nothing written).

#include "remesh_conformal_tool.h"

int main(int argc, char** argv) { return Conformal_remeshing_tools::remesh_conformal_main(argc, argv); }
