#pragma once
// Renderer::Impl, shared by the renderer's files: its GL objects, per-draw state and draw passes.
#include "frame_equal.hpp"
#include "gl_functions.hpp"
#include "shaders.hpp"
#include "sphere_splat.hpp"
#include "spt/render/renderer.hpp"
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace spt::render {

struct Renderer::Impl {
    // One solid sphere as the GPU reads it (20 bytes), also what the CPU splat reads.
    using GpuSphere = detail::SplatSphere;
    static_assert(sizeof(GpuSphere) == 20, "GpuSphere layout");

    // One line or point vertex (16 bytes).
    struct LineVertex {
        float p[3];
        uint8_t rgba[4];
    };
    static_assert(sizeof(LineVertex) == 16, "LineVertex layout");

    // An uploaded mesh: interleaved position + normal, 32-bit indices; bounds in the object frame.
    struct GpuMesh {
        GLuint vao = 0, vbo = 0, ebo = 0;
        GLsizei index_count = 0, vertex_count = 0;
        Bounds bounds;
    };
    // A sphere set: its spheres kept for the CPU splat (sphere_splat.hpp), its marks also in GL
    // for the recolour.
    struct GpuSphereSet {
        std::vector<GpuSphere> spheres;
        GLuint mark_vbo = 0; // one byte a vertex, three a sphere (255 marked), made with the set
        uint32_t count = 0;
        Bounds bounds; // of the spheres, object frame
        uint64_t revision = 0;      // changes when the spheres change
        uint64_t mark_revision = 0; // changes when the marks change
        std::vector<uint8_t> marks; // what mark_vbo holds
    };

    // The last frame drawn, kept as layers in textures of its viewport's size: the base (the
    // opaque passes: colour, depth, and for each pixel of a sphere drawn with marks its index + 1
    // and the colour it has marked and not) and the overlay of the see-through passes (colour
    // "over" nothing, and transmittance). A frame drawn again with the same camera and size is
    // only composited, with the marked spheres' pixels in the colour of their current mark.
    struct FrameLayers {
        int width = 0, height = 0;
        GLuint base_fbo = 0, overlay_fbo = 0, empty_vao = 0, marks_texture = 0;
        GLuint base = 0, plain = 0, marked = 0, ids = 0, depth = 0, cover = 0, transmittance = 0;
        // The layers put together with every sphere unmarked and every sphere marked, made at
        // the first reuse of a frame with marks: a change of marks then only chooses per pixel.
        GLuint finals_fbo = 0, unmarked_final = 0, marked_final = 0;
        // The sphere splat's pixels, uploaded for the pass that puts them into the base.
        GLuint splat_depth = 0, splat_plain = 0, splat_marked = 0, splat_ids = 0;
        bool valid = false;
        bool finals = false; // the two pictures hold the cached layers
        Frame frame;
        Camera camera;
        std::vector<std::pair<uint32_t, uint64_t>> revisions;      // (set id, revision) of the frame's sets
        std::vector<std::pair<uint32_t, uint64_t>> mark_revisions; // (set id, mark revision)
        uint32_t mark_set = 0; // the one set whose marks the ids index; 0 if none or several
    };
    // What of the cached layers a draw can keep.
    enum class Reuse { None, Composite, Recolour };

    // Segments of each wire circle (a full turn).
    static constexpr int kCircleSegments = 64;

    // A sphere and its colour as the GPU reads them.
    static GpuSphere to_gpu(const SphereInstance& s);
    // Appends a line/point vertex at p (frame of the matrix it is drawn with).
    static void push_line_vertex(std::vector<LineVertex>& v, const Eigen::Vector3f& p, const Color& c);

    detail::GlFunctions gl;
    detail::Programs prog;
    std::string renderer_name;

    std::map<uint32_t, GpuMesh> meshes;
    std::map<uint32_t, GpuSphereSet> sphere_sets;
    uint32_t next_id = 1;
    uint64_t next_revision = 1;
    std::vector<uint8_t> scratch_marks; // set_marks' buffer, kept to spare an allocation a call
    FrameLayers layers;
    DrawKind last_kind = DrawKind::Full;

    GLuint circle_vbo = 0; // 4 circles as GL_LINES
    GLuint line_vao = 0, line_vbo = 0;     // streamed lines and points
    detail::SphereSplat splat;             // the sampling spheres of the view being drawn
    std::vector<GpuSphere> collision_spheres; // the collision pairs' spheres, while they are splatted
    GLuint wire_vao = 0, wire_vbo = 0;     // streamed wire-sphere instances

    // Per-draw state.
    Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
    Eigen::Matrix4f proj = Eigen::Matrix4f::Identity();
    bool ortho = false;

    // GPU objects and uploads (renderer_resources.cpp).
    explicit Impl(const ProcLoader& load);
    ~Impl();
    void set_sphere_attributes(GLuint divisor);
    void make_instanced_vao(GLuint& vao, GLuint& vbo, GLuint shape_vbo, int components);
    void free_mesh(GpuMesh& m);
    void free_set(GpuSphereSet& s);
    void upload_spheres(GpuSphereSet& s, const std::vector<SphereInstance>& spheres);
    void set_marks(GpuSphereSet& s, const std::vector<uint32_t>& marked);
    void stream_lines(const std::vector<LineVertex>& v);
    void use_line_program(const Eigen::Matrix4f& mvp, float point_size = 1, bool round = false);
    void draw_lines(const std::vector<LineVertex>& v, GLenum mode, float point_size = 1, bool round = false);
    // The same, placed by `mvp` instead of the view (lines uploaded relative to a point far out).
    void draw_lines(const std::vector<LineVertex>& v, GLenum mode, const Eigen::Matrix4f& mvp, float point_size = 1,
                    bool round = false);

    // The scene: ground grid, meshes, sampling spheres (draw_scene.cpp).
    void draw_grid(const Bounds& b, float ground);
    void draw_mesh_faces(const GpuMesh& m, const MeshItem& item);
    void draw_meshes(const Frame& f, bool transparent);
    void splat_sphere_items(const Frame& f);
    // Ray-casts the queued spheres (splat) and writes them into the bound base framebuffer.
    void draw_splat();

    // Marks over the scene: collision pairs, trails, wire spheres, axis gizmo (draw_overlays.cpp).
    float scene_diameter(const Bounds& b) const;
    void splat_collision_spheres(const CollisionOverlay& c);
    void draw_collision_marks(const CollisionOverlay& c, const Bounds& b);
    void draw_trails(const Frame& f);
    void draw_wire_spheres(const Frame& f, bool outlines);
    void draw_gizmo(const Viewport& vp);

    // One view of a frame: GL state and the order of the passes (renderer_frame.cpp).
    Bounds solid_bounds(const Frame& f) const;
    void draw_layers(const Frame& f, const Camera& cam, int width, int height, const Bounds& b);
    void draw(const Frame& f, const Camera& cam, const Viewport& vp, GLuint fbo, const Bounds& b);

    // The cached layers (frame_layers.cpp).
    void resize_layers(int width, int height);
    void free_layers();
    Reuse reuse(const Frame& f, const Camera& cam, int width, int height) const;
    void remember(const Frame& f, const Camera& cam);
    void marks_seen();
    void composite(const Viewport& vp, GLuint fbo);
    // Binds `texture` (GL_TEXTURE_2D or GL_TEXTURE_BUFFER) to texture unit `unit` for `sampler`.
    void bind_unit(int unit, GLenum target, GLuint texture, GLint sampler);
    void begin_full_view(const Viewport& vp, GLuint fbo, bool clip);
    void bind_layers(const detail::LayerSamplers& s);
    void end_full_view();
    // Makes the two final pictures of the cached layers (FrameLayers::finals).
    void make_finals();
    // Composite from the two final pictures and the marks.
    void recolour(const Viewport& vp, GLuint fbo);
};

} // namespace spt::render
