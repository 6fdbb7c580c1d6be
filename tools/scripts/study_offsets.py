"""Study 2 of tools/scripts/studies.py: where ray offsets fail.

One scene with shadows, reflection and refraction, scaled by 2^-13 .. 2^13 (about 1e-4 .. 1e4)
and moved up to 1e6 from the origin, rendered with Prism's relative offset and the original's
fixed ones (prism-bench variants offset=0.01 and offset=1e-4), with and without the centring on
the camera that every Prism renderer does. A pixel is wrong when it differs from the unit
scene's image by more than TOLERANCE.

`kit` is the studies.py module itself (its output helpers and settings), passed in by it.
"""
import math

METHODS = {"auto": "relative (Prism)", "offset=0.01": "fixed 0.01 (the original)",
           "offset=1e-4": "fixed 1e-4"}
# Any channel of linear RGB (white = 1) off by more than this: about 2.5/255 of display white,
# above float-against-float rounding, far below a visible shadow or reflection error.
TOLERANCE = 0.01


def transform_scene(kit, text, scale, shift):
    """The .scene `text` with every position scaled by `scale`, then moved by `shift` along x, y
    and z, and every length scaled: the same picture, since the camera moves with the scene.
    Scales are powers of two, so a scaled scene holds exactly the scaled floats. Only the
    directives the studies' scenes use are known; another one carrying positions is refused."""
    def place(tokens, i):
        tokens[i:i + 3] = [repr(float(v) * scale + shift) for v in tokens[i:i + 3]]

    lines = []
    for line in text.splitlines():
        tokens = line.split("#")[0].split()
        if not tokens:
            continue
        kw = tokens[0]
        if kw == "camera":
            for i, t in enumerate(tokens):
                if t in ("eye", "look"):
                    place(tokens, i + 1)
                elif t == "ortho":
                    tokens[i + 1] = repr(float(tokens[i + 1]) * scale)
        elif kw == "light":
            place(tokens, 1)
            if "radius" in tokens:
                i = tokens.index("radius") + 1
                tokens[i] = repr(float(tokens[i]) * scale)
        elif kw == "sphere":
            place(tokens, 1)
            tokens[4] = repr(float(tokens[4]) * scale)
        elif kw == "plane":
            place(tokens, 1)
        elif kw not in ("background", "ambient", "material", "use"):
            raise kit.StudyError(f"offsets: cannot scale a '{kw}' line (the study knows camera, "
                                 "light, sphere and plane)")
        lines.append(" ".join(tokens))
    return "\n".join(lines) + "\n"


def _name(exponent, shift):
    """A scene's file stem: prism-bench names its results by it."""
    return f"s{exponent:+d}-d{shift:g}".replace("+", "p").replace("-", "m", 1)


def run(kit, tools, cfg, out, progress, tmp):
    """Renders every placement under every method, centred and not, in two prism-bench
    processes; returns (markdown, summary)."""
    import numpy as np
    c = cfg["offsets"]
    text = (kit.SCENES / f"{c['scene']}.scene").read_text()
    placements = [(e, 0.0) for e in c["scale_exponents"]]
    placements += [(0, float(d)) for d in c["shifts"] if d > 0]
    if (0, 0.0) not in placements:
        raise kit.StudyError("offsets: scale_exponents must include 0 (the unit scene)")
    paths = {}
    for e, d in placements:
        paths[(e, d)] = tmp / f"{_name(e, d)}.scene"
        kit.write_text(paths[(e, d)], transform_scene(kit, text, 2.0 ** e, d))
    progress.begin("offsets", 2)
    images = {}
    for centred in (True, False):
        folder = tmp / ("centred" if centred else "kept")
        folder.mkdir()
        tools.bench(list(paths.values()), list(METHODS), "every placement, " +
                    ("centred on the camera" if centred else "--keep-origin"), c["size"],
                    c["depth"], 1, save_images=folder, keep_origin=not centred)
        for (e, d), path in paths.items():
            for v in METHODS:
                exr = folder / f"{path.stem}_{v}.exr"
                images[(e, d, v, centred)] = kit.read_exr_rgb(exr)
                exr.unlink()
    progress.end()
    reference = images[(0, 0.0, "auto", True)]
    rows = []
    for (e, d, v, centred), img in images.items():
        wrong = np.abs(img - reference).max(axis=2) > TOLERANCE
        rows.append({"scale_exponent": e, "scale": 2.0 ** e, "shift": d, "method": v,
                     "centred": centred, "wrong_pixels": int(wrong.sum()),
                     "wrong_fraction": float(wrong.mean()),
                     "max_difference": float(np.abs(img - reference).max())})
    rows.sort(key=lambda r: (not r["centred"], r["method"], r["shift"], r["scale_exponent"]))
    folder = out / "offsets"
    kit.write_json(folder / "data.json", {"config": c, "tolerance": TOLERANCE, "rows": rows})
    kit.write_csv(folder / "data.csv", rows)
    charts = charts_of(kit, rows, c, folder)
    failures = _failure_images(kit, images, reference, c, folder)
    if failures:
        charts["failures"] = failures
    return markdown(kit, rows, c, charts), summary(rows)


def _series(rows, method, centred, axis):
    """(x, fraction) along one axis: scale at shift 0, or shift at scale 1."""
    if axis == "scale":
        rs = [r for r in rows if r["shift"] == 0.0]
        key = "scale"
    else:
        rs = [r for r in rows if r["scale_exponent"] == 0]
        key = "shift"
    rs = sorted((r for r in rs if r["method"] == method and r["centred"] == centred),
                key=lambda r: r[key])
    return [r[key] for r in rs], [r["wrong_fraction"] for r in rs], rs


def charts_of(kit, rows, c, folder):
    """One figure, two log-log panels: wrong pixels against scale (at the origin) and against
    distance from the origin (at scale 1), each method with and without centring."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    w, h = (int(v) for v in c["size"].split("x"))
    floor = 0.3 / (w * h)  # where "no wrong pixel" is drawn on a log axis
    colours = {"auto": "tab:green", "offset=0.01": "tab:red", "offset=1e-4": "tab:blue"}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True)
    for ax, axis in zip(axes, ("scale", "shift")):
        for v, label in METHODS.items():
            for centred in (False, True):
                x, y, _ = _series(rows, v, centred, axis)
                if axis == "shift":
                    x = [max(s, c["shift_floor"]) for s in x]
                y = [max(f, floor) for f in y]
                ax.plot(x, y, color=colours[v], ls="-" if centred else "--",
                        marker="o" if centred else "x", lw=1.6 if v == "auto" else 1.1,
                        label=f"{label}, " + ("centred (as Prism renders)" if centred
                                              else "file's origin (--keep-origin)"))
        # Scales are powers of two (their ticks say so); distances, powers of ten.
        ax.set_xscale("log", base=2 if axis == "scale" else 10)
        ax.set_yscale("log")
        ax.axhline(floor, color="grey", ls=":", lw=0.8)
        ax.grid(True, which="major", alpha=0.25)
    axes[0].set_xlabel("scene scale (powers of two, at the origin)")
    exponents = sorted(c["scale_exponents"])
    axes[0].set_xticks([2.0 ** e for e in exponents])
    axes[0].set_xticklabels([f"$2^{{{e}}}$" for e in exponents])
    axes[1].set_xlabel("distance moved from the origin along x, y and z (scale 1)")
    axes[0].set_ylabel(f"fraction of wrong pixels (any channel off by > {TOLERANCE})")
    axes[1].set_xticks([c["shift_floor"]] + [d for d in c["shifts"] if d > 0])
    axes[1].set_xticklabels(["0"] + [f"1e{round(math.log10(d))}" for d in c["shifts"] if d > 0])
    axes[0].text(axes[0].get_xlim()[0], floor, " no wrong pixel", va="bottom", fontsize=7,
                 color="grey")
    axes[0].set_title(f"{c['scene']} scaled, {c['size']}, depth {c['depth']}")
    axes[1].set_title("moved away from the origin")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=7.5,
               bbox_to_anchor=(0.5, -0.14))
    kit.save_figure(fig, folder / "wrong-pixels.png")
    return {"wrong_pixels": "wrong-pixels.png"}


def _failure_images(kit, images, reference, c, folder):
    """The unit scene beside what each method makes of it where it fails worst: the failures
    the chart counts, seen."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    smallest, largest = min(c["scale_exponents"]), max(c["scale_exponents"])
    far = max(c["shifts"])
    panels = [("unit scene (the reference)", reference)]
    for key, title in (((smallest, 0.0, "offset=0.01", False), f"fixed 0.01, scale 2^{smallest}"),
                       ((largest, 0.0, "offset=1e-4", False), f"fixed 1e-4, scale 2^{largest}"),
                       ((0, float(far), "auto", False), f"relative, {far:g} away, file's origin"),
                       ((0, float(far), "auto", True), f"relative, {far:g} away, centred")):
        if key in images:
            panels.append((title, images[key]))
    if len(panels) < 2:
        return None
    # Three to a row, each large enough to see its failure and read its title.
    cols = min(3, len(panels))
    rows = (len(panels) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.6 * rows), squeeze=False)
    axes = axes.ravel()
    for ax in axes[len(panels):]:
        ax.axis("off")
    for ax, (title, img) in zip(axes, panels):
        srgb = np.where(img <= 0.0031308, 12.92 * img, 1.055 * np.power(np.clip(img, 0, None),
                                                                        1 / 2.4) - 0.055)
        ax.imshow(np.clip(srgb, 0, 1), interpolation="nearest")
        ax.set_title(title, fontsize=11)
        ax.axis("off")
    kit.save_figure(fig, folder / "failures.png")
    return "failures.png"


def _fraction(rows, e, d, v, centred):
    return next(r["wrong_fraction"] for r in rows if r["scale_exponent"] == e and
                r["shift"] == d and r["method"] == v and r["centred"] == centred)


def _worst(rows, method, centred, axis):
    """The placements where a method gets more than 1% of the pixels wrong, as text."""
    x, y, rs = _series(rows, method, centred, axis)
    bad = [r for r in rs if r["wrong_fraction"] > 0.01]
    if axis == "scale":
        return ", ".join(f"2^{r['scale_exponent']} ({r['wrong_fraction'] * 100:.0f}%)"
                         for r in bad)
    return ", ".join(f"{r['shift']:g} ({r['wrong_fraction'] * 100:.0f}%)" for r in bad)


def _percent(fraction):
    return "none" if fraction == 0 else f"{fraction * 100:.2g}%"


def summary(rows):
    """One paragraph for the README's top: what fails where (numbers from the data)."""
    e = sorted({r["scale_exponent"] for r in rows})
    far = max(r["shift"] for r in rows)
    relative = max(_fraction(rows, x, 0.0, "auto", c) for x in e for c in (True, False))
    return (f"A fixed offset fails with scale: the original's 0.01 gets "
            f"{_fraction(rows, e[0], 0.0, 'offset=0.01', False) * 100:.0f}% of the pixels wrong "
            f"at scale 2^{e[0]}, a fixed 1e-4 "
            f"{_fraction(rows, e[-1], 0.0, 'offset=1e-4', False) * 100:.0f}% at 2^{e[-1]}; "
            f"Prism's relative offset gets {_percent(relative)} wrong at any scale. Moved "
            f"{far:g} from the origin, the relative offset gets "
            f"{_percent(_fraction(rows, 0, far, 'auto', False))} wrong in the file's "
            f"coordinates and {_percent(_fraction(rows, 0, far, 'auto', True))} once the scene "
            "is centred on the camera, as Prism renders: pick the relative offset, with "
            "centring.")


def markdown(kit, rows, c, charts):
    p = "offsets/"
    e = sorted(c["scale_exponents"])
    md = [f"`{c['scene']}` (shadows from two lights, a mirror, a glass ball, a reflective floor) "
          f"at {c['size']}, depth {c['depth']}, scaled by 2^k for k in {e} (powers of two near "
          "1e-4 ... 1e4, so that a scaled scene holds exactly the scaled floats and any "
          f"change in the picture is the method's) and, at scale 1, moved by d in "
          f"{[d for d in c['shifts'] if d > 0]} along x, y and z; the camera and lights move "
          "with it, so every image should be the unit scene's. Each is rendered by "
          "`prism-bench --save-images` with Prism's relative offset (2^-18 max|P|, the "
          "default) and the fixed offsets along the normal `offset=0.01` (the original's) and "
          "`offset=1e-4` (variants kept for this study only), twice: centred on the camera as "
          "every Prism renderer does, and in the file's coordinates (`--keep-origin`). A "
          f"pixel is **wrong** when any channel of linear RGB differs from the unit scene's "
          f"(relative offset, centred) by more than {TOLERANCE}.",
          "", f"![Wrong pixels against scale and distance]({p}{charts['wrong_pixels']})", ""]
    if "failures" in charts:
        md += [f"![What the failures look like]({p}{charts['failures']})", ""]
    header = ["method", "origin"] + [f"2^{x}" for x in e] + \
        [f"moved {d:g}" for d in c["shifts"] if d > 0]
    table = []
    for centred in (True, False):
        for v, label in METHODS.items():
            cells = [f"{_fraction(rows, x, 0.0, v, centred) * 100:.2f}" for x in e]
            cells += [f"{_fraction(rows, 0, float(d), v, centred) * 100:.2f}"
                      for d in c["shifts"] if d > 0]
            table.append([label, "centred" if centred else "file's"] + cells)
    md += ["Wrong pixels in percent:", "", kit.md_table(header, table), "", "### What it shows", ""]
    for v in ("offset=0.01", "offset=1e-4"):
        good = [x for x in e if all(_fraction(rows, x, 0.0, v, c2) <= 0.001
                                    for c2 in (True, False))]
        window = f"2^{good[0]} to 2^{good[-1]}" if good else "no scale"
        bad = [r for r in _series(rows, v, False, "scale")[2] if r["wrong_fraction"] > 0.01]
        small = [r for r in bad if good and r["scale_exponent"] < good[0]]
        large = [r for r in bad if good and r["scale_exponent"] > good[-1]]
        why = []
        if small:
            why.append("below it (" + ", ".join(f"2^{r['scale_exponent']}: "
                                                 f"{r['wrong_fraction'] * 100:.0f}%" for r in small)
                       + ") the offset is large against the objects: secondary rays start past "
                       "thin features and contact shadows vanish")
        if large:
            why.append("above it (" + ", ".join(f"2^{r['scale_exponent']}: "
                                                 f"{r['wrong_fraction'] * 100:.0f}%" for r in large)
                       + ") it drops below the rounding error of a hit point, and surfaces "
                       "shadow and reflect themselves (acne)")
        md.append(f"- **A fixed {v[7:]} works in a window of scales only**: {window} (at most "
                  "0.1% of the pixels wrong, centred or not); "
                  + ("; ".join(why) if why else "no placement here is more than 1% wrong")
                  + ". Centring does not rescue it: it moves the scene, it does not scale it.")
    rel = max(_fraction(rows, x, 0.0, "auto", c2) for x in e for c2 in (True, False))
    noise = max(r["max_difference"] for r in rows if r["method"] == "auto" and r["shift"] == 0)
    md.append(f"- **Prism's relative offset holds at every scale**: {_percent(rel)} of the "
              f"pixels wrong from 2^{e[0]} to 2^{e[-1]}, centred or not; no pixel moves "
              f"by more than {noise:.1g} (the rounding of the file's coordinates against the "
              "camera's).")
    md.append("- **Far from the origin, the coordinates fail before the offset does.** In the "
              "file's coordinates the relative offset gets more than 1% of the pixels wrong at "
              f"{_worst(rows, 'auto', False, 'shift') or 'no distance'}: "
              "floats there are too coarse for the geometry itself (1/16 apart at 1e6), whatever "
              "the offset. Centred on the camera, as Prism renders, it does so at "
              f"{_worst(rows, 'auto', True, 'shift') or 'no distance at all'}.")
    failing = [r for r in rows if r["method"] == "auto" and r["centred"] and
               r["wrong_fraction"] > 0]
    md.append("- **Pick** the relative offset with centring: "
              + ("it gets no pixel wrong at any placement here, " if not failing else
                 f"it is wrong at {len(failing)} placements here (see the table), ")
              + "and costs nothing a fixed offset does not (one max and one multiply per "
              "secondary ray).")
    md += ["", f"Data: [{p}data.csv]({p}data.csv), [{p}data.json]({p}data.json)."]
    return "\n".join(md)


