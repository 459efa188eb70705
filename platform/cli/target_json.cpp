#include "cli/target_json.h"

#include <cstdio>

#include "host/board_runner.h"

namespace qt::cli {

namespace {

std::string num(double v, const char* format = "%.6g") {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace

std::string homography_json(const FrameHomography& g, unsigned features_a, unsigned features_b,
                            uint8_t bin_a, uint8_t bin_b) {
    std::string s = "{\"H\":";
    if (g.ransac.status == HomographyStatus::ok) {
        // In the inputs' pixels: H' = S_B · H · S_A⁻¹, S = [[N, 0, c], [0, N, c], [0, 0, 1]]
        // with c = (N − 1)/2 taking a binned pixel to the input's (binning.h), scaled so that
        // H'[2][2] = 1.
        double h[9];
        for (int i = 0; i < 9; ++i) h[i] = g.ransac.h.m[i];
        const double na = bin_a, ca = (bin_a - 1) / 2.0, nb = bin_b, cb = (bin_b - 1) / 2.0;
        double m[9];  // H · S_A⁻¹, S_A⁻¹ = [[1/na, 0, −ca/na], [0, 1/na, −ca/na], [0, 0, 1]]
        for (int r = 0; r < 3; ++r) {
            m[3 * r] = h[3 * r] / na;
            m[3 * r + 1] = h[3 * r + 1] / na;
            m[3 * r + 2] = h[3 * r + 2] - (h[3 * r] + h[3 * r + 1]) * ca / na;
        }
        double o[9];  // S_B · m
        for (int c = 0; c < 3; ++c) {
            o[c] = nb * m[c] + cb * m[6 + c];
            o[3 + c] = nb * m[3 + c] + cb * m[6 + c];
            o[6 + c] = m[6 + c];
        }
        const double scale = o[8];
        s += "[";
        for (int r = 0; r < 3; ++r) {
            s += r ? ",[" : "[";
            for (int c = 0; c < 3; ++c) s += (c ? "," : "") + num(o[3 * r + c] / scale, "%.9g");
            s += "]";
        }
        s += "]";
    } else {
        s += "null";
    }
    s += ",\"inliers\":" + std::to_string(g.ransac.inliers) +
         ",\"matches\":" + std::to_string(g.matches) + ",\"status\":\"" +
         homography_status_name(g.ransac.status) + "\",\"reprojection_px\":" +
         (g.ransac.status == HomographyStatus::ok ? num(g.ransac.reprojection_px * bin_b, "%.4f")
                                                  : std::string("null")) +
         ",\"features\":[" + std::to_string(features_a) + "," + std::to_string(features_b) +
         "],\"bin\":[" + std::to_string(bin_a) + "," + std::to_string(bin_b) + "]}";
    return s;
}

std::string target_json(int frame, const TargetFrame& f, uint8_t bin) {
    const TargetEstimate& e = f.estimate;
    return "{\"frame\":" + std::to_string(frame) +
           ",\"x\":" + num(host::input_pixel(e.x, bin), "%.2f") +
           ",\"y\":" + num(host::input_pixel(e.y, bin), "%.2f") + ",\"state\":\"" +
           target_state_name(e.state) + "\",\"nds\":" + num(e.nds, "%.3f") +
           ",\"reset\":" + (e.reset ? "true" : "false") +
           ",\"matches\":" + std::to_string(f.geometry.matches) +
           ",\"inliers\":" + std::to_string(f.geometry.ransac.inliers) +
           ",\"bin\":" + std::to_string(bin) + "}";
}

}  // namespace qt::cli
