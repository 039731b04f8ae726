// The hybrid level mode's proxies as its measuring renders draw them
// (hybrid.h): each with its own materials and textures, baked at the
// measuring texels, so no level's pages are needed to measure one.
#pragma once
#include "toolkit/drawing/drawable.h"
#include "toolkit/lod/pages/bake.h"
#include "toolkit/lod/pages/texture_sizing.h"

#include <array>
#include <memory>
#include <vector>

namespace boxlod {

struct ProxyDrawable {
    std::vector<Material> materials;
    DecodedTextures textures;
    std::vector<Primitive> primitives;
    Drawable drawable;
};

// The box's faces baked with texels as `measuring` sizes them.
std::array<BakedFace, 6> bake_box(const Drawable& subtree, const OrientedBox& box,
                                  const TextureSizing& measuring);

// The box: each face one quad over its whole baked texture, cut out where it
// saw nothing (`baked` null: untextured, grey).
std::unique_ptr<ProxyDrawable> box_proxy_drawable(const OrientedBox& box,
                                                  const std::array<BakedFace, 6>* baked);

// A baked proxy: each face's triangles (baked_proxy_faces) in that face's colours and normals, opaque.
std::unique_ptr<ProxyDrawable> baked_proxy_drawable(std::array<Primitive, 6> faces,
                                                    const std::array<BakedFace, 6>& baked);

}  // namespace boxlod
