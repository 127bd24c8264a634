/* SPDX-License-Identifier: MIT */
/** @file
 * sinew rigid-body engine: status codes, error messages and the allocator.
 *
 * Every API call that can fail returns an rb_status. On failure it also
 * records a readable message, retrieved with rb_last_error(); the message
 * names the function, the argument and what was expected. Getters that
 * return a value directly (rb_body_position, ...) return a zero value on a
 * bad id and record the error the same way, so rb_last_status() tells a
 * caller whether the value is real.
 */
#ifndef RB_BASE_H
#define RB_BASE_H

#include <stddef.h>
#include <stdint.h>

#include "rb/export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rb_status {
    RB_OK = 0,
    RB_ERR_INVALID_ARGUMENT, /**< NaN, infinity, out of range, NULL pointer */
    RB_ERR_STALE_ID,         /**< the object was destroyed */
    RB_ERR_FOREIGN_ID,       /**< the id belongs to another world, or is null */
    RB_ERR_DEGENERATE_SHAPE, /**< zero size, collinear or coincident points */
    RB_ERR_NOT_CONVEX,       /**< a polygon whose points are not its own convex hull */
    RB_ERR_NO_MASS,          /**< a dynamic body would get zero or negative mass */
    RB_ERR_LOCKED,           /**< the world is inside rb_world_step (a callback changed it) */
    RB_ERR_OUT_OF_MEMORY,
} rb_status;

/** Short constant name of a status ("RB_ERR_STALE_ID"). */
RB_API const char *rb_status_name(rb_status status);

/** The message of the last failed call on this thread ("" after success). */
RB_API const char *rb_last_error(void);

/** The status of the last call on this thread that can fail. */
RB_API rb_status rb_last_status(void);

/** Records a failure with a printf-style message and returns `status`.
 * For libraries built on the engine (scenes, the muscle layer), so that
 * one rb_last_error() carries their messages too. */
RB_API rb_status rb_report_error(rb_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/** Bytes currently allocated by the engine, over all worlds of the process.
 * Zero once every world is destroyed. */
RB_API size_t rb_bytes_in_use(void);

/** Number of allocations made so far (never decreases); lets a benchmark
 * count heap allocations in a step. */
RB_API uint64_t rb_allocation_count(void);

#ifdef __cplusplus
}
#endif

#endif
