"""Fields as NumPy views over the engine's storage: no copy, read-only, the real particles, by id on request."""
import numpy as np
import pytest
import sphsandbox as sph


@pytest.fixture
def sedov():
    w = sph.World("sedov", set={"scene.n_side": 24})
    w.run_to(0.002)
    return w


def test_field_is_a_view_of_the_engine_storage(sedov):
    for name in ("x", "vy", "rho", "h", "u", "m", "id"):
        a = sedov.field(name)
        assert a.__array_interface__["data"][0] == sedov.address(name), name
        assert not a.flags.owndata


def test_views_are_read_only_and_cover_the_real_particles(sedov):
    x = sedov.field("x")
    assert x.shape == (sedov.n,) and x.dtype == np.float64
    with pytest.raises(ValueError):
        x[0] = 1.0
    assert sedov.field("id").dtype == np.int64 and sedov.field("kind").dtype == np.uint8


def test_view_keeps_the_world_alive():
    rho = sph.World("sod", set={"scene.n_left": 100}).field("rho")
    del_world_then_read = float(rho.sum())  # the world object is gone from Python but the view's base holds it
    assert del_world_then_read > 0


def test_field_names_list_only_allocated_fields_and_unknown_raises_key_error(sedov):
    names = sedov.field_names()
    assert {"x", "y", "vx", "rho", "h", "u", "p", "m"} <= set(names)
    assert "drhodt" not in names  # a gas scene's density is a summation, not the continuity equation
    with pytest.raises(KeyError, match="drhodt"):
        sedov.field("drhodt")


def test_by_id_orders_rows_by_id(sedov):
    ids = sedov.by_id("id")
    assert np.array_equal(ids, np.sort(sedov.field("id")))
    order = np.argsort(sedov.field("id"))
    assert np.array_equal(sedov.by_id("rho"), sedov.field("rho")[order])
    assert sedov.by_id("rho").flags.owndata  # a copy, kept across steps


def test_fields_hold_the_physics_mass_and_energy(sedov):
    # Sedov: total mass = rho0 * area of the periodic unit box; E_kin + E_int from the arrays = diagnostics
    m, u, vx, vy = (sedov.field(k) for k in ("m", "u", "vx", "vy"))
    d = sedov.diagnostics()
    assert abs(m.sum() - 1.0) < 1e-12
    assert abs(0.5 * (m * (vx ** 2 + vy ** 2)).sum() - d["E_kin"]) < 1e-12 * max(1.0, d["E_kin"])
    assert abs((m * u).sum() - d["E_int"]) < 1e-12 * max(1.0, d["E_int"])


def test_generation_tells_when_views_are_stale(sedov):
    g = sedov.generation
    sedov.field("rho")
    assert sedov.generation == g  # reading changes nothing
    sedov.step()
    assert sedov.generation != g
