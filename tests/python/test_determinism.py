"""Python's runs are sph run's runs: the same particle files byte for byte, and the same for any thread count."""
import subprocess

import numpy as np
import sphsandbox as sph
from conftest import particle_csv


def run_sph(sph_bin, out, scene, sets, until):
    cmd = [sph_bin, "run", scene, "--until", str(until), "--out", str(out)]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def check_same_files(tmp_path, sph_bin, scene, sets, until, dt_out):
    run_sph(sph_bin, tmp_path / "o", scene, sets + ["dt_out=%r" % dt_out], until)
    w = sph.World(scene, set=sets)
    k = 0
    while True:
        text = (tmp_path / "o" / ("particles_%05d.csv" % k)).read_text()
        header = text.split("\n", 1)[0].split(",")
        kind = header[-1] == "kind"
        assert particle_csv(w, header[:-1] if kind else header, kind) == text, "particles_%05d.csv" % k
        k += 1
        if w.time >= until * (1 - 1e-12):
            break
        w.run_to(min(until, k * dt_out))
    assert k >= 3


def test_particle_files_equal_sph_run_sedov(tmp_path, sph_bin):
    check_same_files(tmp_path, sph_bin, "sedov", ["scene.n_side=24"], 0.01, 0.004)


def test_particle_files_equal_sph_run_dam_break_with_walls(tmp_path, sph_bin):
    check_same_files(tmp_path, sph_bin, "dam_break", ["scene.dx=0.04"], 0.05, 0.02)


def test_same_result_on_one_and_two_threads():
    runs = []
    for threads in (1, 2):
        sph.set_threads(threads)
        w = sph.World("sedov", set={"scene.n_side": 30})
        w.run_to(0.005)
        runs.append([w.by_id(k) for k in ("x", "y", "vx", "vy", "rho", "u")])
    sph.set_threads(2)
    for a, b in zip(*runs):
        assert np.array_equal(a, b)
