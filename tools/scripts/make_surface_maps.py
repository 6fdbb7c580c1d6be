#!/usr/bin/env python3
"""Writes the shipped normal and bump maps (assets/maps/), so Prism shows its surface maps
without third-party images. Both tile seamlessly (the renderer wraps texture coordinates).

tiles-normal.png: a tangent-space normal map (docs/scene-format.md, "Normal and bump maps":
OpenGL convention, +x = +u, +y = +v, stored as (n + 1) / 2 in 8-bit RGB) of 4 x 4 rounded
square tiles with grooves between them. The normals are those of a height field computed here
at high precision, so the map is exactly what a bump map of that field would give.

studs-height.png: a height map (16-bit grey, read as data, 0 = low, 1 = high) of 6 x 6 round
studs over a low ripple. 16 bits, because the renderer differentiates heights over one texel and
8 bits would show as terraces.

torus.obj: a torus (major radius 1, minor 0.35, in the xz plane) of 48 x 24 quads as 2304
triangles, with vertex normals and texture coordinates that run twice around the ring (u) and
once around the tube (v), so a tiling map meets itself at the seams. Its faces use material
`studded` of torus.mtl, which takes the bump map through MTL's `map_Bump -bm` (a `mesh` line
that names a material uses that one instead). Prism's shipped models have
no clean UV layout to show maps on (Spot's atlas cuts a pattern at every island's edge).

usage: tools/scripts/make_surface_maps.py [OUTDIR]   (default assets/maps)
"""
import os
import sys

import numpy as np
import OpenImageIO as oiio

SIZE = 256


def grid(size: int):
    """Texel-centre coordinates (u, v) in [0, 1), rows top first, so v falls down the rows."""
    u = (np.arange(size) + 0.5) / size
    v = 1.0 - (np.arange(size) + 0.5) / size
    return np.meshgrid(u, v)


def tiles_height(u: np.ndarray, v: np.ndarray, count: int = 4) -> np.ndarray:
    """Pillow tiles: 1 inside, falling smoothly to 0 in the grooves at the tile edges."""
    def edge(t):
        f = (t * count) % 1.0
        d = np.minimum(f, 1.0 - f)  # distance to the nearest edge, in tiles
        x = np.clip((d - 0.03) / 0.12, 0.0, 1.0)
        return x * x * (3.0 - 2.0 * x)  # smoothstep: bevel 0.12 tiles wide
    return edge(u) * edge(v)


def tiles_normal(size: int) -> np.ndarray:
    """(size, size, 3) float in [0, 1]: (n + 1) / 2 of the tiles' height field."""
    fine = 4 * size
    u, v = grid(fine)
    h = 0.03 * tiles_height(u, v)  # height in texture units: the bevel rises 0.03 / 0.03 tiles
    # Central differences, wrapping; rows run down, so dh/dv is minus the row difference.
    dhdu = (np.roll(h, -1, axis=1) - np.roll(h, 1, axis=1)) * fine / 2.0
    dhdv = -(np.roll(h, -1, axis=0) - np.roll(h, 1, axis=0)) * fine / 2.0
    n = np.stack([-dhdu, -dhdv, np.ones_like(h)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    n = n.reshape(size, 4, size, 4, 3).mean(axis=(1, 3))  # box-filter down to the output size
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return 0.5 * n + 0.5


def studs_height(size: int) -> np.ndarray:
    """(size, size) float in [0, 1]: round studs on a 6 x 6 grid over a gentle ripple."""
    u, v = grid(size)
    fu, fv = (u * 6) % 1.0 - 0.5, (v * 6) % 1.0 - 0.5
    r = np.sqrt(fu * fu + fv * fv) / 0.32  # stud radius 0.32 of a cell
    stud = np.where(r < 1.0, np.cos(np.clip(r, 0.0, 1.0) * np.pi / 2.0) ** 2, 0.0)
    ripple = 0.5 + 0.5 * np.sin(2 * np.pi * (2 * u + v))
    return np.clip(0.75 * stud + 0.2 * ripple, 0.0, 1.0)


def torus_obj(ring: int = 48, tube: int = 24, major: float = 1.0, minor: float = 0.35) -> str:
    """OBJ text: (ring + 1) x (tube + 1) vertices (the seams doubled, so UVs do not wrap)."""
    lines = ["# Torus for Prism's normal- and bump-map scene: tools/scripts/make_surface_maps.py",
             "mtllib torus.mtl"]
    for i in range(ring + 1):
        a = 2 * np.pi * i / ring
        for j in range(tube + 1):
            b = 2 * np.pi * j / tube
            n = (np.cos(b) * np.cos(a), np.sin(b), np.cos(b) * np.sin(a))
            p = ((major + minor * np.cos(b)) * np.cos(a), minor * np.sin(b),
                 (major + minor * np.cos(b)) * np.sin(a))
            lines.append("v %.6f %.6f %.6f" % p)
            lines.append("vn %.6f %.6f %.6f" % n)
            lines.append("vt %.6f %.6f" % (2.0 * i / ring, j / tube))
    lines.append("usemtl studded")
    for i in range(ring):
        for j in range(tube):
            c = [i * (tube + 1) + j + 1, (i + 1) * (tube + 1) + j + 1,
                 (i + 1) * (tube + 1) + j + 2, i * (tube + 1) + j + 2]
            # Counter-clockwise seen from outside: the normals' side.
            lines.append("f " + " ".join("%d/%d/%d" % (k, k, k) for k in reversed(c)))
    return "\n".join(lines) + "\n"


def write(path: str, pixels: np.ndarray, fmt) -> bool:
    if pixels.ndim == 2:
        pixels = pixels[..., None]  # set_pixels misreads a 2D array as one row per channel
    height, width, channels = pixels.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(width, height, channels, fmt))
    buf.set_pixels(oiio.ROI(0, width, 0, height), pixels.astype(np.float32))
    temporary = path + ".tmp.png"
    if not buf.write(temporary):
        print(f"make_surface_maps.py: cannot write {path}: {buf.geterror()}", file=sys.stderr)
        return False
    os.replace(temporary, path)
    return True


def main() -> int:
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(__file__), "..", "..", "assets", "maps")
    ok = write(os.path.join(out, "tiles-normal.png"), tiles_normal(SIZE), oiio.UINT8)
    ok = write(os.path.join(out, "studs-height.png"), studs_height(SIZE), oiio.UINT16) and ok
    with open(os.path.join(out, "torus.obj"), "w", encoding="ascii") as obj:
        obj.write(torus_obj())
    with open(os.path.join(out, "torus.mtl"), "w", encoding="ascii") as mtl:
        mtl.write("# The torus's material: tools/scripts/make_surface_maps.py\n"
                  "newmtl studded\nKd 0.85 0.6 0.25\nKs 0.5 0.5 0.5\nNs 48\n"
                  "map_Bump -bm 0.02 studs-height.png\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
