/* SPDX-License-Identifier: MIT */
/* The built-in worm's profile image, models/worm-pool.png, as a formula:
 * the worm's former generated pool (200 neurons rising exponentially from
 * 1 to 100, the worm of McIntyre's "Simulated Muscles") drawn on the white-to-red scale in 16-bit
 * samples. Neuron i's strength s_i = 100^(i/199) is drawn as 2.55·s_i on
 * the scale (255 − blue, so the strongest is 255): blue = green =
 * round(257·(255 − 2.55·s_i)); red fades from white's 65535 to dark red's
 * 139·257 as the strength grows, which keeps red >= green. The tests
 * write the image from it (SINEW_WRITE_WORM_POOL) and check the shipped
 * file against it.
 */
#ifndef TESTS_WORM_POOL_IMAGE_H
#define TESTS_WORM_POOL_IMAGE_H

#include <math.h>

#define WORM_POOL_NEURONS 200
#define WORM_POOL_WEAKEST 1.0
#define WORM_POOL_STRONGEST 100.0

/* s_i of the worm's generated pool (mu_motor_pool_create_exponential). */
static inline double worm_pool_exponential(int i)
{
    return WORM_POOL_WEAKEST *
           pow(WORM_POOL_STRONGEST / WORM_POOL_WEAKEST, (double)i / (double)(WORM_POOL_NEURONS - 1));
}

/* Neuron i's 16-bit red and blue (= green) samples. */
static inline void worm_pool_pixel(int i, unsigned *red, unsigned *blue)
{
    const double share = worm_pool_exponential(i) / WORM_POOL_STRONGEST; /* 0.01 .. 1 */
    *blue = (unsigned)lround(257.0 * (255.0 - 255.0 * share));
    *red = (unsigned)lround(65535.0 - (65535.0 - 139.0 * 257.0) * share);
}

/* The strength the image gives neuron i: 255 − blue/257. */
static inline double worm_pool_image_strength(int i)
{
    unsigned red, blue;
    worm_pool_pixel(i, &red, &blue);
    return 255.0 - (double)blue * 255.0 / 65535.0;
}

#endif
