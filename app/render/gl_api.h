// The OpenGL 3.3 core entry points the renderer uses, loaded through a get_proc_address seam so that
// the renderer library links no GL library: the headless program hands in OSMesaGetProcAddress, the
// GUI hands in glfwGetProcAddress (wrapped to this signature).
#pragma once
#include <GL/glcorearb.h>

#include <string>

namespace sph::render {

/// Looks up a GL entry point by name ("glClear"); returns nullptr if absent.
using GetProcFn = void* (*)(const char* name);

// X-macro: (pointer type, member name). The GL name is "gl" + member name.
#define SPH_GL_FUNCTIONS(X)                                  \
  X(PFNGLGETERRORPROC, GetError)                             \
  X(PFNGLGETSTRINGPROC, GetString)                           \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                       \
  X(PFNGLVIEWPORTPROC, Viewport)                             \
  X(PFNGLSCISSORPROC, Scissor)                               \
  X(PFNGLENABLEPROC, Enable)                                 \
  X(PFNGLDISABLEPROC, Disable)                               \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)           \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                           \
  X(PFNGLDEPTHMASKPROC, DepthMask)                           \
  X(PFNGLCLEARCOLORPROC, ClearColor)                         \
  X(PFNGLCLEARDEPTHPROC, ClearDepth)                         \
  X(PFNGLCLEARPROC, Clear)                                   \
  X(PFNGLFINISHPROC, Finish)                                 \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                       \
  X(PFNGLREADPIXELSPROC, ReadPixels)                         \
  X(PFNGLCREATESHADERPROC, CreateShader)                     \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                     \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                   \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                       \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)             \
  X(PFNGLDELETESHADERPROC, DeleteShader)                     \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                   \
  X(PFNGLATTACHSHADERPROC, AttachShader)                     \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                       \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                     \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)           \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                   \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                         \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)         \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                           \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                           \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                           \
  X(PFNGLUNIFORM4FPROC, Uniform4f)                           \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)             \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)               \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)               \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)         \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                         \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                         \
  X(PFNGLBUFFERDATAPROC, BufferData)                         \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                   \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)       \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)       \
  X(PFNGLGENTEXTURESPROC, GenTextures)                       \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                       \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                   \
  X(PFNGLTEXIMAGE1DPROC, TexImage1D)                         \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                         \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                   \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                 \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                         \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)

/// Function-pointer table; call as gl.Clear(GL_COLOR_BUFFER_BIT).
struct GlApi {
#define SPH_GL_MEMBER(type, name) type name = nullptr;
  SPH_GL_FUNCTIONS(SPH_GL_MEMBER)
#undef SPH_GL_MEMBER

  /// Loads every entry point; on failure *err lists the missing names and the table is unusable.
  bool load(GetProcFn get_proc, std::string* err);
};

}  // namespace sph::render
