#!/usr/bin/env python3
"""tools/scripts/first_image.py on two small rungs (issue 31's ladder, kept from rotting): every
row measured, the cold runs build and store the grid, the warm runs read it back, the phases
add up to no more than the process, and the chart is written."""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    args = parser.parse_args()
    script = Path(__file__).resolve().parents[2] / "tools" / "scripts" / "first_image.py"
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        result = subprocess.run(
            [sys.executable, str(script), "--bin", args.bin, "--rungs", "2000,6000",
             "--kinds", "tori,sphere-mesh", "--runs", "2", "--no-embree", "--work",
             str(out / "work"), "--json", str(out / "ladder.json"), "--chart",
             str(out / "ladder.png")], capture_output=True, text=True)
        if result.returncode != 0:
            print(result.stdout, result.stderr)
            return 1
        rows = json.loads((out / "ladder.json").read_text())
        problems = []
        if len(rows) != 4:
            problems.append(f"{len(rows)} rows, not 4")
        for r in rows:
            name = f"{r['kind']} {r['rung']}"
            if not (0.5 * r["rung"] <= r["triangles"] <= 1.5 * r["rung"]):
                problems.append(f"{name}: {r['triangles']} triangles")
            for run in r["runs"]:
                if run["stats"]["grid_cache"]["state"] != "miss":
                    problems.append(f"{name}: a cold run did not build and store its grid")
            for run in r["warm_runs"]:
                if run["stats"]["grid_cache"]["state"] != "hit":
                    problems.append(f"{name}: a warm run did not read its grid back")
            for run in r["runs"] + r["warm_runs"]:
                phases = run["stats"]["phases_ms"]
                if not 0 < phases["total"] <= run["wall_ms"]:
                    problems.append(f"{name}: phases {phases['total']} ms, process {run['wall_ms']}")
                if run["peak_rss_mb"] <= 0:
                    problems.append(f"{name}: no peak RSS")
        if "| tori 2,000 |" not in result.stdout:
            problems.append("the table has no tori row")
        if not (out / "ladder.png").stat().st_size > 10000:
            problems.append("no chart")
        for p in problems:
            print("first_image_check:", p)
        return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
