/* OpenGL ES 2.0 entry points as a table the renderer calls through.
 *
 * skinplay links no GL library: libGLESv2 (glvnd) and libOSMesa both export
 * the gl* symbols and clash when linked into one binary, so the active
 * display backend hands over its get_proc and gl_api_load() looks every
 * entry point up by name. Members are named after the GL functions without
 * the "gl" prefix, so a call reads gl->CreateShader(GL_VERTEX_SHADER). */
#ifndef GL_API_H
#define GL_API_H

/* Only the types and enums: a direct glFoo() call must not compile. */
#ifndef GL_GLES_PROTOTYPES
#define GL_GLES_PROTOTYPES 0
#endif
#include <GLES2/gl2.h>

#include "skp_error.h"

/* X(Name, NAME): every OpenGL ES 2.0 core function, NAME picks its
 * PFNGL<NAME>PROC type from <GLES2/gl2.h>. */
#define GL_API_ENTRY_POINTS(X) \
	X(ActiveTexture, ACTIVETEXTURE) \
	X(AttachShader, ATTACHSHADER) \
	X(BindAttribLocation, BINDATTRIBLOCATION) \
	X(BindBuffer, BINDBUFFER) \
	X(BindFramebuffer, BINDFRAMEBUFFER) \
	X(BindRenderbuffer, BINDRENDERBUFFER) \
	X(BindTexture, BINDTEXTURE) \
	X(BlendColor, BLENDCOLOR) \
	X(BlendEquation, BLENDEQUATION) \
	X(BlendEquationSeparate, BLENDEQUATIONSEPARATE) \
	X(BlendFunc, BLENDFUNC) \
	X(BlendFuncSeparate, BLENDFUNCSEPARATE) \
	X(BufferData, BUFFERDATA) \
	X(BufferSubData, BUFFERSUBDATA) \
	X(CheckFramebufferStatus, CHECKFRAMEBUFFERSTATUS) \
	X(Clear, CLEAR) \
	X(ClearColor, CLEARCOLOR) \
	X(ClearDepthf, CLEARDEPTHF) \
	X(ClearStencil, CLEARSTENCIL) \
	X(ColorMask, COLORMASK) \
	X(CompileShader, COMPILESHADER) \
	X(CompressedTexImage2D, COMPRESSEDTEXIMAGE2D) \
	X(CompressedTexSubImage2D, COMPRESSEDTEXSUBIMAGE2D) \
	X(CopyTexImage2D, COPYTEXIMAGE2D) \
	X(CopyTexSubImage2D, COPYTEXSUBIMAGE2D) \
	X(CreateProgram, CREATEPROGRAM) \
	X(CreateShader, CREATESHADER) \
	X(CullFace, CULLFACE) \
	X(DeleteBuffers, DELETEBUFFERS) \
	X(DeleteFramebuffers, DELETEFRAMEBUFFERS) \
	X(DeleteProgram, DELETEPROGRAM) \
	X(DeleteRenderbuffers, DELETERENDERBUFFERS) \
	X(DeleteShader, DELETESHADER) \
	X(DeleteTextures, DELETETEXTURES) \
	X(DepthFunc, DEPTHFUNC) \
	X(DepthMask, DEPTHMASK) \
	X(DepthRangef, DEPTHRANGEF) \
	X(DetachShader, DETACHSHADER) \
	X(Disable, DISABLE) \
	X(DisableVertexAttribArray, DISABLEVERTEXATTRIBARRAY) \
	X(DrawArrays, DRAWARRAYS) \
	X(DrawElements, DRAWELEMENTS) \
	X(Enable, ENABLE) \
	X(EnableVertexAttribArray, ENABLEVERTEXATTRIBARRAY) \
	X(Finish, FINISH) \
	X(Flush, FLUSH) \
	X(FramebufferRenderbuffer, FRAMEBUFFERRENDERBUFFER) \
	X(FramebufferTexture2D, FRAMEBUFFERTEXTURE2D) \
	X(FrontFace, FRONTFACE) \
	X(GenBuffers, GENBUFFERS) \
	X(GenerateMipmap, GENERATEMIPMAP) \
	X(GenFramebuffers, GENFRAMEBUFFERS) \
	X(GenRenderbuffers, GENRENDERBUFFERS) \
	X(GenTextures, GENTEXTURES) \
	X(GetActiveAttrib, GETACTIVEATTRIB) \
	X(GetActiveUniform, GETACTIVEUNIFORM) \
	X(GetAttachedShaders, GETATTACHEDSHADERS) \
	X(GetAttribLocation, GETATTRIBLOCATION) \
	X(GetBooleanv, GETBOOLEANV) \
	X(GetBufferParameteriv, GETBUFFERPARAMETERIV) \
	X(GetError, GETERROR) \
	X(GetFloatv, GETFLOATV) \
	X(GetFramebufferAttachmentParameteriv, GETFRAMEBUFFERATTACHMENTPARAMETERIV) \
	X(GetIntegerv, GETINTEGERV) \
	X(GetProgramiv, GETPROGRAMIV) \
	X(GetProgramInfoLog, GETPROGRAMINFOLOG) \
	X(GetRenderbufferParameteriv, GETRENDERBUFFERPARAMETERIV) \
	X(GetShaderiv, GETSHADERIV) \
	X(GetShaderInfoLog, GETSHADERINFOLOG) \
	X(GetShaderPrecisionFormat, GETSHADERPRECISIONFORMAT) \
	X(GetShaderSource, GETSHADERSOURCE) \
	X(GetString, GETSTRING) \
	X(GetTexParameterfv, GETTEXPARAMETERFV) \
	X(GetTexParameteriv, GETTEXPARAMETERIV) \
	X(GetUniformfv, GETUNIFORMFV) \
	X(GetUniformiv, GETUNIFORMIV) \
	X(GetUniformLocation, GETUNIFORMLOCATION) \
	X(GetVertexAttribfv, GETVERTEXATTRIBFV) \
	X(GetVertexAttribiv, GETVERTEXATTRIBIV) \
	X(GetVertexAttribPointerv, GETVERTEXATTRIBPOINTERV) \
	X(Hint, HINT) \
	X(IsBuffer, ISBUFFER) \
	X(IsEnabled, ISENABLED) \
	X(IsFramebuffer, ISFRAMEBUFFER) \
	X(IsProgram, ISPROGRAM) \
	X(IsRenderbuffer, ISRENDERBUFFER) \
	X(IsShader, ISSHADER) \
	X(IsTexture, ISTEXTURE) \
	X(LineWidth, LINEWIDTH) \
	X(LinkProgram, LINKPROGRAM) \
	X(PixelStorei, PIXELSTOREI) \
	X(PolygonOffset, POLYGONOFFSET) \
	X(ReadPixels, READPIXELS) \
	X(ReleaseShaderCompiler, RELEASESHADERCOMPILER) \
	X(RenderbufferStorage, RENDERBUFFERSTORAGE) \
	X(SampleCoverage, SAMPLECOVERAGE) \
	X(Scissor, SCISSOR) \
	X(ShaderBinary, SHADERBINARY) \
	X(ShaderSource, SHADERSOURCE) \
	X(StencilFunc, STENCILFUNC) \
	X(StencilFuncSeparate, STENCILFUNCSEPARATE) \
	X(StencilMask, STENCILMASK) \
	X(StencilMaskSeparate, STENCILMASKSEPARATE) \
	X(StencilOp, STENCILOP) \
	X(StencilOpSeparate, STENCILOPSEPARATE) \
	X(TexImage2D, TEXIMAGE2D) \
	X(TexParameterf, TEXPARAMETERF) \
	X(TexParameterfv, TEXPARAMETERFV) \
	X(TexParameteri, TEXPARAMETERI) \
	X(TexParameteriv, TEXPARAMETERIV) \
	X(TexSubImage2D, TEXSUBIMAGE2D) \
	X(Uniform1f, UNIFORM1F) \
	X(Uniform1fv, UNIFORM1FV) \
	X(Uniform1i, UNIFORM1I) \
	X(Uniform1iv, UNIFORM1IV) \
	X(Uniform2f, UNIFORM2F) \
	X(Uniform2fv, UNIFORM2FV) \
	X(Uniform2i, UNIFORM2I) \
	X(Uniform2iv, UNIFORM2IV) \
	X(Uniform3f, UNIFORM3F) \
	X(Uniform3fv, UNIFORM3FV) \
	X(Uniform3i, UNIFORM3I) \
	X(Uniform3iv, UNIFORM3IV) \
	X(Uniform4f, UNIFORM4F) \
	X(Uniform4fv, UNIFORM4FV) \
	X(Uniform4i, UNIFORM4I) \
	X(Uniform4iv, UNIFORM4IV) \
	X(UniformMatrix2fv, UNIFORMMATRIX2FV) \
	X(UniformMatrix3fv, UNIFORMMATRIX3FV) \
	X(UniformMatrix4fv, UNIFORMMATRIX4FV) \
	X(UseProgram, USEPROGRAM) \
	X(ValidateProgram, VALIDATEPROGRAM) \
	X(VertexAttrib1f, VERTEXATTRIB1F) \
	X(VertexAttrib1fv, VERTEXATTRIB1FV) \
	X(VertexAttrib2f, VERTEXATTRIB2F) \
	X(VertexAttrib2fv, VERTEXATTRIB2FV) \
	X(VertexAttrib3f, VERTEXATTRIB3F) \
	X(VertexAttrib3fv, VERTEXATTRIB3FV) \
	X(VertexAttrib4f, VERTEXATTRIB4F) \
	X(VertexAttrib4fv, VERTEXATTRIB4FV) \
	X(VertexAttribPointer, VERTEXATTRIBPOINTER) \
	X(Viewport, VIEWPORT)

#define GL_API_MEMBER(name, NAME) PFNGL##NAME##PROC name;
typedef struct gl_api {
	GL_API_ENTRY_POINTS(GL_API_MEMBER)
} gl_api;
#undef GL_API_MEMBER

/* Fills every member through get_proc("glActiveTexture") and so on. Fails
 * with SKP_ERR_IO naming the first entry point get_proc cannot give;
 * *gl is then partly filled and must not be used. */
int gl_api_load(gl_api *gl, void *(*get_proc)(const char *name), skp_error *err);

#endif
