#include "setup_mesh_format.h"

#include <string.h>
#include <strings.h>

#include "cli_say.h"
#include "file_reader.h"

mesh_format setup_mesh_format(const char *path)
{
	unsigned char head[MESH_FORMAT_HEAD];
	long n = file_reader_head(path, head, sizeof head);
	return n < 0 ? MESH_FMT_EMPTY : mesh_format_sniff(head, (size_t)n);
}

static const char *extension(const char *path)
{
	const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
	return dot && (!slash || dot > slash) ? dot : "";
}

static int has_extension(const char *path, const char *const *list, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (strcasecmp(extension(path), list[i]) == 0)
			return 1;
	return 0;
}

static const char *const interchange_ext[] = {
	".gltf", ".glb", ".fbx", ".dae", ".zae", ".3ds", ".blend", ".x3d", ".ply", ".stl", ".x", ".ms3d", ".b3d",
	".mdl", ".md5mesh", ".smd", ".ogex", ".iqm", ".xml", ".3mf", ".ase", ".lwo", ".ac", ".off", ".nff",
};

int setup_mesh_is_interchange(const char *path)
{
	mesh_format f = setup_mesh_format(path);
	if (mesh_format_is_interchange(f))
		return 1;
	/* an OBJ's statements are common words (NFF's "v" is its viewpoint):
	 * a file named as another format the importer reads is that format */
	return has_extension(path, interchange_ext, sizeof interchange_ext / sizeof interchange_ext[0]);
}

int setup_mesh_format_named(const char *path, mesh_format f)
{
	static const char *const obj[] = { ".obj" }, *const glb[] = { ".glb", ".vrm" },
				 *const gltf[] = { ".gltf" }, *const fbx[] = { ".fbx" },
				 *const dae[] = { ".dae", ".xml" }, *const zip[] = { ".zae", ".zip", ".3mf" },
				 *const blend[] = { ".blend" }, *const x[] = { ".x" };
	switch (f) {
	case MESH_FMT_OBJ: return has_extension(path, obj, 1);
	case MESH_FMT_GLB: return has_extension(path, glb, 2);
	case MESH_FMT_GLTF: return has_extension(path, gltf, 1);
	case MESH_FMT_FBX: return has_extension(path, fbx, 1);
	case MESH_FMT_COLLADA: return has_extension(path, dae, 2);
	case MESH_FMT_ZIP: return has_extension(path, zip, 3);
	case MESH_FMT_BLEND: return has_extension(path, blend, 1);
	case MESH_FMT_X: return has_extension(path, x, 1);
	default: return 1;   /* nothing to say */
	}
}

void setup_mesh_format_note(const char *path, mesh_format f)
{
	if (setup_mesh_format_named(path, f) || !*extension(path))
		return;
	cli_say("%s: the file is %s, whatever its name says ('%s'): read as that\n", path,
		mesh_format_name(f), extension(path));
}

int setup_mesh_check_obj(const char *path)
{
	if (file_reader_head(path, NULL, 0) < 0)
		return 0;
	mesh_format fmt = setup_mesh_format(path);
	if (fmt == MESH_FMT_OBJ)
		return 0;
	cli_warn("%s: the file is %s, not a mesh skintool reads: give an OBJ (v and f lines) or a rigged "
		"glTF 2.0 (.glb, .gltf), FBX or COLLADA (.dae, .zae)%s\n", path, mesh_format_name(fmt),
		fmt == MESH_FMT_JSON ? "; a MakeHuman skeleton (.mhskel) goes with its OBJ as --rig FILE" : "");
	return -1;
}
