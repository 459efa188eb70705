// The track command's test sequence written as PGM files: the default board turning and moving,
// with the demo's dark bars over its top and bottom sides in three middle frames (the Quadrangle
// Detection paper's frames 41–43, where the paper's sides were missed). Tests only.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "scene/board_scene.h"
#include "scene/board_sequence.h"

namespace qt::test {

constexpr int kBarredFrames = 10, kFirstBarred = 4, kLastBarred = 6;

// Frame f: the default board turned by (f − 5)·0.5° about its centre and moved by
// (5f − 22, 2f − 9) px; in frames kFirstBarred..kLastBarred bars hide the top and bottom sides.
// truth[f] gets the corners (px) in the generator's order TL, TR, BR, BL. Returns the files'
// printf pattern (dir/fNN.pgm).
inline std::string write_barred_board_sequence(const std::filesystem::path& dir,
                                               std::vector<std::array<double, 8>>& truth) {
    truth.clear();
    for (int f = 0; f < kBarredFrames; ++f) {
        scene::BoardScene s = scene::turned_board(scene::default_board_scene(), (f - 5) * 0.5,
                                                  5.0 * f - 22, 2.0 * f - 9);
        std::array<double, 8> t{};
        for (int i = 0; i < 4; ++i) {
            t[2 * i] = s.corners[i].x / 256.0;
            t[2 * i + 1] = s.corners[i].y / 256.0;
        }
        s.seed = 500 + static_cast<uint64_t>(f);
        io::GreyImage img = scene::render_board(s);
        if (f >= kFirstBarred && f <= kLastBarred) {
            scene::draw_bar(img, s.corners[0], s.corners[1]);  // top
            scene::draw_bar(img, s.corners[2], s.corners[3]);  // bottom
        }
        char name[32];
        std::snprintf(name, sizeof name, "f%02d.pgm", f);
        std::string error;
        REQUIRE(io::write_pgm((dir / name).string(), img, error));
        truth.push_back(t);
    }
    return (dir / "f%02d.pgm").string();
}

}  // namespace qt::test
