#include "toolkit/lod/hybrid/simplification.h"

#include "base/input_error.h"
#include "lod_scene.h"
#include "test_support.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace boxlod;

namespace {

const Model& fzk_haus() {
    static const Model model = load_model(test::fzk_haus_ifc);
    return model;
}

std::size_t faces_of(const Model& model) { return mesh_counts(model).faces; }

// The achieved faces may fall a little short of the target (a collapse removes
// two triangles, clustering snaps to a grid) but never exceed it.
void expect_near_budget(const Model& model, double ratio) {
    std::size_t original = mesh_counts(model).triangles;
    auto target = std::size_t(double(original) * ratio);
    Model simplified = simplify_model(model, target, {});
    std::size_t faces = faces_of(simplified);
    EXPECT_LE(faces, target) << "ratio " << ratio;
    EXPECT_GE(double(faces), 0.8 * double(target)) << "ratio " << ratio;
    EXPECT_EQ(faces, mesh_counts(simplified).triangles);
    EXPECT_NO_THROW(validate_model(simplified));
}

using UvSet = std::set<std::array<float, 2>>;

UvSet uvs_of(const Model& model) {
    UvSet uvs;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives)
            for (const auto& uv : p.uvs) uvs.insert({uv.x(), uv.y()});
    return uvs;
}

std::set<int> materials_used(const Model& model) {
    std::set<int> used;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) used.insert(p.material);
    return used;
}

// A sphere whose every vertex carries its own position's normal: smooth shaded.
Model smooth_sphere() {
    Model model;
    model.source = "smooth sphere";
    Primitive& sphere = model.nodes[std::size_t(add_node(model, -1, "sphere"))].primitives.emplace_back();
    const int rings = 16, segments = 32;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = float(M_PI) * float(r) / rings,
                        phi = 2 * float(M_PI) * float(s % segments) / segments;
            const Eigen::Vector3f p(std::sin(theta) * std::cos(phi), std::cos(theta),
                                    std::sin(theta) * std::sin(phi));
            sphere.positions.push_back(p);
            sphere.normals.push_back(p);
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const auto a = std::uint32_t(r * (segments + 1) + s), b = a + segments + 1;
            sphere.indices.insert(sphere.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    sphere.polygon_count = sphere.triangle_count();
    return model;
}

}  // namespace

TEST(Simplification, FzkHausMeetsTheBudget) {
    for (double ratio : {0.5, 0.1, 0.01}) expect_near_budget(fzk_haus(), ratio);
}

TEST(Simplification, TestBuildingMeetsTheBudget) {
    Model building = test::lod_test_building();
    for (double ratio : {0.5, 0.25}) expect_near_budget(building, ratio);
}

TEST(Simplification, KeepsMaterialsTexturesAndUvs) {
    Model building = test::lod_test_building();
    Model simplified = simplify_model(building, 14, {});
    ASSERT_EQ(simplified.materials.size(), building.materials.size());
    for (std::size_t i = 0; i < building.materials.size(); ++i) {
        EXPECT_EQ(simplified.materials[i].name, building.materials[i].name);
        EXPECT_EQ(simplified.materials[i].base_color, building.materials[i].base_color);
        EXPECT_EQ(simplified.materials[i].base_color_texture, building.materials[i].base_color_texture);
    }
    ASSERT_EQ(simplified.textures.size(), building.textures.size());
    EXPECT_EQ(simplified.textures[0].image.pixels, building.textures[0].image.pixels);
    for (const Node& node : simplified.nodes)
        for (const Primitive& p : node.primitives) EXPECT_EQ(p.uvs.size(), p.positions.size());
    // Collapses move no vertex and invent no attribute: every uv is an original one.
    UvSet original = uvs_of(building), kept = uvs_of(simplified);
    EXPECT_TRUE(std::includes(original.begin(), original.end(), kept.begin(), kept.end()));
}

TEST(Simplification, EveryMaterialStaysAtHalfTheFaces) {
    // At small budgets a material made of parts too small to simplify may vanish; at half, none does.
    Model simplified = simplify_model(fzk_haus(), mesh_counts(fzk_haus()).triangles / 2, {});
    EXPECT_EQ(materials_used(simplified), materials_used(fzk_haus()));
}

TEST(Simplification, OneNodePerMaterial) {
    Model simplified = simplify_model(fzk_haus(), 1000, {});
    std::set<int> seen;
    for (std::size_t n = 1; n < simplified.nodes.size(); ++n) {
        ASSERT_FALSE(simplified.nodes[n].primitives.empty());
        int material = simplified.nodes[n].primitives[0].material;
        EXPECT_TRUE(seen.insert(material).second) << "material " << material << " in two nodes";
        for (const Primitive& p : simplified.nodes[n].primitives) EXPECT_EQ(p.material, material);
    }
    EXPECT_TRUE(simplified.nodes[0].primitives.empty());
}

TEST(Simplification, TargetAtOrAboveTheOriginalKeepsEveryFace) {
    const Model& model = fzk_haus();
    std::size_t triangles = mesh_counts(model).triangles;
    for (std::size_t target : {triangles, triangles * 3}) {
        Model same = simplify_model(model, target, {});
        EXPECT_EQ(faces_of(same), triangles);
        EXPECT_EQ(uvs_of(same), uvs_of(model));
        EXPECT_LE(mesh_counts(same).vertices, mesh_counts(model).vertices);  // welded, never more
    }
}

TEST(Simplification, IsDeterministicForAnyThreadCount) {
    SimplifyOptions one, two;
    one.threads = 1;
    two.threads = 2;
    auto target = mesh_counts(fzk_haus()).triangles / 10;
    Model a = simplify_model(fzk_haus(), target, one), b = simplify_model(fzk_haus(), target, two),
          c = simplify_model(fzk_haus(), target, two);
    for (const Model* other : {&b, &c}) {
        ASSERT_EQ(a.nodes.size(), other->nodes.size());
        for (std::size_t n = 0; n < a.nodes.size(); ++n) {
            ASSERT_EQ(a.nodes[n].primitives.size(), other->nodes[n].primitives.size());
            for (std::size_t k = 0; k < a.nodes[n].primitives.size(); ++k) {
                const Primitive &p = a.nodes[n].primitives[k], &q = other->nodes[n].primitives[k];
                EXPECT_EQ(p.indices, q.indices);
                EXPECT_EQ(p.positions, q.positions);
                EXPECT_EQ(p.uvs, q.uvs);
            }
        }
    }
}

TEST(Simplification, LockBorderKeepsBorderVerticesAndStillSimplifies) {
    SimplifyOptions locked;
    locked.lock_border = true;
    locked.clustering_fallback = false;
    Model building = test::lod_test_building();
    // Every quad of the test building is an open sheet: with the border locked nothing may collapse.
    EXPECT_EQ(faces_of(simplify_model(building, 10, locked)), mesh_counts(building).triangles);
    locked.lock_border = false;
    EXPECT_LT(faces_of(simplify_model(building, 10, locked)), mesh_counts(building).triangles);
}

// The variants simplification-best chooses from: each reaches the budget without going
// over it; clustering alone differs from edge collapse first; the area split keeps walls.
TEST(Simplification, EveryVariantStaysWithinTheBudget) {
    Model building = fzk_haus();
    const std::size_t target = mesh_counts(building).triangles / 20;
    std::vector<std::size_t> faces;
    for (const SimplifyVariant& v : simplify_variants(2)) {
        faces.push_back(faces_of(simplify_model(building, target, v.options)));
        EXPECT_LE(faces.back(), target) << v.name;
        EXPECT_GT(faces.back(), target * 9 / 10) << v.name;
    }
    ASSERT_EQ(faces.size(), 4u);
    SimplifyOptions collapse = simplify_variants(1)[0].options, sloppy = simplify_variants(1)[2].options,
                    by_area = simplify_variants(1)[3].options;
    EXPECT_FALSE(sloppy.edge_collapse);
    EXPECT_TRUE(by_area.budget_by_area);
    // Split by area, the FZK-Haus's walls (large, few triangles) keep their surface; split by
    // triangles, the dense small parts take the budget and the walls are clustered away.
    auto area = [&](const SimplifyOptions& options) {
        double sum = 0;
        for (const Node& node : simplify_model(building, target, options).nodes)
            for (const Primitive& p : node.primitives)
                for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3)
                    sum += 0.5 * double((p.positions[p.indices[i + 1]] - p.positions[p.indices[i]])
                                            .cross(p.positions[p.indices[i + 2]] - p.positions[p.indices[i]])
                                            .norm());
        return sum;
    };
    EXPECT_GT(area(by_area), 1.5 * area(collapse));
    auto positions = [&](const SimplifyOptions& options) {
        std::vector<float> all;
        for (const Node& node : simplify_model(building, target, options).nodes)
            for (const Primitive& p : node.primitives)
                for (const Eigen::Vector3f& v : p.positions) all.insert(all.end(), {v.x(), v.y(), v.z()});
        return all;
    };
    EXPECT_NE(positions(collapse), positions(sloppy));
}

// The FZK-Haus's parts are faceted (a position carries one normal per face
// around it); simplified, they come out flat-shaded, without normals: the
// collapse would leave each kept position one face's normal for all of them.
// A smooth part keeps its normals.
TEST(Simplification, FacetedPartsComeOutFlatShadedSmoothOnesKeepTheirNormals) {
    ASSERT_TRUE(std::any_of(fzk_haus().nodes.begin(), fzk_haus().nodes.end(), [](const Node& node) {
        return !node.primitives.empty() && !node.primitives[0].normals.empty();
    }));
    const Model faceted = simplify_model(fzk_haus(), faces_of(fzk_haus()) / 10, {});
    ASSERT_GT(faces_of(faceted), 0u);
    for (const Node& node : faceted.nodes)
        for (const Primitive& p : node.primitives) {
            EXPECT_TRUE(p.normals.empty());
            std::set<std::array<float, 5>> corners;  // welded: no two vertices alike
            for (std::size_t v = 0; v < p.positions.size(); ++v) {
                const Eigen::Vector2f uv = p.uvs.empty() ? Eigen::Vector2f::Zero() : p.uvs[v];
                corners.insert({p.positions[v].x(), p.positions[v].y(), p.positions[v].z(), uv.x(), uv.y()});
            }
            EXPECT_EQ(corners.size(), p.positions.size());
        }
    const Model sphere = smooth_sphere();
    const Model smooth = simplify_model(sphere, faces_of(sphere) / 4, {});
    ASSERT_GT(faces_of(smooth), 0u);
    for (const Node& node : smooth.nodes)
        for (const Primitive& p : node.primitives) EXPECT_EQ(p.normals.size(), p.positions.size());
}

// Whether a faceted part keeps its normals is its material's: tangents that
// no normal map reads (a grammar's untextured parts carry them in memory, not
// in their files) go with the normals, and a normal-mapped part keeps both.
TEST(Simplification, OnlyANormalMapKeepsAFacetedPartsNormals) {
    Model model = fzk_haus();
    for (Node& node : model.nodes)
        for (Primitive& p : node.primitives) p.tangents.assign(p.positions.size(), {1, 0, 0, 1});
    const std::size_t target = faces_of(model) / 10;
    for (const Node& node : simplify_model(model, target, {}).nodes)
        for (const Primitive& p : node.primitives) {
            EXPECT_TRUE(p.normals.empty());
            EXPECT_TRUE(p.tangents.empty());
        }
    model.textures.push_back({"n.png", Image8(4, 4, 3, 128), {}});
    for (Material& material : model.materials) material.normal_texture = int(model.textures.size()) - 1;
    const Model mapped = simplify_model(model, target, {});
    ASSERT_GT(faces_of(mapped), 0u);
    for (const Node& node : mapped.nodes)
        for (const Primitive& p : node.primitives) {
            EXPECT_EQ(p.normals.size(), p.positions.size());
            EXPECT_EQ(p.tangents.size(), p.positions.size());
        }
}

TEST(Simplification, BadInputIsAnInputError) {
    EXPECT_THROW(simplify_model(fzk_haus(), 0, {}), InputError);
    Model lod = test::lod_test_building();
    lod.is_lod = true;
    EXPECT_THROW(simplify_model(lod, 10, {}), InputError);
    Model empty;
    add_node(empty, -1, "root");
    EXPECT_THROW(simplify_model(empty, 10, {}), InputError);
}
