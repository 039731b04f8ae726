// A small hand-built building for LoD tests: a ground plate, a block with
// textured walls, a gable roof and window panes that stick out of the wall.
#pragma once
#include "toolkit/model/model.h"

namespace boxlod::test {

inline void add_quad(Primitive& p, Eigen::Vector3f a, Eigen::Vector3f b, Eigen::Vector3f c,
                     Eigen::Vector3f d) {
    auto base = std::uint32_t(p.positions.size());
    Eigen::Vector3f n = (b - a).cross(d - a).normalized();
    for (const auto& v : {a, b, c, d}) {
        p.positions.push_back(v);
        p.normals.push_back(n);
    }
    p.uvs.insert(p.uvs.end(), {{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    ++p.polygon_count;
}

inline int add_part(Model& model, int parent, const std::string& name, int material) {
    int n = add_node(model, parent, name);
    model.nodes[n].rule = name;
    model.nodes[n].primitives.emplace_back().material = material;
    return n;
}

inline Model lod_test_building() {
    Model model;
    model.source = "test-building";
    add_node(model, -1, "Lot");
    model.nodes[0].rule = "Lot";
    Material ground, wall, roof, glass;
    ground.base_color = {0.4f, 0.45f, 0.35f, 1};
    wall.base_color = {1, 1, 1, 1};
    wall.base_color_texture = 0;
    roof.base_color = {0.6f, 0.2f, 0.15f, 1};
    glass.base_color = {0.1f, 0.15f, 0.3f, 1};
    glass.shininess = 64;
    model.materials = {ground, wall, roof, glass};
    Texture bricks;
    bricks.name = "bricks.png";
    bricks.image = Image8(32, 32, 4, 255);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            bool mortar = y % 8 == 0 || (x + (y / 8 % 2) * 8) % 16 == 0;
            std::uint8_t* p = bricks.image.at(x, y);
            p[0] = mortar ? 210 : 170;
            p[1] = mortar ? 205 : 80;
            p[2] = mortar ? 200 : 60;
        }
    model.textures.push_back(bricks);

    int plate = add_part(model, 0, "Ground", 0);
    add_quad(model.nodes[plate].primitives[0], {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4});
    int house = add_node(model, 0, "House");
    model.nodes[house].rule = "House";
    int walls = add_part(model, house, "Walls", 1);
    Primitive& w = model.nodes[walls].primitives[0];
    add_quad(w, {-2, 0, 1.5f}, {2, 0, 1.5f}, {2, 2, 1.5f}, {-2, 2, 1.5f});
    add_quad(w, {2, 0, -1.5f}, {-2, 0, -1.5f}, {-2, 2, -1.5f}, {2, 2, -1.5f});
    add_quad(w, {2, 0, 1.5f}, {2, 0, -1.5f}, {2, 2, -1.5f}, {2, 2, 1.5f});
    add_quad(w, {-2, 0, -1.5f}, {-2, 0, 1.5f}, {-2, 2, 1.5f}, {-2, 2, -1.5f});
    int roof_node = add_part(model, house, "Roof", 2);
    Primitive& r = model.nodes[roof_node].primitives[0];
    add_quad(r, {-2.2f, 1.9f, 1.7f}, {2.2f, 1.9f, 1.7f}, {2.2f, 3, 0}, {-2.2f, 3, 0});
    add_quad(r, {2.2f, 1.9f, -1.7f}, {-2.2f, 1.9f, -1.7f}, {-2.2f, 3, 0}, {2.2f, 3, 0});
    int windows = add_node(model, house, "Windows");
    model.nodes[windows].rule = "Windows";
    for (int i = 0; i < 3; ++i) {
        int pane = add_part(model, windows, "Window", 3);
        float x = -1.3f + 1.3f * float(i);
        add_quad(model.nodes[pane].primitives[0], {x - 0.35f, 0.7f, 1.55f}, {x + 0.35f, 0.7f, 1.55f},
                 {x + 0.35f, 1.5f, 1.55f}, {x - 0.35f, 1.5f, 1.55f});
    }
    validate_model(model);
    return model;
}

}  // namespace boxlod::test
