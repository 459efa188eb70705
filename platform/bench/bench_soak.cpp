// Soak bench: the quadrangle tracker and the target tracker over long generated runs
// (platform/bench/soak_runs.h says what is generated and which rules are checked), one line per run
// and tracker. bash bench.sh soak builds it with ASan + UBSan (the host-sanitize preset), which
// abort on the first overflow or other undefined behaviour: a run that prints its line had none.
// Exit status 1 when a run broke a rule.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "bench/soak_runs.h"
#include "host/parse_number.h"

namespace {

void usage(FILE* f) {
    std::fprintf(
        f,
        "usage: bench_soak [--frames N] [--seeds K] [--target-frames N] [--model paper|turn|both]\n"
        "  --frames N         quadrangle tracker frames per run, 1..100000000 (default 1000000)\n"
        "  --seeds K          runs with seeds 1..K, 1..1000 (default 3)\n"
        "  --target-frames N  target tracker frames per run, 0..100000000 (default 100000; 0: "
        "none)\n"
        "  --model M          line model of the quadrangle tracker's sides (default both)\n");
}

const char* ub_note() {
#if defined(__SANITIZE_ADDRESS__)
    return "UB none (ASan+UBSan build: any would have aborted the run)";
#else
    return "UB not checked (not a sanitizer build; bash bench.sh soak builds one)";
#endif
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    long frames = 1000000, seeds = 3, target_frames = 100000;
    bool paper = true, turn = true;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        std::string error;
        if (a == "--help") {
            usage(stdout);
            return 0;
        } else if (a == "--frames" && i + 1 < argc) {
            if (!qt::host::parse_int(argv[++i], 1, 100000000, frames, error)) {
                std::fprintf(stderr, "bench_soak: --frames: %s\n", error.c_str());
                return 2;
            }
        } else if (a == "--seeds" && i + 1 < argc) {
            if (!qt::host::parse_int(argv[++i], 1, 1000, seeds, error)) {
                std::fprintf(stderr, "bench_soak: --seeds: %s\n", error.c_str());
                return 2;
            }
        } else if (a == "--target-frames" && i + 1 < argc) {
            if (!qt::host::parse_int(argv[++i], 0, 100000000, target_frames, error)) {
                std::fprintf(stderr, "bench_soak: --target-frames: %s\n", error.c_str());
                return 2;
            }
        } else if (a == "--model" && i + 1 < argc) {
            const std::string m = argv[++i];
            if (m != "paper" && m != "turn" && m != "both") {
                std::fprintf(stderr, "bench_soak: --model must be paper, turn or both, got '%s'\n",
                             m.c_str());
                return 2;
            }
            paper = m != "turn";
            turn = m != "paper";
        } else {
            std::fprintf(stderr, "bench_soak: unknown or incomplete option '%s' (try --help)\n",
                         a.c_str());
            return 2;
        }
    }

    bool broken = false;
    for (long seed = 1; seed <= seeds; ++seed) {
        for (const qt::LineModel model : {qt::LineModel::closest_points, qt::LineModel::turn}) {
            if (model == qt::LineModel::closest_points ? !paper : !turn) continue;
            qt::soak::QuadSoakConfig c;
            c.frames = static_cast<uint32_t>(frames);
            c.seed = static_cast<uint64_t>(seed);
            c.model = model;
            const auto t0 = std::chrono::steady_clock::now();
            const qt::soak::QuadSoakResult r = qt::soak::run_quad_soak(c);
            const double t = seconds_since(t0);
            const bool is_turn = model == qt::LineModel::turn;
            const char* unit = is_turn ? "deg^2" : "px^2";
            std::printf(
                "quad   seed %ld model %s: frames %u, bursts %u (%u longer than max_predicted), "
                "worst recovery %u "
                "frames after a burst's end (worst wait for a frame showing all four sides %u; %u "
                "bursts recovered "
                "only after that frame), max covariance Ppp "
                "%.3f %s (bound %.3f; before a track is %u frames old %.3f, bound %.3f), Pvv %.4f "
                "(bound %.4f; "
                "young %.4f, bound %.4f)%s, lost events %u (side_unseen %u, shape %u, saturated "
                "%u, "
                "detection_disagrees %u; %u away from bursts), tracks started %u, worst corner "
                "error while tracking "
                "away from bursts %.2f px, rule breaks %u, %.1f s, %s\n",
                seed, is_turn ? "turn" : "paper", r.frames, r.bursts, r.long_bursts,
                r.worst_recovery, r.worst_wait_full, r.recovered_after_whole, r.max_pos_variance,
                unit, r.pos_variance_bound, r.settled_age, r.max_pos_variance_young,
                r.pos_variance_bound_young, r.max_vel_variance, r.vel_variance_bound,
                r.max_vel_variance_young, r.vel_variance_bound_young,
                is_turn ? (", offset filter P00 " + std::to_string(r.max_offset_variance) + " px^2")
                              .c_str()
                        : "",
                r.lost[1] + r.lost[2] + r.lost[3] + r.lost[4], r.lost[1], r.lost[2], r.lost[3],
                r.lost[4], r.lost_outside_bursts, r.tracks_started, r.worst_error_tracking,
                r.breaks, t, ub_note());
            if (r.breaks > 0) {
                std::printf("       first break: %s\n", r.first_break.c_str());
                broken = true;
            }
            std::fflush(stdout);
        }
        if (target_frames > 0) {
            qt::soak::TargetSoakConfig c;
            c.frames = static_cast<uint32_t>(target_frames);
            c.seed = static_cast<uint64_t>(seed);
            const auto t0 = std::chrono::steady_clock::now();
            const qt::soak::TargetSoakResult r = qt::soak::run_target_soak(c);
            const double t = seconds_since(t0);
            std::printf(
                "target seed %ld: frames %u, cycles %u (spells: drift %u, unseen %u, bad geometry "
                "%u, scale %u), "
                "lost events %u (unseen %u, bad geometry %u, scale %u; %u in exactly the frame the "
                "rule names), "
                "reacquired %u (longest spell %u frames), worst error while trusted %.4f px (%.4f "
                "px outside the "
                "image, up to %.0f px out), rule breaks %u, %.1f s, %s\n",
                seed, r.frames, r.cycles, r.spells[0], r.spells[1], r.spells[2], r.spells[3],
                r.lost_events, r.lost_by_rule[0], r.lost_by_rule[1], r.lost_by_rule[2],
                r.lost_on_time, r.reacquired, r.longest_unseen, r.worst_error_px,
                r.worst_error_outside_px, r.farthest_outside_px, r.breaks, t, ub_note());
            if (r.breaks > 0) {
                std::printf("       first break: %s\n", r.first_break.c_str());
                broken = true;
            }
            std::fflush(stdout);
        }
    }
    return broken ? 1 : 0;
}
