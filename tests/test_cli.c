/* SPDX-License-Identifier: MIT */
/* The sinew program, run as a user runs it: a model run writes its CSV
 * with the expected header and one row per frame; bad arguments give one
 * line on stderr, a non-zero status and no file; every command's help
 * lists the options its parser takes; `scene` runs the scenes the viewer
 * offers; --version gives the library's version.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, popen */

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "rb/version.h"
#include "scenes/registry.h"

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
     * x, y, angle for each of the 11 parts (1 nail, 10 bones); then 6
     * joint loads for each of the 2 hinges, and a moment arm and a torque
     * for each muscle about each hinge it crosses (3 the shoulder, 5 the
     * elbow); then 6 stress columns for each of the 9 bones that move
     * (the scapula is glued to the nail). */
    const int columns = 1 + 15 * 5 + 2 + 3 * 11 + 6 * 2 + 2 * (3 + 5) + 6 * 9;
    cr_expect_eq(count_fields(line), columns, "%d columns in the header, expected %d", count_fields(line), columns);
    cr_expect(strstr(line, "time_s") == line, "the header starts with time_s: %.40s", line);
    cr_expect(strstr(line, "Biceps Short.total_force_N") != NULL, "a total force column per muscle");
    cr_expect(strstr(line, "Biceps Short.total_force_N,Biceps Short.excitation,Biceps Short.fibre_length_m,"
                           "Biceps Short.tendon_length_m,Biceps Short.pennation_angle_deg,") != NULL,
              "the physiology columns after the forces, with their units");
    cr_expect(strstr(line, "Elbow.angle_deg") != NULL, "an angle column per hinge");
    cr_expect(strstr(line, "Elbow.reaction_x_N,Elbow.reaction_y_N,Elbow.reaction_along_N,Elbow.reaction_across_N,"
                           "Elbow.reaction_torque_N_m,Elbow.muscle_torque_N_m") != NULL,
              "the joint loads per hinge");
    cr_expect(strstr(line, "Biceps Long.Elbow.moment_arm_m,Biceps Long.Elbow.torque_N_m") != NULL,
              "a moment arm and torque per muscle and hinge it crosses");
    cr_expect(strstr(line, "Ulna.max_stress_Pa,Ulna.max_strain,Ulna.safety_factor,Ulna.worst_section_m,"
                           "Ulna.axial_force_N,Ulna.bending_moment_N_m") != NULL,
              "the stress at the worst section per bone that moves");
    cr_expect(strstr(line, "Scapula.max_stress_Pa") == NULL, "none for a bone fixed to the ground");
    int rows = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        cr_expect_eq(count_fields(line), columns, "row %d has %d fields", rows + 1, count_fields(line));
        ++rows;
    }
    fclose(f);
    /* 2 s at 60 frames per second. */
    cr_expect_eq(rows, 120, "%d rows, expected 120", rows);
    char sidecar[700];
    snprintf(sidecar, sizeof sidecar, "%s-metadata.json", csv);
    remove(sidecar);
    remove(csv);
    remove(log);
    cr_expect_eq(rmdir(dir), 0, "%s holds more than the run wrote", dir);
}

/* Reads the file at `path` into `text`, NUL-terminated. */
static void read_text(const char *path, char *text, size_t size)
{
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f, "cannot open %s", path);
    text[fread(text, 1, size - 1, f)] = '\0';
    fclose(f);
}

/* A run's own folder under /tmp, its log and its CSV there. */
typedef struct run_files {
    char dir[32], log[600], csv[600];
} run_files;

static void make_run_files(run_files *files, const char *csv_name)
{
    snprintf(files->dir, sizeof files->dir, "/tmp/sinew-cli-XXXXXX");
    cr_assert_not_null(mkdtemp(files->dir));
    snprintf(files->log, sizeof files->log, "%s/log.txt", files->dir);
    snprintf(files->csv, sizeof files->csv, "%s/%s", files->dir, csv_name);
}

/* Removes the CSV, its metadata sidecar and the log, then their folder. */
static void remove_run(const run_files *files)
{
    remove(files->csv);
    char sidecar[700];
    snprintf(sidecar, sizeof sidecar, "%s-metadata.json", files->csv);
    remove(sidecar);
    remove(files->log);
    rmdir(files->dir);
}

/* The forearm swung into the elbow's limit with 5 kg: the rigid stop
 * loads the ulna past its strength (docs/loads.md), and the summary and
 * stderr say so; holding 1 kg at rest breaks nothing. */
Test(cli, a_bone_past_its_strength_is_warned_of)
{
    run_files files;
    make_run_files(&files, "arm.csv");
    char args[512];
    static char text[1 << 16];
    const char *const runs[] = {"--weight 5 --activation 'Biceps Short=1'",
                                "--weight 1 --activation 'Biceps Long=0.3'"};
    for (int r = 0; r < 2; ++r) {
        snprintf(args, sizeof args, "run arm %s --duration 2 --out '%s'", runs[r], files.dir);
        cr_assert_eq(run_sinew(args, files.log), 0, "sinew run failed; see %s", files.log);
        read_text(files.log, text, sizeof text);
        cr_expect_not_null(strstr(text, "bone stress  Humerus "), "a bone stress line per bone: %s", text);
        const char *warning = strstr(text, "warning: bone \"Ulna\" would break at 1.800 s: safety factor 0.6");
        const char *marked = strstr(text, "(below 1: it would break)");
        if (r == 0) {
            cr_expect_not_null(warning, "the ulna's warning: %s", text);
            cr_expect_not_null(marked, "the summary marks it: %s", text);
        } else {
            cr_expect(warning == NULL && marked == NULL, "nothing breaks holding 1 kg: %s", text);
        }
    }
    remove_run(&files);
}

/* The field at `column` (0-based) of a CSV line without quoted commas,
 * as a number. */
static double field_at(const char *line, int column)
{
    for (int c = 0; c < column && line != NULL; ++c) {
        line = strchr(line, ',');
        line = line != NULL ? line + 1 : NULL;
    }
    cr_assert_not_null(line, "the row has no column %d", column);
    return strtod(line, NULL);
}

/* The column named `name` in a CSV header, or -1. */
static int column_of(const char *header, const char *name)
{
    const size_t length = strlen(name);
    int column = 0;
    for (const char *c = header; c != NULL; c = strchr(c, ','), c = c != NULL ? c + 1 : NULL, ++column) {
        if (strncmp(c, name, length) == 0 && (c[length] == ',' || c[length] == '\n' || c[length] == '\0')) {
            return column;
        }
    }
    return -1;
}

Test(cli, a_bone_is_warned_of_at_the_first_frame_it_would_break)
{
    /* The leg with every muscle at 1 drives its fibula past its strength
     * a third of a second in, and the muscles then hold it there: its
     * safety factor stays on a plateau, the same to 1e-12, whose lowest
     * frame rounding alone picks. The warning gives the first frame
     * below 1, read here from the run's own CSV. */
    run_files files;
    make_run_files(&files, "leg.csv");
    char args[512];
    snprintf(args, sizeof args,
             "run leg --variant 'All Muscles' --activation Soleus=1 --activation 'Gastrocnemius Lateral=1' "
             "--activation 'Gastrocnemius Medial=1' --activation 'Tibialis Anterior=1' --duration 1 --out '%s'",
             files.dir);
    cr_assert_eq(run_sinew(args, files.log), 0, "sinew run failed; see %s", files.log);
    static char line[1 << 16], text[1 << 16];
    FILE *f = fopen(files.csv, "r");
    cr_assert_not_null(f);
    cr_assert_not_null(fgets(line, sizeof line, f));
    const int time_column = column_of(line, "time_s");
    const int factor_column = column_of(line, "Fibula.safety_factor");
    cr_assert(time_column >= 0 && factor_column >= 0, "the CSV's header names time_s and Fibula.safety_factor");
    double first_below = -1.0;
    while (first_below < 0.0 && fgets(line, sizeof line, f) != NULL) {
        first_below = field_at(line, factor_column) < 1.0 ? field_at(line, time_column) : -1.0;
    }
    fclose(f);
    cr_assert_gt(first_below, 0.0, "the fibula's factor fell below 1 in the run");
    read_text(files.log, text, sizeof text);
    char expected[120];
    snprintf(expected, sizeof expected, "warning: bone \"Fibula\" would break at %.3f s:", first_below);
    cr_expect_not_null(strstr(text, expected), "\"%s\" in: %s", expected, text);
    remove_run(&files);
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
    cr_expect(strstr(text, "built-in: sample, arm, leg, leg-unlimited, worm;") != NULL, "the built-ins listed: %s",
              text);
    remove(log);
    rmdir(dir);
}

/* Runs `sinew ARGS` and returns its status, with stdout and stderr
 * together in `output`. */
static int run_sinew_output(const char *args, char *output, size_t size)
{
    char log[] = "/tmp/sinew-cli-log-XXXXXX";
    int fd = mkstemp(log);
    cr_assert(fd >= 0);
    close(fd);
    int status = run_sinew(args, log);
    FILE *f = fopen(log, "r");
    cr_assert_not_null(f);
    output[fread(output, 1, size - 1, f)] = '\0';
    fclose(f);
    remove(log);
    return status;
}

static int count_lines(const char *text)
{
    int lines = 0;
    for (const char *c = text; *c != '\0'; ++c) {
        lines += *c == '\n';
    }
    return lines;
}

/* The commands that take options, with an operand each accepts. */
static const char *const commands[] = {"models",     "check",         "run arm", "scene pyramid",
                                       "plot x.csv", "experiment e1", "version", "view arm"};

/* Whether `sinew COMMAND` can be tried here: `view` only where the viewer
 * was built (GTK 4 found); its bad command lines fail before any window. */
static bool available(const char *command)
{
    char output[16384];
    return strncmp(command, "view", 4) != 0 || run_sinew_output("view --help", output, sizeof output) == 0;
}

Test(cli, the_version_is_the_library_version)
{
    char output[4096], expected[64];
    snprintf(expected, sizeof expected, "sinew %s\n", rb_version());
    cr_expect_eq(run_sinew_output("--version", output, sizeof output), 0);
    cr_expect_str_eq(output, expected);
    cr_expect_eq(run_sinew_output("version", output, sizeof output), 0);
    cr_expect_str_eq(output, expected);
    cr_expect_str_eq(rb_version(), RB_VERSION_STRING, "the program runs with the library it was built with");
    /* --help lists every command, the version among them. */
    cr_expect_eq(run_sinew_output("--help", output, sizeof output), 0);
    const char *names[] = {"models", "check", "run", "scene", "plot", "experiment", "view", "version"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        char line[32];
        snprintf(line, sizeof line, "\n  %s ", names[k]);
        cr_expect(strstr(output, line) != NULL, "no \"%s\" in: %s", line, output);
    }
    cr_expect(strstr(output, "--version") != NULL, "%s", output);
}

/* Every option in a command's help is one its parser knows: given with an
 * empty value (`--NAME=`), each is refused for its value or for having
 * one, never as unknown, and nothing runs. */
Test(cli, every_command_accepts_each_option_its_help_lists)
{
    for (size_t c = 0; c < sizeof commands / sizeof commands[0]; ++c) {
        if (!available(commands[c])) {
            continue;
        }
        char args[256], help[16384];
        snprintf(args, sizeof args, "%.*s --help", (int)strcspn(commands[c], " "), commands[c]);
        cr_assert_eq(run_sinew_output(args, help, sizeof help), 0, "'sinew %s' failed: %s", args, help);
        cr_expect(strncmp(help, "usage: sinew ", 13) == 0, "'sinew %s': %s", args, help);
        int listed = 0;
        for (const char *line = strstr(help, "\n  --"); line != NULL; line = strstr(line + 1, "\n  --")) {
            char name[64];
            snprintf(name, sizeof name, "%.*s", (int)strcspn(line + 3, " \n"), line + 3);
            if (strcmp(name, "--help") == 0) {
                continue;
            }
            ++listed;
            char output[4096];
            snprintf(args, sizeof args, "%s %s=", commands[c], name);
            cr_expect_eq(run_sinew_output(args, output, sizeof output), 2, "'sinew %s': %s", args, output);
            cr_expect(strstr(output, "unknown option") == NULL, "'sinew %s': %s", args, output);
            cr_expect_eq(count_lines(output), 1, "'sinew %s': %s", args, output);
            cr_expect(strstr(output, name) != NULL, "'sinew %s' does not name the option: %s", args, output);
        }
        cr_expect(listed > 0 || strcmp(commands[c], "models") == 0 || strcmp(commands[c], "check") == 0 ||
                      strcmp(commands[c], "version") == 0,
                  "'sinew %s --help' lists no options", commands[c]);
    }
}

Test(cli, every_command_refuses_an_unknown_option_in_one_line)
{
    for (size_t c = 0; c < sizeof commands / sizeof commands[0]; ++c) {
        if (!available(commands[c])) {
            continue;
        }
        char args[256], output[4096];
        snprintf(args, sizeof args, "%s --frobnicate 1", commands[c]);
        cr_expect_eq(run_sinew_output(args, output, sizeof output), 2, "'sinew %s': %s", args, output);
        cr_expect_eq(count_lines(output), 1, "'sinew %s': %s", args, output);
        char command[64];
        snprintf(command, sizeof command, "sinew %.*s: unknown option \"--frobnicate\"", (int)strcspn(commands[c], " "),
                 commands[c]);
        cr_expect(strstr(output, command) != NULL, "'sinew %s': %s", args, output);
    }
}

/* `sinew scene` runs every scene of the registry the viewer offers, and
 * its trace goes where `run` and `experiment` put their files: --out DIR,
 * named after the scene, angles in degrees. */
Test(cli, scene_runs_every_scene_of_the_registry_with_the_shared_flags)
{
    char dir[] = "/tmp/sinew-cli-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char help[16384];
    cr_assert_eq(run_sinew_output("scene --help", help, sizeof help), 0, "%s", help);
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        const scene_entry *entry = &scene_registry[k];
        char listed[64], args[512], output[4096], path[600];
        snprintf(listed, sizeof listed, "\n  %s ", entry->name);
        cr_expect(strstr(help, listed) != NULL, "'sinew scene --help' does not list %s", entry->name);
        for (int p = 0; p < entry->parameter_count; ++p) {
            snprintf(listed, sizeof listed, "\n  --%s ", entry->parameters[p].name);
            cr_expect(strstr(help, listed) != NULL, "no --%s in 'sinew scene --help'", entry->parameters[p].name);
        }
        snprintf(args, sizeof args, "scene %s --duration 0.05 --hz 60 --out '%s'", entry->name, dir);
        cr_expect_eq(run_sinew_output(args, output, sizeof output), 0, "'sinew %s': %s", args, output);
        snprintf(listed, sizeof listed, "scene        %s", entry->name);
        cr_expect(strstr(output, listed) != NULL, "%s", output);
        snprintf(path, sizeof path, "%s/%s.csv", dir, entry->name);
        FILE *f = fopen(path, "r");
        cr_assert_not_null(f, "no trace %s: %s", path, output);
        char line[256] = "";
        cr_expect_not_null(fgets(line, sizeof line, f));
        cr_expect_str_eq(line, "time_s,body,x_m,y_m,angle_deg,vx_m_s,vy_m_s,omega_deg_s\n");
        int rows = 0;
        while (fgets(line, sizeof line, f) != NULL) {
            ++rows;
        }
        fclose(f);
        remove(path);
        char sidecar[700];
        snprintf(sidecar, sizeof sidecar, "%s-metadata.json", path);
        remove(sidecar);
        /* Three steps of each dynamic body. */
        cr_expect(rows > 0 && rows % 3 == 0, "%s: %d rows", entry->name, rows);
    }
    cr_expect_eq(rmdir(dir), 0, "%s holds more than the scenes wrote", dir);

    /* The viewer, when it is built, offers the same scenes. */
    if (run_sinew_output("view --help", help, sizeof help) == 0) {
        for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
            char listed[64];
            snprintf(listed, sizeof listed, "\n  %s ", scene_registry[k].name);
            cr_expect(strstr(help, listed) != NULL, "'sinew view --help' does not list %s", scene_registry[k].name);
        }
    }
}

Test(cli, scene_and_view_refuse_bad_scenes_and_parameters_in_one_line)
{
    static const struct {
        const char *args;
        const char *message;
    } cases[] = {
        {"scene", "missing the scene's name"},
        {"scene nosuch", "unknown scene \"nosuch\""},
        {"scene pyramid --count 3", "--count does not apply to scene pyramid"},
        {"scene stack --count 0", "--count expects an integer from 1 to 1000"},
        {"scene incline --angle 1.5e3", "--angle expects a number >= 0 and <= 80"},
        {"scene balls --seed -1", "--seed expects an integer from 0"},
        {"scene drop --duration 0.001 --hz 60", "less than one step"},
        {"scene drop --seconds 1", "unknown option \"--seconds\""},
        {"scene drop --csv x.csv", "unknown option \"--csv\""},
        {"scene drop pyramid", "unexpected argument \"pyramid\": give one scene"},
        {"view --scene nosuch", "unknown scene \"nosuch\""},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        if (!available(cases[k].args)) {
            continue;
        }
        char output[4096];
        cr_expect_eq(run_sinew_output(cases[k].args, output, sizeof output), 2, "'sinew %s': %s", cases[k].args,
                     output);
        cr_expect_eq(count_lines(output), 1, "'sinew %s': %s", cases[k].args, output);
        cr_expect(strstr(output, cases[k].message) != NULL, "'sinew %s': %s", cases[k].args, output);
    }
    /* An unknown scene's line names the registry's scenes. */
    char names[256], expected[320], output[4096];
    scene_list_names(names, sizeof names);
    snprintf(expected, sizeof expected, "unknown scene \"nosuch\" (%s)", names);
    run_sinew_output("scene nosuch", output, sizeof output);
    cr_expect(strstr(output, expected) != NULL, "%s", output);
}

/* Control files and viewer scripts split their lines alike (cli/words.h):
 * the same mistake gets the same message from both, with file and line. */
Test(cli, control_files_and_viewer_scripts_quote_alike)
{
    char dir[] = "/tmp/sinew-cli-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char control[600], script[600], args[1400], output[4096];
    snprintf(control, sizeof control, "%s/controls.txt", dir);
    snprintf(script, sizeof script, "%s/script.txt", dir);
    FILE *f = fopen(control, "w");
    cr_assert_not_null(f);
    fputs("# a name in quotes, then one quote too few\n0 activation \"Biceps Short\" 0.5\n1 pulse \"Biceps Long\n", f);
    fclose(f);
    f = fopen(script, "w");
    cr_assert_not_null(f);
    fputs("# the same mistake\nset muscle \"Biceps Long\n", f);
    fclose(f);

    snprintf(args, sizeof args, "run arm --duration 0.1 --control '%s' --out '%s'", control, dir);
    cr_expect_eq(run_sinew_output(args, output, sizeof output), 1, "%s", output);
    char expected[700];
    snprintf(expected, sizeof expected, "%s:3: a quote is not closed", control);
    cr_expect(strstr(output, expected) != NULL, "%s", output);
    if (available("view")) {
        snprintf(args, sizeof args, "view arm --script '%s'", script);
        cr_expect_eq(run_sinew_output(args, output, sizeof output), 1, "%s", output);
        snprintf(expected, sizeof expected, "%s:2: a quote is not closed", script);
        cr_expect(strstr(output, expected) != NULL, "%s", output);
    }
    remove(control);
    remove(script);
    rmdir(dir);
}

/* What a run may write is bounded: --duration times the model's frame rate
 * is at most 10,000,000 frames (CSV rows); more is a usage error naming
 * the limit, before any file is made. */
Test(cli, a_run_longer_than_the_frame_limit_is_refused_naming_it)
{
    char dir[] = "/tmp/sinew-cli-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char log[600], args[700], csv[600];
    snprintf(log, sizeof log, "%s/log.txt", dir);
    snprintf(csv, sizeof csv, "%s/sample.csv", dir);
    /* 200,000 s at 60 Hz: 12 million frames. */
    snprintf(args, sizeof args, "run sample --duration 200000 --out '%s'", dir);
    cr_expect_eq(run_sinew(args, log), 2);
    FILE *f = fopen(log, "r");
    cr_assert_not_null(f);
    char text[1024] = "";
    text[fread(text, 1, sizeof text - 1, f)] = '\0';
    fclose(f);
    cr_expect(strstr(text, "--duration 200000 s is 12000000 frames at 60 Hz, more than the 10000000 a run may "
                           "write") != NULL,
              "%s", text);
    cr_expect_neq(access(csv, F_OK), 0, "a refused run left %s behind", csv);
    remove(log);
    rmdir(dir);
}
