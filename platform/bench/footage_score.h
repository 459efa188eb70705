// The real-footage bench's scoring (bench_footage.cpp): a tracker's run over a walker's span
// against the hand-marked truth (platform/scene/footage_truth.h). Host only.
#pragma once
#include <vector>

#include "scene/footage_truth.h"

namespace qt::bench {

// One tracker's output on one frame.
struct Step {
    bool tracking = false;      // it gives a position (ours: not lost; OpenCV: update() true)
    bool claims = false;        // it says it measured the target in this frame
    double x = 0, y = 0;        // its estimate of the box centre, px
    double ms = 0;              // time spent on the frame
    const char* state = "";     // ours: the tracker's state
    double score = 0, nds = 0;  // ours: the template match's NCC and its D_nds
    double wx = 0, wy = 0;      // ours: the search window's centre, px
    int unseen = 0;             // ours: frames since the last accepted measurement
};

// The median of v (NaN when empty).
double median(std::vector<double> v);

// What a run scores against the truth.
struct Score {
    int frames = 0;       // frames where the target is in the frame (visible or occluded)
    int within = 0;       // ... with the estimate within the radius
    int switches = 0;     // runs of wrong claims while the walker is in view
    int claims_out = 0;   // frames claiming a measurement while the walker is out of the frame
    int far_outside = 0;  // frames with the walker in the frame and a position given more than
                          // one frame width (height) outside the image
    int occlusions = 0;   // occlusions (runs of occluded frames) inside the span
    int reacquired = 0;   // ... after which a claim within the radius came
    int wrong_after = 0;  // ... with a wrong claim between its start and the re-acquisition
    std::vector<int> reacquire_frames;  // frames from an occlusion's end to that claim
    std::vector<double> errors, times;  // per frame in view: error, px; per frame: time, ms
    int runs = 0;
    int kept = 0;  // runs without a switch

    void add(const Score& o) {
        frames += o.frames;
        within += o.within;
        switches += o.switches;
        claims_out += o.claims_out;
        far_outside += o.far_outside;
        occlusions += o.occlusions;
        reacquired += o.reacquired;
        wrong_after += o.wrong_after;
        reacquire_frames.insert(reacquire_frames.end(), o.reacquire_frames.begin(),
                                o.reacquire_frames.end());
        errors.insert(errors.end(), o.errors.begin(), o.errors.end());
        times.insert(times.end(), o.times.begin(), o.times.end());
        runs += o.runs;
        kept += o.kept;
    }
};

// Scores run[i], the tracker's output on frame t.start + i (run[0]: the start frame, not
// scored), against the truth, with `radius` px for "within" and twice it for a wrong claim:
//  - frames: the walker in the frame (visible or occluded, the truth interpolated between
//    marks); within: those with the estimate within the radius; errors: their errors (a frame
//    without a position: infinite);
//  - switches: runs of frames that claim a measurement more than 2·radius from the walker in
//    view; claims_out: frames claiming one while it is out of the frame; far_outside: frames
//    with the walker in the frame and a position more than one frame width (height) outside
//    the image (t.width × t.height);
//  - occlusions: runs of occluded frames; wrong_after: those followed, from their first frame
//    until the re-acquisition, by a wrong claim; reacquired: those after which a claim within
//    the radius came once the walker was visible again, reacquire_frames: frames from the
//    first visible frame to that claim.
Score score(const std::vector<Step>& run, const scene::FootageTruth& t, double radius);

}  // namespace qt::bench
