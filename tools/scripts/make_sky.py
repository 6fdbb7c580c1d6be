#!/usr/bin/env python3
"""Writes assets/environments/sky.exr: a procedural lat-long (equirectangular) sky for the
`environment` directive, so Prism ships an environment without a third-party HDR image.

Linear RGB, half float. Above the horizon a blue sky brightening towards the horizon, with a
sun (a small disc of value ~20, so reflections show a highlight) at 35 degrees elevation; below
it a grey-brown ground with a grid every 15 degrees of azimuth, so that reflections and
refractions show which way is which. The image's centre column looks along -z (the default
camera's view), as docs/scene-format.md defines the mapping.

usage: tools/scripts/make_sky.py [OUT.exr]   (default assets/environments/sky.exr)
"""
import os
import sys

import numpy as np
import OpenImageIO as oiio

WIDTH, HEIGHT = 512, 256


def sky(width: int, height: int) -> np.ndarray:
    """The image, rows top first, as (height, width, 3) float32 linear RGB."""
    u = (np.arange(width) + 0.5) / width
    v = 1.0 - (np.arange(height) + 0.5) / height  # v = 0 at the bottom row
    azimuth = (u - 0.5) * 2.0 * np.pi              # 0 along -z, the image's centre
    elevation = (v - 0.5) * np.pi
    az, el = np.meshgrid(azimuth, elevation)
    d = np.stack([np.cos(el) * np.sin(az), np.sin(el), -np.cos(el) * np.cos(az)], axis=-1)
    up = np.clip(np.sin(el), 0.0, 1.0)[..., None]
    zenith, horizon = np.array([0.18, 0.32, 0.70]), np.array([0.85, 0.90, 1.00])
    image = horizon + (zenith - horizon) * up ** 0.5
    sun_dir = np.array([np.cos(np.radians(35)) * np.sin(np.radians(40)), np.sin(np.radians(35)),
                        -np.cos(np.radians(35)) * np.cos(np.radians(40))])
    cos_sun = d @ sun_dir
    image = image + np.array([20.0, 18.0, 15.0]) * (cos_sun > np.cos(np.radians(2.5)))[..., None]
    image = image + np.array([0.6, 0.5, 0.3]) * np.exp((cos_sun - 1.0) * 40.0)[..., None]
    ground = np.array([0.30, 0.26, 0.22]) * (1.0 - 0.5 * np.exp(el * 8.0))[..., None]
    lines = (np.abs(((np.degrees(az) + 7.5) % 15.0) - 7.5) < 0.6)[..., None]
    ground = np.where(lines, ground * 0.45, ground)
    return np.where((el < 0.0)[..., None], ground, image).astype(np.float32)


def main() -> int:
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(__file__), "..", "..", "assets", "environments", "sky.exr")
    spec = oiio.ImageSpec(WIDTH, HEIGHT, 3, oiio.HALF)
    spec.attribute("compression", "zip")
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(0, WIDTH, 0, HEIGHT), sky(WIDTH, HEIGHT))
    temporary = out + ".tmp.exr"
    if not buf.write(temporary):
        print(f"make_sky.py: cannot write {out}: {buf.geterror()}", file=sys.stderr)
        return 1
    os.replace(temporary, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
