/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* newlocale, uselocale */

#include <stdatomic.h>

#include "c_locale.h"

/* Created on first use. Two threads may both create one; the loser frees
 * its own, so exactly one is kept. */
static _Atomic(locale_t) c_locale = (locale_t)0;

static locale_t the_c_locale(void)
{
    locale_t locale = atomic_load(&c_locale);
    if (locale != (locale_t)0) {
        return locale;
    }
    locale_t made = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    if (made == (locale_t)0) {
        return (locale_t)0;
    }
    locale_t expected = (locale_t)0;
    if (!atomic_compare_exchange_strong(&c_locale, &expected, made)) {
        freelocale(made);
        return expected;
    }
    return made;
}

mu_c_locale_scope mu_c_locale_begin(void)
{
    locale_t locale = the_c_locale();
    return (mu_c_locale_scope){.previous = locale != (locale_t)0 ? uselocale(locale) : (locale_t)0};
}

void mu_c_locale_end(mu_c_locale_scope scope)
{
    if (scope.previous != (locale_t)0) {
        uselocale(scope.previous);
    }
}
