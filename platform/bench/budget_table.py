#!/usr/bin/env python3
"""The budget table of bash bench.sh budget-table: instructions per QVGA frame and stage, median
and worst, per kind of frame and part, from the firmware images' own output, and flash and RAM
of every image from its link (the ELF's sections).

    budget_table.py --chain PART=OUTPUT ... --target PART=OUTPUT ... --elves PART=DIR ...
    budget_table.py --memory-only --elves PART=DIR ...   (the README's table: chain_bench and
                                                          target_bench only)

OUTPUT: what chain_bench (or target_bench) printed under QEMU -icount shift=0; its lines
"budget FRAME stage=N ... total=N" are read, the median and worst lines it prints are not: both
are recomputed here the same way (per stage, the upper median; the worst of each stage over the
frames), and "worst frame" is the largest total of a single frame, which the per-stage worst
bounds from above. DIR: a preset's platform/firmware build folder, whose *.elf are measured with
arm-none-eabi-size -A: flash = every allocated section but .qt_frames (test frames standing in
for the camera), .bss and .stack, less the golden vectors gradient_bench keeps in flash (its
qt_vec_*_begin .. _end symbols, arm-none-eabi-nm); RAM = .data + .bss + .stack (the reserved
stack).
"""
import argparse, glob, os, re, subprocess, sys

# The chain cases of chain_bench (the start of their frames' names) and the kind of frame each is.
KINDS = [("board_motion_qvga_", "board"), ("clutter_qvga_", "clutter"),
         ("photos_qvga_", "real photograph"), ("photoseq", "real-photograph sequence"),
         ("stress_qvga_", "stress (noise, strokes)")]
FRAME_RE = {head: re.compile(r"^%s (\S+)((?: \w+=\d+)+)$" % head)
            for head in ("budget", "fpga", "bands", "bands-fpga")}


def frames_of(path, head="budget"):
    """[(frame name, {stage: instructions})] in printed order, per-frame lines only; head
    "fpga": the chain's frames with edges from the FPGA."""
    out = []
    with open(path) as f:
        for line in f:
            m = FRAME_RE[head].match(line.strip())
            if not m or m.group(1) in ("memory", "median", "worst"):
                continue
            stages = {}
            for field in m.group(2).split():
                k, v = field.split("=")
                stages[k] = int(v)
            out.append((m.group(1), stages))
    return out


def chain_cases(chains, head):
    """(part, kind of frame, [its frames]) for every part and kind of chain_bench's output."""
    for part, path in parts(chains):
        frames = frames_of(path, head)
        for case, kind in KINDS:
            mine = [f for f in frames if f[0].startswith(case)]
            if not mine:
                sys.exit("budget_table: no %s frame of %s in %s" % (head, case, path))
            yield part, kind, mine


def summary(frames):
    """Per-stage upper median, per-stage worst, worst single-frame total."""
    stages = [k for k in frames[0][1] if k not in ("total", "banded")]
    med, worst = {}, {}
    for s in stages:
        values = sorted(f[1][s] for f in frames)
        med[s] = values[len(values) // 2]
        worst[s] = values[-1]
    med["total"] = sum(med[s] for s in stages)
    worst["total"] = sum(worst[s] for s in stages)
    worst_frame = max(frames, key=lambda f: f[1]["total"])
    return stages, med, worst, worst_frame


def rates(instructions):
    """Frames a second at one instruction a cycle on a 480 MHz Cortex-M7 and a 168 MHz Cortex-M4."""
    return "%d frames/s at 480 MHz, %d at 168 MHz" % (480e6 // instructions, 168e6 // instructions)


def table(title_cols, rows):
    print("| " + " | ".join(title_cols) + " |")
    print("|" + "---|" * len(title_cols))
    for r in rows:
        print("| " + " | ".join(str(c) for c in r) + " |")
    print()


def parts(args):
    out = []
    for a in args or []:
        part, _, path = a.partition("=")
        out.append((part, path))
    return out


def section_sizes(size_tool, elf):
    text = subprocess.run([size_tool, "-A", elf], capture_output=True, text=True, check=True).stdout
    sizes = {}
    for line in text.splitlines():
        m = re.match(r"^(\.\S+)\s+(\d+)\s+(\d+)", line)
        if m:
            sizes[m.group(1)] = int(m.group(2))
    return sizes


def vector_bytes(nm_tool, elf):
    """Bytes between each qt_vec_NAME_begin and qt_vec_NAME_end: test input, not the program."""
    text = subprocess.run([nm_tool, elf], capture_output=True, text=True, check=True).stdout
    ends = {}
    for line in text.splitlines():
        m = re.match(r"^([0-9a-f]+) \w (qt_vec_\w+)_(begin|end)$", line)
        if m:
            ends.setdefault(m.group(2), {})[m.group(3)] = int(m.group(1), 16)
    return sum(e["end"] - e["begin"] for e in ends.values() if len(e) == 2)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--chain", action="append")
    p.add_argument("--target", action="append")
    p.add_argument("--elves", action="append")
    p.add_argument("--size", default="arm-none-eabi-size")
    p.add_argument("--nm", default="arm-none-eabi-nm")
    # The product images only (the chain and the target tracker), for the README's table.
    p.add_argument("--memory-only", action="store_true")
    args = p.parse_args()
    if args.memory_only:
        memory_table(args, ("chain_bench", "target_bench"))
        return

    print("Quadrangle chain (chain_bench), instructions per QVGA frame; median and worst per "
          "stage, 'worst frame' the largest single-frame total (aim: <= 2 400 000):")
    print()
    rows, stages = [], None
    worst_all = 0
    for part, kind, mine in chain_cases(args.chain, "budget"):
        stages, med, worst, wf = summary(mine)
        worst_all = max(worst_all, wf[1]["total"])
        rows.append([part, kind, len(mine), "median"] + [med[s] for s in stages] +
                    [med["total"], ""])
        rows.append([part, kind, len(mine), "worst"] + [worst[s] for s in stages] +
                    [worst["total"], "%d (%s)" % (wf[1]["total"], wf[0])])
    table(["part", "kind of frame", "frames", "statistic"] + stages + ["total", "worst frame"],
          rows)
    verdict = "met" if worst_all <= 2400000 else "NOT met"
    print("Worst single QVGA frame of the quadrangle chain over every part and case: %d "
          "instructions (aim 2400000: %s; %s)" % (worst_all, verdict, rates(worst_all)))
    print()

    print("The same frames with edges from the FPGA (chain_bench's second pass: the front end's "
          "edge beats through push_edge_beats, results equal to the camera rows'); 'after the "
          "edges' is the total less beats: PPHT, clustering, rules and tracker (aim on board "
          "frames: <= 800 000):")
    print()
    rows, board_rest = [], {}
    for part, kind, mine in chain_cases(args.chain, "fpga"):
        stages, med, worst, wf = summary(mine)
        rest = [f[1]["total"] - f[1]["beats"] for f in mine]
        rows.append([part, kind, len(mine), "median"] + [med[s] for s in stages] +
                    [med["total"], sorted(rest)[len(rest) // 2]])
        rows.append([part, kind, len(mine), "worst"] + [worst[s] for s in stages] +
                    [worst["total"], max(rest)])
        if kind == "board":
            board_rest[part] = (sorted(rest)[len(rest) // 2], max(rest))
    table(["part", "kind of frame", "frames", "statistic"] + stages + ["total", "after the edges"],
          rows)
    for part, (med, worst) in board_rest.items():
        # The aim is set for the Cortex-M4; the other parts are printed against it for comparison.
        print("%s, board frames with edges from the FPGA, after the edges: median %d, worst %d "
              "instructions (the Cortex-M4's aim 800000: %s)" %
              (part, med, worst, "met" if worst <= 800000 else "NOT met"))
    print()

    print("Tracking mode (chain_bench's third pass, tracking/tracking_mode.h): each frame after a "
          "case's first through the bands planned from the frame before when the board was held "
          "with all four sides, the whole frame otherwise; the frames that ran in bands, and "
          "every frame of those cases (aims on real-photograph sequences while tracked: median "
          "<= 800 000, worst <= 2 400 000):")
    print()
    rows, verdicts = [], []
    for head, source in (("bands", "camera rows"), ("bands-fpga", "FPGA beats")):
        for part, kind, mine in chain_cases(args.chain, head):
            if kind not in ("board", "real-photograph sequence"):
                continue
            banded = [f for f in mine if f[1].get("banded") == 1]
            for label, frames in (("in bands", banded), ("every frame", mine)):
                if not frames:
                    continue
                stages, med, worst, wf = summary(frames)
                # The first stage is rows or beats: one column for both.
                first = stages[0]
                rows.append([part, source, kind, label, len(frames), "median", med[first]] +
                            [med[s] for s in stages[1:]] + [med["total"], ""])
                rows.append([part, source, kind, label, len(frames), "worst", worst[first]] +
                            [worst[s] for s in stages[1:]] +
                            [worst["total"], "%d (%s)" % (wf[1]["total"], wf[0])])
                if kind == "real-photograph sequence":
                    totals = sorted(f[1]["total"] for f in frames)
                    m, w = totals[len(totals) // 2], totals[-1]
                    verdicts.append("%s, %s, %s, %s: median %d (%s; %s), worst %d (%s; %s)" % (
                        part, source, kind, label, m, "met" if m <= 800000 else "NOT met",
                        rates(m), w, "met" if w <= 2400000 else "NOT met", rates(w)))
    table(["part", "edges from", "kind of frame", "frames", "count", "statistic",
           "rows or beats"] + stages[1:] + ["total", "worst frame"], rows)
    for v in verdicts:
        print(v)
    print()

    for part, path in parts(args.target):
        frames = frames_of(path)
        stages, med, worst, wf = summary(frames)
        print("Target pipeline (target_bench) on %s, instructions per QVGA frame over %d frames "
              "(aims: median <= 4 000 000, worst <= 5 000 000):" % (part, len(frames)))
        print()
        worst_frame = "%d (%s)" % (wf[1]["total"], wf[0])
        table(["part", "statistic", *stages, "total", "worst frame"],
              [[part, "median"] + [med[s] for s in stages] + [med["total"], ""],
               [part, "worst"] + [worst[s] for s in stages] + [worst["total"], worst_frame]])

    memory_table(args)


# Flash and RAM of the images in each --elves folder (only those named in `images`, if given).
def memory_table(args, images=None):
    print("Flash and RAM of each image, bytes, from its link (arm-none-eabi-size -A; test frames "
          "and vectors excluded; RAM includes the reserved stack):")
    print()
    rows = []
    for part, folder in parts(args.elves):
        for elf in sorted(glob.glob(os.path.join(folder, "*.elf"))):
            name = os.path.basename(elf)[:-4]
            if name == "float_canary":
                continue  # never run: the float check's canary
            if images is not None and name not in images:
                continue
            s = section_sizes(args.size, elf)
            ram = s.get(".data", 0) + s.get(".bss", 0) + s.get(".stack", 0)
            flash = sum(v for k, v in s.items() if k not in (".qt_frames", ".bss", ".stack")
                        and not k.startswith((".comment", ".debug", ".ARM.attributes")))
            flash -= vector_bytes(args.nm, elf)
            rows.append([part, name, flash, ram, s.get(".stack", 0)])
    table(["part", "image", "flash", "RAM", "of which stack"], rows)


if __name__ == "__main__":
    main()
