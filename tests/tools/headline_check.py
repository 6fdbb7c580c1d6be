#!/usr/bin/env python3
"""tools/scripts/headline.py on two scenes at a small size (issue 35: the headline table is made
by a script): the table lands between the markers with every row measured and the stamp filled
in, the page around the markers is kept, the chart and data are written, and a page without
markers is refused before any measuring, left as it was."""
import argparse
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "tools" / "scripts" / "headline.py"
sys.path.insert(0, str(SCRIPT.parent))
from headline import BEGIN, END  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    args = parser.parse_args()
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        doc = out / "page.md"
        doc.write_text(f"# Page\n\nbefore\n\n{BEGIN}\nold table\n{END}\n\nafter\n")
        # CI machines are busy: the load bound is lifted, and the stamp must say the load.
        cmd = [sys.executable, str(SCRIPT), "--bin", args.bin, "--scenes", "rand50,bunny",
               "--size", "96x72", "--runs", "1", "--first-runs", "1", "--max-load", "1000",
               "--doc", str(doc), "--chart", str(out / "h.png"), "--data", str(out / "h.json")]
        result = subprocess.run(cmd, capture_output=True, text=True)
        if result.returncode != 0:
            print(result.stdout, result.stderr)
            return 1
        page = doc.read_text()
        if not page.startswith("# Page\n\nbefore\n\n" + BEGIN) or not page.endswith(
                END + "\n\nafter\n") or "old table" in page:
            problems.append("the page around the markers changed, or the old table stayed:\n"
                            + page)
        rows = [line for line in page.splitlines() if line.startswith("| rand50 ")
                or line.startswith("| bunny ")]
        if len(rows) != 2:
            problems.append(f"expected a row for rand50 and for bunny, got {rows}")
        for row in rows:
            cells = [c.strip() for c in row.strip("|").split("|")]
            numbers = [cells[3], cells[4], cells[5], cells[6], cells[7], cells[8].rstrip("x")]
            if any(float(n) <= 0 for n in numbers):
                problems.append(f"a figure is not positive: {row}")
        if not re.search(r"\*\*Measured \d{4}-\d\d-\d\d \d\d:\d\d UTC\*\* at commit `[0-9a-f]{10}",
                         page) or "load average" not in page:
            problems.append("the stamp (date, commit, load) is missing:\n" + page)
        data = json.loads((out / "h.json").read_text())
        if sorted(data["scenes"]) != ["bunny", "rand50"]:
            problems.append(f"data holds {sorted(data['scenes'])}")
        if (out / "h.png").read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
            problems.append("no chart written")

        bare = out / "bare.md"
        bare.write_text("# no markers\n")
        refused = subprocess.run(cmd[:cmd.index("--doc")] + ["--doc", str(bare)],
                                 capture_output=True, text=True)
        if refused.returncode == 0 or "markers" not in refused.stderr:
            problems.append(f"a page without markers was not refused: {refused.stderr}")
        if "prism-render" in refused.stderr:
            problems.append("measuring began before the page was checked")
        if bare.read_text() != "# no markers\n":
            problems.append("the page without markers was changed")
    for p in problems:
        print("headline_check:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
