/* SPDX-License-Identifier: MIT */
/* Graph colouring of constraints: a colour is a set of constraints no
 * two of which move the same body. */
#ifndef RB_CONSTRAINT_COLOURING_H
#define RB_CONSTRAINT_COLOURING_H

#include <stdint.h>

/* Colours 0 .. RB_COLOUR_COUNT - 1 hold constraints that share no
 * moving body; RB_OVERFLOW_COLOUR holds those of a body already in every
 * colour (one with more than RB_COLOUR_COUNT contacts), solved last and
 * in order. */
#define RB_COLOUR_COUNT 64
#define RB_OVERFLOW_COLOUR RB_COLOUR_COUNT

typedef struct rb_colouring {
    uint64_t *body_colours; /* by body index: bit k set when the body is in colour k */
    int body_capacity;
    int sizes[RB_COLOUR_COUNT + 1]; /* constraints given each colour, overflow last */
} rb_colouring;

/* Starts a colouring of constraints among `body_count` bodies, every
 * colour empty. Returns 0, or -1 when out of memory. */
int rb_colouring_begin(rb_colouring *colouring, int body_count);

/* The lowest colour that neither body is in yet, which both then join.
 * A body index of -1 stands for a body the constraint cannot move
 * (static, kinematic or asleep): it may be in any number of colours. */
int rb_colouring_assign(rb_colouring *colouring, int body_a, int body_b);

/* offsets[k] = where colour k's constraints start when they are laid out
 * in colour order; returns the number of colours used (overflow counted). */
int rb_colouring_offsets(const rb_colouring *colouring, int offsets[RB_COLOUR_COUNT + 1]);

void rb_colouring_free(rb_colouring *colouring);

#endif
