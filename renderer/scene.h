// What the renderer draws and how (docs/design.md: Rendering): meshes with
// their surfaces, the light, the render mode and the settings of a render.
// The pipeline (renderer.h) and the shaders (shading.h) both read these.
#pragma once
#include "base/enum_table.h"
#include "renderer/camera.h"
#include "renderer/rasterizer.h"
#include "renderer/texture.h"

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

enum class RenderMode {
    untextured,  // material colour only, vertex normals
    normal,      // albedo x Blinn-Phong, normal from the normal map
    parallax,    // texture coordinates offset by height (scale, bias), then as normal
    pom,         // parallax occlusion mapping (ray march through the height map)
    albedo,      // unlit albedo (material colour x texture): what baking records
};
std::span<const EnumEntry<RenderMode>> render_modes();  // names ("untextured", ...) and help
bool parse_render_mode(const std::string& name, RenderMode& mode);
const char* render_mode_name(RenderMode mode);

// The maps a mode's colour image reads: what an engine drawing that way loads
// (docs/design.md: Cost). Albedo's normal output reads the normal map too, but
// its picture does not.
struct MapsDrawn {
    bool color = false, normal = false, height = false;
};
MapsDrawn maps_drawn(RenderMode mode);

// A triangle list; every attribute but positions may be empty.
struct Mesh {
    std::vector<Eigen::Vector3f> positions, normals;
    std::vector<Eigen::Vector2f> uvs;
    std::vector<Eigen::Vector4f> tangents;  // xyz + handedness w
    std::vector<std::uint32_t> indices;
};

// glTF 2.0 alphaMode (spec 3.9.4: Alpha Coverage). The alpha is base_color.w x
// the colour map's alpha. Blended triangles are composited source-over after
// every opaque and masked one (docs/design.md: Rendering).
enum class AlphaMode {
    opaque,  // alpha ignored
    mask,    // fragments with alpha < alpha_cutoff are dropped (baked box faces: uncovered texels)
    blend,   // source-over, no depth write (glass)
};
std::span<const EnumEntry<AlphaMode>> alpha_modes();  // glTF's names: "OPAQUE", "MASK", "BLEND"
constexpr NumberRange alpha_cutoff_range{0, 1};

struct Surface {
    Eigen::Vector4f base_color{1, 1, 1, 1};  // linear
    const MipTexture* color = nullptr;       // sRGB-decoded albedo, alpha
    const MipTexture* normal = nullptr;      // tangent-space normal map
    const MipTexture* height = nullptr;      // 1 = surface, 0 = deepest
    // Metres from height 1 to height 0 (baked LoD pages); 0: unstated, and
    // parallax offsets are the manual's, in the texture's own uv (docs/design.md: Rendering).
    float height_depth = 0;
    Eigen::Vector3f specular{0.2f, 0.2f, 0.2f};
    float shininess = 32;
    AlphaMode alpha_mode = AlphaMode::opaque;
    float alpha_cutoff = 0.5f;  // mask only
};

struct Batch {
    const Mesh* mesh = nullptr;
    Surface surface;
    // Drawn at the mesh's positions + translation: one mesh at many places (a
    // city's repeated designs), as an engine's per-instance model matrix.
    Eigen::Vector3f translation = Eigen::Vector3f::Zero();
};

// The manual's light options.
struct Light {
    Eigen::Vector3f position{10, 20, 15};
    float ambient = 0.25f, diffuse = 0.75f, specular = 0.25f;
    float shininess = 0;  // > 0 overrides every material's shininess
};
constexpr NumberRange light_intensity_range{0, 100};  // ambient, diffuse, specular
constexpr NumberRange shininess_range{0, 1e4};

// The default light: above the camera and to its right, as far again as the target.
Light light_for_camera(const Camera& camera);

class Shader;  // renderer/shading.h

struct RenderSettings {
    Camera camera;
    RenderMode mode = RenderMode::normal;
    const Shader* shader = nullptr;  // set: shades every pixel instead of `mode`'s shader
    Light light;
    float parallax_scale = 0.04f, parallax_bias = -0.02f;
    Culling culling = Culling::none;
    bool wireframe = false;
    Eigen::Vector3f wireframe_color{0, 0, 0};
    int threads = 0;  // 0 = all cores
    // Pixels outside [x0, x1) x [y0, y1) are left untouched (split view).
    int scissor_x0 = 0, scissor_y0 = 0, scissor_x1 = 1 << 30, scissor_y1 = 1 << 30;
    // The depth test starts from the frame's depth instead of +infinity: a
    // render over an earlier one with the same camera gives the picture of
    // both drawn in one render, the earlier first, when the earlier drew no
    // blended surface (its depth hides what the blend would show).
    bool depth_from_frame = false;
};

}  // namespace boxlod
