#include "toolkit/lod/hybrid/baked_proxy.h"

#include "toolkit/model/vertex_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace boxlod {
namespace {

// A point's place on a face: 0..1 right and down over the face, as bake_face's image.
Eigen::Vector2f face_uv(const OrientedBoxFace& face, const Eigen::Vector3f& p) {
    const Eigen::Vector3f d = p - face.center;
    const float s = face.half_width > 0 ? d.dot(face.tangent) / face.half_width : 0;
    const float t = face.half_height > 0 ? d.dot(face.bitangent) / face.half_height : 0;
    return {std::clamp((s + 1) / 2, 0.0f, 1.0f), std::clamp((1 - t) / 2, 0.0f, 1.0f)};
}

// How far (metres along the face's normal) the surface the face baked at p's
// texel lies from p; infinite where the face saw nothing there.
float depth_mismatch(const OrientedBoxFace& face, const BakedFace& baked, const Eigen::Vector3f& p) {
    const Eigen::Vector2f uv = face_uv(face, p);
    const int x = std::min(int(uv.x() * float(baked.color.width)), baked.color.width - 1);
    const int y = std::min(int(uv.y() * float(baked.color.height)), baked.color.height - 1);
    if (baked.color.at(x, y)[3] == 0) return std::numeric_limits<float>::infinity();
    const float baked_depth = (1 - float(*baked.height.at(x, y)) / 65535.0f) * 2 * face.half_depth;
    return std::abs(baked_depth - (face.center - p).dot(face.normal));
}

}  // namespace

int sampled_face(const std::array<OrientedBoxFace, 6>& faces, const std::array<const BakedFace*, 6>& baked,
                 const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
    const Eigen::Vector3f normal = (b - a).cross(c - a);
    if (!(normal.squaredNorm() > 0)) return -1;
    const Eigen::Vector3f unit = normal.normalized(), centroid = (a + b + c) / 3;
    int matching = -1, nearest = -1;
    float best_facing = 0, least_mismatch = std::numeric_limits<float>::infinity();
    for (int f = 0; f < 6; ++f) {
        const BakedFace& face_bake = *baked[std::size_t(f)];
        const float facing = unit.dot(faces[std::size_t(f)].normal);
        if (facing <= 0 || face_bake.covered.empty()) continue;
        const float mismatch = depth_mismatch(faces[std::size_t(f)], face_bake, centroid);
        const float texel = 2 * faces[std::size_t(f)].half_width / float(face_bake.color.width);
        const float tolerance = std::max(3 * texel, 0.2f * faces[std::size_t(f)].half_depth);
        if (mismatch <= tolerance && facing > best_facing) {
            matching = f;
            best_facing = facing;
        }
        if (nearest < 0 || mismatch < least_mismatch) {
            nearest = f;
            least_mismatch = mismatch;
        }
    }
    return matching >= 0 ? matching : nearest;
}

std::array<const BakedFace*, 6> face_pointers(const std::array<BakedFace, 6>& baked) {
    return {&baked[0], &baked[1], &baked[2], &baked[3], &baked[4], &baked[5]};
}

std::array<Primitive, 6> baked_proxy_faces(const std::vector<Primitive>& simplified, const OrientedBox& box,
                                           const std::array<const BakedFace*, 6>& baked) {
    const std::array<OrientedBoxFace, 6> faces = oriented_box_faces(box);
    std::array<Primitive, 6> out;
    for (std::size_t k = 0; k < simplified.size(); ++k) {
        const Primitive& p = simplified[k];
        std::array<std::map<std::uint32_t, std::uint32_t>, 6> copied;  // per face: p's vertex -> its copy
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const std::uint32_t* v = &p.indices[t];
            const int f = sampled_face(faces, baked, p.positions[v[0]], p.positions[v[1]], p.positions[v[2]]);
            if (f < 0) continue;
            const OrientedBoxFace& face = faces[std::size_t(f)];
            Primitive& q = out[std::size_t(f)];
            for (int i = 0; i < 3; ++i) {
                auto [at, added] =
                    copied[std::size_t(f)].try_emplace(v[i], std::uint32_t(q.positions.size()));
                if (added) {
                    q.positions.push_back(p.positions[v[i]]);
                    q.normals.push_back(face.normal);
                    q.uvs.push_back(face_uv(face, p.positions[v[i]]));
                    q.tangents.emplace_back(face.tangent.x(), face.tangent.y(), face.tangent.z(), 1.0f);
                }
                q.indices.push_back(at->second);
            }
            ++q.polygon_count;
        }
    }
    return out;
}

std::uint64_t baked_proxy_mesh_bytes(const std::array<Primitive, 6>& faces) {
    std::uint64_t bytes = 0;
    for (const Primitive& q : faces) {
        const VertexLayout layout{true, true, true, q.positions.size() <= 65535 ? 2 : 4};
        bytes +=
            q.positions.size() * layout.vertex_bytes() + q.indices.size() * std::uint64_t(layout.index_bytes);
    }
    return bytes;
}

}  // namespace boxlod
