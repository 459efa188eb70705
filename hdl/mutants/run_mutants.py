#!/usr/bin/env python3
"""The mutation bench of the HDL front end: each mutant of catalogue.txt (one slip in hdl/rtl/)
is applied alone to a copy of hdl/, whose HDL tests (the test command's, label hdl, not long) are
run on it, fastest first, until one fails: that test caught it. Prints the table (mutant, class,
the slip, caught by) and the kill ratio over the mutants not argued equivalent.

usage: run_mutants.py --hdl HDL_DIR --vectors VECTOR_DIR --work DIR [--qt-vectors PATH]
                      [--only ID,ID,...] [--every N]

Progress (a row as each mutant ends) goes to stderr; the table and the ratio to stdout.

Exit status 0 when the bench ran (whatever it found), 1 when the unmutated copy fails its tests
or a mutant's text is not found exactly once (the catalogue no longer matches the RTL)."""
import argparse
import os
import re
import shutil
import subprocess
import sys

# Tests that check the checkers (a fault injected into the expected data or a mutant of their
# own), not the RTL: a mutant can make them pass or fail for reasons of their own.
CHECKER_TESTS = re.compile(r"^hdl_(fault_.*|soak_fault|formal_mutant.*)$")


def parse_catalogue(path):
    mutants, current = [], None
    for raw in open(path, encoding="utf-8"):
        line = raw.rstrip("\n")
        if line.startswith("== "):
            ident, file, cls, slip = [p.strip() for p in line[3:].split("|", 3)]
            current = {"id": ident, "file": file, "class": cls, "slip": slip, "from": [],
                       "to": [], "equivalent": ""}
            mutants.append(current)
        elif current is None or line.startswith("#") or not line.strip():
            continue
        elif line.startswith("- "):
            current["from"].append(line[2:])
        elif line.startswith("+ "):
            current["to"].append(line[2:])
        elif line.startswith("equivalent: "):
            current["equivalent"] = line[len("equivalent: "):]
        elif current["equivalent"]:
            current["equivalent"] += " " + line.strip()
        else:
            sys.exit(f"run_mutants: {path}: a line outside a mutant: {line}")
    return mutants


def run(cmd, **kw):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)


def test_order(build):
    """The tests that check the RTL, fastest first: the direction table, the row limit, the
    gradient block's cases, the front end's, the bounded proof, the soak."""
    listed = run(["ctest", "--test-dir", build, "-N", "-L", "hdl", "-LE", "long"]).stdout
    names = re.findall(r"Test\s+#\d+: (\S+)", listed)
    names = [n for n in names if not CHECKER_TESTS.match(n)]

    def rank(n):
        for k, prefix in enumerate(["hdl_direction", "hdl_row_limit", "hdl_gradient_",
                                    "hdl_front_", "hdl_formal_", "hdl_soak"]):
            if n.startswith(prefix):
                return (k, "nostall" in n, "640x480" in n, n)
        return (9, False, False, n)

    return sorted(names, key=rank)


def first_failure(build, tests, one_by_one=12):
    """The first test, in order, that fails: the fast ones one at a time (most mutants stop
    there), the rest together on two cores, the first in order of those that failed."""
    for name in tests[:one_by_one]:
        r = run(["ctest", "--test-dir", build, "-R", f"^{re.escape(name)}$", "--timeout", "300"])
        if "100% tests passed" not in r.stdout:
            return name
    rest = tests[one_by_one:]
    if not rest:
        return None
    r = run(["ctest", "--test-dir", build, "-j2", "--timeout", "300", "-R",
             "|".join(f"^{re.escape(t)}$" for t in rest)])
    failed = set(re.findall(r"\d+ - (\S+) \(", r.stdout))
    return next((t for t in rest if t in failed), None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--hdl", required=True)
    ap.add_argument("--vectors", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--qt-vectors", default="")
    ap.add_argument("--only", default="")
    ap.add_argument("--every", type=int, default=1, help="every Nth mutant only (a quick run)")
    a = ap.parse_args()
    mutants = parse_catalogue(os.path.join(a.hdl, "mutants", "catalogue.txt"))
    if a.only:
        keep = set(a.only.split(","))
        mutants = [m for m in mutants if m["id"] in keep]
    mutants = mutants[::max(1, a.every)]

    src = os.path.join(a.work, "hdl")
    build = os.path.join(a.work, "build")
    shutil.rmtree(a.work, ignore_errors=True)
    shutil.copytree(a.hdl, src, ignore=shutil.ignore_patterns("mutants", "synth"))
    rtl, original = os.path.join(src, "rtl"), os.path.join(a.hdl, "rtl")
    for m in mutants:
        text = open(os.path.join(original, m["file"]), encoding="utf-8").read()
        n = text.count("\n".join(m["from"]))
        if n != 1:
            sys.exit(f"run_mutants: {m['id']}: its text is found {n} times in {m['file']}")
    configure = ["cmake", "-S", src, "-B", build, f"-DQT_VECTOR_DIR={os.path.abspath(a.vectors)}"]
    if a.qt_vectors:
        configure.append(f"-DQT_VECTORS_TOOL={os.path.abspath(a.qt_vectors)}")
    r = run(configure)
    if r.returncode != 0:
        sys.exit("run_mutants: configure failed:\n" + r.stdout)

    def build_all():
        return run(["cmake", "--build", build, "-j2"]).returncode == 0

    if not build_all():
        sys.exit("run_mutants: the unmutated copy does not build")
    tests = test_order(build)
    base = run(["ctest", "--test-dir", build, "-j2", "-R", "|".join(f"^{t}$" for t in tests)])
    if "100% tests passed" not in base.stdout:
        sys.exit("run_mutants: the unmutated copy fails its tests:\n" + base.stdout[-2000:])
    print(f"{len(mutants)} mutants (hdl/mutants/catalogue.txt); on each, the {len(tests)} HDL "
          f"tests of the test command (label hdl, not long; the checkers' self-tests left out) "
          f"in order, fastest first, until one fails")

    rows, killed, counted, survivors = [], 0, 0, []
    for m in mutants:
        for name in os.listdir(original):
            shutil.copy(os.path.join(original, name), os.path.join(rtl, name))
        path = os.path.join(rtl, m["file"])
        text = open(path, encoding="utf-8").read()
        open(path, "w", encoding="utf-8").write(
            text.replace("\n".join(m["from"]), "\n".join(m["to"]), 1))
        if m["equivalent"]:
            caught = "equivalent (not run): " + m["equivalent"]
        elif not build_all():
            caught = "does not compile (not counted)"
        else:
            counted += 1
            hit = first_failure(build, tests)
            if hit:
                killed += 1
                caught = hit
            else:
                caught = "**survived**"
                survivors.append(m["id"])
        rows.append(f"| {m['id']} | {m['file']} | {m['class']} | {m['slip']} | {caught} |")
        print(rows[-1], file=sys.stderr, flush=True)
    for name in os.listdir(original):
        shutil.copy(os.path.join(original, name), os.path.join(rtl, name))

    print("\n| mutant | file | class | the slip | caught by (first failing test) |")
    print("|---|---|---|---|---|")
    print("\n".join(rows))
    ratio = 100.0 * killed / counted if counted else 0.0
    print(f"\ncaught {killed} of {counted} non-equivalent mutants ({ratio:.1f} %); "
          f"equivalent: {sum(1 for m in mutants if m['equivalent'])}; "
          f"survivors: {', '.join(survivors) if survivors else 'none'}")


if __name__ == "__main__":
    main()
