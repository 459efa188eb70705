// Plane-to-plane homographies (the Filtering and Geometry paper §II-A, equations (1)-(5), (7),
// Table I step 3) in single-precision float: Hartley-normalised 4-point solver (8×8 Gaussian
// elimination, h9 = 1), RANSAC with an adaptive iteration count, normalised DLT refit (9×9 normal
// matrix, cyclic Jacobi), Sampson error. See homography.h for the contract.
//
// Determinism: only +, −, ×, ÷, sqrtf, fabsf, comparisons and integer operations, in a fixed
// order, compiled with -ffp-contract=off: IEEE-754 single precision rounds each of them alike on
// x86-64 (SSE), aarch64 and Cortex-M4F, so the same pairs and seed give the same bits. The one
// transcendental function, the natural log of the iteration count, is ours (ln_unit below).
//
// A fixed-point build would have to change:
//  - normalisation: the per-point sqrtf of the mean distance and the reciprocal √2/mean become
//    isqrt (isqrt.h) and one Q-format reciprocal; normalised coordinates fit Q3.28;
//  - the 8×8 elimination: pivot divisions and the multipliers need a reciprocal per column and
//    64-bit products (wide_mul.h); pivots span ~10⁶, so Q-formats per column or block floating;
//  - the 9×9 normal matrix: sums over n pairs of products of normalised coordinates grow with n
//    (Q2.28² × 65535) and need 64-bit accumulators; its smallest eigenvalue is ~10⁻⁵ of its
//    largest at 0.5 px noise, so ≥ 40 significant bits;
//  - the Jacobi eigen-solve: τ, t = 1/(|τ| + √(τ²+1)), c, s need a divide and a sqrt per
//    rotation (or CORDIC, angle.h, giving c and s from atan2(2a_pq, a_qq − a_pp) directly);
//  - the division by w' in apply/transfer error and the Sampson error's division by det(JJᵀ)
//    (which spans w⁴): reciprocals with range checks in place of the float guards;
//  - the log in the iteration count: N(w) depends only on the inlier count, so a table of
//    thresholds on the count (or a fixed-point log2 by leading-zero count + table) replaces it.
#include "target/float/homography.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "base/prng.h"

namespace qt {

namespace {

// "~0 relative to the scale": a value whose magnitude is below this fraction of the magnitudes
// it was computed from is at the level of a few float roundings (eps = 6e-8) of them.
constexpr float kRelEps = 1e-6f;
// A triple of sample points is collinear when the sine of its smallest angle is below this
// (0.02 ≈ 1.1°): such samples give ill-conditioned 4-point homographies.
constexpr float kSampleMinSin = 0.02f;
// The 8×8 elimination refuses a pivot below this fraction of the largest entry of the matrix
// (normalised coordinates: entries O(1)).
constexpr float kPivotRel = 1e-6f;
// The refit's null space must be one-dimensional: the second smallest eigenvalue of AᵀA at
// least this fraction of its trace (collinear inliers give two tiny ones).
constexpr float kRankRel = 1e-6f;
constexpr int kJacobiMaxSweeps = 16;
// Up to this many refit rounds (refit on the inliers, recount, refit on the new inliers...).
constexpr int kRefitRounds = 2;
constexpr float kSqrt2 = 1.41421356f;
constexpr float kLn2 = 0.693147182f;  // ln 2 rounded to float

bool finite(float v) { return fabsf(v) <= FLT_MAX; }  // false for NaN and ±inf

bool all_finite(const float* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!finite(v[i])) return false;
    return true;
}

// Divides m by m[8]; false (m untouched) when m[8] is ~0 relative to the largest entry or
// anything is not finite.
bool scale_to_h9(float m[9]) {
    if (!all_finite(m, 9)) return false;
    float big = 0;
    for (int i = 0; i < 9; ++i) big = fabsf(m[i]) > big ? fabsf(m[i]) : big;
    if (!(fabsf(m[8]) > kRelEps * big)) return false;
    const float inv = 1.0f / m[8];
    float r[9];
    for (int i = 0; i < 8; ++i) r[i] = m[i] * inv;
    r[8] = 1.0f;
    if (!all_finite(r, 9)) return false;
    for (int i = 0; i < 9; ++i) m[i] = r[i];
    return true;
}

// Natural log of x for 0 < x <= 1 and x normal (x >= FLT_MIN), from +, −, ×, ÷ and the bits of
// x: x = 2^e·m with m in [√½, √2), ln x = e·ln 2 + 2·atanh(s), s = (m−1)/(m+1), |s| <= 0.1716,
// atanh by its series to s⁹ (truncation below 2·s¹¹/11 = 7e-10). Measured against double log
// over every float in [2⁻²⁴, 1]: absolute error <= 1.5e-6, relative <= 2.1e-7 (2 ulp), so
// N = log(1−c)/log(1−w⁴) is within ~5e-7 relative of the double formula before it is rounded
// up (tests/target/test_homography.cpp compares the rounded N).
float ln_unit(float x) {
    uint32_t bits = 0;
    memcpy(&bits, &x, sizeof bits);
    int32_t e = static_cast<int32_t>((bits >> 23) & 0xffu) - 127;
    bits = (bits & 0x007fffffu) | 0x3f800000u;  // mantissa with exponent 0: m in [1, 2)
    float m = 0;
    memcpy(&m, &bits, sizeof m);
    if (m > kSqrt2) {
        m *= 0.5f;
        e += 1;
    }
    const float s = (m - 1.0f) / (m + 1.0f);
    const float s2 = s * s;
    const float series =
        s *
        (2.0f + s2 * (2.0f / 3.0f + s2 * (2.0f / 5.0f + s2 * (2.0f / 7.0f + s2 * (2.0f / 9.0f)))));
    return static_cast<float>(e) * kLn2 + series;
}

// Which pairs an accumulation takes: those whose mask byte is non-zero, or (mask null, h set)
// those within sqrt(thr2) px of h by transfer error, or (both null) all of them. Deciding by a
// predicate rather than a stored mask keeps RANSAC free of an n-byte buffer.
struct Selector {
    const uint8_t* mask = nullptr;
    const Homography* h = nullptr;
    float thr2 = 0;
    bool take(const PointPair* pairs, uint16_t i) const {
        if (mask) return mask[i] != 0;
        if (h) return transfer_error_sq(*h, pairs[i]) <= thr2;
        return true;
    }
};

// Hartley normalisation of one point set: x̃ = s·(x − cx), centroid to the origin and mean
// distance √2.
struct Norm {
    float cx = 0, cy = 0, s = 1;
};

// Both point sets' normalisations over the selected pairs; count gets how many were taken.
// False when fewer than 1 or a set's points all coincide.
bool normalise(const PointPair* pairs, uint16_t n, const Selector& sel, Norm& na, Norm& nb,
               uint32_t& count) {
    float sax = 0, say = 0, sbx = 0, sby = 0;
    uint32_t k = 0;
    for (uint16_t i = 0; i < n; ++i) {
        if (!sel.take(pairs, i)) continue;
        sax += pairs[i].ax;
        say += pairs[i].ay;
        sbx += pairs[i].bx;
        sby += pairs[i].by;
        ++k;
    }
    count = k;
    if (k == 0) return false;
    const float inv_k = 1.0f / static_cast<float>(k);
    na.cx = sax * inv_k;
    na.cy = say * inv_k;
    nb.cx = sbx * inv_k;
    nb.cy = sby * inv_k;
    float da = 0, db = 0;  // sums of distances to the centroids, px
    for (uint16_t i = 0; i < n; ++i) {
        if (!sel.take(pairs, i)) continue;
        const float ax = pairs[i].ax - na.cx, ay = pairs[i].ay - na.cy;
        const float bx = pairs[i].bx - nb.cx, by = pairs[i].by - nb.cy;
        da += sqrtf(ax * ax + ay * ay);
        db += sqrtf(bx * bx + by * by);
    }
    if (!(da > 0) || !(db > 0)) return false;  // also refuses NaN
    na.s = kSqrt2 * static_cast<float>(k) / da;
    nb.s = kSqrt2 * static_cast<float>(k) / db;
    return finite(na.cx) && finite(na.cy) && finite(nb.cx) && finite(nb.cy) && finite(na.s) &&
           finite(nb.s) && na.s > 0 && nb.s > 0;
}

// H = Tb⁻¹ · H̃ · Ta for H̃ between normalised coordinates, Ta = [sa 0 −sa·cax; 0 sa −sa·cay;
// 0 0 1], Tb⁻¹ = [1/sb 0 cbx; 0 1/sb cby; 0 0 1]; then scaled to m[8] == 1.
bool denormalise(const float ht[9], const Norm& na, const Norm& nb, Homography& out) {
    float m[9];  // H̃ · Ta
    for (int r = 0; r < 3; ++r) {
        const float h0 = ht[3 * r], h1 = ht[3 * r + 1], h2 = ht[3 * r + 2];
        m[3 * r] = h0 * na.s;
        m[3 * r + 1] = h1 * na.s;
        m[3 * r + 2] = h2 - (h0 * na.s * na.cx + h1 * na.s * na.cy);
    }
    const float inv_sb = 1.0f / nb.s;
    float h[9];
    for (int c = 0; c < 3; ++c) {
        h[c] = m[c] * inv_sb + nb.cx * m[6 + c];
        h[3 + c] = m[3 + c] * inv_sb + nb.cy * m[6 + c];
        h[6 + c] = m[6 + c];
    }
    if (!scale_to_h9(h)) return false;
    for (int i = 0; i < 9; ++i) out.m[i] = h[i];
    return true;
}

// Every triple of the four points, collinear?
bool has_collinear_triple(const float x[4], const float y[4]) {
    static const uint8_t kTriples[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    for (const auto& t : kTriples)
        if (nearly_collinear(x[t[0]], y[t[0]], x[t[1]], y[t[1]], x[t[2]], y[t[2]], kSampleMinSin))
            return true;
    return false;
}

// Cyclic Jacobi on the symmetric 9×9 a (destroyed: its diagonal becomes the eigenvalues);
// v gets the eigenvectors as columns. Rotation as Golub & Van Loan, sym.schur2, with the
// (p, q) entry set to 0 explicitly; a rotation is skipped when |a_pq| is below 1e-9 of
// |a_pp| + |a_qq| (its effect on the eigenvectors below 1e-9). Stops after a sweep without a
// rotation or after kJacobiMaxSweeps (the float noise floor can keep tiny rotations going; the
// eigenvectors are then converged to rounding).
void jacobi9(float a[9][9], float v[9][9]) {
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) v[i][j] = i == j ? 1.0f : 0.0f;
    for (int sweep = 0; sweep < kJacobiMaxSweeps; ++sweep) {
        bool rotated = false;
        for (int p = 0; p < 8; ++p) {
            for (int q = p + 1; q < 9; ++q) {
                const float apq = a[p][q];
                const float app = a[p][p], aqq = a[q][q];
                if (!(fabsf(apq) > 1e-9f * (fabsf(app) + fabsf(aqq)))) continue;
                rotated = true;
                const float tau = (aqq - app) / (2.0f * apq);
                // τ² overflows to inf for |τ| > 1.8e19: t = 1/inf = 0, a null rotation, no NaN.
                const float t = (tau >= 0 ? 1.0f : -1.0f) / (fabsf(tau) + sqrtf(tau * tau + 1.0f));
                const float c = 1.0f / sqrtf(t * t + 1.0f);
                const float s = t * c;
                for (int k = 0; k < 9; ++k) {
                    if (k == p || k == q) continue;
                    const float akp = a[k][p], akq = a[k][q];
                    a[k][p] = a[p][k] = c * akp - s * akq;
                    a[k][q] = a[q][k] = s * akp + c * akq;
                }
                a[p][p] = app - t * apq;
                a[q][q] = aqq + t * apq;
                a[p][q] = a[q][p] = 0;
                for (int k = 0; k < 9; ++k) {
                    const float vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
        }
        if (!rotated) break;
    }
}

// The normalised DLT on the selected pairs (the body of refit_homography).
bool refit_selected(const PointPair* pairs, uint16_t n, const Selector& sel, Homography& out) {
    Norm na, nb;
    uint32_t count = 0;
    if (!normalise(pairs, n, sel, na, nb, count) || count < 4) return false;
    // Equation (4)'s two independent rows for x̃ = (x, y, 1), x̃' = (x', y', 1):
    //   r1 = [0ᵀ, −x̃ᵀ, y'·x̃ᵀ],  r2 = [x̃ᵀ, 0ᵀ, −x'·x̃ᵀ].
    // With X = x̃x̃ᵀ, r1r1ᵀ + r2r2ᵀ = [[X, 0, −x'X], [0, X, −y'X], [−x'X, −y'X, (x'²+y'²)X]],
    // so AᵀA needs only the sums of X, x'X, y'X and (x'²+y'²)X (6 distinct entries each).
    float sx[6] = {}, sxx[6] = {}, sxy[6] = {}, sxr[6] = {};  // xx, xy, x, yy, y, 1
    for (uint16_t i = 0; i < n; ++i) {
        if (!sel.take(pairs, i)) continue;
        const float x = na.s * (pairs[i].ax - na.cx), y = na.s * (pairs[i].ay - na.cy);
        const float xp = nb.s * (pairs[i].bx - nb.cx), yp = nb.s * (pairs[i].by - nb.cy);
        const float r2 = xp * xp + yp * yp;
        const float e[6] = {x * x, x * y, x, y * y, y, 1.0f};
        for (int k = 0; k < 6; ++k) {
            sx[k] += e[k];
            sxx[k] += xp * e[k];
            sxy[k] += yp * e[k];
            sxr[k] += r2 * e[k];
        }
    }
    // Expand a 6-entry symmetric 3×3 sum into block (bi, bj) of AᵀA with sign sg.
    static const uint8_t kSym[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    float a[9][9] = {};
    auto put = [&](int bi, int bj, const float* s6, float sg) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                a[3 * bi + i][3 * bj + j] = sg * s6[kSym[i][j]];
                a[3 * bj + j][3 * bi + i] = sg * s6[kSym[i][j]];
            }
    };
    put(0, 0, sx, 1.0f);
    put(1, 1, sx, 1.0f);
    put(0, 2, sxx, -1.0f);
    put(1, 2, sxy, -1.0f);
    put(2, 2, sxr, 1.0f);
    float trace = 0;
    for (int i = 0; i < 9; ++i) trace += a[i][i];
    if (!finite(trace) || !(trace > 0)) return false;
    float v[9][9];
    jacobi9(a, v);
    int k1 = 0;  // smallest eigenvalue
    for (int i = 1; i < 9; ++i)
        if (a[i][i] < a[k1][k1]) k1 = i;
    float second = FLT_MAX;
    for (int i = 0; i < 9; ++i)
        if (i != k1 && a[i][i] < second) second = a[i][i];
    if (!(second > kRankRel * trace)) return false;  // null space of dimension >= 2
    float ht[9];
    for (int i = 0; i < 9; ++i) ht[i] = v[i][k1];
    return denormalise(ht, na, nb, out);
}

// Inliers of h (transfer error <= thr2, px²) and the sum of their squared transfer errors, px².
// Stops early (returning a count below `beat`) once fewer than `beat` remain reachable.
uint32_t count_inliers(const Homography& h, const PointPair* pairs, uint16_t n, float thr2,
                       uint32_t beat, float& err_sum) {
    uint32_t count = 0;
    float sum = 0;
    for (uint16_t i = 0; i < n; ++i) {
        if (count + static_cast<uint32_t>(n - i) < beat) break;
        const float e = transfer_error_sq(h, pairs[i]);
        if (e <= thr2) {
            ++count;
            sum += e;
        }
    }
    err_sum = sum;
    return count;
}

// N = log(1 − c) / log(1 − w⁴), w = inliers / n, rounded up and capped at max_it. ln_1mc is
// log(1 − c) (<= 0), or a positive value for "never adapt" (c >= 1 or not a number).
uint16_t adaptive_limit(uint32_t inliers, uint32_t n, float ln_1mc, uint16_t max_it) {
    if (inliers == 0 || n == 0 || ln_1mc > 0) return max_it;
    const float w = static_cast<float>(inliers) / static_cast<float>(n);
    const float p = w * w * w * w;   // probability that a sample of 4 is all inliers
    if (!(p < 1.0f)) return 0;       // every pair an inlier: no better sample exists
    const float q = 1.0f - p;        // in [2⁻²⁴, 1]: p < 1 is a float below 1
    if (!(q < 1.0f)) return max_it;  // p below float resolution: no bound
    const float denom = ln_unit(q);  // < 0
    if (!(denom < 0)) return max_it;
    const float nf = ln_1mc / denom;  // >= 0
    if (!(nf < static_cast<float>(max_it))) return max_it;
    uint16_t it = static_cast<uint16_t>(nf);  // 0 <= nf < 65535: truncation is defined
    if (static_cast<float>(it) < nf) ++it;
    return it;
}

// log(1 − c): c <= 0 → 0 (stop at the first hypothesis); c >= 1 or NaN → 1, "never adapt".
float ln_one_minus(float c) { return c < 1.0f ? (c > 0 ? ln_unit(1.0f - c) : 0.0f) : 1.0f; }

// A hypothesis and how it fits the pairs: inliers and their sum of squared transfer errors.
struct Hypothesis {
    Homography h;
    uint32_t count = 0;
    float err = FLT_MAX;
    bool better_than(const Hypothesis& o) const {
        return count > o.count || (count == o.count && err < o.err);
    }
};

// Four distinct indices below n, bounded time: the k-th is uniform over the n − k indices not
// yet drawn (below(n − k), then stepped over the drawn ones, kept sorted).
void draw_sample(Pcg32& rng, uint16_t n, uint16_t idx[4]) {
    for (uint16_t k = 0; k < 4; ++k) {
        uint16_t r = static_cast<uint16_t>(rng.below(static_cast<uint32_t>(n - k)));
        uint16_t j = 0;
        for (; j < k && r >= idx[j]; ++j) ++r;  // idx[0..k) ascending
        for (uint16_t m = k; m > j; --m) idx[m] = idx[m - 1];
        idx[j] = r;
    }
}

// RANSAC's hypotheses until the adaptive count: the best 4-point homography, false when every
// sample was degenerate. iterations: the hypotheses drawn.
bool best_hypothesis(const PointPair* pairs, uint16_t n, const RansacParams& config, float thr2,
                     Hypothesis& best, uint16_t& iterations) {
    const float ln_1mc = ln_one_minus(config.confidence);
    Pcg32 rng(config.seed);
    bool have = false;
    uint16_t limit = config.max_iterations;
    uint16_t it = 0;
    while (it < limit) {
        ++it;
        uint16_t idx[4] = {};
        draw_sample(rng, n, idx);
        const PointPair sample[4] = {pairs[idx[0]], pairs[idx[1]], pairs[idx[2]], pairs[idx[3]]};
        Hypothesis c;
        if (!homography_from_4(sample, c.h)) continue;  // degenerate samples count as iterations
        c.count = count_inliers(c.h, pairs, n, thr2, have ? best.count : 0, c.err);
        if (have && !c.better_than(best)) continue;
        const bool more = !have || c.count > best.count;
        have = true;
        best = c;
        if (more) {
            const uint16_t lim = adaptive_limit(c.count, n, ln_1mc, config.max_iterations);
            limit = lim < limit ? lim : limit;
        }
    }
    iterations = it;
    return have;
}

// Refit on the inliers, recount under the refit, and refit again on the new set; a round's H
// replaces the current one only when it fits better (so a refit pulled off by borderline points
// is not taken; if no refit is better, or it is degenerate, the 4-point hypothesis stays).
Hypothesis refined(const PointPair* pairs, uint16_t n, float thr2, Hypothesis cur) {
    for (int round = 0; round < kRefitRounds; ++round) {
        Selector sel;
        sel.h = &cur.h;
        sel.thr2 = thr2;
        Hypothesis r;
        if (!refit_selected(pairs, n, sel, r.h)) break;
        r.count = count_inliers(r.h, pairs, n, thr2, 0, r.err);
        if (!r.better_than(cur)) break;
        cur = r;
    }
    return cur;
}

// Equation (7) for res.h: the RMS over its inliers (marked in inlier_mask), D_rep over every
// matched pair as the paper writes it, and the capped RMS the default gate reads.
void judge(const PointPair* pairs, uint16_t n, float thr2, uint8_t* inlier_mask,
           RansacResult& res) {
    float sum = 0;  // px²
    for (uint16_t i = 0; i < n; ++i) {
        if (!(transfer_error_sq(res.h, pairs[i]) <= thr2)) continue;
        if (inlier_mask) inlier_mask[i] = 1;
        sum += reprojection_error_sq(res.h, pairs[i]);
    }
    const float mean = sum / static_cast<float>(res.inliers);  // inliers >= min_inl >= 4
    res.reprojection_px = mean <= FLT_MAX ? sqrtf(mean) : FLT_MAX;
    const float cap = 4.0f * thr2;  // (2·inlier_px)²
    float all = 0, capped = 0;
    for (uint16_t i = 0; i < n; ++i) {
        const float e = reprojection_error_sq(res.h, pairs[i]);  // >= 0, FLT_MAX at most
        all = all + e <= FLT_MAX ? all + e : FLT_MAX;
        capped += e < cap ? e : cap;
    }
    res.d_rep = all;
    const float capped_mean = capped / static_cast<float>(n);
    res.d_rep_capped_px = capped_mean <= FLT_MAX ? sqrtf(capped_mean) : FLT_MAX;
}

}  // namespace

bool nearly_collinear(float x0, float y0, float x1, float y1, float x2, float y2, float min_sin) {
    const float ux = x1 - x0, uy = y1 - y0, vx = x2 - x0, vy = y2 - y0;
    const float wx = x2 - x1, wy = y2 - y1;
    const float cross = ux * vy - uy * vx;  // twice the signed area, px²
    // The two longest sides enclose the smallest angle θ: |cross| = |s1|·|s2|·sin θ whichever
    // vertex is taken, so the test does not depend on the order of the points.
    float l[3] = {ux * ux + uy * uy, vx * vx + vy * vy, wx * wx + wy * wy};  // px²
    // Drop the shortest.
    int shortest = 0;
    if (l[1] < l[shortest]) shortest = 1;
    if (l[2] < l[shortest]) shortest = 2;
    float prod = 1.0f;
    for (int i = 0; i < 3; ++i)
        if (i != shortest) prod *= l[i];
    // Written as !(>) so that NaN coordinates count as collinear (refused by the solvers).
    return !(cross * cross > min_sin * min_sin * prod);
}

bool apply_homography(const Homography& h, float x, float y, float& xo, float& yo) {
    const float* m = h.m;
    const float w = m[6] * x + m[7] * y + m[8];
    const float wscale = fabsf(m[6] * x) + fabsf(m[7] * y) + fabsf(m[8]);
    if (!(w > kRelEps * wscale)) return false;  // at or behind infinity, or NaN
    const float u = (m[0] * x + m[1] * y + m[2]) / w;
    const float v = (m[3] * x + m[4] * y + m[5]) / w;
    if (!finite(u) || !finite(v)) return false;
    xo = u;
    yo = v;
    return true;
}

bool multiply_homographies(const Homography& a, const Homography& b, Homography& out) {
    float m[9];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m[3 * r + c] =
                a.m[3 * r] * b.m[c] + a.m[3 * r + 1] * b.m[3 + c] + a.m[3 * r + 2] * b.m[6 + c];
    if (!scale_to_h9(m)) return false;
    for (int i = 0; i < 9; ++i) out.m[i] = m[i];
    return true;
}

bool invert_homography(const Homography& h, Homography& out) {
    const float* m = h.m;
    // Adjugate (transposed cofactors); H⁻¹ = adj / det, and the scale drops out at m[8] = 1.
    float adj[9] = {
        m[4] * m[8] - m[5] * m[7], m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
        m[5] * m[6] - m[3] * m[8], m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
        m[3] * m[7] - m[4] * m[6], m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3],
    };
    // det by the first row, compared with the magnitude of its terms (a pixel homography's
    // entries differ by orders of magnitude, so a bound on max|m|³ would refuse translations).
    const float t0 = m[0] * adj[0], t1 = m[1] * adj[3], t2 = m[2] * adj[6];
    const float det = t0 + t1 + t2;
    if (!(fabsf(det) > kRelEps * (fabsf(t0) + fabsf(t1) + fabsf(t2)))) return false;
    if (!scale_to_h9(adj)) return false;
    for (int i = 0; i < 9; ++i) out.m[i] = adj[i];
    return true;
}

bool homography_from_4(const PointPair pairs[4], Homography& out) {
    float ax[4], ay[4], bx[4], by[4];
    for (int i = 0; i < 4; ++i) {
        ax[i] = pairs[i].ax;
        ay[i] = pairs[i].ay;
        bx[i] = pairs[i].bx;
        by[i] = pairs[i].by;
    }
    if (has_collinear_triple(ax, ay) || has_collinear_triple(bx, by)) return false;
    Norm na, nb;
    uint32_t count = 0;
    if (!normalise(pairs, 4, Selector{}, na, nb, count)) return false;
    // h9 = 1 in normalised coordinates: h9 = 0 would mean that the centroid of the four A points
    // maps to infinity, i.e. the horizon of B passes through the middle of a sample whose four
    // images are finite: two of them would be seen from behind, which no camera pair produces.
    // Near that case the system is singular and the pivot test refuses it. An 8×8 solve costs
    // far less than a null vector of the 8×9 system (SVD or eigen-solve) per hypothesis.
    //   x' = (h1 x + h2 y + h3) / (h7 x + h8 y + 1)  →  h1 x + h2 y + h3 − h7 x x' − h8 y x' = x'
    float a[8][9];
    float big = 0;
    for (int i = 0; i < 4; ++i) {
        const float x = na.s * (ax[i] - na.cx), y = na.s * (ay[i] - na.cy);
        const float xp = nb.s * (bx[i] - nb.cx), yp = nb.s * (by[i] - nb.cy);
        const float r1[9] = {x, y, 1.0f, 0, 0, 0, -x * xp, -y * xp, xp};
        const float r2[9] = {0, 0, 0, x, y, 1.0f, -x * yp, -y * yp, yp};
        for (int k = 0; k < 9; ++k) {
            a[2 * i][k] = r1[k];
            a[2 * i + 1][k] = r2[k];
            if (k < 8) {
                big = fabsf(r1[k]) > big ? fabsf(r1[k]) : big;
                big = fabsf(r2[k]) > big ? fabsf(r2[k]) : big;
            }
        }
    }
    // Gaussian elimination with partial pivoting, then back substitution.
    for (int c = 0; c < 8; ++c) {
        int piv = c;
        for (int r = c + 1; r < 8; ++r)
            if (fabsf(a[r][c]) > fabsf(a[piv][c])) piv = r;
        if (!(fabsf(a[piv][c]) > kPivotRel * big)) return false;  // singular (or NaN)
        if (piv != c)
            for (int k = c; k < 9; ++k) {
                const float t = a[c][k];
                a[c][k] = a[piv][k];
                a[piv][k] = t;
            }
        const float inv = 1.0f / a[c][c];
        for (int r = c + 1; r < 8; ++r) {
            const float f = a[r][c] * inv;
            for (int k = c; k < 9; ++k) a[r][k] -= f * a[c][k];
        }
    }
    float ht[9];
    for (int r = 7; r >= 0; --r) {
        float s = a[r][8];
        for (int k = r + 1; k < 8; ++k) s -= a[r][k] * ht[k];
        ht[r] = s / a[r][r];
    }
    ht[8] = 1.0f;
    return denormalise(ht, na, nb, out);
}

float transfer_error_sq(const Homography& h, const PointPair& p) {
    float x = 0, y = 0;
    if (!apply_homography(h, p.ax, p.ay, x, y)) return FLT_MAX;
    const float dx = x - p.bx, dy = y - p.by;
    const float e = dx * dx + dy * dy;
    return e <= FLT_MAX ? e : FLT_MAX;  // overflow (or NaN from NaN input) → never an inlier
}

float reprojection_error_sq(const Homography& h, const PointPair& p) {
    // Sampson's first-order approximation of min over x̂ of |x − x̂|² + |x' − H x̂|²
    // (Hartley & Zisserman §4.2.6): ε = algebraic residual of equation (4)'s two rows with
    // w' = 1, J = ∂ε/∂(ax, ay, bx, by), error = εᵀ (J Jᵀ)⁻¹ ε. Invariant to the scale of H.
    const float* m = h.m;
    const float u = m[0] * p.ax + m[1] * p.ay + m[2];
    const float v = m[3] * p.ax + m[4] * p.ay + m[5];
    const float w = m[6] * p.ax + m[7] * p.ay + m[8];
    // A point at or behind infinity, as apply_homography refuses it: no correspondence.
    if (!(w > kRelEps * (fabsf(m[6] * p.ax) + fabsf(m[7] * p.ay) + fabsf(m[8])))) return FLT_MAX;
    const float e1 = p.by * w - v;  // row 1: −h2ᵀx + y'·h3ᵀx
    const float e2 = u - p.bx * w;  // row 2:  h1ᵀx − x'·h3ᵀx
    // J = [[pa, ra, 0, w], [qa, sa, −w, 0]]
    const float pa = p.by * m[6] - m[3], ra = p.by * m[7] - m[4];
    const float qa = m[0] - p.bx * m[6], sa = m[1] - p.bx * m[7];
    const float j11 = pa * pa + ra * ra + w * w;
    const float j22 = qa * qa + sa * sa + w * w;
    const float j12 = pa * qa + ra * sa;
    // det(JJᵀ) by Cauchy-Binet, a sum of squares (>= w⁴), so never negative by rounding.
    const float minor = pa * sa - ra * qa;
    const float det =
        minor * minor + w * w * (pa * pa + qa * qa + ra * ra + sa * sa) + w * w * w * w;
    if (!(det > 0) || !finite(det)) return FLT_MAX;  // overflow
    const float num = j22 * e1 * e1 - 2.0f * j12 * e1 * e2 + j11 * e2 * e2;
    const float r = num / det;
    if (!(r >= 0)) return r < 0 ? 0.0f : FLT_MAX;  // rounding below 0, or NaN
    return r <= FLT_MAX ? r : FLT_MAX;
}

uint16_t ransac_iterations_needed(uint32_t inliers, uint32_t n, float confidence,
                                  uint16_t max_iterations) {
    if (inliers > n) inliers = n;
    return adaptive_limit(inliers, n, ln_one_minus(confidence), max_iterations);
}

const char* homography_status_name(HomographyStatus s) {
    switch (s) {
        case HomographyStatus::ok: return "ok";
        case HomographyStatus::too_few_pairs: return "too_few_pairs";
        case HomographyStatus::degenerate: return "degenerate";
        case HomographyStatus::no_consensus: return "no_consensus";
    }
    return "unknown";
}

bool refit_homography(const PointPair* pairs, uint16_t n, const uint8_t* mask, Homography& out) {
    Selector sel;
    sel.mask = mask;
    return refit_selected(pairs, n, sel, out);
}

RansacResult estimate_homography(const PointPair* pairs, uint16_t n, const RansacParams& config,
                                 uint8_t* inlier_mask) {
    RansacResult res;
    if (inlier_mask)
        for (uint16_t i = 0; i < n; ++i) inlier_mask[i] = 0;
    const uint32_t min_inl = config.min_inliers > 4 ? config.min_inliers : 4u;
    if (!pairs || n < 4 || n < min_inl) return res;          // too_few_pairs
    const float thr2 = config.inlier_px * config.inlier_px;  // NaN or 0: nothing is an inlier
    Hypothesis best;
    if (!best_hypothesis(pairs, n, config, thr2, best, res.iterations)) {
        res.status = HomographyStatus::degenerate;
        return res;
    }
    if (best.count < min_inl) {
        res.status = HomographyStatus::no_consensus;
        res.inliers = static_cast<uint16_t>(best.count);  // the best hypothesis's, for diagnosis
        return res;
    }
    const Hypothesis cur = refined(pairs, n, thr2, best);
    res.status = HomographyStatus::ok;
    res.h = cur.h;
    res.inliers = static_cast<uint16_t>(cur.count);
    judge(pairs, n, thr2, inlier_mask, res);
    return res;
}

}  // namespace qt
