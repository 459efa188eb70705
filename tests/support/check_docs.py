#!/usr/bin/env python3
"""The docs a reader finishes: README.md at most 12 KiB; each page of docs/ at most 25 KiB and all
of them together at most 120 KiB, not counting the figure tables the benches write (between
`<!-- bench NAME -->` and `<!-- end bench NAME -->`); every relative link names a file of the
repository, and a heading of it when it names one (`page.md#heading`); no page names a path
outside it.

    check_docs.py ROOT      exit 0 when the docs hold to this, 1 with each offence on stdout
"""
import functools
import os
import re
import sys

README_LIMIT = 12 * 1024  # bytes
PAGE_LIMIT = 25 * 1024  # bytes of a docs page's prose (generated tables not counted)
TOTAL_LIMIT = 120 * 1024  # bytes of all docs pages' prose
GENERATED = re.compile(r"<!-- bench ([\w-]+) -->.*?<!-- end bench \1 -->", re.S)
LINK = re.compile(r"\]\(([^)#\s]+)(#[^)]*)?\)")
OUTSIDE = re.compile(r"(\.\./shared|/work/|/tmp/|/home/)")


def anchor(heading):
    """A heading's anchor as GitHub makes it: lower case, punctuation dropped, spaces to '-'."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


@functools.lru_cache(maxsize=None)
def anchors(path):
    with open(path, encoding="utf-8") as f:
        return {anchor(m.group(1)) for m in re.finditer(r"(?m)^#+ (.*)$", f.read())}


def prose_bytes(text):
    return len(GENERATED.sub("", text).encode("utf-8"))


def check_page(path, text, bad):
    folder = os.path.dirname(path)
    for target, fragment in LINK.findall(text):
        if re.match(r"[a-z]+:", target):
            continue  # a URL
        file = os.path.normpath(os.path.join(folder, target))
        if not os.path.exists(file):
            bad.append(f"{path}: link to {target}, which is not in the repository")
        elif fragment and file.endswith(".md") and fragment[1:] not in anchors(file):
            bad.append(f"{path}: link to {target}{fragment}, a heading {target} does not have")
    for m in OUTSIDE.finditer(GENERATED.sub("", text)):
        bad.append(f"{path}: names a path outside the repository ({m.group(1)})")


def main():
    root = sys.argv[1]
    bad = []
    readme = os.path.join(root, "README.md")
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    if len(text.encode("utf-8")) > README_LIMIT:
        bad.append(f"README.md: {len(text.encode('utf-8'))} B, over {README_LIMIT} B")
    check_page(readme, text, bad)
    docs = os.path.join(root, "docs")
    total = 0
    for name in sorted(os.listdir(docs)):
        if not name.endswith(".md"):
            continue
        path = os.path.join(docs, name)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        size = prose_bytes(text)
        total += size
        print(f"docs/{name}: {size} B of prose")
        if size > PAGE_LIMIT:
            bad.append(f"docs/{name}: {size} B of prose, over {PAGE_LIMIT} B")
        check_page(path, text, bad)
    print(f"docs: {total} B of prose in all")
    if total > TOTAL_LIMIT:
        bad.append(f"docs: {total} B of prose in all, over {TOTAL_LIMIT} B")
    for line in bad:
        print(line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
