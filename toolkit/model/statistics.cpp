#include "toolkit/model/statistics.h"

#include "toolkit/model/cost.h"

#include <set>

namespace boxlod {

MeshCounts mesh_counts(const Model& model) {
    MeshCounts counts;
    std::set<int> materials;
    for (const Node& node : model.nodes)
        for (const Primitive& primitive : node.primitives) {
            materials.insert(primitive.material);
            counts.faces += primitive.polygon_count;
            counts.triangles += primitive.triangle_count();
            counts.vertices += primitive.positions.size();
        }
    counts.batches = materials.size();
    return counts;
}

KeyValues model_statistics(const Model& model) {
    std::size_t with_geometry = 0;
    for (const Node& node : model.nodes) with_geometry += node.has_geometry();
    MeshCounts counts = mesh_counts(model);
    Eigen::Vector3f size = model_bounds(model).size();
    KeyValues entries = {
        number_entry("nodes", double(model.nodes.size())),
        number_entry("nodes_with_geometry", double(with_geometry)),
        number_entry("depth", tree_depth(model)),
        number_entry("batches_original", double(counts.batches)),
        number_entry("faces_original", double(counts.faces)),
        number_entry("triangles_original", double(counts.triangles)),
        number_entry("vertices_original", double(counts.vertices)),
        float_entry("mesh_width", size.x()),
        float_entry("mesh_height", size.y()),
        float_entry("mesh_depth", size.z()),
    };
    KeyValues cost = cost_entries(model_cost(model), "_original");
    entries.insert(entries.end(), cost.begin(), cost.end());
    return entries;
}

}  // namespace boxlod
