"""What the module's tests share: the `plumbago` program they compare with ($PLUMBAGO_CLI,
set by ctest; else build/plumbago) and the repository root."""
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
MODELS = ROOT.parent / "shared" / "models"


def cli(*args, check=True):
    """Runs the program with `args`; returns the finished process (stdout and stderr as text)."""
    program = os.environ.get("PLUMBAGO_CLI", str(ROOT / "build" / "plumbago"))
    result = subprocess.run([program] + [str(a) for a in args], capture_output=True, text=True, cwd=ROOT)
    if check and result.returncode != 0:
        raise AssertionError("plumbago %s failed (%d): %s" % (" ".join(map(str, args)), result.returncode,
                                                              result.stderr))
    return result


@pytest.fixture(params=["gpu", "reference"])
def backend(request):
    return request.param
