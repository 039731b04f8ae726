#include "toolkit/lod/hybrid/proxy_drawables.h"

#include "toolkit/lod/hybrid/baked_proxy.h"

namespace boxlod {
namespace {

// A material drawing a baked face's colours and normals (untextured: none, grey);
// a box's is cut out where the face saw nothing, a baked proxy's is opaque.
int add_face_material(const BakedFace* baked, AlphaMode alpha_mode, ProxyDrawable& proxy) {
    Material material;
    material.base_color = baked ? Eigen::Vector4f(1, 1, 1, 1) : Eigen::Vector4f(0.7f, 0.7f, 0.7f, 1);
    if (baked) {
        material.base_color_texture = material.normal_texture = int(proxy.textures.color.size());
        material.alpha_mode = alpha_mode;
        proxy.textures.color.push_back(
            std::make_shared<const MipTexture>(make_texture(baked->color, ColorSpace::srgb, Wrap::clamp)));
        proxy.textures.linear.push_back(
            std::make_shared<const MipTexture>(make_texture(baked->normal, ColorSpace::linear, Wrap::clamp)));
    }
    proxy.materials.push_back(material);
    return int(proxy.materials.size()) - 1;
}

void make_proxy_drawable(ProxyDrawable& proxy) {
    std::vector<const Primitive*> primitives;
    for (const Primitive& p : proxy.primitives) primitives.push_back(&p);
    proxy.drawable = make_drawable(proxy.materials, proxy.textures, primitives);
}

}  // namespace

std::array<BakedFace, 6> bake_box(const Drawable& subtree, const OrientedBox& box,
                                  const TextureSizing& measuring) {
    std::array<BakedFace, 6> baked;
    const std::array<OrientedBoxFace, 6> faces = oriented_box_faces(box);
    for (std::size_t f = 0; f < 6; ++f)
        baked[f] = bake_face(subtree, faces[f],
                             face_texels(2 * faces[f].half_width, 2 * faces[f].half_height, measuring), 1);
    return baked;
}

std::unique_ptr<ProxyDrawable> box_proxy_drawable(const OrientedBox& box,
                                                  const std::array<BakedFace, 6>* baked) {
    auto proxy = std::make_unique<ProxyDrawable>();
    const std::array<OrientedBoxFace, 6> faces = oriented_box_faces(box);
    for (std::size_t f = 0; f < 6; ++f) {
        const OrientedBoxFace& face = faces[f];
        Primitive quad;
        quad.material = add_face_material(baked ? &(*baked)[f] : nullptr, AlphaMode::mask, *proxy);
        const float corners[4][2] = {
            {0, 0}, {0, 1}, {1, 1}, {1, 0}};  // (right, down) over the face, as bake_face's image
        for (const auto& c : corners) {
            const float s = 2 * c[0] - 1, t = 1 - 2 * c[1];
            quad.positions.push_back(face.center + face.tangent * (s * face.half_width) +
                                     face.bitangent * (t * face.half_height));
            quad.normals.push_back(face.normal);
            if (baked) {
                quad.uvs.emplace_back(c[0], c[1]);
                quad.tangents.emplace_back(face.tangent.x(), face.tangent.y(), face.tangent.z(), 1.0f);
            }
        }
        quad.indices = {0, 1, 2, 0, 2, 3};
        quad.polygon_count = 1;
        proxy->primitives.push_back(std::move(quad));
    }
    make_proxy_drawable(*proxy);
    return proxy;
}

std::unique_ptr<ProxyDrawable> baked_proxy_drawable(std::array<Primitive, 6> faces,
                                                    const std::array<BakedFace, 6>& baked) {
    auto proxy = std::make_unique<ProxyDrawable>();
    for (std::size_t f = 0; f < 6; ++f) {
        if (faces[f].indices.empty()) continue;
        faces[f].material = add_face_material(&baked[f], AlphaMode::opaque, *proxy);
        proxy->primitives.push_back(std::move(faces[f]));
    }
    make_proxy_drawable(*proxy);
    return proxy;
}

}  // namespace boxlod
