#include "toolkit/formats/gltf_extras.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "base/utf8.h"
#include "toolkit/formats/json_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace boxlod {
namespace {

// The `boxlod` object of an extras value, or null.
const tinygltf::Value* boxlod_fields(const tinygltf::Value& extras) {
    if (!extras.IsObject() || !extras.Has("boxlod")) return nullptr;
    const tinygltf::Value& v = extras.Get("boxlod");
    return v.IsObject() ? &v : nullptr;
}

tinygltf::Value boxlod_object(tinygltf::Value::Object fields) {
    tinygltf::Value::Object extras;
    extras["boxlod"] = tinygltf::Value(std::move(fields));
    return tinygltf::Value(std::move(extras));
}

tinygltf::Value number_array(const float* values, int n) {
    tinygltf::Value::Array array;
    for (int i = 0; i < n; ++i) array.emplace_back(json_number(values[i]));
    return tinygltf::Value(std::move(array));
}

template <int N>
Eigen::Matrix<float, N, 1> read_numbers(const tinygltf::Value& v, const ExtrasPlace& at,
                                        const std::string& field) {
    Eigen::Matrix<float, N, 1> out;
    if (!v.IsArray() || int(v.ArrayLen()) != N)
        throw_input_error(at.file, at.place + " " + field,
                          "expected an array of " + std::to_string(N) + " numbers");
    for (int i = 0; i < N; ++i) {
        if (!v.Get(i).IsNumber()) throw_input_error(at.file, at.place + " " + field, "expected a number");
        out[i] = float(v.Get(i).GetNumberAsDouble());
    }
    return out;
}

constexpr float max_scope_extent = 1e6f;

Scope read_scope(const tinygltf::Value& v, const ExtrasPlace& at) {
    auto fail = [&](const std::string& what) { throw_input_error(at.file, at.place, what); };
    if (!v.IsObject()) fail("scope must be an object");
    Scope scope;
    scope.center = read_numbers<3>(v.Get("center"), at, "scope.center");
    scope.half_extents = read_numbers<3>(v.Get("half_extents"), at, "scope.half_extents");
    const tinygltf::Value& axes = v.Get("axes");
    if (!axes.IsArray() || axes.ArrayLen() != 3) fail("scope.axes must hold three axes");
    for (int i = 0; i < 3; ++i) scope.axes.col(i) = read_numbers<3>(axes.Get(i), at, "scope.axes");
    // A scope is an oriented box: orthonormal axes, extents of 0 or more.
    if (!((scope.axes.transpose() * scope.axes - Eigen::Matrix3f::Identity()).cwiseAbs().maxCoeff() < 1e-3f))
        fail("scope.axes must be three orthonormal axes");
    if (!((scope.half_extents.array() >= 0).all() && (scope.half_extents.array() <= max_scope_extent).all()))
        fail("scope.half_extents must be in [0, 1e6]");
    return scope;
}

}  // namespace

double json_number(float value) {
    if (value == 0) return 0;  // -0 too, as format_number writes it
    char digits[32];
    const char* end =
        std::to_chars(digits, digits + sizeof digits, value).ptr;  // the float's shortest digits
    double number = 0;
    std::from_chars(digits, end, number);
    return number;
}

tinygltf::Value asset_extras(const Model& model) {
    if (!model.is_lod) return {};
    tinygltf::Value::Object params;
    for (const auto& [key, value] : model.lod_params)
        params[key] = tinygltf::Value(utf8_or_latin1(value));  // a path may be neither
    return boxlod_object({{"lod", tinygltf::Value(true)}, {"params", tinygltf::Value(std::move(params))}});
}

tinygltf::Value material_extras(const Material& material, int height_image) {
    tinygltf::Value::Object extras{{"specular", number_array(material.specular_color.data(), 3)},
                                   {"shininess", tinygltf::Value(json_number(material.shininess))}};
    // glTF has no height-map slot; the image index travels in extras.
    if (height_image >= 0) extras["height_texture"] = tinygltf::Value(height_image);
    if (height_image >= 0 && material.height_depth > 0)
        extras["height_depth"] = tinygltf::Value(json_number(material.height_depth));
    return boxlod_object(std::move(extras));
}

std::string node_extras_json(const Node& node, const std::vector<LodSwitch>& switches) {
    if (node.rule.empty() && node.instance_of.empty() && node.source_id.empty() && !node.scope &&
        switches.empty())
        return "";
    JsonText j;
    auto numbers = [&](const char* name, const float* values) {
        if (name) j.key(name);
        j.begin_array();
        for (int i = 0; i < 3; ++i) j.number(json_number(values[i]));
        j.end_array();
    };
    auto switch_numbers = [&](const char* name, double LodSwitch::*field) {
        j.key(name);
        j.begin_array();
        for (const LodSwitch& s : switches) j.number(json_number(float(s.*field)));
        if (field == &LodSwitch::screen_coverage)
            j.number(0);  // the coarsest level is drawn however small: culling is the engine's call
        j.end_array();
    };
    j.begin_object();
    if (!switches.empty()) switch_numbers("MSFT_screencoverage", &LodSwitch::screen_coverage);
    j.key("boxlod");
    j.begin_object();
    if (!node.instance_of.empty()) {
        j.key("instance_of");
        j.string(node.instance_of);
    }
    if (!node.rule.empty()) {
        j.key("rule");
        j.string(node.rule);
    }
    if (node.scope) {
        j.key("scope");
        j.begin_object();
        j.key("axes");
        j.begin_array();
        for (int i = 0; i < 3; ++i) numbers(nullptr, node.scope->axes.col(i).eval().data());
        j.end_array();
        numbers("center", node.scope->center.data());
        numbers("half_extents", node.scope->half_extents.data());
        j.end_object();
    }
    if (!node.source_id.empty()) {
        j.key("source_id");
        j.string(utf8_or_latin1(node.source_id));
    }
    if (!switches.empty()) switch_numbers("switch_distances", &LodSwitch::distance);
    j.end_object();
    j.end_object();
    return std::move(j.text);
}

tinygltf::Value primitive_extras(const Primitive& primitive) {
    if (primitive.polygon_count == primitive.triangle_count()) return {};
    return boxlod_object({{"polygons", tinygltf::Value(int(primitive.polygon_count))}});
}

tinygltf::Value origin_node_extras(const std::string& reference_system) {
    tinygltf::Value::Object fields{{"origin", tinygltf::Value(true)}};
    if (!reference_system.empty()) fields["reference_system"] = tinygltf::Value(reference_system);
    return boxlod_object(std::move(fields));
}

std::string read_origin_reference_system(const tinygltf::Node& node, const ExtrasPlace& at) {
    const tinygltf::Value* fields = boxlod_fields(node.extras);
    if (!fields || !fields->Has("reference_system")) return "";
    const tinygltf::Value& system = fields->Get("reference_system");
    if (!system.IsString() || system.Get<std::string>().empty())
        throw_input_error(at.file, at.place, "extras.boxlod.reference_system is not a non-empty string");
    return system.Get<std::string>();
}

bool is_origin_node(const tinygltf::Node& node) {
    const tinygltf::Value* fields = boxlod_fields(node.extras);
    return fields && fields->Has("origin") && fields->Get("origin").IsBool() &&
           fields->Get("origin").Get<bool>() && node.translation.size() == 3 && node.rotation.empty() &&
           node.scale.empty() && node.matrix.empty() && node.mesh < 0;
}

void read_asset_extras(const tinygltf::Value& extras, Model& model) {
    const tinygltf::Value* fields = boxlod_fields(extras);
    if (!fields) return;
    model.is_lod = fields->Has("lod") && fields->Get("lod").IsBool() && fields->Get("lod").Get<bool>();
    if (fields->Has("params") && fields->Get("params").IsObject()) {
        const tinygltf::Value& params = fields->Get("params");
        for (const std::string& key : params.Keys())
            model.lod_params.emplace_back(
                key, params.Get(key).IsString() ? params.Get(key).Get<std::string>() : "");
    }
}

void read_material_extras(const tinygltf::Value& extras, int image_count, const ExtrasPlace& at,
                          Material& material) {
    const tinygltf::Value* fields = boxlod_fields(extras);
    if (!fields) return;
    if (fields->Has("specular"))
        material.specular_color = read_numbers<3>(fields->Get("specular"), at, "specular");
    if (fields->Has("shininess")) {
        if (!fields->Get("shininess").IsNumber())
            throw_input_error(at.file, at.place, "shininess must be a number");  // range: validate_model
        material.shininess = float(fields->Get("shininess").GetNumberAsDouble());
    }
    if (fields->Has("height_texture")) {  // an index below 2^31 (gltf_structure.cpp)
        material.height_texture = fields->Get("height_texture").GetNumberAsInt();
        if (material.height_texture >= image_count)
            throw_input_error(at.file, at.place, "height_texture out of range");
    }
    if (fields->Has("height_depth")) {
        if (!fields->Get("height_depth").IsNumber())
            throw_input_error(at.file, at.place, "height_depth must be a number");
        material.height_depth =
            float(fields->Get("height_depth").GetNumberAsDouble());  // range: validate_model
    }
}

void read_node_extras(const tinygltf::Value& extras, const ExtrasPlace& at, Node& node) {
    const tinygltf::Value* fields = boxlod_fields(extras);
    if (!fields) return;
    if (fields->Has("rule") && fields->Get("rule").IsString())
        node.rule = fields->Get("rule").Get<std::string>();
    if (fields->Has("scope")) node.scope = read_scope(fields->Get("scope"), at);
    if (fields->Has("instance_of") && fields->Get("instance_of").IsString())
        node.instance_of = fields->Get("instance_of").Get<std::string>();
    if (fields->Has("source_id") && fields->Get("source_id").IsString())
        node.source_id = fields->Get("source_id").Get<std::string>();
}

void read_primitive_extras(const tinygltf::Value& extras, const ExtrasPlace& at, Primitive& primitive) {
    const tinygltf::Value* fields = boxlod_fields(extras);
    if (!fields || !fields->Has("polygons")) return;
    const tinygltf::Value& polygons = fields->Get("polygons");
    // Each polygon is at least one triangle.
    if (!polygons.IsNumber() || !(polygons.GetNumberAsDouble() >= 0 &&
                                  polygons.GetNumberAsDouble() <= double(primitive.triangle_count())))
        throw_input_error(at.file, at.place,
                          "extras.boxlod.polygons must be a count of at most the primitive's triangles");
    primitive.polygon_count = std::size_t(polygons.GetNumberAsDouble());
}

float glossiness_of_shininess(float shininess) {
    return 1 - float(std::pow(2.0 / (std::max(double(shininess), 0.0) + 2), 0.25));
}

float shininess_of_glossiness(float glossiness) {
    const double roughness = 1 - double(glossiness);
    if (roughness <= 0) return float(shininess_range.max);
    return float(std::clamp(2 / std::pow(roughness, 4) - 2, shininess_range.min, shininess_range.max));
}

namespace {

tinygltf::Value texture_info(int index) {
    return tinygltf::Value(tinygltf::Value::Object{{"index", tinygltf::Value(index)}});
}

// A material extension's object, read field by field; `here` names it in errors.
struct ExtensionReader {
    const tinygltf::Value& extension;
    ExtrasPlace here;
    const TextureOfInfo& texture_image;

    // N numbers in [min, max], or `defaults` when the field is absent.
    template <int N>
    Eigen::Matrix<float, N, 1> factors(const char* field, const Eigen::Matrix<float, N, 1>& defaults,
                                       NumberRange range) const {
        if (!extension.Has(field)) return defaults;
        auto values = read_numbers<N>(extension.Get(field), here, field);
        if (!((values.array() >= range.min).all() && (values.array() <= range.max).all()))
            throw_input_error(
                here.file, here.place + " " + field,
                "expected numbers in [" + format_number(range.min) + ", " + format_number(range.max) + "]");
        return values;
    }
    float factor(const char* field, float fallback) const {
        if (!extension.Has(field)) return fallback;
        const tinygltf::Value& v = extension.Get(field);
        if (!v.IsNumber() || !(v.GetNumberAsDouble() >= 0 && v.GetNumberAsDouble() <= 1))
            throw_input_error(here.file, here.place + " " + field, "expected a number in [0, 1]");
        return float(v.GetNumberAsDouble());
    }
    // boxlod's texture of a textureInfo field; -1 when absent.
    int texture(const char* field) const {
        if (!extension.Has(field)) return -1;
        const tinygltf::Value& info = extension.Get(field);
        if (!info.IsObject() || !info.Get("index").IsNumber())
            throw_input_error(here.file, here.place + " " + field, "expected a textureInfo with an index");
        const double index = info.Get("index").GetNumberAsDouble();
        if (!(index >= 0 && index <= 1e9))
            throw_input_error(here.file, here.place + " " + field, "texture index out of range");
        return texture_image(int(index), info);
    }
};

ExtensionReader extension_reader(const tinygltf::Value& extension, const ExtrasPlace& at, const char* name,
                                 const TextureOfInfo& texture_image) {
    ExtensionReader reader{extension, {at.file, at.place + " " + name}, texture_image};
    if (!extension.IsObject()) throw_input_error(reader.here.file, reader.here.place, "expected an object");
    return reader;
}

constexpr NumberRange unit_range{0, 1};

}  // namespace

tinygltf::Value specular_glossiness_extension(const Material& material, int diffuse_texture,
                                              int specular_texture) {
    tinygltf::Value::Object fields{
        {"diffuseFactor", number_array(material.base_color.data(), 4)},
        {"specularFactor", number_array(material.specular_color.data(), 3)},
        {"glossinessFactor",
         tinygltf::Value(json_number(
             material.glossiness >= 0 ? material.glossiness : glossiness_of_shininess(material.shininess)))}};
    if (diffuse_texture >= 0) fields["diffuseTexture"] = texture_info(diffuse_texture);
    if (specular_texture >= 0) fields["specularGlossinessTexture"] = texture_info(specular_texture);
    return tinygltf::Value(std::move(fields));
}

void read_specular_glossiness(const tinygltf::Value& extension, const ExtrasPlace& at,
                              const TextureOfInfo& texture_image, Material& material) {
    const ExtensionReader in = extension_reader(extension, at, specular_glossiness_name, texture_image);
    material.base_color = in.factors<4>("diffuseFactor", Eigen::Vector4f(1, 1, 1, 1), unit_range);
    material.specular_color = in.factors<3>("specularFactor", Eigen::Vector3f(1, 1, 1), unit_range);
    const float glossiness = in.factor("glossinessFactor", 1);
    material.shininess = shininess_of_glossiness(glossiness);
    material.glossiness = glossiness;
    if (int diffuse = in.texture("diffuseTexture"); diffuse >= 0) material.base_color_texture = diffuse;
    material.specular_texture = in.texture("specularGlossinessTexture");
    material.specular_glossiness = true;
}

tinygltf::Value specular_extension_value(const SpecularExtension& specular, int texture, int color_texture) {
    tinygltf::Value::Object fields{{"specularFactor", tinygltf::Value(json_number(specular.factor))},
                                   {"specularColorFactor", number_array(specular.color_factor.data(), 3)}};
    if (texture >= 0) fields["specularTexture"] = texture_info(texture);
    if (color_texture >= 0) fields["specularColorTexture"] = texture_info(color_texture);
    return tinygltf::Value(std::move(fields));
}

SpecularExtension read_specular_extension(const tinygltf::Value& extension, const ExtrasPlace& at,
                                          const TextureOfInfo& texture_image) {
    const ExtensionReader in = extension_reader(extension, at, specular_extension_name, texture_image);
    SpecularExtension specular;
    specular.factor = in.factor("specularFactor", 1);
    specular.color_factor =
        in.factors<3>("specularColorFactor", Eigen::Vector3f(1, 1, 1), specular_color_factor_range);
    specular.texture = in.texture("specularTexture");
    specular.color_texture = in.texture("specularColorTexture");
    return specular;
}

}  // namespace boxlod
