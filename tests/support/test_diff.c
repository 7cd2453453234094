#include "test_diff.h"

#include <math.h>
#include <stdlib.h>

double test_max_diff(const float *a, const float *b, int n)
{
	double d = 0;
	for (int i = 0; i < n; i++)
		d = fmax(d, fabs((double)a[i] - b[i]));
	return d;
}

static long element(const void *p, int i, int bytes)
{
	return bytes == 2 ? ((const int16_t *)p)[i] : ((const int32_t *)p)[i];
}

/* over int16 (bytes 2) or int32 elements */
static long max_diff_int(const void *a, const void *b, int n, int bytes)
{
	long d = 0;
	for (int i = 0; i < n; i++) {
		long e = labs(element(a, i, bytes) - element(b, i, bytes));
		d = e > d ? e : d;
	}
	return d;
}

long test_max_diff_i32(const int32_t *a, const int32_t *b, int n)
{
	return max_diff_int(a, b, n, 4);
}

long test_max_diff_i16(const int16_t *a, const int16_t *b, int n)
{
	return max_diff_int(a, b, n, 2);
}
