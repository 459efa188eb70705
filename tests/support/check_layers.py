#!/usr/bin/env python3
"""The house's layering, read from the #include lines: no folder of platform/ includes a sibling
that includes it back (directly or round a longer circle), and hw_model's beat-level models (the
files of hw_model/ itself) include nothing of platform/ or of the vector generator
(hw_model/generator/).

    check_layers.py ROOT      exit 0 when the layering holds, 1 with each offence on stdout
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
GENERATOR = "generator"


def includes(path):
    with open(path, encoding="utf-8") as f:
        return [m.group(1) for m in map(INCLUDE.match, f) if m]


def sources(folder):
    for dirpath, _, names in os.walk(folder):
        for name in sorted(names):
            if name.endswith((".h", ".cpp", ".c")):
                yield os.path.join(dirpath, name)


def main():
    root = sys.argv[1]
    platform = os.path.join(root, "platform")
    rooms = sorted(d for d in os.listdir(platform) if os.path.isdir(os.path.join(platform, d)))
    edges = {r: set() for r in rooms}  # room -> rooms it includes
    for room in rooms:
        for path in sources(os.path.join(platform, room)):
            for inc in includes(path):
                target = inc.split("/", 1)[0]
                if "/" in inc and target in edges and target != room:
                    edges[room].add(target)
    bad = []
    # A circle through room r: r reaches itself.
    for start in rooms:
        seen, todo = set(), list(edges[start])
        while todo:
            r = todo.pop()
            if r == start:
                bad.append("platform/%s includes a folder that includes it back" % start)
                break
            if r not in seen:
                seen.add(r)
                todo.extend(edges[r])
    hw_model = os.path.join(root, "hw_model")
    generated = set(os.listdir(os.path.join(hw_model, GENERATOR)))
    for name in sorted(os.listdir(hw_model)):
        path = os.path.join(hw_model, name)
        if not name.endswith((".h", ".cpp")):
            continue
        for inc in includes(path):
            if inc.split("/", 1)[0] in rooms:
                bad.append("hw_model/%s (a model) includes platform's %s" % (name, inc))
            if inc.startswith(GENERATOR + "/") or inc in generated:
                bad.append("hw_model/%s (a model) includes the generator's %s" % (name, inc))
    for line in bad:
        print(line)
    print("%d platform folders, %s" % (len(rooms), "FAIL" if bad else "layering holds"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
