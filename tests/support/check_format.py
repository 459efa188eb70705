#!/usr/bin/env python3
"""The house layout of every C and C++ source: clang-format's (.clang-format at the root) and
no line over 100 characters (comments included, which clang-format does not reflow).

    check_format.py CLANG_FORMAT ROOT     exit 0 when every file conforms, 1 with the offenders
"""
import os, subprocess, sys

FOLDERS = ("core", "platform", "tests", "hw_model")
SKIP = ("tests/fuzz/corpus", "tests/fuzz/regressions")


def sources(root):
    for folder in FOLDERS:
        for dirpath, _, names in os.walk(os.path.join(root, folder)):
            rel = os.path.relpath(dirpath, root)
            if rel.startswith(SKIP):
                continue
            for name in sorted(names):
                if name.endswith((".h", ".cpp", ".c")):
                    yield os.path.join(dirpath, name)


def main():
    clang_format, root = sys.argv[1], sys.argv[2]
    files = sorted(sources(root))
    bad = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f.read().split("\n"), 1):
                if len(line) > 100:
                    print("%s:%d: %d characters (at most 100)" % (os.path.relpath(path, root), number, len(line)))
                    bad += 1
    run = subprocess.run([clang_format, "--dry-run", "--Werror", "--style=file"] + files,
                         cwd=root, capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stderr[:4000])
        bad += 1
    print("%d files: %s" % (len(files), "layout as .clang-format says" if bad == 0 else "FAIL (run clang-format -i)"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
