"""remesh()'s callbacks (progress, sizing), its time limit and Ctrl-C."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import cgal_conformal_remeshing as crm
from conftest import diagonal, paraboloid_disc


class Stop(Exception):
    pass


def test_progress_is_called_with_each_stage(remeshed_plate):
    messages = remeshed_plate[3]
    assert messages and all(isinstance(m, str) for m in messages)
    assert messages[0] == "checking the input"
    assert "segmenting into poly-annuli" in messages
    assert any(m.startswith("meshing") for m in messages) and "gluing" in messages


def test_an_exception_in_progress_stops_the_call():
    V, F = paraboloid_disc()
    messages = []

    def progress(message):
        messages.append(message)
        if message.startswith("segmenting"):
            raise Stop(message)

    with pytest.raises(Stop, match="segmenting"):
        crm.remesh(V, F, relative_edge_length=0.05, progress=progress)
    assert messages[-1].startswith("segmenting")  # nothing ran after it
    with pytest.raises(TypeError, match="callable"):
        crm.remesh(V, F, progress=42)


def test_sizing_is_honoured(plate):
    """Edges a third of the target where x < 0 on the plate (centred at the origin), the target
    elsewhere: the callable is called with k x 3 arrays and its lengths are used."""
    V, F = plate
    assert V[:, 0].min() < -50 and V[:, 0].max() > 50
    target = 0.03 * diagonal(V)
    shapes = set()

    def sizing(points):
        shapes.add((points.shape[1], points.dtype))
        return np.where(points[:, 0] < 0.0, target / 3.0, target)

    V2, F2, report = crm.remesh(V, F, target_edge_length=target, sizing=sizing)
    assert shapes == {(3, np.dtype(np.float64))}
    e = np.sort(np.concatenate([F2[:, [0, 1]], F2[:, [1, 2]], F2[:, [2, 0]]]), axis=1)
    e = np.unique(e, axis=0)
    middle = (V2[e[:, 0]] + V2[e[:, 1]]) / 2
    lengths = np.linalg.norm(V2[e[:, 0]] - V2[e[:, 1]], axis=1)
    fine = np.median(lengths[middle[:, 0] < -10.0])
    coarse = np.median(lengths[middle[:, 0] > 10.0])
    assert fine < 0.5 * target < 0.7 * coarse
    uniform = crm.remesh(V, F, target_edge_length=target)[0]
    assert len(V2) > 1.5 * len(uniform)


def test_an_exception_in_sizing_is_raised_again():
    V, F = paraboloid_disc()

    def sizing(points):
        raise Stop("from sizing")

    with pytest.raises(Stop, match="from sizing"):
        crm.remesh(V, F, relative_edge_length=0.05, sizing=sizing)
    with pytest.raises(ValueError, match="one length per point"):
        crm.remesh(V, F, relative_edge_length=0.05, sizing=lambda p: np.ones(len(p) + 1))


def test_time_limit_raises_timeout_error(plate):
    V, F = plate
    with pytest.raises(TimeoutError, match=r"maximum_running_time"):
        crm.remesh(V, F, time_limit=1e-9)
    # A limit reached while the patches are flattened: the call stops there.
    stages = []
    with pytest.raises(TimeoutError, match="the time limit of 0.2 s"):
        crm.remesh(V, F, relative_edge_length=0.005, time_limit=0.2, progress=stages.append)
    assert "gluing" not in stages
    # A generous limit changes nothing.
    limited = crm.remesh(V, F, relative_edge_length=0.04, time_limit=3600.0)
    unlimited = crm.remesh(V, F, relative_edge_length=0.04)
    np.testing.assert_array_equal(limited[1], unlimited[1])


def test_ctrl_c_in_a_callback_raises_keyboard_interrupt(plate):
    """SIGINT while remesh() runs: the call stops at the library's next time-limit check and
    raises KeyboardInterrupt; Python's handler is back afterwards and the next call works."""
    V, F = plate
    messages = []

    def progress(message):
        messages.append(message)
        if message.startswith("segmenting"):
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        crm.remesh(V, F, progress=progress)
    assert messages[-1].startswith("segmenting")  # stopped after the segmentation
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert len(crm.remesh(V, F, relative_edge_length=0.04)[1]) > 0


def test_ctrl_c_stops_the_work_promptly(plate):
    """SIGINT from another thread while the library computes, with the GIL released."""
    V, F = plate
    start = time.monotonic()
    stages = []
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            crm.remesh(V, F, relative_edge_length=0.003, progress=stages.append)
    finally:
        timer.cancel()
    elapsed = time.monotonic() - start
    assert "gluing" not in stages
    assert elapsed < 3.0, stages


def test_a_custom_sigint_handler_is_left_alone(plate):
    """With a handler of the program's own, SIGINT reaches it after the call, which completes."""
    V, F = plate
    received = []
    previous = signal.signal(signal.SIGINT, lambda number, frame: received.append(number))
    try:
        def progress(message):
            if message.startswith("segmenting"):
                os.kill(os.getpid(), signal.SIGINT)

        V2, F2, _ = crm.remesh(V, F, relative_edge_length=0.04, progress=progress)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert received == [signal.SIGINT] and len(F2) > 0
