// Four pixels computed at once: SSE2 lanes through GCC's vector extensions.
// Each lane rounds as the scalar code does, operation for operation and in
// the same order (Eigen's included), so a lane's result has the scalar
// result's bits and renders do not change (docs/performance.md: Lanes).
#pragma once
#include <immintrin.h>
#include <Eigen/Core>
#include <cstdint>
#include <cstring>

namespace boxlod {

constexpr int lane_count = 4;
using FloatLanes = float __attribute__((vector_size(16)));
using IntLanes = std::int32_t __attribute__((vector_size(16)));  // comparisons: -1 true, 0 false

struct Vector3Lanes {
    FloatLanes x, y, z;
};

struct Vector4Lanes {
    FloatLanes x, y, z, w;
};

inline FloatLanes broadcast(float value) { return FloatLanes{value, value, value, value}; }
// Floats p[0] and p[1] into lanes 0 and 1, the others 0: one 8-byte load
// (memcpy, since floats need not lie on 8-byte boundaries).
inline __m128 load_two(const float* p) {
    double two;
    std::memcpy(&two, p, sizeof two);
    return _mm_castpd_ps(_mm_set_sd(two));
}
// In registers (see DoubleLanes).
inline FloatLanes from_scalars(float a, float b, float c, float d) {
    return _mm_movelh_ps(_mm_unpacklo_ps(_mm_set_ss(a), _mm_set_ss(b)),
                         _mm_unpacklo_ps(_mm_set_ss(c), _mm_set_ss(d)));
}
inline Vector3Lanes broadcast(const Eigen::Vector3f& v) {
    return {broadcast(v.x()), broadcast(v.y()), broadcast(v.z())};
}
inline Eigen::Vector3f lane(const Vector3Lanes& v, int j) { return {v.x[j], v.y[j], v.z[j]}; }
inline void set_lane(Vector3Lanes& v, int j, const Eigen::Vector3f& value) {
    v.x[j] = value.x();
    v.y[j] = value.y();
    v.z[j] = value.z();
}
inline FloatLanes square_root(FloatLanes v) { return _mm_sqrt_ps(v); }
inline FloatLanes select(IntLanes mask, FloatLanes a, FloatLanes b) { return mask ? a : b; }
inline Vector3Lanes select(IntLanes mask, const Vector3Lanes& a, const Vector3Lanes& b) {
    return {mask ? a.x : b.x, mask ? a.y : b.y, mask ? a.z : b.z};
}
// std::max(0.0f, v): v where 0 < v, else 0 (NaN too).
inline FloatLanes max_zero(FloatLanes v) { return 0 < v ? v : FloatLanes{}; }

inline Vector3Lanes operator+(const Vector3Lanes& a, const Vector3Lanes& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vector3Lanes operator-(const Vector3Lanes& a, const Vector3Lanes& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vector3Lanes operator-(const Vector3Lanes& a) { return {-a.x, -a.y, -a.z}; }
inline Vector3Lanes operator*(const Vector3Lanes& a, FloatLanes s) { return {a.x * s, a.y * s, a.z * s}; }
inline Vector3Lanes operator/(const Vector3Lanes& a, FloatLanes s) { return {a.x / s, a.y / s, a.z / s}; }

// Four doubles as two SSE2 registers. (GCC's 32-byte vectors without AVX pass
// through memory, and a vector load of fresh scalar stores waits for every
// store before it: the frame's, which miss the cache.)
struct DoubleLanes {
    __m128d low, high;
};
inline DoubleLanes broadcast(double value) { return {_mm_set1_pd(value), _mm_set1_pd(value)}; }
inline DoubleLanes to_doubles(IntLanes v) {
    return {_mm_cvtepi32_pd(__m128i(v)), _mm_cvtepi32_pd(_mm_shuffle_epi32(__m128i(v), 0xee))};
}
inline DoubleLanes to_doubles(FloatLanes v) { return {_mm_cvtps_pd(v), _mm_cvtps_pd(_mm_movehl_ps(v, v))}; }
inline DoubleLanes square_root(const DoubleLanes& v) { return {_mm_sqrt_pd(v.low), _mm_sqrt_pd(v.high)}; }
inline FloatLanes to_floats(const DoubleLanes& v) {
    return _mm_movelh_ps(_mm_cvtpd_ps(v.low), _mm_cvtpd_ps(v.high));
}
inline DoubleLanes operator+(const DoubleLanes& a, const DoubleLanes& b) {
    return {a.low + b.low, a.high + b.high};
}
inline DoubleLanes operator-(const DoubleLanes& a, const DoubleLanes& b) {
    return {a.low - b.low, a.high - b.high};
}
inline DoubleLanes operator*(const DoubleLanes& a, const DoubleLanes& b) {
    return {a.low * b.low, a.high * b.high};
}
inline DoubleLanes operator/(const DoubleLanes& a, const DoubleLanes& b) {
    return {a.low / b.low, a.high / b.high};
}
inline DoubleLanes operator+(const DoubleLanes& a, double b) { return a + broadcast(b); }
inline DoubleLanes operator-(double a, const DoubleLanes& b) { return broadcast(a) - b; }
inline DoubleLanes operator*(const DoubleLanes& a, double b) { return a * broadcast(b); }
inline IntLanes not_zero(const DoubleLanes& v) {
    const __m128d zero = _mm_setzero_pd();
    return IntLanes(_mm_shuffle_ps(_mm_castpd_ps(_mm_cmpneq_pd(v.low, zero)),
                                   _mm_castpd_ps(_mm_cmpneq_pd(v.high, zero)), _MM_SHUFFLE(2, 0, 2, 0)));
}

// Eigen sums three terms as x + (y + z): its reductions split in halves.
inline FloatLanes dot(const Vector3Lanes& a, const Vector3Lanes& b) {
    return a.x * b.x + (a.y * b.y + a.z * b.z);
}
// Eigen's cross() of 3-vectors.
inline Vector3Lanes cross(const Vector3Lanes& a, const Vector3Lanes& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// Eigen's normalized(): v / sqrt(|v|^2) where |v|^2 > 0, else v.
inline Vector3Lanes normalized(const Vector3Lanes& v) {
    FloatLanes squared = dot(v, v);
    return select(squared > 0, v / square_root(squared), v);
}

}  // namespace boxlod
