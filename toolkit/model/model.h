// The scene model (docs/design.md: Scene model): a tree of nodes, each with its own
// geometry in world space, an optional scope (the grammar's oriented box) and
// the rule that made it.
#pragma once
#include "renderer/image.h"
#include "renderer/renderer.h"
#include "renderer/texture.h"

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, rotations: used with the model everywhere
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace boxlod {

// An oriented box: center, three orthonormal axes (columns), half-extents.
struct OrientedBox {
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
    Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();
    Eigen::Vector3f half_extents = Eigen::Vector3f::Zero();
};
// The grammar's scope of a node is an oriented box (it may not enclose the node's geometry).
using Scope = OrientedBox;

struct Texture {
    std::string name;          // file name or label; a hint for export
    Image8 image;              // 8-bit RGB(A), as stored (sRGB for colour, linear for normal maps)
    Image16 image16 = {};      // instead of `image`: one 16-bit channel (baked height maps)
    Wrap wrap = Wrap::repeat;  // LoD pages clamp: their faces may touch the page's border
};

// A 128-bit digest of bytes: FNV-1a and a multiplicative hash side by side.
// Equal digests are taken for equal contents (a false match needs two inputs
// colliding in both, about 2^-128). `from`: a digest to go on from.
using ContentDigest = std::pair<std::uint64_t, std::uint64_t>;
constexpr ContentDigest empty_digest{14695981039346656037ull, 0x243F6A8885A308D3ull};
ContentDigest content_digest(const void* bytes, std::size_t size, ContentDigest from = empty_digest);

// A texture's: its texels, layout and wrap mode.
using TextureDigest = ContentDigest;
TextureDigest texture_digest(const Texture& texture);

// glTF KHR_materials_specular as the source stated it (a metallic-roughness
// material's dielectric specular strength and colour): kept and written back
// by the glTF export; boxlod shades with specular_color, not with it.
struct SpecularExtension {
    float factor = 1;                       // specularFactor, [0, 1]
    Eigen::Vector3f color_factor{1, 1, 1};  // specularColorFactor, [0, specular_color_factor_range.max]
    int texture = -1;                       // specularTexture: strength in A
    int color_texture = -1;                 // specularColorTexture: RGB, sRGB
    bool operator==(const SpecularExtension&) const = default;
};
constexpr NumberRange specular_color_factor_range{0, 1000};  // the extension allows [0, inf): boxlod's bound
constexpr NumberRange height_depth_range{0, 1e6};            // metres, as a scope's extents
// A position's coordinates, in the model's units: beyond any model's (Earth-centred ones too; a city
// file's are kept relative to Model::origin), so that distances between them, and the distances that
// frame them, stay within float and the parameter files' ranges (toolkit/lod/lod_parameters.h).
constexpr NumberRange coordinate_range{-1e9, 1e9};

struct Material {
    std::string name;
    Eigen::Vector4f base_color{1, 1, 1, 1};  // linear RGBA
    int base_color_texture = -1;             // index into Model::textures
    int normal_texture = -1;
    int height_texture = -1;  // baked LoD faces: 1 at the face plane, 0 at height_depth below it
    // Metres from height 1 to height 0; 0: unstated (the manual's parallax scale
    // and bias apply, in uv). LoD pages state it (docs/design.md: Rendering).
    float height_depth = 0;
    Eigen::Vector3f specular_color{0.2f, 0.2f, 0.2f};  // Blinn-Phong, as the renderer shades
    float shininess = 32;
    // The source stated its specular terms (glTF KHR_materials_pbrSpecularGlossiness,
    // or a format with Phong specular through assimp): the glTF export writes
    // them back as that extension (docs/design.md: Files).
    bool specular_glossiness = false;
    int specular_texture = -1;  // the extension's specularGlossinessTexture: RGB specular, A glossiness
    float glossiness = -1;      // its glossinessFactor as read (kept exactly); < 0: from the shininess
    std::optional<SpecularExtension> specular_extension = std::nullopt;
    bool double_sided = false;
    AlphaMode alpha_mode =
        AlphaMode::opaque;      // glTF alphaMode; baked box faces are MASK (cut out where uncovered)
    float alpha_cutoff = 0.5f;  // glTF alphaCutoff, for MASK
    bool operator==(const Material&) const = default;
};

// What a material samples a texture for: it decides the texture's GPU format
// and bytes (docs/design.md: Cost).
enum class TextureUse { color, normal, scalar };  // scalar: one channel (height maps, specular strength)

// Which map of a material a texture is: a render mode loads only the maps it
// draws (renderer.h: maps_drawn; docs/design.md: Cost).
enum class MaterialMap { base_color, normal, height, specular };

// Every texture index of a material with its use and map: the one list all
// code that walks a material's textures (validation, cost, copying, export) reads.
template <typename Index>
struct TextureSlot {
    Index index;  // int* to rewrite it, int to read it
    TextureUse use;
    MaterialMap map;
};
std::vector<TextureSlot<int*>> texture_slots(Material& material);
std::vector<TextureSlot<int>> texture_slots(const Material& material);
bool samples_textures(const Material& material);  // any slot with a texture

// A triangle list with one material. `polygon_count` is how many polygons the
// source stored (a quad is one polygon, two triangles): the manual's # Faces.
struct Primitive {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals;   // empty: flat shading
    std::vector<Eigen::Vector2f> uvs;       // empty: untextured
    std::vector<Eigen::Vector4f> tangents;  // xyz + handedness w; may be empty
    std::vector<std::uint32_t> indices;     // 3 per triangle
    std::size_t polygon_count = 0;
    int material = -1;  // index into Model::materials; -1 = default material

    std::size_t triangle_count() const { return indices.size() / 3; }
    bool operator==(const Primitive&) const = default;
};

struct Node {
    std::string name;
    std::string rule;  // grammar symbol that made the node, if any
    std::vector<Primitive> primitives;
    std::optional<Scope> scope;
    std::string instance_of;  // source mesh shared with other nodes before expansion
    std::string source_id;    // the object's id in its source: an IFC GlobalId, a CityJSON object id
    int parent = -1;
    std::vector<int> children;

    bool has_geometry() const { return !primitives.empty(); }
};

struct Model {
    std::vector<Node> nodes;  // nodes[0] is the root; a parent comes before its children
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::string source;  // the file it came from
    // Where the model's (0, 0, 0) lies in the source's coordinates, in the
    // model's frame (y up): a city file's, an IFC's or a far glTF's vertices are
    // kept relative to it so that float keeps them exact; glTF writes it as the
    // root's translation and 3D Tiles as the root tile's transform (docs/design.md: Files).
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    // The source's coordinate reference system as it names it (CityJSON's
    // metadata.referenceSystem), "" when it names none: where `origin` lies on the Earth.
    std::string reference_system;
    // The files besides itself that its source file was read with (images, a
    // glTF's buffers; also those of the file's other objects): an export
    // beside them never writes over one (docs/design.md: Files).
    std::vector<std::string> read_files;
    // An LoD that boxlod exported: viewable, never simplified again.
    bool is_lod = false;
    std::vector<std::pair<std::string, std::string>> lod_params;
};

// What a model made from another keeps of it: its source file, origin, reference system and read files.
inline void keep_provenance(const Model& from, Model& to) {
    to.source = from.source;
    to.origin = from.origin;
    to.reference_system = from.reference_system;
    to.read_files = from.read_files;
}

// Appends a node under `parent` (-1 for the root) and returns its index.
int add_node(Model& model, int parent, std::string name);

// Longest root-to-leaf path counted in edges (a lone root has depth 0).
int tree_depth(const Model& model);

struct Bounds {
    Eigen::Vector3f min{Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity())};
    Eigen::Vector3f max{Eigen::Vector3f::Constant(-std::numeric_limits<float>::infinity())};
    bool empty() const { return !(min.array() <= max.array()).all(); }
    void add(const Eigen::Vector3f& p) {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
    Eigen::Vector3f size() const { return empty() ? Eigen::Vector3f::Zero() : Eigen::Vector3f(max - min); }
    Eigen::Vector3f center() const { return (min + max) / 2; }
};

Bounds model_bounds(const Model& model);

// Checks the invariants every importer guarantees (indices in range, finite
// numbers, a tree, some geometry); throws InputError naming `model.source`.
void validate_model(const Model& model);

// Whether a valid primitive has a triangle of non-zero area: what a model must draw.
bool has_area(const Primitive& primitive);

// Whether any triangle can be seen: one whose material is not fully
// transparent (blended or masked with a base colour alpha of 0; a texture's
// alpha only scales it). A model that draws nothing has nothing to bake.
bool draws_anything(const Model& model);

// Whether two models draw the same picture: the same primitives in node order,
// the same materials, textures of the same texels; names and the tree aside.
// A chain writes a level once (a level that draws what the last one written
// does is left out): on small models whose boxes cost more than their
// geometry every fine level keeps the original (Testwuson.X: 10 levels of
// 3,732 triangles), and far levels are one box whose faces are drawn flat.
bool draws_the_same(const Model& a, const Model& b);

// Normals and tangents of unit length, handedness +-1, as glTF holds them
// (glTF 2.0, 3.7.2.1) and the renderer assumes. A primitive with one of no
// direction (zero: glTF-Sample-Models' BoxBadNormals) is drawn without them,
// flat or unmapped. An importer calls it before validate_model, which refuses
// what is not finite.
void make_unit_normals_and_tangents(Model& model);

}  // namespace boxlod
