"""render(): the shared renderer's frame as an RGBA array, the same pixels as sph run --frames."""
import subprocess

import matplotlib.image
import numpy as np
import pytest
import sphsandbox as sph


def test_render_returns_an_rgba_image_with_content():
    w = sph.World("sedov", set={"scene.n_side": 24})
    w.run_to(0.01)
    img = w.render(width=320, height=240, color_by="u")
    assert img.shape == (240, 320, 4) and img.dtype == np.uint8
    colours = np.unique(img[..., :3].reshape(-1, 3), axis=0)
    assert len(colours) > 20  # discs in many colours, the colour bar, text


def test_render_equals_sph_run_frames(tmp_path, sph_bin):
    r = subprocess.run([sph_bin, "run", "sod", "--set", "scene.n_left=200", "--until", "0.1", "--frames", str(tmp_path / "f"),
                        "--every", "0.1", "--size", "640x360", "--color-by", "p"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    png = matplotlib.image.imread(str(tmp_path / "f" / "frame_00001.png"))
    w = sph.World("sod", set={"scene.n_left": 200})
    w.run_to(0.1)  # the steps of sph run --until 0.1 (outputs every time.dt_out = 0.05 on the way)
    img = w.render(width=640, height=360, color_by="p")
    ref = np.rint(png[..., :3] * 255).astype(np.uint8)
    assert np.array_equal(img[..., :3], ref)


def test_render_bad_field_or_size_raises_value_error():
    w = sph.World("sod", set={"scene.n_left": 100})
    with pytest.raises(ValueError, match="no_field"):
        w.render(color_by="no_field")
    with pytest.raises(ValueError, match="width"):
        w.render(width=4, height=4)
    with pytest.raises(ValueError, match="cmap"):
        w.render(cmap="rainbow")


def test_render_3d_cut_and_orbit_change_the_picture_and_bad_ones_raise():
    w = sph.World("hydrostatic_tank_3d")
    full = w.render(width=320, height=240, color_by="p")
    cut = w.render(width=320, height=240, color_by="p", cut="y=0.0")  # the near half removed: the water shows
    turned = w.render(width=320, height=240, color_by="p", yaw=120.0)
    assert (full != cut).any(axis=2).sum() > 1000 and (full != turned).any(axis=2).sum() > 1000
    with pytest.raises(ValueError, match="cut"):
        w.render(cut="w=1")
    with pytest.raises(ValueError, match="pitch"):
        w.render(pitch=95.0)
