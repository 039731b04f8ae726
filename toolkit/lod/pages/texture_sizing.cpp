#include "toolkit/lod/pages/texture_sizing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace boxlod {

double half_fovy_tangent(float fovy_degrees) {
    thread_local float last_fovy = std::numeric_limits<float>::quiet_NaN();
    thread_local double tangent = 0;
    if (!(fovy_degrees == last_fovy)) {
        tangent = std::tan(double(fovy_degrees) * M_PI / 360);
        last_fovy = fovy_degrees;
    }
    return tangent;
}

double pixel_world_size(const TextureSizing& s) {
    return 2 * double(s.distance) * half_fovy_tangent(s.fovy_degrees) / double(s.resolution);
}

TextureSizing coarser_sizing(const TextureSizing& sizing, double factor) {
    TextureSizing coarser = sizing;
    coarser.distance *= float(factor);
    return coarser;
}

namespace {
// ceil that forgives rounding noise: a face of 50.0001 texels gets 50.
double texel_ceil(double texels) { return std::ceil(texels - 1e-3); }
}  // namespace

Eigen::Vector2i face_texels(float a, float b, const TextureSizing& s) {
    double p = pixel_world_size(s);
    double wide = texel_ceil(double(a) / p), high = texel_ceil(double(b) / p);
    double limit = s.max_texture_size - 2 * s.gutter;
    double longest = std::max(wide, high);
    if (longest > limit) {  // keep the aspect ratio, give up the 1:1 mapping
        wide = texel_ceil(wide * limit / longest);
        high = texel_ceil(high * limit / longest);
    }
    return {int(std::clamp(wide, 1.0, limit)), int(std::clamp(high, 1.0, limit))};
}

float min_distance(float longest_side, const TextureSizing& s) {
    // ceil(a / p) <= limit  <=>  p >= a / limit  <=>  d >= a / limit * resolution / (2 tan(fovy / 2)).
    float limit = float(s.max_texture_size - 2 * s.gutter);
    return longest_side / limit * s.resolution / (2 * std::tan(s.fovy_degrees * float(M_PI) / 360));
}

}  // namespace boxlod
