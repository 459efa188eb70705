// `quadtrack demo`: the pipeline on a built-in synthetic scene, writing pictures.
#pragma once
#include <string>

namespace qt::cli {

// Writes its pictures under out_dir (created if missing) and a summary on stdout.
// Returns the process exit status.
int run_demo(const std::string& out_dir);

}  // namespace qt::cli
