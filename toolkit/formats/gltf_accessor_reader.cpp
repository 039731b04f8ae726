// Accessor reading (toolkit/formats/gltf_accessor_reader.h).
#include "toolkit/formats/gltf_accessor_reader.h"

#include "base/input_error.h"

#include <algorithm>
#include <cstring>

namespace boxlod {
namespace {

// Bytes of accessor `index`, checked against its buffer view and buffer.
struct View {
    const unsigned char* data;
    std::size_t stride, count;
    int component_type, components;
    bool normalized;
};
View view(const GltfAccessorReader& reader, int index, const std::string& place) {
    const tinygltf::Model& gltf = reader.gltf;
    if (index < 0 || index >= int(gltf.accessors.size()))
        reader.fail(place, "accessor " + std::to_string(index) + " out of range");
    const tinygltf::Accessor& accessor = gltf.accessors[index];
    std::string where = place + " accessor " + std::to_string(index);
    if (accessor.sparse.isSparse) reader.fail(where, "sparse accessors are not supported");
    if (accessor.bufferView < 0 || accessor.bufferView >= int(gltf.bufferViews.size()))
        reader.fail(where, "buffer view out of range");
    const tinygltf::BufferView& buffer_view = gltf.bufferViews[accessor.bufferView];
    if (buffer_view.buffer < 0 || buffer_view.buffer >= int(gltf.buffers.size()))
        reader.fail(where, "buffer out of range");
    const tinygltf::Buffer& buffer = gltf.buffers[buffer_view.buffer];
    int component_size = tinygltf::GetComponentSizeInBytes(accessor.componentType);
    int components = tinygltf::GetNumComponentsInType(accessor.type);
    if (component_size <= 0 || components <= 0) reader.fail(where, "unknown component or element type");
    std::size_t element = std::size_t(component_size) * components;
    std::size_t stride = buffer_view.byteStride ? buffer_view.byteStride : element;
    // glTF 2.0 spec 3.6.2.4, Data Alignment: a stride of 4 to 252 bytes, a multiple of 4.
    if (buffer_view.byteStride && (stride < 4 || stride > 252 || stride % 4 != 0))
        reader.fail(where, "byteStride " + std::to_string(stride) + " is not a multiple of 4 from 4 to 252");
    if (stride < element) reader.fail(where, "byteStride is smaller than an element");
    // Every size here comes from the file: checked against overflow before it is added.
    std::size_t needed = 0;
    if (accessor.count > 0 &&
        (!checked_multiply(accessor.count - 1, stride, needed) || needed > SIZE_MAX - element))
        reader.fail(where, "count " + std::to_string(accessor.count) + " is larger than any buffer");
    if (accessor.count > 0) needed += element;
    if (!range_fits(buffer_view.byteOffset, buffer_view.byteLength, buffer.data.size()) ||
        !range_fits(accessor.byteOffset, needed, buffer_view.byteLength))
        reader.fail(where, "data runs past the end of its buffer (truncated file?)");
    return {buffer.data.data() + buffer_view.byteOffset + accessor.byteOffset,
            stride,
            accessor.count,
            accessor.componentType,
            components,
            accessor.normalized};
}

double component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        auto v = double(std::int8_t(*p));
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default: return 0;
    }
}

}  // namespace

void GltfAccessorReader::fail(const std::string& place, const std::string& what) const {
    throw_input_error(file, place, what);
}

template <int N>
std::vector<Eigen::Matrix<double, N, 1>> GltfAccessorReader::vectors(int index,
                                                                     const std::string& place) const {
    View v = view(*this, index, place);
    if (v.components != N)
        fail(place + " accessor " + std::to_string(index), "expected " + std::to_string(N) + " components");
    int size = tinygltf::GetComponentSizeInBytes(v.component_type);
    std::vector<Eigen::Matrix<double, N, 1>> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i)
        for (int c = 0; c < N; ++c)
            out[i][c] = component(v.data + i * v.stride + c * size, v.component_type, v.normalized);
    return out;
}

std::vector<std::uint32_t> GltfAccessorReader::indices(int index, const std::string& place) const {
    View v = view(*this, index, place);
    if (v.components != 1 || !(v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                               v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                               v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(place, "indices must be unsigned integer scalars");
    std::vector<std::uint32_t> out(v.count);
    for (std::size_t i = 0; i < v.count; ++i)
        out[i] = std::uint32_t(component(v.data + i * v.stride, v.component_type, false));
    return out;
}

template std::vector<Eigen::Matrix<double, 2, 1>> GltfAccessorReader::vectors<2>(int,
                                                                                 const std::string&) const;
template std::vector<Eigen::Matrix<double, 3, 1>> GltfAccessorReader::vectors<3>(int,
                                                                                 const std::string&) const;
template std::vector<Eigen::Matrix<double, 4, 1>> GltfAccessorReader::vectors<4>(int,
                                                                                 const std::string&) const;

}  // namespace boxlod
