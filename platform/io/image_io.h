// Host image files for the quadtrack CLI: grey frames in from PGM (P5), PPM (P6) and YUV4MPEG2
// (.y4m) files or numbered PGM/PPM sequences, and binary PGM out. Host only (heap, stdio); core/
// never sees these types, it gets rows.
//
// Every function reports failure by returning false (or Next::error) with ONE line in `error`:
// the file name first, then what is wrong, e.g. "in.pgm: truncated pixel data: expected 12
// bytes, got 7". Control characters in a message (from a file name or a bad header token) are
// shown as '?' so it stays one line. No exception escapes (allocation failures are caught).
#pragma once
#include <stdint.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "io/grey_image.h"

namespace qt::io {

// Largest width or height accepted from a file; a larger header is refused before anything
// is allocated ("image too large").
constexpr int kMaxImageSide = 16384;
// Longest PGM/PPM header (from after the magic to the raster: numbers, blanks, comments), bytes;
// a longer one is refused, as is a Y4M header or FRAME line of 64 KiB or more.
constexpr size_t kMaxPnmHeader = 65536;

// The path that stands for standard input wherever an image or a sequence is read: "-".
constexpr const char* kStandardInput = "-";

// How messages name an input: "standard input" for "-", the path itself otherwise.
std::string input_name(const std::string& path);

// Reads one grey frame from a file, or from standard input for "-": PGM (P5), PPM (P6,
// converted to grey with BT.601 integer weights Y = (77·R + 150·G + 29·B + 128) >> 8), or the Y
// plane of the first frame of a YUV4MPEG2 (.y4m) stream. The format comes from the magic bytes,
// not the name. Standard input is read up to the end of that frame and left open.
// PGM/PPM maxval 1..255 (samples below 255 are rescaled to 0..255); 16-bit files are refused.
// On failure returns false, leaves `out` unchanged and sets `error` to one line.
bool read_image(const std::string& path, GreyImage& out, std::string& error);

// A grey image and the file name (without its folder) it was read from.
struct NamedImage {
    std::string name;
    GreyImage image;
};

// Reads every .pnm, .pgm and .ppm file of folder `dir` (read_image), in name order. On
// failure (the folder cannot be read, a file is bad, or there is no such file) returns false
// with one line in `error`.
bool read_image_folder(const std::string& dir, std::vector<NamedImage>& out, std::string& error);

// Writes `img` as binary PGM (P5, maxval 255; header "P5\n<w> <h>\n255\n"). Refuses an image
// whose width or height is not positive or whose pixel count is not width·height.
// On failure returns false and sets `error` to one line.
bool write_pgm(const std::string& path, const GreyImage& img, std::string& error);

// A YUV4MPEG2 stream of grey frames, written frame by frame (to a file or a pipe): the header
// "YUV4MPEG2 W<w> H<h> F25:1 Ip A1:1 C<mono|420jpeg>", then per frame "FRAME", the Y plane and,
// for 420jpeg, both chroma planes at 128 (no colour). Return false with one line in `error`
// when the size is not positive or a write fails; `name` names the output in that line.
bool write_y4m_header(std::FILE* f, const std::string& name, int width, int height, bool mono,
                      std::string& error);
bool write_y4m_frame(std::FILE* f, const std::string& name, const GreyImage& img, bool mono,
                     std::string& error);

// The file of `number` in a printf-style pattern as FrameSource reads them ("f%03d.png", 7 ->
// "f007.png"): false when the pattern does not hold exactly one %d or %0Nd (N 1..9).
bool numbered_file(const std::string& pattern, long number, std::string& name);

// A sequence of grey frames, read one at a time. The spec given to open() is one of:
//  - a printf-style pattern of PGM/PPM files (any spec containing '%'), with exactly one
//    "%d" or "%0Nd" (N = 1..9) and "%%" for a literal '%', e.g. "frames/f%03d.pgm": numbered
//    from 0, or from 1 if file 0 does not exist, and ending at the first missing number (gap()
//    says when files follow it);
//  - a .y4m file (recognised by its magic): every frame's Y plane, in order;
//  - any other single image file read_image accepts: one frame;
//  - "-", standard input: a Y4M stream (every frame, as a file), or PGM/PPM images one after
//    another until the stream ends (what `ffmpeg -f image2pipe -c:v pgm -` writes). Each frame is
//    read when next() asks for it, never ahead, so a live pipe is processed as it comes; a
//    stream that ends inside a frame is an error (Next::error) after the whole frames before.
// Frames of a pattern are not required to share one size; the caller checks if it cares.
class FrameSource {
public:
    // Opens a sequence (see above), closing any previous one. A pattern needs file 0 or file
    // 1 to exist; a y4m file's header is read and checked here. Returns false with one line in
    // `error` otherwise.
    bool open(const std::string& spec, std::string& error);

    enum class Next { frame, end, error };
    // The next frame in order: Next::frame with the frame in `out`, Next::end after the last
    // one (a y4m file with a header and no frames is an empty sequence), or Next::error with
    // one line in `error` (frame numbers in y4m messages count from 0). After end or error
    // every further call returns the same result (and the same error line).
    Next next(GreyImage& out, std::string& error);

    // Frames delivered by next() since open().
    int frames_read() const { return frames_read_; }
    // The last open() refused the spec as a malformed pattern (a command-line mistake, not an
    // input one).
    bool bad_pattern() const { return bad_pattern_; }
    // After a pattern's Next::end: one line naming the missing file when a file numbered up to
    // kGapLookahead past it exists (the sequence stopped at a gap), else empty.
    const std::string& gap() const { return gap_; }
    static constexpr int kGapLookahead = 16;

private:
    struct FileCloser {  // standard input is left open
        void operator()(std::FILE* f) const {
            if (f != stdin) std::fclose(f);
        }
    };
    enum class Kind { none, single, pattern, y4m, pnm_stream };
    // pnm_stream: the kind of the image whose magic open() or next() has read already.
    enum class Pending { none, pgm, ppm };

    Kind kind_ = Kind::none;
    std::string spec_;
    // Pattern: the text around the number, its zero-padded width and the next number to read.
    std::string prefix_, suffix_;
    int pad_width_ = 0;
    long next_number_ = 0;
    Pending pending_ = Pending::none;
    // y4m, pnm_stream: the open file; y4m: the frame size and the chroma bytes to skip after
    // each Y plane.
    std::unique_ptr<std::FILE, FileCloser> file_;
    int width_ = 0, height_ = 0;
    uint64_t chroma_bytes_ = 0;
    std::vector<uint8_t> scratch_;
    int frames_read_ = 0;
    bool finished_ = false;  // end reached
    bool failed_ = false;    // next() failed; it repeats sticky_error_
    std::string sticky_error_;
    bool bad_pattern_ = false;
    std::string gap_;  // see gap()
};

}  // namespace qt::io
