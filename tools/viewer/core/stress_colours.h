/* SPDX-License-Identifier: MIT */
/* The colour of a bone's stress on the canvas (the "reactions" overlay on
 * a model): by its use of the bone's strength, u = 1 / safety factor
 * (mu/bone_stress.h), green at u = 0 through yellow at 1/2 to red at 1
 * and beyond, where the bone would break. */
#ifndef VIEWER_STRESS_COLOURS_H
#define VIEWER_STRESS_COLOURS_H

/* Fills rgb[0..2] (each 0 .. 1) for a section of `safety_factor` (> 0;
 * +inf unloaded). */
void stress_colour(double safety_factor, double rgb[3]);

#endif
