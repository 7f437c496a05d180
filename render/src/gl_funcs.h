/* The only door to OpenGL (like raylib's rlgl.h): every GL entry point the renderer uses is
 * listed here once and loaded at run time through the backend's get-proc-address, so the
 * same code runs on EGL, OSMesa and an adopted window context without linking libGL. */
#ifndef RENDER_GL_FUNCS_H
#define RENDER_GL_FUNCS_H

#include <GL/glcorearb.h>

#define RD_GL_FUNCTIONS(X)                                                                         \
    X(PFNGLGETSTRINGPROC, glGetString)                                                             \
    X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                                         \
    X(PFNGLGETERRORPROC, glGetError)                                                               \
    X(PFNGLENABLEPROC, glEnable)                                                                   \
    X(PFNGLDISABLEPROC, glDisable)                                                                 \
    X(PFNGLVIEWPORTPROC, glViewport)                                                               \
    X(PFNGLCLEARPROC, glClear)                                                                     \
    X(PFNGLCLEARCOLORPROC, glClearColor)                                                           \
    X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                                             \
    X(PFNGLDEPTHMASKPROC, glDepthMask)                                                             \
    X(PFNGLCULLFACEPROC, glCullFace)                                                               \
    X(PFNGLFRONTFACEPROC, glFrontFace)                                                             \
    X(PFNGLFINISHPROC, glFinish)                                                                   \
    X(PFNGLREADPIXELSPROC, glReadPixels)                                                           \
    X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                                         \
    X(PFNGLGENBUFFERSPROC, glGenBuffers)                                                           \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                                     \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                                                           \
    X(PFNGLBUFFERDATAPROC, glBufferData)                                                           \
    X(PFNGLGETBUFFERSUBDATAPROC, glGetBufferSubData)                                               \
    X(PFNGLGETBUFFERPARAMETERIVPROC, glGetBufferParameteriv)                                       \
    X(PFNGLTEXBUFFERPROC, glTexBuffer)                                                             \
    X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                                                 \
    X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                                           \
    X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                                 \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)                                 \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, glDisableVertexAttribArray)                               \
    X(PFNGLVERTEXATTRIB2FPROC, glVertexAttrib2f)                                                   \
    X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                                         \
    X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                                       \
    X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                                           \
    X(PFNGLCREATESHADERPROC, glCreateShader)                                                       \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                                                       \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                                                     \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                                         \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                               \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                                                       \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                                     \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                                                       \
    X(PFNGLBINDATTRIBLOCATIONPROC, glBindAttribLocation)                                           \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                                         \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                                       \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                                             \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                                     \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                                                           \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                                           \
    X(PFNGLSCISSORPROC, glScissor)                                                                 \
    X(PFNGLUNIFORM4FPROC, glUniform4f)                                                             \
    X(PFNGLUNIFORM1IPROC, glUniform1i)                                                             \
    X(PFNGLUNIFORM1FPROC, glUniform1f)                                                             \
    X(PFNGLUNIFORM2IPROC, glUniform2i)                                                             \
    X(PFNGLUNIFORM2FPROC, glUniform2f)                                                             \
    X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                                           \
    X(PFNGLUNIFORM1IVPROC, glUniform1iv)                                                           \
    X(PFNGLUNIFORM1FVPROC, glUniform1fv)                                                           \
    X(PFNGLUNIFORM2FVPROC, glUniform2fv)                                                           \
    X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                                           \
    X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                                               \
    X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                                               \
    X(PFNGLGENTEXTURESPROC, glGenTextures)                                                         \
    X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                                   \
    X(PFNGLBINDTEXTUREPROC, glBindTexture)                                                         \
    X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                                           \
    X(PFNGLGETTEXIMAGEPROC, glGetTexImage)                                                         \
    X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                                                     \
    X(PFNGLTEXPARAMETERFPROC, glTexParameterf)                                                     \
    X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                                                     \
    X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                                                   \
    X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                                                 \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                                           \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                                 \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)                                       \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                                   \
    X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                                               \
    X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                                         \
    X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                                               \
    X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)                                         \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)                                 \
    X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                                                         \
    X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                                                     \
    X(PFNGLREADBUFFERPROC, glReadBuffer)                                                           \
    X(PFNGLGENSAMPLERSPROC, glGenSamplers)                                                         \
    X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                                                   \
    X(PFNGLBINDSAMPLERPROC, glBindSampler)                                                         \
    X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)                                             \
    X(PFNGLSTENCILFUNCPROC, glStencilFunc)                                                         \
    X(PFNGLSTENCILOPPROC, glStencilOp)                                                             \
    X(PFNGLSTENCILMASKPROC, glStencilMask)                                                         \
    X(PFNGLCOLORMASKPROC, glColorMask)                                                             \
    X(PFNGLBLENDFUNCPROC, glBlendFunc)                                                             \
    X(PFNGLCLEARSTENCILPROC, glClearStencil)                                                       \
    X(PFNGLGENQUERIESPROC, glGenQueries)                                                           \
    X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                                                     \
    X(PFNGLBEGINQUERYPROC, glBeginQuery)                                                           \
    X(PFNGLENDQUERYPROC, glEndQuery)                                                               \
    X(PFNGLGETQUERYOBJECTUIVPROC, glGetQueryObjectuiv)                                             \
    X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                                                     \
    X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)

#define RD_GL_DECLARE(type, name) extern type rd_##name;
RD_GL_FUNCTIONS(RD_GL_DECLARE)
#undef RD_GL_DECLARE

/* Entry points beyond GL 3.3, loaded when present (ARCHITECTURE.md: 4.x only behind a
 * capability check); rd_gl_has_tex_storage() tells whether glTexStorage2D may be called. */
extern PFNGLTEXSTORAGE2DPROC rd_glTexStorage2D;
int rd_gl_has_tex_storage(void);

/* Code in render/src calls glFoo(...) as usual; these names resolve to the loaded pointers. */
#define glGetString rd_glGetString
#define glTexSubImage2D rd_glTexSubImage2D
#define glGenQueries rd_glGenQueries
#define glDeleteQueries rd_glDeleteQueries
#define glBeginQuery rd_glBeginQuery
#define glEndQuery rd_glEndQuery
#define glGetQueryObjectuiv rd_glGetQueryObjectuiv
#define glGenSamplers rd_glGenSamplers
#define glDeleteSamplers rd_glDeleteSamplers
#define glBindSampler rd_glBindSampler
#define glSamplerParameteri rd_glSamplerParameteri
#define glStencilFunc rd_glStencilFunc
#define glStencilOp rd_glStencilOp
#define glStencilMask rd_glStencilMask
#define glColorMask rd_glColorMask
#define glBlendFunc rd_glBlendFunc
#define glClearStencil rd_glClearStencil
#define glGetIntegerv rd_glGetIntegerv
#define glGetError rd_glGetError
#define glEnable rd_glEnable
#define glDisable rd_glDisable
#define glViewport rd_glViewport
#define glClear rd_glClear
#define glClearColor rd_glClearColor
#define glDepthFunc rd_glDepthFunc
#define glDepthMask rd_glDepthMask
#define glCullFace rd_glCullFace
#define glFrontFace rd_glFrontFace
#define glFinish rd_glFinish
#define glReadPixels rd_glReadPixels
#define glPixelStorei rd_glPixelStorei
#define glGenBuffers rd_glGenBuffers
#define glDeleteBuffers rd_glDeleteBuffers
#define glBindBuffer rd_glBindBuffer
#define glBufferData rd_glBufferData
#define glGetBufferSubData rd_glGetBufferSubData
#define glGetBufferParameteriv rd_glGetBufferParameteriv
#define glTexBuffer rd_glTexBuffer
#define glGenVertexArrays rd_glGenVertexArrays
#define glDeleteVertexArrays rd_glDeleteVertexArrays
#define glBindVertexArray rd_glBindVertexArray
#define glEnableVertexAttribArray rd_glEnableVertexAttribArray
#define glDisableVertexAttribArray rd_glDisableVertexAttribArray
#define glVertexAttrib2f rd_glVertexAttrib2f
#define glVertexAttribPointer rd_glVertexAttribPointer
#define glDrawElements rd_glDrawElements
#define glDrawArrays rd_glDrawArrays
#define glCreateShader rd_glCreateShader
#define glShaderSource rd_glShaderSource
#define glCompileShader rd_glCompileShader
#define glGetShaderiv rd_glGetShaderiv
#define glGetShaderInfoLog rd_glGetShaderInfoLog
#define glDeleteShader rd_glDeleteShader
#define glCreateProgram rd_glCreateProgram
#define glAttachShader rd_glAttachShader
#define glBindAttribLocation rd_glBindAttribLocation
#define glLinkProgram rd_glLinkProgram
#define glGetProgramiv rd_glGetProgramiv
#define glGetProgramInfoLog rd_glGetProgramInfoLog
#define glDeleteProgram rd_glDeleteProgram
#define glUseProgram rd_glUseProgram
#define glGetUniformLocation rd_glGetUniformLocation
#define glScissor rd_glScissor
#define glUniform4f rd_glUniform4f
#define glUniform1i rd_glUniform1i
#define glUniform1f rd_glUniform1f
#define glUniform2i rd_glUniform2i
#define glUniform2f rd_glUniform2f
#define glUniform3fv rd_glUniform3fv
#define glUniform1iv rd_glUniform1iv
#define glUniform1fv rd_glUniform1fv
#define glUniform2fv rd_glUniform2fv
#define glUniform4fv rd_glUniform4fv
#define glUniformMatrix3fv rd_glUniformMatrix3fv
#define glUniformMatrix4fv rd_glUniformMatrix4fv
#define glGenTextures rd_glGenTextures
#define glDeleteTextures rd_glDeleteTextures
#define glBindTexture rd_glBindTexture
#define glTexImage2D rd_glTexImage2D
#define glGetTexImage rd_glGetTexImage
#define glTexParameteri rd_glTexParameteri
#define glTexParameterf rd_glTexParameterf
#define glActiveTexture rd_glActiveTexture
#define glGenerateMipmap rd_glGenerateMipmap
#define glGenFramebuffers rd_glGenFramebuffers
#define glDeleteFramebuffers rd_glDeleteFramebuffers
#define glBindFramebuffer rd_glBindFramebuffer
#define glFramebufferTexture2D rd_glFramebufferTexture2D
#define glCheckFramebufferStatus rd_glCheckFramebufferStatus
#define glGenRenderbuffers rd_glGenRenderbuffers
#define glDeleteRenderbuffers rd_glDeleteRenderbuffers
#define glBindRenderbuffer rd_glBindRenderbuffer
#define glRenderbufferStorage rd_glRenderbufferStorage
#define glFramebufferRenderbuffer rd_glFramebufferRenderbuffer
#define glDrawBuffers rd_glDrawBuffers
#define glClearBufferfv rd_glClearBufferfv
#define glReadBuffer rd_glReadBuffer
#define glBlitFramebuffer rd_glBlitFramebuffer

/* Loads every entry point; on failure names the first missing one in rd_last_error(). */
int rd_gl_load(void *(*get_proc_address)(const char *name));

#endif
