#include "gl_api.h"

#include <stddef.h>

int gl_api_load(gl_api *gl, void *(*get_proc)(const char *name), skp_error *err)
{
	if (!gl || !get_proc)
		return skp_fail(err, SKP_ERR_RANGE, 0, "gl_api_load: no table or no get_proc");
	/* void * to function pointer is what dlsym-style loaders return: POSIX
	 * guarantees it round-trips. */
#define GL_API_LOAD(name, NAME) \
	gl->name = (PFNGL##NAME##PROC)get_proc("gl" #name); \
	if (!gl->name) \
		return skp_fail(err, SKP_ERR_IO, 0, "OpenGL ES 2.0 entry point gl%s is missing", #name);
	GL_API_ENTRY_POINTS(GL_API_LOAD)
#undef GL_API_LOAD
	return SKP_OK;
}
