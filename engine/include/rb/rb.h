/* SPDX-License-Identifier: MIT */
/** @file
 * sinew rigid-body engine: the whole public API. */
#ifndef RB_RB_H
#define RB_RB_H

#include "rb/base.h"
#include "rb/body.h"
#include "rb/cable.h"
#include "rb/collision.h"
#include "rb/debug_draw.h"
#include "rb/events.h"
#include "rb/geometry.h"
#include "rb/id.h"
#include "rb/joint.h"
#include "rb/math.h"
#include "rb/query.h"
#include "rb/shape.h"
#include "rb/version.h"
#include "rb/world.h"

#endif
