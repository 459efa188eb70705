// Runs one of the CLI's commands in-process and captures what it writes (tests only).
#pragma once
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace qt::test {

struct CliRun {
    int status;       // the command's exit status
    std::string out;  // stdout
    std::string err;  // stderr
};

// Reads a temporary file from its start and closes it.
inline std::string slurp(std::FILE* f) {
    std::rewind(f);
    std::string s;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    std::fclose(f);
    return s;
}

// command is run_detect, run_track, ...: int(const std::vector<std::string>&, FILE*, FILE*).
template <class Command>
CliRun run_cli(Command command, const std::vector<std::string>& args) {
    std::FILE* out = std::tmpfile();
    std::FILE* err = std::tmpfile();
    REQUIRE(out);
    REQUIRE(err);
    const int status = command(args, out, err);
    return {status, slurp(out), slurp(err)};
}

}  // namespace qt::test
