/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <string.h>

#include "io/atomic_file.h"
#include "io/provenance.h"
#include "mu/model_desc.h"
#include "rb/version.h"

static int command_argc;
static char *const *command_argv;

void provenance_set_command_line(int argc, char *const *argv)
{
    command_argc = argc;
    command_argv = argv;
}

const char *provenance_creator(void) { return "sinew " RB_VERSION_STRING; }

/* argv[0] without its directory: where the program lies differs between
 * machines and says nothing about the data. */
static const char *program_name(void)
{
    const char *slash = strrchr(command_argv[0], '/');
    return slash != NULL ? slash + 1 : command_argv[0];
}

void provenance_command_text(char *text, size_t size)
{
    if (size == 0) {
        return;
    }
    text[0] = '\0';
    size_t used = 0;
    for (int k = 0; k < command_argc && used < size; ++k) {
        const char *argument = k == 0 ? program_name() : command_argv[k];
        const char *separator = k > 0 ? " " : "";
        int written;
        if (argument[0] != '\0' && strpbrk(argument, " \t\n'\"\\$`*?;&|<>()#~![]{}") == NULL) {
            written = snprintf(text + used, size - used, "%s%s", separator, argument);
        } else {
            /* In single quotes, as a POSIX shell reads them back; a quote
             * inside is closed, escaped and reopened: 'it'\''s'. */
            written = snprintf(text + used, size - used, "%s'", separator);
            for (const char *c = argument; *c != '\0' && written >= 0 && used + (size_t)written < size; ++c) {
                int more =
                    snprintf(text + used + written, size - used - (size_t)written, *c == '\'' ? "'\\''" : "%c", *c);
                written = more < 0 ? more : written + more;
            }
            if (written >= 0 && used + (size_t)written < size) {
                int more = snprintf(text + used + written, size - used - (size_t)written, "'");
                written = more < 0 ? more : written + more;
            }
        }
        if (written < 0) {
            return;
        }
        used += (size_t)written;
    }
}

/* Every field of the solver settings, "type" by name. */
static json_t *solver_settings(const rb_solver_settings *solver)
{
    return json_pack("{s:s, s:i, s:i, s:i, s:i, s:b, s:b, s:f, s:f, s:f, s:f, s:f, s:f, s:f, s:f, s:f}", "type",
                     rb_solver_type_name(solver->type), "velocity_iterations", solver->velocity_iterations,
                     "position_iterations", solver->position_iterations, "relax_iterations", solver->relax_iterations,
                     "substeps", solver->substeps, "warm_starting", solver->warm_starting, "block_solver",
                     solver->block_solver, "baumgarte", solver->baumgarte, "linear_slop_m", solver->linear_slop,
                     "max_linear_correction_m", solver->max_linear_correction, "restitution_threshold_m_s",
                     solver->restitution_threshold, "contact_hertz", solver->contact_hertz, "contact_damping_ratio",
                     solver->contact_damping_ratio, "joint_hertz", solver->joint_hertz, "joint_damping_ratio",
                     solver->joint_damping_ratio, "max_push_speed_m_s", solver->max_push_speed);
}

json_t *provenance_model_settings(mu_model *model, const mu_model_options *options)
{
    const mu_model_desc *desc = mu_model_description(model);
    rb_world *world = mu_model_world(model);
    const rb_vec2 gravity = rb_world_gravity(world);
    const rb_solver_settings solver = rb_world_solver_settings(world);
    json_t *weight = desc->has_weight && options->weight_index >= 0 && options->weight_index < desc->weight.mass_count
                         ? json_real(desc->weight.masses[options->weight_index])
                         : json_null();
    return json_pack("{s:s, s:{s:i, s:s}, s:o, s:i, s:b, s:f, s:i, s:[f, f], s:o}", "model", desc->name, "variant",
                     "index", options->variant, "name", desc->variants[options->variant].name, "weight_kg", weight,
                     "level", options->level, "weld_glues", options->weld_glues, "frame_rate_hz", desc->frame_rate,
                     "substeps_per_frame", desc->substeps, "gravity_m_s2", gravity.x, gravity.y, "solver",
                     solver_settings(&solver));
}

json_t *provenance_scene_settings(const scene_instance *scene)
{
    const scene_entry *entry = &scene_registry[scene->kind];
    json_t *parameters = json_object();
    for (int p = 0; parameters != NULL && p < entry->parameter_count; ++p) {
        char seed[24];
        snprintf(seed, sizeof seed, "%llu", (unsigned long long)scene->values[p].seed);
        const scene_parameter_kind kind = entry->parameters[p].kind;
        json_t *value = kind == SCENE_SEED      ? json_string(seed)
                        : kind == SCENE_INTEGER ? json_integer((json_int_t)scene->values[p].number)
                                                : json_real(scene->values[p].number);
        if (json_object_set_new(parameters, entry->parameters[p].name, value) != 0) {
            json_decref(parameters);
            parameters = NULL;
        }
    }
    const rb_vec2 gravity = rb_world_gravity(scene->world);
    const rb_solver_settings solver = rb_world_solver_settings(scene->world);
    return json_pack("{s:s, s:o, s:[f, f], s:o}", "scene", entry->name, "parameters", parameters, "gravity_m_s2",
                     gravity.x, gravity.y, "solver", solver_settings(&solver));
}

/* The sidecar's document; NULL when out of memory. */
static json_t *sidecar(const char *csv_path, json_t *settings)
{
    json_t *command = json_array();
    for (int k = 0; command != NULL && k < command_argc; ++k) {
        if (json_array_append_new(command, json_string(k == 0 ? program_name() : command_argv[k])) != 0) {
            json_decref(command);
            command = NULL;
        }
    }
    if (command == NULL) {
        json_decref(settings);
        return NULL;
    }
    const char *slash = strrchr(csv_path, '/');
    /* "o" takes over a value (released too if the pack fails); "o*" leaves
     * out settings that are NULL. */
    return json_pack("{s:s, s:s, s:s, s:{s:s, s:o, s:o*}}", "@context", "http://www.w3.org/ns/csvw", "url",
                     slash != NULL ? slash + 1 : csv_path, "dc:creator", provenance_creator(), "sinew", "version",
                     RB_VERSION_STRING, "command", command, "settings", settings);
}

bool provenance_write_sidecar(const char *csv_path, json_t *settings, char *error, size_t error_size)
{
    char path[ATOMIC_FILE_PATH_MAX];
    int length = snprintf(path, sizeof path, "%s-metadata.json", csv_path);
    if (length < 0 || (size_t)length >= sizeof path) {
        json_decref(settings);
        snprintf(error, error_size, "%s-metadata.json: the path is too long", csv_path);
        return false;
    }
    json_t *document = sidecar(csv_path, settings);
    if (document == NULL) {
        snprintf(error, error_size, "%s: out of memory", path);
        return false;
    }
    atomic_file file = {.stream = NULL};
    bool ok = atomic_file_open(&file, path, error, error_size);
    /* Keys in the order they were made; 15 significant digits give back
     * every setting typed with up to 15 (0.005, not 0.0050000000000000001). */
    if (ok && (json_dumpf(document, file.stream, JSON_INDENT(2) | JSON_REAL_PRECISION(15)) != 0 ||
               fputc('\n', file.stream) == EOF)) {
        atomic_file_abandon(&file);
        snprintf(error, error_size, "%s: cannot write", path);
        ok = false;
    }
    ok = ok && atomic_file_commit(&file, error, error_size);
    json_decref(document);
    return ok;
}
