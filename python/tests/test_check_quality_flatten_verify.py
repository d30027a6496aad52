"""check(), quality(), flatten() and verify(), each against what NumPy computes from the arrays."""

import numpy as np
import pytest

import cgal_conformal_remeshing as crm
from conftest import edges, paraboloid_disc, triangle_angles


def test_check_gives_the_topology(plate):
    V, F = plate
    report = crm.check(V, F)
    assert report["valid"] and report["summary"] == "valid" and report["topology_available"]
    assert report["number_of_vertices"] == len(V) and report["number_of_faces"] == len(F)
    (component,) = report["components"]
    chi = len(V) - len(edges(F)) + len(F)
    assert component["euler_characteristic"] == chi
    assert component["genus"] == report["total_genus"] == (2 - chi) // 2
    assert component["boundary_loops"] == 0


def test_check_reports_defects():
    V, F = paraboloid_disc(4)
    isolated = crm.check(np.vstack([V, [[9.0, 9.0, 9.0]]]), F)
    (defect,) = isolated["defects"]
    assert defect["kind"] == "ISOLATED_VERTEX" and defect["count"] == 1 and str(len(V)) in defect["example"]
    assert not isolated["valid"] and isolated["topology_available"]
    # A third face on an inner edge (the diagonal of the first cell): no halfedge structure holds
    # it, so no topology.
    a, b = F[0, 0], F[0, 2]
    fin = crm.check(np.vstack([V, [[0.0, 0.0, 5.0]]]), np.vstack([F, [[a, b, len(V)]]]))
    assert "NON_MANIFOLD_EDGE" in {d["kind"] for d in fin["defects"]}
    assert not fin["topology_available"] and fin["components"] == []


def test_quality_measures_the_angles(plate):
    V, F = plate
    q = crm.quality(V, F)
    angles = triangle_angles(V, F)
    smallest, largest = angles.min(axis=1), angles.max(axis=1)
    assert q["number_of_faces"] == len(F) and q["number_of_vertices"] == len(V)
    assert q["minimum_angle"]["min"] == pytest.approx(smallest.min(), rel=1e-6)
    assert q["minimum_angle"]["mean"] == pytest.approx(smallest.mean(), rel=1e-9)
    assert q["maximum_angle"]["max"] == pytest.approx(largest.max(), rel=1e-9)
    skewness = np.maximum((largest - 60) / 120, (60 - smallest) / 60)
    assert q["skewness"]["mean"] == pytest.approx(skewness.mean(), rel=1e-9)
    assert q["share_with_minimum_angle_below"][10.0] == pytest.approx((smallest < 10).mean())
    assert q["minimum_angle_histogram"]["counts"].sum() == len(F)
    assert q["valence_histogram"].sum() == len(V)
    lengths = np.linalg.norm(V[edges(F)[:, 0]] - V[edges(F)[:, 1]], axis=1)
    assert q["edge_length"]["max"] == pytest.approx(lengths.max(), rel=1e-12)
    assert "fidelity" not in q


def test_quality_against_a_reference(plate, remeshed_plate):
    V, F = plate
    itself = crm.quality(V, F, reference=(V, F))["fidelity"]
    assert itself["relative_hausdorff_distance"] < 1e-12 and itself["area_ratio"] == pytest.approx(1.0)
    assert not itself["self_intersects"]
    V2, F2 = remeshed_plate[:2]
    measured = crm.quality(V2, F2, reference=[V, F])
    remeshed = measured["fidelity"]
    assert 0.0 < remeshed["relative_hausdorff_distance"] < 0.01
    assert remeshed["area_ratio"] == pytest.approx(1.0, abs=0.01)
    # The plate's corners are square: no small angle of the output is forced.
    corners = measured["angles_at_sharp_corners"]
    assert corners["sharp_input_corners"] == 0 and corners["triangles_below_25_at_sharp_input_corners"] == 0
    below = (measured["share_with_minimum_angle_below"][25.0] * len(F2))
    assert corners["triangles_below_25"] == round(below)
    assert corners["share_below_25_away_from_sharp_input_corners"] == pytest.approx(
        measured["share_with_minimum_angle_below"][25.0])
    with pytest.raises(ValueError, match="pair"):
        crm.quality(V, F, reference=V)


def test_flatten_lays_out_every_vertex():
    V, F = paraboloid_disc()
    UV, report = crm.flatten(V, F)
    assert UV.shape == (len(V), 2) and np.isfinite(UV).all()
    assert report["status"] == "SUCCESS" and report["converged"]
    assert report["embedding"]["is_embedding"] and report["boundary_loops"] == 1
    assert report["conformal_factor"].shape == (len(V),)
    # Input triangles whose corners are not counterclockwise in UV: counted by the library too.
    a, b, c = UV[F[:, 0]], UV[F[:, 1]], UV[F[:, 2]]
    signed = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert (signed <= 0).sum() == report["folded_input_triangles_in_uv"]
    # Conformal: angles nearly kept where the surface is nearly flat (the centre).
    assert np.median(np.abs(triangle_angles(np.column_stack([UV, np.zeros(len(UV))]), F)
                            - triangle_angles(V, F))) < 2.0
    with pytest.raises(TimeoutError):
        crm.flatten(V, F, time_limit=1e-9)


def test_verify_finds_what_is_wrong(plate, remeshed_plate):
    V, F = plate
    V2, F2 = remeshed_plate[:2]
    good = crm.verify(V, F, V2, F2)
    assert good["valid"] and good["topology_kept"] and good["max_distance_to_input"] <= good["tolerance"]
    # One vertex moved off the surface.
    moved = V2.copy()
    moved[0] += 1e-3 * good["input_diagonal"] * np.array([0.6, 0.0, 0.8])
    off = crm.verify(V, F, moved, F2)
    assert not off["valid"] and not off["on_input_surface"] and off["vertices_off_surface"] == 1
    # A face removed: a hole, the topology changes.
    holed = crm.verify(V, F, V2, F2[1:])
    assert not holed["valid"] and not holed["topology_kept"] and holed["on_input_surface"]
    assert "topology changed" in holed["summary"]
    with pytest.raises(ValueError, match="relative_tolerance|tolerance"):
        crm.verify(V, F, V2, F2, relative_tolerance=-1.0)
