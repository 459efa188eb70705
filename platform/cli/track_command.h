// `quadtrack track SEQUENCE [OPTIONS]`: a sequence of frames through detection and the
// quadrangle tracker (core/tracking/quad_tracker.h), one JSON line per frame out.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace qt::cli {

// args: everything after "track". Writes one JSON line per frame to `out` (detect_json.h,
// track_json), flushed frame by frame, and one error line to `err`. Returns the exit status: 0
// ok, 1 bad input (a frame that cannot be read, stops the output after the frames before it;
// a frame of another size than the first; an empty sequence), 2 bad command line.
int run_track(const std::vector<std::string>& args, std::FILE* out, std::FILE* err);

// The usage text of track, with every option.
std::string track_usage();

}  // namespace qt::cli
