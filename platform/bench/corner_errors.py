#!/usr/bin/env python3
"""One Markdown table row: `quadtrack track`'s JSON lines against qt_board_y4m's truth.

    corner_errors.py LABEL TRUTH.jsonl TRACK.jsonl EXIT_STATUS

The truth's corners run clockwise as seen (top-left first), the track's anti-clockwise from any
corner: each frame's error is the worst corner distance in the best rotation, px. A frame
without a quadrangle, or missing, counts as no error bound ("none").
"""
import json, math, sys


def worst(quad, truth):
    best = math.inf
    for r in range(4):
        w = 0.0
        for i in range(4):
            tx, ty = truth[(r + 4 - i) % 4]
            x, y = quad[i]
            w = max(w, math.hypot(x - tx, y - ty))
        best = min(best, w)
    return best


def main():
    label, truth_path, track_path, status = sys.argv[1:5]
    with open(truth_path) as f:
        truth = [json.loads(line)["corners"] for line in f if line.strip()]
    with open(track_path) as f:
        lines = [json.loads(line) for line in f if line.strip()]
    errors = []
    for line in lines:
        quad = line.get("quad")
        k = line["frame"]
        errors.append(worst(quad["corners"], truth[k]) if quad and k < len(truth) else math.inf)
    errors += [math.inf] * (len(truth) - len(lines))
    fmt = lambda v: "none" if math.isinf(v) else "%.2f" % v
    bins = sorted({line.get("bin") for line in lines})
    print("| %s | %d of %d | %s | %s | %s | %s |" % (
        label, len(lines), len(truth), ",".join(str(b) for b in bins), fmt(max(errors, default=math.inf)),
        fmt(sum(errors) / len(errors) if errors else math.inf), status))


if __name__ == "__main__":
    main()
