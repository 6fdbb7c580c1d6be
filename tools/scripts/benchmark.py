#!/usr/bin/env python3
"""Benchmarks the eight seed scenes with prism-render and prints a Markdown table next to the
original system's figures (SEED_NOTES: 1024x768, 1 light, OpenCL on an FX 8350 CPU / HD 7870).

trace_ms is the best and trace_ms_median the median of --repeat frames after a warm-up frame,
as prism-render reports them (GPU timestamps); wall_ms the same frames by the host's clock, what a
caller waits, the per-frame host work included; Mrays/s counts every ray the tracer traced (primary, shadow,
secondary).

    tools/scripts/benchmark.py [--bin build/bin] [--size 1024x768] [--repeat 5] [--grid auto]
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ORIGINAL = {  # scene: (primitives, CPU s, GPU s)
    "scene": (621, 0.48, 0.04), "grid": (1001, 0.08, 0.01), "rand50": (53, 0.10, 0.02),
    "rand500": (503, 0.20, 0.03), "rand5000": (5003, 0.70, 0.11), "teapot": (1057, 0.67, 0.05),
    "bunny": (4968, 1.00, 0.13), "objects": (5436, 0.36, 0.04),
}


def main() -> int:
    root = Path(__file__).resolve().parents[2]
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default=str(root / "build" / "bin"))
    parser.add_argument("--size", default="1024x768")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--grid", default="auto")
    parser.add_argument("--depth", type=int, default=5)
    parser.add_argument("scenes", nargs="*", default=list(ORIGINAL))
    args = parser.parse_args()

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.scenes:
            scene = root / "assets" / "scenes" / f"{name}.scene"
            cmd = [str(Path(args.bin) / "prism-render"), str(scene), "-o", f"{tmp}/{name}.exr",
                   "--size", args.size, "--repeat", str(args.repeat), "--grid", args.grid,
                   "--depth", str(args.depth), "--stats", "--quiet"]
            print("running:", " ".join(cmd), file=sys.stderr)
            out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
            rows.append((name, json.loads(out.strip().splitlines()[-1])))

    device = rows[0][1]["device"] if rows else "?"
    print(f"Device: {device}; {args.size}; depth {args.depth}; grid {args.grid}; "
          f"best / median of {args.repeat} frames after a warm-up frame.\n")
    print("| scene | prims | grid | max/cell | build ms | trace ms (best / median) "
          "| wall ms (best / median) | rays (M) | Mrays/s | original CPU s | original GPU s |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, s in rows:
        rays = s["rays"]["primary"] + s["rays"]["shadow"] + s["rays"]["secondary"]
        orig = ORIGINAL.get(name, ("", "", ""))
        print(f"| {name} | {s['primitives']} | {s['grid']} | {s['grid_max_per_cell']} "
              f"| {s['build_ms']:.1f} | {s['trace_ms']:.1f} / {s['trace_ms_median']:.1f} "
              f"| {s['wall_ms']:.1f} / {s['wall_ms_median']:.1f} "
              f"| {rays / 1e6:.2f} | {s['mrays_per_s']:.1f} | {orig[1]} | {orig[2]} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
