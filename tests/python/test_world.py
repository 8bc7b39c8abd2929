"""World: built from a scene name with overrides, stepped, its parameters changed; errors as exceptions."""
import math
import re

import pytest
import sphsandbox as sph


def test_scenes_lists_the_built_in_scenes():
    names = sph.scenes()
    assert "sod" in names and "sedov" in names and "dam_break" in names
    assert len(names) == len(set(names)) >= 30


def test_world_from_scene_name_with_dict_overrides():
    w = sph.World("sod", set={"scene.n_left": 200, "kernel.type": "M6"})
    assert w.scene == "sod" and w.dim == 1 and w.time == 0.0 and w.steps == 0
    assert w.n == w.n_fluid > 200  # 200 on the left and more on the right
    assert '"kernel.type": "M6"' in w.config_json()


def test_list_overrides_apply_in_order_like_sph_run_set():
    w = sph.World("sod", set=["kernel.type=M6", "kernel.type=M5"])
    assert '"kernel.type": "M5"' in w.config_json()


def test_unknown_scene_raises_config_error_naming_it():
    with pytest.raises(sph.ConfigError, match="no_such_scene"):
        sph.World("no_such_scene")


def test_unknown_key_raises_config_error_naming_the_key():
    with pytest.raises(sph.ConfigError, match="kernel.typo"):
        sph.World("sod", set={"kernel.typo": "M6"})


def test_bad_value_raises_config_error_naming_the_key():
    with pytest.raises(sph.ConfigError, match="kernel.type"):
        sph.World("sod", set={"kernel.type": "NOT_A_KERNEL"})
    with pytest.raises(ValueError):  # ConfigError is a ValueError
        sph.World("sod", set=["cfl"])


def test_step_advances_time_and_run_to_lands_on_t():
    w = sph.World("sod", set={"scene.n_left": 100})
    w.step()
    assert w.steps == 1 and 0.0 < w.time < 0.01
    w.run_to(0.05)
    assert w.time == 0.05
    w.step(dt_max=1e-5)
    assert math.isclose(w.time, 0.05 + 1e-5, rel_tol=1e-12)


def test_run_to_refuses_a_time_before_now_or_not_finite():
    w = sph.World("sod", set={"scene.n_left": 100})
    w.run_to(0.01)
    for t in (0.005, float("inf"), float("nan")):
        with pytest.raises(sph.ConfigError, match="run_to"):
            w.run_to(t)
    assert w.time == 0.01


def test_set_params_takes_effect_and_refuses_scene_values():
    # the Courant factor is live: from the same state, the next step is shorter in proportion (dt = cfl h / v_sig;
    # measured 2.998x for 3x: the change re-evaluates the rates, which move in the 4th digit)
    a, b = (sph.World("sod", set={"scene.n_left": 100}) for _ in range(2))
    a.run_to(0.01)
    b.run_to(0.01)
    cfl0 = float(re.search(r'"time.cfl": ([0-9.e+-]+)', a.config_json()).group(1))
    b.set_params({"cfl": cfl0 / 3})
    a.step()
    b.step()
    assert math.isclose(b.diagnostics()["dt"], a.diagnostics()["dt"] / 3, rel_tol=0.01)
    with pytest.raises(sph.ConfigError, match="scene.n"):
        b.set_params({"scene.n_left": 50})


def test_divergence_raises_diverged_error():
    # a Sod tube with no artificial viscosity and a tiny h blows up (NaN or a finite blow-up): the engine stops
    w = sph.World("sod", set={"visc.alpha": 0, "visc.beta": 0, "cfl": 2.0})
    with pytest.raises(sph.DivergedError):
        w.run_to(0.2)


def test_repr_names_scene_time_and_size():
    w = sph.World("sod", set={"scene.n_left": 100})
    assert repr(w).startswith("<sphsandbox.World sod t=0")
