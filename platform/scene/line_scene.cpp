#include "scene/line_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

#include "base/prng.h"
#include "scene/det_math.h"
#include "scene/random.h"

namespace qt::scene {

namespace {

constexpr double kMargin = 4;  // px between generated geometry and the outermost pixel centres

// One PCG stream per purpose, so e.g. the clutter count does not change the noise field.
constexpr uint64_t kStreamTexture = 0x7e47u, kStreamClutter = 0xc1a77u, kStreamNoise = 0x9015eu,
                   kStreamPolygons = 0x9017u, kStreamLines = 0x11e5u;

// Grey levels at least 60 from the background, kept in 10..245 so noise rarely clamps.
uint8_t contrasting_level(Pcg32& rng, int background) {
    const int dark = std::max(0, background - 60 - 10 + 1);       // levels 10..bg-60
    const int bright = std::max(0, 245 - (background + 60) + 1);  // levels bg+60..245
    const int i = static_cast<int>(rng.below(static_cast<uint32_t>(dark + bright)));
    return static_cast<uint8_t>(i < dark ? 10 + i : background + 60 + (i - dark));
}

// Crossing (even-odd) rule; half-open in y, so a sample on a vertex row counts once.
bool inside(const std::vector<Point2>& poly, double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Point2& a = poly[i];
        const Point2& b = poly[j];
        if ((a.y > y) != (b.y > y) && x < a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

double dist2_to_segment(Point2 a, Point2 b, double x, double y) {  // px^2
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0;
    t = std::min(1.0, std::max(0.0, t));
    const double ex = a.x + t * dx - x, ey = a.y + t * dy - y;
    return ex * ex + ey * ey;
}

// Composites `poly` of grey `level` over `buf` (w × h grey levels, row-major) by pixel coverage:
// exact 0/1 for pixels no edge comes near, else the fraction of 8×8 samples inside. With ramps,
// the level at pixel (x, y) is level + ramp_x·(x − poly[0].x) + ramp_y·(y − poly[0].y).
void paint(std::vector<double>& buf, int w, int h, const std::vector<Point2>& poly, double level,
           double ramp_x = 0, double ramp_y = 0) {
    const bool shaded = ramp_x != 0 || ramp_y != 0;
    double minx = poly[0].x, maxx = minx, miny = poly[0].y, maxy = miny;
    for (const Point2& p : poly) {
        minx = std::min(minx, p.x), maxx = std::max(maxx, p.x);
        miny = std::min(miny, p.y), maxy = std::max(maxy, p.y);
    }
    const double x0 = std::max(0.0, std::floor(minx - 0.5)),
                 x1 = std::min(w - 1.0, std::ceil(maxx + 0.5));
    const double y0 = std::max(0.0, std::floor(miny - 0.5)),
                 y1 = std::min(h - 1.0, std::ceil(maxy + 0.5));
    if (x0 > x1 || y0 > y1) return;
    for (int y = static_cast<int>(y0); y <= static_cast<int>(y1); ++y) {
        for (int x = static_cast<int>(x0); x <= static_cast<int>(x1); ++x) {
            bool near = false;  // an edge within half a pixel diagonal of the centre
            for (std::size_t i = 0, j = poly.size() - 1; i < poly.size() && !near; j = i++)
                near = dist2_to_segment(poly[j], poly[i], x, y) < 0.5 + 1e-9;
            double cover;
            if (!near) {
                cover = inside(poly, x, y) ? 1 : 0;
            } else {
                int n = 0;  // samples at offsets (i + 0.5) / 8 - 0.5 px
                for (int sy = 0; sy < 8; ++sy)
                    for (int sx = 0; sx < 8; ++sx)
                        n += inside(poly, x + (sx + 0.5) / 8 - 0.5, y + (sy + 0.5) / 8 - 0.5) ? 1
                                                                                              : 0;
                cover = n / 64.0;
            }
            double& v = buf[static_cast<std::size_t>(y) * w + x];
            const double here =
                shaded ? level + ramp_x * (x - poly[0].x) + ramp_y * (y - poly[0].y) : level;
            if (cover > 0) v += (here - v) * cover;
        }
    }
}

// Value noise: node values in [-amp, amp] on a grid of `cell` px, smoothstep-interpolated.
void add_value_noise(std::vector<double>& buf, int w, int h, double cell, double amp, Pcg32& rng) {
    const int gw = static_cast<int>(std::ceil(w / cell)) + 2,
              gh = static_cast<int>(std::ceil(h / cell)) + 2;
    std::vector<double> node(static_cast<std::size_t>(gw) * gh);
    for (double& n : node) n = amp * (2 * uniform01(rng) - 1);
    for (int y = 0; y < h; ++y) {
        const int iy = static_cast<int>(y / cell);
        double fy = y / cell - iy;
        fy = fy * fy * (3 - 2 * fy);
        for (int x = 0; x < w; ++x) {
            const int ix = static_cast<int>(x / cell);
            double fx = x / cell - ix;
            fx = fx * fx * (3 - 2 * fx);
            const double* r0 = &node[static_cast<std::size_t>(iy) * gw + ix];
            const double* r1 = r0 + gw;
            const double top = r0[0] + (r0[1] - r0[0]) * fx, bottom = r1[0] + (r1[1] - r1[0]) * fx;
            buf[static_cast<std::size_t>(y) * w + x] += top + (bottom - top) * fy;
        }
    }
}

// A random disc or ellipse (as a 64-gon) anywhere in the frame, semi-axes 3..min(w,h)/10 px.
std::vector<Point2> random_blob(Pcg32& rng, int w, int h) {
    const double cx = uniform(rng, 0, w - 1), cy = uniform(rng, 0, h - 1);
    const double a = uniform(rng, 3, std::max(4.0, std::min(w, h) / 10.0));
    const bool disc = rng.below(2) == 0;
    const double b = disc ? a : a * uniform(rng, 0.35, 0.9);
    double s, c;
    det_sincos(uniform(rng, 0, kPi), s, c);
    std::vector<Point2> poly(64);
    for (int k = 0; k < 64; ++k) {
        double sk, ck;
        det_sincos(2 * kPi * k / 64, sk, ck);
        poly[k] = {cx + a * ck * c - b * sk * s, cy + a * ck * s + b * sk * c};
    }
    return poly;
}

// Separable Gaussian, kernel radius ceil(3 sigma) px, replicated borders.
void blur(std::vector<double>& buf, int w, int h, double sigma) {
    const int r = static_cast<int>(std::ceil(3 * sigma));
    std::vector<double> k(2 * static_cast<std::size_t>(r) + 1);
    double sum = 0;
    for (int i = -r; i <= r; ++i) sum += k[i + r] = det_exp(-(i * i) / (2 * sigma * sigma));
    for (double& v : k) v /= sum;
    std::vector<double> tmp(buf.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double acc = 0;
            for (int i = -r; i <= r; ++i)
                acc += k[i + r] *
                       buf[static_cast<std::size_t>(y) * w + std::min(w - 1, std::max(0, x + i))];
            tmp[static_cast<std::size_t>(y) * w + x] = acc;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double acc = 0;
            for (int i = -r; i <= r; ++i)
                acc += k[i + r] *
                       tmp[static_cast<std::size_t>(std::min(h - 1, std::max(0, y + i))) * w + x];
            buf[static_cast<std::size_t>(y) * w + x] = acc;
        }
}

bool within(Point2 p, int w, int h) {
    return p.x >= kMargin && p.x <= w - 1 - kMargin && p.y >= kMargin && p.y <= h - 1 - kMargin;
}

double distance(Point2 a, Point2 b) {  // px
    return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
}

}  // namespace

LineScene::LineScene(const SceneOptions& options) : options_(options) {
    if (options.width < 1 || options.height < 1 || !(options.noise_sigma >= 0) ||
        !(options.blur_sigma >= 0) || options.clutter_blobs < 0 || options.clutter_texture < 0 ||
        !std::isfinite(options.illumination.centre_x) ||
        !std::isfinite(options.illumination.centre_y) ||
        !std::isfinite(options.illumination.centre_gain) ||
        !std::isfinite(options.illumination.ramp_x) ||
        !std::isfinite(options.illumination.ramp_y) || !(options.illumination.falloff >= 0) ||
        !std::isfinite(options.illumination.falloff))
        throw std::invalid_argument("LineScene: bad SceneOptions");
}

void LineScene::add_line(Point2 a, Point2 b, double width_px, uint8_t level) {
    const double len = distance(a, b);
    if (!(len > 0) || !(width_px > 0))
        throw std::invalid_argument("LineScene::add_line: empty line");
    const double nx = -(b.y - a.y) / len * (width_px / 2), ny = (b.x - a.x) / len * (width_px / 2);
    shapes_.push_back(
        {{{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}},
         static_cast<double>(level),
         0,
         0});
    truth_.push_back({a, b});
}

void LineScene::add_polygon(const std::vector<Point2>& vertices, uint8_t level) {
    add_shaded_polygon(vertices, level, 0, 0);
}

void LineScene::add_shaded_polygon(const std::vector<Point2>& vertices, double level, double ramp_x,
                                   double ramp_y) {
    if (vertices.size() < 3)
        throw std::invalid_argument("LineScene::add_polygon: fewer than 3 vertices");
    if (!std::isfinite(level) || !std::isfinite(ramp_x) || !std::isfinite(ramp_y))
        throw std::invalid_argument("LineScene::add_shaded_polygon: level or ramp not finite");
    shapes_.push_back({vertices, level, ramp_x, ramp_y});
    for (std::size_t i = 0; i < vertices.size(); ++i)
        truth_.push_back({vertices[i], vertices[(i + 1) % vertices.size()]});
}

void LineScene::set_background(std::vector<double> levels) {
    if (levels.size() != static_cast<std::size_t>(options_.width) * options_.height)
        throw std::invalid_argument("LineScene::set_background: not width × height levels");
    background_ = std::move(levels);
}

io::GreyImage LineScene::render() const {
    const int w = options_.width, h = options_.height;
    std::vector<double> buf =
        background_.empty()
            ? std::vector<double>(static_cast<std::size_t>(w) * h, options_.background)
            : background_;
    if (options_.clutter_texture > 0) {  // two octaves, peak amplitude clutter_texture
        Pcg32 rng(options_.seed, kStreamTexture);
        add_value_noise(buf, w, h, 32, 0.7 * options_.clutter_texture, rng);
        add_value_noise(buf, w, h, 11, 0.3 * options_.clutter_texture, rng);
    }
    if (options_.clutter_blobs > 0) {
        Pcg32 rng(options_.seed, kStreamClutter);
        for (int i = 0; i < options_.clutter_blobs; ++i) {
            const std::vector<Point2> blob = random_blob(rng, w, h);
            paint(buf, w, h, blob, rng.below(options_.clutter_blob_max + 1u));
        }
    }
    for (const Shape& s : shapes_) paint(buf, w, h, s.polygon, s.level, s.ramp_x, s.ramp_y);
    const SceneOptions::Illumination& light = options_.illumination;
    if (light.centre_gain != 1 || light.ramp_x != 0 || light.ramp_y != 0 || light.falloff != 0) {
        for (int y = 0; y < h; ++y) {
            const double dy = y - light.centre_y;
            for (int x = 0; x < w; ++x) {
                const double dx = x - light.centre_x;
                const double gain = light.centre_gain + light.ramp_x * dx + light.ramp_y * dy -
                                    light.falloff * (dx * dx + dy * dy);
                buf[static_cast<std::size_t>(y) * w + x] *= std::max(0.0, gain);
            }
        }
    }
    if (options_.blur_sigma > 0) blur(buf, w, h, options_.blur_sigma);
    if (options_.noise_sigma > 0) {
        Gaussian g(Pcg32(options_.seed, kStreamNoise));
        for (double& v : buf) v += options_.noise_sigma * g.next();
    }
    io::GreyImage img(w, h);
    for (std::size_t i = 0; i < buf.size(); ++i)
        img.pixels[i] =
            static_cast<uint8_t>(std::min(255.0, std::max(0.0, std::floor(buf[i] + 0.5))));
    return img;
}

bool uneven_illumination(int w, int h, double gain_lo, Pcg32& rng,
                         SceneOptions::Illumination* out) {
    // Pattern: a ramp of up to 1 per half diagonal along a random direction, minus a radial
    // falloff of 0.25–1 per half diagonal squared around a hot spot near the frame; then
    // rescaled so that its range over the pixel centres is [gain_lo, 1].
    const double half_diag =
        0.5 * std::sqrt(static_cast<double>(w) * w + static_cast<double>(h) * h);
    const double hot_x = uniform(rng, -0.25 * w, 1.25 * w),
                 hot_y = uniform(rng, -0.25 * h, 1.25 * h);
    double sd, cd;
    det_sincos(uniform(rng, 0, 2 * kPi), sd, cd);
    const double ramp = uniform(rng, 0, 1) / half_diag,
                 falloff = uniform(rng, 0.25, 1) / (half_diag * half_diag);
    double lo = 1e300, hi = -1e300;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = x - hot_x, dy = y - hot_y;
            const double g = ramp * cd * dx + ramp * sd * dy - falloff * (dx * dx + dy * dy);
            lo = std::min(lo, g), hi = std::max(hi, g);
        }
    if (!(gain_lo < 1 && hi > lo)) return false;
    const double k = (1 - gain_lo) / (hi - lo);
    out->centre_x = hot_x;
    out->centre_y = hot_y;
    out->centre_gain = gain_lo - k * lo;
    out->ramp_x = k * ramp * cd;
    out->ramp_y = k * ramp * sd;
    out->falloff = k * falloff;
    return true;
}

LineScene random_polygon_scene(const SceneOptions& options, int polygons, double min_side,
                               double min_corner_deg) {
    LineScene scene(options);
    const int w = options.width, h = options.height;
    // Vertices on a circle of radius R at angles 2πk/n ± 0.45π/n: convex; sides below
    // min_side are rejected below. R from 0.6 (a triangle's least) to 1.5 times min_side.
    const double r_min = 0.6 * min_side;
    const double r_fit = 0.5 * std::min(w - 1 - 2 * kMargin, h - 1 - 2 * kMargin);
    if (polygons < 0 || !(min_side > 0) || r_min > r_fit)
        throw std::invalid_argument("random_polygon_scene: polygons of that side do not fit");
    const double r_max = std::max(r_min, std::min(r_fit, 1.5 * min_side));
    double max_sine, max_cosine;  // cos(min_corner_deg) with the library-independent sincos
    det_sincos(min_corner_deg * kPi / 180.0, max_sine, max_cosine);
    Pcg32 rng(options.seed, kStreamPolygons);
    struct Circle {
        double x, y, r;
    };
    std::vector<Circle> placed;
    for (int p = 0; p < polygons; ++p) {
        for (int attempt = 0;; ++attempt) {
            if (attempt > 100000) throw std::runtime_error("random_polygon_scene: no placement");
            const int n = 3 + static_cast<int>(rng.below(2));
            const double r = uniform(rng, r_min, r_max);
            const double cx = uniform(rng, kMargin + r, w - 1 - kMargin - r);
            const double cy = uniform(rng, kMargin + r, h - 1 - kMargin - r);
            const double turn = uniform(rng, 0, 2 * kPi);
            std::vector<Point2> v(n);
            for (int k = 0; k < n; ++k) {
                double s, c;
                det_sincos(turn + 2 * kPi * k / n + uniform(rng, -0.45, 0.45) * kPi / n, s, c);
                v[k] = {cx + r * c, cy + r * s};
            }
            bool ok = true;
            for (int k = 0; k < n; ++k) {
                ok = ok && within(v[k], w, h) && distance(v[k], v[(k + 1) % n]) >= min_side;
                // Inner angle at v[k] from the two sides' vectors, degrees.
                const Point2 a = v[(k + n - 1) % n], b = v[(k + 1) % n];
                const double ux = a.x - v[k].x, uy = a.y - v[k].y, wx = b.x - v[k].x,
                             wy = b.y - v[k].y;
                const double cosine = (ux * wx + uy * wy) /
                                      (std::sqrt(ux * ux + uy * uy) * std::sqrt(wx * wx + wy * wy));
                ok = ok && cosine <= max_cosine;
            }
            // Circumcircles at least 4 px apart: no polygon hides another's sides, so every
            // truth segment is visible.
            bool overlap = false;
            for (const Circle& c : placed)
                overlap = overlap || distance({cx, cy}, {c.x, c.y}) < r + c.r + 4;
            if (!ok || overlap) continue;
            scene.add_polygon(v, contrasting_level(rng, options.background));
            placed.push_back({cx, cy, r});
            break;
        }
    }
    return scene;
}

LineScene random_line_scene(const SceneOptions& options, int lines, double min_len,
                            double max_len) {
    LineScene scene(options);
    const int w = options.width, h = options.height;
    const double bw = w - 1 - 2 * kMargin, bh = h - 1 - 2 * kMargin;  // px, room for end points
    const double diagonal =
        std::sqrt(std::max(0.0, bw * std::fabs(bw)) + std::max(0.0, bh * std::fabs(bh)));
    if (lines < 0 || !(min_len > 0) || !(min_len <= max_len) || min_len > diagonal)
        throw std::invalid_argument("random_line_scene: bad or unfitting lengths");
    Pcg32 rng(options.seed, kStreamLines);
    for (int i = 0; i < lines; ++i) {
        for (int attempt = 0;; ++attempt) {
            if (attempt > 100000) throw std::runtime_error("random_line_scene: no placement");
            const double len = uniform(rng, min_len, std::min(max_len, diagonal));
            double s, c;
            det_sincos(uniform(rng, 0, 2 * kPi), s, c);
            const double dx = len * c, dy = len * s;
            if (std::fabs(dx) > bw || std::fabs(dy) > bh) continue;
            const double mx =
                uniform(rng, kMargin + std::fabs(dx) / 2, w - 1 - kMargin - std::fabs(dx) / 2);
            const double my =
                uniform(rng, kMargin + std::fabs(dy) / 2, h - 1 - kMargin - std::fabs(dy) / 2);
            const Point2 a{mx - dx / 2, my - dy / 2}, b{mx + dx / 2, my + dy / 2};
            const double l = distance(a, b);
            if (!within(a, w, h) || !within(b, w, h) || l < min_len || l > max_len) continue;
            scene.add_line(a, b, 2.0, contrasting_level(rng, options.background));
            break;
        }
    }
    return scene;
}

}  // namespace qt::scene
