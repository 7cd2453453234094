/* gl_api_load fills every member from get_proc and names the first entry
 * point it cannot get. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "gl_api.h"

static int calls;
static const char *missing;

static void dummy(void)
{
}

static void *fake_get_proc(const char *name)
{
	calls++;
	if (strncmp(name, "gl", 2) != 0 || (missing && strcmp(name, missing) == 0))
		return NULL;
	return (void *)dummy;
}

static void test_loads_every_entry_point(void **state)
{
	gl_api gl;
	skp_error err;
	(void)state;
	memset(&gl, 0, sizeof gl);
	calls = 0;
	missing = NULL;
	assert_int_equal(gl_api_load(&gl, fake_get_proc, &err), SKP_OK);
	/* OpenGL ES 2.0 has 142 functions, all function pointers. */
	assert_int_equal(calls, 142);
	assert_int_equal(sizeof gl, 142 * sizeof(void (*)(void)));
	assert_ptr_equal((void *)gl.CreateShader, (void *)dummy);
	assert_ptr_equal((void *)gl.Viewport, (void *)dummy);
}

static void test_names_the_missing_entry_point(void **state)
{
	gl_api gl;
	skp_error err;
	(void)state;
	missing = "glUniformMatrix4fv";
	assert_int_equal(gl_api_load(&gl, fake_get_proc, &err), SKP_ERR_IO);
	assert_non_null(strstr(err.msg, "glUniformMatrix4fv"));
	assert_int_equal(gl_api_load(NULL, fake_get_proc, &err), SKP_ERR_RANGE);
	assert_int_equal(gl_api_load(&gl, NULL, &err), SKP_ERR_RANGE);
	missing = NULL;
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_loads_every_entry_point),
		cmocka_unit_test(test_names_the_missing_entry_point),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
