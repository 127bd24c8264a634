/* SPDX-License-Identifier: MIT */
/** @file
 * RB_API marks every function of the engine's public API.
 *
 * The libraries are compiled with hidden visibility (-fvisibility=hidden),
 * so a shared librb.so exports exactly the functions marked here and keeps
 * the engine's internal functions to itself. In a static library the mark
 * changes nothing. GCC and Clang only: sinew builds on Linux.
 */
#ifndef RB_EXPORT_H
#define RB_EXPORT_H

#if defined(__GNUC__)
#define RB_API __attribute__((visibility("default")))
#else
#define RB_API
#endif

#endif
