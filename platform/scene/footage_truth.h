// Hand-marked truth of one target in real footage (vectors/footage/*.txt): the one definition
// of that file format, read by the real-footage bench and the tests. Host only.
//
// The format, one item a line, '#' starts a comment line:
//   target NAME                      a short name (no spaces)
//   video FILE WIDTHxHEIGHT          the source (a Debian package's file) and the marked size
//   start FRAME X Y W H              the box the trackers start from: top-left pixel, size, px
//   FRAME CX CY W H STATE            one mark: the centre of the tightest box around the
//                                    whole target (px, pixel centres at integers), its size,
//                                    STATE visible | occluded | out; an out mark is written
//                                    FRAME - - - - out (no position)
// Marks are in increasing frame order from the start frame on: every 5th frame, and the first
// and last frame of every occlusion and the first frame out, so that the frames between two
// marks are hidden only when both marks are.
#pragma once
#include <string>
#include <vector>

namespace qt::scene {

enum class Seen { visible, occluded, out };

struct FootageMark {
    int frame = 0;
    double x = 0, y = 0;  // centre, px (unused when out)
    int w = 0, h = 0;     // box size, px
    Seen seen = Seen::visible;
};

struct FootageTruth {
    std::string name, video;
    int width = 0, height = 0;                       // the marked frame size, px
    int start = 0;                                   // the first frame of the span
    int box_x = 0, box_y = 0, box_w = 0, box_h = 0;  // the start box, px
    std::vector<FootageMark> marks;

    // The frame of the last mark.
    int last_frame() const { return marks.empty() ? start : marks.back().frame; }
    // The truth at `frame`: the mark itself, or the linear interpolation between the marks
    // either side when neither is out (seen: occluded when both are, since every occlusion's
    // first and last frame is marked). False outside the marks and next to an out mark (seen
    // = out there).
    bool at(int frame, double& x, double& y, Seen& seen) const;
};

// Reads a truth file; false with one line in `error` (file:line: what) when it is malformed.
bool read_footage_truth(const std::string& path, FootageTruth& out, std::string& error);

const char* seen_name(Seen s);

}  // namespace qt::scene
