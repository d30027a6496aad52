"""remesh(): a round trip on the shipped model, compared with the remesh_conformal tool on the
same input and options, and the options that change the output."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

import cgal_conformal_remeshing as crm
from conftest import PLATE, diagonal, edges, paraboloid_disc, read_off


def test_round_trip_keeps_the_surface(plate, remeshed_plate):
    V, F = plate
    V2, F2, report, _ = remeshed_plate
    assert V2.dtype == np.float64 and V2.shape == (report["output_vertices"], 3)
    assert F2.dtype == np.int64 and F2.shape == (report["output_faces"], 3)
    assert F2.min() >= 0 and F2.max() < len(V2)
    verification = crm.verify(V, F, V2, F2)
    assert verification["valid"], verification["summary"]
    before, after = crm.check(V, F), crm.check(V2, F2)
    assert after["valid"], after["summary"]
    assert after["total_genus"] == before["total_genus"]
    assert after["total_boundary_loops"] == before["total_boundary_loops"]
    assert report["target_edge_length"] == pytest.approx(0.01 * diagonal(V), rel=1e-12)


def test_round_trip_matches_the_tool(tmp_path, plate, remeshed_plate):
    """The module and the remesh_conformal tool remesh the same file with the same options into
    the same mesh: the same sizes, the same quality and the same distance to the input."""
    tool = os.environ.get("CGAL_CONFORMAL_REMESHING_TOOL")
    if not tool:
        pytest.skip("CGAL_CONFORMAL_REMESHING_TOOL is not set (CTest sets it)")
    out, report_file = tmp_path / "remeshed.off", tmp_path / "report.json"
    subprocess.run([tool, str(PLATE), str(out), "--quiet", "--report", str(report_file)], check=True)
    tool_report = json.loads(report_file.read_text())
    V, F = plate
    V2, F2, report, _ = remeshed_plate

    Vt, Ft = read_off(out)
    assert (len(V2), len(F2)) == (len(Vt), len(Ft))
    np.testing.assert_allclose(V2, Vt, rtol=0, atol=1e-12 * diagonal(V))
    np.testing.assert_array_equal(F2, Ft)

    quality = crm.quality(V2, F2, reference=(V, F))
    expected = tool_report["output_quality"]
    assert quality["number_of_faces"] == expected["faces"]
    for ours, theirs in [("minimum_angle", "minimum_angle"), ("maximum_angle", "maximum_angle"),
                         ("skewness", "equiangle_skewness"), ("aspect_ratio", "aspect_ratio"),
                         ("edge_length", "edge_length")]:
        for statistic in ("min", "mean", "max"):
            assert quality[ours][statistic] == pytest.approx(expected[theirs][statistic], rel=1e-9), (ours, statistic)
    for threshold, share in expected["share_with_minimum_angle_below"].items():
        assert quality["share_with_minimum_angle_below"][float(threshold)] == pytest.approx(share, abs=1e-12)
    fidelity = tool_report["fidelity"]
    assert quality["fidelity"]["relative_distance_to_reference"] == pytest.approx(
        fidelity["relative_hausdorff_to_reference"], rel=1e-6)
    assert quality["fidelity"]["relative_distance_from_reference"] == pytest.approx(
        fidelity["relative_hausdorff_from_reference"], rel=1e-6)
    assert quality["fidelity"]["self_intersects"] == fidelity["self_intersects"]

    segmentation = tool_report["segmentation"]
    assert report["number_of_patches"] == segmentation["patches"]
    assert report["feature_edges"] == segmentation["feature_edges"]
    assert report["statistics"]["boundary_curves"] == segmentation["boundary_curves"]
    assert report["target_edge_length"] == pytest.approx(tool_report["target_edge_length"], rel=1e-12)


def test_report_holds_the_library_reports(remeshed_plate):
    V2, _, report, _ = remeshed_plate
    for key in ("target_edge_length", "input", "input_crosses_itself", "number_of_patches", "plane_cuts",
                "patch_bisections", "feature_edges", "dangling_feature_edges", "narrow_strip_feature_edges",
                "features_dropped",
                "features_fallback_reason", "frontal_dropped", "frontal_fallback_reason",
                "self_intersection_refinements", "refined_boundary_curves", "split_diagonals",
                "output_vertices", "output_faces", "input_repairs", "statistics"):
        assert key in report, key
    assert report["output_vertices"] == len(V2)
    assert not report["input"]["repaired"] and not report["input_repairs"]["repaired"]
    statistics = report["statistics"]
    assert len(statistics["patches"]) >= report["number_of_patches"] > 0
    assert all(p["status"] == "SUCCESS" and p["embedding"]["is_embedding"] for p in statistics["patches"])
    assert statistics["max_newton_iterations"] == max(p["iterations"] for p in statistics["patches"])
    assert set(statistics["meshing_phases"]) >= {"planar_setup", "planar_refinement", "angle_passes"}


def test_target_edge_length_is_honoured():
    V, F = paraboloid_disc()
    h = 0.1
    V2, F2, report = crm.remesh(V, F, target_edge_length=h)
    assert report["target_edge_length"] == h
    lengths = np.linalg.norm(V2[edges(F2)[:, 0]] - V2[edges(F2)[:, 1]], axis=1)
    assert 0.7 * h < np.median(lengths) < 1.3 * h
    # A relative length is a fraction of the bounding-box diagonal.
    _, _, relative = crm.remesh(V, F, relative_edge_length=0.05)
    assert relative["target_edge_length"] == pytest.approx(0.05 * diagonal(V), rel=1e-12)


def test_chord_error_refines_where_the_surface_bends(plate):
    V, F = plate
    coarse = crm.remesh(V, F, relative_edge_length=0.04)
    adaptive = crm.remesh(V, F, relative_edge_length=0.04, chord_error=2e-4 * diagonal(V))
    assert len(adaptive[0]) > 1.2 * len(coarse[0])


def test_surface_distance_is_passed_on_and_reported(plate):
    """The default bound is a quarter of the target; a bound the output breaks is met by meshing
    again finer there, which adds vertices; 0 turns the check off."""
    V, F = plate
    _, _, default = crm.remesh(V, F, relative_edge_length=0.04)
    h = default["target_edge_length"]
    assert default["surface_distance_bound"] == pytest.approx(0.25 * h, rel=1e-12)
    assert 0.0 < default["largest_surface_distance"]
    _, _, off = crm.remesh(V, F, relative_edge_length=0.04, surface_distance=0.0)
    assert off["surface_distance_bound"] == 0.0 and off["largest_surface_distance"] == 0.0
    assert off["surface_distance_refinements"] == 0
    tight = 0.5 * default["largest_surface_distance"]
    V2, _, bounded = crm.remesh(V, F, relative_edge_length=0.04, surface_distance=tight)
    assert bounded["surface_distance_refinements"] >= 1
    assert bounded["places_beyond_surface_distance"] > 0
    assert bounded["largest_surface_distance"] < default["largest_surface_distance"]
    assert len(V2) > default["output_vertices"]
    for key in ("output_faces_beyond_surface_distance", "input_vertices_beyond_surface_distance",
                "input_edges_beyond_surface_distance", "input_faces_beyond_surface_distance"):
        assert key in bounded, key
    assert "seconds_surface_distance" in bounded["statistics"]
    # Where: the farthest sample, and the places still beyond (one per element beyond at most).
    assert len(default["largest_surface_distance_point"]) == 3
    lo, hi = V.min(axis=0) - h, V.max(axis=0) + h
    assert all(lo[k] <= default["largest_surface_distance_point"][k] <= hi[k] for k in range(3))
    places = bounded["places_still_beyond_surface_distance"]
    beyond = sum(bounded[key] for key in ("output_faces_beyond_surface_distance", "input_vertices_beyond_surface_distance",
                                          "input_edges_beyond_surface_distance", "input_faces_beyond_surface_distance"))
    assert (len(places) > 0) == (beyond > 0)
    assert all(len(p) == 3 for p in places)


def test_features_angle_is_passed_on(plate, remeshed_plate):
    """features_angle=0: no sharp feature, the segmentation cuts by planes instead."""
    _, _, without = crm.remesh(*plate, relative_edge_length=0.04, features_angle=0.0)
    assert without["feature_edges"] == 0 and remeshed_plate[2]["feature_edges"] > 0
    assert without["plane_cuts"] > 0


def test_parameters_out_of_range_raise_value_error():
    V, F = paraboloid_disc(4)
    with pytest.raises(ValueError, match="minimum angle"):
        crm.remesh(V, F, minimum_angle=50.0)
    with pytest.raises(ValueError, match="target edge length"):
        crm.remesh(V, F, target_edge_length=-1.0)
    with pytest.raises(ValueError, match="maximum running time"):
        crm.remesh(V, F, time_limit=-1.0)
    with pytest.raises(ValueError, match="surface distance"):
        crm.remesh(V, F, surface_distance=-1.0)


def test_repairs_are_reported():
    """An isolated vertex and a reversed face: repaired like the tool repairs a file, and said."""
    V, F = paraboloid_disc(6)
    V = np.vstack([V, [[5.0, 5.0, 5.0]]])
    F = F.copy()
    F[3] = F[3, ::-1]
    with pytest.raises(ValueError, match="isolated vertex"):
        crm.remesh(V, F, repair=False)
    V2, F2, report = crm.remesh(V, F, relative_edge_length=0.05)
    repairs = report["input_repairs"]
    assert repairs["removed_isolated_vertices"] == 1 and repairs["reoriented_faces"] == 1
    assert crm.verify(V[:-1], paraboloid_disc(6)[1], V2, F2)["valid"]


def test_example_script_runs(tmp_path):
    script = os.environ.get("CGAL_CONFORMAL_REMESHING_EXAMPLE")
    if not script:
        pytest.skip("CGAL_CONFORMAL_REMESHING_EXAMPLE is not set (CTest sets it)")
    out = tmp_path / "plate_remeshed.off"
    run = subprocess.run([sys.executable, script, str(PLATE), str(out), "--relative-edge-length", "0.04"],
                         check=True, capture_output=True, text=True)
    V2, F2 = read_off(out)
    assert f"{len(V2)} vertices" in run.stdout
    assert crm.check(V2, F2)["valid"]
