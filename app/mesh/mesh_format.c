#include "mesh_format.h"

#include <string.h>

static int starts(const unsigned char *h, size_t n, const char *sig)
{
	size_t k = strlen(sig);
	return n >= k && memcmp(h, sig, k) == 0;
}

/* Binary signatures at the very start. */
static mesh_format by_signature(const unsigned char *h, size_t n)
{
	static const struct {
		const char *sig;
		mesh_format f;
	} sigs[] = {
		{ "glTF", MESH_FMT_GLB },
		{ "PK\x03\x04", MESH_FMT_ZIP },
		{ "PK\x05\x06", MESH_FMT_ZIP },
		{ "BLENDER", MESH_FMT_BLEND },
		{ "Kaydara FBX Binary", MESH_FMT_FBX },
		{ "xof ", MESH_FMT_X },
		{ "ply\n", MESH_FMT_PLY },
		{ "ply\r", MESH_FMT_PLY },
		{ "MS3D000000", MESH_FMT_OTHER_MODEL },
		{ "INTERQUAKEMODEL", MESH_FMT_OTHER_MODEL },
		{ "BB3D", MESH_FMT_OTHER_MODEL },
		{ "IDP2", MESH_FMT_OTHER_MODEL },
		{ "IDP3", MESH_FMT_OTHER_MODEL },
	};
	for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++)
		if (starts(h, n, sigs[i].sig))
			return sigs[i].f;
	return MESH_FMT_COUNT;
}

/* No NUL and no control character but the usual white space: text (any
 * bytes from 0x80 up pass: UTF-8 and Latin-1 names). */
static int is_text(const unsigned char *h, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (h[i] < 0x20 && h[i] != '\t' && h[i] != '\n' && h[i] != '\r' && h[i] != '\f' && h[i] != '\v')
			return 0;
	return 1;
}

static int has(const unsigned char *h, size_t n, const char *needle)
{
	size_t k = strlen(needle);
	for (size_t i = 0; i + k <= n; i++)
		if (memcmp(h + i, needle, k) == 0)
			return 1;
	return 0;
}

static int is_space(unsigned char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

/* The first word of the first line that is neither blank nor a # comment
 * into word (NUL-terminated, at most cap - 1 bytes); 0 when there is none. */
static int first_statement(const unsigned char *h, size_t n, char *word, size_t cap)
{
	size_t i = 0;
	while (i < n) {
		while (i < n && is_space(h[i]))
			i++;
		if (i < n && h[i] == '#') {
			while (i < n && h[i] != '\n')
				i++;
			continue;
		}
		size_t k = 0;
		while (i < n && !is_space(h[i]) && k + 1 < cap)
			word[k++] = (char)h[i++];
		word[k] = '\0';
		return k > 0;
	}
	return 0;
}

static int is_obj_statement(const char *w)
{
	static const char *const kw[] = { "v", "vn", "vt", "vp", "f", "l", "p", "o", "g", "s",
					  "mtllib", "usemtl", "cstype", "deg", "curv", "surf" };
	for (size_t i = 0; i < sizeof kw / sizeof kw[0]; i++)
		if (strcmp(w, kw[i]) == 0)
			return 1;
	return 0;
}

static mesh_format by_text(const unsigned char *h, size_t n)
{
	if (starts(h, n, "\xef\xbb\xbf"))
		h += 3, n -= 3;
	if (starts(h, n, "; FBX"))
		return MESH_FMT_FBX;
	while (n && is_space(*h))
		h++, n--;
	if (starts(h, n, "<"))
		return has(h, n, "<COLLADA") ? MESH_FMT_COLLADA : MESH_FMT_XML;
	if (starts(h, n, "{"))
		return has(h, n, "\"asset\"") || has(h, n, "\"accessors\"") || has(h, n, "\"bufferViews\"")
		       ? MESH_FMT_GLTF : MESH_FMT_JSON;
	if (starts(h, n, "solid ") || starts(h, n, "solid\n") || starts(h, n, "solid\r"))
		return MESH_FMT_STL;
	if (starts(h, n, "MD5Version") || starts(h, n, "version 1"))
		return MESH_FMT_OTHER_MODEL;
	char word[16];
	if (!first_statement(h, n, word, sizeof word) || is_obj_statement(word))
		return MESH_FMT_OBJ;   /* comments only: an OBJ as far as can be seen */
	return MESH_FMT_UNKNOWN_TEXT;
}

mesh_format mesh_format_sniff(const unsigned char *head, size_t n)
{
	if (n == 0)
		return MESH_FMT_EMPTY;
	mesh_format f = by_signature(head, n);
	if (f != MESH_FMT_COUNT)
		return f;
	return is_text(head, n) ? by_text(head, n) : MESH_FMT_UNKNOWN_BINARY;
}

const char *mesh_format_name(mesh_format f)
{
	static const char *const names[MESH_FMT_COUNT] = {
		[MESH_FMT_UNKNOWN_BINARY] = "binary data of no format skintool knows",
		[MESH_FMT_UNKNOWN_TEXT] = "text of no format skintool knows",
		[MESH_FMT_EMPTY] = "an empty file",
		[MESH_FMT_OBJ] = "a Wavefront OBJ",
		[MESH_FMT_GLB] = "a binary glTF (.glb)",
		[MESH_FMT_GLTF] = "a glTF JSON file (.gltf)",
		[MESH_FMT_JSON] = "a JSON file that is not glTF",
		[MESH_FMT_FBX] = "an FBX file",
		[MESH_FMT_COLLADA] = "a COLLADA file (.dae)",
		[MESH_FMT_XML] = "an XML file that is not COLLADA",
		[MESH_FMT_ZIP] = "a zip archive",
		[MESH_FMT_BLEND] = "a Blender file (.blend)",
		[MESH_FMT_X] = "a DirectX file (.x)",
		[MESH_FMT_PLY] = "a PLY file",
		[MESH_FMT_STL] = "an ASCII STL file",
		[MESH_FMT_OTHER_MODEL] = "a model file (MS3D, IQM, B3D, MD2/MD3, MD5, SMD)",
	};
	return f < MESH_FMT_COUNT ? names[f] : "?";
}

int mesh_format_is_interchange(mesh_format f)
{
	return f != MESH_FMT_OBJ && f != MESH_FMT_EMPTY && f != MESH_FMT_UNKNOWN_TEXT &&
	       f != MESH_FMT_UNKNOWN_BINARY && f != MESH_FMT_JSON && f < MESH_FMT_COUNT;
}

const char *mesh_format_extension(mesh_format f)
{
	static const char *const ext[MESH_FMT_COUNT] = {
		[MESH_FMT_OBJ] = "obj", [MESH_FMT_GLB] = "glb", [MESH_FMT_GLTF] = "gltf", [MESH_FMT_FBX] = "fbx",
		[MESH_FMT_COLLADA] = "dae", [MESH_FMT_ZIP] = "zae", [MESH_FMT_BLEND] = "blend", [MESH_FMT_X] = "x",
		[MESH_FMT_PLY] = "ply", [MESH_FMT_STL] = "stl",
	};
	return f < MESH_FMT_COUNT ? ext[f] : NULL;
}
