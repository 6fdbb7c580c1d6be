#!/usr/bin/env python3
"""The first-image ladder: how long a user waits from command to image file for big meshes.

For each rung (triangle count) and each kind of mesh (many separate objects: `tori`; one dense
closed surface read from an OBJ file: `sphere-mesh`), the scene is generated with prism-scenegen,
then rendered by `prism-render --stats` (512x384, depth 1, one sample) --runs times in separate
processes. Reported per rung: the whole process by the wall clock (command to file, process
start and exit included), the phases prism-render measures, peak resident memory (GNU time's
%M), and the bytes the scene takes on the device (`scene_gpu_bytes`). Beside it, Embree on the
same scene in the same run: its BVH build (`prism-gridbench`, rtcCommitScene) and its frame of
the same camera and shadow rays (`prism-bench --baseline embree`), with Prism's load added for
Embree's first image (Embree has no scene reader: it would read the same files). Cold runs
start with an empty cache each; the warm runs then read back the grid and the parsed OBJ the
first one stored.

    tools/scripts/first_image.py [--bin build/bin] [--rungs 100000,1000000,4000000]
                                 [--kinds tori,sphere-mesh] [--runs 3] [--work DIR]
                                 [--json FILE] [--chart FILE.png] [--no-embree] [--no-cache]

Prints a Markdown table (medians of the runs); docs/benchmarks.md, "The first image of big
meshes", keeps it. Needs GNU time (/usr/bin/time) and, for --chart, Debian's python3-matplotlib
(run it with /usr/bin/python3).
"""
import argparse
import json
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

PHASES = ["load", "build", "context", "tracer", "compile", "frames", "readback", "count", "write"]


def run(cmd, **kw):
    print("running:", " ".join(str(c) for c in cmd), file=sys.stderr)
    return subprocess.run([str(c) for c in cmd], check=True, capture_output=True, text=True, **kw)


def prism_first_image(bin_dir: Path, scene: Path, out: Path, cache: Path = None) -> dict:
    """One prism-render process, timed from outside: wall seconds and peak RSS, and its stats.
    With `cache`, the grid cache is that directory (builds without one where the binary
    predates the cache)."""
    cache_args = ["--cache", cache] if cache else []
    start = time.perf_counter()
    result = run(["/usr/bin/time", "-f", "PEAK_RSS_KB %M", bin_dir / "prism-render", scene, "-o",
                  out, "--size", "512x384", "--depth", "1", "--stats", "--quiet"] + cache_args)
    wall_ms = (time.perf_counter() - start) * 1e3
    stats = json.loads(result.stdout.strip().splitlines()[-1])
    rss_kb = int(next(l for l in result.stderr.splitlines() if l.startswith("PEAK_RSS_KB")).split()[1])
    return {"wall_ms": wall_ms, "peak_rss_mb": rss_kb / 1024.0, "stats": stats}


def embree_figures(bin_dir: Path, scene: Path, work: Path) -> dict:
    """Embree's BVH build and Prism's adaptive grid build, full and lean (--grid-build: the
    lean one is what prism-render builds for one image of a big mesh; medians of 3, one process), and
    Embree's depth-1 frame on the same scene, or {} where Embree is not built in."""
    grid_json, bench_json = work / "gridbench.json", work / "bench.json"
    try:
        run([bin_dir / "prism-gridbench", scene, "--grids", "adaptive,adaptive+lean", "--runs", "3",
             "--json", grid_json])
        rows = json.loads(grid_json.read_text())
        build = next((r["build_ms_median"] for r in rows if r.get("grid") == "embree"), None)
        adaptive = next((r["build_ms_median"] for r in rows if r.get("grid") == "adaptive"), None)
        lean = next((r["build_ms_median"] for r in rows if r.get("grid") == "adaptive+lean"), None)
        if build is None:
            return {}
        run([bin_dir / "prism-bench", scene, "--size", "512x384", "--depth", "1", "--runs", "3",
             "--baseline", "embree", "--json", bench_json])
        bench = json.loads(bench_json.read_text())
        frames = [r for r in bench["results"] if r.get("variant") == "embree"]
        frame = statistics.median(frames[0]["frame_ms"]) if frames else None
        return {"build_ms": build, "frame_ms": frame, "adaptive_build_ms": adaptive,
                "lean_build_ms": lean}
    except (subprocess.CalledProcessError, KeyError, StopIteration) as e:
        print(f"first_image: Embree figures not taken ({e})", file=sys.stderr)
        return {}


def ratio(a, b):
    return a / b if a is not None and b else None


def main() -> int:
    root = Path(__file__).resolve().parents[2]
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default=str(root / "build" / "bin"))
    parser.add_argument("--rungs", default="100000,1000000,4000000")
    parser.add_argument("--kinds", default="tori,sphere-mesh")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--work", default=str(root / "build" / "first-image"))
    parser.add_argument("--json")
    parser.add_argument("--chart")
    parser.add_argument("--no-embree", action="store_true")
    parser.add_argument("--no-cache", action="store_true",
                        help="no grid cache (for builds that predate it): no warm column")
    args = parser.parse_args()
    bin_dir, work = Path(args.bin), Path(args.work)
    work.mkdir(parents=True, exist_ok=True)

    rows = []
    for kind in args.kinds.split(","):
        for rung in [int(r) for r in args.rungs.split(",")]:
            scene = work / f"{kind}-{rung}.scene"
            if not scene.exists():
                run([bin_dir / "prism-scenegen", kind, "--triangles", rung, "-o", scene])
            # Cold: each run with an empty grid cache (so it builds and stores, as a first render
            # does); warm: each run with the cache the cold runs filled.
            runs, warm = [], []
            for k in range(args.runs):
                cache = None if args.no_cache else work / f"cache-{kind}-{rung}-{k}"
                if cache:
                    shutil.rmtree(cache, ignore_errors=True)
                runs.append(prism_first_image(bin_dir, scene, work / "out.exr", cache))
            if not args.no_cache:
                warm = [prism_first_image(bin_dir, scene, work / "out.exr",
                                          work / f"cache-{kind}-{rung}-0")
                        for _ in range(args.runs)]
            embree = {} if args.no_embree else embree_figures(bin_dir, scene, work)
            med = lambda f: statistics.median(f(r) for r in runs)
            stats = runs[0]["stats"]
            row = {
                "kind": kind, "rung": rung,
                "triangles": stats["triangles"]["scene"] + stats["triangles"]["prototypes"],
                "wall_ms": med(lambda r: r["wall_ms"]),
                "peak_rss_mb": med(lambda r: r["peak_rss_mb"]),
                "gpu_bytes": stats.get("scene_gpu_bytes", {}).get("total", 0),
                "phases_ms": {p: med(lambda r: r["stats"]["phases_ms"].get(p, 0.0))
                              for p in PHASES + ["total"]},
                "grid": stats["grid"], "device": stats["device"],
                "embree": embree, "runs": runs,
                "warm_wall_ms": statistics.median(r["wall_ms"] for r in warm) if warm else None,
                "warm_runs": warm,
            }
            if embree.get("frame_ms") is not None:
                row["embree"]["first_image_ms"] = (row["phases_ms"]["load"] + embree["build_ms"]
                                                   + embree["frame_ms"])
            rows.append(row)

    print(f"Device: {rows[0]['device'] if rows else '?'}; 512x384, depth 1, 1 sample; "
          f"medians of {args.runs} processes.\n")
    print("| scene | triangles | command to file ms | load | build | tracer | context wait "
          "| compile | frames | write | peak RSS MB | GPU B/triangle | Embree build ms "
          "| Embree frame ms | Embree first image ms (load + build + frame) | Prism / Embree "
          "| adaptive build / Embree build (gridbench): full, lean "
          "| warm cache: command to file ms | warm / cold |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|")
    for r in rows:
        p, e = r["phases_ms"], r["embree"]
        fi = e.get("first_image_ms")
        cell = lambda v, f="{:.0f}": f.format(v) if v is not None else "-"
        print(f"| {r['kind']} {r['rung']:,} | {r['triangles']:,} | {r['wall_ms']:.0f} "
              f"| {p['load']:.0f} | {p['build']:.0f} | {p['tracer']:.0f} | {p['context']:.0f} "
              f"| {p['compile']:.0f} | {p['frames']:.0f} | {p['write']:.0f} "
              f"| {r['peak_rss_mb']:.0f} | {r['gpu_bytes'] / max(1, r['triangles']):.0f} "
              f"| {cell(e.get('build_ms'), '{:.1f}')} | {cell(e.get('frame_ms'), '{:.1f}')} "
              f"| {cell(fi)} | {cell(r['wall_ms'] / fi if fi else None, '{:.2f}x')} "
              f"| {cell(ratio(e.get('adaptive_build_ms'), e.get('build_ms')), '{:.1f}x')}, "
              f"{cell(ratio(e.get('lean_build_ms'), e.get('build_ms')), '{:.1f}x')} "
              f"| {cell(r['warm_wall_ms'])} "
              f"| {cell(ratio(r['warm_wall_ms'], r['wall_ms']), '{:.2f}')} |")

    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1) + "\n")
    if args.chart:
        chart(rows, Path(args.chart))
    return 0


def chart(rows, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    shown = ["load", "build", "context", "tracer", "compile", "frames", "write"]
    colours = ["#4c72b0", "#dd8452", "#8172b3", "#c44e52", "#937860", "#55a868", "#64b5cd"]
    fig, ax = plt.subplots(figsize=(11.5, 4.8), dpi=110)
    labels = [f"{r['kind']}\n{r['triangles'] / 1e6:.2g}M" for r in rows]
    x = range(len(rows))
    bottom = [0.0] * len(rows)
    for phase, colour in zip(shown, colours):
        values = [r["phases_ms"][phase] / 1e3 for r in rows]
        ax.bar(x, values, bottom=bottom, color=colour, label=phase, width=0.6)
        bottom = [b + v for b, v in zip(bottom, values)]
    rest = [r["wall_ms"] / 1e3 - b for r, b in zip(rows, bottom)]
    ax.bar(x, rest, bottom=bottom, color="#cccccc", label="process start, exit, other", width=0.6)
    embree = [r["embree"].get("first_image_ms") for r in rows]
    ex = [i for i, v in zip(x, embree) if v]
    ax.scatter(ex, [v / 1e3 for v in embree if v], marker="_", s=900, color="black", zorder=3,
               linewidths=2.5, label="Embree: load + BVH build + frame")
    warm = [r.get("warm_wall_ms") for r in rows]
    wx = [i for i, v in zip(x, warm) if v]
    ax.scatter(wx, [v / 1e3 for v in warm if v], marker="v", s=70, color="#2a9d8f", zorder=3,
               label="Prism again, grid and OBJ from the cache")
    ax.set_xticks(list(x), labels)
    ax.set_ylabel("seconds, command to image file")
    ax.set_title("First image of big meshes, phase by phase "
                 f"({rows[0]['device'] if rows else ''}, 512x384, depth 1)")
    # Beside the bars, not over the tallest.
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)


if __name__ == "__main__":
    sys.exit(main())
