// A fresh directory under the system temp dir, unique to the process and the instance, removed
// with everything in it at the end: test cases that ctest runs in parallel never share files.
#pragma once
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "io/image_io.h"

namespace qt::test {

struct TempDir {
    std::filesystem::path dir;
    TempDir() {
        std::random_device rd;
        const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
        dir = std::filesystem::temp_directory_path() /
              ("quadtrack_test_" + std::to_string(rd()) + "_" +
               std::to_string(static_cast<long long>(now)));
        std::filesystem::create_directories(dir);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string path(const std::string& name) const { return (dir / name).string(); }
    // Writes `bytes` to `name` and returns its path.
    std::string file(const std::string& name, const std::string& bytes) const {
        const std::string p = path(name);
        std::FILE* f = std::fopen(p.c_str(), "wb");
        REQUIRE(f != nullptr);
        REQUIRE(std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size());
        REQUIRE(std::fclose(f) == 0);
        return p;
    }
    // Writes `img` to `name` as a PGM and returns its path.
    std::string pgm(const std::string& name, const io::GreyImage& img) const {
        const std::string p = path(name);
        std::string error;
        const bool written = io::write_pgm(p, img, error);
        INFO(error);
        REQUIRE(written);
        return p;
    }
};

}  // namespace qt::test
