/* SPDX-License-Identifier: MIT */
/** @file
 * A motor pool (after Robert McIntyre, "Simulated Muscles", aurellem):
 * the motor neurons of one
 * muscle, each with a strength, recruited weakest first as Henneman's size
 * principle orders them (Henneman, Somjen & Carpenter 1965, J Neurophysiol
 * 28: small motor units are recruited before large ones).
 *
 * Recruiting n neurons (0 .. count) gives the exertion
 *
 *   e(n) = (s_0 + … + s_{n-1}) / (s_0 + … + s_{count-1}),
 *
 * so e(0) = 0 and e(count) = 1. McIntyre's code summed the first n + 1
 * strengths, so that recruiting nothing still exerted the weakest
 * neuron's share; that off-by-one is not kept. The exertion drives a Hill
 * muscle's activation or a torque actuator's share of its peak torque.
 *
 * The strengths come from an array, a profile image, a CSV file or a
 * generated exponential profile; a model file names any of the last three
 * (docs/model-format.md). The order given is the recruitment order.
 */
#ifndef MU_MOTOR_POOL_H
#define MU_MOTOR_POOL_H

#include "mu/export.h"
#include "mu/muscle.h"
#include "mu/torque_actuator.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_motor_pool mu_motor_pool;

/** At most this many neurons (a human muscle has tens to a few thousand). */
#define MU_MAX_MOTOR_NEURONS 100000

/** A pool of `count` (1 .. MU_MAX_MOTOR_NEURONS) neurons of the given
 * strengths (arbitrary units, each finite and >= 0, their sum > 0), copied.
 * Nothing is recruited at first. */
MU_API rb_status mu_motor_pool_create(const double *strengths, int count, mu_motor_pool **out);

/** `count` neurons whose strengths rise exponentially from `weakest` to
 * `strongest` (0 < weakest <= strongest, finite):
 * s_i = weakest·(strongest/weakest)^(i/(count - 1)), a single neuron
 * having `weakest`. The built-in worm model: 200 neurons from 1 to 100,
 * whose first 30 % give about 3 % of the force. */
MU_API rb_status mu_motor_pool_create_exponential(int count, double weakest, double strongest, mu_motor_pool **out);

/** McIntyre's profile image: a PNG exactly 1 pixel high, one neuron per
 * pixel from left to right, strength = 255 − blue: white (255, 255, 255)
 * is 0, red (255, 0, 0) and dark red (139, 0, 0) are 255.
 *
 * - The colours between white, red and black, red >= green = blue, are
 *   the scale; any other pixel (a blue, a green, a yellow) is refused,
 *   naming it: its strength would not show in its colour. A grey is on
 *   the scale (red = green = blue), black the strongest.
 * - RGB and RGBA images of 8 or 16 bits a sample, palette images (their
 *   colours) and grey images (each grey g as (g, g, g)) are read; a
 *   16-bit sample b counts as b/257 on the 8-bit scale, so a 16-bit image
 *   gives strengths between the 8-bit steps.
 * - Every pixel must be opaque: a pixel whose alpha is below full (an
 *   alpha channel or a transparent palette entry) is refused, as its
 *   colour depends on what lies behind it.
 *
 * Read with libpng. Errors name the file and say what is wrong: cannot
 * open, not a PNG (no PNG signature), damaged (libpng's complaint), not 1
 * pixel high, wider than MU_MAX_MOTOR_NEURONS, a pixel off the scale or
 * translucent (with its position and colour), all white. */
MU_API rb_status mu_motor_pool_load_png(const char *path, mu_motor_pool **out);

/** Strengths as numbers separated by commas, spaces, tabs or line breaks,
 * in recruitment order; `#` starts a comment to the end of its line.
 * Errors name the file and the line. */
MU_API rb_status mu_motor_pool_load_csv(const char *path, mu_motor_pool **out);

/** Accepts NULL. */
MU_API void mu_motor_pool_destroy(mu_motor_pool *pool);

/** The pool's size; 0, with the error recorded, for NULL. */
MU_API int mu_motor_pool_neuron_count(const mu_motor_pool *pool);
/** The strength of neuron `index`; NaN (and an error) for a bad index. */
MU_API double mu_motor_pool_strength(const mu_motor_pool *pool, int index);
/** The sum of every strength, > 0. NaN (and an error) for NULL. */
MU_API double mu_motor_pool_total_strength(const mu_motor_pool *pool);

/** Recruits the first n neurons, n in 0 .. count. Unlike McIntyre's code,
 * which clamps it, an n outside the pool is refused
 * (RB_ERR_INVALID_ARGUMENT) and recruits nothing: a count that cannot be
 * recruited is a mistake to report, not a request for the whole pool. */
MU_API rb_status mu_motor_pool_recruit(mu_motor_pool *pool, int n);
/** Recruits `delta` more neurons (fewer when negative), clamped to
 * 0 .. count: ±1 for one neuron, ±20 for the worm's keys. */
MU_API rb_status mu_motor_pool_recruit_more(mu_motor_pool *pool, int delta);
/** How many neurons are recruited, 0 .. count; -1 (and an error) for NULL. */
MU_API int mu_motor_pool_recruited(const mu_motor_pool *pool);
/** e(recruited), in [0, 1]; NaN (and an error) for NULL. */
MU_API double mu_motor_pool_exertion(const mu_motor_pool *pool);
/** e(n) for n clamped to 0 .. count, without recruiting; NaN (and an
 * error) for NULL. */
MU_API double mu_motor_pool_exertion_at(const mu_motor_pool *pool, int n);

/** Sets the muscle's activation (mu_muscle_set_activation) to the exertion. */
MU_API rb_status mu_motor_pool_drive_muscle(const mu_motor_pool *pool, mu_muscle *muscle);
/** Sets the actuator's exertion (mu_torque_actuator_set_exertion) to it. */
MU_API rb_status mu_motor_pool_drive_torque(const mu_motor_pool *pool, mu_torque_actuator *actuator);

#ifdef __cplusplus
}
#endif

#endif
