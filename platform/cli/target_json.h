// The one definition of the JSON of `quadtrack homography` and `quadtrack target`
// (docs/cli.md), each written on one line:
//   homography: {"H":[[h1,h2,h3],[h4,h5,h6],[h7,h8,1]]|null,"inliers":N,"matches":M,
//                "status":"ok"|"too_few_pairs"|"degenerate"|"no_consensus",
//                "reprojection_px":E|null,"features":[NA,NB],"bin":[BA,BB]}
//     H maps pixels of image A into image B ((x', y', w') = H (x, y, 1), pixel centres at
//     integers), null unless status is "ok"; inliers of the matches; reprojection_px the RMS
//     of equation (7) over the inliers, in B's pixels (null with H); bin the factors A and B
//     were binned by to fit the build (1: not binned; docs/cli.md): H and E are in the input's
//     pixels all the same.
//   target (JSON Lines, one per frame):
//               {"frame":K,"x":X,"y":Y,"state":"measured"|"reacquired"|"predicted"|
//                "out_of_view"|"lost","nds":D,"reset":true|false,"matches":M,"inliers":N,
//                "bin":B}
//     x, y the target's centre in this frame, px (outside the image while out of view); nds
//     the D_nds of the match considered (0 when none); reset: Table III's reset happened in
//     this frame; matches and inliers of the homography from the previous frame (0 in frame 0);
//     bin the factor the frames were binned by (x, y are in the input's pixels all the same).
#pragma once
#include <string>

#include "cli/target_options.h"

namespace qt::cli {

// g in the binned frames' pixels; bin_a, bin_b the factors of A and B.
std::string homography_json(const FrameHomography& g, unsigned features_a, unsigned features_b,
                            uint8_t bin_a = 1, uint8_t bin_b = 1);

// f in the binned frame's pixels, binned by `bin`.
std::string target_json(int frame, const TargetFrame& f, uint8_t bin = 1);

}  // namespace qt::cli
