#include "toolkit/formats/ifc_io.h"

#include "base/child_process.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/memory_budget.h"
#include "base/utf8.h"
#include "toolkit/formats/ifc_reader_script.h"
#include "toolkit/formats/json_input.h"
#include "toolkit/formats/step_file_check.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <tuple>

namespace boxlod {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// What the script answered (toolkit/formats/ifc_reader.cjs): its header and the bytes after it.
struct Answer {
    json header;
    std::string_view bytes;
};

Answer split_answer(const std::string& answer, const std::string& path) {
    std::uint64_t length = 0;
    if (answer.size() < sizeof length) throw_input_error(path, "", "web-ifc gave no answer");
    std::memcpy(&length, answer.data(), sizeof length);
    if (!range_fits(sizeof length, length, answer.size()))
        throw_input_error(path, "", "web-ifc's answer is cut short");
    check_json_input(std::string_view(answer).substr(sizeof length, length), path, 1,
                     "web-ifc's answer, parsed,");
    Answer out{json::parse(answer.substr(sizeof length, length), nullptr, false),
               std::string_view(answer).substr(sizeof length + length)};
    if (!out.header.is_object()) throw_input_error(path, "", "web-ifc's answer is not JSON");
    if (out.header.contains("error"))
        throw_input_error(path, "", "web-ifc cannot read it: " + out.header["error"].get<std::string>());
    return out;
}

// `count` values of T at the [offset, count] pair `range` of the answer's bytes.
template <typename T>
std::vector<T> values_at(const Answer& answer, const json& range, std::size_t per_item,
                         const std::string& path) {
    std::size_t offset = 0, count = 0, bytes = 0;
    if (range.is_array() && range.size() == 2 && range[0].is_number_unsigned() &&
        range[1].is_number_unsigned()) {
        offset = range[0].get<std::size_t>();
        count = range[1].get<std::size_t>();
    }
    if (!checked_multiply(count, per_item * sizeof(T), bytes) ||
        !range_fits(offset, bytes, answer.bytes.size()))
        throw_input_error(path, "", "web-ifc's answer points outside its bytes");
    std::vector<T> out(count * per_item);
    if (bytes > 0) std::memcpy(out.data(), answer.bytes.data() + offset, bytes);
    return out;
}

// The spatial structure as nodes: parents come first in the answer.
void add_nodes(Model& model, const json& nodes, const std::string& path) {
    if (!nodes.is_array() || nodes.empty()) throw_input_error(path, "", "no spatial structure (IfcProject)");
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const json& node = nodes[n];
        const int parent = node.value("parent", -1);
        if ((n == 0) != (parent < 0) || parent >= int(n))
            throw_input_error(path, "", "web-ifc's tree is not a tree");
        const std::string type = node.value("type", ""), name = utf8_or_latin1(node.value("name", ""));
        const int index = add_node(model, parent, name.empty() ? type : name);
        model.nodes[std::size_t(index)].rule = type;
        model.nodes[std::size_t(index)].source_id = node.value("global_id", "");
    }
}

// One material per colour (IfcSurfaceStyleRendering as web-ifc gives it);
// see-through ones are blended, as assimp's are.
int material_of(Model& model, std::map<std::tuple<float, float, float, float>, int>& materials,
                const json& colour, const std::string& path) {
    Eigen::Vector4f c(1, 1, 1, 1);
    if (colour.is_array() && colour.size() == 4)
        for (int i = 0; i < 4; ++i)
            c[i] = colour[std::size_t(i)].is_number() ? colour[std::size_t(i)].get<float>() : -1;
    if (!((c.array() >= 0).all() && (c.array() <= 1).all()))
        throw_input_error(path, "", "a colour outside [0, 1]");
    const auto key = std::make_tuple(c[0], c[1], c[2], c[3]);
    if (auto known = materials.find(key); known != materials.end()) return known->second;
    Material material;
    material.name = "colour " + std::to_string(materials.size());
    material.base_color = c;
    if (c[3] < 1) material.alpha_mode = AlphaMode::blend;
    model.materials.push_back(material);
    return materials[key] = int(model.materials.size()) - 1;
}

// Each placed geometry joins its element's primitive of its colour.
void add_pieces(Model& model, const Answer& answer, const std::string& path) {
    std::map<std::tuple<float, float, float, float>, int> materials;
    for (const json& piece : answer.header.value("pieces", json::array())) {
        const int node = piece.value("node", -1);
        if (node < 0 || node >= int(model.nodes.size()))
            throw_input_error(path, "", "web-ifc's piece names no node");
        const std::vector<float> positions =
            values_at<float>(answer, piece.value("positions", json()), 3, path);
        const std::vector<float> normals = values_at<float>(answer, piece.value("normals", json()), 3, path);
        const std::vector<std::uint32_t> indices =
            values_at<std::uint32_t>(answer, piece.value("indices", json()), 1, path);
        if (normals.size() != positions.size() || indices.size() % 3 != 0)
            throw_input_error(path, "", "web-ifc's piece is malformed");
        if (indices.empty()) continue;  // a piece that draws nothing: no primitive, no material
        const int material = material_of(model, materials, piece.value("color", json()), path);
        auto& primitives = model.nodes[std::size_t(node)].primitives;
        auto primitive = std::find_if(primitives.begin(), primitives.end(),
                                      [&](const Primitive& p) { return p.material == material; });
        if (primitive == primitives.end()) {
            primitives.push_back({});
            primitive = primitives.end() - 1;
            primitive->material = material;
        }
        const std::uint32_t first = std::uint32_t(primitive->positions.size());
        for (std::size_t v = 0; v < positions.size(); v += 3) {
            primitive->positions.emplace_back(positions[v], positions[v + 1], positions[v + 2]);
            primitive->normals.emplace_back(normals[v], normals[v + 1], normals[v + 2]);
        }
        for (std::uint32_t index : indices) {
            if (index >= positions.size() / 3)
                throw_input_error(path, "", "web-ifc's piece indexes past its vertices");
            primitive->indices.push_back(first + index);
        }
        primitive->polygon_count += indices.size() / 3;
    }
}

}  // namespace

std::string web_ifc_module() {
    std::string folder;
    if (const char* module = std::getenv("BOXLOD_WEB_IFC"); module && *module) {
        folder = module;
    } else {
        fs::path cache;
        if (const char* npm = std::getenv("BOXLOD_NPM_CACHE"); npm && *npm)
            cache = npm;
        else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
            cache = fs::path(xdg) / "boxlod" / "npm";
        else if (const char* home = std::getenv("HOME"); home && *home)
            cache = fs::path(home) / ".cache" / "boxlod" / "npm";
        folder = (cache / ("web-ifc-" + std::string(web_ifc_version)) / "node_modules" / "web-ifc").string();
    }
    std::error_code error;
    // Absolute: the reader finds web-ifc's WebAssembly beside the module by this folder.
    return fs::is_regular_file(fs::path(folder) / "web-ifc-api-node.js", error)
               ? fs::absolute(folder, error).string()
               : "";
}

Model import_ifc_with_web_ifc(const std::string& path) {
    const std::size_t file_bytes = check_input_file(path, "IFC file");
    {
        const std::string bytes = read_input_file(path, "IFC file");
        check_step_file(bytes, path, std::numeric_limits<int>::max());
    }
    const std::string module = web_ifc_module();
    if (module.empty())
        throw_input_error(
            path, "",
            "reading IFC needs web-ifc " + std::string(web_ifc_version) + " (make demo installs it)");
    // A minute, and a second more per megabyte; the memory budget for node's resident memory, but no
    // address-space limit: a WebAssembly memory reserves far more than it uses (web-ifc caps its own).
    const ChildLimits limits{0, 60 + double(file_bytes) / 1e6, memory_budget()};
    const std::string answer = run_program_in_child({"node", "-", module, fs::absolute(path).string()},
                                                    ifc_reader_script, limits, path, "web-ifc");
    const Answer parts = split_answer(answer, path);
    Model model;
    model.source = path;
    add_nodes(model, parts.header.value("nodes", json()), path);
    add_pieces(model, parts, path);
    const json origin = parts.header.value("origin", json::array());
    if (origin.is_array() && origin.size() == 3 && origin[0].is_number() && origin[1].is_number() &&
        origin[2].is_number())
        model.origin =
            Eigen::Vector3d(origin[0].get<double>(), origin[1].get<double>(), origin[2].get<double>());
    make_unit_normals_and_tangents(model);
    validate_model(model);
    return model;
}

}  // namespace boxlod
