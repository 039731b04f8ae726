#include "llvmpipe_peer.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include "benchmark_scene.h"

#include <cstdio>
#include <vector>

namespace boxlod::bench {

struct LlvmpipePeer::State {
    OSMesaContext context = nullptr;
    std::vector<unsigned char> pixels;
    GLuint program = 0, buffers[3] = {0, 0, 0};
    GLsizei index_count = 0;
};

namespace {

const char* vertex_shader = R"(#version 120
uniform mat4 view_projection;
attribute vec3 position;
attribute vec3 normal;
varying vec3 world_position;
varying vec3 world_normal;
void main() {
    world_position = position;
    world_normal = normal;
    gl_Position = view_projection * vec4(position, 1.0);
})";

// The same Blinn-Phong as boxlod's renderer (renderer.cpp: shade).
const char* fragment_shader = R"(#version 120
uniform vec3 eye, light_position, base_color, specular_color;
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
    gl_FragColor = vec4(base_color * (ambient + diffuse * d) + specular_color * (specular * s), 1.0);
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

}  // namespace

std::unique_ptr<LlvmpipePeer> LlvmpipePeer::create(const Mesh& mesh, const RenderSettings& settings, int) {
    auto peer = std::unique_ptr<LlvmpipePeer>(new LlvmpipePeer);
    peer->state_ = std::make_unique<State>();
    State& s = *peer->state_;
    s.context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!s.context) return nullptr;
    s.pixels.resize(std::size_t(frame_width) * frame_height * 4);
    if (!OSMesaMakeCurrent(s.context, s.pixels.data(), GL_UNSIGNED_BYTE, frame_width, frame_height)) return nullptr;

    s.program = glCreateProgram();
    glAttachShader(s.program, compile(GL_VERTEX_SHADER, vertex_shader));
    glAttachShader(s.program, compile(GL_FRAGMENT_SHADER, fragment_shader));
    glBindAttribLocation(s.program, 0, "position");
    glBindAttribLocation(s.program, 1, "normal");
    glLinkProgram(s.program);
    glUseProgram(s.program);

    glGenBuffers(3, s.buffers);
    glBindBuffer(GL_ARRAY_BUFFER, s.buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.positions.size() * 12), mesh.positions.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, nullptr);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, s.buffers[1]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.normals.size() * 12), mesh.normals.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 12, nullptr);
    glEnableVertexAttribArray(1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.buffers[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 4), mesh.indices.data(), GL_STATIC_DRAW);
    s.index_count = GLsizei(mesh.indices.size());

    const Camera& camera = settings.camera;
    Eigen::Matrix4f view_projection = projection_matrix(camera, float(frame_width) / frame_height) * view_matrix(camera);
    glUniformMatrix4fv(glGetUniformLocation(s.program, "view_projection"), 1, GL_FALSE, view_projection.data());
    glUniform3fv(glGetUniformLocation(s.program, "eye"), 1, camera.position.data());
    glUniform3fv(glGetUniformLocation(s.program, "light_position"), 1, settings.light.position.data());
    Surface surface;
    glUniform3f(glGetUniformLocation(s.program, "base_color"), 0.7f, 0.6f, 0.5f);
    glUniform3fv(glGetUniformLocation(s.program, "specular_color"), 1, surface.specular.data());
    glUniform1f(glGetUniformLocation(s.program, "ambient"), settings.light.ambient);
    glUniform1f(glGetUniformLocation(s.program, "diffuse"), settings.light.diffuse);
    glUniform1f(glGetUniformLocation(s.program, "specular"), settings.light.specular);
    glUniform1f(glGetUniformLocation(s.program, "shininess"), surface.shininess);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glViewport(0, 0, frame_width, frame_height);
    return peer;
}

LlvmpipePeer::~LlvmpipePeer() {
    if (state_ && state_->context) OSMesaDestroyContext(state_->context);
}

void LlvmpipePeer::draw() {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, state_->index_count, GL_UNSIGNED_INT, nullptr);
    glFinish();
}

}  // namespace boxlod::bench

namespace boxlod::bench {

double LlvmpipePeer::covered_fraction() const {
    std::size_t covered = 0, n = state_->pixels.size() / 4;
    for (std::size_t i = 0; i < n; ++i) covered += (state_->pixels[i * 4] | state_->pixels[i * 4 + 1] | state_->pixels[i * 4 + 2]) != 0;
    return double(covered) / double(n);
}

}  // namespace boxlod::bench
