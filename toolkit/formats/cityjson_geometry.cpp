#include "toolkit/formats/cityjson_geometry.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "renderer/image.h"
#include "toolkit/cgal/polygon_triangulation.h"
#include "toolkit/formats/cityjson_material.h"
#include "toolkit/formats/cityjson_semantic_colours.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <tuple>

namespace boxlod {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// A value of the semantics, material or texture tree one level down: an
// array's entry i, a single value for all, or nothing.
const json* entry(const CityPlace& at, const json* values, std::size_t i, std::size_t count,
                  const char* name) {
    if (!values || values->is_null()) return nullptr;
    if (!values->is_array()) return values;
    if (values->size() != count)
        at.fail(std::string(name) + " has " + std::to_string(values->size()) +
                " entries where boundaries has " + std::to_string(count));
    return &(*values)[i];
}

std::size_t index_in(const CityPlace& at, const json& value, std::size_t count, const std::string& what) {
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        std::uint64_t(value.get<std::int64_t>()) >= count)
        at.fail(what + " " + value.dump() + " is outside 0.." + std::to_string(std::int64_t(count) - 1));
    return std::size_t(value.get<std::int64_t>());
}

// The theme a geometry's material or texture object is read in: the file's
// default theme where the object has it, else its first theme by name.
const json* theme_values(const CityPlace& at, const json& geometry, const char* key,
                         const std::string& default_theme) {
    auto themes = geometry.find(key);
    if (themes == geometry.end()) return nullptr;
    if (!themes->is_object() || themes->empty())
        at.fail(std::string("'") + key + "' is not an object of themes");
    const json& theme = themes->contains(default_theme) ? themes->at(default_theme) : themes->begin().value();
    if (!theme.is_object()) at.fail(std::string("'") + key + "' theme is not an object");
    if (theme.contains("values")) return &theme.at("values");
    if (theme.contains("value")) return &theme.at("value");
    at.fail(std::string("'") + key + "' theme has neither 'values' nor 'value'");
}

}  // namespace

// What one document holds and what the reading has made so far.
struct CityReadState {
    CityReadState(Model& m, const std::string& f, const Eigen::Vector3d& o) : model(m), file(f), origin(o) {}
    Model& model;
    const std::string& file;
    Eigen::Vector3d origin;  // in the file's coordinates
    // The current document's:
    const json* document = nullptr;
    const std::vector<Eigen::Vector3d>* vertices = nullptr;
    std::vector<Eigen::Vector2f> uvs;
    std::map<std::size_t, int> texture_of;  // appearance texture -> model texture (-1: missing)
    std::map<std::tuple<int, int, std::string>, int>
        material_of;  // (material, texture, semantic type) -> model material
    std::string material_theme, texture_theme;
    // Over all documents:
    std::map<std::pair<std::string, Wrap>, int> texture_of_file;  // (image file, wrap) -> model texture
    std::set<std::string> missing_textures, lods;
    std::size_t without_lod = 0, polygons = 0;
    std::size_t points = 0, instanced_points = 0;  // of polygons emitted; by GeometryInstances
    // Geometry templates: a CityJSONSeq's first line's; those whose points were read (at the first
    // GeometryInstance using them), their points, the points each template names, and the points placed
    // by the latest instance (only those it names).
    const json* file_templates = nullptr;
    const json* templates_read = nullptr;
    std::vector<Eigen::Vector3d> template_points;
    std::map<std::size_t, std::vector<std::size_t>> points_of_template;
    std::vector<Eigen::Vector3d> placed;
    double images_memory = 0;

    const json* appearance(const char* key) const {
        auto a = document->find("appearance");
        if (a == document->end() || !a->is_object() || !a->contains(key)) return nullptr;
        return &a->at(key);
    }
};

namespace {

// The model texture of appearance texture t, read once per document; a file
// that is not there (or a URL) is left out and named in finish's warning.
int texture_index(const CityPlace& at, CityReadState& s, std::size_t t) {
    if (auto known = s.texture_of.find(t); known != s.texture_of.end()) return known->second;
    const json* textures = s.appearance("textures");
    if (!textures || !textures->is_array())
        at.fail("texture " + std::to_string(t) + " but the appearance has no 'textures'");
    const json& texture = (*textures)[index_in(at, json(t), textures->size(), "texture index")];
    if (!texture.is_object() || !texture.contains("image") || !texture["image"].is_string() ||
        texture["image"].get_ref<const std::string&>().find('\0') != std::string::npos)  // read up to it
        at.fail("appearance: texture " + std::to_string(t) + " has no 'image' (a file name, without NUL)");
    const std::string image = texture["image"].get<std::string>();
    const fs::path path = fs::path(s.file).parent_path() / image;
    std::error_code error;
    int index = -1;
    if (image.find("://") != std::string::npos || fs::path(image).is_absolute() ||
        !fs::is_regular_file(path, error)) {
        s.missing_textures.insert(image);
    } else {
        const json mode = texture.value("wrapMode", json("none"));
        const Wrap wrap =
            mode == "wrap" || mode == "mirror" ? Wrap::repeat : Wrap::clamp;  // "none", "border"
        // One image file, one texture: a CityJSONSeq's features or many textures may share one atlas.
        const fs::path canonical = fs::weakly_canonical(path, error);
        const auto key =
            std::make_pair((canonical.empty() ? path.lexically_normal() : canonical).string(), wrap);
        const auto [known, added] = s.texture_of_file.try_emplace(key, int(s.model.textures.size()));
        if (added) {
            s.model.textures.push_back(
                {fs::path(image).filename().string(), read_image(path.string()), {}, wrap});
            s.model.read_files.push_back(path.string());
            s.images_memory += double(s.model.textures.back().image.pixels.size());  // each checked alone
            check_memory(s.file + ": its images, decoded", s.images_memory);
        }
        index = known->second;
    }
    s.texture_of[t] = index;
    return index;
}

// The model material for a surface: its appearance material and texture, or
// its semantic type's colour.
int material_index(const CityPlace& at, CityReadState& s, int material, int texture,
                   const std::string& type) {
    const auto key = std::make_tuple(material, texture, material < 0 && texture < 0 ? type : std::string());
    if (auto known = s.material_of.find(key); known != s.material_of.end()) return known->second;
    Material out;
    if (material >= 0) {
        out = city_material(at.in("appearance: material " + std::to_string(material)),
                            (*s.appearance("materials"))[std::size_t(material)], std::size_t(material));
    } else if (texture < 0) {
        out.name = type.empty() ? "surface" : type;
        out.base_color.head<3>() = semantic_colour(type);
    }
    if (texture >= 0) {
        out.base_color_texture = texture;
        if (out.name.empty()) out.name = s.model.textures[std::size_t(texture)].name;
    }
    s.model.materials.push_back(out);
    return s.material_of[key] = int(s.model.materials.size()) - 1;
}

// A polygon's surface node: the object's node, or (with semantics) a child
// per semantic surface, under the surface its `parent` names (a window in its wall).
struct SurfaceNodes {
    const json* surfaces = nullptr;  // semantics.surfaces
    int object_node = 0;
    std::map<std::size_t, int> node_of;
};

int surface_node(const CityPlace& at, CityReadState& s, SurfaceNodes& nodes, std::size_t surface,
                 std::size_t depth = 0) {
    if (auto known = nodes.node_of.find(surface); known != nodes.node_of.end()) return known->second;
    if (depth > nodes.surfaces->size() || depth > std::size_t(max_nesting_depth))
        at.fail("semantics: surface " + std::to_string(surface) + "'s parents " +
                (depth > nodes.surfaces->size() ? "form a cycle" : nesting_message()));
    const json& entry = (*nodes.surfaces)[surface];
    if (!entry.is_object() || !entry.contains("type") || !entry["type"].is_string())
        at.fail("semantics: surface " + std::to_string(surface) + " has no type");
    int parent = nodes.object_node;
    if (entry.contains("parent"))
        parent = surface_node(at, s, nodes,
                              index_in(at, entry["parent"], nodes.surfaces->size(), "semantics: parent"),
                              depth + 1);
    const std::string type = entry["type"].get<std::string>();
    const int node = add_node(s.model, parent, type + " " + std::to_string(surface));
    s.model.nodes[std::size_t(node)].rule = type;
    return nodes.node_of[surface] = node;
}

// The values that apply to one surface of a geometry (null: none).
struct SurfaceValues {
    const json* semantic = nullptr;
    const json* material = nullptr;
    const json* texture = nullptr;  // per ring: [texture, uv, uv, ...]
};

// One geometry's emission: the vertices it indexes (the document's, or a
// template's placed), where each (vertex, uv) went in each primitive.
struct GeometryEmission {
    CityReadState& s;
    const std::vector<Eigen::Vector3d>& vertices;
    SurfaceNodes nodes;
    std::map<std::tuple<int, int, std::size_t, int>, std::uint32_t>
        vertex_of;  // (node, material, vertex, uv)

    Primitive& primitive(int node, int material) {
        auto& primitives = s.model.nodes[std::size_t(node)].primitives;
        for (Primitive& p : primitives)
            if (p.material == material) return p;
        primitives.push_back({});
        primitives.back().material = material;
        return primitives.back();
    }
    // The file's coordinates (z up) to the model's: local, y up.
    Eigen::Vector3f local(const Eigen::Vector3d& p) const {
        const Eigen::Vector3d d = p - s.origin;
        return Eigen::Vector3f(float(d.x()), float(d.z()), float(-d.y()));
    }
};

// Up: a roof; down: the ground; else a wall (the file's z is up).
std::string facing_type(const std::vector<Eigen::Vector3d>& vertices, const std::vector<std::size_t>& ring) {
    std::vector<Eigen::Vector3d> points;
    for (std::size_t v : ring) points.push_back(vertices[v] - vertices[ring[0]]);
    const Eigen::Vector3d normal = newell_normal(points);
    if (normal.z() > 0.5 * normal.norm()) return "RoofSurface";
    if (normal.z() < -0.5 * normal.norm()) return "GroundSurface";
    return "WallSurface";
}

std::vector<std::size_t> ring_indices(const CityPlace& at, const json& ring, std::size_t vertex_count) {
    if (!ring.is_array()) at.fail("a ring is not an array of vertex indices");
    std::vector<std::size_t> out;
    for (const json& v : ring) out.push_back(index_in(at, v, vertex_count, "vertex index"));
    return out;
}

// The uv indices of one ring from its texture value [t, uv, ...]; -1: untextured.
int ring_texture(const CityPlace& at, const CityReadState& s, const json* value, std::size_t ring_size,
                 std::vector<int>& uvs) {
    if (!value || value->is_null() || !value->is_array() || value->empty() || (*value)[0].is_null())
        return -1;
    if (value->size() != ring_size + 1)
        at.fail("texture values: a ring of " + std::to_string(ring_size) + " vertices has " +
                std::to_string(value->size() - 1) + " uv indices");
    const json* textures = s.appearance("textures");
    const int texture = int(
        index_in(at, (*value)[0], textures && textures->is_array() ? textures->size() : 0, "texture index"));
    for (std::size_t i = 1; i < value->size(); ++i)
        uvs.push_back(int(index_in(at, (*value)[i], s.uvs.size(), "uv index")));
    return texture;
}

// A surface's rings (vertex indices) and, where it is textured, its texture
// and the uv index of each ring's vertices in order.
struct SurfaceRings {
    std::vector<std::vector<std::size_t>> rings;
    std::vector<int> uvs;
    int texture = -1;
};

SurfaceRings read_rings(const CityPlace& at, const CityReadState& s, const json& polygon,
                        const json* texture_values, std::size_t vertex_count) {
    if (!polygon.is_array() || polygon.empty()) at.fail("a surface is not an array of rings");
    SurfaceRings out;
    std::size_t corners = 0;
    for (std::size_t r = 0; r < polygon.size(); ++r) {
        out.rings.push_back(ring_indices(at, polygon[r], vertex_count));
        corners += out.rings.back().size();
        const json* ring_value = entry(at, texture_values, r, polygon.size(), "texture values");
        const int ring_texture_index = ring_texture(at, s, ring_value, out.rings.back().size(), out.uvs);
        if (r == 0) out.texture = ring_texture_index;
    }
    if (out.texture >= 0 && out.uvs.size() != corners)
        at.fail("texture values: every ring of a textured surface needs its uv indices");
    return out;
}

void emit_polygon(const CityPlace& at, GeometryEmission& g, const json& polygon,
                  const SurfaceValues& values) {
    CityReadState& s = g.s;
    const auto [rings, uvs, texture] = read_rings(at, s, polygon, values.texture, g.vertices.size());
    int node = g.nodes.object_node;
    std::string type;
    if (values.semantic && !values.semantic->is_null()) {
        if (!g.nodes.surfaces) at.fail("semantics: values without surfaces");
        const std::size_t surface =
            index_in(at, *values.semantic, g.nodes.surfaces->size(), "semantics: surface index");
        node = surface_node(at, s, g.nodes, surface);
        type = s.model.nodes[std::size_t(node)].rule;
    }
    int material = -1;
    if (values.material && !values.material->is_null()) {
        const json* materials = s.appearance("materials");
        material =
            int(index_in(at, *values.material, materials && materials->is_array() ? materials->size() : 0,
                         "material index"));
    }
    const int model_texture = texture >= 0 ? texture_index(at, s, std::size_t(texture)) : -1;
    // A surface that names no semantic type is coloured as the type its facing
    // suggests, so that a LoD without semantics (3DBAG's 1.2 and 1.3) is
    // drawn in the same colours as one with them.
    const int model_material = material_index(at, s, material, model_texture,
                                              type.empty() ? facing_type(g.vertices, rings[0]) : type);
    Primitive& primitive = g.primitive(node, model_material);
    std::vector<std::vector<Eigen::Vector3d>> points;
    for (const auto& ring : rings) {
        points.emplace_back();
        for (std::size_t v : ring) points.back().push_back(g.vertices[v] - s.origin);
    }
    const PolygonTriangles triangles = triangulate_polygon(points);
    if (triangles.too_many_crossings) at.fail("a polygon whose rings cross more often than they have points");
    std::vector<std::uint32_t> index_of;  // polygon point -> primitive vertex
    std::size_t k = 0;
    for (const auto& ring : rings)
        for (std::size_t v : ring) {
            const int uv = model_texture >= 0 ? uvs[k] : -1;
            ++k;
            auto [it, added] = g.vertex_of.try_emplace({node, model_material, v, uv},
                                                       std::uint32_t(primitive.positions.size()));
            if (added) {
                primitive.positions.push_back(g.local(g.vertices[v]));
                if (uv >= 0) primitive.uvs.push_back(s.uvs[std::size_t(uv)]);
            }
            index_of.push_back(it->second);
        }
    for (const Eigen::Vector3d& p : triangles.added_points) {  // where rings cross: a vertex of its own
        index_of.push_back(std::uint32_t(primitive.positions.size()));
        primitive.positions.push_back(g.local(p + s.origin));
        if (model_texture >= 0) primitive.uvs.push_back(primitive.uvs[index_of[0]]);
    }
    for (const auto& triangle : triangles.triangles)
        for (std::uint32_t corner : triangle) primitive.indices.push_back(index_of[corner]);
    s.points += k;
    if (!triangles.triangles.empty()) {
        ++primitive.polygon_count;
        ++s.polygons;
    }
}

// Down the boundaries to the surfaces (a polygon: an array of rings), the
// semantics, material and texture values alongside.
void walk(const CityPlace& at, GeometryEmission& g, const json& boundaries, int depth,
          const SurfaceValues& values) {
    if (depth == 0) return emit_polygon(at, g, boundaries, values);
    if (!boundaries.is_array()) at.fail("boundaries are not nested as the geometry's type says");
    for (std::size_t i = 0; i < boundaries.size(); ++i) {
        const SurfaceValues below{entry(at, values.semantic, i, boundaries.size(), "semantics values"),
                                  entry(at, values.material, i, boundaries.size(), "material values"),
                                  entry(at, values.texture, i, boundaries.size(), "texture values")};
        walk(at, g, boundaries[i], depth - 1, below);
    }
}

// How deep a geometry type nests surfaces in its boundaries; 0: no surfaces (points, lines); -1: no type
// CityJSON knows.
int surface_depth(const std::string& type) {
    if (type == "MultiSurface" || type == "CompositeSurface") return 1;
    if (type == "Solid") return 2;
    if (type == "MultiSolid" || type == "CompositeSolid") return 3;
    if (type == "MultiPoint" || type == "MultiLineString") return 0;
    return -1;
}

int surface_depth(const CityPlace& at, const std::string& type) {
    const int depth = surface_depth(type);
    if (depth < 0) at.fail("unknown geometry type '" + type + "'");
    return depth;
}

void read_geometry(const CityPlace& at, CityReadState& s, const json& geometry, int object_node,
                   const std::vector<Eigen::Vector3d>& vertices, bool in_template = false);

std::vector<Eigen::Vector3d> read_template_points(const CityPlace& at, const json& points) {
    std::vector<Eigen::Vector3d> read;
    for (const json& p : points) {
        if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
            at.fail("vertices-templates: not three numbers");
        read.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    }
    return read;
}

// The point indices a template's boundaries name, repeats kept (read_geometry refuses what is not one).
void collect_point_indices(const json& boundaries, int depth, std::vector<std::size_t>& indices) {
    if (depth > max_nesting_depth) return;
    for (const json& b : boundaries) {
        if (b.is_array()) collect_point_indices(b, depth + 1, indices);
        if (b.is_number_integer() && b.get<std::int64_t>() >= 0) indices.push_back(b.get<std::size_t>());
    }
}

// Those of a surface template only: a point or line template draws nothing (read_geometry).
std::vector<std::size_t> surface_point_indices(const json& shape) {
    std::vector<std::size_t> indices;
    if (!shape.is_object() || !shape.contains("boundaries") || !shape["boundaries"].is_array())
        return indices;
    const std::string type = shape.contains("type") && shape["type"].is_string() ? shape["type"] : json("");
    if (surface_depth(type) > 0) collect_point_indices(shape["boundaries"], 0, indices);
    return indices;
}

const std::vector<std::size_t>& points_of_template(CityReadState& s, std::size_t t, const json& shape) {
    auto known = s.points_of_template.find(t);
    if (known != s.points_of_template.end()) return known->second;
    std::vector<std::size_t> indices = surface_point_indices(shape);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    return s.points_of_template[t] = std::move(indices);
}

// The geometry templates an instance of the current document uses: its own, or in a CityJSONSeq the
// first line's (CityJSON 2.0, "CityJSONFeature"); their points are read once.
const json& geometry_templates(const CityPlace& at, CityReadState& s) {
    auto own = s.document->find("geometry-templates");
    const json* templates = own != s.document->end() ? &*own : s.file_templates;
    if (!templates || !templates->is_object() || !templates->contains("templates") ||
        !templates->contains("vertices-templates") || !(*templates)["templates"].is_array() ||
        !(*templates)["vertices-templates"].is_array())
        at.fail(
            "a GeometryInstance but the file has no geometry-templates of templates and vertices-templates");
    if (templates != s.templates_read) {
        s.templates_read = templates;
        s.template_points = read_template_points(at, (*templates)["vertices-templates"]);
        s.points_of_template.clear();
    }
    return *templates;
}

// A GeometryInstance: a template of geometry-templates, transformed by its
// matrix (row-major) and moved to its reference point (CityJSON 2.0, "Geometry templates").
void read_instance(const CityPlace& at, CityReadState& s, const json& geometry, int object_node) {
    const json& list = geometry_templates(at, s).at("templates");
    if (!geometry.contains("template")) at.fail("a GeometryInstance without a template");
    const std::size_t t = index_in(at, geometry["template"], list.size(), "template");
    const json& shape = list[t];
    auto boundaries = geometry.find("boundaries");
    if (boundaries == geometry.end() || !boundaries->is_array() || boundaries->size() != 1)
        at.fail("a GeometryInstance's boundaries hold its one reference point");
    const Eigen::Vector3d reference =
        (*s.vertices)[index_in(at, (*boundaries)[0], s.vertices->size(), "vertex index")];
    auto matrix_value = geometry.find("transformationMatrix");
    if (matrix_value == geometry.end() || !matrix_value->is_array() || matrix_value->size() != 16)
        at.fail("'transformationMatrix' is not 16 numbers");
    const json& m = *matrix_value;
    Eigen::Matrix4d matrix;
    for (int i = 0; i < 16; ++i) {
        if (!m[std::size_t(i)].is_number()) at.fail("'transformationMatrix' is not 16 numbers");
        matrix(i / 4, i % 4) = m[std::size_t(i)].get<double>();
    }
    if (!(matrix.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).isZero(1e-6))  // a placement, as glTF's node matrix
        at.fail("'transformationMatrix' is not affine (its last row is not 0, 0, 0, 1)");
    matrix.row(3) << 0, 0, 0, 1;
    const std::vector<std::size_t>& named = points_of_template(s, t, shape);
    s.placed.resize(s.template_points.size());
    // Only the points this template names: the pool is all templates' (time: instances x template).
    for (std::size_t i : named) {
        if (i >= s.placed.size()) continue;  // read_geometry refuses it
        s.placed[i] = (matrix * s.template_points[i].homogeneous()).head<3>() + reference;
        if (!(s.placed[i].array().abs() <= max_city_coordinate).all())
            at.fail("a placed template vertex lies beyond " + format_number(max_city_coordinate));
    }
    const std::size_t before = s.points;
    read_geometry(at.in("template"), s, shape, object_node, s.placed, true);
    s.instanced_points += s.points - before;
    check_memory(s.file + ": the GeometryInstances' copies of their templates",
                 double(s.instanced_points) * bytes_per_instanced_point);
}

void read_geometry(const CityPlace& at, CityReadState& s, const json& geometry, int object_node,
                   const std::vector<Eigen::Vector3d>& vertices, bool in_template) {
    if (!geometry.is_object() || !geometry.contains("type") || !geometry["type"].is_string())
        at.fail("a geometry without a type");
    const std::string type = geometry["type"].get<std::string>();
    if (type == "GeometryInstance") {
        if (in_template) at.fail("a template that is itself a GeometryInstance");
        return read_instance(at, s, geometry, object_node);
    }
    const int depth = surface_depth(at, type);
    if (depth == 0) return;
    if (!geometry.contains("boundaries")) at.fail("missing member 'boundaries'");
    GeometryEmission g{s, vertices, {}, {}};
    g.nodes.object_node = object_node;
    SurfaceValues values;
    if (auto semantics = geometry.find("semantics"); semantics != geometry.end()) {
        if (!semantics->is_object() || !semantics->contains("surfaces") ||
            !(*semantics)["surfaces"].is_array())
            at.fail("semantics without an array of surfaces");
        g.nodes.surfaces = &(*semantics)["surfaces"];
        if (semantics->contains("values")) values.semantic = &(*semantics)["values"];
    }
    values.material = theme_values(at, geometry, "material", s.material_theme);
    values.texture = theme_values(at, geometry, "texture", s.texture_theme);
    walk(at, g, geometry["boundaries"], depth, values);
}

}  // namespace

std::size_t city_template_points(const json& shape) { return surface_point_indices(shape).size(); }

CityGeometryReader::CityGeometryReader(Model& model, const std::string& file, const Eigen::Vector3d& origin)
    : state_(std::make_unique<CityReadState>(model, file, origin)) {}
CityGeometryReader::~CityGeometryReader() = default;

void CityGeometryReader::start_part(const CityPlace& at, const json& document,
                                    const std::vector<Eigen::Vector3d>& vertices) {
    CityReadState& s = *state_;
    s.document = &document;
    s.vertices = &vertices;
    s.uvs.clear();
    s.texture_of.clear();
    s.material_of.clear();
    if (auto a = document.find("appearance"); a != document.end() && !a->is_object())
        at.fail("'appearance' is not an object");
    if (const json* uvs = s.appearance("vertices-texture")) {
        if (!uvs->is_array()) at.fail("appearance: 'vertices-texture' is not an array");
        for (std::size_t i = 0; i < uvs->size(); ++i) {
            const json& uv = (*uvs)[i];
            // Within a million repeats of the texture: a float holds it, and no texture repeats more.
            auto fits = [](const json& x) { return x.is_number() && std::abs(x.get<double>()) <= 1e6; };
            if (!uv.is_array() || uv.size() != 2 || !fits(uv[0]) || !fits(uv[1]))
                at.fail("appearance: vertices-texture " + std::to_string(i) +
                        " is not two numbers in [-1e6, 1e6]");
            s.uvs.emplace_back(uv[0].get<float>(),
                               1 - uv[1].get<float>());  // CityGML's origin is bottom left, glTF's top left
        }
    }
    const json* material_theme = s.appearance("default-theme-material");
    const json* texture_theme = s.appearance("default-theme-texture");
    s.material_theme =
        material_theme && material_theme->is_string() ? material_theme->get<std::string>() : "";
    s.texture_theme = texture_theme && texture_theme->is_string() ? texture_theme->get<std::string>() : "";
}

void CityGeometryReader::use_file_templates(const json& templates) { state_->file_templates = &templates; }

int CityGeometryReader::add_object(const CityPlace& at, const std::string& id, const json& object,
                                   int parent_node, const std::string& lod) {
    CityReadState& s = *state_;
    const CityPlace here = at.in("CityObjects '" + id + "'");
    const int node = add_node(s.model, parent_node, id);
    s.model.nodes[std::size_t(node)].source_id = id;
    if (object.contains("type") && object["type"].is_string())
        s.model.nodes[std::size_t(node)].rule = object["type"].get<std::string>();
    auto geometries = object.find("geometry");
    if (geometries == object.end()) return node;
    if (!geometries->is_array()) here.fail("'geometry' is not an array");
    for (std::size_t g = 0; g < geometries->size(); ++g) {
        const json& geometry = (*geometries)[g];
        if (geometry.is_object() && geometry.contains("lod") &&
            city_lod_number(city_geometry_lod(geometry)) < 0)
            here.in("geometry " + std::to_string(g))
                .fail("'lod' " + geometry["lod"].dump() +
                      " is not an LoD (0 to 4, or a refinement such as 2.2)");
        if (!city_geometry_lod(geometry).empty()) s.lods.insert(city_geometry_lod(geometry));
    }
    const std::vector<std::size_t> chosen = city_geometries_of_lod(*geometries, lod);
    for (std::size_t g : chosen)
        read_geometry(here.in("geometry " + std::to_string(g)), s, (*geometries)[g], node, *s.vertices);
    if (chosen.empty() && !geometries->empty()) ++s.without_lod;
    return node;
}

void CityGeometryReader::finish(const std::string& lod) const {
    const CityReadState& s = *state_;
    std::string lods;
    for (const std::string& l : s.lods) lods += (lods.empty() ? "" : ", ") + l;
    if (s.polygons == 0)
        throw_input_error(s.file, "",
                          lod.empty() ? "no surface to draw"
                                      : "no surface of LoD " + lod + " (the file has LoD " + lods + ")");
    if (s.without_lod > 0)
        std::fprintf(stderr, "boxlod: warning: %s\n",
                     input_message(s.file, "",
                                   std::to_string(s.without_lod) + " objects have no geometry of LoD " + lod +
                                       " (the file has LoD " + lods + "): drawn without them")
                         .c_str());
    if (!s.missing_textures.empty()) {
        std::string names;
        for (const std::string& name : s.missing_textures) names += (names.empty() ? "" : ", ") + name;
        std::fprintf(
            stderr, "boxlod: warning: %s\n",
            input_message(s.file, "",
                          std::to_string(s.missing_textures.size()) + " texture files are missing (" + names +
                              "): their surfaces are drawn in their material colour")
                .c_str());
    }
}

}  // namespace boxlod
