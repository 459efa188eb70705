// Plane-to-plane homographies (the Filtering and Geometry paper §II-A, equations (1)-(5), Table I
// step 3): a normalised 4-point solver for RANSAC hypotheses, RANSAC with an adaptive iteration
// count and the project's PRNG, a least-squares refit on the inliers, and the reprojection error of
// equation (7).
//
// Single-precision float: this stage is for parts with an FPU (Cortex-M4F/M7, ARM Linux,
// hosts). No double anywhere (the firmware link proves it: no __aeabi_d* helpers), no libm
// beyond sqrtf/fabsf (correctly rounded, so with -ffp-contract=off every platform gives the
// same bits).
#pragma once
#include <stdint.h>

#include "base/setting_range.h"

namespace qt {

// H maps homogeneous points of image A into image B: (x', y', w')ᵀ = H (x, y, 1)ᵀ, row-major
// m[0..8] = h1..h9 of equation (5). Scaled so that m[8] == 1 after every function here that
// returns one (a homography with h9 = 0 maps the origin to infinity; such an H is refused as
// degenerate by the solvers).
struct Homography {
    float m[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};

// One correspondence: (ax, ay) in image A and (bx, by) in image B, px.
struct PointPair {
    float ax = 0, ay = 0, bx = 0, by = 0;
};

// H·(x, y): false (and x', y' untouched) when the point maps to or behind infinity: w' <= 1e-6
// of |h7·x| + |h8·y| + |h9| (the magnitudes w' is summed from, so its sign is sure), or a
// result that is not finite. H is expected with h9 > 0 where the origin is in front (as every
// function here returns it).
bool apply_homography(const Homography& h, float x, float y, float& xo, float& yo);
// a·b: first b, then a (maps A→B with b, then B→C with a gives A→C). Rescaled to m[8] == 1;
// false when the product's m[8] is ~0.
bool multiply_homographies(const Homography& a, const Homography& b, Homography& out);
// H⁻¹ by the adjugate; false when |det| is ~0 relative to the entries' scale.
bool invert_homography(const Homography& h, Homography& out);

// The exact homography through four pairs after Hartley normalisation of each point set
// (centroid to the origin, mean distance √2), solved as an 8×8 linear system by Gaussian
// elimination with partial pivoting, h9 = 1 in normalised coordinates (homography.cpp says why).
// False when any three of the four points of either image are (nearly) collinear
// (nearly_collinear with min_sin = 0.02: the triangle's area below 1 % of its squared longest
// side) or the system is singular (a pivot below 1e-6 of the largest entry).
bool homography_from_4(const PointPair pairs[4], Homography& out);

// True when the three points are collinear within `min_sin`: |cross| <= min_sin·|u|·|v| with u, v
// the two longest sides, i.e. the sine of the triangle's smallest angle is at most min_sin
// (whatever the order of the points). Coincident points and NaN coordinates count as collinear.
// homography_from_4 uses min_sin = 0.02 (1.1°).
bool nearly_collinear(float x0, float y0, float x1, float y1, float x2, float y2, float min_sin);

// Equation (7)'s term for one pair, d(x, x̂)² + d(x', x̂')² minimised over x̂' = H x̂, to first
// order (the Sampson error), px². One-way transfer error |H a - b|², px², for the inlier test.
// Both return FLT_MAX (never NaN) when a maps to infinity under H.
float reprojection_error_sq(const Homography& h, const PointPair& p);
float transfer_error_sq(const Homography& h, const PointPair& p);

struct RansacParams {
    float inlier_px = 2.0f;          // an inlier's one-way transfer error |H a - b| <= this, px
    float confidence = 0.995f;       // stop when a better sample is this unlikely, 0 < c < 1
    uint16_t max_iterations = 1000;  // hypotheses tried at most (degenerate samples count)
    uint16_t min_inliers = 8;        // fewer: no_consensus (4 would fit any sample exactly)
    uint64_t seed = 1;  // Pcg32 seed: the same pairs and seed give the same H everywhere
};

// RansacParams' units and accepted ranges (base/setting_range.h).
struct RansacRanges {
    SettingRange inlier_px{"px", 5, 5000, 2};  // 0.05..50
    SettingRange max_iterations{"hypotheses", 1, 65535};
    SettingRange seed{"", 0, 2147483647};
};
inline constexpr RansacRanges kRansacRanges{};

enum class HomographyStatus : uint8_t {
    ok = 0,
    too_few_pairs,  // fewer than 4 pairs (or fewer than min_inliers)
    degenerate,     // no sample of 4 gave a usable hypothesis
    no_consensus,   // the best hypothesis has fewer than min_inliers inliers
};
// The status as one word ("ok", "too_few_pairs", ...), as the CLI's JSON writes it.
const char* homography_status_name(HomographyStatus s);

struct RansacResult {
    HomographyStatus status = HomographyStatus::too_few_pairs;
    Homography h;               // refitted on the inliers (identity unless status == ok)
    uint16_t inliers = 0;       // pairs within inlier_px of the refitted H (no_consensus: of the
                                // best 4-point hypothesis, for diagnosis)
    uint16_t iterations = 0;    // hypotheses drawn
    float reprojection_px = 0;  // sqrt of the mean of equation (7) over the inliers, px: at
                                // most ~inlier_px·√2 by construction, a diagnostic, not a gate
    // Equation (7) over every pair the homography is judged on (all n matched pairs, inliers or
    // not), the paper's D_rep: Σ of the Sampson error, px² (saturates at FLT_MAX). A wrong but
    // self-consistent H (a moving object dominating the matches, a repeated texture) leaves
    // the pairs it does not explain with large terms; RMS over the inliers cannot see them.
    float d_rep = 0;
    // The same terms each capped at (2·inlier_px)² before averaging over the n pairs, as an
    // RMS, px: one gross mismatch adds at most (2·inlier_px)²/n, so the gate measures the share
    // of pairs H fails to explain rather than how far the worst mismatch is.
    float d_rep_capped_px = 0;
};

// RANSAC over n pairs (n <= 65535): samples of 4 drawn by Pcg32(seed), samples with a
// collinear triple skipped, the iteration count adapted as N = log(1-c) / log(1-w⁴) from the
// best inlier ratio w, then a least-squares refit (normalised DLT: the 9×9 normal matrix AᵀA
// of equation (4)'s rows accumulated over the inliers, its eigenvector of the smallest
// eigenvalue by Jacobi rotations) and a final inlier count under the refitted H. The refit runs
// up to two rounds (refit, recount, refit on the new inliers); a round is kept only when it has
// more inliers, or as many with a smaller sum of squared transfer errors, else the previous H
// (at worst the best 4-point hypothesis) stays. Stack ~1.3 KB, no buffer of n: the inliers are
// re-derived from H whenever needed.
// inlier_mask (n bytes, may be null) gets 1 for an inlier, 0 otherwise (all 0 unless ok).
RansacResult estimate_homography(const PointPair* pairs, uint16_t n, const RansacParams& config,
                                 uint8_t* inlier_mask);

// The adaptive bound of the RANSAC loop: N = ⌈log(1−c) / log(1−w⁴)⌉ for w = inliers / n,
// capped at max_iterations; 0 when every pair is an inlier, max_iterations when inliers == 0,
// c >= 1 or w⁴ is below float resolution. The log is the float approximation of
// homography.cpp (relative error <= 2.1e-7 over [2⁻²⁴, 1]), so N is the double formula's except
// where that lies within ~1e-6 relative of an integer.
uint16_t ransac_iterations_needed(uint32_t inliers, uint32_t n, float confidence,
                                  uint16_t max_iterations);

// The least-squares refit alone, on the pairs whose mask byte is non-zero (all when mask is
// null): false when fewer than 4 or the fit is degenerate.
bool refit_homography(const PointPair* pairs, uint16_t n, const uint8_t* mask, Homography& out);

}  // namespace qt
