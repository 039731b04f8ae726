#include "toolkit/formats/gltf_load.h"

#include "base/input_error.h"
#include "base/input_file.h"
#include "base/memory_budget.h"
#include "renderer/image.h"

#include <filesystem>
#include <span>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

// tinygltf's file callback: buffers and images named by URI are read as every
// input file is (a folder, a device or a missing file is a clear error).
bool read_whole_file(std::vector<unsigned char>* out, std::string*, const std::string& path, void*) {
    std::string bytes = read_input_file(path, "file");
    out->assign(bytes.begin(), bytes.end());
    return true;
}

// The images a file has decoded so far: each is checked against the memory budget by its header, and
// all of them together as they come (a file may name one large image many times).
struct ImagesDecoded {
    const std::string& file;
    double bytes = 0;
};

// tinygltf's image callback: our decoders, so that a broken image is named by
// its own file and a claimed size is checked before anything is allocated.
// 16-bit grey stays 16-bit (height maps); everything else becomes RGBA8.
bool load_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                const unsigned char* bytes, int size, void* images_decoded) {
    ImagesDecoded& decoded_so_far = *static_cast<ImagesDecoded*>(images_decoded);
    const std::string& file = decoded_so_far.file;
    std::string name = image->uri.empty() ? file + ": image " + std::to_string(index)
                                          : (fs::path(file).parent_path() / image->uri).string();
    std::span<const std::uint8_t> encoded(bytes, std::size_t(size));
    if (is_grey16(encoded)) {
        Image16 decoded = decode_image16(encoded, name);
        image->image.resize(decoded.pixels.size() * 2);
        for (std::size_t i = 0; i < decoded.pixels.size(); ++i)
            image->image[i * 2] = std::uint8_t(decoded.pixels[i] & 0xff),
                             image->image[i * 2 + 1] = std::uint8_t(decoded.pixels[i] >> 8);
        image->width = decoded.width;
        image->height = decoded.height;
        image->component = 1;
        image->bits = 16;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
        Image8 decoded = decode_image(encoded, name);
        image->image = std::move(decoded.pixels);
        image->width = decoded.width;
        image->height = decoded.height;
        image->component = 4;
        image->bits = 8;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    }
    decoded_so_far.bytes += double(image->image.size());
    check_memory(file + ": its images, decoded and converted",
                 2 * decoded_so_far.bytes);  // convert_image copies
    return true;
}

}  // namespace

tinygltf::Model load_gltf(std::string_view bytes, bool binary, const std::string& path) {
    tinygltf::TinyGLTF loader;
    ImagesDecoded images_decoded{path};
    loader.SetImageLoader(load_image, &images_decoded);
    tinygltf::FsCallbacks files{&tinygltf::FileExists, &tinygltf::ExpandFilePath, &read_whole_file,
                                &tinygltf::WriteWholeFile, nullptr};
    loader.SetFsCallbacks(files);
    tinygltf::Model gltf;
    std::string error, warning, directory = fs::path(path).parent_path().string();
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    bool ok =
        binary ? loader.LoadBinaryFromMemory(&gltf, &error, &warning, data, unsigned(bytes.size()), directory)
               : loader.LoadASCIIFromString(&gltf, &error, &warning, bytes.data(), unsigned(bytes.size()),
                                            directory);
    if (!ok) throw_input_error(path, "", error.empty() ? "malformed glTF" : error);
    return gltf;
}

}  // namespace boxlod
