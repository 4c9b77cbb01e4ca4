#pragma once
// GLSL 3.30 programs of the renderer and their uniform locations.
#include "gl_functions.hpp"

namespace spt::render::detail {

// Attribute locations shared by every program and vertex array.
enum Attrib : GLuint {
    kPosition = 0, // vec3 (mesh, lines) or vec3 circle point
    kNormal = 1,   // vec3 mesh normal
    kColor = 2,    // vec4 per-vertex or per-instance colour
    kSphere = 3,   // vec4 per-instance centre (xyz) and radius (w)
};

// Lit triangles.
struct MeshProgram {
    GLuint id = 0;
    GLint model_view = -1, projection = -1, normal_matrix = -1, color = -1, smooth = -1;
};

// Lines and points with per-vertex colour (or a constant generic attribute).
struct LineProgram {
    GLuint id = 0;
    GLint mvp = -1, point_size = -1, round_points = -1;
};

// The CPU-splatted spheres (sphere_splat.hpp) written into the base layer with their depth.
struct SplatProgram {
    GLuint id = 0;
    GLint depth = -1, plain = -1, marked = -1, ids = -1;
};

// Wire circles of bounding spheres, instanced.
struct CircleProgram {
    GLuint id = 0;
    GLint view = -1, projection = -1, ortho = -1, alpha = -1;
};

// The six layer textures a full-view pass reads (frame_layers.cpp binds them to units 0-5).
struct LayerSamplers {
    GLint base = -1, cover = -1, transmittance = -1, ids = -1, plain = -1, marked = -1;
};

// A view's layers put together: the overlay layer over the base layer (shaders_layers.cpp).
struct CompositeProgram {
    GLuint id = 0;
    LayerSamplers layers; // reads base, cover and transmittance; the rest stay unused (-1)
    GLint origin = -1;
};

struct FinalsProgram {
    GLuint id = 0;
    LayerSamplers layers;
};

struct RecolourProgram {
    GLuint id = 0;
    GLint unmarked = -1, marked = -1, ids = -1, marks = -1, origin = -1;
};

struct Programs {
    MeshProgram mesh;
    LineProgram line;
    SplatProgram splat;
    CircleProgram circle;
    CompositeProgram composite;
    FinalsProgram finals;     // the layers put together as all unmarked and all marked
    RecolourProgram recolour; // the composite from those, for a change of marks
};

// Compiles and links a program from GLSL sources; throws std::runtime_error naming it with the log.
GLuint link_program(const GlFunctions& gl, const char* vs, const char* fs, const char* name);
// Links the splat, composite, finals and recolour programs into `p` (shaders_layers.cpp).
void build_layer_programs(const GlFunctions& gl, Programs& p);

// Compiles and links every program; throws std::runtime_error with the compiler log.
Programs build_programs(const GlFunctions& gl);
// Deletes the programs made by build_programs.
void delete_programs(const GlFunctions& gl, Programs& p);

} // namespace spt::render::detail
