#include "renderer/scene.h"

#include <Eigen/Geometry>
#include <stdexcept>

namespace boxlod {

namespace {
constexpr EnumEntry<RenderMode> render_mode_table[] = {
    {RenderMode::untextured, "untextured", "material colour only, vertex normals (LoD boxes are not baked)"},
    {RenderMode::normal, "normal", "albedo x Blinn-Phong, the normal from the normal map"},
    {RenderMode::parallax, "parallax", "texture coordinates offset by height (scale, bias), then as normal"},
    {RenderMode::pom, "pom", "parallax occlusion mapping: a ray march through the height map"},
    {RenderMode::albedo, "albedo", "unlit albedo (material colour x texture): what baking records"},
};
constexpr EnumEntry<AlphaMode> alpha_mode_table[] = {
    {AlphaMode::opaque, "OPAQUE", "alpha ignored"},
    {AlphaMode::mask, "MASK", "fragments below the alpha cutoff are dropped"},
    {AlphaMode::blend, "BLEND", "composited source-over, after the opaque surfaces"},
};
}  // namespace

std::span<const EnumEntry<AlphaMode>> alpha_modes() { return alpha_mode_table; }

std::span<const EnumEntry<RenderMode>> render_modes() { return render_mode_table; }

bool parse_render_mode(const std::string& name, RenderMode& mode) {
    return parse_enum(render_modes(), name, mode);
}

const char* render_mode_name(RenderMode mode) { return enum_name(render_modes(), mode); }

MapsDrawn maps_drawn(RenderMode mode) {
    switch (mode) {
    case RenderMode::untextured: return {};
    case RenderMode::normal: return {.color = true, .normal = true};
    case RenderMode::parallax:
    case RenderMode::pom: return {.color = true, .normal = true, .height = true};
    case RenderMode::albedo: return {.color = true};
    }
    throw std::logic_error("maps_drawn: unknown render mode");
}

Light light_for_camera(const Camera& camera) {
    Eigen::Vector3f eye = camera.position - camera.target;
    float distance = eye.norm();
    Eigen::Vector3f right = eye.cross(camera.up);
    if (right.squaredNorm() == 0) right = Eigen::Vector3f::UnitX();
    Light light;
    light.position =
        camera.position + right.normalized() * (distance * 0.5f) + camera.up.normalized() * distance;
    return light;
}

}  // namespace boxlod
