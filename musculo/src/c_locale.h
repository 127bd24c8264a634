/* SPDX-License-Identifier: MIT */
/* Numbers read and written in the "C" locale whatever the process locale
 * is (private to the muscle layer; the in-tree tools use it too).
 *
 * strtod and printf follow LC_NUMERIC: a program that calls
 * setlocale(LC_ALL, "") under LANG=de_DE.UTF-8 makes strtod stop at the
 * '.' of "0.3422" and printf write "0,5". sinew's files always use '.',
 * so every number the library parses (csv_reader.c), and every message or
 * warning that quotes one (model_json.c, model.c), is handled inside a
 * scope that switches the calling thread to the "C" locale:
 *
 *   mu_c_locale_scope scope = mu_c_locale_begin();
 *   double x = strtod(text, &end);
 *   mu_c_locale_end(scope);
 *
 * Why uselocale (POSIX 2008) and not strtod_l: uselocale changes only the
 * calling thread, so other threads of the program keep their locale, and
 * it covers formatting too (there is no snprintf_l in glibc), while
 * strtod_l is not in POSIX. The "C" locale object is created once, on
 * first use, and kept for the life of the process. Should newlocale fail
 * (out of memory), the scope leaves the thread's locale as it was: a
 * number then fails to parse to its end and the caller reports it, rather
 * than misreading it.
 *
 * jansson (model files) needs none of this: it swaps '.' for the locale's
 * decimal point itself before strtod and after snprintf (its strconv.c;
 * tests/test_locale.c loads a model under de_DE.UTF-8). The engine's
 * rb_report_error makes its own "C" locale the same way (engine/src/
 * error.c), since the muscle layer reaches the engine only through its
 * public API.
 */
#ifndef MU_C_LOCALE_H
#define MU_C_LOCALE_H

/* locale_t is POSIX 2008: its includer defines this before any #include. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#error "c_locale.h needs _POSIX_C_SOURCE 200809L defined before the first #include"
#endif

#include <locale.h>

typedef struct mu_c_locale_scope {
    locale_t previous; /* the thread's locale before, (locale_t)0 if unchanged */
} mu_c_locale_scope;

/* Switches the calling thread to the "C" locale until mu_c_locale_end. */
mu_c_locale_scope mu_c_locale_begin(void);

/* Gives the thread back the locale it had before mu_c_locale_begin. */
void mu_c_locale_end(mu_c_locale_scope scope);

#endif
