/* SPDX-License-Identifier: MIT */
/* Which version and settings made a file (tools/io/provenance.h): the CSV
 * files of `sinew run` and `sinew experiment` get a sidecar
 * NAME.csv-metadata.json that jansson parses and that names the version,
 * the command and the settings, while the CSV itself keeps its header on
 * line 1; a rerun writes the same bytes; the figures carry the version and
 * the command line (PNG iTXt chunks with valid CRCs, an SVG <metadata>).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <cairo.h>
#include <criterion/criterion.h>
#include <jansson.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "io/provenance.h"
#include "rb/version.h"

static char dir[] = "/tmp/sinew-provenance-XXXXXX";

static void make_dir(void) { cr_assert_not_null(mkdtemp(dir), "mkdtemp failed"); }

static void remove_dir(void)
{
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}

static void run_sinew(const char *arguments)
{
    char command[1024];
    snprintf(command, sizeof command, "'%s' %s >'%s/out.txt' 2>&1", SINEW_TOOL, arguments, dir);
    int status = system(command);
    cr_assert(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0, "sinew %s failed (status %d)", arguments,
              status);
}

/* The whole file, malloc'ed and NUL-terminated; its length in *length. */
static char *read_file(const char *path, size_t *length)
{
    FILE *file = fopen(path, "rb");
    cr_assert_not_null(file, "cannot read %s", path);
    cr_assert_eq(fseek(file, 0, SEEK_END), 0);
    long size = ftell(file);
    rewind(file);
    char *text = malloc((size_t)size + 1);
    cr_assert_not_null(text);
    *length = fread(text, 1, (size_t)size, file);
    text[*length] = '\0';
    fclose(file);
    return text;
}

static json_t *load_sidecar(const char *csv_name)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s-metadata.json", dir, csv_name);
    json_error_t error;
    json_t *root = json_load_file(path, JSON_REJECT_DUPLICATES, &error);
    cr_assert_not_null(root, "%s: line %d: %s", path, error.line, error.text);
    return root;
}

/* The common part of every sidecar: CSVW's context, the CSV's name, the
 * creator and version, and the command as given. */
static json_t *expect_sidecar_head(json_t *root, const char *csv_name, const char *const *command, size_t count)
{
    cr_expect_str_eq(json_string_value(json_object_get(root, "@context")), "http://www.w3.org/ns/csvw");
    cr_expect_str_eq(json_string_value(json_object_get(root, "url")), csv_name);
    cr_expect_str_eq(json_string_value(json_object_get(root, "dc:creator")), "sinew " RB_VERSION_STRING);
    json_t *sinew = json_object_get(root, "sinew");
    cr_assert(json_is_object(sinew));
    cr_expect_str_eq(json_string_value(json_object_get(sinew, "version")), rb_version());
    json_t *given = json_object_get(sinew, "command");
    cr_assert(json_is_array(given));
    cr_assert_eq(json_array_size(given), count, "the command has %zu words", json_array_size(given));
    for (size_t k = 0; k < count; ++k) {
        cr_expect_str_eq(json_string_value(json_array_get(given, k)), command[k], "command word %zu", k);
    }
    json_t *settings = json_object_get(sinew, "settings");
    cr_assert(json_is_object(settings));
    return settings;
}

/* Line 1 is `header_start...`, no line is a comment, and every line has
 * as many commas as the header: the file is a plain rectangle. */
static void expect_plain_csv(const char *name, const char *header_start)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    size_t length;
    char *text = read_file(path, &length);
    cr_expect_eq(strncmp(text, header_start, strlen(header_start)), 0, "%s starts with '%.40s'", name, text);
    long header_commas = -1, lines = 0;
    for (char *line = strtok(text, "\n"); line != NULL; line = strtok(NULL, "\n"), ++lines) {
        long commas = 0;
        for (const char *c = line; *c != '\0'; ++c) {
            commas += *c == ',';
        }
        header_commas = header_commas < 0 ? commas : header_commas;
        cr_expect_neq(line[0], '#', "%s: line %ld is a comment", name, lines + 1);
        cr_expect_eq(commas, header_commas, "%s: line %ld has %ld commas, the header %ld", name, lines + 1, commas,
                     header_commas);
    }
    cr_expect_gt(lines, 1);
    free(text);
}

Test(provenance, a_run_s_sidecar_names_the_version_the_command_and_the_model_s_settings, .init = make_dir,
     .fini = remove_dir, .timeout = 60)
{
    char arguments[256];
    snprintf(arguments, sizeof arguments, "run arm --duration 0.5 --weight 5 --variant 1 --out %s", dir);
    run_sinew(arguments);
    expect_plain_csv("arm.csv", "time_s,");
    json_t *root = load_sidecar("arm.csv");
    const char *command[] = {"sinew", "run",       "arm", "--duration", "0.5", "--weight",
                             "5",     "--variant", "1",   "--out",      dir};
    json_t *settings = expect_sidecar_head(root, "arm.csv", command, sizeof command / sizeof command[0]);
    /* The model's own numbers are checked against models/arm.json, read
     * here with jansson. */
    cr_expect_str_eq(json_string_value(json_object_get(settings, "model")), "arm");
    cr_expect_eq(json_integer_value(json_object_get(json_object_get(settings, "variant"), "index")), 1);
    cr_expect_eq(json_real_value(json_object_get(settings, "weight_kg")), 5.0);
    cr_expect_eq(json_integer_value(json_object_get(settings, "level")), 4);
    cr_expect_eq(json_integer_value(json_object_get(settings, "frames")), 30);
    cr_expect_eq(json_real_value(json_object_get(settings, "duration_s")), 0.5);

    json_error_t error;
    json_t *model = json_load_file(SINEW_SOURCE_DIR "/models/arm.json", 0, &error);
    cr_assert_not_null(model, "models/arm.json: %s", error.text);
    cr_expect_eq(json_number_value(json_object_get(settings, "frame_rate_hz")),
                 json_number_value(json_object_get(model, "frame_rate")));
    json_t *solver = json_object_get(settings, "solver");
    cr_expect_eq(json_integer_value(json_object_get(settings, "substeps_per_frame")),
                 json_integer_value(json_object_get(model, "substeps")));
    cr_expect_eq(json_integer_value(json_object_get(solver, "substeps")),
                 json_integer_value(json_object_get(model, "substeps")));
    cr_expect_str_eq(json_string_value(json_object_get(solver, "type")), "ngs");
    json_t *variant = json_array_get(json_object_get(model, "variants"), 1);
    cr_expect_str_eq(json_string_value(json_object_get(json_object_get(settings, "variant"), "name")),
                     json_string_value(json_object_get(variant, "name")));
    json_decref(model);
    json_decref(root);
}

Test(provenance, a_rerun_writes_the_same_sidecar, .init = make_dir, .fini = remove_dir, .timeout = 60)
{
    char arguments[256], path[160];
    snprintf(arguments, sizeof arguments, "run sample --duration 0.25 --out %s", dir);
    snprintf(path, sizeof path, "%s/sample.csv-metadata.json", dir);
    run_sinew(arguments);
    size_t first_length, second_length;
    char *first = read_file(path, &first_length);
    run_sinew(arguments);
    char *second = read_file(path, &second_length);
    cr_expect(first_length == second_length && memcmp(first, second, first_length) == 0,
              "the rerun's sidecar differs:\n%s\n---\n%s", first, second);
    free(first);
    free(second);
}

Test(provenance, a_scene_s_trace_names_the_scene_its_parameters_and_the_solver, .init = make_dir, .fini = remove_dir,
     .timeout = 60)
{
    char arguments[256];
    snprintf(arguments, sizeof arguments, "scene incline --duration 0.5 --angle 20 --substeps 3 --out %s", dir);
    run_sinew(arguments);
    expect_plain_csv("incline.csv", "time_s,body,");
    json_t *root = load_sidecar("incline.csv");
    const char *command[] = {"sinew", "scene",      "incline", "--duration", "0.5", "--angle",
                             "20",    "--substeps", "3",       "--out",      dir};
    json_t *settings = expect_sidecar_head(root, "incline.csv", command, sizeof command / sizeof command[0]);
    cr_expect_str_eq(json_string_value(json_object_get(settings, "scene")), "incline");
    json_t *parameters = json_object_get(settings, "parameters");
    cr_expect_eq(json_real_value(json_object_get(parameters, "angle")), 20.0);
    cr_expect(json_is_real(json_object_get(parameters, "friction")), "the default friction is named too");
    cr_expect_eq(json_integer_value(json_object_get(json_object_get(settings, "solver"), "substeps")), 3);
    cr_expect_eq(json_real_value(json_object_get(settings, "frame_rate_hz")), 60.0);
    cr_expect_eq(json_integer_value(json_object_get(settings, "steps")), 30);
    json_decref(root);

    /* A seed beyond a double's 53 bits is kept whole, as text; a count is
     * an integer. */
    snprintf(arguments, sizeof arguments, "scene balls --duration 0.05 --count 3 --seed 18446744073709551615 --out %s",
             dir);
    run_sinew(arguments);
    root = load_sidecar("balls.csv");
    parameters = json_object_get(json_object_get(json_object_get(root, "sinew"), "settings"), "parameters");
    cr_expect_str_eq(json_string_value(json_object_get(parameters, "seed")), "18446744073709551615");
    cr_expect(json_is_integer(json_object_get(parameters, "count")));
    cr_expect_eq(json_integer_value(json_object_get(parameters, "count")), 3);
    json_decref(root);
}

/* CRC-32 as PNG defines it, written here independently of the program's
 * and checked against the standard check value before use. */
static uint32_t crc32_of(const unsigned char *bytes, size_t length)
{
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < length; ++i) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; ++bit) {
            crc = crc & 1u ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
        }
    }
    return crc ^ 0xFFFFFFFFu;
}

static uint32_t big_endian(const unsigned char *at)
{
    return (uint32_t)at[0] << 24 | (uint32_t)at[1] << 16 | (uint32_t)at[2] << 8 | (uint32_t)at[3];
}

/* Walks the chunks of the PNG `path`, checks every CRC, and returns the
 * text of the iTXt chunk `keyword` (malloc'ed), or NULL. */
static char *png_text(const char *path, const char *keyword)
{
    cr_assert_eq(crc32_of((const unsigned char *)"123456789", 9), 0xCBF43926u, "the test's CRC-32 is wrong");
    size_t length;
    unsigned char *png = (unsigned char *)read_file(path, &length);
    cr_assert(length > 8 && memcmp(png, "\x89PNG\r\n\x1a\n", 8) == 0, "%s is not a PNG", path);
    char *found = NULL;
    for (size_t at = 8; at + 12 <= length;) {
        uint32_t size = big_endian(png + at);
        cr_assert_leq(at + 12 + size, length, "%s: a chunk runs past the end", path);
        const unsigned char *type = png + at + 4, *data = png + at + 8;
        cr_expect_eq(crc32_of(type, 4 + size), big_endian(data + size), "%s: chunk %.4s has a bad CRC", path, type);
        size_t keyword_length = strlen(keyword);
        if (memcmp(type, "iTXt", 4) == 0 && size > keyword_length + 5 &&
            memcmp(data, keyword, keyword_length + 1) == 0) {
            /* keyword NUL, compression flag, method, language NUL,
             * translated keyword NUL, then the text */
            found = strndup((const char *)data + keyword_length + 5, size - keyword_length - 5);
        }
        at += 12 + size;
    }
    free(png);
    return found;
}

Test(provenance, an_experiment_s_files_name_the_version_and_the_command, .init = make_dir, .fini = remove_dir,
     .timeout = 120)
{
    char arguments[256], path[160], expected[256];
    snprintf(arguments, sizeof arguments, "experiment c1 --out %s", dir);
    run_sinew(arguments);

    expect_plain_csv("c1_hill_curves.csv", "normalized_length,");
    json_t *root = load_sidecar("c1_hill_curves.csv");
    const char *command[] = {"sinew", "experiment", "c1", "--out", dir};
    json_t *settings = expect_sidecar_head(root, "c1_hill_curves.csv", command, sizeof command / sizeof command[0]);
    cr_expect_str_eq(json_string_value(json_object_get(settings, "experiment")), "c1");
    json_decref(root);

    snprintf(path, sizeof path, "%s/c1_hill_curves.png", dir);
    char *software = png_text(path, "Software"), *comment = png_text(path, "Comment");
    cr_expect_str_eq(software != NULL ? software : "(none)", "sinew " RB_VERSION_STRING);
    snprintf(expected, sizeof expected, "sinew experiment c1 --out %s", dir);
    cr_expect_str_eq(comment != NULL ? comment : "(none)", expected);
    free(software);
    free(comment);
    /* The chunks added leave an image Cairo (libpng) reads. */
    cairo_surface_t *image = cairo_image_surface_create_from_png(path);
    cr_expect_eq(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
    cairo_surface_destroy(image);

    snprintf(path, sizeof path, "%s/c1_hill_curves.svg", dir);
    size_t length;
    char *svg = read_file(path, &length);
    snprintf(expected, sizeof expected,
             "<metadata>sinew " RB_VERSION_STRING ": sinew experiment c1 --out %s</metadata>", dir);
    const char *metadata = strstr(svg, expected), *root_element = strstr(svg, "<svg");
    cr_expect_not_null(metadata, "%s has no %s", path, expected);
    cr_expect(root_element != NULL && metadata > root_element, "the metadata is not inside <svg>");
    free(svg);
}

Test(provenance, the_command_line_reads_back_in_a_shell)
{
    char *argv[] = {"/some/build/tools/sinew", "plot", "my data.csv", "it's", "--x", "a", "", "#1", NULL};
    provenance_set_command_line(8, argv);
    char text[256];
    provenance_command_text(text, sizeof text);
    cr_expect_str_eq(text, "sinew plot 'my data.csv' 'it'\\''s' --x a '' '#1'");
    /* The shell reads it back to the same words. */
    char command[512];
    snprintf(command, sizeof command, "set -- %s; test \"$#|$3|$4|$6|$7\" = \"7|it's|--x||#1\"", text + 6);
    cr_expect_eq(system(command), 0, "the shell read back other words from: %s", text);
    provenance_command_text(text, 12);
    cr_expect_str_eq(text, "sinew plot ", "truncated to the buffer");
}
