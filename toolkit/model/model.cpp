#include "toolkit/model/model.h"

#include "base/input_error.h"
#include "base/key_values.h"

#include <cmath>

namespace boxlod {

ContentDigest content_digest(const void* bytes, std::size_t size, ContentDigest d) {
    const auto* p = static_cast<const std::uint8_t*>(bytes);
    for (std::size_t i = 0; i < size; ++i) {
        d.first = (d.first ^ p[i]) * 1099511628211ull;
        d.second = (d.second + p[i] + 1) * 0x9E3779B97F4A7C15ull;
    }
    return d;
}

TextureDigest texture_digest(const Texture& texture) {
    int layout[] = {texture.image.width,   texture.image.height,   texture.image.channels,
                    texture.image16.width, texture.image16.height, texture.image16.channels,
                    int(texture.wrap)};
    TextureDigest d = content_digest(layout, sizeof layout);
    d = content_digest(texture.image.pixels.data(), texture.image.pixels.size(), d);
    return content_digest(texture.image16.pixels.data(),
                          texture.image16.pixels.size() * sizeof(std::uint16_t), d);
}

std::vector<TextureSlot<int*>> texture_slots(Material& m) {
    std::vector<TextureSlot<int*>> slots = {
        {&m.base_color_texture, TextureUse::color, MaterialMap::base_color},
        {&m.normal_texture, TextureUse::normal, MaterialMap::normal},
        {&m.height_texture, TextureUse::scalar, MaterialMap::height},
        {&m.specular_texture, TextureUse::color, MaterialMap::specular}};
    if (m.specular_extension)
        slots.insert(slots.end(),
                     {{&m.specular_extension->texture, TextureUse::scalar, MaterialMap::specular},
                      {&m.specular_extension->color_texture, TextureUse::color, MaterialMap::specular}});
    return slots;
}

std::vector<TextureSlot<int>> texture_slots(const Material& material) {
    std::vector<TextureSlot<int>> slots;
    for (auto [index, use, map] : texture_slots(const_cast<Material&>(material)))
        slots.push_back({*index, use, map});
    return slots;
}

bool samples_textures(const Material& material) {
    const auto slots = texture_slots(material);
    return std::any_of(slots.begin(), slots.end(), [](const auto& slot) { return slot.index >= 0; });
}

bool draws_anything(const Model& model) {
    for (const Node& node : model.nodes)
        for (const Primitive& primitive : node.primitives) {
            if (primitive.indices.empty()) continue;
            if (primitive.material < 0 || primitive.material >= int(model.materials.size())) return true;
            const Material& material = model.materials[std::size_t(primitive.material)];
            if (material.alpha_mode == AlphaMode::opaque || material.base_color.w() > 0) return true;
        }
    return false;
}

bool draws_the_same(const Model& a, const Model& b) {
    if (a.materials != b.materials || a.textures.size() != b.textures.size()) return false;
    for (std::size_t t = 0; t < a.textures.size(); ++t)
        if (texture_digest(a.textures[t]) != texture_digest(b.textures[t])) return false;
    std::vector<const Primitive*> drawn_a, drawn_b;
    for (const Node& node : a.nodes)
        for (const Primitive& primitive : node.primitives) drawn_a.push_back(&primitive);
    for (const Node& node : b.nodes)
        for (const Primitive& primitive : node.primitives) drawn_b.push_back(&primitive);
    return std::equal(drawn_a.begin(), drawn_a.end(), drawn_b.begin(), drawn_b.end(),
                      [](const Primitive* x, const Primitive* y) { return *x == *y; });
}

int add_node(Model& model, int parent, std::string name) {
    int index = int(model.nodes.size());
    Node& node = model.nodes.emplace_back();
    node.name = std::move(name);
    node.parent = parent;
    if (parent >= 0) model.nodes[parent].children.push_back(index);
    return index;
}

int tree_depth(const Model& model) {
    // Parents precede children, so one forward pass gives every node's depth.
    std::vector<int> depth(model.nodes.size(), 0);
    int deepest = 0;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        int parent = model.nodes[i].parent;
        if (parent >= 0) depth[i] = depth[parent] + 1;
        deepest = std::max(deepest, depth[i]);
    }
    return deepest;
}

Bounds model_bounds(const Model& model) {
    Bounds bounds;
    for (const Node& node : model.nodes)
        for (const Primitive& primitive : node.primitives)
            for (const Eigen::Vector3f& p : primitive.positions) bounds.add(p);
    return bounds;
}

namespace {

// One primitive's indices, attribute counts, finite values and material; true
// when it has a triangle of non-zero area.
bool validate_primitive(const Model& model, const Primitive& primitive, const std::string& where) {
    const std::string& file = model.source;
    std::size_t n = primitive.positions.size();
    if (primitive.indices.size() % 3 != 0)
        throw_input_error(file, where, "index count is not a multiple of 3");
    for (std::uint32_t index : primitive.indices)
        if (index >= n)
            throw_input_error(file, where,
                              "vertex index " + std::to_string(index) + " out of range (" +
                                  std::to_string(n) + " vertices)");
    auto check_size = [&](std::size_t size, const char* what) {
        if (size != 0 && size != n)
            throw_input_error(file, where, std::string(what) + " count differs from position count");
    };
    check_size(primitive.normals.size(), "normal");
    check_size(primitive.uvs.size(), "texture coordinate");
    check_size(primitive.tangents.size(), "tangent");
    auto check_finite = [&](const auto& values, const char* what) {
        for (const auto& v : values)
            if (!v.allFinite()) throw_input_error(file, where, std::string(what) + " is NaN or infinite");
    };
    check_finite(primitive.positions, "position");
    for (const Eigen::Vector3f& p : primitive.positions)
        if (!(coordinate_range.contains(p.x()) && coordinate_range.contains(p.y()) &&
              coordinate_range.contains(p.z())))
            throw_input_error(file, where,
                              "a position (" + format_number(p.x()) + ", " + format_number(p.y()) + ", " +
                                  format_number(p.z()) + ") outside " + range_text(coordinate_range));
    check_finite(primitive.normals, "normal");
    check_finite(primitive.uvs, "texture coordinate");
    check_finite(primitive.tangents, "tangent");
    if (primitive.material >= int(model.materials.size()))
        throw_input_error(file, where, "material index out of range");
    return has_area(primitive);
}

// One material's texture indices, colours and ranges.
void validate_material(const Model& model, const Material& material) {
    const std::string& file = model.source;
    const std::string place = "material '" + material.name + "'";
    for (const auto& slot : texture_slots(material))
        if (slot.index >= int(model.textures.size()))
            throw_input_error(file, place, "texture index out of range");
    // glTF 2.0's factors (5.19.4, KHR_materials_pbrSpecularGlossiness): each in [0, 1], NaN failing too.
    auto check_unit = [&](const auto& colour, const char* name) {
        if (((colour.array() >= 0) && (colour.array() <= 1)).all()) return;
        std::string values;
        for (float c : colour) values += (values.empty() ? "" : ", ") + format_number(c);
        throw_input_error(file, place, std::string(name) + " (" + values + ") out of range [0, 1]");
    };
    check_unit(material.base_color, "base colour");
    check_unit(material.specular_color, "specular colour");
    if (const auto& extension = material.specular_extension;
        extension && !(extension->factor >= 0 && extension->factor <= 1 &&
                       (extension->color_factor.array() >= specular_color_factor_range.min).all() &&
                       (extension->color_factor.array() <= specular_color_factor_range.max).all()))
        throw_input_error(file, place, "KHR_materials_specular factor out of range");
    if (!shininess_range.contains(material.shininess))
        throw_input_error(
            file, place,
            "shininess " + out_of_range_message(shininess_range, format_number(material.shininess)));
    if (!height_depth_range.contains(material.height_depth))
        throw_input_error(
            file, place,
            "height_depth " + out_of_range_message(height_depth_range, format_number(material.height_depth)));
}

}  // namespace

void make_unit_normals_and_tangents(Model& model) {
    constexpr float least_squared_length = 1e-12f;
    auto unit = [](auto& vectors, auto&& xyz) {
        for (auto& v : vectors)
            if (!v.allFinite()) return true;  // validate_model's to refuse
        for (auto& v : vectors)
            if (!(xyz(v).squaredNorm() > least_squared_length)) return false;
        for (auto& v : vectors) xyz(v).normalize();
        return true;
    };
    for (Node& node : model.nodes)
        for (Primitive& p : node.primitives) {
            if (!unit(p.normals, [](Eigen::Vector3f& n) -> Eigen::Vector3f& { return n; })) p.normals.clear();
            if (!unit(p.tangents, [](Eigen::Vector4f& t) { return t.head<3>(); })) p.tangents.clear();
            for (Eigen::Vector4f& t : p.tangents) t.w() = t.w() < 0 ? -1.0f : 1.0f;
        }
}

bool has_area(const Primitive& primitive) {
    for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
        const auto& a = primitive.positions[primitive.indices[t]];
        if ((primitive.positions[primitive.indices[t + 1]] - a)
                .cross(primitive.positions[primitive.indices[t + 2]] - a)
                .squaredNorm() > 0)
            return true;
    }
    return false;
}

void validate_model(const Model& model) {
    const std::string& file = model.source;
    if (model.nodes.empty()) throw_input_error(file, "", "the scene has no nodes");
    bool any_triangle = false;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const Node& node = model.nodes[i];
        std::string place = "node " + std::to_string(i) + (node.name.empty() ? "" : " '" + node.name + "'");
        if ((i == 0) != (node.parent < 0) || node.parent >= int(i))
            throw_input_error(file, place, "the node hierarchy is not a tree");
        for (std::size_t p = 0; p < node.primitives.size(); ++p)
            any_triangle =
                validate_primitive(model, node.primitives[p], place + " primitive " + std::to_string(p)) ||
                any_triangle;
        if (node.scope && !(node.scope->center.allFinite() && node.scope->axes.allFinite() &&
                            node.scope->half_extents.allFinite()))
            throw_input_error(file, place, "scope is NaN or infinite");
    }
    for (const Material& material : model.materials) validate_material(model, material);
    if (!any_triangle)
        throw_input_error(file, "", "the scene has no triangle of non-zero area (empty model)");
}

}  // namespace boxlod
