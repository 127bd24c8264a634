/* SPDX-License-Identifier: MIT */
/* The library's version, compiled in from rb/version.h. */
#include "rb/version.h"

const char *rb_version(void) { return RB_VERSION_STRING; }
