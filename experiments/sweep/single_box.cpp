#include "experiments/sweep/single_box.h"

#include "toolkit/lod/pages/bake.h"
#include "toolkit/lod/pages/boxes.h"

namespace boxlod {
namespace {

// The linear mean colour of a texture's texels (its uv use is ignored: a
// tiled texture is seen about evenly).
Eigen::Vector3f mean_texture_color(const Texture& texture) {
    const Image8& image = texture.image;
    if (image.width <= 0 || image.height <= 0 || image.channels < 3) return Eigen::Vector3f::Ones();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            for (int c = 0; c < 3; ++c) sum[c] += srgb_to_linear(p[c]);
        }
    return (sum / double(image.width) / double(image.height)).cast<float>();
}

Eigen::Vector3f average_color(const Model& model) {
    std::vector<Eigen::Vector3f> material_colors;
    for (const Material& material : model.materials) {
        Eigen::Vector3f color = material.base_color.head<3>();
        if (material.base_color_texture >= 0 &&
            std::size_t(material.base_color_texture) < model.textures.size())
            color = color.cwiseProduct(
                mean_texture_color(model.textures[std::size_t(material.base_color_texture)]));
        material_colors.push_back(color);
    }
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double area = 0;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) {
            Eigen::Vector3f color =
                p.material >= 0 ? material_colors[std::size_t(p.material)] : Material().base_color.head<3>();
            for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) {
                const auto &a = p.positions[p.indices[i]], &b = p.positions[p.indices[i + 1]],
                           &c = p.positions[p.indices[i + 2]];
                double triangle_area = 0.5 * double((b - a).cross(c - a).norm());
                sum += triangle_area * color.cast<double>();
                area += triangle_area;
            }
        }
    return area > 0 ? Eigen::Vector3f((sum / area).cast<float>()) : Material().base_color.head<3>();
}

// The root's minimal box: it depends on the hull of all vertices only, so the
// geometry gathered into one node gives exactly the root's box.
OrientedBox root_box(const Model& model, int threads) {
    Model gathered;
    add_node(gathered, -1, "all");
    for (const Node& node : model.nodes)
        gathered.nodes[0].primitives.insert(gathered.nodes[0].primitives.end(), node.primitives.begin(),
                                            node.primitives.end());
    return node_boxes(gathered, BoxKind::minimal, threads)[0].value_or(OrientedBox{});
}

}  // namespace

Model single_box_model(const Model& model, int threads) {
    Model result;
    keep_provenance(model, result);
    Material material;
    material.name = "average";
    Eigen::Vector3f color = average_color(model);
    material.base_color = {color.x(), color.y(), color.z(), 1};
    result.materials.push_back(material);
    add_node(result, -1, "box");
    Primitive& quads = result.nodes[0].primitives.emplace_back();
    quads.material = 0;
    for (const OrientedBoxFace& face : oriented_box_faces(root_box(model, threads))) {
        Eigen::Vector3f t = face.tangent * face.half_width, b = face.bitangent * face.half_height;
        auto base = std::uint32_t(quads.positions.size());
        // tangent x bitangent = normal: this order is counter-clockwise seen from outside.
        for (Eigen::Vector3f corner :
             {Eigen::Vector3f(face.center - t - b), Eigen::Vector3f(face.center + t - b),
              Eigen::Vector3f(face.center + t + b), Eigen::Vector3f(face.center - t + b)}) {
            quads.positions.push_back(corner);
            quads.normals.push_back(face.normal);
        }
        quads.indices.insert(quads.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        ++quads.polygon_count;
    }
    return result;
}

}  // namespace boxlod
