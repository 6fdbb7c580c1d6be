#!/usr/bin/env python3
"""Studies: what an image costs against what it is worth, and where methods fail (issue 9).

    tools/scripts/studies.py [STUDY...] [--quick] [--out DIR] [--bin build/bin]

Drives prism-render, prism-bench and prism-scenegen, reads their JSON and EXR files and writes,
for each study, charts (PNG, and SVG but for --quick), data (JSON + CSV) and a Markdown
section under DIR (default docs/studies/); DIR/README.md collects every section with the device, date and
command line of the run that made it. --quick runs every study at toy size (the test suite
runs it); the full set is sized to take about half an hour on 2 CPU cores with lavapipe.

Studies: accuracy (speed against accuracy), offsets (ray offsets; study_offsets.py), triangles
(watertight triangles; study_triangles.py), acceleration (grids against primitive count),
original (the original system's tables).

Needs Python 3 with numpy, matplotlib and OpenImageIO (Debian: python3-numpy,
python3-matplotlib, python3-openimageio) and a release build (cmake --preset release &&
cmake --build build).
"""
import argparse
import csv
import datetime
import io
import json
import math
import os
import platform
import re
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import study_offsets
import study_triangles

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "assets" / "scenes"
SEEDS = ["scene", "grid", "rand50", "rand500", "rand5000", "teapot", "bunny", "objects"]

# The original system's figures (SEED_NOTES.md; docs/benchmarks.md sets them beside Prism's):
# OpenCL on an 8-core 4 GHz FX 8350 CPU and a Radeon HD 7870 GPU, 1024x768, one level of
# reflection/refraction, a 10^3 grid.
ORIGINAL = {  # scene: (primitives, CPU s, GPU s)
    "scene": (621, 0.48, 0.04), "grid": (1001, 0.08, 0.01), "rand50": (53, 0.10, 0.02),
    "rand500": (503, 0.20, 0.03), "rand5000": (5003, 0.70, 0.11), "teapot": (1057, 0.67, 0.05),
    "bunny": (4968, 1.00, 0.13), "objects": (5436, 0.36, 0.04),
}
ORIGINAL_DENSITY_GPU_S = {  # scene: {grid: GPU s}
    "scene": {"grid=10": 0.041, "grid=20": 0.048, "grid=30": 0.046},
    "bunny": {"grid=10": 0.132, "grid=20": 0.084, "grid=30": 0.077},
}
ORIGINAL_FEATURE_FPS = {"auto": 16, "no-reflection": 17, "no-refraction": 24, "no-shadows": 18,
                        "no-reflection+no-refraction+no-shadows": 32}
FEATURE_LABELS = {"auto": "all features", "no-reflection": "no reflection",
                  "no-refraction": "no refraction", "no-shadows": "no shadows",
                  "no-reflection+no-refraction+no-shadows": "none of the three"}

STUDY_ORDER = ["accuracy", "offsets", "triangles", "acceleration", "original"]
STUDY_TITLES = {
    "accuracy": "1. Speed against accuracy",
    "offsets": "2. Where methods fail: ray offsets",
    "triangles": "3. Where methods fail: triangles",
    "acceleration": "4. Where methods fail: acceleration",
    "original": "5. The original's tables, reproduced",
}


class StudyError(Exception):
    """A failure the user can act on; main() prints it and exits non-zero."""


# --------------------------------------------------------------------------------------------
# Configuration: the full set and --quick differ only in sizes and counts.

def make_config(quick):
    """Returns the sizes of every study. Quick is for the test suite: tiny images, two scenes,
    one process per study where possible, so that the whole run stays well under a minute on
    two busy cores while still exercising every chart and file."""
    if quick:
        return {
            "quick": True,
            "accuracy": {"scenes": ["cornell"], "size": "64x48", "spp": [1, 16],
                         "depth": [1, 5], "ref_spp": 64, "ref_depth": 8, "check_spp": 32},
            "offsets": {"scene": "studies/five-objects", "size": "64x48", "depth": 5,
                        "scale_exponents": [-13, 0, 13], "shifts": [0, 1e6],
                        "shift_floor": 10},
            "triangles": {"size": 32, "shifts": [0, 1e5], "shift_floor": 1,
                          "time_scenes": ["bunny"], "time_size": "64x48", "time_depth": 1,
                          "runs": 1},
            "acceleration": {"size": "64x48", "depth": 1, "runs": 1, "spheres": [50, 500],
                             "tori": [5000], "stadium": False, "off_max_primitives": 5000,
                             "embree": False},
            "original": {"seed_scenes": ["rand50", "bunny"], "size": "64x48", "runs": 1,
                         "density_scenes": ["bunny"], "feature_scene": "teapot",
                         "feature_size": "64x48", "resolution_scene": "rand50",
                         "resolutions": ["32x24", "128x96"]},
        }
    return {
        "quick": False,
        "accuracy": {"scenes": SEEDS + ["showcase", "cornell"], "size": "160x120",
                     "spp": [1, 2, 4, 8, 16, 64], "depth": [1, 2, 3, 5, 8], "ref_spp": 256,
                     "ref_depth": 12, "check_spp": 128},
        "offsets": {"scene": "studies/five-objects", "size": "160x120", "depth": 5,
                    "scale_exponents": [-13, -10, -7, -3, 0, 3, 7, 10, 13],
                    "shifts": [0, 1e2, 1e3, 1e4, 1e5, 1e6], "shift_floor": 10},
        "triangles": {"size": 128, "shifts": [0, 1e1, 1e2, 1e3, 1e4, 1e5], "shift_floor": 1,
                      "time_scenes": ["bunny", "teapot"], "time_size": "512x384",
                      "time_depth": 2, "runs": 9},
        "acceleration": {"size": "256x192", "depth": 1, "runs": 3,
                         "spheres": [50, 500, 5000, 50000],
                         "tori": [5000, 50000, 200000, 1000000], "stadium": True,
                         "off_max_primitives": 5100, "embree": True},
        "original": {"seed_scenes": SEEDS, "size": "1024x768", "runs": 3,
                     "density_scenes": ["scene", "bunny"], "feature_scene": "teapot",
                     "feature_size": "1024x768", "resolution_scene": "scene",
                     "resolutions": ["160x120", "320x240", "640x480", "1024x768", "1600x1200",
                                     "2048x1536"]},
    }


def apply_overrides(config, overrides):
    """--set study.key=value (JSON value) lets a run be reduced or enlarged without editing the
    script; the README records the overrides with the command line."""
    for item in overrides:
        m = re.fullmatch(r"(\w+)\.(\w+)=(.*)", item)
        if not m or m.group(1) not in config or m.group(2) not in config[m.group(1)]:
            raise StudyError(f"--set {item}: expected STUDY.KEY=JSON with a known key, e.g. "
                             f"accuracy.scenes='[\"cornell\"]'")
        try:
            config[m.group(1)][m.group(2)] = json.loads(m.group(3))
        except json.JSONDecodeError:
            config[m.group(1)][m.group(2)] = m.group(3)


# --------------------------------------------------------------------------------------------
# Output helpers: every file is written under a temporary name and renamed, so an interrupted
# run never leaves a half-written chart or table in docs/.

def write_text(path, text):
    """Writes text atomically (temporary file in the same folder, then rename)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def write_json(path, data):
    write_text(path, json.dumps(data, indent=1, sort_keys=False) + "\n")


def write_csv(path, rows):
    """Flat rows (list of dicts with the same keys) as CSV, atomically."""
    if not rows:
        write_text(path, "")
        return
    keys = list(rows[0].keys())
    for r in rows[1:]:
        keys += [k for k in r if k not in keys]
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=keys, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: r.get(k, "") for k in keys})
    write_text(path, buf.getvalue())


WRITE_SVG = True  # --quick writes PNG only: the test checks the charts, not their vector copies


# "run 2026-12-05, commit 1a2b3c, load 0.12 before": set for each study's run (and from its
# section.json when replotting) and written in a corner of every chart, because absolute times
# on a shared 2-core machine are only as good as the load they were measured under.
FIGURE_STAMP = None


def stamp_text(section):
    load = section.get("load_before")
    if section.get("load_note"):  # a run from before the load was recorded, noted by hand
        return (f"run {section['date']}, commit {section.get('commit', 'not recorded')}, "
                f"load {section['load_note']}")
    return (f"run {section['date']}, commit {section.get('commit', 'not recorded')}, "
            + (f"load {load:.2f} when the run began (1-min average, "
               f"{section.get('cpus', '?')} CPUs)"
               if load is not None else "machine load not recorded"))


def save_figure(fig, path_png):
    """Saves a matplotlib figure as PNG (and SVG unless --quick) atomically and closes it. SVG
    metadata dates are dropped so that regenerated charts differ only where the data do."""
    import matplotlib.pyplot as plt
    if FIGURE_STAMP:
        # Under the figure (bbox_inches="tight" takes it in), clear of the axis labels.
        fig.text(0.995, -0.01, FIGURE_STAMP, ha="right", va="top", fontsize=7, color="0.45")
    svg = WRITE_SVG
    path_png.parent.mkdir(parents=True, exist_ok=True)
    targets = [(path_png, "png", {"dpi": 110})]
    if svg:
        targets.append((path_png.with_suffix(".svg"), "svg", {"metadata": {"Date": None}}))
    for path, fmt, extra in targets:
        tmp = path.with_name(path.stem + ".tmp." + fmt)
        fig.savefig(tmp, format=fmt, bbox_inches="tight", **extra)
        os.replace(tmp, path)
    plt.close(fig)


def md_table(header, rows):
    """A Markdown table; numbers already formatted as strings by the caller."""
    def numeric(i):
        cells = [str(r[i]) for r in rows]
        return cells and all(re.fullmatch(r"[-+]?[\d.,]+(e[-+]?\d+)?( \(.*\))?|-", c)
                             for c in cells)
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---:" if numeric(i) else "---" for i in range(len(header))) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


# --------------------------------------------------------------------------------------------
# Progress: one line, rewritten in place on a terminal, one line per step otherwise (ctest logs).

class Progress:
    """Prints where the run is: study, step k of n, what is running and the time so far."""

    def __init__(self):
        self.start = time.monotonic()
        self.tty = sys.stderr.isatty()
        self.study = ""
        self.total = 0
        self.done = 0

    def begin(self, study, total):
        self.study, self.total, self.done = study, total, 0

    def step(self, what):
        self.done += 1
        elapsed = time.monotonic() - self.start
        line = (f"studies: [{self.study}] {self.done}/{self.total} {what} "
                f"({int(elapsed // 60)}:{int(elapsed % 60):02d} elapsed)")
        if self.tty:
            sys.stderr.write("\r" + line[:150].ljust(150))
        else:
            sys.stderr.write(line + "\n")
        sys.stderr.flush()

    def end(self):
        if self.tty:
            sys.stderr.write("\n")
            sys.stderr.flush()


# --------------------------------------------------------------------------------------------
# Running the tools.

class Tools:
    """Runs prism-render, prism-bench and prism-scenegen and parses what they print."""

    def __init__(self, bin_dir, progress):
        self.bin = Path(bin_dir)
        self.progress = progress
        for name in ("prism-render", "prism-bench", "prism-scenegen"):
            if not (self.bin / name).is_file():
                raise StudyError(
                    f"{self.bin / name} not found: build it first (cmake --preset release && "
                    f"cmake --build build), or give its folder with --bin")
        self._help = None
        self.device = None

    def _run(self, cmd, what):
        self.progress.step(what)
        proc = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
        if proc.returncode != 0:
            raise StudyError(f"{what}: {' '.join(shlex.quote(str(c)) for c in cmd)} failed "
                             f"(exit {proc.returncode}):\n{proc.stderr.strip()[-2000:]}")
        return proc.stdout

    def render(self, scene, out, what, size, spp=1, depth=5, grid="auto", repeat=1):
        """Renders one image; returns prism-render's --stats JSON."""
        cmd = [self.bin / "prism-render", scene, "-o", out, "--size", size, "--spp", spp,
               "--depth", depth, "--grid", grid, "--repeat", repeat, "--stats", "--quiet"]
        stats = json.loads(self._run(cmd, what).strip().splitlines()[-1])
        self.device = self.device or stats.get("device")
        return stats

    def bench(self, scenes, variants, what, size, depth, runs, spp=1, embree=False,
              save_images=None, keep_origin=False):
        """Times scenes under variants in one prism-bench process (frames interleaved); returns
        its --json document. save_images: a folder for each variant's SCENE_VARIANT.exr;
        keep_origin: trace in the files' coordinates, not centred on the camera."""
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "bench.json"
            cmd = [self.bin / "prism-bench", *scenes, "--size", size, "--depth", depth,
                   "--runs", runs, "--spp", spp, "--variants", ",".join(variants),
                   "--json", path]
            if embree:
                cmd += ["--baseline", "embree"]
            if save_images:
                cmd += ["--save-images", save_images]
            if keep_origin:
                cmd += ["--keep-origin"]
            self._run(cmd, what)
            doc = json.loads(path.read_text())
        self.device = self.device or doc.get("device")
        return doc

    def scenegen(self, args, out, what):
        self._run([self.bin / "prism-scenegen", *args, "-o", out], what)

    def bench_help(self):
        if self._help is None:
            proc = subprocess.run([str(self.bin / "prism-bench"), "--help"],
                                  capture_output=True, text=True)
            self._help = " ".join((proc.stdout + proc.stderr).split())
        return self._help

    def grid_modes(self):
        """Every grid prism-bench knows, read from its --help, so that a grid added later is
        measured without editing this script."""
        m = re.search(r"Comma-separated variants:(.*?)grid=", self.bench_help())
        if not m:
            return ["auto", "regular", "adaptive", "two-level"]
        modes = [t.strip() for t in m.group(1).split(",") if t.strip()]
        return [t for t in modes if re.fullmatch(r"[a-z][a-z0-9-]*", t) and t != "off"]

    def has_embree(self, scene):
        """Whether this prism-bench was built with Embree: a tiny run with the baseline."""
        cmd = [str(self.bin / "prism-bench"), str(scene), "--size", "8x8", "--runs", "1",
               "--depth", "1", "--variants", "regular", "--baseline", "embree"]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        return proc.returncode == 0


def read_exr_rgb(path):
    """Linear RGB of an EXR as a float64 array (H, W, 3)."""
    import numpy as np
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(str(path))
    if inp is None:
        raise StudyError(f"cannot read {path}: {oiio.geterror()}")
    try:
        pixels = inp.read_image("float")
    finally:
        inp.close()
    if pixels is None:
        raise StudyError(f"cannot read pixels of {path}")
    return np.asarray(pixels, dtype=np.float64)[:, :, :3]


# --------------------------------------------------------------------------------------------
# Image error measures.

def rmse(a, b):
    """Root-mean-square error over all pixels and the three channels of linear RGB."""
    import numpy as np
    return float(np.sqrt(np.mean((a - b) ** 2)))


def psnr(err, peak=1.0):
    """PSNR in dB for an RMSE on linear RGB with the peak at 1.0 (display white)."""
    return float("inf") if err == 0 else 20.0 * math.log10(peak / err)


def _srgb_luma(rgb):
    """Display-encoded luminance: Rec. 709 Y of linear RGB, clipped to [0, 1], sRGB-encoded.
    SSIM was designed for and validated on gamma-encoded images, so it is given what a viewer
    sees, not linear radiance."""
    import numpy as np
    y = np.clip(rgb @ np.array([0.2126, 0.7152, 0.0722]), 0.0, 1.0)
    return np.where(y <= 0.0031308, 12.92 * y, 1.055 * np.power(y, 1 / 2.4) - 0.055)


def _gaussian_valid(img, sigma=1.5, radius=5):
    """Separable 11x11 Gaussian filter (sigma 1.5), 'valid' region only (no padding)."""
    import numpy as np
    x = np.arange(-radius, radius + 1)
    w = np.exp(-x ** 2 / (2 * sigma ** 2))
    w /= w.sum()
    n = 2 * radius + 1
    h, wd = img.shape
    tmp = sum(w[i] * img[i:h - n + 1 + i, :] for i in range(n))
    return sum(w[i] * tmp[:, i:wd - n + 1 + i] for i in range(n))


def ssim(a, b):
    """Mean SSIM (Wang, Bovik, Sheikh & Simoncelli 2004) of display luminance: 11x11 Gaussian
    window with sigma 1.5, K1 = 0.01, K2 = 0.03, dynamic range L = 1, mean over the valid
    region. 1 is identical; it weighs structure (edges, noise) the way PSNR does not."""
    la, lb = _srgb_luma(a), _srgb_luma(b)
    c1, c2 = (0.01 * 1.0) ** 2, (0.03 * 1.0) ** 2
    mu_a, mu_b = _gaussian_valid(la), _gaussian_valid(lb)
    saa = _gaussian_valid(la * la) - mu_a ** 2
    sbb = _gaussian_valid(lb * lb) - mu_b ** 2
    sab = _gaussian_valid(la * lb) - mu_a * mu_b
    m = ((2 * mu_a * mu_b + c1) * (2 * sab + c2)) / ((mu_a ** 2 + mu_b ** 2 + c1) * (saa + sbb + c2))
    return float(m.mean())


def pareto_front(points):
    """Indices of the points no other point beats on both cost and error (lower is better on
    both), sorted by cost: the configurations worth choosing."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


# --------------------------------------------------------------------------------------------
# Study 1: speed against accuracy.

PSNR_TARGETS = [20, 25, 30, 35, 40]


def study_accuracy(tools, cfg, out, progress, tmp):
    """Trace time against image error over spp x depth for each scene, against a converged
    reference rendered by the same tracer (so the error is sampling and depth truncation, not
    a difference between implementations)."""
    c = cfg["accuracy"]
    combos = [(s, d) for d in c["depth"] for s in c["spp"]]
    progress.begin("accuracy", len(c["scenes"]) * (len(combos) + 2))
    rows, refs = [], {}
    for scene in c["scenes"]:
        path = SCENES / f"{scene}.scene"
        ref_exr, check_exr = tmp / f"{scene}-ref.exr", tmp / f"{scene}-check.exr"
        ref = tools.render(path, ref_exr, f"{scene} reference spp {c['ref_spp']} depth "
                           f"{c['ref_depth']}", c["size"], c["ref_spp"], c["ref_depth"])
        tools.render(path, check_exr, f"{scene} convergence check spp {c['check_spp']}",
                     c["size"], c["check_spp"], c["ref_depth"])
        ref_img, check_img = read_exr_rgb(ref_exr), read_exr_rgb(check_exr)
        refs[scene] = {"trace_ms": ref["trace_ms"], "check_rmse": rmse(check_img, ref_img),
                       "check_ssim": ssim(check_img, ref_img),
                       "mean_radiance": float(ref_img.mean())}
        for spp, depth in combos:
            exr = tmp / f"{scene}-{spp}-{depth}.exr"
            st = tools.render(path, exr, f"{scene} spp {spp} depth {depth}", c["size"], spp,
                              depth)
            img = read_exr_rgb(exr)
            e = rmse(img, ref_img)
            rows.append({"scene": scene, "spp": spp, "depth": depth,
                         "trace_ms": st["trace_ms"],
                         "rays": sum(st["rays"].values()), "rmse": e, "psnr_db": psnr(e),
                         "ssim": ssim(img, ref_img), "grid": st["grid"]})
            exr.unlink()
    progress.end()

    (out / "accuracy").mkdir(parents=True, exist_ok=True)
    write_json(out / "accuracy" / "data.json", {"config": c, "references": refs, "rows": rows})
    write_csv(out / "accuracy" / "data.csv", rows)
    charts = _accuracy_charts(rows, refs, c, out / "accuracy")
    return _accuracy_markdown(rows, refs, c, charts), _accuracy_summary(rows, c)


def _accuracy_charts(rows, refs, c, folder):
    """One chart per scene (time against RMSE, log-log, Pareto front) and one with every
    scene's front (PSNR against time)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    import numpy as np
    markers = ["o", "s", "^", "D", "v", "P", "X", "*"]
    colours = plt.get_cmap("viridis")
    depths, spps = c["depth"], c["spp"]
    charts = {}
    for scene in c["scenes"]:
        rs = [r for r in rows if r["scene"] == scene]
        fig, ax = plt.subplots(figsize=(7, 4.6))
        for r in rs:
            ax.scatter(r["trace_ms"], r["rmse"], s=42,
                       marker=markers[spps.index(r["spp"]) % len(markers)],
                       color=colours(depths.index(r["depth"]) / max(1, len(depths) - 1)),
                       edgecolors="black", linewidths=0.4, zorder=3)
        front = pareto_front([(r["trace_ms"], r["rmse"]) for r in rs])
        fx = [rs[i]["trace_ms"] for i in front]
        fy = [rs[i]["rmse"] for i in front]
        ax.step(fx, fy, where="post", color="crimson", lw=1.5, zorder=2, label="Pareto front")
        for i in front:
            ax.annotate(f"{rs[i]['spp']}/{rs[i]['depth']}", (rs[i]["trace_ms"], rs[i]["rmse"]),
                        textcoords="offset points", xytext=(4, 4), fontsize=7, color="crimson")
        ax.axhline(refs[scene]["check_rmse"], color="grey", ls=":", lw=1,
                   label=f"reference noise (spp {c['check_spp']} vs {c['ref_spp']})")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("trace time per frame (ms, GPU timestamps, lavapipe)")
        ax.set_ylabel("RMSE against the reference (linear RGB)")
        sec = ax.secondary_yaxis("right", functions=(lambda e: 20 * np.log10(1 / np.maximum(e, 1e-12)),
                                                     lambda p: 10 ** (-p / 20)))
        sec.set_ylabel("PSNR (dB, peak 1)")
        sec.yaxis.set_major_locator(matplotlib.ticker.FixedLocator(range(0, 101, 5)))
        sec.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:.0f}"))
        sec.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_title(f"{scene}: time against error, {c['size']} (labels: spp/depth)")
        handles = [plt.Line2D([], [], ls="", marker=markers[i % len(markers)], color="grey",
                              label=f"spp {s}") for i, s in enumerate(spps)]
        handles += [plt.Line2D([], [], ls="", marker="o",
                               color=colours(i / max(1, len(depths) - 1)), label=f"depth {d}")
                    for i, d in enumerate(depths)]
        handles += ax.get_legend_handles_labels()[0]
        ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.13, 1.0))
        ax.grid(True, which="both", alpha=0.25)
        name = f"time-vs-error-{scene}.png"
        save_figure(fig, folder / name)
        charts[scene] = name

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    cmap = plt.get_cmap("tab10")
    for k, scene in enumerate(c["scenes"]):
        rs = [r for r in rows if r["scene"] == scene]
        front = pareto_front([(r["trace_ms"], r["rmse"]) for r in rs])
        ax.plot([rs[i]["trace_ms"] for i in front], [rs[i]["psnr_db"] for i in front],
                marker=markers[k % len(markers)], ms=4, color=cmap(k % 10), label=scene)
    ax.set_xscale("log")
    ax.set_xlabel("trace time per frame (ms, GPU timestamps, lavapipe)")
    ax.set_ylabel("PSNR against the reference (dB, linear RGB, peak 1)")
    ax.set_title(f"Pareto fronts of every scene, {c['size']}: the best image a time buys")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, ncol=2)
    save_figure(fig, folder / "pareto-fronts.png")
    charts["_all"] = "pareto-fronts.png"
    return charts


def _accuracy_findings(rows, refs, c):
    """Sentences computed from the data (so that they stay true when the data change): where
    depth stops mattering, how error falls with spp, how converged the reference is."""
    import numpy as np
    out = []
    top_spp, top_depth = max(c["spp"]), max(c["depth"])
    saturate = {}
    for scene in c["scenes"]:
        rs = {(r["spp"], r["depth"]): r for r in rows if r["scene"] == scene}
        base = rs[(top_spp, top_depth)]["rmse"]
        saturate[scene] = next(d for d in c["depth"] if rs[(top_spp, d)]["rmse"] <= 1.05 * base)
    groups = {}
    for scene, d in saturate.items():
        groups.setdefault(d, []).append(scene)
    out.append("**Where depth stops mattering** (the smallest depth whose RMSE at "
               f"spp {top_spp} is within 5% of depth {top_depth}'s): " +
               "; ".join(f"depth {d}: {', '.join(groups[d])}" for d in sorted(groups)) + ".")
    slopes = []
    for scene in c["scenes"]:
        rs = sorted((r for r in rows if r["scene"] == scene and r["depth"] == top_depth),
                    key=lambda r: r["spp"])
        x = np.log([r["spp"] for r in rs])
        y = np.log([r["rmse"] for r in rs])
        slopes.append((scene, float(np.polyfit(x, y, 1)[0])))
    out.append("**Error against samples** (slope of log RMSE against log spp at depth "
               f"{top_depth}; -0.5 is plain Monte Carlo, steeper is stratification paying): " +
               ", ".join(f"{s} {k:.2f}" for s, k in slopes) + ".")
    ratio = max(refs[s]["check_rmse"] / min(r["rmse"] for r in rows if r["scene"] == s)
                for s in c["scenes"])
    if ratio < 0.25:
        out.append(f"**The reference is converged enough**: between spp {c['check_spp']} and "
                   f"spp {c['ref_spp']} (depth {c['ref_depth']}) the RMSE is at most "
                   f"{ratio * 100:.0f}% of the smallest error charted for the same scene (the "
                   "grey dotted line on each chart), so the charted errors are the "
                   "configurations' own, not the reference's noise.")
    else:
        floor = sum(1 for r in rows if r["rmse"] < 2 * refs[r["scene"]]["check_rmse"])
        out.append(f"**How far the reference can be trusted**: spp {c['check_spp']} against spp "
                   f"{c['ref_spp']} differs by up to {ratio * 100:.0f}% of the smallest "
                   "charted error, i.e. the best configurations reach the reference's own "
                   "noise (the grey dotted line on each chart). In depth, "
                   + (f"every scene's error has stopped changing by depth {max(saturate.values())}, "
                      f"well before the reference's {c['ref_depth']}"
                      if max(saturate.values()) < top_depth else
                      f"some scenes still change up to depth {top_depth}, so depth "
                      f"{c['ref_depth']} is converged only as far as depth {top_depth} shows")
                   + f"; in samples, not for the very best points: {floor} of {len(rows)} "
                   "configurations lie within 2x of that noise (marked † in the table) and "
                   "their error is an upper bound, not a measurement. Every other error is at "
                   "least twice the reference's noise. A 4x larger reference (spp 1024) would "
                   "halve the noise floor at 4x the reference's cost.")
    return out


def _accuracy_summary(rows, c):
    """One paragraph for the README's top: what to pick for a middling and a high quality."""
    picks = []
    for t in (30, 40):
        chosen = []
        for scene in c["scenes"]:
            ok = [r for r in rows if r["scene"] == scene and r["psnr_db"] >= t]
            if ok:
                chosen.append(min(ok, key=lambda r: r["trace_ms"]))
        if chosen:
            spp = sorted({r["spp"] for r in chosen})
            depth = sorted({r["depth"] for r in chosen})
            ms = sorted(r["trace_ms"] for r in chosen)
            picks.append(f"for {t} dB the cheapest choice on {len(chosen)} of "
                         f"{len(c['scenes'])} scenes is spp {spp[0]}-{spp[-1]} at depth "
                         f"{'/'.join(map(str, depth))}, {ms[0]:.0f}-{ms[-1]:.0f} ms at "
                         f"{c['size']}")
    top_spp, top_depth = max(c["spp"]), max(c["depth"])
    sat = []
    for scene in c["scenes"]:
        rs = {(r["spp"], r["depth"]): r["rmse"] for r in rows if r["scene"] == scene}
        sat.append(next(d for d in c["depth"]
                        if rs[(top_spp, d)] <= 1.05 * rs[(top_spp, top_depth)]))
    where = (f"at depth {min(sat)} on every scene" if min(sat) == max(sat) else
             f"at depth {min(sat)} to {max(sat)}, depending on the scene")
    return (f"Error stops falling with depth {where}; past that, time buys accuracy only "
            "through samples. " +
            ("; ".join(picks)[:1].upper() + "; ".join(picks)[1:] + ". " if picks else "") +
            "The per-scene table gives the pick for each target.")


def _accuracy_markdown(rows, refs, c, charts):
    p = "accuracy/"
    md = [f"For each scene, every `--spp` in {c['spp']} and `--depth` in {c['depth']} "
          f"at {c['size']}, one frame each, against a reference of `--spp {c['ref_spp']} "
          f"--depth {c['ref_depth']}` rendered by the same tracer. Errors: **RMSE** and "
          "**PSNR** on linear RGB (all pixels, three channels, PSNR peak 1.0 = display white), "
          "and **SSIM** (Wang et al. 2004) on display luminance (Rec. 709 Y, clipped to [0, 1], "
          "sRGB-encoded), 11x11 Gaussian window, sigma 1.5, K1 = 0.01, K2 = 0.03: SSIM sees "
          "noise and jagged edges as a viewer does, where PSNR counts only energy. Time is "
          "`trace_ms` (GPU timestamps of one frame) on a shared machine: single frames drift "
          "by 5-10%, so read the fronts, not the third digit.",
          "",
          f"Is the reference converged? In depth, {c['ref_depth']} is deeper than any charted "
          "depth (where error stops changing with depth is below). In samples, halving them "
          f"(spp {c['check_spp']}) shows the reference's own noise; errors far above it "
          "(ratio well below 1) are the configurations' own, errors near it are bounded by "
          "it:",
          "",
          md_table(["scene", f"RMSE spp {c['check_spp']} vs {c['ref_spp']}",
                    "smallest charted RMSE", "ratio", "reference trace ms"],
                   [[s, f"{refs[s]['check_rmse']:.2e}",
                     f"{min(r['rmse'] for r in rows if r['scene'] == s):.2e}",
                     f"{refs[s]['check_rmse'] / min(r['rmse'] for r in rows if r['scene'] == s):.2f}",
                     f"{refs[s]['trace_ms']:.0f}"] for s in c["scenes"]]),
          "",
          f"![Pareto fronts of every scene]({p}{charts['_all']})",
          "",
          "### For this error, pick this",
          "",
          "The cheapest configuration (spp / depth, and its trace ms) that reaches each PSNR; "
          "'-' where none charted does; † where its error is within 2x of the reference's "
          "noise (an upper bound):",
          ""]
    table = []
    for scene in c["scenes"]:
        rs = [r for r in rows if r["scene"] == scene]
        cells = []
        for t in PSNR_TARGETS:
            ok = [r for r in rs if r["psnr_db"] >= t]
            if ok:
                r = min(ok, key=lambda r: r["trace_ms"])
                dag = "†" if r["rmse"] < 2 * refs[scene]["check_rmse"] else ""
                cells.append(f"{r['spp']} / {r['depth']} ({r['trace_ms']:.0f} ms){dag}")
            else:
                cells.append("-")
        best = max(rs, key=lambda r: r["ssim"])
        cells.append(f"{best['ssim']:.3f} ({best['spp']} / {best['depth']})")
        table.append([scene] + cells)
    md.append(md_table(["scene"] + [f"PSNR >= {t} dB" for t in PSNR_TARGETS] + ["best SSIM"],
                       table))
    md += ["", "### What it shows", ""]
    md += [f"- {s}" for s in _accuracy_findings(rows, refs, c)]
    md += ["", "Per scene (x: trace ms, y: RMSE, right axis PSNR; colour = depth, marker = spp; "
           "the red staircase is the Pareto front, labelled spp/depth):", ""]
    md += [f"- [{s}]({p}{charts[s]})" for s in c["scenes"]]
    md += ["", f"Data: [{p}data.csv]({p}data.csv), [{p}data.json]({p}data.json)."]
    return "\n".join(md)


# --------------------------------------------------------------------------------------------
# Studies 2 and 3 (where offsets and triangle tests fail) live in their own files; they use this
# module's helpers, so it passes itself in.

def study_offsets_run(tools, cfg, out, progress, tmp):
    return study_offsets.run(sys.modules[__name__], tools, cfg, out, progress, tmp)


def study_triangles_run(tools, cfg, out, progress, tmp):
    return study_triangles.run(sys.modules[__name__], tools, cfg, out, progress, tmp)


def variant_supported(tools, token):
    return token in tools.bench_help()


# --------------------------------------------------------------------------------------------
# Study 4: acceleration against primitive count.

def study_acceleration(tools, cfg, out, progress, tmp):
    """Trace time and per-ray work (cells visited, primitive tests; counted on the CPU over a
    48-column lattice of primary rays) for every grid against primitive count, on spheres at
    constant density and on tori whose tessellation alone changes, and the teapot in a
    stadium; Embree's BVH beside them where prism-bench has it."""
    c = cfg["acceleration"]
    modes = tools.grid_modes()
    scenes = []
    for n in c["spheres"]:
        box = 10.0 * (n / 500.0) ** (1.0 / 3.0)
        scenes.append(("spheres", n, ["random", "--count", str(n), "--box", f"{box:.2f}",
                                      "--min-radius", "0.2", "--max-radius", "0.4"]))
    for n in c["tori"]:
        scenes.append(("tori", n, ["tori", "--triangles", str(n)]))
    stadium = [("stadium", "teapot-alone"), ("stadium", "teapot-in-stadium")] if c["stadium"] else []
    embree = False
    # Scenes with the same variants share one prism-bench process (one Vulkan start-up).
    groups = {}
    for family, n, args in scenes:
        variants = (["off"] if n <= c["off_max_primitives"] else []) + ["grid=10"] + modes
        groups.setdefault(tuple(variants), []).append((family, n, args))
    progress.begin("acceleration", len(scenes) + len(groups) + (1 if stadium else 0)
                   + (1 if c["embree"] else 0))
    if c["embree"]:
        progress.step("probing for Embree")
        embree = tools.has_embree(SCENES / "rand50.scene")
    rows = []
    for variants, members in groups.items():
        paths = []
        for family, n, args in members:
            path = tmp / f"{family}{n}.scene"
            tools.scenegen(args, path, f"generating {family} {n}")
            paths.append(path)
        names = ", ".join(f"{f} {n}" for f, n, _ in members)
        doc = tools.bench(paths, list(variants), f"{names}: {', '.join(variants)}", c["size"],
                          c["depth"], c["runs"], embree=embree)
        by_name = {p.stem: (f, n) for p, (f, n, _) in zip(paths, members)}
        rows += [_accel_row(*by_name[r["scene"]], r) for r in doc["results"]]
        for path in paths:
            path.unlink()
    if stadium:
        variants = ["grid=10"] + modes
        doc = tools.bench([SCENES / "studies" / f"{name}.scene" for _, name in stadium],
                          variants, f"teapot alone and in a stadium: {', '.join(variants)}",
                          c["size"], c["depth"], c["runs"], embree=embree)
        rows += [_accel_row(r["scene"], 0, r) for r in doc["results"]]
    progress.end()
    folder = out / "acceleration"
    write_json(folder / "data.json", {"config": c, "grid_modes": modes, "embree": embree,
                                      "rows": rows})
    write_csv(folder / "data.csv", rows)
    charts = _accel_charts(rows, c, modes, folder)
    return _accel_markdown(rows, c, modes, embree, charts), _accel_summary(rows)


def _accel_row(family, n, r):
    return {"family": family, "count": n, "variant": r["variant"], "grid": r["grid"],
            "primitives": r["primitives"], "build_ms": r["build_ms"],
            "trace_ms": r["trace_ms_median"], "mrays_per_s": r["mrays_per_s"],
            "cells_per_ray": r["cells_per_primary_ray"] if r["variant"] != "embree" else None,
            "tests_per_ray": r["tests_per_primary_ray"] if r["variant"] != "embree" else None,
            "max_per_cell": r["max_per_cell"], "grid_bytes": r["grid_bytes"],
            "rays": sum(r["rays"].values())}


def _variant_label(v):
    return {"off": "no grid", "grid=10": "10³ (original)", "auto": "auto (Prism)",
            "embree": "Embree BVH (CPU)"}.get(v, v)


def _accel_charts(rows, c, modes, folder):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    variants = ["off", "grid=10"] + modes + ["embree"]
    cmap = plt.get_cmap("tab10")
    style = {v: dict(color=cmap(i % 10), marker="os^DvPX*"[i % 8]) for i, v in enumerate(variants)}
    style["auto"].update(lw=2.6)
    charts = {}
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5))
    for col, (family, unit) in enumerate([("spheres", "spheres"), ("tori", "triangles")]):
        fam = [r for r in rows if r["family"] == family]
        for v in variants:
            rs = sorted((r for r in fam if r["variant"] == v), key=lambda r: r["count"])
            if not rs:
                continue
            kw = dict(style[v])
            kw.setdefault("lw", 1.3)
            label = _variant_label(v)
            if v == "off":
                label += f" (up to {c['off_max_primitives']:,})"
            axes[0][col].plot([r["count"] for r in rs], [r["trace_ms"] for r in rs],
                              label=label, ms=5, **kw)
            rt = [r for r in rs if r["tests_per_ray"] is not None]
            if rt:
                axes[1][col].plot([r["count"] for r in rt], [r["tests_per_ray"] for r in rt],
                                  label=f"{_variant_label(v)}: tests", ms=5, **kw)
                if v != "off":
                    kw2 = dict(kw, ls="--", alpha=0.6)
                    axes[1][col].plot([r["count"] for r in rt], [r["cells_per_ray"] for r in rt],
                                      ms=3, **kw2)
        axes[0][col].set_title(f"{family}: trace time ({c['size']}, depth {c['depth']})",
                               fontsize=10)
        axes[0][col].set_ylabel("trace ms per frame (median)")
        axes[1][col].set_title(f"{family}: per primary ray (solid: tests, dashed: cells)",
                               fontsize=10)
        axes[1][col].set_ylabel("primitive tests / cells visited per ray")
        for row in (0, 1):
            ax = axes[row][col]
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel(f"{unit} in the scene")
            ax.grid(True, which="both", alpha=0.25)
        axes[0][col].legend(fontsize=7)
        # No grid is measured only up to off_max_primitives: a lone point needs saying so.
        off = [r for r in fam if r["variant"] == "off"]
        if off and len(off) < len({r["count"] for r in fam}):
            last = max(off, key=lambda r: r["count"])
            for row, key in ((1, "tests_per_ray"),):  # the top row's legend says it
                axes[row][col].annotate(
                    f"no grid: measured up to {c['off_max_primitives']:,} {unit}\n"
                    "(beyond, a frame takes minutes)", (last["count"], last[key]),
                    xytext=(8, -4), textcoords="offset points", fontsize=7, va="top",
                    color=style["off"]["color"])
    fig.tight_layout()
    save_figure(fig, folder / "scaling.png")
    charts["scaling"] = "scaling.png"

    stadium = [r for r in rows if r["family"] in ("teapot-alone", "teapot-in-stadium")]
    if stadium:
        import numpy as np
        fig, ax = plt.subplots(figsize=(8, 4.2))
        present = [v for v in variants if any(r["variant"] == v for r in stadium)]
        width = 0.8 / len(present)
        for k, v in enumerate(present):
            ys = []
            for fam in ("teapot-alone", "teapot-in-stadium"):
                r = next((r for r in stadium if r["family"] == fam and r["variant"] == v), None)
                ys.append(r["trace_ms"] if r else np.nan)
            ax.bar(np.arange(2) + (k - (len(present) - 1) / 2) * width, ys, width,
                   color=style[v]["color"], label=_variant_label(v))
        ax.set_xticks([0, 1], ["teapot alone", "teapot in a 1000-unit stadium"])
        ax.set_yscale("log")
        ax.set_ylabel("trace ms per frame (median, log)")
        ax.set_title(f"One small dense object in a large scene ({c['size']}, depth {c['depth']})")
        ax.legend(fontsize=8)
        ax.grid(True, axis="y", which="both", alpha=0.25)
        save_figure(fig, folder / "stadium.png")
        charts["stadium"] = "stadium.png"
    return charts


def _accel_markdown(rows, c, modes, embree, charts):
    p = "acceleration/"
    md = [f"Scenes from `prism-scenegen`: random spheres at constant density (`random --count N "
          f"--box 10·(N/500)^(1/3) --min-radius 0.2 --max-radius 0.4`) for N in {c['spheres']}, "
          f"and five tori whose tessellation alone changes (`tori --triangles N`) for N in "
          f"{c['tori']}. `prism-bench --depth {c['depth']} --runs {c['runs']} --size {c['size']}` "
          "with every grid it knows (read from its `--help`: "
          f"{', '.join(modes)}), the original's fixed 10³ grid (`grid=10`) and no grid "
          f"(`off`, only up to {c['off_max_primitives']} primitives: beyond that a frame "
          "takes tens of seconds). Cells and tests per ray are counted on the CPU over a "
          "48-column lattice of primary rays. "
          + ("Embree 3's BVH (`--baseline embree`, the same rays, on all cores of the CPU, wall "
             "time) is beside them." if embree else
             "Embree's BVH is not in this run (`prism-bench --baseline embree` was not "
             "available or not asked for)."),
          ""]
    if max(c["tori"], default=0) < 1_000_000:
        md += ["The issue asks for tori up to 1M triangles; this run stops at "
               f"{max(c['tori'], default=0):,} to fit its time (add it with `--set "
               "acceleration.tori='[5000,50000,200000,1000000]'`).", ""]
    md += [f"![Scaling]({p}{charts['scaling']})", ""]
    header = ["scene", "variant", "grid", "build ms", "trace ms", "Mrays/s", "cells/ray",
              "tests/ray", "max/cell"]
    table = []
    for r in rows:
        name = f"{r['family']} {r['count']:,}" if r["count"] else r["family"]
        table.append([name, _variant_label(r["variant"]), r["grid"], f"{r['build_ms']:.1f}",
                      f"{r['trace_ms']:.1f}", f"{r['mrays_per_s']:.2f}",
                      "-" if r["cells_per_ray"] is None else f"{r['cells_per_ray']:.2f}",
                      "-" if r["tests_per_ray"] is None else f"{r['tests_per_ray']:.2f}",
                      r["max_per_cell"] if r["variant"] != "embree" else "-"])
    md += ["<details><summary>All rows</summary>", "", md_table(header, table), "",
           "</details>", "", "### What it shows", ""]
    md += [f"- {s}" for s in _accel_findings(rows, c)]
    if "stadium" in charts:
        md += ["", f"![Teapot in a stadium]({p}{charts['stadium']})"]
    md += ["", f"Data: [{p}data.csv]({p}data.csv), [{p}data.json]({p}data.json)."]
    return "\n".join(md)


def _growth(rows, family, variant):
    rs = sorted((r for r in rows if r["family"] == family and r["variant"] == variant),
                key=lambda r: r["count"])
    if len(rs) < 2:
        return None
    return rs[0], rs[-1]


def _accel_summary(rows):
    """One paragraph for the README's top: where each acceleration method fails."""
    out = []
    for family in ("spheres", "tori"):
        g10, ga = _growth(rows, family, "grid=10"), _growth(rows, family, "auto")
        if g10 and ga:
            out.append(f"from {g10[0]['count']:,} to {g10[1]['count']:,} {family} the original's "
                       f"fixed 10³ grid slows {g10[1]['trace_ms'] / g10[0]['trace_ms']:.1f}x, "
                       f"Prism's auto grid {ga[1]['trace_ms'] / ga[0]['trace_ms']:.1f}x")
    st = {r["variant"]: r for r in rows if r["family"] == "teapot-in-stadium"}
    text = ""
    for family in ("spheres", "tori"):
        off, ga = _growth(rows, family, "off"), _growth(rows, family, "auto")
        if off and ga and off[1]["tests_per_ray"] > 5 * ga[1]["tests_per_ray"]:
            text += (f"Without a grid a ray tests {off[1]['tests_per_ray']:.0f} {family} at "
                     f"{off[1]['count']:,} (auto: {ga[1]['tests_per_ray']:.1f}). ")
            break
    if out:
        text += "; ".join(out)[:1].upper() + "; ".join(out)[1:] + "."
    if "regular" in st and "auto" in st:
        text += (f" A regular grid fails on a small dense object in a large scene (teapot in a "
                 f"stadium: {st['regular']['trace_ms']:.0f} ms against auto's "
                 f"{st['auto']['trace_ms']:.0f} ms).")
    return text.strip()


def _accel_findings(rows, c):
    """Sentences computed from the data: how each method's time grows with the count."""
    out = []
    for family, unit in (("spheres", "spheres"), ("tori", "triangles")):
        parts = []
        for v in ["off", "grid=10", "auto", "regular", "adaptive", "two-level", "embree"]:
            g = _growth(rows, family, v)
            if g:
                a, b = g
                parts.append(f"{_variant_label(v)} {b['trace_ms'] / a['trace_ms']:.1f}x "
                             f"({a['count']:,} -> {b['count']:,})")
        if parts:
            out.append(f"**Time growth on {unit}** (last count's trace ms over the first's): "
                       + "; ".join(parts) + ".")
        g10 = _growth(rows, family, "grid=10")
        ga = _growth(rows, family, "auto")
        if g10 and ga:
            out.append(f"At {g10[1]['count']:,} {unit} the original's 10³ grid tests "
                       f"{g10[1]['tests_per_ray']:.0f} primitives a primary ray where auto "
                       f"tests {ga[1]['tests_per_ray']:.1f}: a fixed grid fails as the count "
                       f"grows ({g10[1]['trace_ms'] / ga[1]['trace_ms']:.1f}x the time).")
    st = {r["variant"]: r for r in rows if r["family"] == "teapot-in-stadium"}
    al = {r["variant"]: r for r in rows if r["family"] == "teapot-alone"}
    if st and "auto" in st and "regular" in st:
        out.append(f"**Teapot in a stadium**: the regular grid puts {st['regular']['max_per_cell']:,} "
                   f"triangles in one cell and takes {st['regular']['trace_ms']:.0f} ms; auto "
                   f"({st['auto']['grid']}) takes {st['auto']['trace_ms']:.0f} ms, "
                   f"{st['auto']['trace_ms'] / al['auto']['trace_ms']:.2f}x the teapot alone.")
    if any(r["variant"] == "embree" for r in rows):
        ratios = [(r, next(e for e in rows if e["variant"] == "embree" and
                           e["family"] == r["family"] and e["count"] == r["count"]))
                  for r in rows if r["variant"] == "auto"]
        out.append("**Against Embree** (auto's Mrays/s over Embree's): " + ", ".join(
            (f"{r['family']} {r['count']:,}" if r["count"] else r["family"]) +
            f" {r['mrays_per_s'] / e['mrays_per_s']:.2f}" for r, e in ratios) + ".")
    return out


# --------------------------------------------------------------------------------------------
# Study 5: the original's tables.

def study_original(tools, cfg, out, progress, tmp):
    """The original's four experiments on Prism: seed scenes against its CPU and GPU times,
    grid density, feature cost on the teapot and frame time against resolution."""
    c = cfg["original"]
    seeds = [SCENES / f"{s}.scene" for s in c["seed_scenes"]]
    progress.begin("original", 3 + len(c["resolutions"]))
    seed = tools.bench(seeds, ["auto"], f"seed scenes at {c['size']}, depth 2", c["size"], 2,
                       c["runs"])["results"]
    density = tools.bench([SCENES / f"{s}.scene" for s in c["density_scenes"]],
                          ["grid=10", "grid=20", "grid=30", "auto"],
                          "grid density 10³/20³/30³/auto", c["size"], 2, c["runs"])["results"]
    features = tools.bench([SCENES / f"{c['feature_scene']}.scene"], list(ORIGINAL_FEATURE_FPS),
                           "feature cost on teapot", c["feature_size"], 2, c["runs"])["results"]
    resolution = []
    for size in c["resolutions"]:
        r = tools.bench([SCENES / f"{c['resolution_scene']}.scene"], ["auto"],
                        f"{c['resolution_scene']} at {size}", size, 2, c["runs"])["results"][0]
        w, h = (int(x) for x in size.split("x"))
        resolution.append({"size": size, "pixels": w * h, "trace_ms": r["trace_ms_median"],
                           "frame_ms": r["frame_ms"], "rays": sum(r["rays"].values())})
    progress.end()
    folder = out / "original"
    data = {"config": c, "seed": seed, "density": density, "features": features,
            "resolution": resolution}
    write_json(folder / "data.json", data)
    flat = []
    for part in ("seed", "density", "features"):
        for r in data[part]:
            flat.append({"table": part, "scene": r["scene"], "variant": r["variant"],
                         "grid": r["grid"], "trace_ms": r["trace_ms_median"],
                         "mrays_per_s": r["mrays_per_s"], "max_per_cell": r["max_per_cell"],
                         "rays": sum(r["rays"].values())})
    for r in resolution:
        flat.append({"table": "resolution", "scene": c["resolution_scene"], "variant": r["size"],
                     "grid": "", "trace_ms": r["trace_ms"], "mrays_per_s": "",
                     "max_per_cell": "", "rays": r["rays"]})
    write_csv(folder / "data.csv", flat)
    charts = _original_charts(data, c, folder)
    return _original_markdown(data, c, charts), _original_summary(data)


def _resolution_fit(resolution):
    """Least-squares fit of log time against log pixels: the exponent (1 = linear)."""
    import numpy as np
    x = np.log([r["pixels"] for r in resolution])
    y = np.log([r["trace_ms"] for r in resolution])
    k, b = np.polyfit(x, y, 1)
    return float(k), float(b)


def _original_charts(data, c, folder):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    charts = {}
    seed = data["seed"]
    fig, ax = plt.subplots(figsize=(8.5, 4.2))
    x = np.arange(len(seed))
    ax.bar(x - 0.27, [r["trace_ms_median"] / 1000 for r in seed], 0.27,
           label=f"Prism, lavapipe, 2 cores ({c['size']})", color="tab:blue")
    ax.bar(x, [ORIGINAL[r["scene"]][1] for r in seed], 0.27,
           label="original, OpenCL, FX 8350 CPU (8 cores)", color="tab:orange")
    ax.bar(x + 0.27, [ORIGINAL[r["scene"]][2] for r in seed], 0.27,
           label="original, HD 7870 GPU", color="tab:green")
    ax.set_xticks(x, [r["scene"] for r in seed])
    ax.set_yscale("log")
    ax.set_ylabel("seconds per frame (log)")
    ax.set_title("Seed scenes, depth 2 (one level of reflection/refraction), 1 spp")
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=3)
    ax.grid(True, axis="y", which="both", alpha=0.25)
    save_figure(fig, folder / "seed-scenes.png")
    charts["seed"] = "seed-scenes.png"

    res = data["resolution"]
    k, b = _resolution_fit(res)
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    px = np.array([r["pixels"] for r in res], dtype=float)
    ax.plot(px / 1e6, [r["trace_ms"] for r in res], "o-", label="Prism (median trace ms)")
    lin = res[-1]["trace_ms"] * px / px[-1]
    ax.plot(px / 1e6, lin, "k:", label="linear in pixels (through the largest)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("megapixels per frame")
    ax.set_ylabel("trace ms per frame")
    ax.set_title(f"{c['resolution_scene']}, depth 2: time ∝ pixels^{k:.2f}")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.25)
    save_figure(fig, folder / "resolution.png")
    charts["resolution"] = "resolution.png"

    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    dens = data["density"]
    scenes = list(dict.fromkeys(r["scene"] for r in dens))
    variants = ["grid=10", "grid=20", "grid=30", "auto"]
    for k2, v in enumerate(variants):
        ys = []
        for s in scenes:
            r = next(r for r in dens if r["scene"] == s and r["variant"] == v)
            first = next(r for r in dens if r["scene"] == s and r["variant"] == "grid=10")
            ys.append(r["trace_ms_median"] / first["trace_ms_median"])
        axes[0].bar(np.arange(len(scenes)) + (k2 - 1.5) * 0.2, ys, 0.2,
                    label=v.replace("grid=", "") + ("³" if v != "auto" else ""))
    for k2, s in enumerate(scenes):
        if s in ORIGINAL_DENSITY_GPU_S:
            o = ORIGINAL_DENSITY_GPU_S[s]
            axes[0].plot(np.array([-1.5, -0.5, 0.5]) * 0.2 + k2,
                         [o[v] / o["grid=10"] for v in variants[:3]], "kx", ms=8,
                         label="original GPU" if k2 == 0 else None)
    axes[0].set_xticks(range(len(scenes)), scenes)
    axes[0].set_ylabel("time relative to the 10³ grid")
    axes[0].set_title("Grid density (bars: Prism; x: original GPU)")
    axes[0].legend(fontsize=8)
    feats = data["features"]
    base = feats[0]["trace_ms_median"]
    labels = [FEATURE_LABELS[r["variant"]] for r in feats]
    axes[1].bar(np.arange(len(feats)) - 0.2, [r["trace_ms_median"] / base for r in feats], 0.4,
                label="Prism")
    axes[1].bar(np.arange(len(feats)) + 0.2,
                [ORIGINAL_FEATURE_FPS["auto"] / ORIGINAL_FEATURE_FPS[r["variant"]] for r in feats],
                0.4, label="original GPU (1/FPS)")
    axes[1].set_xticks(range(len(feats)), labels, rotation=15, fontsize=8)
    axes[1].set_ylabel("frame time relative to all features")
    axes[1].set_title(f"Feature cost on {c['feature_scene']}")
    axes[1].legend(fontsize=8)
    for ax in axes:
        ax.grid(True, axis="y", alpha=0.25)
    save_figure(fig, folder / "density-features.png")
    charts["density"] = "density-features.png"
    return charts


def _original_summary(data):
    """One paragraph for the README's top: Prism against the original, and resolution."""
    seed = data["seed"]
    faster = sum(r["trace_ms_median"] / 1000 < ORIGINAL[r["scene"]][1] for r in seed)
    k, _ = _resolution_fit(data["resolution"])
    return (f"On lavapipe (2 cores) Prism beats the original's 8-core OpenCL CPU on {faster} of "
            f"{len(seed)} seed scenes; its frame time grows as pixels^{k:.2f} "
            + ("(close to linear, where the original's was not)." if 0.9 <= k <= 1.1 else
               "(not linear: see the resolution chart)."))


def _original_markdown(data, c, charts):
    p = "original/"
    seed = data["seed"]
    md = [f"`prism-bench --depth 2 --runs {c['runs']}` (median frame, GPU timestamps, "
          "`--grid auto`); the original's figures are from SEED_NOTES (OpenCL, 1024x768, one "
          "light, a 10³ grid). Scenes are recreations (assets/scenes/README.md), so a row "
          "compares the same kind of work, not identical images"
          + ("." if c["size"] == "1024x768" else
             f"; **this run is at {c['size']}, not the original's 1024x768**."),
          "", "### Seed scenes against the original", "", f"![Seed scenes]({p}{charts['seed']})",
          "",
          md_table(["scene", "primitives", "grid", "max/cell", "trace ms", "Mrays/s",
                    "original CPU s", "original GPU s", "Prism / original CPU"],
                   [[r["scene"], r["primitives"], r["grid"], r["max_per_cell"],
                     f"{r['trace_ms_median']:.1f}", f"{r['mrays_per_s']:.2f}",
                     ORIGINAL[r["scene"]][1], ORIGINAL[r["scene"]][2],
                     f"{r['trace_ms_median'] / 1000 / ORIGINAL[r['scene']][1]:.3g}"]
                    for r in seed]),
          "", "### Grid density and feature cost", "",
          f"![Grid density and feature cost]({p}{charts['density']})", ""]
    rows = []
    for r in data["density"]:
        first = next(x for x in data["density"] if x["scene"] == r["scene"]
                     and x["variant"] == "grid=10")
        o = ORIGINAL_DENSITY_GPU_S.get(r["scene"], {})
        rows.append([r["scene"], r["variant"], r["grid"], r["max_per_cell"],
                     f"{r['trace_ms_median']:.1f}",
                     f"{r['trace_ms_median'] / first['trace_ms_median']:.2f}",
                     f"{o[r['variant']] / o['grid=10']:.2f}" if r["variant"] in o else "-"])
    md += [md_table(["scene", "variant", "grid", "max/cell", "trace ms", "vs 10³",
                     "original GPU vs 10³"], rows), ""]
    base = data["features"][0]["trace_ms_median"]
    md += [md_table(["variant", "trace ms", "rays (M)", "time vs all", "original GPU FPS (vs all)"],
                    [[FEATURE_LABELS[r["variant"]], f"{r['trace_ms_median']:.1f}",
                      f"{sum(r['rays'].values()) / 1e6:.2f}",
                      f"{r['trace_ms_median'] / base:.2f}",
                      f"{ORIGINAL_FEATURE_FPS[r['variant']]} "
                      f"({ORIGINAL_FEATURE_FPS['auto'] / ORIGINAL_FEATURE_FPS[r['variant']]:.2f})"]
                     for r in data["features"]]), ""]
    res = data["resolution"]
    k, _ = _resolution_fit(res)
    per_px = [r["trace_ms"] * 1e3 / r["pixels"] for r in res]
    md += ["### Frame time against resolution", "", f"![Resolution]({p}{charts['resolution']})", "",
           md_table(["size", "pixels", "trace ms", "µs per pixel"],
                    [[r["size"], f"{r['pixels']:,}", f"{r['trace_ms']:.1f}", f"{q:.2f}"]
                     for r, q in zip(res, per_px)]), "",
           "### What it shows", ""]
    faster = [r["scene"] for r in seed if r["trace_ms_median"] / 1000 < ORIGINAL[r["scene"]][1]]
    md.append(f"- Prism on lavapipe beats the original's 8-core CPU on "
              f"{len(faster)} of {len(seed)} seed scenes"
              + (f" ({', '.join(faster)})" if faster else "") + "; the original's GPU is "
              "faster than Prism on " + str(sum(r["trace_ms_median"] / 1000 > ORIGINAL[r["scene"]][2]
                                                for r in seed)) + f" of {len(seed)}.")
    linear = "close to linear" if 0.9 <= k <= 1.1 else ("sub-linear" if k < 0.9 else "super-linear")
    md.append(f"- Frame time grows as pixels^{k:.2f}, {linear}: per-pixel cost goes from "
              f"{per_px[0]:.2f} to {per_px[-1]:.2f} µs per pixel from {res[0]['size']} to "
              f"{res[-1]['size']}. Small frames cost more per pixel (fixed dispatch cost, too few "
              "workgroups to fill the cores); the original's non-linearity came from host "
              "overhead, which these GPU timestamps do not include.")
    f = {r["variant"]: r["trace_ms_median"] / base for r in data["features"]}
    if "no-refraction" in f:
        costliest = min(("no-reflection", "no-refraction", "no-shadows"), key=lambda v: f[v])
        md.append(f"- Switching off {FEATURE_LABELS[costliest][3:]} saves the most "
                  f"({f[costliest]:.2f}x the time), as in the original (no refraction: "
                  f"{ORIGINAL_FEATURE_FPS['auto'] / ORIGINAL_FEATURE_FPS['no-refraction']:.2f}x).")
    md += ["", f"Data: [{p}data.csv]({p}data.csv), [{p}data.json]({p}data.json)."]
    return "\n".join(md)


# --------------------------------------------------------------------------------------------
# The README.

README_INTRO = """# Studies

What an image costs against what it is worth, and where methods fail (issue 9). Every chart,
table and figure below was made by `tools/scripts/studies.py`; run it again to regenerate this
folder (`--help` for options, `--quick` for a toy run). The sentences under "What it shows" are
computed from the data by the script, so they stay true to the numbers of the run above them.
"""


def write_readme(out, status, review):
    """Collects every study's section (from this run or an earlier one) into DIR/README.md."""
    parts = [README_INTRO]
    meta = {}
    for name in STUDY_ORDER:
        f = out / name / "section.json"
        if f.is_file():
            meta[name] = json.loads(f.read_text())
    parts.append("## Contents\n")
    for name in STUDY_ORDER:
        s = meta.get(name, {}).get("status", "not run")
        anchor = re.sub(r"[^a-z0-9 -]", "", STUDY_TITLES[name].lower()).replace(" ", "-")
        parts.append(f"- [{STUDY_TITLES[name]}](#{anchor}): {s}")
    parts.append("")
    if meta:
        parts.append("## In short\n")
        parts += [f"- **{STUDY_TITLES[n][3:]}.** {meta[n].get('summary', '')}" for n in STUDY_ORDER
                  if n in meta]
        parts.append("")
    if review:
        parts += ["## Checked by eye\n", review.strip(), ""]
    for name in STUDY_ORDER:
        m = meta.get(name)
        parts.append(f"## {STUDY_TITLES[name]}\n")
        if not m:
            parts.append("Not run yet: `tools/scripts/studies.py " + name + "`.\n")
            continue
        load = (f", load {m['load_note']}" if m.get("load_note")
                else f", load {m['load_before']:.2f} when the run began" if "load_before" in m
                else ", machine load not recorded")
        parts.append(f"*Run {m['date']} on {m['device']} ({m['host']}), "
                     f"{m['seconds']:.0f} s{load}: `{m['command']}`*\n")
        parts.append(m["markdown"] + "\n")
    write_text(out / "README.md", "\n".join(parts))


def replot(out, chosen, args):
    """Remakes charts, Markdown and README from the data of an earlier run, keeping that run's
    date, device, command line and time: a chart can be fixed without re-measuring."""
    global WRITE_SVG, FIGURE_STAMP
    for name in chosen:
        data_path, sec_path = out / name / "data.json", out / name / "section.json"
        if not (data_path.is_file() and sec_path.is_file()):
            continue
        d, sec = json.loads(data_path.read_text()), json.loads(sec_path.read_text())
        WRITE_SVG = "quick" not in sec["status"]
        FIGURE_STAMP = stamp_text(sec)
        folder = out / name
        if name == "accuracy":
            charts = _accuracy_charts(d["rows"], d["references"], d["config"], folder)
            sec["markdown"] = _accuracy_markdown(d["rows"], d["references"], d["config"], charts)
            sec["summary"] = _accuracy_summary(d["rows"], d["config"])
        elif name == "offsets":
            kit = sys.modules[__name__]
            charts = study_offsets.charts_of(kit, d["rows"], d["config"], folder)
            if (folder / "failures.png").is_file():  # made from the images, not the data
                charts["failures"] = "failures.png"
            sec["markdown"] = study_offsets.markdown(kit, d["rows"], d["config"], charts)
            sec["summary"] = study_offsets.summary(d["rows"])
        elif name == "triangles":
            kit = sys.modules[__name__]
            chart = study_triangles.charts_of(kit, d["rows"], d["timing"], d["config"], folder)
            renders = "renders.png" if (folder / "renders.png").is_file() else None
            sec["markdown"] = study_triangles.markdown(kit, d["rows"], d["timing"], d["config"],
                                                       chart, renders)
            sec["summary"] = study_triangles.summary(d["rows"], d["timing"])
        elif name == "acceleration":
            charts = _accel_charts(d["rows"], d["config"], d["grid_modes"], folder)
            sec["markdown"] = _accel_markdown(d["rows"], d["config"], d["grid_modes"],
                                              d["embree"], charts)
            sec["summary"] = _accel_summary(d["rows"])
        elif name == "original":
            charts = _original_charts(d, d["config"], folder)
            sec["markdown"] = _original_markdown(d, d["config"], charts)
            sec["summary"] = _original_summary(d)
        write_json(sec_path, sec)
        print(f"studies: [{name}] replotted", file=sys.stderr)
    review_path = Path(args.review) if args.review else out / "REVIEW.md"
    write_readme(out, {}, review_path.read_text() if review_path.is_file() else None)
    return 0


def main():
    parser = argparse.ArgumentParser(
        description="Charts what an image costs against what it is worth, and where methods "
                    "fail (issue 9). Writes charts, data and DIR/README.md.",
        epilog="Studies: " + ", ".join(STUDY_ORDER) + ". Without STUDY, all of them.")
    parser.add_argument("studies", nargs="*", metavar="STUDY", help="studies to run (default all)")
    parser.add_argument("--quick", action="store_true",
                        help="toy sizes: every study in well under a minute (the test runs it)")
    parser.add_argument("--out", default=str(ROOT / "docs" / "studies"),
                        help="output folder (default docs/studies/)")
    parser.add_argument("--bin", default=str(ROOT / "build" / "bin"),
                        help="folder of prism-render, prism-bench, prism-scenegen (default "
                             "build/bin)")
    parser.add_argument("--set", action="append", default=[], metavar="STUDY.KEY=JSON",
                        help="override one size of the configuration, e.g. "
                             "accuracy.size='\"160x120\"' (recorded in the README)")
    parser.add_argument("--replot", action="store_true",
                        help="remake charts, sections and README from DIR/STUDY/data.json "
                             "without running anything (after a change to a chart)")
    parser.add_argument("--review", metavar="FILE",
                        help="Markdown notes of a by-eye check of the charts, put in the README "
                             "under 'Checked by eye' (default: DIR/REVIEW.md if it exists)")
    args = parser.parse_args()

    unknown = [s for s in args.studies if s not in STUDY_ORDER]
    if unknown:
        parser.error(f"unknown study {', '.join(unknown)} (choose from {', '.join(STUDY_ORDER)})")
    chosen = [s for s in STUDY_ORDER if s in (args.studies or STUDY_ORDER)]
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
        import OpenImageIO  # noqa: F401
    except ImportError as e:
        print(f"studies.py: {e}: install python3-numpy, python3-matplotlib and "
              "python3-openimageio (Debian) or run with /usr/bin/python3", file=sys.stderr)
        return 2

    out = Path(args.out).resolve()
    if args.replot:
        return replot(out, chosen, args)
    global WRITE_SVG, FIGURE_STAMP
    WRITE_SVG = not args.quick
    progress = Progress()
    failed = []
    try:
        config = make_config(args.quick)
        apply_overrides(config, args.set)
        tools = Tools(args.bin, progress)
        command = " ".join(["tools/scripts/studies.py"] + [shlex.quote(a) for a in sys.argv[1:]])
        head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short=10", "HEAD"],
                              capture_output=True, text=True).stdout.strip() or "unknown"
        # The load as the command began, before its own work raised it: a study that follows
        # another would otherwise read the first one's load as if it were someone else's.
        stamp = {"date": datetime.date.today().isoformat(), "commit": head,
                 "load_before": os.getloadavg()[0], "cpus": os.cpu_count()}
        FIGURE_STAMP = stamp_text(stamp)
        for name in chosen:
            started = time.monotonic()
            with tempfile.TemporaryDirectory(prefix=f"studies-{name}-") as tmp:
                try:
                    fn = {"accuracy": study_accuracy, "offsets": study_offsets_run,
                          "triangles": study_triangles_run, "acceleration": study_acceleration,
                          "original": study_original}[name]
                    md, summary = fn(tools, config, out, progress, Path(tmp))
                    status = "done" + (" (quick)" if args.quick else "")
                except StudyError as e:
                    progress.end()
                    print(f"studies.py: {name}: {e}", file=sys.stderr)
                    failed.append(name)
                    continue
            seconds = time.monotonic() - started
            write_json(out / name / "section.json", {
                **stamp, "load_after": os.getloadavg()[0], "status": status,
                "device": tools.device or "no device used", "host": f"{platform.node()}, "
                f"{os.cpu_count()} CPUs", "seconds": seconds, "command": command,
                "config": config.get(name, {}), "summary": summary,
                "markdown": md})
            print(f"studies: [{name}] {status} in {seconds:.0f} s", file=sys.stderr)
        review = None
        review_path = Path(args.review) if args.review else out / "REVIEW.md"
        if review_path.is_file():
            review = review_path.read_text()
        write_readme(out, {}, review)
    except StudyError as e:
        progress.end()
        print(f"studies.py: {e}", file=sys.stderr)
        return 1
    if failed:
        print(f"studies.py: failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    print(f"studies: wrote {out / 'README.md'} in {time.monotonic() - progress.start:.0f} s",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
