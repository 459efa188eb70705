#include "edge_model.h"

#include <stdexcept>

namespace qt::vec {

EdgeModel::EdgeModel(int max_width, uint16_t threshold, bool per_frame)
    : max_width_(max_width),
      cfg_threshold_(threshold),
      per_frame_(per_frame),
      above_(static_cast<size_t>(max_width)),
      center_(static_cast<size_t>(max_width)),
      below_(static_cast<size_t>(max_width)),
      zero_(static_cast<size_t>(max_width)),
      center_dir_(static_cast<size_t>(max_width)),
      below_dir_(static_cast<size_t>(max_width)) {}

void EdgeModel::emit(edge_beat b, bool last, std::vector<EdgeOutBeat>& out) {
    out.push_back(EdgeOutBeat{b, sof_due_, last});
    sof_due_ = last;
}

void EdgeModel::decide(int x, int y, const std::vector<uint16_t>& above,
                       const std::vector<uint16_t>& center, const std::vector<uint8_t>& center_dir,
                       const std::vector<uint16_t>& below, std::vector<EdgeOutBeat>& out) {
    const auto at = [this](const std::vector<uint16_t>& row, int k) -> uint32_t {
        return k >= 0 && k < width_ ? row[static_cast<size_t>(k)] : 0u;
    };
    const uint32_t m = center[static_cast<size_t>(x)];
    const uint32_t dir = center_dir[static_cast<size_t>(x)];
    // The eight neighbours in a ring, starting at the right and turning with the angle
    // (towards +y, down): n[k] lies at k * 45 degrees.
    const uint32_t n[8] = {at(center, x + 1), at(below, x + 1), at(below, x), at(below, x - 1),
                           at(center, x - 1), at(above, x - 1), at(above, x), at(above, x + 1)};
    // Bin d points at d * 22.5 degrees: the ring position j = d / 2, between j and j + 1 when d
    // is odd (the mean of the two: both sides and the centre counted twice). Behind: opposite.
    const uint32_t j = dir >> 1, odd = dir & 1u;
    const uint32_t ahead = n[j] + (odd ? n[(j + 1) & 7u] : 0u);
    const uint32_t behind = n[(j + 4) & 7u] + (odd ? n[(j + 5) & 7u] : 0u);
    const uint32_t mm = odd ? 2 * m : m;
    if (m < threshold_ || !(mm > ahead && mm >= behind)) return;
    // Parabola through behind, centre, ahead: peak at (behind - ahead) / (2 (behind + ahead -
    // 2 mm)) steps; in 1/16 step 8 (behind - ahead) / (behind + ahead - 2 mm), whose denominator
    // is negative: q = round(8 |behind - ahead| / (2 mm - ahead - behind)), half away from 0,
    // with the sign of ahead - behind; limited to -8..7.
    const uint32_t num = behind > ahead ? behind - ahead : ahead - behind;
    const uint32_t den = 2 * mm - ahead - behind;
    const uint32_t q = (8 * num + den / 2) / den;
    int32_t delta = behind > ahead ? -static_cast<int32_t>(q) : static_cast<int32_t>(q);
    delta = delta > 7 ? 7 : delta < -8 ? -8 : delta;
    emit(eb::point(static_cast<uint32_t>(x), static_cast<uint32_t>(y), dir, delta, m), false, out);
}

void EdgeModel::push(const OutBeat& beat, std::vector<EdgeOutBeat>& out) {
    if (beat.tuser) {
        if (active_) throw std::logic_error("edge model: start of frame inside a frame");
        active_ = true;
        broken_ = false;
        threshold_ = per_frame_ ? frame_threshold(cfg_threshold_, beat.word) : cfg_threshold_;
        x_ = 0;
        y_ = 0;
    } else if (!active_) {
        throw std::logic_error("edge model: a gradient beat outside a frame");
    }
    if (x_ >= max_width_ || (y_ >= 1 && x_ >= width_) || (beat.eof && !beat.tlast) ||
        (y_ >= 1 && beat.tlast != (x_ == width_ - 1)))
        throw std::logic_error("edge model: a row of the wrong length");
    broken_ = broken_ || gradient_fill(beat.word);
    below_[static_cast<size_t>(x_)] = static_cast<uint16_t>(gradient_mag(beat.word));
    below_dir_[static_cast<size_t>(x_)] = static_cast<uint8_t>(gradient_dir(beat.word));
    if (y_ == 0 && beat.tlast) width_ = x_ + 1;
    const std::vector<uint16_t>& above = y_ >= 2 ? above_ : zero_;
    if (y_ >= 1 && x_ >= 1) decide(x_ - 1, y_ - 1, above, center_, center_dir_, below_, out);
    if (!beat.tlast) {
        ++x_;
        return;
    }
    if (y_ >= 1) decide(x_, y_ - 1, above, center_, center_dir_, below_, out);
    if (beat.eof) {
        // The last row: its lower neighbour row is outside the frame.
        const std::vector<uint16_t>& over = y_ >= 1 ? center_ : zero_;
        for (int x = 0; x < width_; ++x) decide(x, y_, over, below_, below_dir_, zero_, out);
        emit(eb::trailer(static_cast<uint32_t>(width_ - 1), static_cast<uint32_t>(y_), broken_),
             true, out);
        active_ = false;
        return;
    }
    above_.swap(center_);
    center_.swap(below_);
    center_dir_.swap(below_dir_);
    ++y_;
    x_ = 0;
}

void FrontModel::push(const InBeat& beat, std::vector<OutBeat>& words,
                      std::vector<EdgeOutBeat>& edges) {
    InBeat b = beat;
    if (b.tuser && b.height > kFrontMaxRows) b.height = 0;
    scratch_.clear();
    gradient_.push(b, scratch_);
    for (const OutBeat& w : scratch_) edges_.push(w, edges);
    words.insert(words.end(), scratch_.begin(), scratch_.end());
}

}  // namespace qt::vec
