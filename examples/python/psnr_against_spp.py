#!/usr/bin/env python3
"""How fast an image converges: PSNR against samples per pixel for one scene. The reference is
the same view at many samples; each curve point averages several seeds (each seed draws an
independent set of samples), so the curve shows the estimator, not one lucky draw.

    python3 examples/python/psnr_against_spp.py -o psnr.png
"""
import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import prism

ASSETS = Path(__file__).resolve().parents[2] / "assets"


def psnr(image, reference):
    """Peak signal-to-noise ratio in dB, the peak being the reference's largest value."""
    mse = float(np.mean((image - reference) ** 2))
    return float("inf") if mse == 0.0 else 10.0 * np.log10(float(reference.max()) ** 2 / mse)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=str(ASSETS / "scenes" / "showcase.scene"))
    parser.add_argument("--size", default="160x120")
    parser.add_argument("--max-spp", type=int, default=64,
                        help="the curve's last point; powers of 2 up to it (default 64)")
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--seeds", type=int, default=3, help="draws averaged a point")
    parser.add_argument("-o", "--output", default="psnr-against-spp.png")
    parser.add_argument("--json", help="also write the curve's numbers here")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))

    scene = prism.load(args.scene)
    renderer = prism.Renderer()
    # The reference draws under a seed no curve point uses.
    reference = renderer.render(scene, width, height, spp=args.reference_spp,
                                seed=10_000)["rgb"]
    counts = [1 << k for k in range(args.max_spp.bit_length()) if 1 << k <= args.max_spp]
    curve = []
    for spp in counts:
        values = [psnr(renderer.render(scene, width, height, spp=spp, seed=seed)["rgb"],
                       reference) for seed in range(1, args.seeds + 1)]
        curve.append({"spp": spp, "psnr_db": float(np.mean(values)),
                      "psnr_db_each_seed": values})
        print(f"{spp:5d} spp: {curve[-1]['psnr_db']:.2f} dB")

    figure, ax = plt.subplots(figsize=(5, 3.5))
    ax.semilogx([c["spp"] for c in curve], [c["psnr_db"] for c in curve], "o-", base=2)
    ax.set_xticks(counts, [str(c) for c in counts])
    ax.set_xlabel("samples per pixel")
    ax.set_ylabel(f"PSNR against {args.reference_spp} spp (dB)")
    ax.set_title(f"{Path(args.scene).name} at {width}x{height}, mean of {args.seeds} seeds",
                 fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.output, dpi=100)
    if args.json:
        Path(args.json).write_text(json.dumps({"scene": args.scene, "size": args.size,
                                               "reference_spp": args.reference_spp,
                                               "curve": curve}, indent=1))
    print(f"-> {args.output}")


if __name__ == "__main__":
    main()
