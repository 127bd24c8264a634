/* SPDX-License-Identifier: MIT */
/* The tools' shared pieces: files written atomically (tools/io) and option
 * values parsed with their ranges (tools/cli).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/option_value.h"
#include "io/atomic_file.h"

/* A fresh empty directory for one test; path is filled in. */
static void make_scratch_directory(char *path, size_t size)
{
    snprintf(path, size, "/tmp/sinew-test-XXXXXX");
    cr_assert_not_null(mkdtemp(path), "mkdtemp failed");
}

static void read_whole_file(const char *path, char *out, size_t size)
{
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f, "cannot read %s", path);
    size_t n = fread(out, 1, size - 1, f);
    out[n] = '\0';
    fclose(f);
}

static void write_whole_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f, "cannot write %s", path);
    fputs(text, f);
    fclose(f);
}

static bool exists(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0;
}

Test(atomic_file, commit_replaces_the_target_and_leaves_no_temporary_file)
{
    char dir[64];
    make_scratch_directory(dir, sizeof dir);
    char path[128];
    snprintf(path, sizeof path, "%s/out.csv", dir);
    write_whole_file(path, "old\n");

    atomic_file file = {0};
    char error[ATOMIC_FILE_ERROR_SIZE];
    cr_assert(atomic_file_open(&file, path, error, sizeof error), "%s", error);
    fputs("a,b\n1,2\n", file.stream);
    char contents[64];
    read_whole_file(path, contents, sizeof contents);
    cr_expect_str_eq(contents, "old\n", "the target changed before the commit");
    cr_assert(exists(file.temp_path), "the temporary file %s is missing while open", file.temp_path);
    char temp_path[ATOMIC_FILE_PATH_MAX];
    snprintf(temp_path, sizeof temp_path, "%s", file.temp_path);

    cr_assert(atomic_file_commit(&file, error, sizeof error), "%s", error);
    read_whole_file(path, contents, sizeof contents);
    cr_expect_str_eq(contents, "a,b\n1,2\n");
    cr_expect(!exists(temp_path), "the temporary file %s was left behind", temp_path);
    cr_expect_null(file.stream, "the file is still open after the commit");
    unlink(path);
    rmdir(dir);
}

Test(atomic_file, abandon_keeps_the_old_target)
{
    char dir[64];
    make_scratch_directory(dir, sizeof dir);
    char path[128];
    snprintf(path, sizeof path, "%s/out.csv", dir);
    write_whole_file(path, "old\n");
    atomic_file file = {0};
    char error[ATOMIC_FILE_ERROR_SIZE];
    cr_assert(atomic_file_open(&file, path, error, sizeof error), "%s", error);
    fputs("half a fi", file.stream);
    char temp_path[ATOMIC_FILE_PATH_MAX];
    snprintf(temp_path, sizeof temp_path, "%s", file.temp_path);
    atomic_file_abandon(&file);
    char contents[64];
    read_whole_file(path, contents, sizeof contents);
    cr_expect_str_eq(contents, "old\n", "abandoning a file changed its target");
    cr_expect(!exists(temp_path), "the temporary file %s was left behind", temp_path);
    atomic_file_abandon(&file); /* a closed file: nothing to do */
    unlink(path);
    rmdir(dir);
}

Test(atomic_file, refuses_targets_that_are_not_regular_files)
{
    /* The regression: as root, the rename replaced the device /dev/full
     * with a regular file. A device, or a directory, must be refused at
     * open, before anything is written, and stay what it was. */
    const char *targets[] = {"/dev/null", "/tmp"};
    for (int i = 0; i < 2; ++i) {
        struct stat before;
        cr_assert_eq(stat(targets[i], &before), 0);
        atomic_file file = {0};
        char error[ATOMIC_FILE_ERROR_SIZE] = "";
        cr_expect(!atomic_file_open(&file, targets[i], error, sizeof error), "%s was accepted as a target", targets[i]);
        cr_expect(strstr(error, targets[i]) != NULL, "the message '%s' does not name %s", error, targets[i]);
        cr_expect_null(file.stream);
        struct stat after;
        cr_assert_eq(stat(targets[i], &after), 0);
        cr_expect_eq(before.st_mode, after.st_mode, "%s changed type", targets[i]);
    }
}

Test(atomic_file, a_missing_directory_is_an_error_that_names_the_path)
{
    atomic_file file = {0};
    char error[ATOMIC_FILE_ERROR_SIZE] = "";
    const char *path = "/nonexistent-sinew-dir/out.csv";
    cr_expect(!atomic_file_open(&file, path, error, sizeof error));
    cr_expect(strstr(error, path) != NULL, "the message '%s' does not name the path", error);
    cr_expect(!atomic_file_commit(&file, error, sizeof error), "a file that never opened committed");
}

Test(option_value, integers_are_whole_and_in_range)
{
    char error[OPTION_ERROR_SIZE];
    int value = 7;
    cr_expect(option_parse_int("--base", "20", 1, 1000, &value, error, sizeof error));
    cr_expect_eq(value, 20);
    const char *bad[] = {"", "abc", "12x", "0", "1001", "-5", "2.5", "99999999999999999999"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        value = 7;
        cr_expect(!option_parse_int("--base", bad[i], 1, 1000, &value, error, sizeof error), "'%s' was accepted",
                  bad[i]);
        cr_expect_eq(value, 7, "'%s' changed the value", bad[i]);
        cr_expect(strstr(error, "--base") != NULL, "the message '%s' does not name the option", error);
    }
}

Test(option_value, numbers_are_finite_and_in_range)
{
    char error[OPTION_ERROR_SIZE];
    double value = 1.0;
    cr_expect(option_parse_double("--seconds", "2.5", 0.0, true, 1e6, &value, error, sizeof error));
    cr_expect_eq(value, 2.5);
    const char *bad[] = {"nan", "inf", "-inf", "0", "-1", "1e7", "1.5s", ""};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        value = 1.0;
        cr_expect(!option_parse_double("--seconds", bad[i], 0.0, true, 1e6, &value, error, sizeof error),
                  "'%s' was accepted", bad[i]);
        cr_expect_eq(value, 1.0, "'%s' changed the value", bad[i]);
    }
    uint64_t seed = 0;
    cr_expect(option_parse_u64("--seed", "18446744073709551615", &seed, error, sizeof error));
    cr_expect_eq(seed, UINT64_MAX);
    cr_expect(!option_parse_u64("--seed", "-1", &seed, error, sizeof error), "a negative seed was accepted");
}
