"""Shared fixtures of the sphsandbox tests: the module (from SPH_PYTHON_DIR, the build's python folder) and
the `sph` program (SPH_BIN) for the comparisons against `sph run`. ctest sets both (tests/python/CMakeLists.txt)."""
import os
import sys

import pytest

sys.path.insert(0, os.environ.get("SPH_PYTHON_DIR", os.path.join(os.path.dirname(__file__), "../../build/python")))


@pytest.fixture(scope="session")
def sph_bin():
    path = os.environ.get("SPH_BIN", os.path.join(os.path.dirname(__file__), "../../build/app/headless/sph"))
    if not os.path.exists(path):
        pytest.fail("SPH_BIN: no sph program at " + path)
    return path


def particle_csv(world, columns, kind):
    """The text of `sph run`'s particle file for this state: the header's columns in id order, each value as
    C's %.15g (Python's % formatting gives the same digits), kind as 0/1 when the scene has walls."""
    values = [world.by_id(c) for c in columns]
    walls = world.by_id("kind") if kind else None
    lines = [",".join(columns + (["kind"] if kind else []))]
    for r in range(world.n):
        row = [str(int(values[0][r]))] + ["%.15g" % v[r] for v in values[1:]]
        if kind:
            row.append("1" if walls[r] == 1 else "0")
        lines.append(",".join(row))
    return "\n".join(lines) + "\n"
