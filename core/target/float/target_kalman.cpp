#include "target/float/target_kalman.h"

namespace qt {

void TargetKalman::init(float x, float y, const TargetKalmanParams& params) {
    params_ = params;
    x_[0] = x;
    x_[1] = y;
    x_[2] = 0;
    x_[3] = 0;
    for (auto& row : p_)
        for (float& v : row) v = 0;
    p_[0][0] = p_[1][1] = params.r;
    p_[2][2] = p_[3][3] = params.p0_vel;
}

void TargetKalman::predict() {
    x_[0] += x_[2];
    x_[1] += x_[3];
    // P ← Φ P Φᵀ + Q with Φ = [[I, I], [0, I]] in 2×2 blocks [[A, B], [Bᵀ, C]]:
    // A ← A + B + Bᵀ + C, B ← B + C, C unchanged; then + Q.
    float n[4][4];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            float v = p_[i][j];
            if (i < 2) v += p_[i + 2][j];
            if (j < 2) v += p_[i][j + 2];
            if (i < 2 && j < 2) v += p_[i + 2][j + 2];
            n[i][j] = v;
        }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p_[i][j] = n[i][j];
    p_[0][0] += params_.q_pos;
    p_[1][1] += params_.q_pos;
    p_[2][2] += params_.q_vel;
    p_[3][3] += params_.q_vel;
    symmetrise();
}

Innovation TargetKalman::innovation(float zx, float zy) const {
    Innovation in;
    in.nu_x = zx - x_[0];
    in.nu_y = zy - x_[1];
    in.s[0] = p_[0][0] + params_.r;
    in.s[1] = p_[0][1];
    in.s[2] = p_[1][1] + params_.r;
    in.det_s = in.s[0] * in.s[2] - in.s[1] * in.s[1];
    // S is positive definite (P >= 0, r > 0): det S >= r² > 0, no division by zero.
    in.nds = (in.s[2] * in.nu_x * in.nu_x - 2.0f * in.s[1] * in.nu_x * in.nu_y +
              in.s[0] * in.nu_y * in.nu_y) /
             in.det_s;
    return in;
}

void TargetKalman::update(const Innovation& in) {
    // S⁻¹ = [[s2, −s1], [−s1, s0]] / det S;  K = P Hᵀ S⁻¹ (4×2, P Hᵀ = P's first two columns).
    const float inv_det = 1.0f / in.det_s;
    const float si[3] = {in.s[2] * inv_det, -in.s[1] * inv_det, in.s[0] * inv_det};
    float k[4][2];
    for (int i = 0; i < 4; ++i) {
        k[i][0] = p_[i][0] * si[0] + p_[i][1] * si[1];
        k[i][1] = p_[i][0] * si[1] + p_[i][1] * si[2];
    }
    for (int i = 0; i < 4; ++i) x_[i] += k[i][0] * in.nu_x + k[i][1] * in.nu_y;
    // P ← P − K S Kᵀ = P − K (H P): (H P) is P's first two rows.
    float hp[2][4];
    for (int j = 0; j < 4; ++j) {
        hp[0][j] = p_[0][j];
        hp[1][j] = p_[1][j];
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p_[i][j] -= k[i][0] * hp[0][j] + k[i][1] * hp[1][j];
    symmetrise();
}

bool homography_jacobian(const Homography& h, float x, float y, float j[4]) {
    float xo, yo;
    if (!apply_homography(h, x, y, xo, yo)) return false;
    // (x', y') = (h1 x + h2 y + h3, h4 x + h5 y + h6) / w, w = h7 x + h8 y + h9:
    // J = ([[h1, h2], [h4, h5]] − (x', y')ᵀ [h7, h8]) / w; w is not ~0 (apply succeeded).
    const float* m = h.m;
    const float w = m[6] * x + m[7] * y + m[8];
    j[0] = (m[0] - xo * m[6]) / w;
    j[1] = (m[1] - xo * m[7]) / w;
    j[2] = (m[3] - yo * m[6]) / w;
    j[3] = (m[4] - yo * m[7]) / w;
    return true;
}

bool TargetKalman::change_frame(const Homography& h) {
    float xo, yo, jac[4];
    if (!apply_homography(h, x_[0], x_[1], xo, yo) || !homography_jacobian(h, x_[0], x_[1], jac))
        return false;
    const float j[2][2] = {{jac[0], jac[1]}, {jac[2], jac[3]}};
    x_[0] = xo;
    x_[1] = yo;
    const float vx = x_[2], vy = x_[3];
    x_[2] = j[0][0] * vx + j[0][1] * vy;
    x_[3] = j[1][0] * vx + j[1][1] * vy;
    // P ← T P Tᵀ, T = diag(J, J).
    float t[4][4] = {};
    for (int b = 0; b < 4; b += 2)
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) t[b + r][b + c] = j[r][c];
    float tp[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            float v = 0;
            for (int k = 0; k < 4; ++k) v += t[r][k] * p_[k][c];
            tp[r][c] = v;
        }
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            float v = 0;
            for (int k = 0; k < 4; ++k) v += tp[r][k] * t[c][k];
            p_[r][c] = v;
        }
    symmetrise();
    return true;
}

void TargetKalman::symmetrise() {
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) p_[i][j] = p_[j][i] = 0.5f * (p_[i][j] + p_[j][i]);
}

}  // namespace qt
