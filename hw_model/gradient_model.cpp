#include "gradient_model.h"

namespace qt::vec {

GradientModel::GradientModel(int max_width)
    : max_width_(max_width),
      above_(static_cast<size_t>(max_width)),
      center_(static_cast<size_t>(max_width)),
      below_(static_cast<size_t>(max_width)) {}

void GradientModel::fail(std::vector<OutBeat>& out) {
    ++errors_;
    if (state_ == State::rows) {
        // Row y >= 1 was arriving with x_ good beats: words 0 .. x_ - 2 of row y - 1 are out
        // (a row's first beat emits nothing). The rest of the row comes as fill words.
        for (int x = x_ == 0 ? 0 : x_ - 1; x < width_; ++x) {
            OutBeat b;
            b.word = kFillWord;
            b.tuser = first_word_pending_;
            b.tlast = b.eof = x == width_ - 1;
            first_word_pending_ = false;
            out.push_back(b);
        }
    }
    state_ = State::idle;
}

void GradientModel::emit(int x, const std::vector<uint8_t>& above,
                         const std::vector<uint8_t>& center, const std::vector<uint8_t>& below,
                         bool last_of_row, bool eof, std::vector<OutBeat>& out) {
    const int left = x > 0 ? x - 1 : 0;
    const int right = x + 1 < width_ ? x + 1 : width_ - 1;
    OutBeat b;
    b.word =
        make_gradient_word(center[static_cast<size_t>(right)] - center[static_cast<size_t>(left)],
                           below[static_cast<size_t>(x)] - above[static_cast<size_t>(x)]);
    b.tuser = first_word_pending_;
    b.tlast = last_of_row;
    b.eof = eof;
    first_word_pending_ = false;
    out.push_back(b);
}

void GradientModel::start_frame(const InBeat& beat, std::vector<OutBeat>& out) {
    if (state_ != State::idle) fail(out);  // a frame was in progress: it ended early
    if (beat.height == 0) {
        fail(out);
        return;
    }
    state_ = State::row0;
    height_ = beat.height;
    x_ = 0;
    y_ = 0;
    first_word_pending_ = true;
}

void GradientModel::push(const InBeat& beat, std::vector<OutBeat>& out) {
    if (beat.tuser) {
        start_frame(beat, out);
        if (state_ == State::idle) return;
    } else if (state_ == State::idle) {
        return;  // no frame in progress: dropped silently
    }

    if (state_ == State::row0) {
        // Row 0 is both the row and its upper neighbour (replicated border).
        center_[static_cast<size_t>(x_)] = beat.pixel;
        if (beat.tlast) {
            width_ = x_ + 1;
            above_ = center_;
            if (height_ == 1) {
                for (int x = 0; x < width_; ++x) {
                    const bool last = x == width_ - 1;
                    emit(x, center_, center_, center_, last, last, out);
                }
                state_ = State::idle;
            } else {
                state_ = State::rows;
                y_ = 1;
                x_ = 0;
            }
        } else if (x_ == max_width_ - 1) {
            fail(out);  // no end of line within MAX_WIDTH pixels
        } else {
            ++x_;
        }
        return;
    }

    // Rows y >= 1: the beat must end the line exactly at column W - 1.
    if (beat.tlast != (x_ == width_ - 1)) {
        fail(out);
        return;
    }
    below_[static_cast<size_t>(x_)] = beat.pixel;
    if (x_ >= 1) emit(x_ - 1, above_, center_, below_, false, false, out);
    if (x_ == width_ - 1) {
        emit(x_, above_, center_, below_, true, false, out);
        if (y_ == height_ - 1) {
            // Flush the last row; its lower neighbour is itself.
            for (int x = 0; x < width_; ++x) {
                const bool last = x == width_ - 1;
                emit(x, center_, below_, below_, last, last, out);
            }
            state_ = State::idle;
        } else {
            above_.swap(center_);
            center_.swap(below_);
            ++y_;
            x_ = 0;
        }
        return;
    }
    ++x_;
}

std::vector<OutBeat> run_model(const std::vector<InBeat>& in, int max_width, int* errors) {
    GradientModel model(max_width);
    std::vector<OutBeat> out;
    out.reserve(in.size());
    for (const InBeat& b : in) model.push(b, out);
    if (errors) *errors = model.errors();
    return out;
}

}  // namespace qt::vec
