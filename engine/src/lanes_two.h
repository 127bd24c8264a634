// SPDX-License-Identifier: MIT
/* Two values side by side in SSE2's 2 × double registers (part of every
 * x86-64 processor): lane 0 holds the first's, lane 1 the second's. Each
 * operation is one instruction on both lanes and rounds each lane exactly
 * as the scalar operation would (the build contracts no product into a
 * fused multiply-add, -ffp-contract=off), so code written with these in a
 * scalar reference's order of sums and products gives that reference's
 * doubles, lane by lane: two contacts (contact_lanes_two.h) or two pins
 * (pin_rows_two.c) at once. Include only where __SSE2__ is defined. */
#ifndef SINEW_LANES_TWO_H
#define SINEW_LANES_TWO_H

#include <emmintrin.h>
#include <stdbool.h>

typedef __m128d lanes;

static inline lanes pair(double first, double second) { return _mm_set_pd(second, first); }
static inline lanes both(double value) { return _mm_set1_pd(value); }
static inline lanes add(lanes a, lanes b) { return _mm_add_pd(a, b); }
static inline lanes sub(lanes a, lanes b) { return _mm_sub_pd(a, b); }
static inline lanes mul(lanes a, lanes b) { return _mm_mul_pd(a, b); }
static inline lanes divide(lanes a, lanes b) { return _mm_div_pd(a, b); }
static inline lanes negate(lanes a) { return _mm_xor_pd(a, _mm_set1_pd(-0.0)); }
/* a > b ? a : b and a < b ? a : b in each lane, as rb_max and rb_min. */
static inline lanes max(lanes a, lanes b) { return _mm_max_pd(a, b); }
static inline lanes min(lanes a, lanes b) { return _mm_min_pd(a, b); }
/* In each lane, `yes` where the mask is all ones, `no` where it is zero. */
static inline lanes select(lanes mask, lanes yes, lanes no)
{
    return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}
static inline lanes mask_of(bool first, bool second)
{
    return _mm_castsi128_pd(_mm_set_epi64x(second ? -1 : 0, first ? -1 : 0));
}
/* Lane 0 into *first and lane 1 into *second. */
static inline void store_pair(double *first, double *second, lanes a)
{
    _mm_storel_pd(first, a);
    _mm_storeh_pd(second, a);
}
static inline double first_of(lanes a) { return _mm_cvtsd_f64(a); }
static inline double second_of(lanes a) { return _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)); }

#endif
