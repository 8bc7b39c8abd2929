"""Diagnostics, the reference's errors and the warnings as Python values, matching the run's physics."""
import sphsandbox as sph


def test_diagnostics_conserve_energy_and_momentum_in_sod():
    w = sph.World("sod", set={"scene.n_left": 400})
    e0 = w.diagnostics()["E_tot"]
    w.run_to(0.1)
    d = w.diagnostics()
    assert d["t"] == 0.1 and d["step"] == w.steps
    assert abs(d["E_tot"] - e0) < 1e-4 * abs(e0)  # the tube's walls do no work: energy is kept
    # the end walls push with p_L = 1 and p_R = 0.1 until a wave reaches them: P_x = (p_L - p_R) t
    assert abs(d["P"][0] - 0.9 * 0.1) < 0.01 * 0.09


def test_errors_against_the_exact_riemann_solution():
    w = sph.World("sod", set={"scene.n_left": 400})
    w.run_to(0.2)
    e = w.errors()
    assert e["valid"]
    assert 0.0 < e["L1_rho"] < 0.01  # the README's Sod error is 3e-3 at n = 400
    assert "L1_v" in e and "L1_p" in e


def test_errors_empty_without_a_reference():
    w = sph.World("box_lattice")  # a periodic lattice at rest: no reference
    assert w.errors() == {}


def test_warnings_name_a_reference_assumption_and_none_at_the_defaults():
    w = sph.World("sod", set={"scene.n_left": 100})  # the reference's error bounds assume n_left >= 400
    w.run_to(0.01)
    kinds = [x["kind"] for x in w.warnings()]
    assert "assumption" in kinds and "n_left" in w.warnings()[kinds.index("assumption")]["message"]
    w = sph.World("sod")
    w.run_to(0.01)
    assert w.warnings() == []


def test_dfsph_solves_are_reported_and_hold_the_density():
    """DFSPH's columns of diagnostics.csv: its mean density error stays within liquid.dfsph_eta (0.1%), and
    the inviscid drop keeps its kinetic energy (there is no internal energy: the pressure does no net work
    on an incompressible flow) within 2%."""
    w = sph.World("elliptical_drop_dfsph", set={"scene.dx": 0.05})
    e0 = w.diagnostics()["E_kin"]
    worst = 0.0
    while w.time < 0.002 - 1e-12:
        w.step(0.002 - w.time)
        worst = max(worst, w.diagnostics()["dfsph_error"])
    d = w.diagnostics()
    assert d["dfsph_iter"] >= 0 and d["dfsph_div_iter"] >= 0
    assert 0.0 < worst <= 1e-3
    assert d["dfsph_error_max"] >= d["dfsph_error"]
    assert abs(d["E_kin"] / e0 - 1.0) < 0.02
