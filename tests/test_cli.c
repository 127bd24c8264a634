/* SPDX-License-Identifier: MIT */
/* The sinew program, run as a user runs it: a model run writes its CSV
 * with the expected header and one row per frame; bad arguments give one
 * line on stderr, a non-zero status and no file.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, popen */

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* Runs `sinew ARGS` with stdout and stderr sent to `log`; returns its
 * exit status. */
static int run_sinew(const char *args, const char *log)
{
    char command[2048];
    snprintf(command, sizeof command, "'%s' %s > '%s' 2>&1", SINEW_TOOL, args, log);
    const int status = system(command);
    cr_assert(status != -1 && WIFEXITED(status), "could not run: %s", command);
    return WEXITSTATUS(status);
}

static int count_fields(const char *line)
{
    int fields = 1;
    bool quoted = false;
    for (const char *c = line; *c != '\0' && *c != '\n'; ++c) {
        quoted = *c == '"' ? !quoted : quoted;
        fields += *c == ',' && !quoted;
    }
    return fields;
}

Test(cli, a_run_writes_one_row_per_frame_with_every_readout)
{
    char dir[] = "/tmp/sinew-cli-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char args[512];
    char log[600];
    snprintf(log, sizeof log, "%s/log.txt", dir);
    snprintf(args, sizeof args, "run arm --weight 1 --duration 2 --activation 'Biceps Short'=0.5 --out '%s'", dir);
    cr_assert_eq(run_sinew(args, log), 0, "sinew run failed; see %s", log);

    char csv[600];
    snprintf(csv, sizeof csv, "%s/arm.csv", dir);
    FILE *f = fopen(csv, "r");
    cr_assert_not_null(f, "no CSV at %s", csv);
    static char line[1 << 16];
    cr_assert_not_null(fgets(line, sizeof line, f), "empty CSV");
    /* time, 15 readouts for each of the 5 muscles, 2 hinge angles, and
     * x, y, angle for each of the 11 parts (1 nail, 10 bones). */
    const int columns = 1 + 15 * 5 + 2 + 3 * 11;
    cr_expect_eq(count_fields(line), columns, "%d columns in the header, expected %d", count_fields(line), columns);
    cr_expect(strstr(line, "time_s") == line, "the header starts with time_s: %.40s", line);
    cr_expect(strstr(line, "Biceps Short.total_force_N") != NULL, "a total force column per muscle");
    cr_expect(strstr(line, "Biceps Short.total_force_N,Biceps Short.excitation,Biceps Short.fibre_length_m,"
                           "Biceps Short.tendon_length_m,Biceps Short.pennation_angle_deg,") != NULL,
              "the physiology columns after the forces, with their units");
    cr_expect(strstr(line, "Elbow.angle_deg") != NULL, "an angle column per hinge");
    int rows = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        cr_expect_eq(count_fields(line), columns, "row %d has %d fields", rows + 1, count_fields(line));
        ++rows;
    }
    fclose(f);
    /* 2 s at 60 frames per second. */
    cr_expect_eq(rows, 120, "%d rows, expected 120", rows);
    remove(csv);
    remove(log);
    rmdir(dir);
}

Test(cli, bad_arguments_fail_with_one_line_and_no_file)
{
    char dir[] = "/tmp/sinew-cli-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char log[600];
    snprintf(log, sizeof log, "%s/../sinew-cli-log-%d.txt", dir, (int)getpid());
    const char *cases[] = {
        "run nosuchmodel",
        "run arm --activation 'No Such Muscle'=1",
        "run arm --weight 3",
        "run arm --level 7",
        "run arm --duration -1",
        "run arm --out /nonexistent/dir",
        "check /nonexistent/model.json",
        "frobnicate",
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char args[700];
        snprintf(args, sizeof args, "%s --out '%s'", cases[i], dir);
        if (strstr(cases[i], "--out") != NULL || strncmp(cases[i], "run", 3) != 0) {
            snprintf(args, sizeof args, "%s", cases[i]);
        }
        const int status = run_sinew(args, log);
        cr_expect_neq(status, 0, "'sinew %s' exited 0", args);
        FILE *f = fopen(log, "r");
        cr_assert_not_null(f);
        char text[4096] = "";
        size_t n = fread(text, 1, sizeof text - 1, f);
        text[n] = '\0';
        fclose(f);
        int lines = 0;
        for (const char *c = text; *c != '\0'; ++c) {
            lines += *c == '\n';
        }
        cr_expect(lines >= 1 && lines <= 3, "'sinew %s' printed %d lines: %s", args, lines, text);
    }
    char csv[600];
    snprintf(csv, sizeof csv, "%s/arm.csv", dir);
    cr_expect_neq(access(csv, F_OK), 0, "a failed run left %s behind", csv);

    /* An unknown model's message lists every built-in (it once left the
     * worm out), and the usage status says the command line was wrong. */
    cr_expect_eq(run_sinew("run nosuchmodel", log), 2, "an unknown model is a usage error");
    FILE *f = fopen(log, "r");
    cr_assert_not_null(f);
    char text[1024] = "";
    text[fread(text, 1, sizeof text - 1, f)] = '\0';
    fclose(f);
    cr_expect(strstr(text, "built-in: sample, arm, leg, worm;") != NULL, "the built-ins listed: %s", text);
    remove(log);
    rmdir(dir);
}
