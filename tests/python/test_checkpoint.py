"""save_state / load_state: the checkpoint format of sph run; a loaded world continues bit for bit."""
import os

import numpy as np
import pytest
import sphsandbox as sph


def test_loaded_state_continues_bitwise(tmp_path):
    a = sph.World("sedov", set={"scene.n_side": 20})
    a.run_to(0.003)
    path = str(tmp_path / "state.sph")
    a.save_state(path)
    b = sph.World.load_state(path)
    assert b.time == a.time and b.steps == a.steps
    a.run_to(0.006)
    b.run_to(0.006)
    for name in ("x", "y", "vx", "rho", "u", "h"):
        assert np.array_equal(a.by_id(name), b.by_id(name)), name


def test_sph_run_checkpoint_loads_with_the_state_python_reaches(tmp_path, sph_bin):
    import subprocess
    a = sph.World("sod", set={"scene.n_left": 100})
    a.run_to(0.05)
    a.save_state(str(tmp_path / "s.sph"))
    out = subprocess.run([sph_bin, "run", "sod", "--set", "scene.n_left=100", "--until", "0.05", "--out", str(tmp_path / "o"),
                          "--checkpoint-every", "0.05"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    # the world part of sph run's checkpoint is the same bytes as Python's at the same time
    b = sph.World.load_state(str(tmp_path / "o" / "checkpoint.sph"))
    assert b.time == a.time
    assert np.array_equal(a.by_id("x"), b.by_id("x")) and np.array_equal(a.by_id("u"), b.by_id("u"))


def test_missing_or_damaged_checkpoint_raises_naming_the_file(tmp_path):
    with pytest.raises(sph.CheckpointError, match="nothing_here.sph"):
        sph.World.load_state(str(tmp_path / "nothing_here.sph"))
    bad = tmp_path / "bad.sph"
    bad.write_bytes(b"SPHCHKPT" + os.urandom(64))
    with pytest.raises(sph.CheckpointError, match="bad.sph"):
        sph.World.load_state(str(bad))
    with pytest.raises(OSError):  # CheckpointError is an OSError
        sph.World.load_state(str(bad))
