// Host image readers and writer (platform/io/image_io.h). Files are written byte by byte into a
// temporary directory and read back; every expected pixel and message is worked out by hand
// from the file formats and the rules in image_io.h, not taken from a run of the code.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "support/temp_dir.h"

using qt::io::FrameSource;
using qt::io::GreyImage;
using qt::io::read_image;
using qt::io::write_pgm;
namespace fs = std::filesystem;

namespace {

using qt::test::TempDir;

std::string bytes(std::initializer_list<int> values) {
    std::string s;
    for (int v : values) s.push_back(static_cast<char>(v));
    return s;
}

std::string repeat(int value, int n) {
    return std::string(static_cast<size_t>(n), static_cast<char>(value));
}

std::string slurp(const std::string& path) {
    std::string s;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    REQUIRE(f != nullptr);
    int c;
    while ((c = std::getc(f)) != EOF) s.push_back(static_cast<char>(c));
    std::fclose(f);
    return s;
}

// Pixels as ints, so that a failed comparison prints numbers rather than characters.
std::vector<int> px(std::initializer_list<int> values) { return std::vector<int>(values); }
std::vector<int> ints(const std::vector<uint8_t>& pixels) {
    return std::vector<int>(pixels.begin(), pixels.end());
}
std::vector<int> ints(const std::string& raw) {
    std::vector<int> v;
    for (char c : raw) v.push_back(static_cast<unsigned char>(c));
    return v;
}

// The message is one line, starts with "<path>: " and contains `fragment`.
void check_message(const std::string& error, const std::string& path, const std::string& fragment) {
    INFO("error: " << error);
    CHECK(error.rfind(path + ": ", 0) == 0);
    CHECK(error.find('\n') == std::string::npos);
    CHECK(error.find(fragment) != std::string::npos);
}

// read_image must fail on `path`, leave the output image alone, and say `fragment`.
void check_read_fails(const std::string& path, const std::string& fragment) {
    GreyImage img(1, 1, 42);
    std::string error;
    CHECK_FALSE(read_image(path, img, error));
    CHECK(img.width == 1);
    CHECK(img.height == 1);
    CHECK(ints(img.pixels) == px({42}));
    check_message(error, path, fragment);
}

// The sequence `spec` delivers one frame, then fails saying `fragment` about `path`, and keeps
// failing with the same message.
void check_second_frame_fails(const std::string& spec, const std::string& path,
                              const std::string& fragment) {
    FrameSource src;
    std::string error;
    REQUIRE(src.open(spec, error));
    GreyImage img;
    REQUIRE(src.next(img, error) == FrameSource::Next::frame);
    CHECK(src.next(img, error) == FrameSource::Next::error);
    check_message(error, path, fragment);
    std::string again;
    CHECK(src.next(img, again) == FrameSource::Next::error);
    CHECK(again == error);
}

GreyImage read_ok(const std::string& path) {
    GreyImage img;
    std::string error;
    const bool ok = read_image(path, img, error);
    INFO("error: " << error);
    REQUIRE(ok);
    return img;
}

}  // namespace

TEST_CASE("write_pgm writes a P5 file that read_image reads back", "[image_io]") {
    TempDir tmp;
    GreyImage img(5, 3);
    img.pixels = {0, 1, 2, 3, 4, 10, 32, 35, 13, 9, 128, 200, 253, 254, 255};
    const std::string path = tmp.path("out.pgm");
    std::string error;
    REQUIRE(write_pgm(path, img, error));
    CHECK(slurp(path) ==
          "P5\n5 3\n255\n" + bytes({0, 1, 2, 3, 4, 10, 32, 35, 13, 9, 128, 200, 253, 254, 255}));
    const GreyImage back = read_ok(path);
    CHECK(back.width == 5);
    CHECK(back.height == 3);
    CHECK(ints(back.pixels) == ints(img.pixels));

    SECTION("bad images and paths are refused") {
        GreyImage bad(2, 2);
        bad.pixels.pop_back();
        const std::string p = tmp.path("bad.pgm");
        CHECK_FALSE(write_pgm(p, bad, error));
        check_message(error, p, "cannot write a 2 x 2 image holding 3 pixels");
        CHECK_FALSE(fs::exists(p));
        const std::string q = tmp.path("no_such_dir/x.pgm");
        CHECK_FALSE(write_pgm(q, img, error));
        CHECK(error == q + ": cannot create (No such file or directory)");
    }
}

TEST_CASE("PGM headers take comments and any whitespace, then one whitespace byte", "[image_io]") {
    TempDir tmp;
    SECTION("comments between every field, trailing bytes after the raster ignored") {
        const std::string p =
            tmp.file("c.pgm", "P5#after magic\n3\t# width\r\n \v2\f#height\n#again\n255\n" +
                                  bytes({9, 8, 7, 6, 5, 4}) + "trailing junk");
        const GreyImage img = read_ok(p);
        CHECK(img.width == 3);
        CHECK(img.height == 2);
        CHECK(ints(img.pixels) == px({9, 8, 7, 6, 5, 4}));
    }
    SECTION("a comment straight after the maxval ends with the one whitespace byte") {
        const GreyImage img = read_ok(tmp.file("m.pgm", "P5 2 1 255#note\n" + bytes({35, 10})));
        CHECK(ints(img.pixels) == px({35, 10}));  // '#' and '\n' as pixels, not header
    }
    SECTION("only one whitespace byte after the maxval: the second is a pixel") {
        const GreyImage img = read_ok(tmp.file("w.pgm", "P5 2 1 255\n\n" + bytes({7})));
        CHECK(ints(img.pixels) == px({10, 7}));
    }
    SECTION("the largest side accepted is 16384") {
        const GreyImage img =
            read_ok(tmp.file("wide.pgm", "P5 16384 1 255\n" + repeat(200, 16384)));
        CHECK(img.width == 16384);
        CHECK(img.height == 1);
        CHECK(img.pixels.size() == 16384u);
        CHECK(img.pixels.back() == 200);
    }
}

TEST_CASE("PGM samples below maxval 255 are scaled to 0..255, rounded to nearest", "[image_io]") {
    TempDir tmp;
    // maxval 15: 255/15 = 17 exactly, so v -> 17 v.
    CHECK(ints(read_ok(tmp.file("m15.pgm", "P5 6 1 15\n" + bytes({0, 1, 7, 8, 14, 15}))).pixels) ==
          px({0, 17, 119, 136, 238, 255}));
    // maxval 7: 255 v / 7 = 0, 36.43, 72.86, 109.29, 145.71, 182.14, 218.57, 255.
    CHECK(
        ints(read_ok(tmp.file("m7.pgm", "P5 8 1 7\n" + bytes({0, 1, 2, 3, 4, 5, 6, 7}))).pixels) ==
        px({0, 36, 73, 109, 146, 182, 219, 255}));
    // maxval 2: 255/2 = 127.5, a tie, goes up.
    CHECK(ints(read_ok(tmp.file("m2.pgm", "P5 3 1 2\n" + bytes({0, 1, 2}))).pixels) ==
          px({0, 128, 255}));
    // maxval 1: a bitmap.
    CHECK(ints(read_ok(tmp.file("m1.pgm", "P5 2 1 1\n" + bytes({1, 0}))).pixels) == px({255, 0}));
}

TEST_CASE("PPM is converted to grey with (77 R + 150 G + 29 B + 128) >> 8", "[image_io]") {
    TempDir tmp;
    // red   77·255 + 128 = 19763, / 256 = 77.2  -> 77
    // green 150·255 + 128 = 38378, / 256 = 149.9 -> 149
    // blue  29·255 + 128 = 7523, / 256 = 29.4   -> 29
    // white 256·255 + 128 = 65408, / 256 = 255.5 -> 255;  black -> 0
    // (10, 200, 30): 770 + 30000 + 870 + 128 = 31768 = 124·256 + 24 -> 124
    // (100, 100, 100): 25600 + 128 = 25728 -> 100
    const std::string p =
        tmp.file("c.ppm", "P6\n# colours\n7 1\n255\n" +
                              bytes({255, 0, 0, 0, 255, 0,   0,  0,   255, 255, 255,
                                     255, 0, 0, 0, 10,  200, 30, 100, 100, 100}));
    const GreyImage img = read_ok(p);
    CHECK(img.width == 7);
    CHECK(img.height == 1);
    CHECK(ints(img.pixels) == px({77, 149, 29, 255, 0, 124, 100}));

    SECTION("channels are scaled to 0..255 before the conversion") {
        // maxval 15: (15, 0, 0) -> (255, 0, 0) -> 77; (1, 1, 1) -> (17, 17, 17) -> (256·17 + 128)
        // >> 8 = 17; (0, 15, 15) -> (0, 255, 255): 38250 + 7395 + 128 = 45773 = 178·256 + 205 ->
        // 178.
        const GreyImage m =
            read_ok(tmp.file("m.ppm", "P6 3 1 15\n" + bytes({15, 0, 0, 1, 1, 1, 0, 15, 15})));
        CHECK(ints(m.pixels) == px({77, 17, 178}));
    }
}

TEST_CASE("Y4M: every frame's Y plane, chroma planes skipped", "[image_io]") {
    TempDir tmp;
    SECTION("420jpeg with odd width and height: chroma planes are 3 x 2") {
        // Y is 5·3 = 15 bytes; each chroma plane ceil(5/2)·ceil(3/2) = 3·2 = 6 bytes, so 12.
        std::string y0, y1;
        for (int i = 1; i <= 15; ++i) {
            y0.push_back(static_cast<char>(i));
            y1.push_back(static_cast<char>(100 + i));
        }
        const std::string p =
            tmp.file("a.y4m",
                     "YUV4MPEG2 W5 H3 F30:1 Ip A1:1 C420jpeg XYSCSS=420JPEG\n"
                     "FRAME\n" +
                         y0 + repeat(0x80, 12) + "FRAME Ixyz\n" + y1 + repeat(0x81, 12));
        const GreyImage first = read_ok(p);
        CHECK(first.width == 5);
        CHECK(first.height == 3);
        CHECK(ints(first.pixels) == ints(y0));

        FrameSource src;
        std::string error;
        REQUIRE(src.open(p, error));
        GreyImage img;
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(img.width == 5);
        CHECK(img.height == 3);
        CHECK(ints(img.pixels) == ints(y0));
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == ints(y1));
        CHECK(src.next(img, error) == FrameSource::Next::end);
        CHECK(src.next(img, error) == FrameSource::Next::end);
        CHECK(src.frames_read() == 2);
    }
    SECTION("mono has no chroma") {
        const std::string p =
            tmp.file("m.y4m", "YUV4MPEG2 W3 H2 F25:1 Cmono\nFRAME\n" + bytes({1, 2, 3, 4, 5, 6}) +
                                  "FRAME\n" + bytes({7, 8, 9, 10, 11, 12}));
        FrameSource src;
        std::string error;
        REQUIRE(src.open(p, error));
        GreyImage img;
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(img.width == 3);
        CHECK(img.height == 2);
        CHECK(ints(img.pixels) == px({1, 2, 3, 4, 5, 6}));
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({7, 8, 9, 10, 11, 12}));
        CHECK(src.next(img, error) == FrameSource::Next::end);
    }
    SECTION("420 by default, 422 and 444: the second frame lands where the sizes say") {
        // 3 x 3: 420 -> 2·(2·2) = 8 chroma bytes, 422 -> 2·(2·3) = 12, 444 -> 2·9 = 18.
        const struct {
            const char* c;
            int chroma;
        } cases[] = {{"", 8},           {" C420", 8},  {" C420paldv", 8},
                     {" C420mpeg2", 8}, {" C422", 12}, {" C444", 18}};
        for (const auto& k : cases) {
            INFO("colour token '" << k.c << "'");
            const std::string p = tmp.file(
                "k.y4m", std::string("YUV4MPEG2 W3 H3") + k.c + "\nFRAME\n" + repeat(1, 9) +
                             repeat(2, k.chroma) + "FRAME\n" + repeat(3, 9) + repeat(4, k.chroma));
            FrameSource src;
            std::string error;
            REQUIRE(src.open(p, error));
            GreyImage img;
            REQUIRE(src.next(img, error) == FrameSource::Next::frame);
            CHECK(ints(img.pixels) == std::vector<int>(9, 1));
            const auto r = src.next(img, error);
            INFO("error: " << error);
            REQUIRE(r == FrameSource::Next::frame);
            CHECK(ints(img.pixels) == std::vector<int>(9, 3));
            CHECK(src.next(img, error) == FrameSource::Next::end);
        }
    }
    SECTION("a header without frames is an empty sequence, and no image") {
        const std::string p = tmp.file("e.y4m", "YUV4MPEG2 W3 H3\n");
        FrameSource src;
        std::string error;
        REQUIRE(src.open(p, error));
        GreyImage img;
        CHECK(src.next(img, error) == FrameSource::Next::end);
        check_read_fails(p, "Y4M file has no frames");
    }
}

TEST_CASE("FrameSource: printf patterns of PGM files and single images", "[image_io]") {
    TempDir tmp;
    SECTION("numbered from 1 when file 0 is missing, ending at the first gap") {
        tmp.file("f001.pgm", "P5 2 1 255\n" + bytes({1, 11}));
        tmp.file("f002.pgm", "P5 2 1 255\n" + bytes({2, 22}));
        tmp.file("f003.pgm", "P5 2 1 255\n" + bytes({3, 33}));
        tmp.file("f005.pgm", "P5 2 1 255\n" + bytes({5, 55}));  // after the gap: never read
        FrameSource src;
        std::string error;
        REQUIRE(src.open(tmp.path("f%03d.pgm"), error));
        GreyImage img;
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({1, 11}));
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({2, 22}));
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({3, 33}));
        CHECK(src.next(img, error) == FrameSource::Next::end);
        CHECK(src.frames_read() == 3);
    }
    SECTION("numbered from 0, unpadded, with a literal %") {
        tmp.file("g%0.ppm", "P6 1 1 255\n" + bytes({255, 0, 0}));
        tmp.file("g%1.pgm", "P5 1 1 255\n" + bytes({9}));  // other extension: not in the sequence
        tmp.file("g%1.ppm", "P6 1 1 255\n" + bytes({0, 0, 255}));
        FrameSource src;
        std::string error;
        REQUIRE(src.open(tmp.path("g%%%d.ppm"), error));
        GreyImage img;
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({77}));
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({29}));
        CHECK(src.next(img, error) == FrameSource::Next::end);
    }
    SECTION("a bad frame file stops the sequence with its own name in the message") {
        tmp.file("h0.pgm", "P5 1 1 255\n" + bytes({1}));
        const std::string bad = tmp.file("h1.pgm", "P5 2 2 255\n" + bytes({1}));
        check_second_frame_fails(tmp.path("h%d.pgm"), bad,
                                 "truncated pixel data: expected 4 bytes, got 1");
    }
    SECTION("a single image is a sequence of one") {
        const std::string p = tmp.file("one.pgm", "P5 1 1 255\n" + bytes({200}));
        FrameSource src;
        std::string error;
        REQUIRE(src.open(p, error));
        GreyImage img;
        REQUIRE(src.next(img, error) == FrameSource::Next::frame);
        CHECK(ints(img.pixels) == px({200}));
        CHECK(src.next(img, error) == FrameSource::Next::end);
    }
    SECTION("open errors") {
        FrameSource src;
        std::string error;
        const std::string none = tmp.path("none%02d.pgm");
        CHECK_FALSE(src.open(none, error));
        check_message(error, none,
                      "no frame files (neither " + tmp.path("none00.pgm") + " nor " +
                          tmp.path("none01.pgm") + " exists)");
        for (const char* pattern : {"f%s.pgm", "f%d_%d.pgm", "f%3d.pgm", "f%0d.pgm", "f%"}) {
            const std::string spec = tmp.path(pattern);
            INFO(pattern);
            CHECK_FALSE(src.open(spec, error));
            check_message(error, spec, "bad frame pattern");
        }
        const std::string missing = tmp.path("missing.y4m");
        CHECK_FALSE(src.open(missing, error));
        CHECK(error == missing + ": cannot open (No such file or directory)");
        const std::string junk = tmp.file("junk.bin", "hello");
        CHECK_FALSE(src.open(junk, error));
        check_message(error, junk, "not a PGM (P5), PPM (P6) or Y4M file");
        GreyImage img;
        CHECK(src.next(img, error) == FrameSource::Next::error);
    }
}

TEST_CASE("PGM/PPM errors: one line, path first, saying what is wrong", "[image_io]") {
    TempDir tmp;
    SECTION("missing file") {
        const std::string p = tmp.path("missing.pgm");
        check_read_fails(p, "cannot open (No such file or directory)");
        GreyImage img;
        std::string error;
        CHECK_FALSE(read_image(p, img, error));
        CHECK(error == p + ": cannot open (No such file or directory)");
    }
    SECTION("a directory is not readable") {
        check_read_fails(tmp.dir.string(), "cannot read (Is a directory)");
    }
    SECTION("unknown magic") {
        for (const std::string& content :
             {std::string("GIF89a"), std::string("P2 1 1 255\n7\n"), std::string("P7\n"),
              std::string("P51 1 255\n"), std::string(""), std::string("YUV4MPEG2X W1 H1\n")}) {
            INFO("content: " << content);
            check_read_fails(tmp.file("u.bin", content), "not a PGM (P5), PPM (P6) or Y4M file");
        }
    }
    SECTION("truncated header") {
        check_read_fails(tmp.file("t1.pgm", "P5"),
                         "truncated PGM header: file ends before the width");
        check_read_fails(tmp.file("t2.pgm", "P5\n4 "),
                         "truncated PGM header: file ends before the height");
        check_read_fails(tmp.file("t3.pgm", "P5\n4 # a comment that never ends"),
                         "truncated PGM header: file ends before the height");
        check_read_fails(tmp.file("t4.pgm", "P5\n4 3"),
                         "truncated PGM header: file ends before the maxval");
        check_read_fails(tmp.file("t5.pgm", "P5\n4 3\n255"),
                         "truncated PGM header: file ends after the maxval");
        check_read_fails(tmp.file("t6.ppm", "P6 4 3"),
                         "truncated PPM header: file ends before the maxval");
    }
    SECTION("non-numeric, negative and zero sizes") {
        check_read_fails(tmp.file("n1.pgm", "P5\nab 3\n255\n"),
                         "malformed PGM header: width 'ab' is not a positive integer");
        check_read_fails(tmp.file("n2.pgm", "P5\n-4 3\n255\n"),
                         "malformed PGM header: width '-4' is not a positive integer");
        check_read_fails(tmp.file("n3.pgm", "P5\n4x 3\n255\n"),
                         "malformed PGM header: width '4x' is not a positive integer");
        check_read_fails(tmp.file("z1.pgm", "P5\n0 3\n255\n"),
                         "malformed PGM header: width '0' is not a positive integer");
        check_read_fails(tmp.file("z2.ppm", "P6\n3 0\n255\n"),
                         "malformed PPM header: height '0' is not a positive integer");
        // A control character in the token is shown as '?', keeping the message on one line.
        check_read_fails(tmp.file("n4.pgm", "P5\n4" + bytes({27}) + " 3\n255\n"),
                         "malformed PGM header: width '4?' is not a positive integer");
    }
    SECTION("too large, refused before anything is allocated") {
        check_read_fails(tmp.file("l1.pgm", "P5\n16385 2\n255\n"),
                         "image too large: 16385 x 2 (at most 16384 pixels per side)");
        check_read_fails(tmp.file("l2.pgm", "P5\n2 16385\n255\n"), "image too large: 2 x 16385");
        check_read_fails(tmp.file("l3.pgm", "P5 1 99999999999999999999999 255\n"),
                         "image too large");
    }
    SECTION("maxval out of range") {
        check_read_fails(tmp.file("x0.pgm", "P5 1 1 0\n" + bytes({0})),
                         "malformed PGM header: maxval '0' is not in 1..65535");
        check_read_fails(tmp.file("x1.pgm", "P5 1 1 65536\n" + bytes({0, 0})),
                         "malformed PGM header: maxval '65536' is not in 1..65535");
        check_read_fails(tmp.file("x2.pgm", "P5 1 1 big\n" + bytes({0})),
                         "malformed PGM header: maxval 'big' is not in 1..65535");
        check_read_fails(tmp.file("x3.pgm", "P5 1 1 65535\n" + bytes({0, 0})),
                         "unsupported maxval 65535 (only 8-bit samples, maxval <= 255)");
        check_read_fails(tmp.file("x4.ppm", "P6 1 1 256\n" + bytes({0, 0, 0, 0, 0, 0})),
                         "unsupported maxval 256 (only 8-bit samples, maxval <= 255)");
    }
    SECTION("sample above maxval") {
        check_read_fails(tmp.file("s1.pgm", "P5\n2 2\n15\n" + bytes({3, 15, 4, 16})),
                         "sample 16 at pixel (1, 1) above maxval 15");
        check_read_fails(tmp.file("s2.ppm", "P6 2 1 200\n" + bytes({0, 0, 0, 0, 201, 0})),
                         "sample 201 at pixel (1, 0) above maxval 200");
    }
    SECTION("truncated raster") {
        check_read_fails(tmp.file("r1.pgm", "P5\n4 3\n255\n" + repeat(1, 7)),
                         "truncated pixel data: expected 12 bytes, got 7");
        check_read_fails(tmp.file("r2.ppm", "P6\n2 2\n255\n" + repeat(1, 5)),
                         "truncated pixel data: expected 12 bytes, got 5");
        check_read_fails(tmp.file("r3.pgm", "P5\n4 3\n255\n"),
                         "truncated pixel data: expected 12 bytes, got 0");
    }
}

TEST_CASE("Y4M errors: one line, path first, frame numbers from 0", "[image_io]") {
    TempDir tmp;
    const std::string frame15 =
        "FRAME\n" + repeat(1, 15) + repeat(2, 12);  // a whole 5 x 3 420 frame
    SECTION("unsupported colour space") {
        check_read_fails(tmp.file("c1.y4m", "YUV4MPEG2 W5 H3 C420p10\nFRAME\n" + repeat(0, 60)),
                         "unsupported Y4M colour space '420p10'");
        check_read_fails(tmp.file("c2.y4m", "YUV4MPEG2 W5 H3 C444alpha\n"),
                         "unsupported Y4M colour space '444alpha'");
        FrameSource src;
        std::string error;
        const std::string p = tmp.file("c3.y4m", "YUV4MPEG2 W5 H3 Cmono16\n");
        CHECK_FALSE(src.open(p, error));
        check_message(error, p, "unsupported Y4M colour space 'mono16'");
    }
    SECTION("bad header") {
        check_read_fails(tmp.file("h1.y4m", "YUV4MPEG2 H3 C420jpeg\n"),
                         "Y4M header lacks the width (W)");
        check_read_fails(tmp.file("h2.y4m", "YUV4MPEG2 W5\n"), "Y4M header lacks the height (H)");
        check_read_fails(tmp.file("h3.y4m", "YUV4MPEG2 W5x H3\n"),
                         "Y4M header: width '5x' is not a positive integer");
        check_read_fails(tmp.file("h4.y4m", "YUV4MPEG2 W5 H0\n"),
                         "Y4M header: height '0' is not a positive integer");
        check_read_fails(tmp.file("h5.y4m", "YUV4MPEG2 W16385 H3\n"), "image too large: 16385 x 3");
        check_read_fails(tmp.file("h6.y4m", "YUV4MPEG2 W5 H3"),
                         "truncated Y4M header (no end of line)");
    }
    SECTION("bad FRAME marker") {
        check_read_fails(tmp.file("f1.y4m", "YUV4MPEG2 W5 H3\nFRAMX\n" + repeat(1, 27)),
                         "Y4M frame 0: bad FRAME marker 'FRAMX'");
        check_read_fails(tmp.file("f2.y4m", "YUV4MPEG2 W5 H3\nxyz"),
                         "Y4M frame 0: bad FRAME marker 'xyz'");
        check_read_fails(tmp.file("f3.y4m", "YUV4MPEG2 W5 H3\nFRAME"),
                         "Y4M frame 0: truncated (file ends inside the FRAME line)");
        // Frame 1's marker is garbled: frame 0 is delivered, then the error, then the same error.
        const std::string p =
            tmp.file("f4.y4m", "YUV4MPEG2 W5 H3\n" + frame15 + "FRAMES\n" + repeat(1, 27));
        check_second_frame_fails(p, p, "Y4M frame 1: bad FRAME marker 'FRAMES'");
    }
    SECTION("truncated frame") {
        // 5 x 3 420: 15 Y + 12 chroma = 27 bytes a frame. Frame 1 stops inside its chroma (20
        // bytes) or inside its Y plane (9 bytes).
        for (int have : {20, 9}) {
            const std::string p = tmp.file(
                "t.y4m", "YUV4MPEG2 W5 H3 C420jpeg\n" + frame15 + "FRAME\n" + repeat(3, have));
            check_second_frame_fails(p, p,
                                     "Y4M frame 1: truncated frame data: expected 27 bytes, got " +
                                         std::to_string(have));
        }
        check_read_fails(tmp.file("t0.y4m", "YUV4MPEG2 W5 H3\nFRAME\n" + repeat(1, 26)),
                         "Y4M frame 0: truncated frame data: expected 27 bytes, got 26");
    }
}
