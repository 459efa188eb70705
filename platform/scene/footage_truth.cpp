#include "scene/footage_truth.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace qt::scene {

const char* seen_name(Seen s) {
    switch (s) {
        case Seen::visible: return "visible";
        case Seen::occluded: return "occluded";
        case Seen::out: return "out";
    }
    return "?";
}

bool FootageTruth::at(int frame, double& x, double& y, Seen& seen) const {
    seen = Seen::out;
    for (size_t i = 0; i < marks.size(); ++i) {
        const FootageMark& b = marks[i];
        if (b.frame < frame) continue;
        if (b.frame == frame) {
            seen = b.seen;
            x = b.x;
            y = b.y;
            return b.seen != Seen::out;
        }
        if (i == 0) return false;
        const FootageMark& a = marks[i - 1];
        if (a.seen == Seen::out || b.seen == Seen::out) return false;
        const double t = static_cast<double>(frame - a.frame) / (b.frame - a.frame);
        x = a.x + t * (b.x - a.x);
        y = a.y + t * (b.y - a.y);
        // Every occlusion's first and last frame are marked: the frames between two marks
        // are hidden only when both are.
        seen =
            (a.seen == Seen::occluded && b.seen == Seen::occluded) ? Seen::occluded : Seen::visible;
        return true;
    }
    return false;
}

bool read_footage_truth(const std::string& path, FootageTruth& out, std::string& error) {
    out = FootageTruth{};
    std::ifstream in(path);
    if (!in) {
        error = path + ": cannot open";
        return false;
    }
    std::string line;
    int number = 0;
    bool have_start = false;
    auto fail = [&](const std::string& what) {
        error = path + ":" + std::to_string(number) + ": " + what;
        return false;
    };
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::string first;
        words >> first;
        if (first == "target") {
            if (!(words >> out.name)) return fail("target needs a name");
        } else if (first == "video") {
            std::string size;
            if (!(words >> out.video >> size) ||
                std::sscanf(size.c_str(), "%dx%d", &out.width, &out.height) != 2)
                return fail("video needs FILE WIDTHxHEIGHT");
        } else if (first == "start") {
            if (!(words >> out.start >> out.box_x >> out.box_y >> out.box_w >> out.box_h) ||
                out.box_w <= 0 || out.box_h <= 0)
                return fail("start needs FRAME X Y W H");
            have_start = true;
        } else {
            FootageMark m;
            std::string xs, ys, ws, hs, state;
            try {
                m.frame = std::stoi(first);
            } catch (...) {
                return fail("unknown line '" + first + "'");
            }
            if (!(words >> xs >> ys >> ws >> hs >> state)) return fail("a mark needs 6 fields");
            if (state == "out") {
                m.seen = Seen::out;
            } else if (state != "visible" && state != "occluded") {
                return fail("state '" + state + "' (visible, occluded or out)");
            } else {
                m.seen = state == "visible" ? Seen::visible : Seen::occluded;
                try {
                    m.x = std::stod(xs);
                    m.y = std::stod(ys);
                    m.w = std::stoi(ws);
                    m.h = std::stoi(hs);
                } catch (...) {
                    return fail("a mark's CX CY W H must be numbers");
                }
            }
            if (!out.marks.empty() && m.frame <= out.marks.back().frame)
                return fail("marks must be in increasing frame order");
            out.marks.push_back(m);
        }
    }
    if (out.name.empty() || out.video.empty() || !have_start) {
        number = 0;
        return fail("target, video and start lines are required");
    }
    if (out.marks.empty() || out.marks.front().frame != out.start)
        return fail("the first mark must be at the start frame");
    return true;
}

}  // namespace qt::scene
