// `quadtrack demo`: the pipeline on a built-in synthetic scene, writing pictures.
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

namespace qt::cli {

// Writes its pictures under out_dir (created if missing) and a summary on stdout.
// Returns the process exit status.
int run_demo(const std::string& out_dir);

// Writes one of the demo's pictures as PNG (channels 1 or 3) and says "wrote PATH" on stdout;
// false after one error line on stderr.
bool save_demo_picture(const std::string& path, int width, int height, int channels,
                       const std::vector<uint8_t>& pixels);

}  // namespace qt::cli
