"""Shared fixtures of the Python module's tests: the shipped model, small generated meshes, and
one remeshing of the model that several tests read.

CTest runs these tests with PYTHONPATH set to the build directory of the module and
CGAL_CONFORMAL_REMESHING_DATA, _TOOL and _EXAMPLE set to the shipped data, the remesh_conformal
tool and the example script (python/CMakeLists.txt).
"""

import os
import pathlib

import numpy as np
import pytest

import cgal_conformal_remeshing as crm

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("CGAL_CONFORMAL_REMESHING_DATA", ROOT / "examples/Conformal_remeshing/data"))
PLATE = DATA / "perforated_plate.off"


def read_off(path):
    """The vertices and triangles of an ASCII OFF file."""
    words = []
    for line in pathlib.Path(path).read_text().splitlines():
        words += line.split("#", 1)[0].split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    V = np.array(words[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
    rest = np.array(words[4 + 3 * nv:], dtype=np.int64).reshape(nf, 4)
    assert (rest[:, 0] == 3).all()
    return V, rest[:, 1:]


def paraboloid_disc(n=12):
    """A curved square patch (genus 0, one boundary loop): an n x n grid lifted onto
    z = 0.3 (x^2 + y^2), two counterclockwise triangles per cell."""
    x, y = np.meshgrid(np.linspace(-1.0, 1.0, n + 1), np.linspace(-1.0, 1.0, n + 1), indexing="xy")
    V = np.column_stack([x.ravel(), y.ravel(), 0.3 * (x.ravel() ** 2 + y.ravel() ** 2)])
    F = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 1, a + n + 2
            F += [[a, b, d], [a, d, c]]
    return V, np.array(F, dtype=np.int64)


def diagonal(V):
    return float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))


def edges(F):
    """The unique undirected edges of a triangle array, as an e x 2 array."""
    e = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    return np.unique(e, axis=0)


def triangle_angles(V, F):
    """The three corner angles of every triangle, in degrees (m x 3)."""
    P = V[F]
    angles = []
    for c in range(3):
        u, w = P[:, (c + 1) % 3] - P[:, c], P[:, (c + 2) % 3] - P[:, c]
        angles.append(np.degrees(np.arctan2(np.linalg.norm(np.cross(u, w), axis=1), (u * w).sum(axis=1))))
    return np.column_stack(angles)


@pytest.fixture(scope="session")
def plate():
    return read_off(PLATE)


@pytest.fixture(scope="session")
def remeshed_plate(plate):
    """The shipped model remeshed with the default options: (V2, F2, report, progress messages)."""
    messages = []
    V2, F2, report = crm.remesh(*plate, progress=messages.append)
    return V2, F2, report, messages
