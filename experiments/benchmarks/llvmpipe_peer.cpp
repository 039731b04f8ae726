#include "llvmpipe_peer.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace boxlod::bench {

struct LlvmpipePeer::State {
    struct Draw {
        GLuint buffers[5] = {0, 0, 0, 0, 0};  // positions, normals, uvs, tangents, indices
        GLsizei index_count = 0;
        bool uvs = false, tangents = false;
        GLuint color = 0, normal = 0;  // textures; 0: none
        Surface surface;
    };
    OSMesaContext context = nullptr;
    std::vector<unsigned char> pixels;
    GLuint programs[3] = {0, 0, 0};  // untextured, mapped, mapped with alpha cut-out
    std::vector<Draw> draws;
    std::map<const MipTexture*, GLuint> textures;
};

namespace {

const char* vertex_shader = R"(#version 120
uniform mat4 view_projection;
attribute vec3 position;
attribute vec3 normal;
attribute vec2 uv;
attribute vec4 tangent;
varying vec3 world_position;
varying vec3 world_normal;
varying vec2 texture_uv;
varying vec4 world_tangent;
void main() {
    world_position = position;
    world_normal = normal;
    texture_uv = uv;
    world_tangent = tangent;
    gl_Position = view_projection * vec4(position, 1.0);
})";

// boxlod's untextured mode (renderer/shading.cpp: UntexturedShader, blinn_phong), with
// no more work than it needs, so that llvmpipe is at its best.
const char* untextured_fragment_shader = R"(#version 120
uniform vec3 eye, light_position, specular_color;
uniform vec4 base_color;
uniform float ambient, diffuse, specular, shininess;
varying vec3 world_position;
varying vec3 world_normal;
void main() {
    vec3 n = normalize(world_normal);
    vec3 v = normalize(eye - world_position);
    if (dot(n, v) < 0.0) n = -n;
    vec3 l = normalize(light_position - world_position);
    vec3 h = normalize(l + v);
    float d = max(0.0, dot(n, l));
    float s = d > 0.0 ? pow(max(0.0, dot(n, h)), shininess) : 0.0;
    gl_FragColor = vec4(base_color.rgb * (ambient + diffuse * d) + specular_color * (specular * s), base_color.a);
})";

// boxlod's normal mode (renderer/shading.cpp: MappedShader, blinn_phong).
const char* fragment_shader = R"(#version 120
uniform vec3 eye, light_position, specular_color;
uniform vec4 base_color;
uniform float ambient, diffuse, specular, shininess;
uniform bool has_color, has_normal;
uniform sampler2D color_map, normal_map;
varying vec3 world_position;
varying vec3 world_normal;
varying vec2 texture_uv;
varying vec4 world_tangent;
void main() {
    vec4 albedo = base_color;
    if (has_color) albedo *= texture2D(color_map, texture_uv);
#ifdef CUTOUT
    if (albedo.a < 0.5) discard;
#endif
    vec3 n = normalize(world_normal);
    vec3 v = normalize(eye - world_position);
    float facing = gl_FrontFacing ? 1.0 : -1.0;
    n *= facing;
    if (has_normal) {
        vec3 t = world_tangent.xyz - n * dot(n, world_tangent.xyz);
        if (dot(t, t) > 0.0) {
            t = normalize(t);
            vec3 b = cross(n, t) * (world_tangent.w < 0.0 ? -1.0 : 1.0);
            vec3 m = texture2D(normal_map, texture_uv).xyz * 2.0 - 1.0;
            vec3 mapped = t * m.x + b * m.y + n * m.z;
            if (dot(mapped, mapped) > 0.0) n = normalize(mapped);
        }
    }
    vec3 l = normalize(light_position - world_position);
    vec3 h = normalize(l + v);
    float d = max(0.0, dot(n, l));
    float s = d > 0.0 ? pow(max(0.0, dot(n, h)), shininess) : 0.0;
    gl_FragColor = vec4(albedo.rgb * (ambient + diffuse * d) + specular_color * (specular * s), albedo.a);
})";

GLuint compile(GLenum type, const char* source) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        std::fprintf(stderr, "llvmpipe peer: shader: %s\n", log);
    }
    return shader;
}

// A program with the camera, light and texture units set.
GLuint link(const char* fragment_source, const RenderSettings& settings, int width, int height) {
    GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, vertex_shader));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, fragment_source));
    const char* attributes[] = {"position", "normal", "uv", "tangent"};
    for (GLuint a = 0; a < 4; ++a) glBindAttribLocation(program, a, attributes[a]);
    glLinkProgram(program);
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "color_map"), 0);
    glUniform1i(glGetUniformLocation(program, "normal_map"), 1);
    const Camera& camera = settings.camera;
    Eigen::Matrix4f view_projection =
        projection_matrix(camera, float(width) / float(height)) * view_matrix(camera);
    glUniformMatrix4fv(glGetUniformLocation(program, "view_projection"), 1, GL_FALSE, view_projection.data());
    glUniform3fv(glGetUniformLocation(program, "eye"), 1, camera.position.data());
    glUniform3fv(glGetUniformLocation(program, "light_position"), 1, settings.light.position.data());
    glUniform1f(glGetUniformLocation(program, "ambient"), settings.light.ambient);
    glUniform1f(glGetUniformLocation(program, "diffuse"), settings.light.diffuse);
    glUniform1f(glGetUniformLocation(program, "specular"), settings.light.specular);
    return program;
}

// boxlod's own mip chain, so both sample the same texels (RGBA8; sRGB colour maps).
GLuint upload(const MipTexture& texture) {
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    GLint internal = texture.format == TexelFormat::srgb8 ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    for (std::size_t l = 0; l < texture.levels.size(); ++l)
        glTexImage2D(GL_TEXTURE_2D, GLint(l), internal, texture.levels[l].width, texture.levels[l].height, 0,
                     GL_RGBA, GL_UNSIGNED_BYTE, texture.levels[l].rgba8.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(texture.levels.size()) - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    GLint wrap = texture.wrap == Wrap::clamp ? GL_CLAMP_TO_EDGE : GL_REPEAT;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    return name;
}

template <typename T>
GLuint array_buffer(const std::vector<T>& values) {
    GLuint name = 0;
    glGenBuffers(1, &name);
    glBindBuffer(GL_ARRAY_BUFFER, name);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(values.size() * sizeof(T)), values.data(), GL_STATIC_DRAW);
    return name;
}

}  // namespace

std::unique_ptr<LlvmpipePeer> LlvmpipePeer::create(const std::vector<Batch>& batches,
                                                   const RenderSettings& settings, int width, int height) {
    auto peer = std::unique_ptr<LlvmpipePeer>(new LlvmpipePeer);
    peer->state_ = std::make_unique<State>();
    State& s = *peer->state_;
    s.context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!s.context) return nullptr;
    s.pixels.resize(std::size_t(width) * std::size_t(height) * 4);
    if (!OSMesaMakeCurrent(s.context, s.pixels.data(), GL_UNSIGNED_BYTE, width, height)) return nullptr;

    const bool textured = settings.mode != RenderMode::untextured;
    const std::string mapped = fragment_shader,
                      cutout = "#version 120\n#define CUTOUT\n" + mapped.substr(mapped.find('\n') + 1);
    const char* sources[3] = {untextured_fragment_shader, mapped.c_str(), cutout.c_str()};
    for (int p = 0; p < 3; ++p) s.programs[p] = link(sources[p], settings, width, height);
    for (const Batch& batch : batches) {
        const Mesh& mesh = *batch.mesh;
        State::Draw draw;
        draw.surface = batch.surface;
        draw.buffers[0] = array_buffer(mesh.positions);
        draw.buffers[1] = array_buffer(mesh.normals);
        draw.uvs = textured && !mesh.uvs.empty();
        draw.tangents = !mesh.tangents.empty();
        if (draw.uvs) draw.buffers[2] = array_buffer(mesh.uvs);
        if (draw.tangents) draw.buffers[3] = array_buffer(mesh.tangents);
        glGenBuffers(1, &draw.buffers[4]);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, draw.buffers[4]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 4), mesh.indices.data(),
                     GL_STATIC_DRAW);
        draw.index_count = GLsizei(mesh.indices.size());
        for (auto [texture, name] :
             {std::pair{batch.surface.color, &draw.color}, std::pair{batch.surface.normal, &draw.normal}}) {
            if (!draw.uvs || !texture || texture->levels.empty() || texture->levels[0].rgba8.empty())
                continue;
            auto [at, added] = s.textures.try_emplace(texture, 0);
            if (added) at->second = upload(*texture);
            *name = at->second;
        }
        s.draws.push_back(draw);
    }
    // As boxlod: blended surfaces after the opaque ones (renderer/renderer.cpp: composite_blended).
    std::stable_partition(s.draws.begin(), s.draws.end(),
                          [](const State::Draw& d) { return d.surface.alpha_mode != AlphaMode::blend; });
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glViewport(0, 0, width, height);
    return peer;
}

LlvmpipePeer::~LlvmpipePeer() {
    if (state_ && state_->context) OSMesaDestroyContext(state_->context);
}

void LlvmpipePeer::draw() {
    State& s = *state_;
    glDepthMask(GL_TRUE);  // glClear honours the depth mask a blended draw left off
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (const State::Draw& d : s.draws) {
        const GLuint program = s.programs[d.uvs ? (d.surface.alpha_mode == AlphaMode::mask ? 2 : 1) : 0];
        const bool blend = d.surface.alpha_mode == AlphaMode::blend;
        (blend ? glEnable : glDisable)(GL_BLEND);
        glDepthMask(blend ? GL_FALSE : GL_TRUE);
        glUseProgram(program);
        glUniform4fv(glGetUniformLocation(program, "base_color"), 1, d.surface.base_color.data());
        glUniform3fv(glGetUniformLocation(program, "specular_color"), 1, d.surface.specular.data());
        glUniform1f(glGetUniformLocation(program, "shininess"), d.surface.shininess);
        glUniform1i(glGetUniformLocation(program, "has_color"), d.color != 0);
        glUniform1i(glGetUniformLocation(program, "has_normal"), d.normal != 0 && d.tangents);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, d.color);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, d.normal);
        const GLint sizes[4] = {3, 3, 2, 4};
        const bool present[4] = {true, true, d.uvs, d.tangents};
        for (GLuint a = 0; a < 4; ++a) {
            if (!present[a]) {
                glDisableVertexAttribArray(a);
                continue;
            }
            glBindBuffer(GL_ARRAY_BUFFER, d.buffers[a]);
            glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, 0, nullptr);
            glEnableVertexAttribArray(a);
        }
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.buffers[4]);
        glDrawElements(GL_TRIANGLES, d.index_count, GL_UNSIGNED_INT, nullptr);
    }
    glFinish();
}

double LlvmpipePeer::covered_fraction() const {
    std::size_t covered = 0, n = state_->pixels.size() / 4;
    for (std::size_t i = 0; i < n; ++i)
        covered += (state_->pixels[i * 4] | state_->pixels[i * 4 + 1] | state_->pixels[i * 4 + 2]) != 0;
    return double(covered) / double(n);
}

int LlvmpipePeer::rasterizer_threads() {
    int count = 0;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
        std::string name;
        std::getline(std::ifstream(task.path() / "comm"), name);
        count += name.rfind("llvmpipe-", 0) == 0;
    }
    return count;
}

}  // namespace boxlod::bench
