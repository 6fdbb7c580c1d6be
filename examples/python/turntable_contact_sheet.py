#!/usr/bin/env python3
"""A turntable as a contact sheet: frames of a scene's camera animation rendered in one
process (the scene loaded, its grid built and the tracer compiled once, then each frame traced
into NumPy), tone-mapped and laid out in a grid with matplotlib.

    python3 examples/python/turntable_contact_sheet.py -o turntable.png
"""
import argparse
import math
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt
import numpy as np

import prism

ASSETS = Path(__file__).resolve().parents[2] / "assets"


def display(rgb):
    """Linear radiance to an sRGB image matplotlib shows as it is."""
    x = np.clip(rgb, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=str(ASSETS / "scenes" / "showcase-turntable.scene"))
    parser.add_argument("--frames", type=int, default=24,
                        help="how many frames, spread evenly over the animation (default 24)")
    parser.add_argument("--size", default="240x180", help="each frame's WxH (default 240x180)")
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("--columns", type=int, default=6)
    parser.add_argument("-o", "--output", default="turntable-contact-sheet.png")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))

    scene = prism.load(args.scene)
    if not scene.animated:
        parser.error(f"{args.scene} has no camera animation (key lines or a turntable)")
    renderer = prism.Renderer()
    last = scene.last_frame
    # A turntable's frame last + 1 is frame 1 again: spread the frames over one turn.
    frames = [1 + last * k / args.frames for k in range(args.frames)]
    rows = math.ceil(len(frames) / args.columns)
    figure, axes = plt.subplots(rows, args.columns, figsize=(2.0 * args.columns, 1.6 * rows),
                                squeeze=False)
    start = time.monotonic()
    traced_ms = 0.0
    for k, ax in enumerate(axes.flat):
        ax.axis("off")
        if k >= len(frames):
            continue
        scene.frame = frames[k]
        rgb = renderer.render(scene, width, height, spp=args.spp, depth=4)["rgb"]
        traced_ms += renderer.last_stats["trace_ms"]
        ax.imshow(display(rgb))
        ax.set_title(f"frame {frames[k]:g}", fontsize=8)
    elapsed = time.monotonic() - start
    figure.suptitle(f"{Path(args.scene).name}: {len(frames)} frames at {width}x{height}, "
                    f"{args.spp} spp ({renderer.device})", fontsize=9)
    figure.tight_layout()
    figure.savefig(args.output, dpi=100)
    print(f"{len(frames)} frames in {elapsed:.1f} s ({traced_ms / 1e3:.1f} s tracing) "
          f"-> {args.output}")


if __name__ == "__main__":
    main()
