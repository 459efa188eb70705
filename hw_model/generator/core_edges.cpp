#include "core_edges.h"

#include <memory>

#include "gradient/gradient_stage.h"
#include "lines/edge_stage.h"

namespace qt::vec {

namespace {

constexpr uint16_t kMaxWidth = 2048, kMaxRows = 2048;
constexpr uint16_t kCapacity = 65532;  // the list's largest capacity (a multiple of 4)

struct Core {
    GradientStage<kMaxWidth> gradient;
    EdgeStage<kMaxWidth> edges;
    EdgeListStorage<kCapacity, kMaxRows> storage;
    // Magnitude of every gradient word of the frame, to give each point its exact magnitude
    // (the list keeps magnitude / 2).
    std::vector<uint16_t> mags;
};

}  // namespace

bool core_edge_beats(const io::GreyImage& img, uint16_t threshold, std::vector<edge_beat>& beats,
                     std::string& why) {
    beats.clear();
    if (img.width < 1 || img.width > kMaxWidth || img.height < 1 || img.height > kMaxRows) {
        why = "frame size outside core's capacity here";
        return false;
    }
    auto core = std::make_unique<Core>();
    EdgeList list = core->storage.view();
    const auto w = static_cast<uint16_t>(img.width), h = static_cast<uint16_t>(img.height);
    core->mags.assign(static_cast<size_t>(w) * h, 0);
    if (core->gradient.begin_frame(w, h) != Status::ok ||
        core->edges.begin_frame(w, h, threshold, list) != Status::ok) {
        why = "core refused the frame";
        return false;
    }
    Status edge_status = Status::ok;
    auto sink = [&](uint16_t y, const gradient_word* words, uint16_t width) {
        for (uint16_t x = 0; x < width; ++x)
            core->mags[static_cast<size_t>(y) * w + x] =
                static_cast<uint16_t>(gradient_mag(words[x]));
        const Status s = core->edges.push_row(words, width);
        if (s != Status::ok) edge_status = s;
    };
    for (int y = 0; y < img.height; ++y)
        if (core->gradient.push_row(img.row(y), w, sink) != Status::ok) {
            why = "core refused a row";
            return false;
        }
    if (edge_status != Status::ok || core->edges.in_frame()) {
        why = "core's edge stage did not finish the frame";
        return false;
    }
    if (list.dropped() != 0) {
        why = "more edges than core's list holds";
        return false;
    }
    for (uint16_t i = 0; i < list.size(); ++i) {
        const edge_point p = list[i];
        const uint32_t mag = core->mags[static_cast<size_t>(ep::y(p)) * w + ep::x(p)];
        beats.push_back(eb::point(ep::x(p), ep::y(p), ep::dir(p), ep::delta16(p), mag));
    }
    beats.push_back(eb::trailer(w - 1u, h - 1u, false));
    return true;
}

}  // namespace qt::vec
