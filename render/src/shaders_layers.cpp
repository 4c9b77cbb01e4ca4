// GLSL 3.30 sources of the full-view passes: the splatted spheres into the base, and the cached layers put together.
#include "shaders.hpp"
#include <string>

namespace spt::render::detail {
namespace {

// The layers the composite and the finals read (LayerSamplers; frame_layers.cpp binds them),
// ahead of either's own source.
const char* kLayerSamplersFs = R"(#version 330 core
uniform sampler2D u_base;
uniform sampler2D u_cover;
uniform sampler2D u_transmittance;
uniform usampler2D u_ids;
uniform sampler2D u_plain;
uniform sampler2D u_marked;
)";

// One triangle over the whole viewport; no vertex arrays read.
const char* kFullViewVs = R"(#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// The spheres the CPU ray-cast (sphere_splat.hpp) into the base: what the GL impostor shader wrote
// for each sphere pixel (colour, both mark colours, id) and its depth, so the passes after it are
// depth-tested against the spheres as before. Pixels no sphere covers hold a depth of 2.
const char* kSplatFs = R"(#version 330 core
uniform sampler2D u_depth;
uniform sampler2D u_plain;
uniform sampler2D u_marked;
uniform usampler2D u_ids;
layout(location = 0) out vec4 frag_color;
layout(location = 1) out vec4 frag_plain;
layout(location = 2) out vec4 frag_marked;
layout(location = 3) out uint frag_id;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_depth, p, 0).r;
    if (depth > 1.0) discard;
    gl_FragDepth = depth;
    uint id = texelFetch(u_ids, p, 0).r;
    frag_plain = texelFetch(u_plain, p, 0);
    frag_marked = texelFetch(u_marked, p, 0);
    frag_color = (id & 0x80000000u) != 0u ? frag_marked : frag_plain;
    frag_id = id & 0x7fffffffu;
}
)";

// out = cover + transmittance * base: the see-through passes "over" the base, as blending them one
// by one onto it would (in half floats, rounded to the target once). The base's spheres were
// splatted with the marks of this very frame; a later change of marks goes through the finals
// and the recolour below instead, so the composite never reads the marks.
const char* kCompositeFs = R"(
uniform ivec2 u_origin;
out vec4 frag_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
    frag_color = texelFetch(u_cover, p, 0) + texelFetch(u_transmittance, p, 0).r * texelFetch(u_base, p, 0);
}
)";

// The two pictures a change of marks chooses between, made once for cached layers: every sphere
// unmarked (location 0) and every sphere marked (location 1), each exactly what the composite
// above writes for that mark: the same sum, rounded to eight bits as every target here rounds
// it (Qt's widget framebuffer and the off-screen buffers are RGBA8).
const char* kFinalsFs = R"(
layout(location = 0) out vec4 unmarked_color;
layout(location = 1) out vec4 marked_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint id = texelFetch(u_ids, p, 0).r;
    vec4 cover = texelFetch(u_cover, p, 0);
    float t = texelFetch(u_transmittance, p, 0).r;
    vec4 base = texelFetch(u_base, p, 0);
    unmarked_color = cover + t * (id == 0u ? base : texelFetch(u_plain, p, 0));
    marked_color = cover + t * (id == 0u ? base : texelFetch(u_marked, p, 0));
}
)";

// The composite from those two pictures: three reads a pixel instead of seven.
const char* kRecolourFs = R"(#version 330 core
uniform sampler2D u_unmarked;
uniform sampler2D u_marked;
uniform usampler2D u_ids;
uniform usamplerBuffer u_marks;
uniform ivec2 u_origin;
out vec4 frag_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
    uint id = texelFetch(u_ids, p, 0).r;
    bool marked = id != 0u && texelFetch(u_marks, int(3u * (id - 1u))).r != 0u;
    frag_color = marked ? texelFetch(u_marked, p, 0) : texelFetch(u_unmarked, p, 0);
}
)";

} // namespace

void build_layer_programs(const GlFunctions& gl, Programs& p) {
    auto loc = [&](GLuint prog, const char* n) { return gl.GetUniformLocation(prog, n); };
    auto layers = [&](GLuint prog) {
        return LayerSamplers{loc(prog, "u_base"), loc(prog, "u_cover"), loc(prog, "u_transmittance"),
                             loc(prog, "u_ids"),  loc(prog, "u_plain"), loc(prog, "u_marked")};
    };
    SplatProgram& s = p.splat;
    s.id = link_program(gl, kFullViewVs, kSplatFs, "splat");
    s.depth = loc(s.id, "u_depth");
    s.plain = loc(s.id, "u_plain");
    s.marked = loc(s.id, "u_marked");
    s.ids = loc(s.id, "u_ids");
    CompositeProgram& c = p.composite;
    const std::string composite = std::string(kLayerSamplersFs) + kCompositeFs;
    c.id = link_program(gl, kFullViewVs, composite.c_str(), "composite");
    c.layers = layers(c.id);
    c.origin = loc(c.id, "u_origin");
    FinalsProgram& f = p.finals;
    const std::string finals = std::string(kLayerSamplersFs) + kFinalsFs;
    f.id = link_program(gl, kFullViewVs, finals.c_str(), "finals");
    f.layers = layers(f.id);
    RecolourProgram& r = p.recolour;
    r.id = link_program(gl, kFullViewVs, kRecolourFs, "recolour");
    r.unmarked = loc(r.id, "u_unmarked");
    r.marked = loc(r.id, "u_marked");
    r.ids = loc(r.id, "u_ids");
    r.marks = loc(r.id, "u_marks");
    r.origin = loc(r.id, "u_origin");
}

} // namespace spt::render::detail
