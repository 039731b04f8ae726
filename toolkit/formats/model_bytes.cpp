#include "toolkit/formats/model_bytes.h"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace boxlod {
namespace {

// Every field in declaration order; plain values as their bytes, a vector as
// its count then its elements. One template pair per shape keeps writing and
// reading the same walk.
struct Writer {
    std::string out;
    template <typename T>
    void value(const T& v) {
        // Plain values, enums and Eigen's fixed-size matrices, whose storage is their bytes.
        static_assert(std::is_standard_layout_v<T> && !std::is_pointer_v<T>);
        out.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void text(const std::string& s) { values(std::vector<char>(s.begin(), s.end())); }
    template <typename T>
    void values(const std::vector<T>& v) {
        value(std::uint64_t(v.size()));
        out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
};

struct Reader {
    std::string_view in;
    void take(void* to, std::size_t size) {
        if (size > in.size()) throw std::logic_error("model_from_bytes: the bytes end early");
        std::memcpy(to, in.data(), size);
        in.remove_prefix(size);
    }
    template <typename T>
    void value(T& v) {
        take(&v, sizeof v);
    }
    void text(std::string& s) {
        std::vector<char> chars;
        values(chars);
        s.assign(chars.begin(), chars.end());
    }
    template <typename T>
    void values(std::vector<T>& v) {
        std::uint64_t size = 0;
        value(size);
        if (size > in.size() / sizeof(T))
            throw std::logic_error("model_from_bytes: a count beyond the bytes");
        v.resize(size);
        take(v.data(), size * sizeof(T));
    }
};

// Reading sizes vectors and fills optionals; writing (a const model) leaves them.
template <typename V>
void resize_to(V& v, std::uint64_t size) {
    if constexpr (!std::is_const_v<V>) v.resize(size);
}
template <typename O>
auto& filled(O& optional) {
    if constexpr (!std::is_const_v<O>)
        if (!optional) optional.emplace();
    return *optional;
}

// A node's fields, its primitives' with them.
template <typename Stream, typename N>
void walk_node(Stream& s, N& node) {
    s.text(node.name);
    s.text(node.rule);
    s.text(node.instance_of);
    s.text(node.source_id);
    s.value(node.parent);
    s.values(node.children);
    bool scoped = node.scope.has_value();
    s.value(scoped);
    if (scoped) {
        auto& scope = filled(node.scope);
        s.value(scope.center);
        s.value(scope.axes);
        s.value(scope.half_extents);
    }
    std::uint64_t count = node.primitives.size();
    s.value(count);
    resize_to(node.primitives, count);
    for (auto& p : node.primitives) {
        s.values(p.positions);
        s.values(p.normals);
        s.values(p.uvs);
        s.values(p.tangents);
        s.values(p.indices);
        s.value(p.polygon_count);
        s.value(p.material);
    }
}

template <typename Stream, typename Mat>
void walk_material(Stream& s, Mat& m) {
    s.text(m.name);
    s.value(m.base_color);
    s.value(m.base_color_texture);
    s.value(m.normal_texture);
    s.value(m.height_texture);
    s.value(m.height_depth);
    s.value(m.specular_color);
    s.value(m.shininess);
    s.value(m.specular_glossiness);
    s.value(m.specular_texture);
    s.value(m.glossiness);
    bool extension = m.specular_extension.has_value();
    s.value(extension);
    if (extension) s.value(filled(m.specular_extension));
    s.value(m.double_sided);
    s.value(m.alpha_mode);
    s.value(m.alpha_cutoff);
}

// The walk over a model's fields, for a Writer (const model) or a Reader.
template <typename Stream, typename M>
void walk(Stream& s, M& model) {
    s.text(model.source);
    s.value(model.origin);
    s.text(model.reference_system);
    std::uint64_t count = model.read_files.size();
    s.value(count);
    resize_to(model.read_files, count);
    for (auto& file : model.read_files) s.text(file);
    s.value(model.is_lod);
    count = model.lod_params.size();
    s.value(count);
    resize_to(model.lod_params, count);
    for (auto& [key, value] : model.lod_params) {
        s.text(key);
        s.text(value);
    }
    count = model.nodes.size();
    s.value(count);
    resize_to(model.nodes, count);
    for (auto& node : model.nodes) walk_node(s, node);
    count = model.materials.size();
    s.value(count);
    resize_to(model.materials, count);
    for (auto& m : model.materials) walk_material(s, m);
    count = model.textures.size();
    s.value(count);
    resize_to(model.textures, count);
    for (auto& t : model.textures) {
        s.text(t.name);
        s.value(t.image.width);
        s.value(t.image.height);
        s.value(t.image.channels);
        s.values(t.image.pixels);
        s.value(t.image16.width);
        s.value(t.image16.height);
        s.value(t.image16.channels);
        s.values(t.image16.pixels);
        s.value(t.wrap);
    }
}

}  // namespace

std::string model_bytes(const Model& model) {
    Writer writer;
    walk(writer, model);
    return std::move(writer.out);
}

Model model_from_bytes(std::string_view bytes) {
    Reader reader{bytes};
    Model model;
    walk(reader, model);
    if (!reader.in.empty()) throw std::logic_error("model_from_bytes: bytes left over");
    return model;
}

}  // namespace boxlod
