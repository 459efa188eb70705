#!/usr/bin/env bash
# The benchmarks. Each prints its figures and writes them into its docs/ page (between the
# page's <!-- bench NAME --> markers, with the date, commit and machine): the figures in docs/
# are only ever written this way. Usage: bash bench.sh [--quick] [NAME...]
#   --quick        for iterating: each bench on a fixed subset of about a tenth of its inputs
#                  (photos-host 150 scenes per set, target-host 2 seeds, footage-host one walker
#                  and the coin, ...; a bench with one fixed input, such as a firmware image's
#                  frames, runs whole), printed only: docs/ is left as it is
#   gradient-host  core gradient throughput at 640x480, median of repeats, beside OpenCV's Sobel
#   gradient-m4    instructions per pixel of the core gradient on Cortex-M4 (QEMU -icount)
#   lines-host     lines stage accuracy table (default and the paper's Canny front end), vote
#                  window, VGA time vs OpenCV, RAM table
#   budgets        the whole QVGA chain on Cortex-M4 (QEMU -icount): instructions per frame and
#                  stage on the board sequence and the cluttered frame, flash, RAM, stack
#   budgets-m3     the same on Cortex-M3 (mps2-an385)
#   budgets-m4f    the same on Cortex-M4F (hard float; the chain has no float, so ~ Cortex-M4)
#   target-m4f     the target pipeline (Harris, NCC, homography, template search, filter) on
#                  Cortex-M4F (hard float, QEMU -icount): instructions per QVGA frame and stage,
#                  median and worst, flash, RAM, stack
#   budget-table   one table of the above for Cortex-M4, M4F and M3: per stage and kind of frame
#                  (board, clutter, real photograph, stress), median and worst; flash and RAM per image
#   memory         flash and RAM of the chain and target firmware images (README's table)
#   track-m4       instructions per line per frame of the line tracker (1KF, 2KF, 3KF, turn) on
#                  Cortex-M4 (QEMU -icount), output checksums against the host's
#   quads-host     board detection on 3 x 500 generated scenes: detection rate, corner RMSE,
#                  false detections, time, beside OpenCV's squares.cpp recipe
#   photos-host    boards composited onto real photographs (opencv-doc; held out: python3-skimage;
#                  patterned: opencv-doc's checkerboard calibration shots),
#                  QVGA and VGA, unoccluded / occluded / board-free / in front of a background
#                  as bright as the board, 1500 scenes each, detection by the weakest side's
#                  contrast and by noise (a point
#                  moved by up to 0.6 with PPHT's visiting order alone at 500; other sizes:
#                  BENCH_PHOTO_SCENES=N), beside OpenCV's squares.cpp recipe, and a 150-frame
#                  tracked sequence; pictures of the misses in bench_out/photos
#   pictures       the README's --draw pictures (docs/pictures): a detection on a photograph
#                  and a tracked frame of the board sequence
#   homography-host  RANSAC homography on generated inter-frame pairs (200 pairs, 0-50 % outliers):
#                  corner error, inliers, iterations, time, beside OpenCV's findHomography
#                  (RANSAC, RHO)
#   track-host     line tracker on the paper's synthetic translations and rotations: overlap
#                  tables for 1KF, 2KF, 3KF and the turn model, Experiment 1 with varying
#                  lengths and noise, Experiment 2 in the settings the paper leaves open, SVG
#                  charts in bench_out/track
#   streams-host   the board sequences (demo, turning) at 640x480, 768x576, 1280x720 and 1920x1080,
#                  binned as quadtrack track bins them, with each line model: corner errors while
#                  sides are hidden and after; and a 1280x720 clip through ffmpeg and GStreamer
#                  pipes into quadtrack track -, and OpenCV's vtest.avi (768x576) through ffmpeg
#   target-host    the Filtering and Geometry paper's comparison on 15 generated airborne sequences:
#                  template only, filter only, homography only, fused (with and without Table
#                  III's reset), the paper's version of each of the project's choices (D_rep,
#                  search region, morphological detection, formulation); error tables and SVG
#                  charts in bench_out/target, Fig. 12 (with and without the reset) among them
#   footage-host   the target tracker on real footage (OpenCV's vtest.avi, opencv-doc, at 384x288;
#                  node-opencv's motion.mov, a coin, at 568x320) against hand-marked truth
#                  (vectors/footage): frames within 10 px, identity switches, re-acquisition
#                  after occlusions, time, beside OpenCV's CSRT and KCF; a chart of the error
#                  over time a target in bench_out/footage
#   soak           the quadrangle tracker (10^6 generated frames, 30 % of sides missed, bursts of
#                  total loss) and the target tracker (10^5 frames of spells out of view) on seeds
#                  1-3, built with ASan + UBSan (host-sanitize): recovery, covariance, lost events;
#                  other lengths: BENCH_SOAK_FLAGS='--frames N --seeds K' (bench_soak --help)
#   fuzz           libFuzzer targets (clang, ASan + UBSan; tests/fuzz/run_fuzzers.sh) from a copy of
#                  the committed corpus: image readers and CLI parser 10^6 executions, the pipeline
#                  10^5 (QT_FUZZ_RUNS_<TARGET> to change), fixed seed; executions, findings, coverage
#   hdl-latency    clocks from a pixel's arrival to its gradient word (Icarus, no stalls)
#   hdl-soak       the gradient block against its model on QT_SOAK_SEEDS (10) soak streams of
#                  QT_SOAK_PIXELS (10^6, at most ~1.9*10^6) pixels: faults, resets, 30 % stalls
#   hdl-mutants    each single mutant of hdl/mutants/catalogue.txt (slips in hdl/rtl/) run through
#                  the test command's HDL tests, fastest first: which test caught it, the kill
#                  ratio (--quick: every 5th mutant)
#   long           the ctests labelled long, which the test command leaves out: in the host
#                  preset the whole VGA frame through both HDL blocks with 30 % stalls and the
#                  proof at 20 clocks; in the aarch64 preset the test cases tagged [slow]
#                  (statistics over scenes and photographs, 20 s or more under qemu-aarch64)
#   fpga           iCE40 UP5K and HX8K logic cells, block RAMs and Fmax (yosys + nextpnr)
# With no NAME, runs them all.
set -euo pipefail
cd "$(dirname "$0")"
source platform/ensure_packages.sh
jobs=$(nproc)
quick=0
if [ "${1:-}" = "--quick" ]; then
    quick=1
    shift
fi
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(gradient-host lines-host quads-host photos-host pictures track-host streams-host homography-host target-host footage-host soak gradient-m4 budgets budgets-m3 budgets-m4f target-m4f budget-table memory track-m4 hdl-latency hdl-soak hdl-mutants long fpga fuzz)

# full_or_quick FULL QUICK: the size of a bench's input set, full or --quick (about a tenth).
full_or_quick() {
    if [ "$quick" = 1 ]; then echo "$2"; else echo "$1"; fi
}

# The host benches compare with OpenCV in the same run: its development packages are installed
# here (never by the test command; the runtime never links it), and the configure step fails
# rather than print a table without its comparison rows.
host_build() {
    ensure_packages cmake make g++ catch2 iverilog libopencv-imgproc-dev libopencv-calib3d-dev \
        libopencv-contrib-dev
    cmake --preset host -DQT_REQUIRE_OPENCV=ON >/dev/null
    cmake --build --preset host -j"$jobs" --target "$@" >/dev/null
}

# Builds a Cortex-M preset (cortex-m4, cortex-m4f or cortex-m3): its images and the frames they
# stream (the photo chain's from opencv-doc, converted with netpbm).
build_firmware() {
    ensure_packages cmake make g++ gcc-arm-none-eabi libnewlib-arm-none-eabi \
        libstdc++-arm-none-eabi-newlib opencv-doc netpbm
    cmake --preset "$1" >/dev/null
    cmake --build --preset "$1" -j"$jobs" >/dev/null
}

# Builds a Cortex-M preset and runs one firmware image under QEMU with -icount shift=0 (one
# SysTick tick per 40 instructions, deterministic). The QEMU CPU is the preset's without the f:
# QEMU's cortex-m4 has the FPU either way.
run_firmware() {
    local preset=$1 machine=$2 image=$3
    ensure_packages qemu-system-arm
    build_firmware "$preset"
    qemu-system-arm -M "$machine" -cpu "${preset%f}" -nographic \
        -semihosting-config enable=on,target=native -icount shift=0 \
        -kernel "build/$preset/platform/firmware/$image.elf"
}

# budget-table: chain_bench on the three parts and target_bench on the M4F, then one table.
budget_table() {
    local out=bench_out/budgets
    mkdir -p "$out"
    run_firmware cortex-m4 mps2-an386 chain_bench >"$out/m4.txt" 2>&1
    run_firmware cortex-m4f mps2-an386 chain_bench >"$out/m4f.txt" 2>&1
    run_firmware cortex-m3 mps2-an385 chain_bench >"$out/m3.txt" 2>&1
    run_firmware cortex-m4f mps2-an386 target_bench >"$out/m4f-target.txt" 2>&1
    python3 platform/bench/budget_table.py \
        --chain Cortex-M4="$out/m4.txt" --chain Cortex-M4F="$out/m4f.txt" \
        --chain Cortex-M3="$out/m3.txt" --target Cortex-M4F="$out/m4f-target.txt" \
        --elves Cortex-M4=build/cortex-m4/platform/firmware \
        --elves Cortex-M4F=build/cortex-m4f/platform/firmware \
        --elves Cortex-M3=build/cortex-m3/platform/firmware
}

# memory: flash and RAM of the product images, from their link (the README's table).
memory_table() {
    local preset
    for preset in cortex-m4 cortex-m4f cortex-m3; do build_firmware "$preset"; done
    python3 platform/bench/budget_table.py --memory-only \
        --elves Cortex-M4=build/cortex-m4/platform/firmware \
        --elves Cortex-M4F=build/cortex-m4f/platform/firmware \
        --elves Cortex-M3=build/cortex-m3/platform/firmware
}

# The board sequence at 1280 x 720 (qt_board_y4m) encoded to H.264, then decoded by ffmpeg and
# by GStreamer into `quadtrack track -` as a user's pipe would: one table row per pipe.
stream_pipes() {
    local d q=build/host/platform/cli/quadtrack y=build/host/platform/scene/qt_board_y4m status
    d=$(mktemp -d)
    "$y" --size 1280x720 --colour 420 --truth "$d/truth.jsonl" |
        ffmpeg -loglevel error -f yuv4mpegpipe -i - -c:v libx264 -crf 18 -pix_fmt yuv420p "$d/clip.mp4"
    echo "A 1280x720 H.264 clip of the demo's board sequence through a pipe into quadtrack track -;"
    echo "worst and mean corner error over the frames, camera px."
    echo
    echo "| pipe | lines | bin | worst | mean | exit status |"
    echo "|---|---:|---:|---:|---:|---:|"
    status=0
    ffmpeg -loglevel error -i "$d/clip.mp4" -f yuv4mpegpipe -pix_fmt gray - |
        "$q" track - >"$d/ffmpeg.jsonl" || status=$?
    python3 platform/bench/corner_errors.py "ffmpeg -f yuv4mpegpipe -pix_fmt gray" \
        "$d/truth.jsonl" "$d/ffmpeg.jsonl" "$status"
    status=0
    gst-launch-1.0 -q filesrc location="$d/clip.mp4" ! decodebin ! videoconvert \
        ! video/x-raw,format=Y42B ! y4menc ! fdsink fd=1 | "$q" track - >"$d/gst.jsonl" || status=$?
    python3 platform/bench/corner_errors.py "gst-launch-1.0 ... y4menc" \
        "$d/truth.jsonl" "$d/gst.jsonl" "$status"
    # A camera-size clip a user has at hand: a street, no board, so no errors to measure.
    status=0
    ffmpeg -loglevel error -i /usr/share/doc/opencv-doc/examples/data/vtest.avi \
        -f yuv4mpegpipe -pix_fmt gray - | "$q" track - >"$d/vtest.jsonl" || status=$?
    echo
    echo "OpenCV's vtest.avi (opencv-doc, 768x576) through ffmpeg: $(wc -l <"$d/vtest.jsonl") lines," \
        "bin $(grep -o '"bin":[0-9]*' "$d/vtest.jsonl" | sort -u | cut -d: -f2 | paste -sd,)," \
        "exit status $status"
    rm -rf "$d"
}

# footage_video SOURCE OUT.y4m [FILTER]: a video as the grey Y4M its truth in vectors/footage was
# marked on (FILTER: ffmpeg's -vf, e.g. scale=384:288 with its default bicubic scaler), and the
# same frames in colour, raw BGR, beside it for OpenCV's trackers (bench_footage --colour).
footage_video() {
    [ -s "$2" ] && [ -s "${2%.y4m}.bgr" ] && return 0
    mkdir -p "$(dirname "$2")"
    local vf=()
    [ -z "${3:-}" ] || vf=(-vf "$3")
    ffmpeg -loglevel error -y -i "$1" "${vf[@]}" -f yuv4mpegpipe -pix_fmt gray "$2"
    ffmpeg -loglevel error -y -i "$1" "${vf[@]}" -f rawvideo -pix_fmt bgr24 "${2%.y4m}.bgr"
}

# package_file PACKAGE PATH OUT: one file of a Debian package, fetched with apt-get download and
# unpacked without installing the package (node-opencv's dependencies are a Node.js runtime the
# bench never runs).
package_file() {
    [ -s "$3" ] && return 0
    local d
    d=$(mktemp -d)
    (cd "$d" && apt-get download -q "$1" >/dev/null 2>&1) || {
        apt-get update -q >/dev/null && (cd "$d" && apt-get download -q "$1" >/dev/null)
    }
    dpkg-deb -x "$d"/"$1"_*.deb "$d/x"
    mkdir -p "$(dirname "$3")"
    cp "$d/x/$2" "$3"
    rm -rf "$d"
}

# Runs one bench, printing its figures.
run_bench() {
    local b=build/host/platform/bench
    case "$1" in
        gradient-host)
            host_build bench_gradient
            "$b/bench_gradient" ;;
        lines-host)
            host_build bench_lines
            "$b/bench_lines" --scenes "$(full_or_quick 1000 100)" ;;
        quads-host)
            host_build bench_quads
            "$b/bench_quads" --scenes "$(full_or_quick 500 50)" ;;
        photos-host)
            ensure_packages opencv-doc netpbm python3-skimage
            host_build bench_photo_boards real_photos heldout_photos patterned_photos
            rm -rf bench_out/photos && mkdir -p bench_out/photos
            local scenes=${BENCH_PHOTO_SCENES:-$(full_or_quick 1500 150)} others
            others=$(mktemp)
            photo_sets() {
                echo "Held out: photographs never used to choose a parameter (python3-skimage)."
                "$b/bench_photo_boards" build/host/photos_heldout --scenes "$scenes" --no-sequence
                echo "Patterned backgrounds: opencv-doc's checkerboard calibration shots."
                "$b/bench_photo_boards" build/host/photos_patterned --scenes "$scenes" --no-sequence
            }
            # --quick: the held-out and patterned sets on the second core meanwhile (their
            # times are then shared-core times; the full run measures one set at a time).
            if [ "$quick" = 1 ]; then photo_sets >"$others" & fi
            "$b/bench_photo_boards" build/host/photos --scenes "$scenes" --pictures bench_out/photos
            wait
            if [ "$quick" = 0 ]; then photo_sets >"$others"; fi
            cat "$others"
            rm -f "$others" ;;
        pictures)
            # The README's two --draw pictures: a board on one of opencv-doc's photographs
            # (scene 1 of the photo bench's occluded set, QVGA), and frame 6 of the demo's board
            # sequence at 320 x 240, tracked, its hidden sides predicted.
            ensure_packages opencv-doc netpbm optipng
            host_build quadtrack qt_board_y4m bench_photo_boards real_photos
            local tmp q=build/host/platform/cli/quadtrack y=build/host/platform/scene/qt_board_y4m
            tmp=$(mktemp -d)
            "$b/bench_photo_boards" build/host/photos --scenes 2 --size qvga --no-sequence \
                --pictures "$tmp" >/dev/null
            mkdir -p docs/pictures
            "$q" detect "$tmp/QVGA_o2000001.pgm" --draw docs/pictures/detect_photo.png >/dev/null
            "$y" --size 320x240 | "$q" track - --draw "$tmp/track_%02d.png" >/dev/null
            cp "$tmp/track_06.png" docs/pictures/track_frame.png
            optipng -quiet -o2 docs/pictures/detect_photo.png docs/pictures/track_frame.png
            ls -l docs/pictures
            rm -rf "$tmp" ;;
        track-host)
            host_build bench_track
            "$b/bench_track" --out bench_out/track ;;
        streams-host)
            ensure_packages ffmpeg gstreamer1.0-tools gstreamer1.0-plugins-good gstreamer1.0-libav \
                opencv-doc
            host_build bench_streams quadtrack qt_board_y4m
            "$b/bench_streams"
            stream_pipes ;;
        homography-host)
            host_build bench_homography
            "$b/bench_homography" --trials "$(full_or_quick 200 20)" ;;
        target-host)
            host_build bench_target
            "$b/bench_target" --out bench_out/target --seeds "$(full_or_quick 15 2)" ;;
        footage-host)
            ensure_packages opencv-doc ffmpeg
            host_build bench_footage
            local f=build/host/footage
            footage_video /usr/share/doc/opencv-doc/examples/data/vtest.avi \
                "$f/vtest_384x288.y4m" scale=384:288
            package_file node-opencv usr/share/doc/node-opencv/examples/files/motion.mov \
                "$f/motion.mov"
            footage_video "$f/motion.mov" "$f/motion.y4m"
            rm -rf bench_out/footage && mkdir -p bench_out/footage
            local truth
            mapfile -t truth < <(ls vectors/footage/vtest_T*.txt | grep -v '\.second\.txt$' | sort -V)
            [ "$quick" = 0 ] || truth=("${truth[0]}")  # --quick: the first walker
            "$b/bench_footage" "$f/vtest_384x288.y4m" --out bench_out/footage \
                --colour "$f/vtest_384x288.bgr" "${truth[@]}"
            echo
            "$b/bench_footage" "$f/motion.y4m" --out bench_out/footage \
                --colour "$f/motion.bgr" vectors/footage/motion_coin.txt ;;
        gradient-m4)
            run_firmware cortex-m4 mps2-an386 gradient_bench 2>&1 ;;
        budgets)
            run_firmware cortex-m4 mps2-an386 chain_bench 2>&1 | grep -E '^(budget|work|fpga|bands|chain:|FAIL)' ;;
        budgets-m3)
            run_firmware cortex-m3 mps2-an385 chain_bench 2>&1 | grep -E '^(budget|work|fpga|bands|chain:|FAIL)' ;;
        budgets-m4f)
            run_firmware cortex-m4f mps2-an386 chain_bench 2>&1 | grep -E '^(budget|work|fpga|bands|chain:|FAIL)' ;;
        target-m4f)
            run_firmware cortex-m4f mps2-an386 target_bench 2>&1 | grep -E '^(budget|target:|FAIL)' ;;
        budget-table)
            budget_table ;;
        memory)
            memory_table ;;
        track-m4)
            run_firmware cortex-m4 mps2-an386 track_bench 2>&1 ;;
        soak)
            ensure_packages cmake make g++ catch2
            cmake --preset host-sanitize >/dev/null
            cmake --build --preset host-sanitize -j"$jobs" --target bench_soak >/dev/null
            # shellcheck disable=SC2086  # the flags are words
            ./build/host-sanitize/platform/bench/bench_soak \
                ${BENCH_SOAK_FLAGS:-$(full_or_quick "" "--frames 100000 --target-frames 10000")} ;;
        hdl-latency)
            host_build all
            (cd build/host && ctest -R '^hdl_.*_nostall$' -V | grep -E 'LATENCY|TRAILER|STALLS|PASS|Failed') ;;
        hdl-mutants)
            host_build qt_vectors
            python3 hdl/mutants/run_mutants.py --hdl hdl --vectors vectors/gradient \
                --work build/hdl-mutants --qt-vectors build/host/hw_model/qt_vectors \
                --every "$(full_or_quick 1 5)" ;;
        hdl-soak)
            host_build qt_vectors hdl_benches
            local seeds=${QT_SOAK_SEEDS:-$(full_or_quick 10 1)}
            for ((s = 101; s <= 100 + seeds; ++s)); do
                cmake -DQT_VECTORS=build/host/hw_model/qt_vectors -DVVP="$(command -v vvp)" \
                    -DBENCH=build/host/hdl/tb_front_w640.vvp -DSEED="$s" -DPIXELS="${QT_SOAK_PIXELS:-1000000}" \
                    -DPREFIX=build/host/hdl/soak/bench -P hdl/bench/run_soak.cmake 2>&1 |
                    grep -E -A1 --no-group-separator 'mismatches=|MISMATCH|EXTRA|MISSING|FATAL|Error' || true
            done | awk -v seeds="$seeds" '{ print }
                /mismatches=/ { n++; if (/mismatches=FAIL/) bad++; for (i = 2; i <= NF; i++) { split($i, kv, "="); t[kv[1]] += kv[2] } }
                END { printf "total seeds=%d pixels=%d frames=%d resets=%d faults=%d errors=%d checked=%d cut=%d failed=%d seconds=%d\n",
                      n, t["pixels"], t["frames"], t["resets"], t["faults"], t["errors"], t["checked"], t["cut"], bad + seeds - n, t["seconds"]
                      exit (n != seeds || bad > 0) }' ;;
        long)
            ensure_packages g++-aarch64-linux-gnu qemu-user opencv-doc netpbm yosys
            host_build all
            cmake --preset aarch64-linux >/dev/null
            cmake --build --preset aarch64-linux -j"$jobs" >/dev/null
            (cd build/host && ctest -L long -j"$jobs" --output-on-failure)
            (cd build/aarch64-linux && ctest -L long -j"$jobs" --output-on-failure) ;;
        fuzz)
            ensure_packages cmake make clang libclang-rt-14-dev
            QT_FUZZ_RUNS_IMAGE_READER=${QT_FUZZ_RUNS_IMAGE_READER:-$(full_or_quick 1000000 100000)} \
                QT_FUZZ_RUNS_CLI_ARGS=${QT_FUZZ_RUNS_CLI_ARGS:-$(full_or_quick 1000000 100000)} \
                QT_FUZZ_RUNS_PIPELINE=${QT_FUZZ_RUNS_PIPELINE:-$(full_or_quick 100000 10000)} \
                bash tests/fuzz/run_fuzzers.sh ;;
        fpga)
            ensure_packages yosys nextpnr-ice40 fpga-icestorm
            bash hdl/synth/ice40.sh ;;
        *)
            echo "unknown benchmark '$1'" >&2
            return 2 ;;
    esac
}

# The docs page whose figures each bench writes (between its <!-- bench NAME --> markers).
doc_of() {
    case "$1" in
        gradient-host|gradient-m4|hdl-latency|hdl-soak|hdl-mutants|fpga) echo docs/gradient.md ;;
        lines-host) echo docs/lines.md ;;
        quads-host|photos-host) echo docs/quadrangles.md ;;
        track-host|track-m4) echo docs/tracking.md ;;
        streams-host) echo docs/cli.md ;;
        homography-host|target-host|footage-host) echo docs/target.md ;;
        budgets|budgets-m3|budgets-m4f|target-m4f|budget-table) echo docs/firmware.md ;;
        memory) echo README.md ;;
        soak|fuzz) echo docs/robustness.md ;;
    esac
}

for name in "${names[@]}"; do
    echo "=== $name"
    out=$(mktemp)
    run_bench "$name" | tee "$out"
    doc=$(doc_of "$name")
    [ -z "$doc" ] || [ "$quick" = 1 ] || python3 platform/bench/record_figures.py "$doc" "$name" "$out"
    rm -f "$out"
done
