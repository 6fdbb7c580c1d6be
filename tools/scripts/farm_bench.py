#!/usr/bin/python3
"""What a frame range and a tiled still cost in one process and on a farm (issue 32), measured in
one run on this machine:

    tools/scripts/farm_bench.py [--bin build/bin] [--size 1024x768] [--frames 24] [--chunks 4,12]
                                [--tiles 16] [--alone 4] [--rounds 2] [--exr-compression C]
                                [--no-slurm] [--work DIR]

1. The turntable's frames 1-N in one prism-render process: the whole run's wall time, and each
   frame's cost after the first (frame_ms: from its start to its image queued for writing, the
   write itself overlapped with the next frame) against its trace time in the same run.
2. --alone of those frames rendered each by itself with --repeat 3 (a warm-up frame, then the
   best of 3 traces, no write overlapping): each frame's own trace time, and the range's
   frame_ms against it.
3. The same range as a Slurm job array of chunks (tools/farm/prism-farm on a local Slurm started
   here, as root): wall time until the last frame is written and until the contact sheet is,
   against the one-process range. And a still split into --tiles tiles as an array, merged,
   against the whole still in one process; the merged image must be the same, bit for bit.

Prints a Markdown table for docs/benchmarks.md. Medians where several values are taken."""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TURNTABLE = ROOT / "assets" / "scenes" / "showcase-turntable.scene"
STILL = ROOT / "assets" / "scenes" / "showcase.scene"
FARM = ROOT / "tools" / "farm"


def run(command, env=None):
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.exit(f"farm_bench: {' '.join(map(str, command))} failed:\n{result.stderr}")
    return result


def timed(command, env=None):
    start = time.monotonic()
    result = run(command, env)
    return time.monotonic() - start, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", type=Path, default=ROOT / "build" / "bin")
    parser.add_argument("--size", default="1024x768")
    parser.add_argument("--frames", type=int, default=24)
    parser.add_argument("--chunks", type=lambda t: [int(c) for c in t.split(",")],
                        default=[4, 12], help="frames a task, one array for each")
    parser.add_argument("--tiles", type=int, default=16)
    parser.add_argument("--alone", type=int, default=4, help="frames also rendered alone")
    parser.add_argument("--rounds", type=int, default=2, help="runs of the range and of each "
                        "frame alone (the best of them is taken)")
    parser.add_argument("--exr-compression", default="zip",
                        help="prism-render --exr-compression for every image written")
    parser.add_argument("--no-slurm", action="store_true")
    parser.add_argument("--work", type=Path)
    args = parser.parse_args()
    render = args.bin / "prism-render"
    work = args.work or Path(tempfile.mkdtemp(prefix="prism-farm-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, PRISM_BIN=str(args.bin.resolve()))
    rows = []

    # 1 and 2, in --rounds rounds (this machine's speed drifts between runs): the range in one
    # process, then some of its frames alone; each frame's best over the rounds on both sides.
    one = work / "one"
    walls, runs, alone_ms = [], [], {}
    step = max(1, (args.frames - 1) // max(1, args.alone))
    sampled = list(range(2, args.frames + 1, step))[: args.alone]
    for _ in range(args.rounds):
        shutil.rmtree(one, ignore_errors=True)
        one.mkdir()
        wall, result = timed([render, TURNTABLE, "--frames", f"1-{args.frames}", "--size",
                              args.size, "--stats", "--quiet", "--no-cache",
                              "--exr-compression", args.exr_compression, "-o",
                              one / "f.####.exr"])
        walls.append(wall)
        runs.append(json.loads(result.stdout))
        for frame in sampled:
            _, r = timed([render, TURNTABLE, "--frames", str(frame), "--size", args.size,
                          "--repeat", "3", "--stats", "--quiet", "--no-cache",
                          "--exr-compression", args.exr_compression, "-o", work / "alone.exr"])
            own = json.loads(r.stdout)["trace_ms"]
            alone_ms[frame] = min(alone_ms.get(frame, own), own)
    wall = min(walls)
    stats = runs[walls.index(wall)]
    best = {}  # frame -> (frame_ms, trace_ms), each the best over the rounds
    for run_stats in runs:
        for f in run_stats["per_frame"]:
            old = best.get(f["frame"], (f["frame_ms"], f["trace_ms"]))
            best[f["frame"]] = (min(old[0], f["frame_ms"]), min(old[1], f["trace_ms"]))
    later = [best[f] for f in sorted(best)[1:]]
    in_range = [cost / trace for cost, trace in later]
    phases = stats["phases_ms"]
    rows.append(("one process, whole range", f"{wall:.1f} s",
                 f"{args.frames} frames, best of {args.rounds} runs; "
                 f"{phases['total'] - phases['frames']:.0f} ms outside the frames "
                 "(load, build, context, compile, the last write)"))
    rows.append(("a frame after the first, against its trace in the range",
                 f"{statistics.median(in_range):.3f}x (max {max(in_range):.3f}x)",
                 f"frame_ms median {statistics.median(c for c, _ in later):.0f} ms, trace "
                 f"{statistics.median(t for _, t in later):.0f} ms "
                 f"({stats['mrays_per_s']:.1f} Mrays/s at the best frame)"))
    ratios = [best[f][0] / alone_ms[f] for f in sampled]
    rows.append(("a frame after the first, against its own trace alone (best of 3 x rounds)",
                 f"{statistics.median(ratios):.3f}x (max {max(ratios):.3f}x)",
                 ", ".join(f"frame {f}: {best[f][0]:.0f} / {alone_ms[f]:.0f} ms"
                           for f in sampled)))

    if not args.no_slurm:
        slurm_dir = work / "slurm"
        env["PRISM_SLURM_PORT"] = env.get("PRISM_SLURM_PORT", "16817")
        line = run([FARM / "local-slurm.sh", "start", slurm_dir], env).stdout
        env["SLURM_CONF"] = line.strip().split("=", 1)[1]
        try:
            for chunk in args.chunks:
                array = work / f"array-{chunk}"
                shutil.rmtree(array, ignore_errors=True)
                start = time.monotonic()
                run([FARM / "prism-farm", "slurm", TURNTABLE, "-o", array / "f.####.exr",
                     "--frames", f"1-{args.frames}", "--chunk", str(chunk), "--wait", "--",
                     "--size", args.size, "--quiet", "--no-cache"], env)
                done = time.monotonic() - start
                last = max(p.stat().st_mtime for p in array.glob("f.*.exr"))
                frames_wall = last - (time.time() - done)
                tasks = -(-args.frames // chunk)
                rows.append((f"Slurm array, {tasks} tasks of {chunk} frames",
                             f"{frames_wall:.1f} s = {frames_wall / wall:.2f}x one process",
                             f"{done:.1f} s with the contact sheet; 1 core and 1 lavapipe "
                             "thread a task, 2 tasks at once"))
            tiles = work / "tiles"
            shutil.rmtree(tiles, ignore_errors=True)
            tiles.mkdir()
            still_wall, _ = timed([render, STILL, "--size", args.size, "--quiet", "--no-cache",
                                   "-o", tiles / "whole.exr"])
            start = time.monotonic()
            run([FARM / "prism-farm", "slurm", STILL, "-o", tiles / "poster.exr", "--tiles",
                 str(args.tiles), "--wait", "--", "--size", args.size, "--quiet", "--no-cache"],
                env)
            tiled_wall = time.monotonic() - start
            same = subprocess.run(["idiff", "-fail", "0", "-failpercent", "0", "-hardfail", "0",
                                   "-warn", "0", tiles / "poster.exr", tiles / "whole.exr"],
                                  capture_output=True).returncode == 0
            rows.append((f"still in {args.tiles} tiles on the Slurm array, merged",
                         f"{tiled_wall:.1f} s = {tiled_wall / still_wall:.2f}x one process "
                         f"({still_wall:.1f} s)",
                         "merged image identical to the whole render" if same
                         else "MERGED IMAGE DIFFERS"))
        finally:
            run([FARM / "local-slurm.sh", "stop", slurm_dir], env)

    print(f"| {args.size}, showcase turntable | value | notes |")
    print("|---|---|---|")
    for what, value, notes in rows:
        print(f"| {what} | {value} | {notes} |")


if __name__ == "__main__":
    main()
