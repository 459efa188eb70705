#include "host/board_runner.h"

#include "gradient/binning.h"
#include "io/push_frame.h"

namespace qt::host {

const char* capacity_name(DetectorCapacity c) {
    return c == DetectorCapacity::qvga ? "qvga" : "vga";
}
int max_frame_width(DetectorCapacity c) {
    return c == DetectorCapacity::qvga ? Qvga::max_width : kMaxFrameWidth;
}
int max_frame_height(DetectorCapacity c) {
    return c == DetectorCapacity::qvga ? Qvga::max_height : kMaxFrameHeight;
}

namespace {

// The chain on one frame with detector `det`, its results copied into `result` (whose size and
// bin factor are set).
template <class Detector>
bool run_chain(Detector& det, const io::GreyImage& frame, const BoardParams& params,
               DetectResult& result, BandWindow* window) {
    static BinningStage<kMaxFrameWidth> binning;  // 1.9 KB
    const uint8_t bin = result.bin;
    const uint16_t w = result.width, h = result.height;
    Status s;
    if (bin == 1 && window == nullptr) {
        s = io::push_frame(det, frame, params);
    } else {
        s = det.begin_frame(w, h, params, window);
        if (s == Status::previous_frame_incomplete) s = Status::ok;
        if (s == Status::ok)
            s = io::push_binned_rows(binning, frame, bin, [&](const uint8_t* row, uint16_t n) {
                return det.push_row(row, n);
            });
        if (s == Status::ok) s = det.finish();
    }
    result.status = s;
    if (s != Status::ok && s != Status::capacity_exceeded) return false;
    const auto& lines = det.lines();
    result.lines.assign(lines.lines(), lines.lines() + lines.line_count());
    result.quads.assign(det.quads(), det.quads() + det.quad_count());
    result.line_stats = lines.stats();
    result.quad_stats = det.quad_stats();
    return true;
}

HostBoardDetector vga_detector;   // ~90 KB: static, as firmware keeps it
BoardDetectorQvga qvga_detector;  // ~50 KB

}  // namespace

q16_16 evidence_share(const TrackedQuad& quad, const RefineParams& params,
                      DetectorCapacity capacity) {
    if (quad.state == TrackState::none) return q16_16::from_int(0);
    const EdgeList& edges = capacity == DetectorCapacity::qvga ? qvga_detector.lines().edges()
                                                               : vga_detector.lines().edges();
    RefineParams scored = params;
    // Scored, never turned down.
    scored.min_side_evidence_percent = kCheckOff;
    scored.min_hidden_side_evidence_percent = kCheckOff;
    scored.min_evidence_percent = kCheckOff;
    Quad q{};
    const Segment* lines[4];
    for (int i = 0; i < 4; ++i) {
        q.corners[i] = quad.corners[i];
        q.lines[i] = static_cast<uint8_t>(i);
        lines[i] = &quad.sides[i];
    }
    Segment sides[4];
    q16_16 share = q16_16::from_int(0);
    refine_verified(edges, lines, scored, q, sides, &share);
    return share;
}

bool detect_board(const io::GreyImage& frame, const BoardParams& params, DetectResult& result,
                  uint8_t bin, DetectorCapacity capacity, BandWindow* window) {
    HostBoardDetector& vga = vga_detector;
    BoardDetectorQvga& qvga = qvga_detector;
    result = DetectResult{};
    const int w = bin > 0 ? frame.width / bin : 0, h = bin > 0 ? frame.height / bin : 0;
    result.width = static_cast<uint16_t>(w);
    result.height = static_cast<uint16_t>(h);
    result.bin = bin;
    if (w <= 0 || h <= 0 || w > max_frame_width(capacity) || h > max_frame_height(capacity) ||
        frame.width > 65535 || frame.height > 65535) {
        result.status = Status::bad_size;
        return false;
    }
    return capacity == DetectorCapacity::qvga ? run_chain(qvga, frame, params, result, window)
                                              : run_chain(vga, frame, params, result, window);
}

uint8_t choose_bin(int width, int height, uint8_t requested, std::string& error,
                   DetectorCapacity capacity) {
    const int max_w = max_frame_width(capacity), max_h = max_frame_height(capacity);
    const std::string build =
        capacity == DetectorCapacity::qvga ? "the QVGA capacity's " : "this build's ";
    const auto size = [](int w, int h) { return std::to_string(w) + " x " + std::to_string(h); };
    if (width <= 0 || height <= 0 || width > 65535 || height > 65535) {
        error = size(width, height) + " cannot be binned";
        return 0;
    }
    const uint16_t w = static_cast<uint16_t>(width), h = static_cast<uint16_t>(height);
    if (requested == 0) {
        const uint8_t n =
            bin_factor_to_fit(w, h, static_cast<uint16_t>(max_w), static_cast<uint16_t>(max_h));
        if (n == 0)
            error = size(width, height) + " does not fit " + build + size(max_w, max_h) +
                    " by any bin factor up to " + std::to_string(kMaxBinFactor);
        return n;
    }
    const int bw = width / requested, bh = height / requested;
    if (bw == 0 || bh == 0 || bw > max_w || bh > max_h) {
        error = size(width, height) + " binned by " + std::to_string(requested) + " is " +
                size(bw, bh) + ", not within " + build + size(max_w, max_h) +
                " (--bin auto picks a factor)";
        return 0;
    }
    return requested;
}

Segment to_input_pixels(const Segment& s, uint8_t bin) {
    if (bin <= 1) return s;
    Segment o = s;
    o.x1 = unbinned(s.x1, bin);
    o.y1 = unbinned(s.y1, bin);
    o.x2 = unbinned(s.x2, bin);
    o.y2 = unbinned(s.y2, bin);
    // n·(N·p + c·(1, 1)) = N·rho + c·(cos θ + sin θ), c = (N − 1)/2 px.
    const SinCos n = sin_cos(s.theta);
    int64_t rho = static_cast<int64_t>(s.rho.raw) * bin +
                  shr_round_half_away(
                      static_cast<int64_t>(bin - 1) * (static_cast<int64_t>(n.cos.raw) + n.sin.raw),
                      15);  // (N − 1)·2^15·(cos + sin)·2^30 / 2^30
    angle_t theta = s.theta;
    int8_t bright = s.bright_side;
    if (rho < 0) {  // the origin crossed to the line's other side: the normal turns round
        rho = -rho;
        theta += kAngleHalfTurn;
        bright = static_cast<int8_t>(-bright);
    }
    const SinCos m = sin_cos(theta);
    o.rho = q16_16::from_raw(rho);
    o.theta = theta;
    o.bright_side = bright;
    o.cx = q16_16::from_raw(shr_round_half_away(o.rho.raw * static_cast<int64_t>(m.cos.raw), 30));
    o.cy = q16_16::from_raw(shr_round_half_away(o.rho.raw * static_cast<int64_t>(m.sin.raw), 30));
    return o;
}

void to_input_pixels(DetectResult& r, int input_width, int input_height) {
    r.width = static_cast<uint16_t>(input_width);
    r.height = static_cast<uint16_t>(input_height);
    if (r.bin <= 1) return;
    for (Segment& s : r.lines) s = to_input_pixels(s, r.bin);
    for (Quad& q : r.quads)
        for (Point16& c : q.corners) c = {unbinned(c.x, r.bin), unbinned(c.y, r.bin)};
}

void to_input_pixels(TrackedQuad& t, uint8_t bin) {
    if (bin <= 1) return;
    for (Point16& c : t.corners) c = {unbinned(c.x, bin), unbinned(c.y, bin)};
    for (Segment& s : t.sides) s = to_input_pixels(s, bin);
}

}  // namespace qt::host
