/* SPDX-License-Identifier: MIT */
/** @file
 * MU_API marks every function of the muscle layer's public API.
 *
 * The libraries are compiled with hidden visibility (-fvisibility=hidden),
 * so a shared libmu.so exports exactly the functions marked here and keeps
 * the layer's internal functions to itself. In a static library the mark
 * changes nothing. GCC and Clang only: sinew builds on Linux.
 */
#ifndef MU_EXPORT_H
#define MU_EXPORT_H

#if defined(__GNUC__)
#define MU_API __attribute__((visibility("default")))
#else
#define MU_API
#endif

#endif
