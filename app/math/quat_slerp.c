/* Slerp with its own trigonometry: the angles it needs are in [0, pi/2],
 * where short polynomials (Cephes' single-precision sinf and atanf
 * coefficients) are within an ulp or two, and plain float arithmetic gives
 * the same bits on every board; libm's sinf differs between glibc and
 * newlib in the last bit, which would make a clip sampled on a Cortex-M
 * differ from the host's. */
#include "quat.h"

#include <math.h>

#define PI_2 1.5707963267948966f
#define PI_4 0.78539816339744831f

/* sin x for x in [0, pi/4] */
static float sin_small(float x)
{
	float z = x * x;
	return ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * x + x;
}

/* cos x for x in [0, pi/4] */
static float cos_small(float x)
{
	float z = x * x;
	return ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
	       0.5f * z + 1.0f;
}

/* sin x for x in [0, pi/2] */
static float sin_quadrant(float x)
{
	return x <= PI_4 ? sin_small(x) : cos_small(PI_2 - x);
}

/* atan(y / x) for y, x >= 0, not both 0: in [0, pi/2] */
static float atan_quadrant(float y, float x)
{
	if (y > x)
		return PI_2 - atan_quadrant(x, y);
	float z = y / x, base = 0.0f;
	if (z > 0.41421356237309503f) { /* tan(pi/8): fold onto [-tan(pi/8), tan(pi/8)] */
		z = (z - 1.0f) / (z + 1.0f);
		base = PI_4;
	}
	float zz = z * z;
	return base + (((8.05374449538e-2f * zz - 1.38776856032e-1f) * zz + 1.99777106478e-1f) * zz -
		       3.33329491539e-1f) * zz * z + z;
}

quat quat_slerp(quat a, quat b, float t)
{
	if (quat_dot(a, b) < 0.0f)
		b = (quat){ -b.w, -b.x, -b.y, -b.z };
	/* the angle between them from |a - b| and |a + b|: accurate for
	 * neighbouring frames, where acos(a.b) loses half its bits */
	quat d = { a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z };
	quat s = { a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z };
	float theta = 2.0f * atan_quadrant(sqrtf(quat_dot(d, d)), sqrtf(quat_dot(s, s)));
	float wa = 1.0f - t, wb = t;
	if (theta > 1e-3f) {
		float inv = 1.0f / sin_quadrant(theta);
		wa = sin_quadrant((1.0f - t) * theta) * inv;
		wb = sin_quadrant(t * theta) * inv;
	}
	quat r = { wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z };
	return quat_normalize(r);
}
