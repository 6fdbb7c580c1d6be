"""Study 3 of tools/scripts/studies.py: where triangle tests fail.

A parallel camera looks, along a slanted direction, at a closed mesh built so that every pixel
ray passes through a shared edge or vertex of its front: the front's vertices lie on the rays of
every second pixel row and column, so the pixels between them look at edge midpoints. The front
is red, the back and sides blue, the background green: a pixel that is not red is a ray that
leaked through the front. Prism's watertight test (Woop et al. 2013, the default) is set
against Moller-Trumbore 1997 (prism-bench variant triangle=mt), at the origin and moved up to
1e5 away (in the file's coordinates, so that rounding bites, and centred on the camera as Prism
renders), and both are timed on real meshes.

`kit` is the studies.py module itself (its output helpers and settings), passed in by it.
"""
import math

METHODS = {"auto": "watertight (Prism)", "triangle=mt": "Möller–Trumbore"}
MARGIN = 4  # pixels around the mesh: its outline (edge-on side walls) is not counted
KINDS = ("vertex", "edge", "diagonal")


def _unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def mesh_scene(n, shift):
    """The .scene text of the study's closed mesh for an n x n image, moved by `shift` along
    x, y and z, and the camera that aims its pixel rays at the mesh's edges and vertices."""
    spacing = 1.0  # scene units per pixel
    view = _unit([1.0, 2.0, 3.0])  # from the mesh towards the eye: no axis, no 45 degrees
    distance = 2.0 * n * spacing
    centre = [shift, shift, shift]
    eye = [c + distance * v for c, v in zip(centre, view)]
    forward = [-v for v in view]
    right = _unit(_cross(forward, [0.0, 1.0, 0.0]))
    up = _cross(right, forward)

    def pixel_ray(i, j):  # docs/scene-format.md, "Cameras": the ray of pixel (i, j)'s centre
        x, y = (i + 0.5 - n / 2) * spacing, (n / 2 - j - 0.5) * spacing
        return [e + x * r + y * u for e, r, u in zip(eye, right, up)]

    cells = (n - 2 * MARGIN) // 2
    lattice = [MARGIN + 2 * k for k in range(cells + 1)]

    def depth(a, b, back):  # a bumpy front and back, so no two faces are coplanar
        wave = math.sin(1.3 * a + 0.4) * math.cos(0.9 * b) + 0.5 * math.sin(0.7 * (a + b))
        return distance + (n * spacing / 4 if back else 0.0) + (0.7 if back else 3.0) * wave

    index = {}
    lines = ["# Made by tools/scripts/studies.py (study 3): every pixel ray meets a shared edge",
             "# or vertex of the red front; green or blue pixels are rays that leaked through.",
             "camera eye " + " ".join(map(repr, eye)) + " look " + " ".join(map(repr, centre)) +
             f" ortho {n * spacing!r}",
             "background 0 1 0", "ambient 1 1 1",
             "material front color 1 0 0 ambient 1 diffuse 0 specular 0",
             "material back color 0 0 1 ambient 1 diffuse 0 specular 0"]
    for back in (False, True):
        for b, j in enumerate(lattice):
            for a, i in enumerate(lattice):
                o = pixel_ray(i, j)
                t = depth(a, b, back)
                lines.append("v " + " ".join(repr(oc + t * fc) for oc, fc in zip(o, forward)))
                index[(back, a, b)] = len(index) + 1

    def quad(p, q, r, s):  # split along p-r: the diagonal whose midpoint a pixel ray meets
        return [f"f {p} {q} {r}", f"f {p} {r} {s}"]

    lines.append("use front")
    for b in range(cells):
        for a in range(cells):
            v = [index[(False, a + da, b + db)] for da, db in ((0, 0), (1, 0), (1, 1), (0, 1))]
            lines += quad(*v)
    lines.append("use back")
    for b in range(cells):
        for a in range(cells):
            v = [index[(True, a + da, b + db)] for da, db in ((0, 0), (0, 1), (1, 1), (1, 0))]
            lines += quad(*v)
    rim = [(a, 0) for a in range(cells)] + [(cells, b) for b in range(cells)] + \
          [(a, cells) for a in range(cells, 0, -1)] + [(0, b) for b in range(cells, 0, -1)]
    for k, (a, b) in enumerate(rim):
        a2, b2 = rim[(k + 1) % len(rim)]
        lines += quad(index[(False, a, b)], index[(True, a, b)], index[(True, a2, b2)],
                      index[(False, a2, b2)])
    return "\n".join(lines) + "\n"


def classify(img, n):
    """Counts, over the pixels inside the mesh's outline, those that show the red front and
    those that leaked, by what the ray was aimed at (vertex, axis edge, diagonal edge)."""
    counts = {k: {"rays": 0, "leaks": 0, "through_both": 0} for k in KINDS}
    for j in range(MARGIN + 1, n - MARGIN):
        for i in range(MARGIN + 1, n - MARGIN):
            odd = (i - MARGIN) % 2 + (j - MARGIN) % 2
            kind = KINDS[odd]
            r, g, b = img[j, i]
            counts[kind]["rays"] += 1
            if not (r > 0.5 and g < 0.5 and b < 0.5):
                counts[kind]["leaks"] += 1
                counts[kind]["through_both"] += int(g > 0.5)
    return counts


def run(kit, tools, cfg, out, progress, tmp):
    """Renders the mesh at every distance under both tests, centred and not, then times both
    tests on the mesh and on real meshes; returns (markdown, summary)."""
    c = cfg["triangles"]
    n = c["size"]
    paths = {}
    for d in c["shifts"]:
        paths[d] = tmp / f"mesh-d{d:g}.scene"
        kit.write_text(paths[d], mesh_scene(n, float(d)))
    progress.begin("triangles", 3)
    rows, seen = [], {}
    for centred in (True, False):
        folder = tmp / ("centred" if centred else "kept")
        folder.mkdir()
        tools.bench(list(paths.values()), list(METHODS), "every distance, " +
                    ("centred on the camera" if centred else "--keep-origin"), f"{n}x{n}", 1, 1,
                    save_images=folder, keep_origin=not centred)
        for d, path in paths.items():
            for v in METHODS:
                exr = folder / f"{path.stem}_{v}.exr"
                img = kit.read_exr_rgb(exr)
                counts = classify(img, n)
                exr.unlink()
                if centred and d == c["shifts"][0]:
                    seen[v] = img
                rays = sum(k["rays"] for k in counts.values())
                leaks = sum(k["leaks"] for k in counts.values())
                rows.append({"shift": float(d), "method": v, "centred": centred, "rays": rays,
                             "leaks": leaks, "leak_fraction": leaks / rays,
                             "through_both": sum(k["through_both"] for k in counts.values()),
                             **{f"{k}_rays": counts[k]["rays"] for k in KINDS},
                             **{f"{k}_leaks": counts[k]["leaks"] for k in KINDS}})
    timing_scenes = [paths[c["shifts"][0]]] + [kit.SCENES / f"{s}.scene" for s in c["time_scenes"]]
    doc = tools.bench(timing_scenes, list(METHODS), "timing both tests", c["time_size"],
                      c["time_depth"], c["runs"])
    progress.end()
    timing = [{"scene": "study mesh" if r["scene"] == timing_scenes[0].stem else r["scene"],
               "method": r["variant"], "primitives": r["primitives"],
               "trace_ms": r["trace_ms_median"], "frame_ms": r["frame_ms"],
               "rays": sum(r["rays"].values())} for r in doc["results"]]
    folder = out / "triangles"
    kit.write_json(folder / "data.json", {"config": c, "margin": MARGIN, "rows": rows,
                                          "timing": timing})
    kit.write_csv(folder / "data.csv", rows)
    chart = charts_of(kit, rows, timing, c, folder)
    renders = _renders(kit, seen, n, folder)
    return markdown(kit, rows, timing, c, chart, renders), summary(rows, timing)


def _renders(kit, seen, n, folder):
    """The two tests' images of the mesh side by side: the leaks the chart counts, seen."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.patches
    import matplotlib.pyplot as plt
    import numpy as np
    fig, axes = plt.subplots(1, len(seen), figsize=(4.2 * len(seen), 4.4))
    for ax, (v, img) in zip(axes, seen.items()):
        ax.imshow(np.clip(img, 0, 1), interpolation="nearest")
        side = n - 2 * MARGIN - 1  # the counted pixels; the rim outside is edge-on side walls
        ax.add_patch(matplotlib.patches.Rectangle((MARGIN + 0.5, MARGIN + 0.5), side, side,
                                                  fill=False, ec="white", lw=0.8, ls=":"))
        leaks = sum(k["leaks"] for k in classify(img, n).values())
        ax.set_title(f"{METHODS[v]}:\n{leaks:,} leaking pixels inside the dotted line",
                     fontsize=9)
        ax.axis("off")
    kit.save_figure(fig, folder / "renders.png")
    return "renders.png"



def _leaks(rows, method, centred):
    return sorted((r for r in rows if r["method"] == method and r["centred"] == centred),
                  key=lambda r: r["shift"])


def _ratio(timing, scene):
    """Moller-Trumbore's time over the watertight test's: the median over prism-bench's rounds
    of the ratio of the two frames of a round, which ran one after the other (so load that
    drifts between rounds cancels), and the lowest and highest of those ratios."""
    t = {r["method"]: r["frame_ms"] for r in timing if r["scene"] == scene}
    ratios = sorted(m / w for m, w in zip(t["triangle=mt"], t["auto"]))
    k = len(ratios)
    median = ratios[k // 2] if k % 2 else 0.5 * (ratios[k // 2 - 1] + ratios[k // 2])
    return median, ratios[0], ratios[-1]


def charts_of(kit, rows, timing, c, folder):
    """Leaking rays against distance from the origin (log x, log y with a 'none' floor), and the
    trace time of each test on each timed scene."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    rays = rows[0]["rays"]
    floor = 0.3 / rays
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [3, 2]})
    ax = axes[0]
    colours = {"auto": "tab:green", "triangle=mt": "tab:red"}
    for v, label in METHODS.items():
        for centred in (False, True):
            rs = _leaks(rows, v, centred)
            ax.plot([max(r["shift"], c["shift_floor"]) for r in rs],
                    [max(r["leak_fraction"], floor) for r in rs], color=colours[v],
                    ls="-" if centred else "--", marker="o" if centred else "x",
                    label=f"{label}, " + ("centred (as Prism renders)" if centred
                                          else "file's origin (--keep-origin)"))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axhline(floor, color="grey", ls=":", lw=0.8)
    ax.text(c["shift_floor"], floor, " no leak", va="bottom", fontsize=7, color="grey")
    shifts = [d for d in c["shifts"]]
    ax.set_xticks([max(d, c["shift_floor"]) for d in shifts])
    ax.set_xticklabels(["0" if d == 0 else f"1e{round(math.log10(d))}" for d in shifts])
    ax.set_xlabel("distance of the mesh from the origin along x, y and z")
    ax.set_ylabel(f"fraction of the {rays:,} rays that leak")
    ax.set_title(f"Rays aimed at shared edges and vertices ({c['size']}² image)")
    ax.grid(True, alpha=0.25)
    ax.legend(fontsize=7.5)
    ax = axes[1]
    scenes = list(dict.fromkeys(r["scene"] for r in timing))
    x = np.arange(len(scenes))
    for k, (v, label) in enumerate(METHODS.items()):
        ms = [next(r["trace_ms"] for r in timing if r["scene"] == s and r["method"] == v)
              for s in scenes]
        ax.bar(x + (k - 0.5) * 0.38, ms, 0.38, color=colours[v], label=label)
    ax.set_xticks(x, scenes)
    ax.set_ylabel(f"trace ms (median of {c['runs']}, {c['time_size']})")
    ax.set_title("What each test costs")
    ax.legend(fontsize=7.5)
    ax.grid(True, axis="y", alpha=0.25)
    kit.save_figure(fig, folder / "leaks.png")
    return "leaks.png"


def summary(rows, timing):
    mt = max(r["leaks"] for r in rows if r["method"] == "triangle=mt")
    wt = max(r["leaks"] for r in rows if r["method"] == "auto")
    rays = rows[0]["rays"]
    scenes = list(dict.fromkeys(r["scene"] for r in timing))
    return (f"Of {rays:,} rays aimed at shared edges and vertices of a closed mesh, "
            f"Möller–Trumbore lets up to {mt:,} leak through (worst placement), Prism's "
            f"watertight test {wt:,}; Möller–Trumbore's time is "
            + ", ".join(f"{_ratio(timing, s)[0]:.2f}x" for s in scenes) +
            f" the watertight test's ({', '.join(scenes)}): pick the watertight test, whose "
            "meshes stay closed.")


def markdown(kit, rows, timing, c, chart, renders=None):
    p = "triangles/"
    n = c["size"]
    md = [f"A closed mesh (a bumpy red front, a blue back and sides) seen by a parallel camera "
          f"along (-1, -2, -3) at {n}x{n}: the front's vertices lie on the rays of every second "
          "pixel column and row, so the pixels between them look at the midpoints of shared "
          "edges (axis-aligned in the image, or the diagonals that split each quad). Every one "
          f"of the {rows[0]['rays']:,} pixels inside the outline (a {MARGIN + 1}-pixel rim, where "
          "the side walls are edge-on, is left out) should be red; one that is blue or green "
          "(the background) is a ray that **leaked** through the front. Coordinates are exact in "
          "double and rounded to float by the renderer, so each ray passes within rounding of "
          "its edge, the case a watertight test is for. The mesh and camera are moved by d along "
          f"x, y and z, d in {c['shifts']}, and rendered by `prism-bench --save-images` with "
          "Prism's watertight test (Woop, Benthin & Wald 2013, the default) and "
          "Möller–Trumbore 1997 (`triangle=mt`, a variant kept for this study only), in the "
          "file's coordinates (`--keep-origin`) and centred on the camera as Prism renders. "
          f"Time: `prism-bench --variants auto,triangle=mt --runs {c['runs']} --size "
          f"{c['time_size']} --depth {c['time_depth']}` on the study's mesh and "
          f"{', '.join(c['time_scenes'])} (median frame, variants' frames interleaved, so the "
          "ratio holds on a shared machine).",
          "", f"![Leaking rays and the cost of each test]({p}{chart})", ""]
    if renders:
        md += [f"![The mesh by each test, centred, at the origin: red is the front, blue and "
               f"green are leaks]({p}{renders})", ""]
    table = []
    for centred in (False, True):
        for v, label in METHODS.items():
            for r in _leaks(rows, v, centred):
                table.append([label, "centred" if centred else "file's", f"{r['shift']:g}",
                              f"{r['leaks']:,}", f"{r['leak_fraction'] * 100:.2f}",
                              f"{r['vertex_leaks']:,} / {r['vertex_rays']:,}",
                              f"{r['edge_leaks']:,} / {r['edge_rays']:,}",
                              f"{r['diagonal_leaks']:,} / {r['diagonal_rays']:,}",
                              f"{r['through_both']:,}"])
    md += [kit.md_table(["test", "origin", "moved", "leaks", "%", "at vertices", "at edges",
                         "at diagonals", "through both sides"], table), ""]
    cost = []
    for s in dict.fromkeys(r["scene"] for r in timing):
        by = {r["method"]: r for r in timing if r["scene"] == s}
        cost.append([s, f"{by['auto']['primitives']:,}", f"{by['auto']['trace_ms']:.1f}",
                     f"{by['triangle=mt']['trace_ms']:.1f}",
                     "%.2f (%.2f-%.2f)" % _ratio(timing, s)])
    md += [kit.md_table(["scene", "primitives", "watertight ms", "Möller–Trumbore ms",
                         "MT / watertight (range over rounds)"], cost), ""]
    md += ["### What it shows", ""]
    mt = _leaks(rows, "triangle=mt", False)
    wt = [r for r in rows if r["method"] == "auto"]
    centred = _leaks(rows, "triangle=mt", True)
    md.append("- **Möller–Trumbore leaks** where rounding decides which side of a shared edge a "
              f"ray is on: {centred[0]['leak_fraction'] * 100:.1f}% of the aimed rays centred on "
              "the camera, and in the file's coordinates "
              + ", ".join(f"{r['leak_fraction'] * 100:.1f}% at {r['shift']:g}" for r in mt) +
              ". Its edge tests of a shared edge are computed from different vertices, so both "
              "triangles can say 'outside'. Far from the origin fewer rays leak, most likely "
              "because coarser floats no longer put the rays on the edges.")
    md.append(f"- **The watertight test lets {max(r['leaks'] for r in wt):,} rays through** in "
              f"all {len(wt)} renders: its edge functions are exact in sign for a shared edge, so "
              "one of the two triangles always takes the ray.")
    scenes = list(dict.fromkeys(r["scene"] for r in timing))
    ratios = {s: _ratio(timing, s)[0] for s in scenes}
    md.append("- **Cost**: Möller–Trumbore's trace time is " +
              ", ".join(f"{ratios[s]:.2f}x on {s}" for s in scenes) + " the watertight test's "
              "(median ratio of paired frames); the frames also walk the grid and shade, so the "
              "tests themselves differ by more than these ratios. Single frames on this shared "
              "machine vary by tens of percent, so read the ratio, not the milliseconds.")
    dearest = min(scenes, key=lambda s: ratios[s])
    extra = (1 / ratios[dearest] - 1) * 100
    md.append(f"- **Pick** the watertight test: it costs up to {extra:.0f}% more trace time here "
              f"({dearest}) and buys closed meshes; Möller–Trumbore's holes are single pixels "
              "that come and go as the camera moves (specks of what lies behind a closed "
              "surface), worst on fine meshes, whose edges often fall near pixel centres.")
    md += ["", f"Data: [{p}data.csv]({p}data.csv), [{p}data.json]({p}data.json)."]
    return "\n".join(md)
