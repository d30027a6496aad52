"""Bad arrays raise ValueError, with the library's words where the library finds the defect."""

import numpy as np
import pytest

import cgal_conformal_remeshing as crm
from conftest import paraboloid_disc

V0, F0 = paraboloid_disc(4)


def with_vertex(value):
    V = V0.copy()
    V[2, 1] = value
    return V


def with_index(value):
    F = F0.copy()
    F[5, 2] = value
    return F


# (V, F, what the message says)
BAD_ARRAYS = {
    "V of 2 columns": (V0[:, :2], F0, r"V must be an array of shape \(n, 3\), not \(25, 2\)"),
    "V of one dimension": (V0.ravel(), F0, r"V must be an array of shape \(n, 3\), not \(75,\)"),
    "F of 4 columns": (V0, np.hstack([F0, F0[:, :1]]), r"F must be an array of shape \(m, 3\)"),
    "F of floats": (V0, F0.astype(float), "F must hold integer vertex indices, not float64"),
    "V of strings": (V0.astype(str), F0, "V must hold floating-point coordinates, not <U"),
    "V of complex numbers": (V0.astype(complex), F0, "V must hold floating-point coordinates, not complex128"),
    "V of booleans": (V0 > 0, F0, "V must hold floating-point coordinates, not bool"),
    "index past the vertices": (V0, with_index(len(V0)), "invalid vertex index"),
    "negative index": (V0, with_index(-1), r"F\[5, 2\] = -1 is out of range"),
    "huge unsigned index": (V0, with_index(0).astype(np.uint64) + np.uint64(2**63), "out of range"),
    "NaN coordinate": (with_vertex(np.nan), F0, "non-finite coordinates"),
    "infinite coordinate": (with_vertex(np.inf), F0, "non-finite coordinates"),
    "repeated index": (V0, with_index(F0[5, 0]), r"F\[5\] = .* repeats a vertex"),
}


def named(message, v_name, f_name):
    """The message with the arrays' names as the function calls them."""
    return message.replace("V must", v_name + " must").replace("F must", f_name + " must").replace(r"F\[", f_name + r"\[")


@pytest.mark.parametrize("name", sorted(BAD_ARRAYS))
@pytest.mark.parametrize("function", ["remesh", "quality", "flatten", "verify input", "verify output"])
def test_bad_arrays_raise_value_error(function, name):
    V, F, message = BAD_ARRAYS[name]
    if function == "verify output":
        if name == "repeated index":
            # An output that no halfedge structure holds is no error: its verification fails.
            assert not crm.verify(V0, F0, V, F)["valid"]
            return
        with pytest.raises(ValueError, match=named(message, "V_out", "F_out")):
            crm.verify(V0, F0, V, F)
        return
    call = {
        "remesh": lambda: crm.remesh(V, F),
        "quality": lambda: crm.quality(V, F),
        "flatten": lambda: crm.flatten(V, F),
        "verify input": lambda: crm.verify(V, F, V0, F0),
    }[function]
    with pytest.raises(ValueError, match=named(message, "V_in", "F_in") if function == "verify input" else message):
        call()


@pytest.mark.parametrize("name", sorted(BAD_ARRAYS))
def test_check_reports_what_it_can_read(name):
    """check() raises only for arrays that are no soup; it reports the defects of the others."""
    V, F, message = BAD_ARRAYS[name]
    if name in ("index past the vertices", "NaN coordinate", "infinite coordinate", "repeated index"):
        report = crm.check(V, F)
        assert not report["valid"]
        kinds = {d["kind"] for d in report["defects"]}
        expected = {"index past the vertices": "INVALID_VERTEX_INDEX", "NaN coordinate": "NON_FINITE_COORDINATES",
                    "infinite coordinate": "NON_FINITE_COORDINATES", "repeated index": "DEGENERATE_FACE"}[name]
        assert expected in kinds
    else:
        with pytest.raises(ValueError):
            crm.check(V, F)


def test_surfaces_the_library_refuses_raise_its_message():
    # A Moebius strip: no orientation, no repair.
    n = 8
    V = np.array([[np.cos(2 * np.pi * i / n) * (1 + s * 0.3 * np.cos(np.pi * i / n)),
                   np.sin(2 * np.pi * i / n) * (1 + s * 0.3 * np.cos(np.pi * i / n)),
                   s * 0.3 * np.sin(np.pi * i / n)] for i in range(n) for s in (-1, 1)])
    F = []
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        c, d = (2 * i + 2, 2 * i + 3) if i + 1 < n else (1, 0)  # the half twist
        F += [[a, c, b], [b, c, d]]
    F = np.array(F)
    assert "NON_ORIENTABLE" in {d["kind"] for d in crm.check(V, F)["defects"]}
    with pytest.raises(ValueError, match="non-orientable"):
        crm.remesh(V, F)
    # No faces.
    with pytest.raises(ValueError, match="empty mesh"):
        crm.remesh(V0, np.zeros((0, 3), dtype=int))
    # flatten() needs a patch with a boundary: the library says what is wrong.
    closed_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    closed_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    assert crm.check(closed_V, closed_F)["valid"]
    with pytest.raises(ValueError, match="boundary"):
        crm.flatten(closed_V, closed_F)


def test_array_likes_and_other_dtypes_are_accepted():
    V2, F2, _ = crm.remesh(V0.astype(np.float32).tolist(), F0.astype(np.uint16), relative_edge_length=0.1)
    assert len(F2) > 0
    assert crm.check(np.asfortranarray(V0), F0.astype(np.int32))["valid"]


def test_remeshing_error_is_a_runtime_error():
    assert issubclass(crm.RemeshingError, RuntimeError)
