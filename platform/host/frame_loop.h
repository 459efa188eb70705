// The frame loop of the sequence commands (track, target): every frame of a sequence, all of
// frame 0's size, with one error line for whatever goes wrong. Host only.
#pragma once
#include <cstdio>
#include <functional>
#include <string>

#include "io/grey_image.h"

namespace qt::host {

// Calls body(k, frame) for frames k = 0, 1, ... of `spec` (image_io.h's FrameSource; "-" is
// standard input), each frame read only after body has returned for the one before. Returns 0
// after the last frame (with a warning line on `err` when a numbered sequence stopped at a gap);
// 2 after one line "quadtrack COMMAND: ..." on `err` for a malformed pattern, 1 when the sequence
// cannot be opened, a frame cannot be read, there are no frames or a frame's size differs from
// frame 0's; or the first non-zero value body returns (body writes its own error line). When
// `err` is a terminal, a progress line (frames done, frames a second) is rewritten on it at most
// twice a second.
int for_each_frame(const std::string& spec, const char* command, std::FILE* err,
                   const std::function<int(int, const io::GreyImage&)>& body);

}  // namespace qt::host
