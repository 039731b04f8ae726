#include "toolkit/formats/cityjson_import.h"

#include "base/input_error.h"
#include "base/input_file.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "base/utf8.h"
#include "toolkit/formats/cityjson_geometry.h"
#include "toolkit/formats/json_input.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace boxlod {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// One document of the file: the whole file, or a CityJSONSeq line (its own
// vertices and appearance, the first line's transform).
struct Part {
    json document;
    std::string line;                       // "line N: " in a CityJSONSeq, else ""
    std::vector<Eigen::Vector3d> vertices;  // transformed: the file's coordinates
};

struct Transform {
    Eigen::Vector3d scale = Eigen::Vector3d::Ones(), translate = Eigen::Vector3d::Zero();
};

// A member's value with one line for each way it can be missing or wrong.
const json& member(const CityPlace& at, const json& object, const char* name, json::value_t type,
                   const char* what) {
    auto it = object.find(name);
    if (it == object.end()) at.fail(std::string("missing member '") + name + "'");
    if (it->type() != type && !(type == json::value_t::number_float && it->is_number()))
        at.fail(std::string("'") + name + "' is not " + what);
    return *it;
}

Eigen::Vector3d read_triple(const CityPlace& at, const json& value, const char* name, bool positive) {
    if (!value.is_array() || value.size() != 3) at.fail(std::string("'") + name + "' is not three numbers");
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number()) at.fail(std::string("'") + name + "' is not three numbers");
        out[i] = value[i].get<double>();
        if (!std::isfinite(out[i]) || (positive && !(out[i] > 0)))
            at.fail(std::string("'") + name + "' holds " + value[i].dump() +
                    (positive ? ": scales are positive" : ""));
    }
    return out;
}

// CityJSON 1.1 and 2.0 store vertices as integers scaled and translated by
// `transform` (CityJSON 2.0, section "Transform object"), which both require.
Transform read_transform(const CityPlace& at, const json& root) {
    if (!root.contains("transform"))
        at.fail("missing member 'transform' (CityJSON 1.1 and 2.0 require it; cjio upgrades older files)");
    const json& transform = member(at, root, "transform", json::value_t::object, "an object");
    const CityPlace in{at.file, at.place + "transform: "};
    return {read_triple(in, member(in, transform, "scale", json::value_t::array, "an array"), "scale", true),
            read_triple(in, member(in, transform, "translate", json::value_t::array, "an array"), "translate",
                        false)};
}

void read_vertices(const CityPlace& at, Part& part, const Transform& transform) {
    const json& vertices = member(at, part.document, "vertices", json::value_t::array, "an array");
    part.vertices.reserve(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const CityPlace in{at.file, at.place + "vertex " + std::to_string(i) + ": "};
        const Eigen::Vector3d stored = read_triple(in, vertices[i], "vertex", false);
        part.vertices.push_back(stored.cwiseProduct(transform.scale) + transform.translate);
        if (!(part.vertices.back().array().abs() <= max_city_coordinate).all())
            in.fail("coordinates beyond " + format_number(max_city_coordinate) +
                    " (the Earth is 1.3e7 m across)");
    }
}

void check_version(const CityPlace& at, const json& root, const char* type) {
    const json& found = member(at, root, "type", json::value_t::string, "a string");
    if (found != type) at.fail("type is " + found.dump() + ", not \"" + type + "\"");
    if (std::string(type) != "CityJSON") return;
    const json& version = member(at, root, "version", json::value_t::string, "a string");
    if (version != "1.1" && version != "2.0")
        at.fail("version " + version.dump() +
                ": boxlod reads CityJSON 1.1 and 2.0 (cjio upgrades older files)");
}

json parse_json(const CityPlace& at, std::string_view text) {
    check_json_input(text, at.file);
    try {
        return json::parse(text);
    } catch (
        const json::exception& error) {  // a syntax error, or a number beyond a double (out_of_range.406)
        std::string what = error.what();
        what = what.substr(what.find(']') + 2);  // drop "[json.exception.parse_error.101] "
        at.fail("not valid JSON: " + what);
    }
}

// metadata.referenceSystem of a CityJSON document (a CityJSONSeq's first line), "" without one.
std::string read_reference_system(const CityPlace& at, const json& document) {
    const auto metadata = document.find("metadata");
    if (metadata == document.end()) return "";
    if (!metadata->is_object()) at.fail("'metadata' is not an object");
    if (!metadata->contains("referenceSystem")) return "";
    std::string system =
        member(at.in("metadata"), *metadata, "referenceSystem", json::value_t::string, "a string")
            .get<std::string>();
    // Empty, it would place the file as one without a system does, at the default place, without a word.
    if (system.find_first_not_of(" \t") == std::string::npos)
        at.in("metadata").fail("'referenceSystem' is empty (leave it out where the file has none)");
    return system;
}

// A CityJSONFeature's objects (CityJSON 2.0 spec, CityJSON Text Sequences):
// its `id` names one of them, its main object, and no object is in an earlier
// line too (it would be drawn twice).
void check_feature_objects(const CityPlace& at, const json& feature, std::size_t line,
                           std::map<std::string, std::size_t>& lines) {
    const auto objects = feature.find("CityObjects");
    const auto id = feature.find("id");
    if (objects == feature.end() || !objects->is_object()) at.fail("a CityJSONFeature without CityObjects");
    if (id == feature.end() || !id->is_string() || !objects->contains(id->get<std::string>()))
        at.fail("'id' names none of the feature's CityObjects (its main object)");
    for (const auto& [name, object] : objects->items())
        if (const auto [where, first] = lines.emplace(name, line); !first)
            at.fail("CityObjects '" + name + "' is on line " + std::to_string(where->second) +
                    " too: each object is in one feature");
}

// The documents of a file: one, or a CityJSONSeq's lines (the first holds
// the transform and the metadata; each later line a CityJSONFeature); the
// reference system and a CityJSONSeq's first line's geometry templates, if asked.
std::vector<Part> read_parts(std::string_view bytes, const std::string& path,
                             std::string* reference_system = nullptr, json* file_templates = nullptr) {
    std::vector<Part> parts;
    const CityPlace file{path, ""};
    if (lowercase_extension(path) != ".jsonl") {
        parts.push_back({parse_json(file, bytes), "", {}});
        if (!parts[0].document.is_object()) file.fail("not a CityJSON object");
        check_version(file, parts[0].document, "CityJSON");
        read_vertices(file, parts[0], read_transform(file, parts[0].document));
        if (reference_system) *reference_system = read_reference_system(file, parts[0].document);
        return parts;
    }
    std::size_t line_number = 0;
    std::optional<Transform> transform;        // from the first line that is not blank
    std::map<std::string, std::size_t> lines;  // each CityObject's line: one feature holds it
    for (std::size_t start = 0; start < bytes.size();) {
        std::size_t end = std::min(bytes.find('\n', start), bytes.size());
        std::string_view line = bytes.substr(start, end - start);
        start = end + 1;
        ++line_number;
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
        const std::string prefix = "line " + std::to_string(line_number) + ": ";
        const CityPlace at{path, prefix};
        json document = parse_json(at, line);
        if (!document.is_object()) at.fail("not a JSON object");
        if (!transform) {
            check_version(at, document, "CityJSON");
            transform = read_transform(at, document);
            // Its first line holds no objects (CityJSON 2.0 spec, CityJSON Text Sequences), so none are read.
            for (const char* key : {"CityObjects", "vertices"})
                if (const auto found = document.find(key);
                    found != document.end() && !((found->is_object() || found->is_array()) && found->empty()))
                    at.fail(std::string(key) +
                            " is not empty: a CityJSONSeq's first line holds the metadata, " +
                            "its objects follow as CityJSONFeature lines");
            if (reference_system) *reference_system = read_reference_system(at, document);
            if (file_templates && document.contains("geometry-templates"))
                *file_templates = std::move(document["geometry-templates"]);
            continue;
        }
        check_version(at, document, "CityJSONFeature");
        check_feature_objects(at, document, line_number, lines);
        parts.push_back({std::move(document), prefix, {}});
        read_vertices(at, parts.back(), *transform);
    }
    if (!transform) file.fail("empty file: a CityJSONSeq starts with a CityJSON line");
    return parts;
}

// The model's origin in the file's coordinates: the middle of the vertices'
// ground rectangle, in whole units, so local coordinates stay small.
Eigen::Vector3d local_origin(const CityPlace& at, const std::vector<Part>& parts) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
    for (const Part& part : parts)
        for (const Eigen::Vector3d& p : part.vertices) {
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
    if (!(low.array() <= high.array()).all()) at.fail("no vertices: nothing to draw");
    return {std::round((low.x() + high.x()) / 2), std::round((low.y() + high.y()) / 2), std::round(low.z())};
}

// Each object's parent (its first `parents` entry, or an object listing it
// in `children`), checked to exist and to lead to a root.
std::map<std::string, std::string> parents_of(const CityPlace& at, const json& objects) {
    std::map<std::string, std::string> parent;
    for (const auto& [id, object] : objects.items()) {
        const CityPlace in{at.file, at.place + "CityObjects '" + id + "': "};
        if (!object.is_object()) in.fail("not an object");
        for (const char* key : {"parents", "children"}) {
            if (!object.contains(key)) continue;
            const json& list = member(in, object, key, json::value_t::array, "an array");
            for (const json& other : list) {
                if (!other.is_string() || !objects.contains(other.get<std::string>()))
                    in.fail(std::string(key) + ": " + other.dump() + " is not a CityObject of the file");
                if (std::string(key) == "parents" && !parent.count(id)) parent[id] = other.get<std::string>();
                if (std::string(key) == "children" && !parent.count(other.get<std::string>()))
                    parent[other.get<std::string>()] = id;
            }
        }
    }
    for (const auto& [id, first] : parent) {
        std::string at_id = id;
        for (int depth = 0; parent.count(at_id); ++depth) {
            at_id = parent.at(at_id);
            if (depth > max_nesting_depth) at.fail("CityObjects '" + id + "': parents " + nesting_message());
            if (at_id != id) continue;
            std::string chain = id;  // the cycle, named once it is found
            for (std::string step = parent.at(id); step != id; step = parent.at(step)) chain += " > " + step;
            at.fail("CityObjects '" + id + "': parents: a cycle (" + chain + " > " + id + ")");
        }
    }
    return parent;
}

// Each GeometryInstance the reading draws copies its template's points (cityjson_geometry.h): their
// count is checked against the memory budget before any is read, not after minutes of copying.
void check_instance_copies(const std::string& file, const std::vector<Part>& parts,
                           const json& file_templates, const std::string& lod) {
    double points = 0;
    for (const Part& part : parts) {
        auto own = part.document.find("geometry-templates");
        const json& templates = own != part.document.end() ? *own : file_templates;
        auto objects = part.document.find("CityObjects");
        if (!templates.is_object() || !templates.contains("templates") ||
            !templates["templates"].is_array() || objects == part.document.end() || !objects->is_object())
            continue;  // an instance without templates is refused as it is read
        const json& list = templates["templates"];
        std::vector<std::optional<std::size_t>> copied(list.size());  // each template's points, counted once
        for (const auto& [id, object] : objects->items()) {
            auto geometries = object.is_object() ? object.find("geometry") : object.end();
            if (!object.is_object() || geometries == object.end() || !geometries->is_array()) continue;
            for (std::size_t g : city_geometries_of_lod(*geometries, lod)) {
                const json& geometry = (*geometries)[g];
                if (!geometry.is_object() || !geometry.contains("type") ||
                    geometry["type"] != json("GeometryInstance"))
                    continue;
                auto t = geometry.find("template");
                if (t == geometry.end() || !t->is_number_unsigned() || t->get<std::size_t>() >= list.size())
                    continue;  // refused as it is read
                std::optional<std::size_t>& count = copied[t->get<std::size_t>()];
                if (!count) count = city_template_points(list[t->get<std::size_t>()]);
                points += double(*count);
            }
        }
    }
    check_memory(file + ": the GeometryInstances' copies of their templates",
                 points * bytes_per_instanced_point);
}

}  // namespace

Model import_cityjson(const std::string& path, const std::string& lod) {
    return import_cityjson_bytes(read_input_file(path, "CityJSON file"), path, lod);
}

// The steps: the documents and their vertices, the local origin, then each
// document's objects, parents first, with the geometry of the chosen LoD.
Model import_cityjson_bytes(std::string_view bytes, const std::string& path, const std::string& lod) {
    std::string reference_system;
    json file_templates;
    std::vector<Part> parts = read_parts(bytes, path, &reference_system, &file_templates);
    check_instance_copies(path, parts, file_templates, lod);
    const Eigen::Vector3d origin = local_origin({path, ""}, parts);
    Model model;
    model.source = path;
    model.origin = Eigen::Vector3d(origin.x(), origin.z(), -origin.y());  // z-up to the model's y-up
    model.reference_system = reference_system;
    add_node(model, -1, utf8_or_latin1(fs::path(path).stem().string()));
    CityGeometryReader reader(model, path, origin);
    if (!file_templates.is_null()) reader.use_file_templates(file_templates);
    for (Part& part : parts) {
        const CityPlace at{path, part.line};
        const json& objects = member(at, part.document, "CityObjects", json::value_t::object, "an object");
        const std::map<std::string, std::string> parent = parents_of(at, objects);
        reader.start_part(at, part.document, part.vertices);
        std::map<std::string, int> node_of;
        // Parents before children: an explicit stack from the roots.
        std::vector<std::pair<std::string, int>> pending;
        for (auto it = objects.rbegin(); it != objects.rend(); ++it)
            if (!parent.count(it.key())) pending.emplace_back(it.key(), 0);
        std::multimap<std::string, std::string> children;
        for (const auto& [child, p] : parent) children.emplace(p, child);
        while (!pending.empty()) {
            auto [id, parent_node] = pending.back();
            pending.pop_back();
            const int node = reader.add_object(at, id, objects.at(id), parent_node, lod);
            auto range = children.equal_range(id);
            std::vector<std::string> kids;
            for (auto it = range.first; it != range.second; ++it) kids.push_back(it->second);
            for (auto it = kids.rbegin(); it != kids.rend(); ++it) pending.emplace_back(*it, node);
        }
    }
    reader.finish(lod);
    // A polygon that triangulates to nothing (collinear, or fewer than 3 points) may leave a primitive
    // without triangles, which glTF cannot hold (an accessor of count 0).
    for (Node& node : model.nodes)
        std::erase_if(node.primitives, [](const Primitive& p) { return p.indices.empty(); });
    make_unit_normals_and_tangents(model);
    validate_model(model);
    return model;
}

std::vector<std::string> cityjson_lods(const std::string& path) {
    std::set<std::string> lods;
    for (const Part& part : read_parts(read_input_file(path, "CityJSON file"), path)) {
        auto objects = part.document.find("CityObjects");
        if (objects == part.document.end() || !objects->is_object()) continue;
        for (const auto& [id, object] : objects->items()) {
            auto geometries = object.is_object() ? object.find("geometry") : object.end();
            if (geometries == object.end() || !geometries->is_array()) continue;
            for (const json& geometry : *geometries)
                if (geometry.is_object() && !city_geometry_lod(geometry).empty())
                    lods.insert(city_geometry_lod(geometry));
        }
    }
    std::vector<std::string> out(lods.begin(), lods.end());
    std::stable_sort(out.begin(), out.end(), [](const std::string& a, const std::string& b) {
        return city_lod_number(a) > city_lod_number(b);
    });
    return out;
}

}  // namespace boxlod
