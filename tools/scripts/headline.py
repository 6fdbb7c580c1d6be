#!/usr/bin/env python3
"""Remakes benchmarks.md's headline table and chart from one run: the seed scenes and the showcase
at 1024x768 (time a frame, Mrays/s, command to file), against Intel Embree on the same cores and
the original system's figures, stamped with the date, commit, machine and load.

It waits for the machine to be idle first (the 1-minute load average at or below --max-load) and
refuses to stamp a busy machine's figures as the headline, because on two shared cores a busy
machine's times are off by 2x. The table goes between the headline markers of --doc; the chart to
docs/images/headline.png; every figure to docs/data/headline.json.

    tools/scripts/headline.py                 # about 4 minutes on two cores
    tools/scripts/headline.py --print         # the table on stdout; nothing written
    tools/scripts/headline.py --replot        # table and chart again from the saved data
"""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchmark import ORIGINAL

BEGIN = "<!-- headline: begin (made by tools/scripts/headline.py; edits here are overwritten) -->"
END = "<!-- headline: end -->"
SCENES = list(ORIGINAL) + ["showcase"]
DEPTH = 2  # the original's recursion: one bounce


def load_average():
    return os.getloadavg()[0]


def wait_until_idle(max_load, wait_s):
    deadline = time.monotonic() + wait_s
    while load_average() > max_load:
        if time.monotonic() > deadline:
            return False
        print(f"headline: waiting for an idle machine (load {load_average():.2f} > {max_load})",
              file=sys.stderr)
        time.sleep(10)
    return True


def cpu_model():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def commit(root):
    def git(*args):
        return subprocess.run(["git", "-C", str(root), *args], capture_output=True,
                              text=True).stdout.strip()
    head = git("rev-parse", "--short=10", "HEAD") or "unknown"
    return head + (" with uncommitted changes" if git("status", "--porcelain", "-uno") else "")


def run(cmd):
    print("headline: " + " ".join(str(c) for c in cmd), file=sys.stderr)
    done = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"headline: {cmd[0]} failed (exit {done.returncode}):\n{done.stderr}")
    return done.stdout


def measure(root, bin_dir, scenes, size, runs, first_runs, tmp):
    render, bench = bin_dir / "prism-render", bin_dir / "prism-bench"
    rows = {}
    for name in scenes:
        scene = root / "assets" / "scenes" / f"{name}.scene"
        common = [scene, "--size", size, "--depth", DEPTH, "--quiet"]
        stats = json.loads(run([render, *common, "-o", f"{tmp}/{name}.exr", "--runs", runs,
                                "--stats"]).strip().splitlines()[-1])
        # Command to file, as a user waits it: the process from start to exit, one frame.
        seconds = []
        for _ in range(first_runs):
            start = time.perf_counter()
            run([render, *common, "-o", f"{tmp}/{name}.png"])
            seconds.append(time.perf_counter() - start)
        rows[name] = {"stats": stats, "command_to_file_s": seconds}
    # Embree traces camera rays and one shadow ray per light: the same rays as Prism at depth 1.
    bench_json = Path(tmp) / "embree.json"
    run([bench, *[root / "assets" / "scenes" / f"{n}.scene" for n in scenes], "--size", size,
         "--depth", 1, "--runs", runs, "--baseline", "embree", "--quiet", "--json", bench_json])
    for r in json.loads(bench_json.read_text())["results"]:
        rows[r["scene"]]["depth1_" + ("embree" if r["variant"] == "embree" else "prism")] = {
            "mrays_per_s": r["mrays_per_s"], "trace_ms_median": r["trace_ms_median"],
            "wall_ms_median": r["wall_ms_median"], "rays": sum(r["rays"].values())}
    return rows


def table(data):
    s = data["stamp"]
    lines = [
        f"**Measured {s['date']}** at commit `{s['commit']}` on {s['machine']}, "
        f"{s['device']}; 1-minute load average {s['load_before']:.2f} before the run and "
        f"{s['load_after']:.2f} after; {s['seconds']:.0f} s in all. "
        f"Remake: `tools/scripts/headline.py`.",
        "",
        f"{s['size']}, 1 sample a pixel. **Depth {DEPTH}** (camera rays, one bounce of reflection and "
        "refraction, shadow rays at every hit: the original's recursion), `--grid auto`: frame "
        f"= median of {s['runs']} frames after a warm-up (GPU timestamps), command to file = the "
        f"whole `prism-render` process for one frame, PNG written (median of {s['first_runs']}). "
        "**Against Embree**: depth 1 (camera rays and one shadow ray per light, the rays both "
        "trace alike), Mrays/s of each, interleaved in one `prism-bench --baseline embree` run; "
        "Embree 8-wide packets on all cores, by wall time; Embree only traces, while Prism's "
        "rate includes its shading (and the showcase's textures, bump map, sky and instances, "
        "which the seed scenes do not have). **Original**: the dissertation's "
        "OpenCL renderer on an 8-core FX 8350 CPU and an HD 7870 GPU (its tables; our scenes are "
        "recreations of its descriptions, so a row compares the same kind of work, not the same "
        "image).",
        "",
        "| scene | primitives | grid | frame ms | Mrays/s | command to file s "
        "| depth 1 Mrays/s | Embree Mrays/s | vs Embree | original CPU s | original GPU s "
        "| frame vs original CPU |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for name, r in data["scenes"].items():
        st, prism, embree = r["stats"], r["depth1_prism"], r["depth1_embree"]
        orig = ORIGINAL.get(name)
        frame_ms = st["trace_ms_median"]
        rays = sum(st["rays"].values())
        lines.append(
            f"| {name} | {st['primitives']} | {st['grid'].split(',')[0]} | {frame_ms:.1f} "
            f"| {rays / (frame_ms * 1e3):.2f} "
            f"| {statistics.median(r['command_to_file_s']):.2f} "
            f"| {prism['mrays_per_s']:.2f} | {embree['mrays_per_s']:.2f} "
            f"| {prism['mrays_per_s'] / embree['mrays_per_s']:.2f}x "
            + (f"| {orig[1]} | {orig[2]} | {frame_ms / 1e3 / orig[1]:.2f}x |" if orig
               else "| - | - | - |"))
    lines += ["", "![Headline: time a frame against the original, rays per second against "
              "Embree](images/headline.png)"]
    return "\n".join(lines)


def chart(data, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(data["scenes"])
    rows = [data["scenes"][n] for n in names]
    x = range(len(names))
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.6))
    w = 0.27
    left.bar([i - w for i in x], [r["stats"]["trace_ms_median"] / 1e3 for r in rows], w,
             label="Prism, lavapipe (this machine)")
    left.bar(list(x), [ORIGINAL[n][1] if n in ORIGINAL else 0 for n in names], w,
             label="original, OpenCL, FX 8350 CPU (8 cores)")
    left.bar([i + w for i in x], [ORIGINAL[n][2] if n in ORIGINAL else 0 for n in names], w,
             label="original, HD 7870 GPU")
    left.set_yscale("log")
    left.set_ylabel("seconds a frame (log)")
    left.set_title(f"Depth {DEPTH}, {data['stamp']['size']}, 1 spp (no bar: no original figure)")
    right.bar([i - w / 2 for i in x], [r["depth1_prism"]["mrays_per_s"] for r in rows], w,
              label="Prism, lavapipe")
    right.bar([i + w / 2 for i in x], [r["depth1_embree"]["mrays_per_s"] for r in rows], w,
              label="Intel Embree, same cores")
    right.set_ylabel("Mrays/s")
    right.set_title("Depth 1: the same camera and shadow rays")
    for ax in (left, right):
        ax.set_xticks(list(x))
        ax.set_xticklabels(names, rotation=30, ha="right")
        ax.grid(axis="y", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    s = data["stamp"]
    fig.suptitle(f"{s['date']}, commit {s['commit'].split()[0]}, {s['machine']}, "
                 f"load {s['load_before']:.2f} / {s['load_after']:.2f} (before / after)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)


def replace_between_markers(doc, text):
    body = doc.read_text()
    if BEGIN not in body or END not in body:
        sys.exit(f"headline: {doc}: the markers are missing; put\n{BEGIN}\n{END}\n"
                 "where the headline goes")
    head, rest = body.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    new = head + BEGIN + "\n" + text + "\n" + END + tail
    tmp = doc.with_suffix(".md.tmp")
    tmp.write_text(new)
    tmp.replace(doc)


def main():
    root = Path(__file__).resolve().parents[2]
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0] + "\n\n" + __doc__.split("\n\n")[1],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", type=Path, default=root / "build" / "bin",
                        help="where prism-render and prism-bench are (default build/bin)")
    parser.add_argument("--runs", type=int, default=5, help="timed frames a scene (median)")
    parser.add_argument("--first-runs", type=int, default=3,
                        help="command-to-file runs a scene (median)")
    parser.add_argument("--max-load", type=float, default=0.5,
                        help="1-minute load average above which the machine is busy")
    parser.add_argument("--wait", type=float, default=300,
                        help="seconds to wait for the load to fall before refusing")
    parser.add_argument("--scenes", default=",".join(SCENES),
                        help="comma-separated scenes of assets/scenes (default: %(default)s)")
    parser.add_argument("--size", default="1024x768", help="image size (the original's)")
    parser.add_argument("--doc", type=Path, default=root / "docs" / "benchmarks.md",
                        help="the page whose headline markers get the table")
    parser.add_argument("--chart", type=Path, default=root / "docs" / "images" / "headline.png")
    parser.add_argument("--data", type=Path, default=root / "docs" / "data" / "headline.json")
    parser.add_argument("--replot", action="store_true",
                        help="measure nothing: remake the table and chart from --data (after a "
                             "change to their layout; the stamp stays that of the measuring run)")
    parser.add_argument("--print", action="store_true",
                        help="print the table and write nothing (figures from a busy machine "
                             "are allowed then)")
    args = parser.parse_args()
    if args.replot:
        data = json.loads(args.data.read_text())
        chart(data, args.chart)
        replace_between_markers(args.doc, table(data))
        print(f"headline: rewrote {args.doc} and {args.chart} from {args.data}", file=sys.stderr)
        return 0
    for tool in ("prism-render", "prism-bench"):
        if not (args.bin / tool).exists():
            sys.exit(f"headline: {args.bin / tool} not found; build first "
                     "(cmake --preset release && cmake --build --preset release) or give --bin")
    if not args.print:
        try:
            import matplotlib  # noqa: F401  (the chart; checked before minutes of measuring)
        except ImportError:
            sys.exit("headline: matplotlib is missing for the chart: install python3-matplotlib "
                     "(tools/scripts/install-deps.sh) and run it with Debian's /usr/bin/python3")
    if not args.print and not wait_until_idle(args.max_load, args.wait):
        sys.exit(f"headline: the machine stayed busy (load {load_average():.2f} > "
                 f"{args.max_load}) for {args.wait:.0f} s; the headline must come from an idle "
                 "machine (stop other work, or --print to see figures without writing them)")

    scenes = [n for n in args.scenes.split(",") if n]
    for name in scenes:
        if not (root / "assets" / "scenes" / f"{name}.scene").exists():
            sys.exit(f"headline: --scenes: no assets/scenes/{name}.scene")
    if not args.print:  # refuse before measuring, not after
        with open(args.doc) as doc:
            if BEGIN not in doc.read():
                sys.exit(f"headline: {args.doc}: no headline markers; put\n{BEGIN}\n{END}\n"
                         "where the headline goes")
    load_before, started = load_average(), time.monotonic()
    with tempfile.TemporaryDirectory() as tmp:
        rows = measure(root, args.bin, scenes, args.size, args.runs, args.first_runs, tmp)
    device = rows[scenes[0]]["stats"]["device"]
    data = {"stamp": {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "commit": commit(root), "machine": f"{cpu_model()}, {os.cpu_count()} cores",
        "device": device, "load_before": load_before, "load_after": load_average(),
        "seconds": time.monotonic() - started, "runs": args.runs, "size": args.size,
        "first_runs": args.first_runs}, "scenes": rows}
    text = table(data)
    if args.print:
        print(text)
        return 0
    args.data.write_text(json.dumps(data, indent=1) + "\n")
    chart(data, args.chart)
    replace_between_markers(args.doc, text)
    print(f"headline: wrote {args.doc}, {args.chart} and {args.data}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
