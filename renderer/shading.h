// Shading, kept out of the pipeline (as tinyrenderer's IShader): the pipeline
// finds the visible triangle of each pixel and interpolates its attributes
// into a Fragment; a Shader turns that into a colour and a normal. A new render
// mode is a new Shader; the rasterizer does not change (docs/design.md: Rendering).
#pragma once
#include "renderer/lanes.h"
#include "renderer/scene.h"

#include <Eigen/Core>
#include <memory>

namespace boxlod {

// A triangle's uv gradient in world space: uv per metre.
struct UvGradient {
    Eigen::Vector3f du_dposition, dv_dposition;
};

// The interpolated inputs of one pixel, in world space.
struct Fragment {
    Eigen::Vector3f position, normal, geometric_normal;
    Eigen::Vector2f uv{0, 0}, duv_dx{0, 0}, duv_dy{0, 0};  // uv and its change one pixel right and down
    // Tangent frame: tangent along +u, bitangent up the image (against +v), as
    // glTF's B = cross(N, T) * w; normal maps store (T, B, N) components.
    Eigen::Vector3f tangent{1, 0, 0}, bitangent{0, 1, 0};
    // Set only where the surface's height map states its depth: a metric
    // parallax offset maps to uv through it (docs/design.md: Rendering).
    const UvGradient* uv_gradient = nullptr;
    bool has_uv = false;
};

struct ShadedPixel {
    Eigen::Vector3f color;   // linear RGB
    Eigen::Vector3f normal;  // the shading normal, facing the viewer
    float alpha = 1;         // base colour alpha x colour map alpha: the blend weight of AlphaMode::blend
};

// The inputs of lane_count pixels at once, made by the pipeline in lanes
// (renderer/lanes.h), each lane with the bits make_fragment gives its pixel.
// Lanes from `count` on repeat the last pixel and are not written.
struct FragmentLanes {
    Vector3Lanes position, normal, geometric_normal;
    // Made only for shaders that read uvs (Fragment's defaults elsewhere).
    FloatLanes u, v, du_dx, dv_dx, du_dy, dv_dy;
    Vector3Lanes tangent, bitangent;
    IntLanes has_uv;
    const UvGradient* uv_gradient[lane_count];  // as Fragment's
    const Surface* surface[lane_count];
    int count;
};

// Lane j as a Fragment.
Fragment fragment_of(const FragmentLanes& lanes, int j);

struct ShadedLanes {
    Vector3Lanes color, normal;
    FloatLanes alpha;
};

class Shader {
public:
    virtual ~Shader() = default;
    // False: the shader never reads uvs, and the pipeline skips them, their
    // derivatives and the tangent frame (has_uv stays false).
    virtual bool reads_uv() const = 0;
    // `fragment` may be turned to face the viewer on the way.
    virtual ShadedPixel shade(const Surface& surface, Fragment& fragment) const = 0;
    // Opaque pixels are handed over lane_count at once, with the same result
    // as shade() on each; by default each lane goes through shade().
    virtual void shade_lanes(const FragmentLanes& fragments, ShadedLanes& shaded) const;
    // False: the pipeline makes each pixel's fragment on its own, as for
    // blended surfaces, and calls shade() (the reference lanes are tested against).
    virtual bool takes_lanes() const { return true; }
};

// The shader of a render mode, lit by settings.light and seen from `eye`.
std::unique_ptr<Shader> make_shader(const RenderSettings& settings, const Eigen::Vector3f& eye);

}  // namespace boxlod
