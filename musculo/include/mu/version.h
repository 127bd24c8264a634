/* SPDX-License-Identifier: MIT */
/** @file
 * The version of the muscle layer: sinew's version, shared with the engine
 * (rb/version.h), so MU_VERSION_STRING is RB_VERSION_STRING.
 *
 * mu_version() is the version of the libmu a program runs with, which may
 * differ from the headers it was compiled with (MU_VERSION_STRING) when it
 * runs with another release's shared library.
 */
#ifndef MU_VERSION_H
#define MU_VERSION_H

#include "mu/export.h"
#include "rb/version.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MU_VERSION_MAJOR RB_VERSION_MAJOR
#define MU_VERSION_MINOR RB_VERSION_MINOR
#define MU_VERSION_PATCH RB_VERSION_PATCH
#define MU_VERSION_STRING RB_VERSION_STRING

/** The library's version, "MAJOR.MINOR.PATCH". Never NULL. */
MU_API const char *mu_version(void);

#ifdef __cplusplus
}
#endif

#endif
