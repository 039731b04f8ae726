#include "data_gen/materials.h"

#include "data_gen/textures.h"

#include <cmath>
#include <cstdio>

namespace boxlod {

namespace {

struct BuiltinMaterial {
    const char* name;
    std::uint8_t red, green, blue;  // sRGB base colour; white leaves the texture as it is
    const char* texture;            // "" = untextured
    float specular, shininess;
};

const BuiltinMaterial builtins[] = {
    {"default", 200, 200, 200, "", 0.2f, 32},     {"plaster", 255, 255, 255, "plaster", 0.1f, 16},
    {"brick", 255, 255, 255, "brick", 0.1f, 16},  {"roof_tiles", 255, 255, 255, "roof_tiles", 0.2f, 24},
    {"glass", 255, 255, 255, "glass", 0.9f, 96},  {"wood", 255, 255, 255, "wood", 0.15f, 24},
    {"stone", 255, 255, 255, "stone", 0.15f, 24}, {"concrete", 180, 180, 175, "plaster", 0.1f, 16},
    {"metal", 95, 100, 108, "", 0.7f, 64},        {"asphalt", 70, 70, 74, "stone", 0.05f, 8},
    {"grass", 86, 125, 62, "", 0.05f, 8},
};

const BuiltinMaterial& builtin(const std::string& name) {
    for (const BuiltinMaterial& m : builtins)
        if (name == m.name) return m;
    return builtins[0];
}

std::string texture_of(const Appearance& appearance) {
    if (appearance.texture == "none") return "";
    return appearance.texture.empty() ? builtin(appearance.material).texture : appearance.texture;
}

std::string key_of(const Appearance& appearance) {
    std::string key = appearance.material;
    if (appearance.color) {
        char hex[8];
        const Eigen::Vector3f& c = *appearance.color;
        std::snprintf(hex, sizeof hex, "%02x%02x%02x", int(std::lround(c.x() * 255)),
                      int(std::lround(c.y() * 255)), int(std::lround(c.z() * 255)));
        key += std::string("_") + hex;
    }
    if (!appearance.texture.empty()) key += "_" + appearance.texture;
    return key;
}

}  // namespace

bool is_material_name(const std::string& name) {
    for (const BuiltinMaterial& m : builtins)
        if (name == m.name) return true;
    return false;
}

std::string material_names() {
    std::string out;
    for (const BuiltinMaterial& m : builtins) out += (out.empty() ? "" : ", ") + std::string(m.name);
    return out;
}

int MaterialCache::index(Model& model, const Appearance& appearance) {
    std::string key = key_of(appearance);
    if (auto it = materials_.find(key); it != materials_.end()) return it->second;
    const BuiltinMaterial& base = builtin(appearance.material);
    Material material;
    material.name = key;
    Eigen::Vector3f srgb =
        appearance.color.value_or(Eigen::Vector3f(base.red, base.green, base.blue) / 255.0f);
    for (int c = 0; c < 3; ++c)
        material.base_color[c] =
            srgb_to_linear(std::uint8_t(std::lround(std::clamp(srgb[c], 0.0f, 1.0f) * 255)));
    material.specular_color = Eigen::Vector3f::Constant(base.specular);
    material.shininess = base.shininess;
    if (std::string texture = texture_of(appearance); !texture.empty()) {
        auto found = textures_.find(texture);
        if (found == textures_.end()) {
            ProceduralTexture made = procedural_texture(texture);
            int color_index = int(model.textures.size());
            model.textures.push_back({texture + "_color.png", std::move(made.color)});
            model.textures.push_back({texture + "_normal.png", std::move(made.normal)});
            found = textures_.emplace(texture, std::pair{color_index, color_index + 1}).first;
        }
        material.base_color_texture = found->second.first;
        material.normal_texture = found->second.second;
    }
    int index = int(model.materials.size());
    model.materials.push_back(material);
    materials_[key] = index;
    return index;
}

float MaterialCache::tile_metres(const Appearance& appearance) const {
    std::string texture = texture_of(appearance);
    return texture.empty() ? 1.0f : texture_tile_metres(texture);
}

}  // namespace boxlod
