#include "bench/footage_score.h"

#include <algorithm>
#include <cmath>

namespace qt::bench {

using scene::Seen;

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Score score(const std::vector<Step>& run, const scene::FootageTruth& t, double radius) {
    Score s;
    s.runs = 1;
    std::vector<double>& errors = s.errors;
    std::vector<double>& times = s.times;
    bool in_wrong = false;
    bool was_occluded = false, waiting = false, wrong_seen = false;
    int occlusion_end = 0;
    for (size_t i = 1; i < run.size(); ++i) {  // frame 0 of the span is the start
        const Step& st = run[i];
        times.push_back(st.ms);
        const int frame = t.start + static_cast<int>(i);
        double x = 0, y = 0;
        Seen seen;
        const bool present = t.at(frame, x, y, seen);
        const double error = st.tracking ? std::hypot(st.x - x, st.y - y) : INFINITY;
        // A claim far from the walker in view is on someone or something else; a claim while
        // the walker is out of the frame is on something else too, counted apart.
        const bool wrong = st.claims && present && error > 2 * radius;
        if (wrong && !in_wrong) ++s.switches;
        in_wrong = wrong;
        if (st.claims && !present && seen == Seen::out) ++s.claims_out;
        if (present) {
            ++s.frames;
            if (st.tracking && (st.x < -t.width || st.x > 2.0 * t.width - 1 || st.y < -t.height ||
                                st.y > 2.0 * t.height - 1))
                ++s.far_outside;
            errors.push_back(error);
            if (error <= radius) ++s.within;
        }
        // Occlusions: from an occlusion's first frame, wrong claims count against it until a
        // claim within the radius after its last frame re-acquires the target.
        const bool occluded = present && seen == Seen::occluded;
        if (occluded && !was_occluded) {
            ++s.occlusions;
            waiting = true;
            wrong_seen = false;
        }
        if (!occluded && was_occluded) occlusion_end = frame;
        was_occluded = occluded;
        if (waiting) {
            if (wrong && !wrong_seen) {
                wrong_seen = true;
                ++s.wrong_after;
            }
            if (!occluded && st.claims && present && error <= radius) {
                waiting = false;
                ++s.reacquired;
                s.reacquire_frames.push_back(frame - occlusion_end);
            }
        }
    }
    s.kept = s.switches == 0;
    return s;
}

}  // namespace qt::bench
