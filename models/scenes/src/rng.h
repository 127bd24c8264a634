/* SPDX-License-Identifier: MIT */
/* A small deterministic random number generator for the scenes.
 *
 * xoshiro256** (Blackman and Vigna, "Scrambled linear pseudorandom number
 * generators", ACM TOMS 47(4), 2021) with its state filled by splitmix64
 * (Steele, Lea and Flood, "Fast splittable pseudorandom number
 * generators", OOPSLA 2014), the seeding the xoshiro authors recommend.
 * The sequence depends only on the seed, never on the platform or the C
 * library, so a scene built with the same seed is bit-identical
 * everywhere.
 */
#ifndef SCENES_RNG_H
#define SCENES_RNG_H

#include <stdint.h>

typedef struct scene_rng {
    uint64_t state[4]; /* never all zero */
} scene_rng;

/* Any seed is valid, zero included. */
void scene_rng_seed(scene_rng *rng, uint64_t seed);

/* The next 64 random bits. */
uint64_t scene_rng_next(scene_rng *rng);

/* A double uniform in [0, 1), a multiple of 2^-53. */
double scene_rng_unit(scene_rng *rng);

/* A double uniform in [low, high), low <= high. */
double scene_rng_uniform(scene_rng *rng, double low, double high);

#endif
