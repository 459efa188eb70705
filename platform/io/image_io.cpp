#include "io/image_io.h"

#include "io/error_line.h"

#include <dirent.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>
#include <utility>

namespace qt::io {

namespace {

// Closes what was opened; standard input is left open.
struct FileCloser {
    void operator()(std::FILE* f) const {
        if (f != stdin) std::fclose(f);
    }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

bool fail(std::string& error, const std::string& path, const std::string& what) {
    error = one_line(input_name(path) + ": " + what);
    return false;
}

// When even the message cannot be built; clear() cannot throw.
void out_of_memory(std::string& error, const std::string& path) noexcept {
    try {
        error = one_line(input_name(path) + ": out of memory");
    } catch (...) {
        error.clear();
    }
}

std::string errno_text(int e) { return std::strerror(e); }

// "-" is standard input (not closed by FilePtr), anything else a file.
FilePtr open_read(const std::string& path, std::string& error) {
    if (path == kStandardInput) return FilePtr(stdin);
    errno = 0;
    FilePtr f(std::fopen(path.c_str(), "rb"));
    if (!f) fail(error, path, "cannot open (" + errno_text(errno) + ")");
    return f;
}

// Netpbm whitespace: blank, tab, CR, LF, VT, FF.
bool is_space(int c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

enum class Format { unknown, pgm, ppm, y4m };

// Reads the magic at the start of `f` and leaves the file just after it. "P5"/"P6" must be
// followed by whitespace, '#' or the end of the file (then the header is truncated);
// "YUV4MPEG2" by a blank or the end of its line. Anything else is unknown.
Format sniff(std::FILE* f) {
    char m[9];
    if (std::fread(m, 1, 2, f) != 2) return Format::unknown;
    if (m[0] == 'P' && (m[1] == '5' || m[1] == '6')) {
        const int c = std::getc(f);
        if (c != EOF) std::ungetc(c, f);
        if (c != EOF && !is_space(c) && c != '#') return Format::unknown;
        return m[1] == '5' ? Format::pgm : Format::ppm;
    }
    if (m[0] != 'Y' || m[1] != 'U' || std::fread(m + 2, 1, 7, f) != 7 ||
        std::memcmp(m, "YUV4MPEG2", 9) != 0)
        return Format::unknown;
    const int c = std::getc(f);
    if (c != EOF) std::ungetc(c, f);
    return c == ' ' || c == '\n' ? Format::y4m : Format::unknown;
}

// A decimal header field. `text` keeps the token (shortened) for messages; `value` saturates
// at kCap so that a long run of digits cannot overflow.
struct Token {
    std::string text;
    bool numeric = false;
    uint64_t value = 0;
};
constexpr uint64_t kCap = 1000000000000ull;

void parse_number(Token& t, const std::string& full) {
    t.numeric = !full.empty();
    t.value = 0;
    for (char c : full) {
        if (c < '0' || c > '9') {
            t.numeric = false;
            break;
        }
        t.value = t.value >= kCap ? kCap : t.value * 10 + static_cast<uint64_t>(c - '0');
    }
    t.text = full.size() > 24 ? full.substr(0, 24) + "..." : full;
}

// The bytes of a PGM/PPM header (after the magic, up to the raster) that the reader takes, at
// most kMaxPnmHeader: a header is a few numbers, so a stream of comment, blank or digit bytes
// with no end is refused instead of read for ever.
class HeaderBytes {
public:
    explicit HeaderBytes(std::FILE* f) : f_(f) {}
    // The next byte, or EOF at the end of the file and once the limit is reached (over()).
    int get() {
        if (left_ == 0) {
            over_ = true;
            return EOF;
        }
        --left_;
        return std::getc(f_);
    }
    void unget(int c) {
        std::ungetc(c, f_);
        ++left_;
    }
    bool over() const { return over_; }

private:
    std::FILE* f_;
    size_t left_ = kMaxPnmHeader;
    bool over_ = false;
};

// Skips whitespace and '#' comments (to the end of their line). Returns the next byte, left
// unread, or EOF.
int skip_space(HeaderBytes& h) {
    for (;;) {
        int c = h.get();
        if (c == '#') {
            do c = h.get();
            while (c != EOF && c != '\n');
            if (c == EOF) return EOF;
            continue;
        }
        if (c == EOF) return EOF;
        if (!is_space(c)) {
            h.unget(c);
            return c;
        }
    }
}

// Reads the bytes up to whitespace, '#' or EOF (the terminator is left unread).
Token read_token(HeaderBytes& h) {
    std::string full;
    for (;;) {
        const int c = h.get();
        if (c == EOF) break;
        if (is_space(c) || c == '#') {
            h.unget(c);
            break;
        }
        if (full.size() < 64) full.push_back(static_cast<char>(c));  // longer tokens are bad anyway
    }
    Token t;
    parse_number(t, full);
    return t;
}

// The P5/P6 header and raster after the magic. maxval < 255 is rescaled with
// (v·255 + maxval/2) / maxval: round to nearest, ties (possible only for even maxval) upward.
bool read_pnm(std::FILE* f, const std::string& path, bool ppm, GreyImage& out, std::string& error) {
    const std::string kind = ppm ? "PPM" : "PGM";
    const std::string truncated = "truncated " + kind + " header: file ends ";
    const std::string malformed = "malformed " + kind + " header: ";
    const std::string too_long =
        kind + " header longer than " + std::to_string(kMaxPnmHeader) + " bytes";
    const char* names[2] = {"width", "height"};
    HeaderBytes h(f);
    Token size[2];
    for (int i = 0; i < 2; ++i) {
        if (skip_space(h) == EOF)
            return fail(error, path, h.over() ? too_long : truncated + "before the " + names[i]);
        size[i] = read_token(h);
        if (h.over()) return fail(error, path, too_long);
        if (!size[i].numeric || size[i].value == 0)
            return fail(error, path,
                        malformed + names[i] + " '" + size[i].text + "' is not a positive integer");
    }
    if (size[0].value > static_cast<uint64_t>(kMaxImageSide) ||
        size[1].value > static_cast<uint64_t>(kMaxImageSide))
        return fail(error, path,
                    "image too large: " + size[0].text + " x " + size[1].text + " (at most " +
                        std::to_string(kMaxImageSide) + " pixels per side)");
    const int width = static_cast<int>(size[0].value);
    const int height = static_cast<int>(size[1].value);

    if (skip_space(h) == EOF)
        return fail(error, path, h.over() ? too_long : truncated + "before the maxval");
    const Token mt = read_token(h);
    if (h.over()) return fail(error, path, too_long);
    if (!mt.numeric || mt.value == 0 || mt.value > 65535)
        return fail(error, path, malformed + "maxval '" + mt.text + "' is not in 1..65535");
    if (mt.value > 255)
        return fail(error, path,
                    "unsupported maxval " + mt.text + " (only 8-bit samples, maxval <= 255)");
    const unsigned maxval = static_cast<unsigned>(mt.value);
    // Exactly one whitespace byte before the raster. A comment straight after the maxval ends
    // with its newline, which is that byte (as libnetpbm reads it).
    int c = h.get();
    if (c == '#') {
        do c = h.get();
        while (c != EOF && c != '\n');
    }
    if (h.over()) return fail(error, path, too_long);
    if (c == EOF) return fail(error, path, truncated + "after the maxval");

    uint8_t scale[256];
    for (unsigned v = 0; v <= maxval; ++v)
        scale[v] = static_cast<uint8_t>((v * 255u + maxval / 2u) / maxval);

    const size_t channels = ppm ? 3 : 1;
    const size_t row_bytes = static_cast<size_t>(width) * channels;
    const uint64_t expected = static_cast<uint64_t>(row_bytes) * static_cast<uint64_t>(height);
    GreyImage img;
    std::vector<uint8_t> row;
    img.width = width;
    img.height = height;
    try {
        row.resize(row_bytes);
    } catch (const std::bad_alloc&) {
        return fail(error, path,
                    "out of memory for a " + size[0].text + " x " + size[1].text + " image");
    }
    uint64_t got = 0;
    for (int y = 0; y < height; ++y) {
        // Storage grows with the rows that arrive (the vector at most doubles), so a short file
        // declaring a huge image is refused as truncated without taking the whole image's memory.
        try {
            img.pixels.resize(static_cast<size_t>(y + 1) * static_cast<size_t>(width));
        } catch (const std::bad_alloc&) {
            return fail(error, path,
                        "out of memory for a " + size[0].text + " x " + size[1].text + " image");
        }
        const size_t n = std::fread(row.data(), 1, row_bytes, f);
        got += n;
        if (n < row_bytes) {
            if (std::ferror(f)) return fail(error, path, "read error (" + errno_text(errno) + ")");
            return fail(error, path,
                        "truncated pixel data: expected " + std::to_string(expected) +
                            " bytes, got " + std::to_string(got));
        }
        for (size_t i = 0; i < row_bytes; ++i) {
            if (row[i] > maxval)
                return fail(error, path,
                            "sample " + std::to_string(row[i]) + " at pixel (" +
                                std::to_string(i / channels) + ", " + std::to_string(y) +
                                ") above maxval " + std::to_string(maxval));
        }
        uint8_t* dst = img.pixels.data() + static_cast<size_t>(y) * static_cast<size_t>(width);
        if (!ppm) {
            for (int x = 0; x < width; ++x) dst[x] = scale[row[static_cast<size_t>(x)]];
        } else {
            // BT.601 luma in integers: the weights 77 + 150 + 29 sum to 256, so white stays 255
            // and the +128 rounds the >> 8 to nearest.
            for (int x = 0; x < width; ++x) {
                const uint8_t* p = row.data() + 3 * static_cast<size_t>(x);
                const unsigned r = scale[p[0]], g = scale[p[1]], b = scale[p[2]];
                dst[x] = static_cast<uint8_t>((77u * r + 150u * g + 29u * b + 128u) >> 8);
            }
        }
    }
    // Bytes after the raster are allowed and ignored (several tools append data; a multi-image
    // PGM stream yields its first image).
    out = std::move(img);
    return true;
}

// What a y4m stream header says.
struct Y4mInfo {
    int width = 0, height = 0;
    uint64_t chroma_bytes = 0;  // both chroma planes of one frame
};

constexpr size_t kMaxY4mLine = 65536;

// Reads up to and including '\n' into `line` (without it). Returns false at EOF before the
// newline or when the line is longer than kMaxY4mLine.
bool read_line(std::FILE* f, std::string& line, bool& too_long) {
    line.clear();
    too_long = false;
    for (;;) {
        const int c = std::getc(f);
        if (c == EOF) return false;
        if (c == '\n') return true;
        if (line.size() >= kMaxY4mLine) {
            too_long = true;
            return false;
        }
        line.push_back(static_cast<char>(c));
    }
}

uint64_t ceil_half(uint64_t n) { return (n + 1) / 2; }

// The stream header after "YUV4MPEG2": tokens W, H and C are used; F, I, A, X and any other
// tag are ignored.
bool read_y4m_header(std::FILE* f, const std::string& path, Y4mInfo& info, std::string& error) {
    std::string line;
    bool too_long = false;
    if (!read_line(f, line, too_long))
        return fail(error, path,
                    too_long
                        ? "Y4M header line longer than " + std::to_string(kMaxY4mLine) + " bytes"
                        : "truncated Y4M header (no end of line)");
    Token w, h;
    bool have_w = false, have_h = false;
    std::string colour = "420";
    size_t pos = 0;
    while (pos < line.size()) {
        const size_t end =
            line.find(' ', pos) == std::string::npos ? line.size() : line.find(' ', pos);
        const std::string tok = line.substr(pos, end - pos);
        pos = end + 1;
        if (tok.empty()) continue;
        const std::string value = tok.substr(1);
        if (tok[0] == 'W') {
            parse_number(w, value);
            have_w = true;
        } else if (tok[0] == 'H') {
            parse_number(h, value);
            have_h = true;
        } else if (tok[0] == 'C') {
            colour = value;
        }
    }
    if (!have_w) return fail(error, path, "Y4M header lacks the width (W)");
    if (!have_h) return fail(error, path, "Y4M header lacks the height (H)");
    if (!w.numeric || w.value == 0)
        return fail(error, path, "Y4M header: width '" + w.text + "' is not a positive integer");
    if (!h.numeric || h.value == 0)
        return fail(error, path, "Y4M header: height '" + h.text + "' is not a positive integer");
    if (w.value > static_cast<uint64_t>(kMaxImageSide) ||
        h.value > static_cast<uint64_t>(kMaxImageSide))
        return fail(error, path,
                    "image too large: " + w.text + " x " + h.text + " (at most " +
                        std::to_string(kMaxImageSide) + " pixels per side)");
    info.width = static_cast<int>(w.value);
    info.height = static_cast<int>(h.value);
    const uint64_t W = w.value, H = h.value;
    if (colour == "420jpeg" || colour == "420paldv" || colour == "420mpeg2" || colour == "420")
        info.chroma_bytes = 2 * ceil_half(W) * ceil_half(H);
    else if (colour == "422")
        info.chroma_bytes = 2 * ceil_half(W) * H;
    else if (colour == "444")
        info.chroma_bytes = 2 * W * H;
    else if (colour == "mono")
        info.chroma_bytes = 0;
    else
        return fail(error, path,
                    "unsupported Y4M colour space '" +
                        (colour.size() > 24 ? colour.substr(0, 24) + "..." : colour) +
                        "' (8-bit 420jpeg, 420paldv, 420mpeg2, 420, 422, 444 or mono only)");
    return true;
}

enum class FrameResult { frame, end, error };

// One y4m frame: "FRAME", optional parameters up to '\n', the Y plane into `out`, the chroma
// planes read into `scratch` and dropped (reading rather than seeking also works on pipes and
// notices truncation). `index` counts from 0 and names the frame in messages.
FrameResult read_y4m_frame(std::FILE* f, const std::string& path, const Y4mInfo& info, int index,
                           std::vector<uint8_t>& scratch, GreyImage& out, std::string& error) {
    const std::string frame = "Y4M frame " + std::to_string(index) + ": ";
    char marker[6] = {0, 0, 0, 0, 0, 0};
    const size_t n = std::fread(marker, 1, 5, f);
    if (n == 0 && !std::ferror(f)) return FrameResult::end;
    if (std::ferror(f)) {
        fail(error, path, frame + "read error (" + errno_text(errno) + ")");
        return FrameResult::error;
    }
    if (std::memcmp(marker, "FRAME", n) != 0) {
        fail(error, path, frame + "bad FRAME marker '" + std::string(marker, n) + "'");
        return FrameResult::error;
    }
    const int c = n == 5 ? std::getc(f) : EOF;
    if (c == EOF) {
        fail(error, path, frame + "truncated (file ends inside the FRAME line)");
        return FrameResult::error;
    }
    if (c != '\n' && c != ' ') {
        fail(error, path,
             frame + "bad FRAME marker '" + std::string(marker, 5) + static_cast<char>(c) + "'");
        return FrameResult::error;
    }
    if (c == ' ') {
        std::string params;
        bool too_long = false;
        if (!read_line(f, params, too_long)) {
            fail(error, path,
                 frame + (too_long ? "FRAME parameters longer than " + std::to_string(kMaxY4mLine) +
                                         " bytes"
                                   : "truncated (file ends inside the FRAME line)"));
            return FrameResult::error;
        }
    }
    const uint64_t y_bytes = static_cast<uint64_t>(info.width) * static_cast<uint64_t>(info.height);
    const uint64_t expected = y_bytes + info.chroma_bytes;
    GreyImage img;
    img.width = info.width;
    img.height = info.height;
    // The luma plane is read a row at a time into storage that grows as the rows arrive (the
    // vector at most doubles): a truncated frame of a huge declared size costs what it holds.
    uint64_t got = 0;
    try {
        if (scratch.size() < 65536) scratch.resize(65536);
        const size_t row = static_cast<size_t>(info.width);
        for (size_t filled = 0; filled < y_bytes;) {
            img.pixels.resize(filled + row);
            const size_t r = std::fread(img.pixels.data() + filled, 1, row, f);
            got += r;
            filled += r;
            if (r < row) break;
        }
    } catch (const std::bad_alloc&) {
        fail(error, path,
             frame + "out of memory for a " + std::to_string(info.width) + " x " +
                 std::to_string(info.height) + " frame");
        return FrameResult::error;
    }
    if (got == y_bytes) {
        for (uint64_t left = info.chroma_bytes; left > 0;) {
            const size_t want = left < scratch.size() ? static_cast<size_t>(left) : scratch.size();
            const size_t r = std::fread(scratch.data(), 1, want, f);
            got += r;
            left -= r;
            if (r < want) break;
        }
    }
    if (got < expected) {
        if (std::ferror(f))
            fail(error, path, frame + "read error (" + errno_text(errno) + ")");
        else
            fail(error, path,
                 frame + "truncated frame data: expected " + std::to_string(expected) +
                     " bytes, got " + std::to_string(got));
        return FrameResult::error;
    }
    out = std::move(img);
    return FrameResult::frame;
}

}  // namespace

std::string input_name(const std::string& path) {
    return path == kStandardInput ? "standard input" : path;
}

bool read_image(const std::string& path, GreyImage& out, std::string& error) {
    try {
        FilePtr f = open_read(path, error);
        if (!f) return false;
        switch (sniff(f.get())) {
            case Format::pgm: return read_pnm(f.get(), path, false, out, error);
            case Format::ppm: return read_pnm(f.get(), path, true, out, error);
            case Format::y4m: {
                Y4mInfo info;
                if (!read_y4m_header(f.get(), path, info, error)) return false;
                std::vector<uint8_t> scratch;
                switch (read_y4m_frame(f.get(), path, info, 0, scratch, out, error)) {
                    case FrameResult::frame: return true;
                    case FrameResult::end: return fail(error, path, "Y4M file has no frames");
                    case FrameResult::error: return false;
                }
                return false;
            }
            case Format::unknown: break;
        }
        if (std::ferror(f.get()))
            return fail(error, path, "cannot read (" + errno_text(errno) + ")");
        return fail(error, path, "not a PGM (P5), PPM (P6) or Y4M file");
    } catch (const std::bad_alloc&) {  // a message string itself could not be built
        out_of_memory(error, path);
        return false;
    }
}

bool read_image_folder(const std::string& dir, std::vector<NamedImage>& out, std::string& error) {
    try {
        std::vector<std::string> names;
        DIR* d = opendir(dir.c_str());
        if (d == nullptr) {
            error = one_line(dir + ": cannot read the folder (" + std::strerror(errno) + ")");
            return false;
        }
        while (const dirent* e = readdir(d)) {
            const std::string n = e->d_name;
            const std::string ext = n.size() > 4 ? n.substr(n.size() - 4) : "";
            if (ext == ".pnm" || ext == ".pgm" || ext == ".ppm") names.push_back(n);
        }
        closedir(d);
        if (names.empty()) {
            error = one_line(dir + ": no .pnm, .pgm or .ppm file");
            return false;
        }
        std::sort(names.begin(), names.end());
        std::vector<NamedImage> images;
        for (const std::string& n : names) {
            NamedImage img{n, {}};
            if (!read_image(dir + "/" + n, img.image, error)) return false;
            images.push_back(std::move(img));
        }
        out = std::move(images);
        return true;
    } catch (const std::bad_alloc&) {
        error = one_line(dir + ": out of memory");
        return false;
    }
}

bool write_pgm(const std::string& path, const GreyImage& img, std::string& error) {
    try {
        if (img.width <= 0 || img.height <= 0 ||
            img.pixels.size() != static_cast<size_t>(img.width) * static_cast<size_t>(img.height))
            return fail(error, path,
                        "cannot write a " + std::to_string(img.width) + " x " +
                            std::to_string(img.height) + " image holding " +
                            std::to_string(img.pixels.size()) + " pixels");
        errno = 0;
        FilePtr f(std::fopen(path.c_str(), "wb"));
        if (!f) return fail(error, path, "cannot create (" + errno_text(errno) + ")");
        errno = 0;
        bool ok =
            std::fprintf(f.get(), "P5\n%d %d\n255\n", img.width, img.height) > 0 &&
            std::fwrite(img.pixels.data(), 1, img.pixels.size(), f.get()) == img.pixels.size();
        int e = errno;
        if (std::fclose(f.release()) != 0 && ok) {
            ok = false;
            e = errno;
        }
        if (!ok) {
            std::remove(path.c_str());  // no half-written picture left behind
            return fail(error, path, "write failed (" + errno_text(e) + ")");
        }
        return true;
    } catch (const std::bad_alloc&) {
        out_of_memory(error, path);
        return false;
    }
}

bool write_y4m_header(std::FILE* f, const std::string& name, int width, int height, bool mono,
                      std::string& error) {
    try {
        if (width <= 0 || height <= 0)
            return fail(error, name,
                        "cannot write " + std::to_string(width) + " x " + std::to_string(height) +
                            " frames");
        errno = 0;
        if (std::fprintf(f, "YUV4MPEG2 W%d H%d F25:1 Ip A1:1 C%s\n", width, height,
                         mono ? "mono" : "420jpeg") < 0)
            return fail(error, name, "write failed (" + errno_text(errno) + ")");
        return true;
    } catch (const std::bad_alloc&) {
        out_of_memory(error, name);
        return false;
    }
}

bool write_y4m_frame(std::FILE* f, const std::string& name, const GreyImage& img, bool mono,
                     std::string& error) {
    try {
        if (img.width <= 0 || img.height <= 0 ||
            img.pixels.size() != static_cast<size_t>(img.width) * static_cast<size_t>(img.height))
            return fail(error, name,
                        "cannot write a " + std::to_string(img.width) + " x " +
                            std::to_string(img.height) + " frame holding " +
                            std::to_string(img.pixels.size()) + " pixels");
        errno = 0;
        bool ok = std::fputs("FRAME\n", f) >= 0 &&
                  std::fwrite(img.pixels.data(), 1, img.pixels.size(), f) == img.pixels.size();
        if (ok && !mono) {
            const size_t chroma = 2 * ((static_cast<size_t>(img.width) + 1) / 2) *
                                  ((static_cast<size_t>(img.height) + 1) / 2);
            const std::vector<uint8_t> grey(chroma, 128);
            ok = std::fwrite(grey.data(), 1, chroma, f) == chroma;
        }
        if (!ok) return fail(error, name, "write failed (" + errno_text(errno) + ")");
        return true;
    } catch (const std::bad_alloc&) {
        out_of_memory(error, name);
        return false;
    }
}

namespace {

// The pattern's file for `number`: prefix, the number zero-padded to `pad` digits, suffix.
std::string pattern_name(const std::string& prefix, int pad, long number,
                         const std::string& suffix) {
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < pad)
        digits.insert(0, static_cast<size_t>(pad) - digits.size(), '0');
    return prefix + digits + suffix;
}

// Whether a file is there. Only "no such file" (or a missing directory) counts as absent; a
// file that exists but cannot be read is present, and reading it reports why.
bool file_present(const std::string& path) {
    errno = 0;
    FilePtr f(std::fopen(path.c_str(), "rb"));
    if (f) return true;
    return errno != ENOENT && errno != ENOTDIR;
}

// Splits "a%03db%%c" into prefix "a", pad 3, suffix "b%c". Exactly one %d or %0Nd (N 1..9).
bool parse_pattern(const std::string& spec, std::string& prefix, int& pad, std::string& suffix) {
    bool seen = false;
    std::string* part = &prefix;
    prefix.clear();
    suffix.clear();
    pad = 0;
    for (size_t i = 0; i < spec.size(); ++i) {
        if (spec[i] != '%') {
            part->push_back(spec[i]);
            continue;
        }
        if (i + 1 < spec.size() && spec[i + 1] == '%') {
            part->push_back('%');
            ++i;
            continue;
        }
        if (seen) return false;
        size_t j = i + 1;
        if (j < spec.size() && spec[j] == '0') {
            ++j;
            if (j >= spec.size() || spec[j] < '1' || spec[j] > '9') return false;
            pad = spec[j] - '0';
            ++j;
        }
        if (j >= spec.size() || spec[j] != 'd') return false;
        seen = true;
        part = &suffix;
        i = j;
    }
    return seen;
}

}  // namespace

bool numbered_file(const std::string& pattern, long number, std::string& name) {
    std::string prefix, suffix;
    int pad = 0;
    if (!parse_pattern(pattern, prefix, pad, suffix)) return false;
    name = pattern_name(prefix, pad, number, suffix);
    return true;
}

bool FrameSource::open(const std::string& spec, std::string& error) {
    try {
        kind_ = Kind::none;
        pending_ = Pending::none;
        spec_ = spec;
        file_.reset();
        frames_read_ = 0;
        finished_ = false;
        failed_ = false;
        bad_pattern_ = false;
        sticky_error_.clear();
        gap_.clear();
        if (spec.find('%') != std::string::npos) {
            bad_pattern_ = !parse_pattern(spec, prefix_, pad_width_, suffix_);
            if (bad_pattern_)
                return fail(
                    error, spec,
                    "bad frame pattern (use one %d or %0Nd with N 1..9, and %% for a literal %)");
            const std::string first0 = pattern_name(prefix_, pad_width_, 0, suffix_);
            const std::string first1 = pattern_name(prefix_, pad_width_, 1, suffix_);
            if (file_present(first0)) {
                next_number_ = 0;
            } else if (file_present(first1)) {
                next_number_ = 1;
            } else {
                return fail(error, spec,
                            "no frame files (neither " + first0 + " nor " + first1 + " exists)");
            }
            kind_ = Kind::pattern;
            return true;
        }
        FilePtr f = open_read(spec, error);
        if (!f) return false;
        const Format format = sniff(f.get());
        switch (format) {
            case Format::pgm:
            case Format::ppm:
                if (spec != kStandardInput) {
                    kind_ = Kind::single;
                    return true;
                }
                // Standard input: images one after another until it ends. The first one's
                // magic is read here; next() reads the rest of it.
                pending_ = format == Format::ppm ? Pending::ppm : Pending::pgm;
                file_.reset(f.release());
                kind_ = Kind::pnm_stream;
                return true;
            case Format::y4m: {
                Y4mInfo info;
                if (!read_y4m_header(f.get(), spec, info, error)) return false;
                width_ = info.width;
                height_ = info.height;
                chroma_bytes_ = info.chroma_bytes;
                file_.reset(f.release());
                kind_ = Kind::y4m;
                return true;
            }
            case Format::unknown: break;
        }
        if (std::ferror(f.get()))
            return fail(error, spec, "cannot read (" + errno_text(errno) + ")");
        return fail(error, spec, "not a PGM (P5), PPM (P6) or Y4M file");
    } catch (const std::bad_alloc&) {
        out_of_memory(error, spec);
        return false;
    }
}

FrameSource::Next FrameSource::next(GreyImage& out, std::string& error) {
    if (failed_) {
        try {
            error = sticky_error_;
        } catch (...) {
            out_of_memory(error, "");
        }
        return Next::error;
    }
    if (finished_) return Next::end;
    try {
        bool ok = false;
        switch (kind_) {
            case Kind::none: fail(error, spec_, "no frame source open"); return Next::error;
            case Kind::single:
                if (frames_read_ > 0) {
                    finished_ = true;
                    return Next::end;
                }
                ok = read_image(spec_, out, error);
                break;
            case Kind::pattern: {
                const std::string name = pattern_name(prefix_, pad_width_, next_number_, suffix_);
                if (!file_present(name)) {
                    finished_ = true;
                    // A numbered file a little further on: the sequence stopped at a gap.
                    for (int k = 1; k <= kGapLookahead && gap_.empty(); ++k) {
                        const std::string later =
                            pattern_name(prefix_, pad_width_, next_number_ + k, suffix_);
                        if (file_present(later))
                            gap_ = one_line(name + " is missing but " + later +
                                            " exists: the sequence ends at the gap");
                    }
                    return Next::end;
                }
                ok = read_image(name, out, error);
                ++next_number_;
                break;
            }
            case Kind::pnm_stream: {
                // After the first image: its magic, or the end of the stream.
                if (pending_ == Pending::none) {
                    const int c = std::getc(file_.get());
                    if (c == EOF && !std::ferror(file_.get())) {
                        finished_ = true;
                        file_.reset();
                        return Next::end;
                    }
                    if (c != EOF) std::ungetc(c, file_.get());
                    const Format format = sniff(file_.get());
                    if (format != Format::pgm && format != Format::ppm) {
                        fail(error, spec_,
                             "image " + std::to_string(frames_read_) +
                                 ": not a PGM (P5) or PPM (P6) image after the one before it");
                        ok = false;
                        break;
                    }
                    pending_ = format == Format::ppm ? Pending::ppm : Pending::pgm;
                }
                const bool ppm = pending_ == Pending::ppm;
                pending_ = Pending::none;
                // Messages name the image: "standard input: image 3: truncated pixel data...".
                ok = read_pnm(file_.get(),
                              input_name(spec_) + ": image " + std::to_string(frames_read_), ppm,
                              out, error);
                break;
            }
            case Kind::y4m: {
                const Y4mInfo info{width_, height_, chroma_bytes_};
                switch (
                    read_y4m_frame(file_.get(), spec_, info, frames_read_, scratch_, out, error)) {
                    case FrameResult::frame: ok = true; break;
                    case FrameResult::end:
                        finished_ = true;
                        file_.reset();
                        return Next::end;
                    case FrameResult::error: ok = false; break;
                }
                break;
            }
        }
        if (!ok) {
            failed_ = true;
            sticky_error_ = error;
            file_.reset();
            return Next::error;
        }
        ++frames_read_;
        return Next::frame;
    } catch (const std::bad_alloc&) {
        out_of_memory(error, spec_);
        failed_ = true;
        try {
            sticky_error_ = error;
        } catch (...) {
            sticky_error_.clear();
        }
        return Next::error;
    }
}

}  // namespace qt::io
