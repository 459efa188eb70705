#include "edge_stage.h"

#include "fixed.h"

namespace qt {

void pack_nms_row(const gradient_word* words, uint16_t width, uint16_t* row) {
    row[0] = 0;
    for (uint16_t x = 0; x < width; ++x)
        row[x + 1] = static_cast<uint16_t>(gradient_mag(words[x]) | (gradient_dir(words[x]) << 9));
    row[width + 1] = 0;
}

void nms_row(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t width, uint16_t y,
             uint16_t edge_threshold, EdgeList& out) {
    out.begin_row(y);
    // Index i = x + 1 in the padded rows.
    for (uint32_t i = 1; i <= width; ++i) {
        const uint32_t m = c[i] & 0x1FFu;
        if (m < edge_threshold) continue;
        const uint32_t dir = (c[i] >> 9) & 15u;
        auto M = [](const uint16_t* r, uint32_t k) { return static_cast<uint32_t>(r[k] & 0x1FFu); };
        uint32_t ahead, behind, mm = 2 * m;  // odd axes compare 2m with a sum of two
        switch (dir & 7u) {  // ahead = along +gradient (y down), behind = along -gradient
            case 0: ahead = M(c, i + 1); behind = M(c, i - 1); mm = m; break;
            case 2: ahead = M(b, i + 1); behind = M(a, i - 1); mm = m; break;
            case 4: ahead = M(b, i); behind = M(a, i); mm = m; break;
            case 6: ahead = M(b, i - 1); behind = M(a, i + 1); mm = m; break;
            case 1: ahead = M(c, i + 1) + M(b, i + 1); behind = M(c, i - 1) + M(a, i - 1); break;
            case 3: ahead = M(b, i + 1) + M(b, i); behind = M(a, i - 1) + M(a, i); break;
            case 5: ahead = M(b, i) + M(b, i - 1); behind = M(a, i) + M(a, i + 1); break;
            default: ahead = M(b, i - 1) + M(c, i - 1); behind = M(a, i + 1) + M(c, i + 1); break;
        }
        // Bins 8..15 point the other way along the same axis: swap the roles so that the tie
        // rule follows the gradient, not the axis.
        if (dir >= 8) {
            const uint32_t t = ahead;
            ahead = behind;
            behind = t;
        }
        if (!(mm > ahead && mm >= behind)) continue;
        // Parabola through (behind, mm, ahead) at -1, 0, +1: peak at
        // (behind - ahead) / (2·(behind - 2mm + ahead)) steps, in [-1/2, 1/2) by the tests above;
        // in 1/16 step: 8·(behind - ahead) / (behind + ahead - 2mm), rounded half away.
        const int32_t num = 8 * (static_cast<int32_t>(behind) - static_cast<int32_t>(ahead));
        const int32_t den = static_cast<int32_t>(behind + ahead) - 2 * static_cast<int32_t>(mm);
        int32_t delta16 = static_cast<int32_t>(div_round_half_away(num, den));
        delta16 = delta16 < -8 ? -8 : delta16 > 7 ? 7 : delta16;
        out.push(static_cast<uint16_t>(i - 1), dir, delta16);
    }
}

}  // namespace qt
