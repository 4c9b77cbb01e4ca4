#pragma once
// The table of GL entry points spt calls, loaded through the caller's ProcLoader.
// libOSMesa and glvnd's libOpenGL both export every `gl*` symbol, and a direct call
// can silently land in the wrong one (DESIGN.md §4); so nothing in spt calls GL
// directly. GL_GLEXT_PROTOTYPES stays undefined: a direct call does not compile.
#include "spt/render/gl_loader.hpp"
#include <GL/glcorearb.h>

namespace spt::render::detail {

// Every GL 3.3 core function the renderer uses: X(pointer type, name without "gl").
#define SPT_GL_FUNCTIONS(X)                                   \
    X(PFNGLGETERRORPROC, GetError)                            \
    X(PFNGLGETSTRINGPROC, GetString)                          \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                      \
    X(PFNGLFINISHPROC, Finish)                                \
    X(PFNGLCLEARPROC, Clear)                                  \
    X(PFNGLCLEARCOLORPROC, ClearColor)                        \
    X(PFNGLCLEARDEPTHPROC, ClearDepth)                        \
    X(PFNGLENABLEPROC, Enable)                                \
    X(PFNGLDISABLEPROC, Disable)                              \
    X(PFNGLVIEWPORTPROC, Viewport)                            \
    X(PFNGLSCISSORPROC, Scissor)                              \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                          \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                          \
    X(PFNGLDEPTHMASKPROC, DepthMask)                          \
    X(PFNGLCOLORMASKPROC, ColorMask)                          \
    X(PFNGLPOLYGONMODEPROC, PolygonMode)                      \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                  \
    X(PFNGLCULLFACEPROC, CullFace)                            \
    X(PFNGLFRONTFACEPROC, FrontFace)                          \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                      \
    X(PFNGLREADPIXELSPROC, ReadPixels)                        \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                        \
    X(PFNGLDRAWBUFFERPROC, DrawBuffer)                        \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                        \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                  \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                        \
    X(PFNGLBUFFERDATAPROC, BufferData)                        \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                  \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)              \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)        \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)              \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray) \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)      \
    X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)      \
    X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f)                \
    X(PFNGLCREATESHADERPROC, CreateShader)                    \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                    \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                  \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                      \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)            \
    X(PFNGLDELETESHADERPROC, DeleteShader)                    \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                  \
    X(PFNGLATTACHSHADERPROC, AttachShader)                    \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                      \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                    \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)          \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                  \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                        \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)        \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                          \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                          \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                          \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)            \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)            \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                        \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                    \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)      \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)              \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)        \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)              \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus) \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)            \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)      \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)            \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)     \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)   \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                      \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                  \
    X(PFNGLCLEARBUFFERUIVPROC, ClearBufferuiv)                \
    X(PFNGLGENTEXTURESPROC, GenTextures)                      \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                      \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                  \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                        \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                  \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                  \
    X(PFNGLTEXBUFFERPROC, TexBuffer)                          \
    X(PFNGLUNIFORM2IPROC, Uniform2i)

// The GL functions spt uses, as pointers into the current context's implementation.
struct GlFunctions {
#define SPT_GL_DECLARE(type, name) type name = nullptr;
    SPT_GL_FUNCTIONS(SPT_GL_DECLARE)
#undef SPT_GL_DECLARE

    // Resolves every entry point through `load` ("gl" + name); throws
    // std::runtime_error naming the first one the loader cannot find.
    void load(const ProcLoader& load);
};

// Throws std::runtime_error("what: GL error 0x...") if the context has a pending GL error.
void check_gl(const GlFunctions& gl, const char* what);

} // namespace spt::render::detail
