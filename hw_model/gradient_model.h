// Bit-accurate, beat-level model of hdl/rtl/gradient.v: the same widths, border rule, framing and
// error behaviour (docs/gradient.md), but none of its clocks. Feed it the accepted input beats
// in order; it returns the output beats the block emits, in order.
#pragma once
#include <stdint.h>

#include <vector>

#include "vector_format.h"

namespace qt::vec {

class GradientModel {
public:
    explicit GradientModel(int max_width);

    // Process one accepted input beat; append the words it makes the block emit to `out`.
    void push(const InBeat& beat, std::vector<OutBeat>& out);

    int errors() const { return errors_; }  // error pulses so far

private:
    enum class State { idle, row0, rows };

    void start_frame(const InBeat& beat, std::vector<OutBeat>& out);
    void emit(int x, const std::vector<uint8_t>& above, const std::vector<uint8_t>& center,
              const std::vector<uint8_t>& below, bool last_of_row, bool eof,
              std::vector<OutBeat>& out);
    // A framing error: the frame in progress is abandoned. Once its row 0 is complete, the
    // output row in progress is completed with fill words and ends the frame.
    void fail(std::vector<OutBeat>& out);

    int max_width_;
    State state_ = State::idle;
    int width_ = 0, height_ = 0, x_ = 0, y_ = 0, errors_ = 0;
    bool first_word_pending_ = false;              // the next word emitted carries tuser
    std::vector<uint8_t> above_, center_, below_;  // rows y-2, y-1 and the arriving row y
};

// Run a whole beat stream through a fresh model.
std::vector<OutBeat> run_model(const std::vector<InBeat>& in, int max_width, int* errors);

}  // namespace qt::vec
