"""Shared fixtures of the Python module's tests: the module itself and the CLI beside it."""
import os
import pathlib
import shutil

import pytest

import envcrust

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    """The envcrust program of the same build (ctest sets ENVCRUST_BINARY), to compare with."""
    binary = os.environ.get("ENVCRUST_BINARY") or str(ROOT / "build" / "envcrust")
    if not os.access(binary, os.X_OK):
        pytest.skip(f"no envcrust program at {binary} (set ENVCRUST_BINARY)")
    return binary


@pytest.fixture(scope="session")
def moebius_points():
    """10,000 samples of the built-in Moebius strip (seed 1), as `envcrust sample moebius` draws them."""
    return envcrust.sample("moebius", 10000, seed=1)
