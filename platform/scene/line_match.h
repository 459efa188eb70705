// Scoring detected lines against a scene's ground truth (host side, double precision): the
// acceptance rule of the lines stage and the accuracy table of bash bench.sh lines-host.
#pragma once
#include <vector>

#include "scene/line_scene.h"

namespace qt::scene {

struct DetectedLine {
    Point2 a, b;  // end points, pixels
};

struct MatchRule {
    double min_length = 40;        // truth segments shorter than this are not scored, pixels
    double max_angle_deg = 1.0;    // orientation error allowed
    double max_endpoint_px = 2.0;  // each end point within this of its true end
};

struct MatchResult {
    int scored = 0;              // truth segments at least min_length long
    int found = 0;               // of those, matched by some detected line
    int detected = 0;            // detected lines
    int false_positives = 0;     // detected lines that lie on no truth segment (see line_match.cpp)
    double worst_angle_deg = 0;  // over matched segments
    double worst_endpoint_px = 0;  // over matched segments
};

MatchResult match_lines(const std::vector<TrueSegment>& truth,
                        const std::vector<DetectedLine>& detected, const MatchRule& rule);

}  // namespace qt::scene
