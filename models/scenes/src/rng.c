/* SPDX-License-Identifier: MIT */
/* xoshiro256** seeded by splitmix64; see rng.h for the references. */
#include "rng.h"

/* splitmix64: a Weyl sequence (golden-ratio increment) passed through a
 * 64-bit mixing function. Every seed, including 0, gives a state that is
 * not all zero, which xoshiro requires. */
static uint64_t splitmix64_next(uint64_t *x)
{
    uint64_t z = (*x += UINT64_C(0x9e3779b97f4a7c15));
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

static uint64_t rotate_left(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

void scene_rng_seed(scene_rng *rng, uint64_t seed)
{
    uint64_t x = seed;
    for (int i = 0; i < 4; ++i) {
        rng->state[i] = splitmix64_next(&x);
    }
}

uint64_t scene_rng_next(scene_rng *rng)
{
    uint64_t *s = rng->state;
    const uint64_t result = rotate_left(s[1] * 5, 7) * 9;
    const uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotate_left(s[3], 45);
    return result;
}

double scene_rng_unit(scene_rng *rng)
{
    /* The top 53 bits fill a double's mantissa exactly: the result is
     * k·2^-53 for k uniform in 0 .. 2^53 - 1. */
    return (double)(scene_rng_next(rng) >> 11) * 0x1.0p-53;
}

double scene_rng_uniform(scene_rng *rng, double low, double high) { return low + (high - low) * scene_rng_unit(rng); }
