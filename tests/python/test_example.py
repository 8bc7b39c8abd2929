"""The notebook-style example runs as a script and shows the Sod tube converging (seed 000: L1 ~ n^-1 at best
for a shock; the README's tube errors fall 1.6-1.9x per doubling)."""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "../../app/python/examples/sod_convergence.py")


def test_sod_convergence_example_runs_and_converges(tmp_path):
    env = dict(os.environ, PYTHONPATH=os.environ.get("SPH_PYTHON_DIR", os.path.join(HERE, "../../build/python")))
    out = tmp_path / "conv.png"
    r = subprocess.run([sys.executable, SCRIPT, "--n", "50,100,200", "--out", str(out)], capture_output=True,
                       text=True, env=env)
    assert r.returncode == 0, r.stderr
    order = float(re.search(r"order=([0-9.]+)", r.stdout).group(1))
    assert 0.5 < order < 1.5, r.stdout
    assert out.stat().st_size > 10000 and out.read_bytes()[:4] == b"\x89PNG"
