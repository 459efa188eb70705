// Table I end to end between two frames' features: NCC matches (ncc_match.h) become point
// pairs, RANSAC and the refit (homography.h) give the homography from the first frame's image
// into the second's. Used by the target pipeline and by `quadtrack homography`.
//
// By default a pair is not (corner in A, corner in B): a corner's position wobbles by a few
// tenths of a pixel between frames (the response's maximum moves with noise and with the view),
// which the homography would inherit. Instead a pair is (A's corner pixel, that pixel + the
// displacement of its patch into B's), the displacement measured to sub-pixel precision by
// correlating the two patches (match_displacement_q8). PairSource::corners gives the paper's
// pairs, (A's sub-pixel corner, B's sub-pixel corner), for comparison.
#pragma once
#include <stdint.h>

#include "target/feature.h"
#include "target/float/homography.h"
#include "target/ncc_match.h"

namespace qt {

// What a point pair for the homography is made of (see the top of this file).
enum class PairSource : uint8_t {
    displacement,  // A's corner pixel and the patch displacement into B (ours, the default)
    corners,       // the two matched corners' sub-pixel positions (the paper's Table I)
};
inline const char* pair_source_name(PairSource p) {
    return p == PairSource::corners ? "corners" : "displacement";
}

struct FrameHomographyParams {
    MatchParams match;
    RansacParams ransac;
    PairSource pairs = PairSource::displacement;
};

struct FrameHomography {
    RansacResult ransac;
    uint16_t matches = 0;  // NCC correspondences given to RANSAC (with a sub-pixel displacement)
    MatchStats match_stats{};
};

// Scratch: room for MaxFeatures matches, pairs and inlier flags (the mutual-best matches are
// at most min(|a|, |b|)). matches[i], pairs[i] and mask[i] describe correspondence i afterwards.
template <int R, uint16_t MaxFeatures>
struct FrameHomographyScratch {
    FeatureMatch matches[MaxFeatures];
    PointPair pairs[MaxFeatures];
    uint8_t inlier[MaxFeatures];
};

// Displacement of A's patch content into B's, 1/256 px: the integer offset between their
// centres plus one Lucas–Kanade step on the patches' inner (2R−1)² pixels with the mean of the
// two patches' gradients (symmetric, so the error of the linearisation is of second order):
//   s = −(Σ g gᵀ)⁻¹ Σ g (b − a),  g = (∇a + ∇b)/2.
// With E = Da + Db the sum of the two central differences (E = 4g): s = −4 (Σ E Eᵀ)⁻¹ Σ E (b − a).
// Bounds over at most 13² inner pixels: |E| <= 1020, Σ E² <= 169·1020² < 2^28, |Σ E·t| <=
// 169·1020·255 < 2^26, det < 2^56, numerators·1024 < 2^28+26+10 = 2^64 / 4: int64 throughout.
// False when the texture does not fix both directions (det below 1/64 of its scale) or the
// step exceeds one pixel (the corners disagree by more than the match allows).
template <int R>
bool match_displacement_q8(const Feature<R>& a, const Feature<R>& b, int32_t& dx_q8,
                           int32_t& dy_q8) {
    static_assert(R >= 1 && R <= 7, "inner block of at most 13×13");
    constexpr int kSide = Feature<R>::kSide;
    int64_t sxx = 0, sxy = 0, syy = 0, sxt = 0, syt = 0;
    for (int y = 1; y < kSide - 1; ++y)
        for (int x = 1; x < kSide - 1; ++x) {
            const uint8_t* pa = a.patch + y * kSide + x;
            const uint8_t* pb = b.patch + y * kSide + x;
            const int32_t ex = (pa[1] - pa[-1]) + (pb[1] - pb[-1]);
            const int32_t ey = (pa[kSide] - pa[-kSide]) + (pb[kSide] - pb[-kSide]);
            const int32_t t = pb[0] - pa[0];
            sxx += ex * ex;
            sxy += ex * ey;
            syy += ey * ey;
            sxt += ex * t;
            syt += ey * t;
        }
    const int64_t det = sxx * syy - sxy * sxy;
    if (det <= 0 || det < (sxx * syy) / 64) return false;
    // s = −4·[[syy, −sxy], [−sxy, sxx]]·[sxt, syt] / det, in 1/256 px (·1024 = 4·256).
    const int64_t nx = -(syy * sxt - sxy * syt) * 1024, ny = -(sxx * syt - sxy * sxt) * 1024;
    const int64_t sx = nx / det, sy = ny / det;
    if (sx < -256 || sx > 256 || sy < -256 || sy > 256) return false;
    dx_q8 = (b.px - a.px) * 256 + static_cast<int32_t>(sx);
    dy_q8 = (b.py - a.py) * 256 + static_cast<int32_t>(sy);
    return true;
}

// matched() is called once, between the matching (NCC and displacements) and RANSAC, for a
// caller that times the two (the firmware's budgets). keep(feature of A) false leaves that
// corner's match out of the pairs: the target tracker's own corners, which move with the
// target and not with the ground the homography describes.
template <int R, uint16_t MaxFeatures, class Keep, class Matched>
FrameHomography homography_between(const FeatureSet<R, MaxFeatures>& a,
                                   const FeatureSet<R, MaxFeatures>& b,
                                   const FrameHomographyParams& config,
                                   FrameHomographyScratch<R, MaxFeatures>& scratch, Keep&& keep,
                                   Matched&& matched) {
    FrameHomography out;
    const uint16_t found =
        match_features(a, b, config.match, scratch.matches, MaxFeatures, &out.match_stats);
    for (uint16_t i = 0; i < found; ++i) {
        const Feature<R>& fa = a.items[scratch.matches[i].prev];
        const Feature<R>& fb = b.items[scratch.matches[i].cur];
        if (!keep(fa)) continue;
        // 1/256 px to px: exact in float (positions below 2^15 px need 23 bits).
        constexpr float kQ8 = 1.0f / 256.0f;
        PointPair pair;
        if (config.pairs == PairSource::corners) {
            pair = PointPair{static_cast<float>(fa.x_q8) * kQ8, static_cast<float>(fa.y_q8) * kQ8,
                             static_cast<float>(fb.x_q8) * kQ8, static_cast<float>(fb.y_q8) * kQ8};
        } else {
            int32_t dx_q8, dy_q8;
            if (!match_displacement_q8(fa, fb, dx_q8, dy_q8)) continue;
            const float ax = static_cast<float>(fa.px), ay = static_cast<float>(fa.py);
            pair = PointPair{ax, ay, ax + static_cast<float>(dx_q8) * kQ8,
                             ay + static_cast<float>(dy_q8) * kQ8};
        }
        scratch.matches[out.matches] = scratch.matches[i];
        scratch.pairs[out.matches++] = pair;
    }
    matched();
    out.ransac = estimate_homography(scratch.pairs, out.matches, config.ransac, scratch.inlier);
    return out;
}

template <int R, uint16_t MaxFeatures>
FrameHomography homography_between(const FeatureSet<R, MaxFeatures>& a,
                                   const FeatureSet<R, MaxFeatures>& b,
                                   const FrameHomographyParams& config,
                                   FrameHomographyScratch<R, MaxFeatures>& scratch) {
    return homography_between(
        a, b, config, scratch, [](const Feature<R>&) { return true; }, [] {});
}

}  // namespace qt
