// Small fixed-size matrices in double precision for the tests' reference Kalman filters: no
// structure assumed, straight from the textbook equations.
#pragma once

namespace qt::test {

template <int R, int C>
struct Mat {
    double m[R][C] = {};
};

template <int R, int K, int C>
Mat<R, C> operator*(const Mat<R, K>& a, const Mat<K, C>& b) {
    Mat<R, C> out;
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j)
            for (int k = 0; k < K; ++k) out.m[i][j] += a.m[i][k] * b.m[k][j];
    return out;
}
template <int R, int C>
Mat<R, C> operator+(const Mat<R, C>& a, const Mat<R, C>& b) {
    Mat<R, C> out;
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out.m[i][j] = a.m[i][j] + b.m[i][j];
    return out;
}
template <int R, int C>
Mat<R, C> operator-(const Mat<R, C>& a, const Mat<R, C>& b) {
    Mat<R, C> out;
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out.m[i][j] = a.m[i][j] - b.m[i][j];
    return out;
}
template <int R, int C>
Mat<C, R> transpose(const Mat<R, C>& a) {
    Mat<C, R> out;
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out.m[j][i] = a.m[i][j];
    return out;
}

}  // namespace qt::test
