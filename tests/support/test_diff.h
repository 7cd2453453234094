/* The largest difference between two arrays of kernel results, element by
 * element: float outputs, Q16.16 (fixed-point) and snorm16 ones. */
#ifndef TEST_DIFF_H
#define TEST_DIFF_H

#include <stdint.h>

double test_max_diff(const float *a, const float *b, int n);
long test_max_diff_i32(const int32_t *a, const int32_t *b, int n);
long test_max_diff_i16(const int16_t *a, const int16_t *b, int n);

#endif
