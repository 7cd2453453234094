#include "skin_compact.h"

#include "skin_kernels.h"

size_t skin_compact_bytes(int count)
{
	return SKIN_COMPACT_BYTES(count);
}

void skin_compact_attach(skin_compact *c, void *mem, int count)
{
	char *at = mem;
	size_t n = SKIN_SOA_PADDED(count);
	c->count = count;
	c->padded = (int)n;
	c->qx = skin_carve(&at, n * 2); c->qy = skin_carve(&at, n * 2); c->qz = skin_carve(&at, n * 2);
	c->ox = skin_carve(&at, n * 2); c->oy = skin_carve(&at, n * 2);
	for (int k = 0; k < SKP_MAX_INFLUENCES - 1; k++)
		c->weight[k] = skin_carve(&at, n * 2);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		c->bone[k] = skin_carve(&at, n);
}

void skin_quant_bounds(const float *values, int count, int stride, float *origin, float *step)
{
	float lo = count ? values[0] : 0.0f, hi = lo;
	for (int i = 1; i < count; i++) {
		lo = fminf(lo, values[(size_t)i * (size_t)stride]);
		hi = fmaxf(hi, values[(size_t)i * (size_t)stride]);
	}
	*origin = lo;
	*step = (hi - lo) / 65535.0f;
}

uint16_t skin_quantise(float x, float origin, float step)
{
	if (!(step > 0.0f))
		return 0;
	float q = roundf((x - origin) / step);
	return (uint16_t)(q < 0.0f ? 0.0f : q > 65535.0f ? 65535.0f : q);
}

static int16_t snorm16(float x)
{
	float q = roundf(x * SKIN_COMPACT_NORMAL_ONE);
	return (int16_t)(q < -32767.0f ? -32767.0f : q > 32767.0f ? 32767.0f : q);
}

static float angle_error(vec3 n, int16_t ox, int16_t oy)
{
	return vec3_length(vec3_sub(vec3_normalize(skin_oct_decode(ox, oy)), n));
}

/* The octahedral pair nearest n: the projection, rounded each of the four
 * ways, keeping the best (about twice as precise as rounding alone). */
void skin_oct_encode(vec3 n, int16_t *ox, int16_t *oy)
{
	float l1 = fabsf(n.x) + fabsf(n.y) + fabsf(n.z);
	float x = l1 > 0.0f ? n.x / l1 : 0.0f, y = l1 > 0.0f ? n.y / l1 : 1.0f;
	if (n.z < 0.0f) {
		float fx = (1.0f - fabsf(y)) * (x >= 0.0f ? 1.0f : -1.0f);
		float fy = (1.0f - fabsf(x)) * (y >= 0.0f ? 1.0f : -1.0f);
		x = fx;
		y = fy;
	}
	float bx = floorf(x * SKIN_COMPACT_NORMAL_ONE), by = floorf(y * SKIN_COMPACT_NORMAL_ONE), best = INFINITY;
	for (int i = 0; i < 4; i++) {
		int16_t cx = snorm16((bx + (float)(i & 1)) / SKIN_COMPACT_NORMAL_ONE);
		int16_t cy = snorm16((by + (float)(i >> 1)) / SKIN_COMPACT_NORMAL_ONE);
		float e = angle_error(n, cx, cy);
		if (e < best) {
			best = e;
			*ox = cx;
			*oy = cy;
		}
	}
}

/* Influences 1.. rounded to 1/65535; the pivot takes the rest, so the
 * weights sum to exactly 1 (it is the largest, so the rest is positive). */
static void load_influences(skin_compact *c, const skin_soa *s, int v)
{
	unsigned rest = SKIN_COMPACT_WEIGHT_ONE;
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		unsigned w = (unsigned)lroundf(s->weight[k][v] * (float)SKIN_COMPACT_WEIGHT_ONE);
		w = w > rest ? rest : w;
		c->weight[k - 1][v] = (uint16_t)w;
		rest -= w;
	}
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		c->bone[k][v] = (uint8_t)s->bone[k][v];
}

void skin_compact_load(skin_compact *c, const skin_soa *s)
{
	const float *const axis[3] = { s->px, s->py, s->pz };
	for (int i = 0; i < 3; i++)
		skin_quant_bounds(axis[i], c->count, 1, &c->origin[i], &c->step[i]);
	for (int v = 0; v < c->padded; v++) {
		c->qx[v] = skin_quantise(s->px[v], c->origin[0], c->step[0]);
		c->qy[v] = skin_quantise(s->py[v], c->origin[1], c->step[1]);
		c->qz[v] = skin_quantise(s->pz[v], c->origin[2], c->step[2]);
		skin_oct_encode(vec3_make(s->nx[v], s->ny[v], s->nz[v]), &c->ox[v], &c->oy[v]);
		load_influences(c, s, v);
	}
}

float skin_compact_position_bound(const skin_compact *c)
{
	return 0.5f * sqrtf(c->step[0] * c->step[0] + c->step[1] * c->step[1] + c->step[2] * c->step[2]);
}
