/* SPDX-License-Identifier: MIT */
/* The libraries' error messages as a user reads them. rb_last_error()
 * starts with the library function that failed ("mu_model_recruit:
 * neurons is 300, expected 0 .. 200"), which a program's user never
 * called and cannot act on; what follows names the argument, the file or
 * the object, which they can. */
#ifndef CLI_USER_ERROR_H
#define CLI_USER_ERROR_H

/* `message` without the library function names in it ("rb_..: " or
 * "mu_..: " at the start of a word, however many), in a buffer of the
 * calling thread that the next call overwrites. */
const char *user_error_text(const char *message);

/* user_error_text(rb_last_error()). */
const char *user_error(void);

#endif
