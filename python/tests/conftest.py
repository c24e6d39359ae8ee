"""Shared fixtures: small volumes, and the texsplat command line to compare with."""

import os
import pathlib
import shutil

import numpy as np
import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def blob(n=32, dtype=np.float32):
    """A smooth (z, y, x) volume: one Gaussian blob off the centre."""
    z, y, x = np.mgrid[0:n, 0:n, 0:n].astype(np.float64) / (n - 1)
    return np.exp(-((x - 0.4) ** 2 + (y - 0.5) ** 2 + (z - 0.55) ** 2) / 0.05).astype(dtype)


@pytest.fixture
def volume():
    return blob()


@pytest.fixture(scope="session")
def cli():
    """The texsplat command: $TEXSPLAT_CLI, else one built in this checkout (ci or release)."""
    candidates = [os.environ.get("TEXSPLAT_CLI"),
                  REPOSITORY / "build" / "ci" / "apps" / "texsplat",
                  REPOSITORY / "build" / "release" / "apps" / "texsplat",
                  shutil.which("texsplat")]
    for candidate in candidates:
        if candidate and os.access(candidate, os.X_OK):
            return str(candidate)
    pytest.skip("no texsplat command line (set TEXSPLAT_CLI)")
