#!/usr/bin/env python3
"""Writes assets/scenes/large/forest.scene: a thousand placements of one bunny (scene format 1.1,
`mesh ... as` and `place`), each turned, scaled and coloured on its own, on a field that runs to
the horizon under the sky of environment.scene, with a glass and a mirror sphere in front.

The bunny's 4,968 triangles are stored once; the placements add a transform each (112 bytes on
the GPU). Written out as plain triangles the field would hold 4,968,000 of them.

Deterministic: a fixed seed, so running it again writes the same file.
    tools/scripts/make_forest.py [--count 1000] [-o assets/scenes/large/forest.scene]
"""
import argparse
import math
import random
from pathlib import Path

HEADER = """\
# A field of {count} bunnies (scene format 1.1): one mesh, placed {count} times with `place`,
# each turned, scaled and coloured on its own. The mesh's 4,968 triangles are stored once and
# each placement adds one transform: `prism-render --stats` shows the triangle array at one
# bunny's size and the instance array at 112 bytes a placement. Written by
# tools/scripts/make_forest.py (seeded: the same file each time).
camera eye 0 6 14 look 0 0 -12 fov 40
environment ../../environments/sky.exr intensity 1 rotate 200
light -30 40 30 color 0.95 0.9 0.8 radius 2
light 20 15 25 color 0.25 0.28 0.35

material meadow color 0.35 0.45 0.28 specular 0.1 shininess 20
material glass color 1 1 1 diffuse 0 specular 1 shininess 300 transmit 0.95 ior 1.5
material mirror color 0.9 0.9 0.92 diffuse 0.05 specular 0.9 shininess 300 reflect 0.9
material cream color 0.88 0.82 0.7 specular 0.4 shininess 48
material rust color 0.75 0.35 0.2 specular 0.4 shininess 48
material slate color 0.35 0.4 0.5 specular 0.5 shininess 64
material sand color 0.85 0.7 0.45 specular 0.3 shininess 32
material snow color 0.95 0.95 0.97 specular 0.6 shininess 96

plane 0 0 0 0 1 0 meadow
sphere -2.6 1.3 5.5 1.3 glass
sphere 2.8 1.5 3.2 1.5 mirror

# The bunny, 3 units tall with its feet at the origin (the prototype; it draws nothing itself).
mesh ../../models/bunny/bunny_lowres.obj cream scale 16 translate 0.27 -0.533 0.05 smooth as bunny
"""

COLOURS = ["cream", "rust", "slate", "sand", "snow"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("-o", "--output", default=str(
        Path(__file__).resolve().parents[2] / "assets" / "scenes" / "large" / "forest.scene"))
    args = parser.parse_args()
    rng = random.Random(20261202)
    columns = 40
    rows = math.ceil(args.count / columns)
    lines = [HEADER.format(count=args.count)]
    k = 0
    while len(lines) - 1 < args.count:
        row, column = divmod(k, columns)
        k += 1
        # Rows run away from the camera; the field is 2.2 units a bunny, jittered.
        x = (column - (columns - 1) / 2) * 2.2 + rng.uniform(-0.6, 0.6)
        z = 8.0 - row * 2.2 + rng.uniform(-0.6, 0.6)
        if min(math.hypot(x + 2.6, z - 5.5), math.hypot(x - 2.8, z - 3.2)) < 2.8:
            continue  # the spheres stand in a clearing
        scale = rng.uniform(0.5, 0.9)
        turn = rng.uniform(0.0, 360.0)
        colour = rng.choice(COLOURS)
        lines.append(f"place bunny {colour} scale {scale:.3f} rotate y {turn:.1f} "
                     f"translate {x:.3f} 0 {z:.3f}\n")
    Path(args.output).write_text("".join(lines))
    print(f"wrote {args.output}: {args.count} placements in {rows} rows")


if __name__ == "__main__":
    main()
