#include "modes.h"

#include <string.h>

static const char *const algo_names[] = { "lbs", "dqbs", "dqbs-fixed", "compare" };
static const char *const view_names[] = { "body", "skeleton", "weights", "difference" };

_Static_assert(sizeof algo_names / sizeof algo_names[0] == SKIN_SHOW_COUNT, "a name per skin_algo");
_Static_assert(sizeof view_names / sizeof view_names[0] == RENDER_VIEW_COUNT, "a name per render_view");

static int find(const char *const *names, int n, const char *name)
{
	for (int i = 0; name && i < n; i++)
		if (strcmp(name, names[i]) == 0)
			return i;
	return -1;
}

const char *skin_algo_name(int a)
{
	return a >= 0 && a < SKIN_SHOW_COUNT ? algo_names[a] : "?";
}

int skin_algo_parse(const char *name)
{
	return find(algo_names, SKIN_SHOW_COUNT, name);
}

const char *render_view_name(int v)
{
	return v >= 0 && v < RENDER_VIEW_COUNT ? view_names[v] : "?";
}

int render_view_parse(const char *name)
{
	return find(view_names, RENDER_VIEW_COUNT, name);
}
