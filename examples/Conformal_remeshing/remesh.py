#!/usr/bin/env python3
"""Remeshes an OFF file with the Python module cgal_conformal_remeshing, then measures and
verifies the result: the Python counterpart of the remesh_conformal tool, for NumPy arrays.

    python3 remesh.py [IN.off [OUT.off]] [--relative-edge-length R | --target-edge-length L]
                      [--time-limit SECONDS]

IN defaults to the shipped model data/perforated_plate.off, OUT to IN's name with _remeshed, in
the current directory.
Any reader that gives vertex and face arrays (meshio, trimesh, libigl's read_triangle_mesh)
can replace read_off(). Ctrl-C stops the remeshing cleanly. Exit codes: 0 success, 1 the input
cannot be remeshed, 3 the time limit was exceeded, 130 interrupted.
"""

import argparse
import pathlib
import sys

import numpy as np

import cgal_conformal_remeshing as crm


def read_off(path):
    """The vertices (n x 3) and triangles (m x 3) of an ASCII OFF file."""
    words = []
    for line in pathlib.Path(path).read_text().splitlines():
        words += line.split("#", 1)[0].split()
    if not words or words[0] != "OFF":
        raise ValueError(f"{path}: not an ASCII OFF file")
    nv, nf = int(words[1]), int(words[2])
    V = np.array(words[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
    faces = np.array(words[4 + 3 * nv:4 + 3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    if (faces[:, 0] != 3).any():
        raise ValueError(f"{path}: only triangles are read here")
    return V, faces[:, 1:]


def write_off(path, V, F):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(out, V, fmt="%.17g")
        np.savetxt(out, np.column_stack([np.full(len(F), 3), F]), fmt="%d")


def main():
    here = pathlib.Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", nargs="?", default=str(here / "data" / "perforated_plate.off"))
    parser.add_argument("output", nargs="?")
    size = parser.add_mutually_exclusive_group()
    size.add_argument("--relative-edge-length", type=float, default=0.01)
    size.add_argument("--target-edge-length", type=float)
    parser.add_argument("--time-limit", type=float)
    args = parser.parse_args()
    output = args.output or pathlib.Path(args.input).stem + "_remeshed.off"

    V, F = read_off(args.input)
    try:
        V2, F2, report = crm.remesh(V, F, relative_edge_length=args.relative_edge_length,
                                    target_edge_length=args.target_edge_length, time_limit=args.time_limit,
                                    progress=lambda message: print("remesh:", message, file=sys.stderr))
    except ValueError as e:  # the input or an option: the message says what
        print("remesh.py:", e, file=sys.stderr)
        return 1
    except TimeoutError as e:
        print("remesh.py:", e, file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        print("remesh.py: interrupted, nothing written", file=sys.stderr)
        return 130

    before, after = crm.quality(V, F), crm.quality(V2, F2, reference=(V, F))
    verification = crm.verify(V, F, V2, F2)
    pathlib.Path(output).parent.mkdir(parents=True, exist_ok=True)
    write_off(output, V2, F2)
    print(f"{output}: {len(V2)} vertices, {len(F2)} faces (target edge length {report['target_edge_length']:.4g}, "
          f"{report['number_of_patches']} patches)")
    print(f"  minimum angle {after['minimum_angle']['min']:.2f} deg (input {before['minimum_angle']['min']:.3g}), "
          f"mean skewness {after['skewness']['mean']:.3f} (input {before['skewness']['mean']:.3f})")
    print(f"  Hausdorff distance {after['fidelity']['relative_hausdorff_distance']:.2e} x diagonal; "
          f"verification: {verification['summary']}")
    return 0 if verification["valid"] else 1


if __name__ == "__main__":
    sys.exit(main())
