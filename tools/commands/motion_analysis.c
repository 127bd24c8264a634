/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/model_source.h"
#include "cli/output_path.h"
#include "cli/user_error.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/csv_table.h"
#include "io/provenance.h"
#include "motion_analysis.h"
#include "motion_filter.h"

motion_analysis_options motion_analysis_default_options(void)
{
    return (motion_analysis_options){
        .cutoff = MOTION_FILTER_DEFAULT_CUTOFF, .weight_index = -1, .level = 4, .out_dir = "."};
}

/* Takes a shared option; false when `id` is not one. */
static bool take_shared(int id, const cli_value *value, motion_analysis_options *opts)
{
    switch (id) {
    case MOTION_OPT_MOTION:
        opts->motion = value->text;
        return true;
    case MOTION_OPT_CUTOFF:
        opts->cutoff = value->number;
        return true;
    case MOTION_OPT_VARIANT:
        opts->variant = value->text;
        return true;
    case MOTION_OPT_WEIGHT:
        opts->weight_kg = value->number;
        opts->has_weight_kg = true;
        return true;
    case MOTION_OPT_WEIGHT_INDEX:
        opts->weight_index = (int)value->integer;
        return true;
    case MOTION_OPT_LEVEL:
        opts->level = (int)value->integer;
        return true;
    case MOTION_OPT_OUT:
        opts->out_dir = value->text;
        return true;
    default:
        return false;
    }
}

int motion_analysis_parse(const cli_command *command, int argc, char **argv, motion_analysis_options *opts,
                          motion_analysis_take_option take, void *own)
{
    cli_parser parser;
    cli_parser_start(&parser, command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        if (!take_shared(id, &value, opts)) {
            take(id, &value, own);
        }
    }
    if (id == CLI_END && parser.operand_count == 1) {
        opts->model = parser.operands[0];
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? MOTION_ANALYSIS_HELP : EXIT_USAGE;
    }
    if (opts->model == NULL) {
        return cli_usage_error(command, "missing the model (sample, arm, leg, worm or a model file)");
    }
    if (opts->motion == NULL) {
        return cli_usage_error(command, "missing --motion FILE");
    }
    if (opts->has_weight_kg && opts->weight_index >= 0) {
        return cli_usage_error(command, "give --weight or --weight-index, not both");
    }
    return 0;
}

int motion_analysis_build_model(const motion_analysis_options *opts, const mu_model_desc *desc,
                                mu_model_options *options, mu_model **model)
{
    int variant = 0, weight = 0;
    int code = model_source_choose_variant(desc, opts->variant, &variant);
    code = code == 0
               ? model_source_choose_weight(desc, opts->has_weight_kg, opts->weight_kg, opts->weight_index, &weight)
               : code;
    if (code != 0) {
        return code;
    }
    *options = mu_default_model_options();
    options->variant = variant;
    options->weight_index = weight;
    options->level = opts->level;
    if (mu_model_create(desc, options, model) != RB_OK) {
        fprintf(stderr, "sinew: building the model failed: %s\n", user_error());
        return EXIT_FAILURE;
    }
    int built = 0;
    for (int h = 0; h < mu_model_hinge_count(*model); ++h) {
        built += !rb_joint_id_is_null(mu_model_hinge_joint(*model, h));
    }
    if (built == 0) {
        fprintf(stderr, "sinew: model %s has no hinge at level %d in variant \"%s\": nothing to compute\n", desc->name,
                opts->level, desc->variants[variant].name);
        mu_model_destroy(*model);
        *model = NULL;
        return EXIT_USAGE;
    }
    return 0;
}

int motion_analysis_read(const motion_analysis_options *opts, const mu_model *model, motion *m)
{
    if (!motion_file_read(opts->motion, model, m)) {
        return EXIT_FAILURE;
    }
    if (opts->cutoff > 0.0 && !motion_filter_cutoff_valid(opts->cutoff, 1.0 / m->step)) {
        fprintf(stderr,
                "sinew: --cutoff %g Hz: %s is sampled at %g Hz, so the cut-off must be below %g Hz (or 0 to turn the "
                "filter off)\n",
                opts->cutoff, opts->motion, 1.0 / m->step, 0.5 / m->step * MOTION_FILTER_TWO_PASS_CORRECTION);
        return EXIT_USAGE;
    }
    return 0;
}

bool motion_kinematics_compute(const motion *m, double cutoff, motion_kinematics *k)
{
    const size_t n = (size_t)m->frames, size = (size_t)m->hinge_count * n + 1;
    k->frames = m->frames;
    k->angles = calloc(size, sizeof *k->angles);
    k->rates = calloc(size, sizeof *k->rates);
    k->accelerations = calloc(size, sizeof *k->accelerations);
    if (k->angles == NULL || k->rates == NULL || k->accelerations == NULL) {
        return false;
    }
    for (int h = 0; h < m->hinge_count; ++h) {
        if (m->angles[h] == NULL) {
            continue;
        }
        double *angle = &k->angles[(size_t)h * n];
        memcpy(angle, m->angles[h], n * sizeof *angle);
        if (cutoff > 0.0 && !motion_filter_low_pass(angle, n, cutoff, 1.0 / m->step)) {
            return false;
        }
        motion_filter_differentiate(angle, n, m->step, &k->rates[(size_t)h * n], &k->accelerations[(size_t)h * n]);
    }
    return true;
}

void motion_kinematics_free(motion_kinematics *k)
{
    free(k->angles);
    free(k->rates);
    free(k->accelerations);
    *k = (motion_kinematics){0};
}

int motion_analysis_output_path(const motion_analysis_options *opts, const char *suffix, const char *extension,
                                char *path, size_t path_size)
{
    char stem[MODEL_STEM_SIZE];
    model_source_stem(opts->model, stem, sizeof stem);
    return output_path_in_folder(opts->out_dir, stem, suffix, extension, path, path_size);
}

json_t *motion_analysis_settings(mu_model *model, const mu_model_options *options, const motion_analysis_options *opts,
                                 double step)
{
    json_t *settings = provenance_model_settings(model, options);
    if (settings != NULL) {
        json_object_set_new(settings, "motion", json_string(opts->motion));
        json_object_set_new(settings, "sample_rate_Hz", json_real(1.0 / step));
        json_object_set_new(settings, "cutoff_Hz", json_real(opts->cutoff));
        json_object_set_new(settings, "filter",
                            json_string(opts->cutoff > 0.0 ? "zero-phase 4th-order Butterworth low-pass (a 2nd-order "
                                                             "section forwards and backwards, Winter's 0.802 "
                                                             "correction), ends extended by point reflection"
                                                           : "none"));
        json_object_set_new(settings, "derivatives", json_string("second-order finite differences"));
    }
    return settings;
}

bool motion_analysis_write_csv(const char *path, int columns, const char *const *names, const double *const *values,
                               long frames, json_t *settings)
{
    double *row = malloc(((size_t)columns + 1) * sizeof *row);
    csv_table table = {0};
    char error[ATOMIC_FILE_ERROR_SIZE] = "out of memory";
    bool ok = row != NULL && csv_table_init(&table, columns, names, error, sizeof error);
    for (long i = 0; ok && i < frames; ++i) {
        for (int c = 0; c < columns; ++c) {
            row[c] = values[c][i];
        }
        ok = csv_table_add_row(&table, row, error, sizeof error);
    }
    ok = ok && csv_table_write(&table, path, error, sizeof error);
    if (ok) {
        ok = provenance_write_sidecar(path, settings, error, sizeof error);
    } else {
        json_decref(settings);
    }
    if (!ok) {
        fprintf(stderr, "sinew: %s\n", error);
    }
    csv_table_free(&table);
    free(row);
    return ok;
}

void motion_analysis_print_header(const motion_analysis_options *opts, long frames, double step)
{
    printf("motion       %s: %ld frames at %g Hz\n", opts->motion, frames, 1.0 / step);
    if (opts->cutoff > 0.0) {
        printf("filter       zero-phase 4th-order Butterworth low-pass at %g Hz\n", opts->cutoff);
    } else {
        printf("filter       none\n");
    }
}
