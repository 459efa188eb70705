#include "cli/target_json.h"

#include <cstdio>

namespace qt::cli {

namespace {

std::string num(double v, const char* format = "%.6g") {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace

std::string homography_json(const FrameHomography& g, unsigned features_a, unsigned features_b) {
    std::string s = "{\"H\":";
    if (g.ransac.status == HomographyStatus::ok) {
        s += "[";
        for (int r = 0; r < 3; ++r) {
            s += r ? ",[" : "[";
            for (int c = 0; c < 3; ++c) s += (c ? "," : "") + num(g.ransac.h.m[3 * r + c], "%.9g");
            s += "]";
        }
        s += "]";
    } else {
        s += "null";
    }
    s += ",\"inliers\":" + std::to_string(g.ransac.inliers) +
         ",\"matches\":" + std::to_string(g.matches) + ",\"status\":\"" +
         homography_status_name(g.ransac.status) +
         "\",\"reprojection_px\":" + num(g.ransac.reprojection_px, "%.4f") + ",\"features\":[" +
         std::to_string(features_a) + "," + std::to_string(features_b) + "]}";
    return s;
}

std::string target_json(int frame, const TargetFrame& f) {
    const TargetEstimate& e = f.estimate;
    return "{\"frame\":" + std::to_string(frame) + ",\"x\":" + num(e.x, "%.2f") +
           ",\"y\":" + num(e.y, "%.2f") + ",\"state\":\"" + target_state_name(e.state) +
           "\",\"nds\":" + num(e.nds, "%.3f") + ",\"reset\":" + (e.reset ? "true" : "false") +
           ",\"matches\":" + std::to_string(f.geometry.matches) +
           ",\"inliers\":" + std::to_string(f.geometry.ransac.inliers) + "}";
}

}  // namespace qt::cli
