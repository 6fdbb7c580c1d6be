#!/usr/bin/env python3
"""The seeded-bug list of tools/scripts/mutants.sh: parsing, checking and applying it.

    mutants.py check LIST ROOT          every entry applies to the tree at ROOT (exit 1 if not)
    mutants.py ids LIST [ID,...]        "id US targets US labels US tests US description" of every
                                        (or each named) entry, US the ASCII unit separator (a tab
                                        would let bash's read merge empty fields); the middle
                                        three are the entry's own selection, empty where it has
                                        none
    mutants.py apply LIST ID ROOT SAVE  seeds entry ID into ROOT, saving the files it edits in SAVE
    mutants.py revert ROOT SAVE         puts the files saved in SAVE back into ROOT
    mutants.py sync SRC DST             makes DST a copy of the files SRC lists on stdin (NUL-
                                        separated, relative), rewriting only those whose bytes
                                        differ so that DST's build stays incremental
    mutants.py selftest                 checks that `check` refuses what it must

The list format is described at the top of tools/scripts/mutants.txt.
"""
import os
import re
import shutil
import sys
import tempfile

KEYS = ("id", "desc", "targets", "labels", "tests", "file", "from", "to")
# An entry's own selection (mutants.sh uses its defaults where an entry gives none): the build
# targets that hold its tests, and ctest's -L and -R regexes that pick them.
SELECTION = ("targets", "labels", "tests")


class ListError(Exception):
    pass


def parse(path):
    """Entries as dicts {id, desc, targets, labels, tests, edits: [(file, from, to)], line}, in
    list order."""
    entries, current, pending = [], None, {}

    def finish(lineno):
        nonlocal current, pending
        if current is None:
            return
        if pending:
            raise ListError(f"{path}:{lineno}: entry '{current['id']}' has an unfinished "
                            f"file/from/to edit (needs all three, in that order)")
        if not current["edits"]:
            raise ListError(f"{path}:{current['line']}: entry '{current['id']}' has no edit")
        if not current["desc"]:
            raise ListError(f"{path}:{current['line']}: entry '{current['id']}' has no desc")
        entries.append(current)
        current, pending = None, {}

    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for lineno, line in enumerate(lines, 1):
        if line.startswith("#"):
            continue
        if not line.strip():
            finish(lineno)
            continue
        m = re.match(r"([a-z]+):(.*)$", line)
        if not m or m.group(1) not in KEYS:
            raise ListError(f"{path}:{lineno}: expected one of {', '.join(k + ':' for k in KEYS)}"
                            f" at the start of the line, got: {line!r}")
        key, value = m.group(1), m.group(2)
        value = value[1:] if value.startswith(" ") else value  # one space after the colon
        if key == "id":
            finish(lineno)
            if not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_-]*", value):
                raise ListError(f"{path}:{lineno}: id {value!r}: letters, digits, '-' and '_'")
            current = {"id": value, "desc": "", "edits": [], "line": lineno,
                       "targets": "", "labels": "", "tests": ""}
            continue
        if current is None:
            raise ListError(f"{path}:{lineno}: '{key}:' before any 'id:'")
        if key == "desc":
            current["desc"] = value.strip()
        elif key in SELECTION:
            if current["edits"] or pending:
                raise ListError(f"{path}:{lineno}: '{key}:' must come before the entry's edits")
            if not value.strip() or "\t" in value:
                raise ListError(f"{path}:{lineno}: '{key}:' needs a value (no tabs)")
            if key == "targets" and not re.fullmatch(r"[A-Za-z0-9_.-]+(,[A-Za-z0-9_.-]+)*",
                                                     value.strip()):
                raise ListError(f"{path}:{lineno}: targets: comma-separated target names")
            current[key] = value.strip()
        elif key == "file":
            if pending:
                raise ListError(f"{path}:{lineno}: 'file:' before the previous edit's 'to:'")
            pending = {"file": value.strip(), "line": lineno}
        elif key == "from":
            if set(pending) != {"file", "line"}:
                raise ListError(f"{path}:{lineno}: 'from:' must follow 'file:'")
            if not value:
                raise ListError(f"{path}:{lineno}: empty 'from:'")
            pending["from"] = value
        else:  # to
            if "from" not in pending:
                raise ListError(f"{path}:{lineno}: 'to:' must follow 'from:'")
            if value == pending["from"]:
                raise ListError(f"{path}:{lineno}: 'to:' is the same text as 'from:'")
            current["edits"].append((pending["file"], pending["from"], value, pending["line"]))
            pending = {}
    finish(len(lines))
    seen = {}
    for e in entries:
        if e["id"] in seen:
            raise ListError(f"{path}:{e['line']}: id '{e['id']}' already used on line "
                            f"{seen[e['id']]}")
        seen[e["id"]] = e["line"]
    if not entries:
        raise ListError(f"{path}: no entries")
    return entries


def problems(entries, root, list_path):
    """Why each edit would not apply: a missing file, or an original found other than once."""
    out = []
    for e in entries:
        for file, old, _new, line in e["edits"]:
            where = f"{list_path}:{line}: {e['id']}: {file}"
            full = os.path.join(root, file)
            if not os.path.isfile(full):
                out.append(f"{where}: no such file")
                continue
            with open(full, encoding="utf-8") as f:
                count = f.read().count(old)
            if count != 1:
                out.append(f"{where}: the original text occurs {count} times, not once: {old!r}")
    return out


def select(entries, only):
    if not only:
        return entries
    wanted = [x for x in only.split(",") if x]
    by_id = {e["id"]: e for e in entries}
    unknown = [x for x in wanted if x not in by_id]
    if unknown:
        raise ListError(f"no such mutant(s) in the list: {', '.join(unknown)}")
    return [by_id[x] for x in wanted]


def apply(entry, root, save):
    for file, old, new, _line in entry["edits"]:
        full = os.path.join(root, file)
        kept = os.path.join(save, file)
        if not os.path.exists(kept):  # an entry may edit one file twice: keep the original
            os.makedirs(os.path.dirname(kept), exist_ok=True)
            shutil.copy2(full, kept)
        with open(full, encoding="utf-8") as f:
            text = f.read()
        if text.count(old) != 1:
            raise ListError(f"{entry['id']}: {file}: the original text occurs {text.count(old)} "
                            f"times, not once: {old!r}")
        with open(full, "w", encoding="utf-8") as f:
            f.write(text.replace(old, new))


def revert(root, save):
    for folder, _dirs, files in os.walk(save):
        for name in files:
            kept = os.path.join(folder, name)
            rel = os.path.relpath(kept, save)
            # Copied, not renamed, with a fresh mtime: the build must see the file as changed.
            shutil.copyfile(kept, os.path.join(root, rel))
            os.remove(kept)


def sync(src, dst, names):
    wanted = set()
    for rel in names:
        if not rel or not os.path.isfile(os.path.join(src, rel)):
            continue  # deleted in the working tree but still in the index
        wanted.add(rel)
        a, b = os.path.join(src, rel), os.path.join(dst, rel)
        if os.path.isfile(b) and os.path.getsize(a) == os.path.getsize(b):
            with open(a, "rb") as fa, open(b, "rb") as fb:
                if fa.read() == fb.read():
                    continue
        os.makedirs(os.path.dirname(b), exist_ok=True)
        shutil.copy2(a, b)
        os.utime(b)  # newer than anything built from the old copy
    for folder, _dirs, files in os.walk(dst):
        for name in files:
            rel = os.path.relpath(os.path.join(folder, name), dst)
            if rel not in wanted:
                os.remove(os.path.join(folder, name))


def expect(condition, what):
    if not condition:  # not `assert`: python -O would skip it
        raise SystemExit(f"mutants.py selftest: {what}")


def selftest():
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "a.txt"), "w") as f:
            f.write("x = 1;\ny = 1;\nz = 2;\n")

        def check_list(text):
            path = os.path.join(tmp, "list.txt")
            with open(path, "w") as f:
                f.write(text)
            try:
                return problems(parse(path), tmp, path)
            except ListError as e:
                return [str(e)]

        entry = "id: m\ndesc: d\nfile: a.txt\nfrom: {}\nto: {}\n"
        expect(check_list(entry.format("z = 2;", "z = 3;")) == [], "a good entry is refused")
        expect(check_list(entry.format("= 1;", "= 0;")), "an original found twice is accepted")
        expect(check_list(entry.format("w = 1;", "w = 0;")), "a missing original is accepted")
        expect(check_list(entry.format("z = 2;", "z = 2;")), "a no-op edit is accepted")
        expect(check_list(entry.replace("a.txt", "b.txt").format("z", "y")), "no such file")
        expect(check_list(entry.format("z", "y") + "\n" + entry.format("x", "w")), "duplicate id")
        expect(check_list("id: m\nfile: a.txt\nfrom: z\nto: y\n"), "an entry without desc")
        own = "id: m\ndesc: d\ntargets: a_tests,b_tests\ntests: ^A\\.\nfile: a.txt\nfrom: z\nto: y\n"
        expect(check_list(own) == [], "an entry with its own targets and tests is refused")
        expect(check_list(own.replace("a_tests,b_tests", "a tests")), "a bad target list")
        expect(check_list(entry.format("z", "y") + "labels: cpu\n"), "a selection after the edits")
        path = os.path.join(tmp, "list.txt")
        with open(path, "w") as f:
            f.write(entry.format("z = 2;", "z = 3;"))
        save = os.path.join(tmp, "save")
        apply(parse(path)[0], tmp, save)
        with open(os.path.join(tmp, "a.txt")) as f:
            expect(f.read() == "x = 1;\ny = 1;\nz = 3;\n", "apply")
        revert(tmp, save)
        with open(os.path.join(tmp, "a.txt")) as f:
            expect(f.read() == "x = 1;\ny = 1;\nz = 2;\n", "revert")
    print("mutants.py selftest: ok")


def main(argv):
    try:
        if len(argv) == 3 and argv[0] == "check":
            entries = parse(argv[1])
            found = problems(entries, argv[2], argv[1])
            for p in found:
                print(f"mutants: {p}", file=sys.stderr)
            if found:
                print(f"mutants: {len(found)} edit(s) of {argv[1]} no longer apply: update the "
                      f"list to the code", file=sys.stderr)
                return 1
            print(f"mutants: all {len(entries)} entries of {argv[1]} apply")
            return 0
        if len(argv) in (2, 3) and argv[0] == "ids":
            for e in select(parse(argv[1]), argv[2] if len(argv) == 3 else ""):
                print("\x1f".join([e["id"], e["targets"], e["labels"], e["tests"], e["desc"]]))
            return 0
        if len(argv) == 5 and argv[0] == "apply":
            entry = select(parse(argv[1]), argv[2])[0]
            apply(entry, argv[3], argv[4])
            return 0
        if len(argv) == 3 and argv[0] == "revert":
            revert(argv[1], argv[2])
            return 0
        if len(argv) == 3 and argv[0] == "sync":
            sync(argv[1], argv[2], sys.stdin.buffer.read().decode().split("\0"))
            return 0
        if argv == ["selftest"]:
            selftest()
            return 0
    except ListError as e:
        print(f"mutants: {e}", file=sys.stderr)
        return 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
