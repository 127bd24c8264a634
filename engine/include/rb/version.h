/* SPDX-License-Identifier: MIT */
/** @file
 * The version of sinew, which the engine and the muscle layer share.
 *
 * Semantic versioning: within a MAJOR version (and, before 1.0, within a
 * MINOR version) a program built against these headers keeps building and
 * working against a newer library. The build reads the three numbers from
 * this file (CMakeLists.txt), so this is the only place they are written.
 *
 * RB_VERSION_STRING is the version of the headers a program was compiled
 * with; rb_version() the version of the library it runs with. They differ
 * when a program built against one release runs with another's shared
 * library.
 */
#ifndef RB_VERSION_H
#define RB_VERSION_H

#include "rb/export.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RB_VERSION_MAJOR 0
#define RB_VERSION_MINOR 2
#define RB_VERSION_PATCH 0

#define RB_VERSION_STRINGIFY_(x) #x
#define RB_VERSION_STRINGIFY(x) RB_VERSION_STRINGIFY_(x)
/** "MAJOR.MINOR.PATCH", e.g. "0.2.0". */
#define RB_VERSION_STRING                                                                                              \
    RB_VERSION_STRINGIFY(RB_VERSION_MAJOR)                                                                             \
    "." RB_VERSION_STRINGIFY(RB_VERSION_MINOR) "." RB_VERSION_STRINGIFY(RB_VERSION_PATCH)
/** One number that grows with every release: MAJOR·10000 + MINOR·100 + PATCH. */
#define RB_VERSION_NUMBER (RB_VERSION_MAJOR * 10000 + RB_VERSION_MINOR * 100 + RB_VERSION_PATCH)

/** The library's version, "MAJOR.MINOR.PATCH". Never NULL. */
RB_API const char *rb_version(void);

#ifdef __cplusplus
}
#endif

#endif
