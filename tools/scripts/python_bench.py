#!/usr/bin/python3
"""What the Python module costs beside the renderer's own work (issue 33), measured in one run:

    PYTHONPATH=build/python tools/scripts/python_bench.py [--imports 7] [--calls 15]
                                                          [--views 100] [--json FILE]

1. `import prism` in a fresh python3, timed inside it (median of --imports processes), beside
   `import numpy` alone: the module's own share is the difference.
2. The Python call at 640x480 (the showcase, 1 sample, depth 5): each call's wall time in Python
   against the same render's trace_ms (GPU timestamps) and wall_ms (the renderer's host clock
   over the frame's submissions) from last_stats; medians of --calls calls after one warm-up.
3. A loop of --views random views of the bunny at 320x240 (the data-set example's loop, without
   the files): the loop's wall time against the sum of its renders' trace_ms and wall_ms.

Prints a Markdown table for docs/benchmarks.md."""
import argparse
import json
import math
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import prism

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "assets" / "scenes"


def import_seconds(module, runs):
    code = f"import time; t = time.perf_counter(); import {module}; print(time.perf_counter() - t)"
    return [float(subprocess.run([sys.executable, "-c", code], check=True, capture_output=True,
                                 text=True).stdout) for _ in range(runs)]


def call_overhead(calls):
    scene = prism.load(str(SCENES / "showcase.scene"))
    renderer = prism.Renderer()
    renderer.render(scene, 640, 480)  # the tracer made and compiled
    call, trace, wall = [], [], []
    for _ in range(calls):
        start = time.perf_counter()
        renderer.render(scene, 640, 480)
        call.append((time.perf_counter() - start) * 1e3)
        trace.append(renderer.last_stats["trace_ms"])
        wall.append(renderer.last_stats["wall_ms"])
    return {"call_ms": statistics.median(call), "trace_ms": statistics.median(trace),
            "wall_ms": statistics.median(wall),
            "call_over_trace": statistics.median(c / t for c, t in zip(call, trace)),
            "call_over_wall": statistics.median(c / w for c, w in zip(call, wall))}


def view_loop(views):
    scene = prism.load(str(SCENES / "bunny.scene"))
    renderer = prism.Renderer()
    target = scene.camera.look
    distance = math.dist(scene.camera.eye, target)
    rng = np.random.default_rng(0)
    renderer.render(scene, 320, 240, depth=2, aovs=("rgb", "z"))  # made and compiled once
    traced = walled = 0.0
    start = time.perf_counter()
    for _ in range(views):
        azimuth, elevation = rng.uniform(0, 2 * math.pi), math.radians(rng.uniform(5, 60))
        scene.camera.look_at((target[0] + distance * math.cos(elevation) * math.sin(azimuth),
                              target[1] + distance * math.sin(elevation),
                              target[2] + distance * math.cos(elevation) * math.cos(azimuth)),
                             target)
        renderer.render(scene, 320, 240, depth=2, aovs=("rgb", "z"))
        traced += renderer.last_stats["trace_ms"]
        walled += renderer.last_stats["wall_ms"]
    loop = (time.perf_counter() - start) * 1e3
    return {"views": views, "loop_ms": loop, "trace_ms_sum": traced, "wall_ms_sum": walled,
            "loop_over_trace": loop / traced, "loop_over_wall": loop / walled}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--imports", type=int, default=7)
    parser.add_argument("--calls", type=int, default=15)
    parser.add_argument("--views", type=int, default=100)
    parser.add_argument("--json")
    args = parser.parse_args()
    prism_s = import_seconds("prism", args.imports)
    numpy_s = import_seconds("numpy", args.imports)
    result = {"device": prism.Renderer().device,
              "import_prism_s": statistics.median(prism_s), "import_prism_each_s": prism_s,
              "import_numpy_s": statistics.median(numpy_s),
              "call_640x480": call_overhead(args.calls), "bunny_views": view_loop(args.views)}
    c, v = result["call_640x480"], result["bunny_views"]
    print(f"device: {result['device']}\n")
    print("| measure | value | bound |\n|---|---:|---|")
    print(f"| `import prism` (median of {args.imports}) | {result['import_prism_s']:.3f} s "
          f"(numpy alone {result['import_numpy_s']:.3f} s) | <= 0.3 s |")
    print(f"| a call at 640x480: Python wall / trace_ms | {c['call_over_trace']:.3f} "
          f"({c['call_ms']:.1f} against {c['trace_ms']:.1f} ms) | <= 1.05 |")
    print(f"| the same / the renderer's wall_ms | {c['call_over_wall']:.3f} "
          f"({c['wall_ms']:.1f} ms) | |")
    print(f"| {v['views']} bunny views at 320x240: loop / sum of trace_ms | "
          f"{v['loop_over_trace']:.3f} ({v['loop_ms']:.0f} against {v['trace_ms_sum']:.0f} ms) "
          f"| <= 1.1 |")
    print(f"| the same / sum of wall_ms | {v['loop_over_wall']:.3f} "
          f"({v['wall_ms_sum']:.0f} ms) | |")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
