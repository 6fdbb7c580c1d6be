"""`import prism` (issue 33), run by ctest with the module's build directory on PYTHONPATH:
the module renders what prism-render renders, bit for bit (seeds too); bad scenes raise
SceneError at their line; arrays are what the documentation says; renders release the GIL; a
Renderer reuses its tracer across cameras and frames; last_stats has --stats' names; prism.write
writes what it is given; 200 renders do not grow the process; two Renderers in two threads
render what one does."""
import json
import os
import subprocess
import sys
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


def test_a_lean_build_renders_what_prism_render_lean_renders(renderer, tmp_path):
    scene = prism.load(str(SCENES / "bunny.scene"), build="lean", cache=False)
    images = renderer.render(scene, 64, 48, depth=2, aovs=("rgb", "z"))
    assert renderer.last_stats["grid_build"] == "lean"
    assert renderer.last_stats["scene_gpu_bytes"]["grid cell triangle"] <= 16, "ids, no copies"
    cli = render_cli(tmp_path, SCENES / "bunny.scene", "--size", "64x48", "--depth", "2",
                     "--aov", "z", "--grid-build", "lean")
    for k, channel in enumerate("RGB"):
        assert np.array_equal(images["rgb"][:, :, k], cli[channel]), channel
    assert np.array_equal(images["z"][:, :, 0], cli["Z"])
    full = prism.load(str(SCENES / "bunny.scene"), cache=False)
    renderer.render(full, 16, 12)
    assert renderer.last_stats["grid_build"] == "full"
    for bad in ("auto", "fast", ""):
        with pytest.raises(ValueError):
            prism.load(str(SCENES / "bunny.scene"), build=bad)
        with pytest.raises(ValueError):
            prism.Scene.from_string("sphere 0 0 0 1\n", build=bad)


def test_a_renderer_keeps_its_specialized_tracer_in_the_cache(tmp_path, monkeypatch):
    # The tracer's module folded for a scene's features is stored, and a later Renderer (a
    # script run again) reads it back instead of folding it: the same image either way.
    cache = tmp_path / "cache"
    monkeypatch.setenv("PRISM_CACHE_DIR", str(cache))
    scene = prism.load(str(SCENES / "rand50.scene"), cache=False)
    without = prism.Renderer(validation=True, cache=False).render(scene, 32, 24)["rgb"]
    assert not cache.exists(), "cache=False writes nothing"
    entries = []
    for _ in range(2):  # folded and stored, then read back (nothing new stored)
        stored = prism.Renderer(validation=True).render(scene, 32, 24)["rgb"]
        assert np.array_equal(stored, without)
        entries.append(sorted(p.name for p in cache.glob("spirv-*.bin")))
    assert entries[0] and entries[1] == entries[0]


def test_big_obj_files_are_kept_parsed_in_the_cache_and_render_the_same(renderer, tmp_path,
                                                                         monkeypatch):
    # A height field of 1.2 MB of OBJ text: over the 1 MiB that is worth caching.
    n = 136
    lines = [f"v {4 * i / (n - 1) - 2:.6f} {0.2 * np.sin(i * 0.3) * np.cos(j * 0.2):.6f} "
             f"{4 * j / (n - 1) - 2:.6f}" for j in range(n) for i in range(n)]
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i + 1
            lines += [f"f {a} {a + n} {a + 1}", f"f {a + 1} {a + n} {a + n + 1}"]
    (tmp_path / "field.obj").write_text("\n".join(lines) + "\n")
    assert (tmp_path / "field.obj").stat().st_size >= 1 << 20
    scene_path = tmp_path / "field.scene"
    scene_path.write_text("camera eye 0 3 4 look 0 0 0 fov 50\nlight 2 5 3 color 1 1 1\n"
                          "mesh field.obj smooth\n")
    cache = tmp_path / "cache"
    monkeypatch.setenv("PRISM_CACHE_DIR", str(cache))
    uncached = renderer.render(prism.load(str(scene_path), cache=False), 32, 24)["rgb"]
    assert not cache.exists(), "cache=False writes nothing"
    for _ in range(2):  # parsed and stored, then read back
        scene = prism.load(str(scene_path))
        assert np.array_equal(renderer.render(scene, 32, 24)["rgb"], uncached)
        assert len(list(cache.glob("obj-*.bin"))) == 1
    assert scene.grid_cache == "hit"


def test_a_frame_set_from_python_is_prism_render_frame(renderer, tmp_path):
    scene = prism.load(str(SCENES / "showcase-turntable.scene"))
    assert scene.animated
    scene.frame = 37
    rgb = renderer.render(scene, 48, 36, depth=2)["rgb"]
    cli = render_cli(tmp_path, SCENES / "showcase-turntable.scene", "--frames", "37", "--size",
                     "48x36", "--depth", "2")
    assert np.array_equal(rgb[:, :, 0], cli["R"])
    assert renderer.last_stats["phases_ms"]["tracer"] > 0  # a new scene: a new tracer
    scene.frame = 1
    first = renderer.render(scene, 48, 36, depth=2)["rgb"]
    assert renderer.last_stats["phases_ms"]["tracer"] == 0  # the same tracer, another camera
    assert not np.array_equal(first, rgb)


def test_a_frame_moves_keyed_instances_as_prism_render_does(renderer, tmp_path):
    path = SCENES / "moving-instances.scene"
    scene = prism.load(str(path), grid="regular")
    assert scene.animated and scene.last_frame == 48
    first = renderer.render(scene, 48, 36, depth=2)["rgb"]
    scene.frame = 30
    moved = renderer.render(scene, 48, 36, depth=2)["rgb"]
    cli = render_cli(tmp_path, path, "--frames", "30", "--size", "48x36", "--depth", "2",
                     "--grid", "regular")
    for k, channel in enumerate("RGB"):
        assert np.array_equal(moved[:, :, k], cli[channel]), channel
    assert not np.array_equal(first, moved)
    scene.frame = 1
    assert np.array_equal(renderer.render(scene, 48, 36, depth=2)["rgb"], first)


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
    for kwargs in ({"width": 0}, {"spp": 0}, {"depth": 17}, {"aovs": ("rgb", "alpha")},
                   {"seed": 2**24}):
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


def test_a_seed_draws_what_prism_render_draws_under_it(renderer, tmp_path):
    scene = prism.load(str(SCENES / "showcase.scene"))
    seeded = renderer.render(scene, 48, 36, spp=2, depth=2, seed=4242)["rgb"]
    assert renderer.last_stats["seed"] == 4242
    cli = render_cli(tmp_path, SCENES / "showcase.scene", "--size", "48x36", "--spp", "2",
                     "--depth", "2", "--seed", "4242")
    for k, channel in enumerate("RGB"):
        assert np.array_equal(seeded[:, :, k], cli[channel]), channel
    unseeded = renderer.render(scene, 48, 36, spp=2, depth=2)["rgb"]
    assert not np.array_equal(seeded, unseeded)
    assert renderer.last_stats["phases_ms"]["tracer"] == 0, "a seed needs no new tracer"


# What only a command's run reports: the CPU's walk counts of every image, the process's
# pipeline cache, a range's frames, and how its one load read the OBJ files (a render from
# Python does not load: prism.load did, perhaps long before).
COMMAND_ONLY = {"grid_cells_per_primary_ray", "grid_tests_per_primary_ray", "grid_counts_stopped",
                "pipeline_cache", "per_frame", "skipped", "obj_cache"}


def test_last_stats_has_the_names_and_figures_of_prism_render_stats(renderer, tmp_path):
    scene = prism.load(str(SCENES / "showcase.scene"))
    renderer.render(scene, 64, 48, spp=2, depth=3)
    stats = renderer.last_stats
    # A loaded scene serves any number of renders, so its grid is built in full, as the CLI's
    # is for images with 4 samples a primitive (a 64x48 image of the showcase has fewer).
    line = subprocess.run([RENDER, str(SCENES / "showcase.scene"), "-o", str(tmp_path / "s.exr"),
                           "--quiet", "--stats", "--size", "64x48", "--spp", "2", "--depth", "3",
                           "--grid-build", "full"],
                          check=True, capture_output=True, text=True).stdout
    cli = json.loads(line)
    assert set(cli) - COMMAND_ONLY <= set(stats), set(cli) - COMMAND_ONLY - set(stats)
    for key in ("width", "height", "region", "spp", "depth", "seed", "rays", "tiles",
                "primitives", "grid", "grid_cells", "grid_choice", "grid_build", "triangles",
                "scene_gpu_bytes", "backend", "device"):
        assert stats[key] == cli[key], key
    assert stats["scene"].endswith("showcase.scene")
    assert stats["trace_ms"] > 0 and stats["mrays_per_s"] > 0
    assert set(stats["phases_ms"]) == {"tracer", "frames", "readback", "arrays"}


def test_write_keeps_the_arrays_and_metadata(tmp_path):
    rng = np.random.default_rng(1)
    rgb = rng.random((30, 40, 3), dtype=np.float32) * 4.0  # radiance above 1 kept in EXR
    z = rng.random((30, 40, 1), dtype=np.float32)
    n = rng.random((30, 40, 3), dtype=np.float32)
    path = tmp_path / "out.exr"
    prism.write(str(path), rgb, z=z, n=n,
                metadata={"prism:note": "hello", "prism:count": 7, "prism:scale": 0.5})
    back = read_exr(path)
    for k, channel in enumerate("RGB"):
        assert np.array_equal(back[channel], rgb[:, :, k]), channel
    assert np.all(back["A"] == 1.0)
    assert np.array_equal(back["Z"], z[:, :, 0])
    for k, channel in enumerate(("N.X", "N.Y", "N.Z")):
        assert np.array_equal(back[channel], n[:, :, k]), channel
    spec = oiio.ImageBuf(str(path)).spec()
    assert spec.getattribute("prism:note") == "hello"
    assert spec.getattribute("prism:count") == 7
    assert spec.getattribute("prism:scale") == 0.5
    # A PNG: sRGB, 8 bits, clamped; float64 and non-contiguous input are taken as they come.
    png = tmp_path / "out.png"
    prism.write(str(png), np.asfortranarray(rgb.astype(np.float64)))
    assert oiio.ImageBuf(str(png)).spec().width == 40


def test_write_refuses_bad_arrays_and_paths_and_leaves_nothing(tmp_path):
    good = np.zeros((4, 5, 3), dtype=np.float32)
    for rgb, z in ((np.zeros((4, 5, 2)), None), (np.zeros(5), None), (good, np.zeros((4, 6))),
                   (good, np.zeros((4, 5, 3)))):
        with pytest.raises(ValueError):
            prism.write(str(tmp_path / "a.exr"), rgb, z=z)
    with pytest.raises(ValueError):
        prism.write(str(tmp_path / "a.exr"), good, metadata={"prism:list": [1, 2]})
    with pytest.raises(RuntimeError) as caught:
        prism.write(str(tmp_path / "a.tga"), good)
    assert "a.tga" in str(caught.value)
    with pytest.raises(RuntimeError):
        prism.write(str(tmp_path / "missing" / "a.exr"), good)
    assert list(tmp_path.iterdir()) == []


def rss_kib():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS in /proc/self/status")


def assert_rss_flat(render, warm_up, count):
    """render(i) `count` times after `warm_up` times: RSS grows less than 5%."""
    for i in range(warm_up):
        render(i)
    before = rss_kib()
    for i in range(count):
        render(i)
    after = rss_kib()
    assert after < 1.05 * before, (before, after)


def test_200_renders_do_not_grow_the_process(renderer):
    # Cameras, seeds and sample counts change every render, on one tracer. Validation is on: a
    # message would raise. RSS measured after each render stays flat between tracers (a few
    # bytes a render); it moves only when a tracer is made (below).
    scene = prism.load(str(SCENES / "showcase.scene"))
    eye, look = scene.camera.eye, scene.camera.look

    def render(i):
        scene.camera.look_at((eye[0] + 0.01 * (i % 17), eye[1], eye[2]), look)
        return renderer.render(scene, 64, 48, spp=1 + i % 3, depth=3, seed=i,
                               aovs=("rgb", "z", "n"))

    assert_rss_flat(render, warm_up=20, count=200)  # warm-up: allocators and caches fill


def test_tracers_made_again_and_again_do_not_grow_the_process(renderer):
    # Each render switches the AOVs, which makes a new tracer: its arrays and pipelines freed
    # and made again. Measured: RSS climbs for the first dozen tracers (lavapipe's and the
    # allocator's pools) and then stays within a few KiB.
    scene = prism.load(str(SCENES / "showcase.scene"))

    def render(i):
        renderer.render(scene, 64, 48, depth=3, aovs=("rgb", "z") if i % 2 else ("rgb",))
        assert renderer.last_stats["phases_ms"]["tracer"] > 0

    assert_rss_flat(render, warm_up=20, count=40)


def test_two_renderers_in_two_threads_render_what_one_renders():
    frames = [1, 13, 25, 37]

    def render_frames(renderer, chosen, into):
        # Each thread its own Scene: the frame (the camera) belongs to a Scene.
        own = prism.load(str(SCENES / "showcase-turntable.scene"))
        for frame in chosen:
            own.frame = frame
            into[frame] = renderer.render(own, 48, 36, spp=2, depth=2)["rgb"]

    one = {}
    render_frames(prism.Renderer(), frames, one)
    two = {}
    threads = [threading.Thread(target=render_frames, args=(prism.Renderer(), frames[k::2], two))
               for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert sorted(two) == frames
    for frame in frames:
        assert np.array_equal(two[frame], one[frame]), frame


def test_openimageio_loads_only_when_an_image_file_is_touched(tmp_path):
    # OpenImageIO's ~260 libraries take 0.4-1 s to load: `import prism` and an untextured
    # render do without them (engine/io/oiio_plugin.h); a texture or prism.write loads them.
    code = """
import numpy as np, prism
def loaded():
    return "libOpenImageIO" in open("/proc/self/maps").read()
print(loaded())
scene = prism.Scene.from_string("camera eye 0 0 5 look 0 0 0\\nsphere 0 0 0 1\\n")
rgb = prism.Renderer().render(scene, 16, 12)["rgb"]
print(loaded())
prism.write(%r, rgb)
print(loaded())
""" % str(tmp_path / "out.exr")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["False", "False", "True"]
    assert (tmp_path / "out.exr").exists()
