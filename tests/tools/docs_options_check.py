#!/usr/bin/env python3
"""Test: each tool's options in its documentation are those its --help lists, no more, no fewer.

For each tool, the options named in its doc section (the synopsis code block and the first
column of the option table) are compared with the options of `TOOL --help`; --help and
--version are left out (every tool has them: README, "prism-render"); an option with several
names (-o and --output, --runs and --repeat) is documented by any one of them. Exit 0 when all agree,
1 with the differences otherwise.
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OPTION = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*|-[a-z](?![\w-]))")
COMMON = {"--help", "--version"}

# tool, documentation file, the heading of its section (up to the next heading of that level)
DOCS = [
    ("prism-render", "README.md", "## prism-render"),
    ("prism-merge", "README.md", "## prism-merge"),
    ("prism-view", "docs/prism-view.md", "# prism-view"),
    ("prism-bench", "docs/development.md", "## Benchmarks: prism-bench"),
    ("prism-gridbench", "docs/development.md", "## prism-gridbench"),
]


def section(text, heading):
    """From `heading` to the next heading of any level."""
    start = text.index(heading + "\n") + len(heading)
    m = re.search(r"^#+ ", text[start:], re.M)
    return text[start:start + m.start()] if m else text[start:]


def documented(doc):
    names = set()
    blocks = re.findall(r"```\n(prism-[a-z-]+ .*?)```", doc, re.S)
    for block in blocks:
        names |= set(OPTION.findall(block))
    for row in re.findall(r"^\| (`--[^|]*)\|", doc, re.M):  # the table's first column
        names |= set(OPTION.findall(row))
    return names


def listed(exe):
    """Each option of --help as the set of its names (-o,--output: both)."""
    text = subprocess.run([exe, "--help"], capture_output=True, text=True, check=True).stdout
    groups = []
    for line in text.splitlines():
        m = re.match(r"\s+(-[^ ]+)", line)
        if m and not set(OPTION.findall(m.group(1))) & {"-h", "--help", "--version"}:
            groups.append(frozenset(OPTION.findall(m.group(1))))
    return groups


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", required=True, help="folder of the built tools")
    args = parser.parse_args()
    failures = 0
    for tool, doc_file, heading in DOCS:
        doc = section((ROOT / doc_file).read_text(), heading)
        docs, helps = documented(doc) - COMMON, listed(str(Path(args.bin) / tool))
        where = f"{doc_file}, \"{heading.lstrip('# ')}\""
        for names in helps:  # any of an option's names will do (--runs or its alias --repeat)
            if not names & docs:
                print(f"{tool}: {'/'.join(sorted(names))} is in --help but not in {where}")
                failures += 1
        known = set().union(*helps) if helps else set()
        for name in sorted(docs - known):
            print(f"{tool}: {where} names {name}, which --help does not list")
            failures += 1
        if not helps:
            print(f"{tool}: --help lists no options")
            failures += 1
    print(f"{failures} difference(s)" if failures else "every tool's options agree with its docs")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
