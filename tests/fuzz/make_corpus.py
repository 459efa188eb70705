#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpus: tests/fuzz/corpus/<target>/ (the committed files are
what ctest fuzz_replay_<target> and `bash bench.sh fuzz` use; this only says how they were made).

    python3 tests/fuzz/make_corpus.py          # rewrites corpus/image_reader, cli_args, pipeline

Each file is small (at most a few KiB); the pipeline programs follow the operation encoding at
the top of fuzz_pipeline.cpp.
"""
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def write(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


# --- image_reader ------------------------------------------------------------------------------
def ramp(w, h, maxval=255, channels=1):
    return bytes(((x * 7 + y * 13 + c * 5) % (maxval + 1)) for y in range(h) for x in range(w) for c in range(channels))


def board(w, h):
    return bytes(200 if w // 4 <= x < 3 * w // 4 and h // 4 <= y < 3 * h // 4 else 40 for y in range(h) for x in range(w))


def y4m(header, frames, frame_params=b""):
    out = b"YUV4MPEG2 " + header + b"\n"
    for f in frames:
        out += b"FRAME" + frame_params + b"\n" + f
    return out


def yuv_frame(w, h, chroma_bytes, seed):
    y = bytes((x * 9 + yy * 3 + seed * 17) & 0xFF for yy in range(h) for x in range(w))
    return y + bytes((i + seed) & 0xFF for i in range(chroma_bytes))


def half(n):
    return (n + 1) // 2


def images():
    t = "image_reader"
    write(t, "pgm_1x1.pgm", b"P5\n1 1\n255\n\x80")
    write(t, "pgm_ramp_16x12.pgm", b"P5\n16 12\n255\n" + ramp(16, 12))
    write(t, "pgm_board_40x30.pgm", b"P5 40 30 255\n" + board(40, 30))
    write(t, "pgm_maxval15.pgm", b"P5\n9 7\n15\n" + ramp(9, 7, 15))
    write(t, "pgm_maxval1.pgm", b"P5\n8 2\n1\n" + ramp(8, 2, 1))
    write(t, "pgm_comments.pgm", b"P5 # made by hand\n# a whole comment line\n 5 # width\n4\n# maxval next\n255# after the maxval\n" + ramp(5, 4))
    write(t, "pgm_whitespace.pgm", b"P5\t6\r\n3\x0b\x0c255\r" + ramp(6, 3))
    write(t, "pgm_two_images.pgm", b"P5\n3 2\n255\n" + ramp(3, 2) + b"P5\n2 2\n255\n" + ramp(2, 2))
    write(t, "pgm_truncated.pgm", b"P5\n10 10\n255\n" + ramp(10, 3))
    write(t, "pgm_sample_above_maxval.pgm", b"P5\n4 2\n100\n" + bytes([1, 2, 3, 4, 5, 6, 7, 101]))
    write(t, "pgm_16bit.pgm", b"P5\n2 2\n65535\n" + bytes(8))
    write(t, "pgm_too_large.pgm", b"P5\n16385 1\n255\n\x00")
    write(t, "pgm_header_only.pgm", b"P5\n7 ")
    write(t, "ppm_4x3.ppm", b"P6\n4 3\n255\n" + ramp(4, 3, 255, 3))
    write(t, "ppm_maxval100.ppm", b"P6 3 3 100\n" + ramp(3, 3, 100, 3))
    write(t, "ppm_1x1_comment.ppm", b"P6#c\n1 1 255\n\xff\x00\x80")
    # y4m: every colour space, odd sizes, tags, FRAME parameters, several frames.
    w, h = 8, 6
    write(t, "y4m_420jpeg_2frames.y4m",
          y4m(b"W8 H6 F30:1 Ip A1:1 C420jpeg XYSCSS=420JPEG",
              [yuv_frame(w, h, 2 * half(w) * half(h), s) for s in range(2)]))
    write(t, "y4m_420_odd_frame_params.y4m",
          y4m(b"W5 H3 C420", [yuv_frame(5, 3, 2 * 3 * 2, s) for s in range(2)], b" Ip XTAG=1"))
    write(t, "y4m_420paldv.y4m", y4m(b"W4 H4 C420paldv", [yuv_frame(4, 4, 8, 1)]))
    write(t, "y4m_420mpeg2.y4m", y4m(b"W2 H2 C420mpeg2", [yuv_frame(2, 2, 2, 2)]))
    write(t, "y4m_422.y4m", y4m(b"W6 H2 C422", [yuv_frame(6, 2, 2 * 3 * 2, s) for s in range(3)]))
    write(t, "y4m_444_3frames.y4m", y4m(b"W4 H4 C444", [yuv_frame(4, 4, 32, s) for s in range(3)]))
    write(t, "y4m_mono_4frames.y4m", y4m(b"W3 H3 Cmono", [yuv_frame(3, 3, 0, s) for s in range(4)]))
    write(t, "y4m_default_colour_1x1.y4m", y4m(b"H1 W1", [yuv_frame(1, 1, 2, 0)]))
    write(t, "y4m_no_frames.y4m", b"YUV4MPEG2 W4 H4 C444\n")
    write(t, "y4m_truncated_second_frame.y4m",
          y4m(b"W4 H2 Cmono", [yuv_frame(4, 2, 0, 0)]) + b"FRAME\n\x01\x02")
    write(t, "y4m_bad_marker.y4m", y4m(b"W2 H1 Cmono", [yuv_frame(2, 1, 0, 0)]) + b"FRAMX\n\x00\x00")
    write(t, "y4m_unsupported_colour.y4m", y4m(b"W2 H2 C420p10", [bytes(12)]))
    write(t, "not_an_image.txt", b"hello, not a picture\n")
    write(t, "empty", b"")


# --- cli_args ------------------------------------------------------------------------------------
def argv(*args):
    return b"\0".join(a.encode() for a in args)


def cli():
    t = "cli_args"
    detect = ["--edge-threshold", "40", "--theta-bins", "90", "--rho", "2", "--threshold", "12",
              "--min-line-length", "20", "--max-gap", "4", "--vote-window", "24", "--corridor", "1",
              "--max-walk-steps", "200000", "--seed", "1", "--cluster-distance", "6", "--cluster-angle", "4",
              "--cluster-gap", "16", "--corner-join-distance", "3", "--corner-join-angle", "20",
              "--parallel-tolerance", "34", "--perpendicular-tolerance", "35", "--corner-margin", "0",
              "--min-side", "20", "--max-side", "2048", "--aspect-tolerance", "1.6", "--min-coverage", "0.333",
              "--min-score", "0.7", "--collinear-distance", "2", "--contrast", "bright", "--display", "1024x768",
              "--max-quads", "4"]
    write(t, "detect_every_flag", argv(*(detect + ["board.pgm"])))
    write(t, "detect_equals_form", argv("frame.pgm", "--edge-threshold=510", "--rho=4", "--contrast=any",
                                        "--display=4096x1", "--seed=2147483647", "--max-walk-steps=1"))
    write(t, "detect_limits", argv("--edge-threshold", "1", "--theta-bins", "2", "--threshold", "255",
                                   "--min-line-length", "2048", "--max-gap", "0", "--vote-window", "90",
                                   "--corridor", "4", "--cluster-distance", "1000", "--cluster-angle", "90",
                                   "--parallel-tolerance", "45", "--perpendicular-tolerance", "60",
                                   "--min-side", "1", "--max-side", "1", "--aspect-tolerance", "10",
                                   "--min-coverage", "1", "--min-score", "0", "--contrast", "dark", "x"))
    track = ["--model", "turn", "--filters", "1", "--gate-angle", "8.5", "--gate-distance", "12",
             "--max-predicted", "15", "f%03d.pgm"]
    write(t, "track_flags", argv(*track))
    write(t, "track_paper_model", argv("seq.y4m", "--model=paper", "--filters=3", "--gate-angle=90",
                                       "--gate-distance=1000", "--max-predicted=255"))
    target = ["--roi", "100,80,16,16", "--method", "fused", "--reset", "on", "--q-pos", "20", "--q-vel", "1",
              "--r", "4", "--gate-nds", "9.21", "--gate-rep", "1.5", "--reset-nds", "5.99", "--reset-det-s", "2500",
              "--min-score", "0.7", "--max-radius", "24", "--max-unseen", "400", "--coast-fit", "32", "--search-radius", "24",
              "--min-match", "0.8", "--inlier-px", "2", "--max-iterations", "1000", "--seed", "1", "ground.y4m"]
    write(t, "target_every_flag", argv(*target))
    write(t, "target_roi_limits", argv("--roi=-100000,100000,24,1", "--method=template_only", "--reset=off",
                                       "--r=0.01", "--min-match=-1", "s%d.pgm"))
    write(t, "homography_flags", argv("a.pgm", "b.pgm", "--search-radius", "128", "--min-match", "1",
                                      "--inlier-px", "0.05", "--max-iterations", "1", "--seed", "0"))
    write(t, "help_long", argv("--help"))
    write(t, "help_short", argv("img.pgm", "-h"))
    write(t, "error_unknown_flag", argv("--frobnicate", "1", "img.pgm"))
    write(t, "error_missing_value", argv("img.pgm", "--threshold"))
    write(t, "error_out_of_range", argv("--edge-threshold", "511", "img.pgm"))
    write(t, "error_rho_3", argv("--rho", "3", "img.pgm"))
    write(t, "error_display", argv("--display", "640x", "img.pgm"))
    write(t, "error_min_above_max_side", argv("--min-side", "100", "--max-side", "50", "img.pgm"))
    write(t, "error_not_numbers", argv("--cluster-gap", "1e999", "--q-pos", "nan", "--roi", "1,2,3", "img"))
    write(t, "error_two_positionals", argv("a.pgm", "b.pgm", "c.pgm"))
    write(t, "empty_argument", argv("", "--seed=", ""))


# --- pipeline ------------------------------------------------------------------------------------
def size(v):
    """An exact size (size code mode 1)."""
    return struct.pack("<H", (v << 2) | 1)


CAP = struct.pack("<H", 0)                  # the capacity
ABOVE = struct.pack("<H", 3)                # capacity + 1


def pattern(kind=1, lo=40, hi=200, cx=160.0, cy=120.0, hw=70, hh=52, angle=3, noise=0, seed=1, dx=0, dy=0, turn=0):
    return bytes([4, kind, lo, hi]) + struct.pack("<HH", int(cx * 64), int(cy * 64)) + \
        bytes([hw, hh, angle, noise, seed]) + struct.pack("<bbb", dx, dy, turn)


def board_begin(w, h, flags=0, extra=b""):
    return bytes([0]) + w + h + bytes([flags]) + extra


def board_rows(count, lenmode=1, bad=None):
    return bytes([1, count, lenmode]) + (struct.pack("<H", bad) if lenmode % 8 == 0 else b"")


def board_words(count, mode, lenmode=1, bad=None, extra=b""):
    return bytes([2, count, lenmode]) + (struct.pack("<H", bad) if lenmode % 8 == 0 else b"") + bytes([mode]) + extra


FINISH = bytes([3])
TARGET_FINISH = bytes([8])


def board_frame(w=CAP, h=CAP, words=False):
    return bytes([10]) + w + h + bytes([1 if words else 0])


def target_box(x, y, w, h, raw=False):
    if raw:
        return bytes([5, 0]) + struct.pack("<iiBB", x, y, w, h)
    return bytes([5, 2]) + struct.pack("<hhBB", x, y, w, h)


def target_begin(w, h):
    return bytes([6]) + w + h


def target_rows(count, lenmode=1, bad=None):
    return bytes([7, count, lenmode]) + (struct.pack("<H", bad) if lenmode % 8 == 0 else b"")


def target_frame(w=CAP, h=CAP):
    return bytes([11]) + w + h


def configure(method=0, flags=0):
    return bytes([9, method, flags])


def pipeline():
    t = "pipeline"
    write(t, "board_one_frame", pattern() + board_frame())
    # Sequences in smaller frames: the pixel budget per input is one QVGA frame.
    q = (size(120), size(90))
    write(t, "board_sequence_moving", pattern(cx=60, cy=45, hw=30, hh=22, dx=10, dy=-4, turn=4) +
          board_frame(*q) * 6)
    write(t, "board_turn_model", configure(0, 2) + pattern(cx=60, cy=45, hw=30, hh=22, dx=-8, turn=-3) +
          board_frame(*q) * 5)
    write(t, "board_words_frame", pattern(angle=250) + board_frame(words=True) + board_begin(CAP, CAP))
    write(t, "board_dark_noisy", pattern(kind=4, lo=220, hi=30, noise=40, hw=90, hh=60) +
          board_begin(CAP, CAP, 7, struct.pack("<H", 20) + bytes([6])) + board_rows(0) + FINISH)
    write(t, "board_noise_capacity", pattern(kind=2, seed=7) + board_begin(CAP, CAP, 1, struct.pack("<H", 1)) +
          board_rows(0) + FINISH)
    write(t, "board_small_frames", pattern(cx=10, cy=8, hw=5, hh=4) + board_frame(size(24), size(16)) +
          board_frame(size(1), size(1)) + board_frame(size(320), size(1)) + board_frame(size(1), size(240)))
    h = (size(160), size(120))
    write(t, "board_torn_frames", pattern(cx=80, cy=60, hw=40, hh=30) + board_begin(*h) + board_rows(50) +
          board_rows(1, 0, 159) + board_rows(5) + FINISH + board_begin(*h) + board_rows(25) +
          board_begin(*h) + board_rows(0) + FINISH)
    write(t, "board_bad_sizes", board_begin(size(0), CAP) + board_rows(1) + FINISH + board_begin(ABOVE, CAP) +
          board_begin(CAP, ABOVE) + board_rows(2) + FINISH + board_begin(struct.pack("<H", 0xFFFF), CAP) + FINISH)
    write(t, "board_rows_after_end", pattern() + board_begin(size(32), size(4)) + board_rows(6) + FINISH +
          board_words(2, 0) + FINISH)
    write(t, "board_raw_words", board_begin(size(16), size(16)) +
          board_words(16, 1) + bytes((i * 37 + 11) & 0xFF for i in range(16 * 16 * 4)) + FINISH)
    write(t, "board_corrupted_words", pattern(cx=60, cy=40, hw=30, hh=20) + board_begin(size(120), size(80)) +
          board_words(0, 2, extra=bytes([3]) + struct.pack("<HI", 5, 0xFFFFFFFF) +
                      struct.pack("<HI", 60, 0x7FFFFFFF) + struct.pack("<HI", 119, 0x80000000)) + FINISH)
    write(t, "board_repeated_word", board_begin(size(64), size(48)) +
          board_words(0, 3, extra=struct.pack("<I", 0x7E03FC01)) + FINISH)
    write(t, "board_words_wrong_length", pattern(cx=80, cy=60, hw=40, hh=30) + board_begin(*h) +
          board_words(10, 0) + board_words(1, 0, 0, 321) + FINISH + board_begin(*h) + board_words(0, 0) + FINISH)
    write(t, "board_pixels_from_program", pattern(kind=3) + board_begin(size(24), size(8)) + board_rows(0) +
          bytes((i * 29) & 0xFF for i in range(24 * 8)) + FINISH)
    s = (size(96), size(80))
    write(t, "target_track", pattern(kind=4, noise=6, cx=48, cy=40, hw=6, hh=5, dx=8, dy=4, turn=2) +
          target_box(40, 34, 16, 12) + target_frame(*s) * 8)
    write(t, "target_methods", pattern(kind=4, noise=10, cx=60, cy=45, hw=7, hh=6, dx=-6, dy=3) +
          configure(3) + target_box(52, 38, 16, 16) + target_frame(*s) * 2 + configure(1) + target_frame(*s) +
          configure(2) + target_frame(*s))
    write(t, "target_box_outside", pattern() + target_box(310, 230, 16, 16) + target_frame() +
          target_box(-4, 10, 8, 8) + target_frame() + target_box(0, 0, 0, 8) + target_box(0, 0, 17, 8))
    write(t, "target_torn", pattern() + target_box(50, 50, 8, 8) + target_begin(CAP, CAP) + target_rows(30) +
          target_rows(1, 0, 5) + TARGET_FINISH + target_begin(CAP, CAP) + target_rows(10) +
          target_begin(size(64), size(48)) + target_rows(0) + TARGET_FINISH + TARGET_FINISH)
    write(t, "target_sizes", pattern(cx=20, cy=20, hw=6, hh=6) + target_frame(size(40), size(40)) +
          target_frame(size(40), size(41)) + target_begin(ABOVE, CAP) + target_begin(CAP, size(0)) +
          TARGET_FINISH + target_frame(size(5), struct.pack("<H", (300 << 2) | 3)))
    m = (size(128), size(96))
    write(t, "mixed_board_and_target", pattern(cx=64, cy=48, hw=32, hh=24, dx=4, dy=2, turn=1) +
          target_box(56, 40, 16, 16) + board_frame(*m) + target_frame(*m) + board_frame(*m, words=True) +
          target_frame(*m))


def main():
    images()
    cli()
    pipeline()
    return 0


if __name__ == "__main__":
    sys.exit(main())
