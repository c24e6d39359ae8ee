"""The GIL is released while texsplat works; progress callbacks, tqdm and Ctrl-C."""

import signal
import threading
import time

import numpy as np
import pytest

import texsplat
from conftest import blob


def test_other_threads_run_while_rendering():
    volume = blob(96)
    ticks = []
    rendering = threading.Event()
    done = threading.Event()

    def count():
        rendering.wait()
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        rendering.set()
        start = time.perf_counter()
        texsplat.render(volume, size=(512, 512))
        end = time.perf_counter()
    finally:
        done.set()
        counter.join()
    during = [t for t in ticks if start < t < end]
    # A thread blocked on the GIL would tick once per switch interval (5 ms) at best, and not at
    # all while one C++ call holds it.
    assert end - start > 0.05
    assert len(during) > 0.3 * (end - start) / 0.001 * 0.5, (len(during), end - start)


def test_progress_is_reported_and_may_cancel():
    volume = blob(64)
    reports = []
    texsplat.render(volume, size=(64, 64), progress=lambda step, f: reports.append((step, f)))
    steps = {step for step, _ in reports}
    assert any("classif" in step for step in steps), steps
    assert all(0.0 <= f <= 1.0 for _, f in reports)
    with pytest.raises(texsplat.Cancelled, match="cancelled"):
        texsplat.render(volume, size=(64, 64), progress=lambda step, f: False)
    with pytest.raises(ZeroDivisionError):
        texsplat.render(volume, size=(64, 64), progress=lambda step, f: 1 / 0)
    with pytest.raises(TypeError, match="progress: expected a callable"):
        texsplat.render(volume, progress=3)


def test_tqdm_shows_the_steps(capsys):
    pytest.importorskip("tqdm")
    image = texsplat.render(blob(64), size=(64, 64), progress=True)
    assert image.width == 64
    assert "%" in capsys.readouterr().err


def test_ctrl_c_cancels_a_long_render():
    volume = blob(160)
    # A kernel timer raises the signal 0.2 s into the render, with Ctrl-C's handler (a thread
    # calling os.kill needs the GIL first, and on a loaded machine it got it only after the
    # render: the signal then came too late). Python runs the handler at the next progress
    # report, as it would SIGINT's.
    previous = signal.signal(signal.SIGALRM, signal.default_int_handler)
    start = time.perf_counter()
    signal.setitimer(signal.ITIMER_REAL, 0.2)
    try:
        with pytest.raises(KeyboardInterrupt):
            texsplat.render(volume, size=(1024, 1024), max_splats=0)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    # Cancelled at the next report, not at the end of the render.
    assert time.perf_counter() - start < 3.0
    # The next render starts afresh.
    assert texsplat.render(blob(16), size=(16, 16)).width == 16
