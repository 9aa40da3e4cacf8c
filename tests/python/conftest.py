"""Shared fixtures of the Python module's tests (CTest sets PYTHONPATH to the build tree's package
folder, SEFLEX_BIN to the seflex command and SEFLEX_SOURCE_DIR to the repository)."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("SEFLEX_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
VALIDATION = SOURCE / "tests" / "data" / "validation"


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE


def seflex_command(*args, cwd=None):
    """Run the seflex command; returns the CompletedProcess (text)."""
    exe = os.environ.get("SEFLEX_BIN")
    if not exe:
        pytest.skip("SEFLEX_BIN is not set (run through ctest)")
    return subprocess.run([exe, *map(str, args)], cwd=cwd, capture_output=True, text=True, check=False)
