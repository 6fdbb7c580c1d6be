#!/usr/bin/env python3
"""A data set for a vision model: random views of a mesh with their depth and normal maps, each
written as one EXR (R, G, B, A, Z, N.X, N.Y, N.Z) with the camera in its metadata, and an
index.json of every view's camera. The scene is loaded and the tracer compiled once; each view
only moves the camera.

    python3 examples/python/depth_dataset.py --views 100 -o bunny-views/
"""
import argparse
import json
import math
import time
from pathlib import Path

import numpy as np

import prism

ASSETS = Path(__file__).resolve().parents[2] / "assets"


def random_eye(rng, target, distance):
    """A point on the upper part of a sphere round the target: azimuth anywhere, elevation
    5 to 60 degrees, distance within 20% of the given one."""
    azimuth = rng.uniform(0.0, 2.0 * math.pi)
    elevation = math.radians(rng.uniform(5.0, 60.0))
    r = distance * rng.uniform(0.8, 1.2)
    return (target[0] + r * math.cos(elevation) * math.sin(azimuth),
            target[1] + r * math.sin(elevation),
            target[2] + r * math.cos(elevation) * math.cos(azimuth))


def draw_preview(shown, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(2, len(shown), figsize=(2.2 * len(shown), 3.6), squeeze=False)
    for k, (rgb, z) in enumerate(shown):
        x = np.clip(rgb, 0.0, 1.0)
        axes[0, k].imshow(np.where(x <= 0.0031308, 12.92 * x, 1.055 * x ** (1 / 2.4) - 0.055))
        axes[1, k].imshow(np.where(np.isfinite(z), z, np.nan), cmap="viridis")
        axes[0, k].set_title(f"view {k}", fontsize=8)
        for ax in axes[:, k]:
            ax.axis("off")
    figure.tight_layout()
    figure.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=str(ASSETS / "scenes" / "bunny.scene"))
    parser.add_argument("--views", type=int, default=100)
    parser.add_argument("--size", default="320x240")
    parser.add_argument("--spp", type=int, default=1)
    parser.add_argument("--seed", type=int, default=0, help="the views' random generator")
    parser.add_argument("-o", "--output", default="dataset")
    parser.add_argument("--preview", help="also draw the first 6 views and their depth here "
                                          "(a PNG, with matplotlib)")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    out = Path(args.output)
    out.mkdir(parents=True, exist_ok=True)

    scene = prism.load(args.scene)
    target = scene.camera.look
    distance = math.dist(scene.camera.eye, target)
    renderer = prism.Renderer()
    rng = np.random.default_rng(args.seed)
    index = []
    shown = []  # the first views' colour and depth, for --preview
    start = time.monotonic()
    traced_ms = 0.0
    for view in range(args.views):
        eye = random_eye(rng, target, distance)
        scene.camera.look_at(eye, target)
        images = renderer.render(scene, width, height, spp=args.spp, depth=2,
                                 aovs=("rgb", "z", "n"))
        traced_ms += renderer.last_stats["trace_ms"]
        name = f"view{view:04d}.exr"
        camera = {"eye": list(eye), "look": list(target), "up": list(scene.camera.up),
                  "fov": scene.camera.fov}
        prism.write(str(out / name), images["rgb"], z=images["z"], n=images["n"],
                    metadata={"prism:camera": json.dumps(camera), "prism:view": view})
        if len(shown) < 6:
            shown.append((images["rgb"], images["z"][:, :, 0]))
        hit = np.isfinite(images["z"])
        index.append({"file": name, "camera": camera,
                      "coverage": float(hit.mean()),
                      "depth_range": [float(images["z"][hit].min()), float(images["z"][hit].max())]
                      if hit.any() else None})
        if (view + 1) % 10 == 0 or view + 1 == args.views:
            print(f"{view + 1}/{args.views} views, {time.monotonic() - start:.1f} s")
    (out / "index.json").write_text(json.dumps({"scene": args.scene, "size": [width, height],
                                                "views": index}, indent=1))
    elapsed = time.monotonic() - start
    if args.preview:
        draw_preview(shown, args.preview)
    print(f"{args.views} views in {elapsed:.1f} s ({traced_ms / 1e3:.1f} s tracing) -> {out}/")


if __name__ == "__main__":
    main()
