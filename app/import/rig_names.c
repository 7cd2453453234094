#include "rig_names.h"

#include <ctype.h>
#include <string.h>

enum {
	RIGIFY = 1, MIXAMO = 2, MAKEHUMAN = 4, UNREAL = 8, DAZ = 16, CMU = 32, UNITY = 64, BIPED = 128,
	JOINTS = 256, FAMILY_COUNT = 10
};

static const char *const family_names[FAMILY_COUNT] = {
	"Rigify (Blender metarig)", "Mixamo", "MakeHuman default", "Unreal", "Daz", "CMU", "Unity/Mecanim humanoid",
	"3ds Max Biped", "joint names (hip, knee, ankle)", "none: the skeleton's shape",
};

/* Base names without separators: "upper_arm" and "UpperArm" both read upperarm. */
static const struct {
	const char *base;
	rig_slot slot;
	int families;
} table[] = {
	{ "head", RIG_HEAD, RIGIFY | MIXAMO | MAKEHUMAN | UNREAL | DAZ | CMU },
	{ "shoulder", RIG_CLAVICLE, RIGIFY | MIXAMO | UNITY },
	{ "clavicle", RIG_CLAVICLE, MAKEHUMAN | UNREAL | CMU | BIPED },
	{ "collar", RIG_CLAVICLE, DAZ },
	{ "upperarm", RIG_UPPER_ARM, RIGIFY | UNREAL | UNITY | BIPED },
	{ "arm", RIG_UPPER_ARM, MIXAMO },
	{ "upperarm01", RIG_UPPER_ARM, MAKEHUMAN },
	{ "shldr", RIG_UPPER_ARM, DAZ },
	{ "shldrbend", RIG_UPPER_ARM, DAZ },
	{ "humerus", RIG_UPPER_ARM, CMU },
	{ "forearm", RIG_FOREARM, RIGIFY | MIXAMO | DAZ | BIPED },
	{ "elbow", RIG_FOREARM, JOINTS },
	{ "forearmbend", RIG_FOREARM, DAZ },
	{ "lowerarm", RIG_FOREARM, UNREAL | UNITY },
	{ "lowerarm01", RIG_FOREARM, MAKEHUMAN },
	{ "radius", RIG_FOREARM, CMU },
	{ "hand", RIG_HAND, RIGIFY | MIXAMO | UNREAL | DAZ | CMU | UNITY | BIPED },
	{ "wrist", RIG_HAND, MAKEHUMAN | CMU | JOINTS },
	{ "thigh", RIG_THIGH, RIGIFY | UNREAL | DAZ | BIPED },
	{ "upperleg", RIG_THIGH, UNITY },
	{ "hip", RIG_THIGH, JOINTS },
	{ "thighbend", RIG_THIGH, DAZ },
	{ "upleg", RIG_THIGH, MIXAMO },
	{ "upperleg01", RIG_THIGH, MAKEHUMAN },
	{ "femur", RIG_THIGH, CMU },
	{ "shin", RIG_SHIN, RIGIFY | DAZ },
	{ "leg", RIG_SHIN, MIXAMO },
	{ "calf", RIG_SHIN, UNREAL | BIPED },
	{ "lowerleg", RIG_SHIN, UNITY },
	{ "knee", RIG_SHIN, JOINTS },
	{ "lowerleg01", RIG_SHIN, MAKEHUMAN },
	{ "tibia", RIG_SHIN, CMU },
	{ "foot", RIG_FOOT, RIGIFY | MIXAMO | MAKEHUMAN | UNREAL | DAZ | CMU | UNITY | BIPED },
	{ "ankle", RIG_FOOT, JOINTS },
	{ "toe", RIG_TOE, RIGIFY | DAZ | JOINTS },
	{ "toe0", RIG_TOE, BIPED },
	{ "toebase", RIG_TOE, MIXAMO },
	{ "ball", RIG_TOE, UNREAL },
	{ "toes", RIG_TOE, CMU | UNITY },
	/* each toe and finger that has joints of its own: all map to the one
	 * bone a mocap skeleton has (CMU's ltoes, lfingers); the thumb stays
	 * with the hand (CMU's lthumb turns tens of degrees on its own in a
	 * clip: mapped, MakeHuman's thumb swung 13% of the height away) */
	{ "toe11", RIG_TOE, MAKEHUMAN }, { "toe21", RIG_TOE, MAKEHUMAN }, { "toe31", RIG_TOE, MAKEHUMAN },
	{ "toe41", RIG_TOE, MAKEHUMAN }, { "toe51", RIG_TOE, MAKEHUMAN },
	{ "fingers", RIG_FINGERS, CMU },
	{ "fingerbase", RIG_FINGERS, CMU },
	{ "finger21", RIG_FINGERS, MAKEHUMAN }, { "finger31", RIG_FINGERS, MAKEHUMAN },
	{ "finger41", RIG_FINGERS, MAKEHUMAN }, { "finger51", RIG_FINGERS, MAKEHUMAN },
	{ "findex01", RIG_FINGERS, RIGIFY }, { "fmiddle01", RIG_FINGERS, RIGIFY },
	{ "fring01", RIG_FINGERS, RIGIFY }, { "fpinky01", RIG_FINGERS, RIGIFY },
	{ "handindex1", RIG_FINGERS, MIXAMO }, { "handmiddle1", RIG_FINGERS, MIXAMO },
	{ "handring1", RIG_FINGERS, MIXAMO }, { "handpinky1", RIG_FINGERS, MIXAMO },
	{ "index01", RIG_FINGERS, UNREAL }, { "middle01", RIG_FINGERS, UNREAL },
	{ "ring01", RIG_FINGERS, UNREAL }, { "pinky01", RIG_FINGERS, UNREAL },
	{ "index1", RIG_FINGERS, DAZ }, { "mid1", RIG_FINGERS, DAZ },
	{ "ring1", RIG_FINGERS, DAZ }, { "pinky1", RIG_FINGERS, DAZ },
	{ "indexproximal", RIG_FINGERS, UNITY }, { "middleproximal", RIG_FINGERS, UNITY },
	{ "ringproximal", RIG_FINGERS, UNITY }, { "littleproximal", RIG_FINGERS, UNITY },
	{ "finger1", RIG_FINGERS, BIPED }, { "finger2", RIG_FINGERS, BIPED },
	{ "finger3", RIG_FINGERS, BIPED }, { "finger4", RIG_FINGERS, BIPED },
};

#define NAME_MAX_LEN 128

/* Lower case, without a namespace (mixamorig:, Armature|) or a rig prefix
 * (DEF-, ORG-, Bip01, B_, CC_Base_). */
static void normalise(const char *name, char *out)
{
	const char *s = name;
	for (const char *c = name; *c; c++)
		if (*c == ':' || *c == '|')
			s = c + 1;
	size_t n = 0;
	for (; n < NAME_MAX_LEN - 1 && s[n]; n++)
		out[n] = (char)tolower((unsigned char)s[n]);
	out[n] = '\0';
	static const char *const prefixes[] = { "def-", "def_", "org-", "mch-", "bip001 ", "bip01 ", "bip001_", "bip01_",
						"cc_base_", "b_", "jnt_", "bn_" };
	for (size_t p = 0; p < sizeof prefixes / sizeof prefixes[0]; p++) {
		size_t k = strlen(prefixes[p]);
		if (strncmp(out, prefixes[p], k) == 0)
			memmove(out, out + k, strlen(out + k) + 1);
	}
}

static int is_sep(char c)
{
	return c == '.' || c == '_' || c == '-' || c == ' ';
}

static void squeeze(const char *in, size_t len, char *out)
{
	size_t n = 0;
	for (size_t i = 0; i < len; i++)
		if (!is_sep(in[i]))
			out[n++] = in[i];
	out[n] = '\0';
}

static int lookup(const char *base)
{
	for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
		if (strcmp(table[i].base, base) == 0)
			return (int)i;
	return -1;
}

/* Splits s into a side and a squeezed base; *side RIG_CENTRE when none. */
static void split_side(const char *s, rig_side *side, char *base)
{
	static const char *const words[2] = { "left", "right" };
	size_t n = strlen(s);
	for (int k = 0; k < 2; k++) {
		size_t w = strlen(words[k]);
		rig_side sd = k ? RIG_RIGHT : RIG_LEFT;
		/* suffix: .L _l -left */
		if (n > 2 && is_sep(s[n - 2]) && s[n - 1] == words[k][0]) {
			*side = sd;
			squeeze(s, n - 2, base);
			return;
		}
		if (n > w + 1 && is_sep(s[n - w - 1]) && strcmp(s + n - w, words[k]) == 0) {
			*side = sd;
			squeeze(s, n - w - 1, base);
			return;
		}
		/* prefix: Left, l_ */
		if (strncmp(s, words[k], w) == 0 && n > w) {
			*side = sd;
			squeeze(s + w, n - w, base);
			return;
		}
		if (n > 2 && s[0] == words[k][0] && is_sep(s[1])) {
			*side = sd;
			squeeze(s + 2, n - 2, base);
			return;
		}
	}
	squeeze(s, n, base);
	*side = RIG_CENTRE;
	/* a bare l or r before a known name: lhumerus, rShin */
	if ((base[0] == 'l' || base[0] == 'r') && lookup(base) < 0 && lookup(base + 1) >= 0) {
		*side = base[0] == 'l' ? RIG_LEFT : RIG_RIGHT;
		memmove(base, base + 1, strlen(base));
	}
}

rig_side rig_name_side(const char *name)
{
	char s[NAME_MAX_LEN], base[NAME_MAX_LEN];
	rig_side side;
	normalise(name, s);
	split_side(s, &side, base);
	return side;
}

rig_slot rig_name_parse(const char *name, rig_name *out)
{
	char s[NAME_MAX_LEN], base[NAME_MAX_LEN];
	normalise(name, s);
	memset(out, 0, sizeof *out);
	split_side(s, &out->side, base);
	int i = lookup(base);
	if (i < 0)
		return RIG_NONE;
	/* limbs come in pairs: a limb name without a side is not one of them */
	if ((table[i].slot == RIG_HEAD) != (out->side == RIG_CENTRE))
		return RIG_NONE;
	out->slot = table[i].slot;
	out->rig = table[i].families;
	return out->slot;
}

const char *rig_family_name(int rig)
{
	for (int k = 0; k < FAMILY_COUNT; k++)
		if (rig & (1 << k))
			return family_names[k];
	return "none";
}

const char *rig_slot_name(rig_slot slot)
{
	static const char *const names[RIG_SLOT_COUNT] = {
		"-", "head", "clavicle", "upper arm", "forearm", "hand", "thigh", "shin", "foot", "toe", "fingers"
	};
	return slot < RIG_SLOT_COUNT ? names[slot] : "-";
}
