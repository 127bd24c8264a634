/* SPDX-License-Identifier: MIT */
/* The library's version, compiled in from mu/version.h. */
#include "mu/version.h"

const char *mu_version(void) { return MU_VERSION_STRING; }
