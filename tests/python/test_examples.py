"""The examples of examples/python/ (issue 33) run as a user runs them, at small sizes, and what
they make is checked: the contact sheet is a picture, the PSNR curve rises with the samples, the
data set's files hold the views its index describes."""
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import OpenImageIO as oiio

import prism

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "python"
SCENES = Path(os.environ["PRISM_SCENES_DIR"])


def run(script, *args):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_turntable_contact_sheet(tmp_path):
    sheet = tmp_path / "sheet.png"
    out = run("turntable_contact_sheet.py", "--frames", 6, "--size", "64x48", "--spp", 1,
              "--columns", 3, "-o", sheet)
    assert "6 frames" in out
    image = oiio.ImageBuf(str(sheet))
    assert not image.has_error, image.geterror()
    pixels = image.get_pixels(oiio.FLOAT)
    assert image.spec().width == 600 and image.spec().height == 320  # 6 x 3.2 inches, 100 dpi
    assert pixels[:, :, :3].std() > 0.05, "frames drawn, not a blank page"


def test_psnr_rises_with_the_samples(tmp_path):
    numbers = tmp_path / "psnr.json"
    run("psnr_against_spp.py", "--size", "48x36", "--max-spp", 8, "--reference-spp", 128,
        "--seeds", 2, "-o", tmp_path / "psnr.png", "--json", numbers)
    curve = json.loads(numbers.read_text())["curve"]
    assert [c["spp"] for c in curve] == [1, 2, 4, 8]
    db = [c["psnr_db"] for c in curve]
    assert all(b > a for a, b in zip(db, db[1:])), db
    # Independent samples: the error's variance halves with each doubling (+3 dB); 1 -> 8 spp
    # gains at least 6 dB.
    assert db[-1] - db[0] > 6.0, db
    assert (tmp_path / "psnr.png").stat().st_size > 0


def test_depth_dataset_files_hold_the_views_of_its_index(tmp_path):
    out = tmp_path / "views"
    run("depth_dataset.py", "--views", 5, "--size", "64x48", "-o", out)
    index = json.loads((out / "index.json").read_text())
    assert len(index["views"]) == 5
    assert len({tuple(v["camera"]["eye"]) for v in index["views"]}) == 5, "five views"
    for view in index["views"]:
        image = oiio.ImageBuf(str(out / view["file"]))
        spec = image.spec()
        assert list(spec.channelnames) == ["R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z"]
        assert json.loads(spec.getattribute("prism:camera")) == view["camera"]
        z = image.get_pixels(oiio.FLOAT)[:, :, 4]
        hit = np.isfinite(z)
        assert view["coverage"] == hit.mean()
        assert view["coverage"] > 0.01, "the mesh is in view"
        assert [z[hit].min(), z[hit].max()] == view["depth_range"]
    # A view rendered again from its index entry is the file's image, bit for bit.
    first = index["views"][0]
    scene = prism.load(str(SCENES / "bunny.scene"))
    scene.camera.look_at(first["camera"]["eye"], first["camera"]["look"], first["camera"]["up"])
    rgb = prism.Renderer().render(scene, 64, 48, depth=2)["rgb"]
    stored = oiio.ImageBuf(str(out / first["file"])).get_pixels(oiio.FLOAT)[:, :, :3]
    assert np.array_equal(rgb, stored)


def test_the_readmes_python_runs_as_written():
    """The README's three lines, from the repository's root, as a newcomer pastes them."""
    root = EXAMPLES.parents[1]
    readme = (root / "README.md").read_text()
    start = readme.index("```python\n") + len("```python\n")
    code = readme[start:readme.index("```", start)]
    done = subprocess.run([sys.executable, "-c", code + "\nprint(rgb.shape, rgb.dtype)\n"],
                          cwd=root, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "(480, 640, 3) float32" in done.stdout, done.stdout
