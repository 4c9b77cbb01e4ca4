// GLSL 3.30 sources of the renderer's programs (meshes, lines, wire circles), linked.
#include "shaders.hpp"
#include <stdexcept>
#include <string>

namespace spt::render::detail {
namespace {

// Shared lighting: a headlight a little above and to the left of the eye, two-sided
// so open meshes and inner faces are never black.
#define SPT_GLSL_SHADE                                                         \
    "vec3 shade(vec3 base, vec3 n) {\n"                                        \
    "    const vec3 L = vec3(-0.3333, 0.6667, 0.6667);\n"                     \
    "    float d = abs(dot(n, L));\n"                                          \
    "    float rim = abs(n.z);\n"                                              \
    "    return base * (0.30 + 0.58 * d + 0.12 * rim);\n"                     \
    "}\n"

const char* kMeshVs = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model_view;
uniform mat4 u_projection;
uniform mat3 u_normal_matrix;
out vec3 v_position;
out vec3 v_normal;
void main() {
    vec4 p = u_model_view * vec4(a_position, 1.0);
    v_position = p.xyz;
    v_normal = u_normal_matrix * a_normal;
    gl_Position = u_projection * p;
}
)";

const char* kMeshFs = "#version 330 core\n" SPT_GLSL_SHADE R"(
in vec3 v_position;
in vec3 v_normal;
uniform vec4 u_color;
uniform int u_smooth;
layout(location = 0) out vec4 frag_color;
layout(location = 1) out vec4 frag_cover; // see-through layer: alpha drives the transmittance
void main() {
    vec3 n;
    // Vertices without a normal carry zero; their faces fall back to the face normal.
    if (u_smooth == 1 && dot(v_normal, v_normal) > 0.25)
        n = normalize(v_normal);
    else
        n = normalize(cross(dFdx(v_position), dFdy(v_position)));
    frag_color = vec4(shade(u_color.rgb, n), u_color.a);
    frag_cover = vec4(0.0, 0.0, 0.0, u_color.a);
}
)";

const char* kLineVs = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec4 a_color;
uniform mat4 u_mvp;
uniform float u_point_size;
out vec4 v_color;
void main() {
    gl_Position = u_mvp * vec4(a_position, 1.0);
    gl_PointSize = u_point_size;
    v_color = a_color;
}
)";

const char* kLineFs = R"(#version 330 core
in vec4 v_color;
uniform int u_round_points;
layout(location = 0) out vec4 frag_color;
layout(location = 1) out vec4 frag_cover;
void main() {
    if (u_round_points == 1) {
        vec2 d = gl_PointCoord * 2.0 - 1.0;
        if (dot(d, d) > 1.0) discard;
    }
    frag_color = v_color;
    frag_cover = vec4(0.0, 0.0, 0.0, v_color.a);
}
)";

// Circle vertices: xy on the unit circle, z the circle: 0, 1, 2 the great circles
// normal to X, Y, Z (world axes); 3 the outline seen from the eye.
const char* kCircleVs = R"(#version 330 core
layout(location = 0) in vec3 a_circle;
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec4 a_sphere;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform int u_ortho;
uniform float u_alpha;
out vec4 v_color;
void main() {
    vec3 c = (u_view * vec4(a_sphere.xyz, 1.0)).xyz;
    float r = a_sphere.w;
    vec2 k = a_circle.xy;
    vec3 p;
    int which = int(a_circle.z + 0.5);
    if (which < 3) {
        vec3 local = which == 0 ? vec3(0.0, k.x, k.y) : which == 1 ? vec3(k.x, 0.0, k.y) : vec3(k.x, k.y, 0.0);
        p = c + mat3(u_view) * local * r;
    } else if (u_ortho == 1) {
        p = c + vec3(k * r, 0.0);
    } else {
        float d = length(c);
        if (d <= r * 1.001) {  // eye inside the sphere: it has no outline
            gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
            v_color = vec4(0.0);
            return;
        }
        vec3 w = c / d;
        vec3 helper = abs(w.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 u = normalize(cross(helper, w));
        vec3 v = cross(w, u);
        // The tangent points of the eye's cone: a circle nearer the eye than the centre.
        float back = r * r / d;
        float rr = r * sqrt(d * d - r * r) / d;
        p = c - w * back + (k.x * u + k.y * v) * rr;
    }
    v_color = vec4(a_color.rgb, a_color.a * u_alpha);
    gl_Position = u_projection * vec4(p, 1.0);
}
)";

const char* kCircleFs = R"(#version 330 core
in vec4 v_color;
layout(location = 0) out vec4 frag_color;
layout(location = 1) out vec4 frag_cover;
void main() {
    frag_color = v_color;
    frag_cover = vec4(0.0, 0.0, 0.0, v_color.a);
}
)";

GLuint compile(const GlFunctions& gl, GLenum type, const char* source, const char* name) {
    const GLuint s = gl.CreateShader(type);
    gl.ShaderSource(s, 1, &source, nullptr);
    gl.CompileShader(s);
    GLint ok = 0;
    gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
        gl.DeleteShader(s);
        throw std::runtime_error(std::string("OpenGL: cannot compile the ") + name + " shader: " + log);
    }
    return s;
}

} // namespace

GLuint link_program(const GlFunctions& gl, const char* vs, const char* fs, const char* name) {
    const GLuint v = compile(gl, GL_VERTEX_SHADER, vs, name);
    const GLuint f = compile(gl, GL_FRAGMENT_SHADER, fs, name);
    const GLuint p = gl.CreateProgram();
    gl.AttachShader(p, v);
    gl.AttachShader(p, f);
    gl.LinkProgram(p);
    gl.DeleteShader(v);
    gl.DeleteShader(f);
    GLint ok = 0;
    gl.GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetProgramInfoLog(p, sizeof log, nullptr, log);
        gl.DeleteProgram(p);
        throw std::runtime_error(std::string("OpenGL: cannot link the ") + name + " program: " + log);
    }
    return p;
}

Programs build_programs(const GlFunctions& gl) {
    Programs p;
    auto loc = [&](GLuint prog, const char* n) { return gl.GetUniformLocation(prog, n); };
    p.mesh.id = link_program(gl, kMeshVs, kMeshFs, "mesh");
    p.mesh.model_view = loc(p.mesh.id, "u_model_view");
    p.mesh.projection = loc(p.mesh.id, "u_projection");
    p.mesh.normal_matrix = loc(p.mesh.id, "u_normal_matrix");
    p.mesh.color = loc(p.mesh.id, "u_color");
    p.mesh.smooth = loc(p.mesh.id, "u_smooth");
    p.line.id = link_program(gl, kLineVs, kLineFs, "line");
    p.line.mvp = loc(p.line.id, "u_mvp");
    p.line.point_size = loc(p.line.id, "u_point_size");
    p.line.round_points = loc(p.line.id, "u_round_points");
    p.circle.id = link_program(gl, kCircleVs, kCircleFs, "circle");
    p.circle.view = loc(p.circle.id, "u_view");
    p.circle.projection = loc(p.circle.id, "u_projection");
    p.circle.ortho = loc(p.circle.id, "u_ortho");
    p.circle.alpha = loc(p.circle.id, "u_alpha");
    build_layer_programs(gl, p);
    return p;
}

void delete_programs(const GlFunctions& gl, Programs& p) {
    for (GLuint* id : {&p.mesh.id, &p.line.id, &p.circle.id, &p.splat.id, &p.composite.id, &p.finals.id, &p.recolour.id})
        if (*id) gl.DeleteProgram(*id), *id = 0;
}

} // namespace spt::render::detail
