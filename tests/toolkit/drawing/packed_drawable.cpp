#include "toolkit/drawing/packed_drawable.h"

#include "lod_scene.h"
#include "toolkit/lod/chain/chain.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// Level 1 of the test building: baked pages (colour, normal, height) and the kept bricks texture.
Model baked_level() {
    static const Model level = [] {
        Model model = test::lod_test_building();
        LodParameters p;
        set_manual(p);  // every sub-tree boxed: level 1 has pages
        p.level_mode = LevelMode::top_down;
        p.resolution = 128;
        p.min_texture_size = 16;
        return Chain(model, p, 1).build(1).model;
    }();
    return level;
}

Image8 render_with(const Drawable& drawable, RenderMode mode) {
    RenderSettings settings;
    Bounds b = drawable.bounds;
    settings.camera = camera_at_position({1, 0.6f, 0.8f}, b.center(), 9, 40, b.size().norm() / 2);
    settings.mode = mode;
    settings.threads = 1;
    Frame frame = make_frame(96, 72, {0.5f, 0.6f, 0.7f});
    render(drawable.batches, settings, frame);
    return frame_to_srgb8(frame);
}

}  // namespace

TEST(PackedDrawable, UnpacksToWhatMakeDrawableModelGives) {
    Model model = baked_level();
    ASSERT_GT(model.textures.size(), 3u);
    auto direct = make_drawable_model(model);
    auto unpacked = unpack_drawable(pack_drawable(model, nullptr));
    const Drawable &a = direct->drawable, &b = unpacked->drawable;
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t m = 0; m < a.meshes.size(); ++m) {
        EXPECT_EQ(a.meshes[m]->positions, b.meshes[m]->positions);
        EXPECT_EQ(a.meshes[m]->normals, b.meshes[m]->normals);
        EXPECT_EQ(a.meshes[m]->uvs, b.meshes[m]->uvs);
        EXPECT_EQ(a.meshes[m]->tangents, b.meshes[m]->tangents);
        EXPECT_EQ(a.meshes[m]->indices, b.meshes[m]->indices);
    }
    EXPECT_EQ(a.materials, b.materials);
    EXPECT_EQ(a.bounds.min, b.bounds.min);
    EXPECT_EQ(a.bounds.max, b.bounds.max);
    for (RenderMode mode : {RenderMode::normal, RenderMode::pom, RenderMode::albedo}) {
        Image8 x = render_with(a, mode), y = render_with(b, mode);
        EXPECT_EQ(x.pixels, y.pixels) << int(mode);
    }
}

TEST(PackedDrawable, KeepsTexturesTheCacheHoldsSharedAndPacksTheRest) {
    Model model = baked_level();
    TextureCache cache;
    int bricks = -1;  // the kept walls' texture, which a city would have decoded already
    for (std::size_t t = 0; t < model.textures.size(); ++t)
        if (model.textures[t].name == "bricks.png") bricks = int(t);
    ASSERT_GE(bricks, 0);
    auto decoded = cache.decode(model.textures[std::size_t(bricks)], ColorSpace::srgb);

    PackedDrawable packed = pack_drawable(model, &cache);
    EXPECT_EQ(packed.shared.color[std::size_t(bricks)], decoded);
    for (const PackedDrawable::OwnTexture& own : packed.own) EXPECT_NE(own.index, bricks);
    EXPECT_EQ(packed.own.size(),
              textures_read(model.materials).size() - 1);  // every page map, not the bricks

    auto unpacked = unpack_drawable(packed);
    bool drawn = false;
    for (const Batch& batch : unpacked->drawable.batches) drawn |= batch.surface.color == decoded.get();
    EXPECT_TRUE(drawn);  // the kept walls sample the cache's own texture
}

TEST(PackedDrawable, WithoutHeightMapsOnlyTheHeightsGoAndNormalModeDrawsTheSame) {
    Model model = baked_level();
    PackedDrawable with = pack_drawable(model, nullptr, true), without = pack_drawable(model, nullptr, false);
    EXPECT_LT(without.own.size(), with.own.size());
    EXPECT_LT(without.raw_size, with.raw_size);
    auto a = unpack_drawable(with), b = unpack_drawable(without);
    bool had_height = false;
    for (std::size_t i = 0; i < b->drawable.batches.size(); ++i) {
        const Surface &x = a->drawable.batches[i].surface, &y = b->drawable.batches[i].surface;
        had_height |= x.height != nullptr;
        EXPECT_EQ(y.height, nullptr);
        EXPECT_EQ(x.color != nullptr, y.color != nullptr);
        EXPECT_EQ(x.normal != nullptr, y.normal != nullptr);
    }
    EXPECT_TRUE(had_height);
    EXPECT_EQ(render_with(a->drawable, RenderMode::normal).pixels,
              render_with(b->drawable, RenderMode::normal).pixels);
}

TEST(PackedDrawable, PackedIsSmallerThanUnpackedAndCountsItRight) {
    Model model = baked_level();
    PackedDrawable packed = pack_drawable(model, nullptr);
    // What unpacked holds, counted from the unpacked drawable itself.
    auto unpacked = unpack_drawable(packed);
    std::size_t bytes = 0;
    for (const auto& mesh : unpacked->drawable.meshes)
        bytes += mesh->positions.size() * 12 + mesh->normals.size() * 12 + mesh->uvs.size() * 8 +
                 mesh->tangents.size() * 16 + mesh->indices.size() * 4;
    for (const auto* list : {&unpacked->textures.color, &unpacked->textures.linear})
        for (const auto& texture : *list)
            if (texture)
                for (const MipTexture::Level& level : texture->levels)
                    bytes += level.rgba8.size() + 2 * level.r16.size() + 4 * level.r32.size();
    EXPECT_EQ(packed.unpacked_size, bytes);
    EXPECT_LT(packed_size(packed) * 2, packed.unpacked_size);
}
