#!/usr/bin/env python3
"""Writes a bench's output into a docs page, between the page's markers
    <!-- bench NAME -->  and  <!-- end bench NAME -->
with a line saying which command wrote it, when, at which commit and on which machine. Lines
of a markdown table stay a table; every other run of lines becomes a text block. The figures in
docs/ are only ever written this way (bash bench.sh NAME), never by hand.

    record_figures.py DOC NAME OUTPUT_FILE
"""
import datetime, os, platform, subprocess, sys


def machine():
    cpu = ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores%s" % (platform.machine(), os.cpu_count() or 0, ", " + cpu if cpu else "")


def commit():
    try:
        out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
        # docs/ is left out: an earlier bench of the same run has just written its figures there.
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--",
                                ".", ":(exclude)docs"],
                               capture_output=True, text=True).stdout.strip()
        return out.stdout.strip() + (" with uncommitted changes" if dirty else "")
    except OSError:
        return "unknown"


def body(lines):
    out, text = [], []

    def flush():
        while text and not text[-1].strip():
            text.pop()
        if text:
            out.extend(["```text"] + text + ["```", ""])
        text.clear()

    in_table = False
    for line in lines:
        if line.startswith("|"):
            if not in_table:
                flush()
            out.append(line)
            in_table = True
            continue
        if in_table:
            out.append("")
            in_table = False
        if line.strip() or text:
            text.append(line)
    flush()
    while out and out[-1] == "":
        out.pop()
    return out


def main():
    doc, name, output = sys.argv[1], sys.argv[2], sys.argv[3]
    begin, end = "<!-- bench %s -->" % name, "<!-- end bench %s -->" % name
    with open(doc, encoding="utf-8") as f:
        page = f.read().split("\n")
    if begin not in page or end not in page:
        print("record_figures: %s has no markers for %s" % (doc, name), file=sys.stderr)
        return 1
    with open(output, encoding="utf-8", errors="replace") as f:
        lines = [l.rstrip() for l in f.read().split("\n")]
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    header = ["*Written by `bash bench.sh %s` on %s at commit %s (%s); do not edit by hand.*"
              % (name, stamp, commit(), machine()), ""]
    i, j = page.index(begin), page.index(end)
    page = page[: i + 1] + header + body(lines) + page[j:]
    with open(doc, "w", encoding="utf-8") as f:
        f.write("\n".join(page))
    return 0


if __name__ == "__main__":
    sys.exit(main())
