#!/usr/bin/env python3
"""Renders every shipped scene (assets/scenes/*.scene, in the order of the scenes README's table)
with prism-render and puts the images side by side in docs/images/scenes.png, five to a row.

    tools/scripts/scenes_montage.py [--bin build/bin] [--size 320x240] [--spp 4] [-o OUT.png]

Needs Debian's python3-numpy and python3-openimageio. Each scene is rendered to a temporary PNG
(depth 5, the scene's own camera); the montage is written to a temporary name and renamed.
"""
import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import OpenImageIO as oiio

ROOT = Path(__file__).resolve().parents[2]
# The README's order: the eight seed scenes, then the others.
ORDER = ["scene", "grid", "rand50", "rand500", "rand5000", "teapot", "bunny", "objects",
         "showcase", "cornell", "environment", "bump-maps", "instances"]
PER_ROW = 5
# Scenes that would show another scene again: the turntable is the showcase, animated.
SAME_PICTURE = {"showcase-turntable"}


def render(binary: Path, scene: Path, out: Path, size: str, spp: int) -> np.ndarray:
    subprocess.run([str(binary), str(scene), "-o", str(out), "--size", size, "--spp", str(spp),
                    "--quiet"], check=True)
    image = oiio.ImageBuf(str(out))
    pixels = image.get_pixels(oiio.UINT8)
    return pixels[:, :, :3]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=str(ROOT / "build" / "bin"))
    parser.add_argument("--size", default="320x240")
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("-o", "--output", default=str(ROOT / "docs" / "images" / "scenes.png"))
    args = parser.parse_args()
    binary = Path(args.bin) / "prism-render"
    scenes = ROOT / "assets" / "scenes"
    names = ORDER + sorted(p.stem for p in scenes.glob("*.scene")
                           if p.stem not in ORDER and p.stem not in SAME_PICTURE)
    width, height = (int(v) for v in args.size.split("x"))
    rows = (len(names) + PER_ROW - 1) // PER_ROW
    montage = np.full((rows * height, PER_ROW * width, 3), 255, dtype=np.uint8)
    with tempfile.TemporaryDirectory() as tmp:
        for k, name in enumerate(names):
            print(f"{k + 1}/{len(names)} {name}", file=sys.stderr)
            image = render(binary, scenes / f"{name}.scene", Path(tmp) / f"{name}.png",
                           args.size, args.spp)
            row, column = divmod(k, PER_ROW)
            montage[row * height:(row + 1) * height, column * width:(column + 1) * width] = image
    out = Path(args.output)
    temporary = out.with_name(out.stem + ".tmp" + out.suffix)
    buf = oiio.ImageBuf(oiio.ImageSpec(montage.shape[1], montage.shape[0], 3, oiio.UINT8))
    buf.set_pixels(oiio.ROI(0, montage.shape[1], 0, montage.shape[0]), montage)
    if not buf.write(str(temporary)):
        print(f"scenes_montage.py: cannot write {out}: {buf.geterror()}", file=sys.stderr)
        return 1
    os.replace(temporary, out)
    print(f"wrote {out}: {len(names)} scenes", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
