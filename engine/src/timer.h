/* SPDX-License-Identifier: MIT */
/* A monotonic clock for the step profile. */
#ifndef RB_TIMER_H
#define RB_TIMER_H

/* Milliseconds since an arbitrary fixed point. */
double rb_now_ms(void);

#endif
