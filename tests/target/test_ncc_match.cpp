// Zero-mean NCC in Q15 (core/target/ncc_match.h) against the double formula, hand-worked blocks,
// and corner matching between a textured frame and the same frame shifted.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "base/prng.h"
#include "target/harris.h"
#include "target/ncc_match.h"

using namespace qt;

namespace {

// Zero-mean NCC in double, then round(32768·r) clamped to int16; flat when either block's
// variance (grey levels²) is below min_variance or zero.
struct RefNcc {
    int q15;
    bool flat;
    bool near_half;  // 32768·r within 0.01 of a half: rounding may go either way
};
RefNcc ref_ncc(const uint8_t* a, int as, const uint8_t* b, int bs, int w, int h,
               double min_variance) {
    const double n = w * h;
    double ma = 0, mb = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            ma += a[y * as + x];
            mb += b[y * bs + x];
        }
    ma /= n;
    mb /= n;
    double ab = 0, aa = 0, bb = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double da = a[y * as + x] - ma, db = b[y * bs + x] - mb;
            ab += da * db;
            aa += da * da;
            bb += db * db;
        }
    if (aa == 0 || bb == 0 || aa / n < min_variance || bb / n < min_variance)
        return {0, true, false};
    const double x = 32768 * ab / std::sqrt(aa * bb), q = std::round(x);
    return {static_cast<int>(std::min(32767.0, std::max(-32768.0, q))), false,
            std::abs(std::abs(x - std::floor(x)) - 0.5) < 0.01};
}

uint8_t clamp8(int v) { return static_cast<uint8_t>(std::min(std::max(v, 0), 255)); }

// White noise blurred once by a 3×3 box and stretched to 0..255: every 9×9 neighbourhood its
// own (a smoother texture, e.g. bilinear blobs, lets unrelated corners correlate above 0.8).
std::vector<uint8_t> noise_texture(int w, int h, uint64_t seed) {
    Pcg32 rng(seed);
    std::vector<int> a(static_cast<size_t>(w * h)), b(a.size());
    for (int& v : a) v = static_cast<int>(rng.below(256));
    int lo = 1 << 30, hi = -(1 << 30);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int sum = 0;
            for (int v = -1; v <= 1; ++v)
                for (int u = -1; u <= 1; ++u) {
                    const int xx = std::min(std::max(x + u, 0), w - 1),
                              yy = std::min(std::max(y + v, 0), h - 1);
                    sum += a[static_cast<size_t>(yy * w + xx)];
                }
            b[static_cast<size_t>(y * w + x)] = sum;
            lo = std::min(lo, sum);
            hi = std::max(hi, sum);
        }
    std::vector<uint8_t> im(a.size());
    for (size_t i = 0; i < im.size(); ++i)
        im[i] = static_cast<uint8_t>((b[i] - lo) * 255 / (hi - lo));
    return im;
}

// The w×h window at (x0, y0) of a frame of width fw.
std::vector<uint8_t> crop(const std::vector<uint8_t>& frame, int fw, int x0, int y0, int w, int h) {
    std::vector<uint8_t> out(static_cast<size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            out[static_cast<size_t>(y * w + x)] =
                frame[static_cast<size_t>((y0 + y) * fw + x0 + x)];
    return out;
}

template <uint16_t MF>
void features(const std::vector<uint8_t>& im, int w, int h, FeatureSet<4, MF>& out,
              const HarrisParams& c = HarrisParams{}) {
    static HarrisDetector<256, 96, 4, 2> det;
    static_assert(MF == 96, "one detector");
    REQUIRE(detect_features(det, im.data(), static_cast<uint16_t>(w), static_cast<uint16_t>(h),
                            static_cast<uint32_t>(w), c, out) == Status::ok);
}

Feature<4> patch_feature(int px, int py, const std::vector<uint8_t>& patch) {
    Feature<4> f;
    f.px = static_cast<int16_t>(px);
    f.py = static_cast<int16_t>(py);
    f.x_q8 = px * 256;
    f.y_q8 = py * 256;
    std::copy(patch.begin(), patch.end(), f.patch);
    return f;
}

uint16_t sum_of(const MatchStats& s, uint16_t matched) {
    return static_cast<uint16_t>(s.flat + s.no_candidate + s.below_min + s.ambiguous +
                                 s.not_mutual + s.dropped_capacity + matched);
}

}  // namespace

TEST_CASE("NCC equals the double formula within 1 in Q15", "[ncc]") {
    Pcg32 rng(77);
    int worst = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const int w = 1 + static_cast<int>(rng.below(32)),
                  h = 1 + static_cast<int>(rng.below(static_cast<uint32_t>(1024 / w)));
        const int as = w + static_cast<int>(rng.below(5)), bs = w + static_cast<int>(rng.below(5));
        std::vector<uint8_t> a(static_cast<size_t>(as * h)), b(static_cast<size_t>(bs * h));
        const int kind =
            trial % 4;  // 0 independent, 1 correlated, 2 anti-correlated, 3 binary 0/255
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int v = static_cast<int>(rng.below(256)),
                          noise = static_cast<int>(rng.below(61)) - 30;
                uint8_t& pa = a[static_cast<size_t>(y * as + x)];
                uint8_t& pb = b[static_cast<size_t>(y * bs + x)];
                pa = kind == 3 ? static_cast<uint8_t>(rng.below(2) * 255) : static_cast<uint8_t>(v);
                pb = kind == 0   ? static_cast<uint8_t>(rng.below(256))
                     : kind == 1 ? clamp8(v + noise)
                     : kind == 2 ? clamp8(255 - v + noise)
                                 : static_cast<uint8_t>(rng.below(8) == 0 ? 255 - pa : pa);
            }
        const RefNcc want = ref_ncc(a.data(), as, b.data(), bs, w, h, 4);
        const NccScore got =
            ncc_q15(a.data(), static_cast<uint32_t>(as), b.data(), static_cast<uint32_t>(bs),
                    static_cast<uint16_t>(w), static_cast<uint16_t>(h));
        INFO("trial " << trial << " " << w << "x" << h);
        REQUIRE(got.flat == want.flat);
        // The root carries 32 significant bits: the quotient is exact to ~10^-4 before
        // rounding, so the result is round(32768·r) except, at most by 1, next to a half.
        if (want.near_half)
            REQUIRE(std::abs(got.q15 - want.q15) <= 1);
        else
            REQUIRE(got.q15 == want.q15);
        worst = std::max(worst, std::abs(got.q15 - want.q15));
    }
    CHECK(worst <= 1);
}

TEST_CASE("ncc_certainly_below never calls a score below that is not, and spares most", "[ncc]") {
    // Blocks of 1..1024 pixels, scores spread over [-1, 1]: independent, correlated at several
    // noise levels, and low-contrast blocks (grey levels within a span of 3..12, the small
    // variances the bound's shifts must not coarsen). For each, the bound is asked about
    // every score from q - 3 to q + 8 (q: ncc_from_sums' own) and a random one: it may say
    // "below" only for scores above q, and must for most scores 8 or more above a positive q.
    Pcg32 rng(4242);
    uint32_t asked_above = 0, spared_above = 0, said_below = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const int w = 1 + static_cast<int>(rng.below(32)),
                  h = 1 + static_cast<int>(rng.below(static_cast<uint32_t>(1024 / w)));
        const int kind = trial % 4;  // 0 independent, 1 correlated, 2 faint, 3 faint correlated
        const int span = kind >= 2 ? 3 + static_cast<int>(rng.below(10)) : 256;
        const int noise = 1 + static_cast<int>(rng.below(kind >= 2 ? 4 : 120));
        std::vector<uint8_t> a(static_cast<size_t>(w * h)), b(a.size());
        const int base = static_cast<int>(rng.below(static_cast<uint32_t>(257 - span)));
        auto grey = [&] { return base + static_cast<int>(rng.below(static_cast<uint32_t>(span))); };
        for (size_t i = 0; i < a.size(); ++i) {
            const int v = grey();
            const int jitter = static_cast<int>(rng.below(static_cast<uint32_t>(2 * noise + 1)));
            a[i] = static_cast<uint8_t>(v);
            b[i] = kind % 2 == 0 ? static_cast<uint8_t>(grey()) : clamp8(v + jitter - noise);
        }
        NccSums s;
        s.n = static_cast<uint32_t>(w * h);
        ncc_add_row<true>(a.data(), b.data(), s.n, s);
        const int32_t q = ncc_from_sums(s).q15;
        INFO("trial " << trial << " " << w << "x" << h << " q15 " << q);
        for (int32_t score = q - 3; score <= q + 8; ++score) {
            const bool below = ncc_certainly_below(s, score);
            said_below += below;
            REQUIRE((!below || q < score));
            if (score >= q + 8 && q > 0 && score <= 32767) {
                ++asked_above;
                spared_above += below;
            }
        }
        const int32_t any = static_cast<int32_t>(rng.below(32768));
        REQUIRE((!ncc_certainly_below(s, any) || q < any));
    }
    CHECK(said_below > 1000);
    CHECK(asked_above > 500);
    CHECK(spared_above * 100 >= asked_above * 99);
}

TEST_CASE("dot_block is the sum of products over the block, whatever its width", "[ncc]") {
    // The template search's Σab; on a Cortex-M4 its rows go four bytes a step with a masked last
    // step (the firmware's ncc_check runs this on the target), here the plain loop.
    Pcg32 rng(11);
    std::vector<uint8_t> a(32 * 32), b(40 * 33);
    for (uint32_t w = 1; w <= 32; ++w)
        for (uint32_t h = 1; h <= 32 && w * h <= kNccMaxPixels; h += 5) {
            for (auto& v : a) v = static_cast<uint8_t>(rng.next() >> 24);
            for (auto& v : b) v = static_cast<uint8_t>(rng.next() >> 24);
            a[0] = b[0] = 255;  // the largest product
            uint64_t want = 0;
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) want += uint64_t{a[y * w + x]} * b[y * 40 + x];
            CAPTURE(w, h);
            CHECK(dot_block(a.data(), w, h, b.data(), 40) == want);
        }
}

TEST_CASE("NCC hand-worked blocks", "[ncc]") {
    Pcg32 rng(3);
    std::vector<uint8_t> p(81), neg(81), affine(81), doubled(81);
    for (size_t i = 0; i < 81; ++i) {
        p[i] = static_cast<uint8_t>(20 + rng.below(101));  // 20..120
        neg[i] = static_cast<uint8_t>(255 - p[i]);
        affine[i] = clamp8((p[i] + 1) / 2 + 60);           // a·p + b rounded
        doubled[i] = static_cast<uint8_t>(2 * p[i] - 40);  // exact
    }
    auto score = [](const std::vector<uint8_t>& x, const std::vector<uint8_t>& y,
                    uint32_t min_var = kNccMinVariance) {
        return ncc_q15(x.data(), 9, y.data(), 9, 9, 9, min_var);
    };
    REQUIRE(score(p, p).q15 == 32767);
    REQUIRE_FALSE(score(p, p).flat);
    REQUIRE(score(p, neg).q15 == -32768);
    REQUIRE(score(p, doubled).q15 == 32767);
    REQUIRE(score(p, affine).q15 >= 32600);
    // Flat: constant, and alternating 100/101 (variance 1/4 < 4 grey levels²).
    std::vector<uint8_t> flat(81, 90), nearly(81);
    for (size_t i = 0; i < 81; ++i) nearly[i] = static_cast<uint8_t>(100 + i % 2);
    REQUIRE((score(p, flat).flat && score(p, flat).q15 == 0));
    REQUIRE((score(flat, flat).flat && score(flat, flat).q15 == 0));
    REQUIRE((score(nearly, p).flat && score(nearly, p).q15 == 0));
    REQUIRE(score(nearly, nearly, 0).q15 == 32767);  // no floor: tiny variance still correlates
    REQUIRE(score(flat, flat, 0).flat);              // zero variance is always flat
    // Threshold: variance exactly min_variance is not flat (n·Σa² − (Σa)² = n²·4 for ±2).
    std::vector<uint8_t> pm2(64);
    for (size_t i = 0; i < 64; ++i) pm2[i] = static_cast<uint8_t>(i % 2 ? 102 : 98);
    REQUIRE_FALSE(ncc_q15(pm2.data(), 8, pm2.data(), 8, 8, 8, 4).flat);
    REQUIRE(ncc_q15(pm2.data(), 8, pm2.data(), 8, 8, 8, 5).flat);
    // Sizes: 0 and over kNccMaxPixels give no score; 32×32 is allowed.
    std::vector<uint8_t> big(33 * 32);
    for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<uint8_t>(rng.below(256));
    REQUIRE(ncc_q15(big.data(), 33, big.data(), 33, 33, 32).flat);
    REQUIRE(ncc_q15(big.data(), 33, big.data(), 33, 0, 32).flat);
    REQUIRE(ncc_q15(big.data(), 33, big.data(), 33, 32, 32).q15 == 32767);
    // Sums no block gives: refused or saturated, never undefined.
    NccSums s;
    s.n = 4;
    s.sa = s.sb = 200;
    s.saa = s.sbb = 20000;
    s.sab = 5000000;  // above 4·255²
    REQUIRE(ncc_from_sums(s).flat);
    s.sab = 260000;  // within bounds but |ncc| > 1
    REQUIRE(ncc_from_sums(s).q15 == 32767);
    s.sab = 0;
    REQUIRE(ncc_from_sums(s).q15 == -32768);
}

TEST_CASE("Matching a textured frame to itself shifted recovers the shift exactly", "[ncc]") {
    const std::vector<uint8_t> world = noise_texture(240, 180, 11);
    const int w = 160, h = 120;
    for (const auto& shift : {std::pair<int, int>{7, -4}, {-3, 5}, {0, 0}, {30, 12}}) {
        const int dx = shift.first, dy = shift.second;
        // cur(x, y) = prev(x − dx, y − dy): the content moves by (dx, dy).
        const auto prev_im = crop(world, 240, 40, 30, w, h);
        const auto cur_im = crop(world, 240, 40 - dx, 30 - dy, w, h);
        static FeatureSet<4, 96> prev, cur;
        features(prev_im, w, h, prev);
        features(cur_im, w, h, cur);
        REQUIRE(prev.count >= 60);
        MatchParams c;
        if (std::abs(dx) > 24) {  // beyond the search radius: the offset brings it back
            c.offset_x = static_cast<int16_t>(dx);
            c.offset_y = static_cast<int16_t>(dy);
            c.search_radius_px = 8;
        }
        FeatureMatch m[96];
        MatchStats st;
        const uint16_t n = match_features(prev, cur, c, m, 96, &st);
        INFO("shift " << dx << "," << dy << ": " << n << " of " << prev.count << " matched");
        REQUIRE(n >= 30);
        REQUIRE(sum_of(st, n) == prev.count);
        for (uint16_t k = 0; k < n; ++k) {
            const Feature<4>& a = prev.items[m[k].prev];
            const Feature<4>& b = cur.items[m[k].cur];
            REQUIRE(b.px - a.px == dx);
            REQUIRE(b.py - a.py == dy);
            REQUIRE(b.x_q8 - a.x_q8 == dx * 256);
            REQUIRE(b.y_q8 - a.y_q8 == dy * 256);
            REQUIRE(m[k].score_q15 == ncc_q15(a.patch, 9, b.patch, 9, 9, 9).q15);
            REQUIRE(m[k].score_q15 >= c.min_score_q15);
            if (k > 0) REQUIRE(m[k].prev > m[k - 1].prev);
        }
        // Capacity: the first matches in prev order, the rest counted.
        FeatureMatch few[5];
        MatchStats st5;
        REQUIRE(match_features(prev, cur, c, few, 5, &st5) == 5);
        REQUIRE(st5.dropped_capacity == n - 5);
        for (int k = 0; k < 5; ++k) REQUIRE((few[k].prev == m[k].prev && few[k].cur == m[k].cur));
    }
}

TEST_CASE("Matching refuses a repeated pattern by the margin check", "[ncc]") {
    // The same asymmetric motif every 16 px, lit differently in each cell (NCC ignores that).
    const int w = 128, h = 96, period = 16;
    auto render = [&](int dx) {
        std::vector<uint8_t> im(static_cast<size_t>(w * h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int u = ((x - dx) % period + period) % period, v = y % period;
                const int cell = ((x - dx) / period + y / period) % 3;
                const bool on =
                    (u >= 4 && u < 10 && v >= 4 && v < 7) || (u >= 4 && u < 7 && v >= 4 && v < 12);
                im[static_cast<size_t>(y * w + x)] =
                    static_cast<uint8_t>(on ? 150 + 30 * cell : 60);
            }
        return im;
    };
    static FeatureSet<4, 96> prev, cur;
    features(render(0), w, h, prev);
    features(render(3), w, h, cur);
    REQUIRE(prev.count >= 20);
    FeatureMatch m[96];
    MatchStats st;
    const uint16_t n = match_features(prev, cur, MatchParams{}, m, 96, &st);
    REQUIRE(st.ambiguous >= prev.count / 2);
    for (uint16_t k = 0; k < n; ++k)
        REQUIRE(cur.items[m[k].cur].px - prev.items[m[k].prev].px == 3);
    // Without the margin and mutual checks the first of the equal candidates wins: wrong pairs.
    MatchParams loose;
    loose.min_margin_q15 = 0;
    loose.mutual = false;
    const uint16_t n_loose = match_features(prev, cur, loose, m, 96);
    int wrong = 0;
    for (uint16_t k = 0; k < n_loose; ++k)
        wrong += cur.items[m[k].cur].px - prev.items[m[k].prev].px != 3;
    REQUIRE(wrong > 0);
}

TEST_CASE("Matching: mutual check, flat patches, thresholds", "[ncc]") {
    Pcg32 rng(5);
    std::vector<uint8_t> p(81), q(81), r(81), flat(81, 77);
    for (size_t i = 0; i < 81; ++i) {
        p[i] = static_cast<uint8_t>(rng.below(256));
        q[i] = clamp8(p[i] + static_cast<int>(rng.below(41)) - 20);  // p plus noise
        r[i] = static_cast<uint8_t>(rng.below(256));                 // unrelated
    }
    static FeatureSet<4, 8> prev, cur;
    // prev: p at (20,20), q at (24,20), flat at (30,30), r at (60,60) (nothing near it).
    prev.count = 4;
    prev.items[0] = patch_feature(20, 20, p);
    prev.items[1] = patch_feature(24, 20, q);
    prev.items[2] = patch_feature(30, 30, flat);
    prev.items[3] = patch_feature(60, 60, r);
    // cur: p at (21,20) and r far from every prev corner but prev 3's window edge (+25 px).
    cur.count = 2;
    cur.items[0] = patch_feature(21, 20, p);
    cur.items[1] = patch_feature(85, 60, r);
    FeatureMatch m[8];
    MatchStats st;
    MatchParams c;
    c.min_score_q15 = 16384;
    REQUIRE(match_features(prev, cur, c, m, 8, &st) == 1);
    REQUIRE((m[0].prev == 0 && m[0].cur == 0 && m[0].score_q15 == 32767));
    REQUIRE(st.not_mutual == 1);    // prev 1's best is cur 0, whose best is prev 0
    REQUIRE(st.flat == 1);          // prev 2
    REQUIRE(st.no_candidate == 1);  // prev 3: cur 1 is 25 px away
    REQUIRE(st.scored == 2);
    c.mutual = false;
    REQUIRE(match_features(prev, cur, c, m, 8, &st) == 2);
    REQUIRE((m[1].prev == 1 && m[1].cur == 0));
    c.search_radius_px = 25;
    REQUIRE(match_features(prev, cur, c, m, 8, &st) == 3);
    REQUIRE((m[2].prev == 3 && m[2].cur == 1));
    c.min_score_q15 = 32767;
    REQUIRE(match_features(prev, cur, c, m, 8, &st) == 2);  // q's score is below 1
    REQUIRE(st.below_min == 1);
    REQUIRE(match_features(prev, cur, c, m, 8) == 2);  // stats optional
}
