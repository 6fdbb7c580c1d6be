"""`import prism` (issue 33), run by ctest with the module's build directory on PYTHONPATH:
the module renders what prism-render renders, bit for bit; bad scenes raise SceneError at their
line; arrays are what the documentation says; renders release the GIL; a Renderer reuses its
tracer across cameras and frames."""
import os
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import OpenImageIO as oiio
import pytest

import prism

SCENES = Path(os.environ["PRISM_SCENES_DIR"])
RENDER = os.environ["PRISM_RENDER_EXE"]


@pytest.fixture(scope="module")
def renderer():
    return prism.Renderer(validation=True)


def read_exr(path):
    image = oiio.ImageBuf(str(path))
    assert not image.has_error, image.geterror()
    names = list(image.spec().channelnames)
    pixels = image.get_pixels(oiio.FLOAT)
    return {name: pixels[:, :, k] for k, name in enumerate(names)}


def render_cli(tmp_path, scene, *args):
    out = tmp_path / "cli.exr"
    subprocess.run([RENDER, str(scene), "-o", str(out), "--quiet", *args], check=True)
    return read_exr(out)


def test_the_module_renders_what_prism_render_renders(renderer, tmp_path):
    scene = prism.load(str(SCENES / "showcase.scene"))
    images = renderer.render(scene, 64, 48, spp=2, depth=3, aovs=("rgb", "z", "n"))
    cli = render_cli(tmp_path, SCENES / "showcase.scene", "--size", "64x48", "--spp", "2",
                     "--depth", "3", "--aov", "z,normal")
    for k, channel in enumerate("RGB"):
        assert np.array_equal(images["rgb"][:, :, k], cli[channel]), channel
    assert np.array_equal(images["z"][:, :, 0], cli["Z"])
    for k, channel in enumerate(("N.X", "N.Y", "N.Z")):
        assert np.array_equal(images["n"][:, :, k], cli[channel]), channel


def test_a_frame_set_from_python_is_prism_render_frame(renderer, tmp_path):
    scene = prism.load(str(SCENES / "showcase-turntable.scene"))
    assert scene.animated
    scene.frame = 37
    rgb = renderer.render(scene, 48, 36, depth=2)["rgb"]
    cli = render_cli(tmp_path, SCENES / "showcase-turntable.scene", "--frames", "37", "--size",
                     "48x36", "--depth", "2")
    assert np.array_equal(rgb[:, :, 0], cli["R"])
    assert renderer.last_stats["tracer_ms"] > 0  # a new scene: a new tracer
    scene.frame = 1
    first = renderer.render(scene, 48, 36, depth=2)["rgb"]
    assert renderer.last_stats["tracer_ms"] == 0  # the same tracer, another camera
    assert not np.array_equal(first, rgb)


def test_arrays_are_c_contiguous_float32_height_width_channels(renderer):
    # A unit sphere 5 units ahead: hit in the middle, missed in the corners.
    scene = prism.Scene.from_string("camera eye 0 0 5 look 0 0 0 fov 40\nsphere 0 0 0 1\n")
    images = renderer.render(scene, 40, 30, aovs=("rgb", "z", "n"))
    assert sorted(images) == ["n", "rgb", "z"]
    for name, channels in (("rgb", 3), ("z", 1), ("n", 3)):
        a = images[name]
        assert a.dtype == np.float32 and a.flags["C_CONTIGUOUS"], name
        assert a.shape == (30, 40, channels), name
    z, n = images["z"][:, :, 0], images["n"]
    assert np.isinf(z[0, 0]) and np.all(n[0, 0] == 0), "a corner misses"
    assert abs(z[15, 20] - 4.0) < 0.01, "the sphere's front is 4 units away"
    assert n[15, 20, 2] > 0.99, "its normal faces the camera"
    stats = renderer.last_stats
    assert stats["rays"]["primary"] == 40 * 30
    assert stats["trace_ms"] > 0 and stats["mrays_per_s"] > 0


def test_the_camera_is_settable_and_setting_it_back_gives_the_same_bits(renderer):
    scene = prism.load(str(SCENES / "scene.scene"))
    before = renderer.render(scene, 40, 30)["rgb"]
    eye, look, fov = scene.camera.eye, scene.camera.look, scene.camera.fov
    scene.camera.look_at((eye[0] + 1.0, eye[1] + 0.5, eye[2]), look)
    scene.camera.fov = fov * 0.8
    moved = renderer.render(scene, 40, 30)["rgb"]
    assert not np.array_equal(moved, before)
    scene.camera.look_at(eye, look)
    scene.camera.fov = fov
    assert np.array_equal(renderer.render(scene, 40, 30)["rgb"], before)
    with pytest.raises(ValueError):
        scene.camera.fov = 180
    with pytest.raises(ValueError):
        scene.camera.look_at(eye, eye)


def test_a_bad_scene_raises_scene_error_at_its_line(tmp_path):
    bad = tmp_path / "bad.scene"
    bad.write_text("camera eye 0 0 5 look 0 0 0\nsphere 0 0 0\n")
    with pytest.raises(prism.SceneError) as caught:
        prism.load(str(bad))
    assert caught.value.file == str(bad)
    assert caught.value.line == 2
    assert "sphere" in caught.value.message and str(bad) + ":2:" in str(caught.value)
    with pytest.raises(prism.SceneError) as caught:
        prism.Scene.from_string("camera eye 0 0 5 look 0 0 0\nmesh missing.obj\n",
                                base_dir=str(tmp_path))
    assert caught.value.line == 2


def test_bad_arguments_raise_value_error(renderer):
    scene = prism.Scene.from_string("camera eye 0 0 5 look 0 0 0\nsphere 0 0 0 1\n")
    for kwargs in ({"width": 0}, {"spp": 0}, {"depth": 17}, {"aovs": ("rgb", "alpha")}):
        with pytest.raises(ValueError):
            renderer.render(scene, **{"width": 16, "height": 16, **kwargs})


def test_a_render_releases_the_gil(renderer):
    scene = prism.load(str(SCENES / "showcase.scene"))
    renderer.render(scene, 160, 120)  # the tracer made and compiled beforehand
    counted = 0
    done = threading.Event()

    def count():
        nonlocal counted
        while not done.is_set():
            counted += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    renderer.render(scene, 160, 120, spp=4)
    elapsed = time.monotonic() - start
    done.set()
    counter.join()
    # A thread that could not run while the render held the GIL would count once or twice.
    assert counted > 0.2 * elapsed * 1000, (counted, elapsed)


def test_help_and_version():
    assert prism.__version__.count(".") == 2
    for item in (prism, prism.load, prism.Renderer, prism.Renderer.render, prism.Scene,
                 prism.Camera, prism.SceneError):
        assert item.__doc__, item
