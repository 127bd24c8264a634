/* SPDX-License-Identifier: MIT */
/* Islands and sleeping: bodies that rest together stop being simulated
 * together, and wake together.
 */
#ifndef RB_SLEEP_H
#define RB_SLEEP_H

#include "world_internal.h"

/* A body slower than both tolerances for RB_TIME_TO_SLEEP, with its whole
 * island, falls asleep (Box2D 2.4's values: 1 cm/s, 2 degrees/s, 0.5 s). */
#define RB_LINEAR_SLEEP_TOLERANCE 0.01                   /* m/s */
#define RB_ANGULAR_SLEEP_TOLERANCE (2.0 * RB_PI / 180.0) /* rad/s */
#define RB_TIME_TO_SLEEP 0.5                             /* s */

/* Before the solve: groups the bodies into islands (dynamic bodies linked
 * by touching contacts, joints and cables) and wakes every sleeping body
 * whose island holds an awake one, or that touches or is jointed to a
 * moving kinematic body. Fails only when out of memory. */
rb_status rb_islands_wake(rb_world *world);

/* After the step: advances each awake body's time at rest and puts every
 * island whose bodies have all rested RB_TIME_TO_SLEEP to sleep. Uses the
 * islands rb_islands_wake found this step. */
void rb_islands_sleep(rb_world *world, double dt);

/* Wakes a body and restarts its time at rest. */
void rb_body_wake(rb_world *world, int body);

#endif
