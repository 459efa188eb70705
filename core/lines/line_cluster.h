// Clustering of duplicate segments (section 2.4 of the Quadrangle Detection paper): one strong edge
// often comes out of PPHT as several short segments. Two segments are similar when their closest
// points to the origin are near, S(li, lj) = |Ci − Cj| <= distance, as in the paper, AND their
// orientations are near: two different lines through (or near) the origin both have C ≈ (0, 0) and
// the paper's measure alone would merge them. Near the origin C moves little with the angle (|ΔC| ≈
// rho·Δθ), so two parallel-ish sides of neighbouring shapes can pass both tests: the shorter
// segment's ends must also lie near the longer one's line. Each cluster is refitted from all its
// members (total least squares over their points, each member standing for its points spread evenly
// along it), not represented by its longest member.
#pragma once
#include <stdint.h>

#include "base/angle.h"
#include "base/fixed.h"
#include "base/setting_range.h"
#include "base/status.h"
#include "lines/segment.h"

namespace qt {

struct ClusterParams {
    q16_16 distance = q16_16::from_int(6);  // |Ci − Cj| threshold, pixels
    angle_t max_angle = angle_from_deg(4);  // orientation difference (mod 180°) threshold
    q16_16 gap = q16_16::from_int(16);    // largest gap between merged segments along the line, px
    q16_16 offset = q16_16::from_int(3);  // ends of the shorter segment from the longer's line, px
};

// Corners: where two lines' ends meet at a clear angle, both ends move to the lines'
// intersection. Edge pixels give out within a pixel or two of a corner (the two sides'
// gradients mix there), so ends found by PPHT stop short of it; the intersection is where the
// sides really meet.
struct CornerParams {
    q16_16 max_distance = q16_16::from_int(4);  // an end moves at most this far, pixels
    angle_t min_angle = angle_from_deg(20);     // lines closer to parallel are left alone
};

// ClusterParams' and CornerParams' units and accepted ranges (base/setting_range.h).
struct ClusterRanges {
    SettingRange distance{"px", 0, 1000};
    SettingRange max_angle{"degrees", 0, 90};
    SettingRange gap{"px", 0, 2048};
    SettingRange offset{"px", 0, 1000};
    SettingRange corner_distance{"px", 0, 100};
    SettingRange corner_angle{"degrees", 0, 90};
};
inline constexpr ClusterRanges kClusterRanges{};

struct ClusterStats {
    uint16_t clusters = 0;
    uint16_t clusters_dropped = 0;  // clusters found with the output full
    uint16_t ends_joined = 0;       // line ends moved to a corner
};

// Orientation difference of two line normals modulo 180°, in [0°, 90°].
angle_t orientation_difference(angle_t a, angle_t b);

// Greedy clustering: the segment with most points seeds a cluster, which takes every unused
// segment similar to the seed; repeat. O(n²) similarity tests for n segments, n <= 255.
// `scratch` needs n bytes. Writes the refitted lines to out[0 .. *count).
Status cluster_segments(const Segment* in, uint16_t n, const ClusterParams& params,
                        uint8_t* scratch, Segment* out, uint16_t capacity, uint16_t* count,
                        ClusterStats* stats);

// The nearest corner found so far for one line end.
struct CornerCandidate {
    int64_t distance2;  // squared distance from the end, q16_16 units squared
    q16_16 x, y;        // the corner, pixels
};

// Moves line ends to corners (CornerParams); O(n²). Each end takes the nearest corner within
// reach; the decisions are made on the ends as found, then applied. rho, theta and C do not
// change (the ends stay on their lines). `scratch` holds 2·n candidates. Returns the ends moved.
uint16_t join_corners(Segment* lines, uint16_t n, const CornerParams& params,
                      CornerCandidate* scratch);

}  // namespace qt
