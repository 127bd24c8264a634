/* SPDX-License-Identifier: MIT */
/* `sinew scene NAME [options]`: run one of the engine scenes of the
 * registry (scenes/registry.h), print a summary, and write a trace.
 *
 * The file reads top to bottom: the options, made from the registry's
 * scene parameters (every value is checked and a bad one exits with
 * status 2 and a message naming the option); scene setup; the CSV trace
 * writer (rows go to a temporary file renamed over the target at the
 * end, so an interrupted run never leaves a half-written trace); the run
 * loop; the summary.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/option_value.h"
#include "cli/user_error.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/provenance.h"
#include "rb/rb.h"
#include "scenes/registry.h"

/* Degrees per radian: angles are given and written in degrees. */
#define DEGREES (180.0 / RB_PI)

/* --------------------------------------------------------------- options */

/* The options every scene takes; each scene's own parameters follow them
 * in the table, one option per name (balls and stack share --count). */
enum {
    OPT_DURATION,
    OPT_HZ,
    OPT_SUBSTEPS,
    OPT_VELOCITY_ITERATIONS,
    OPT_POSITION_ITERATIONS,
    OPT_OUT,
    COMMON_OPTION_COUNT,
};

static const cli_option common_options[COMMON_OPTION_COUNT] = {
    {.name = "duration",
     .id = OPT_DURATION,
     .kind = CLI_NUMBER,
     .value_name = "S",
     .help = "simulated time in s",
     .min = 0.0,
     .max = 1e6,
     .min_open = true,
     .fallback = "10"},
    {.name = "hz",
     .id = OPT_HZ,
     .kind = CLI_NUMBER,
     .value_name = "H",
     .help = "steps per second",
     .min = 0.1,
     .max = 1e6,
     .fallback = "60"},
    {.name = "substeps",
     .id = OPT_SUBSTEPS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "substeps per step",
     .min = 1,
     .max = 1000,
     .fallback = "the engine's"},
    {.name = "velocity-iterations",
     .id = OPT_VELOCITY_ITERATIONS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "the solver's velocity iterations",
     .min = 1,
     .max = 1000,
     .fallback = "the engine's"},
    {.name = "position-iterations",
     .id = OPT_POSITION_ITERATIONS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "the solver's position iterations",
     .min = 0,
     .max = 1000,
     .fallback = "the engine's"},
    {.name = "out",
     .id = OPT_OUT,
     .kind = CLI_PATH,
     .value_name = "DIR",
     .help = "write a trace DIR/NAME.csv\n"
             "one row per step per dynamic body:\n"
             "time_s,body,x_m,y_m,angle_deg,vx_m_s,vy_m_s,omega_deg_s",
     .fallback = "no trace"},
};

/* Room for every scene parameter's option and its help. */
enum { MAX_OPTIONS = COMMON_OPTION_COUNT + SCENE_KIND_COUNT * SCENE_MAX_PARAMETERS, HELP_SIZE = 1024 };

typedef struct scene_command {
    cli_command command;
    cli_option options[MAX_OPTIONS];
    char help[MAX_OPTIONS][HELP_SIZE];
} scene_command;

/* One parameter's range and default, as the help shows them. */
static void describe_parameter(const scene_parameter *parameter, char *text, size_t size)
{
    switch (parameter->kind) {
    case SCENE_INTEGER:
        snprintf(text, size, "%s, %g .. %g (default %g)", parameter->help, parameter->min, parameter->max,
                 parameter->fallback.number);
        break;
    case SCENE_NUMBER:
        snprintf(text, size, "%s, %s%g .. %g (default %g)", parameter->help, parameter->min_open ? "> " : "",
                 parameter->min, parameter->max, parameter->fallback.number);
        break;
    case SCENE_SEED:
        snprintf(text, size, "%s, 0 .. 2^64-1 (default %llu)", parameter->help,
                 (unsigned long long)parameter->fallback.seed);
        break;
    }
}

/* The command's table: the common options, then one option per distinct
 * parameter name of the registry's scenes, whose help says, scene by
 * scene, what it sets. A parameter's value is checked once the scene is
 * known (check_parameter), since scenes may give one name different
 * ranges. */
static void build_command(scene_command *out)
{
    static const char about[] = "Runs an engine scene and prints a summary; NAME is one of the scenes below.\n";
    *out = (scene_command){.command = {.name = "sinew scene",
                                       .operands = "NAME [options]",
                                       .max_operands = 1,
                                       .operand = "scene",
                                       .about = about}};
    int count = COMMON_OPTION_COUNT;
    memcpy(out->options, common_options, sizeof common_options);
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        const scene_entry *entry = &scene_registry[k];
        for (int p = 0; p < entry->parameter_count; ++p) {
            const scene_parameter *parameter = &entry->parameters[p];
            int o = COMMON_OPTION_COUNT;
            while (o < count && strcmp(out->options[o].name, parameter->name) != 0) {
                ++o;
            }
            char *help = out->help[o];
            size_t used = strlen(help);
            if (o == count) {
                out->options[count++] = (cli_option){.name = parameter->name,
                                                     .id = o,
                                                     .kind = CLI_TEXT,
                                                     .value_name = parameter->value_name,
                                                     .help = help};
            } else {
                used += (size_t)snprintf(help + used, HELP_SIZE - used, "\n");
            }
            if (used < HELP_SIZE) {
                int written = snprintf(help + used, HELP_SIZE - used, "%s: ", entry->name);
                if (written > 0 && used + (size_t)written < HELP_SIZE) {
                    describe_parameter(parameter, help + used + written, HELP_SIZE - used - (size_t)written);
                }
            }
        }
    }
    out->command.options = out->options;
    out->command.option_count = count;
}

static void print_help(const scene_command *command)
{
    cli_print_help(&command->command, stdout);
    fputs("\nscenes (each also opens in `sinew view --scene NAME`):\n", stdout);
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        const scene_entry *entry = &scene_registry[k];
        fprintf(stdout, "  %-12s %s", entry->name, entry->summary);
        for (int p = 0; p < entry->parameter_count; ++p) {
            fprintf(stdout, "%s--%s", p == 0 ? "; " : ", ", entry->parameters[p].name);
        }
        if (entry->gravity != NULL) {
            fprintf(stdout, "; gravity %g m/s^2", -entry->gravity->y);
        }
        fputc('\n', stdout);
    }
    rb_world_def def = rb_default_world_def();
    fprintf(stdout, "Gravity is the engine's default, %g m/s^2, unless a scene says otherwise.\n", -def.gravity.y);
}

typedef struct options {
    scene_kind scene;
    scene_value values[SCENE_MAX_PARAMETERS];
    double duration;         /* s, (0, 1e6] */
    double hz;               /* 1/s, 0.1 .. 1e6 */
    int substeps;            /* 1 .. 1000, or 0 for the engine default */
    int velocity_iterations; /* 1 .. 1000, or 0 for the engine default */
    int position_iterations; /* 0 .. 1000, or -1 for the engine default */
    const char *out_dir;     /* NULL: no trace */
    char trace_path[ATOMIC_FILE_PATH_MAX];
} options;

/* Checks `text` against the scene's parameter and stores it; false after
 * one line on stderr. */
static bool check_parameter(const cli_command *command, const options *opts, int p, const char *text,
                            scene_value *value)
{
    const scene_parameter *parameter = &scene_registry[opts->scene].parameters[p];
    char name[64], error[OPTION_ERROR_SIZE];
    snprintf(name, sizeof name, "--%s", parameter->name);
    bool ok = false;
    int integer;
    switch (parameter->kind) {
    case SCENE_INTEGER:
        ok = option_parse_int(name, text, (long)parameter->min, (long)parameter->max, &integer, error, sizeof error);
        value->number = integer;
        break;
    case SCENE_NUMBER:
        ok = option_parse_double(name, text, parameter->min, parameter->min_open, parameter->max, &value->number, error,
                                 sizeof error);
        break;
    case SCENE_SEED:
        ok = option_parse_u64(name, text, &value->seed, error, sizeof error);
        break;
    }
    if (!ok) {
        cli_usage_error(command, "%s (scene %s)", error, scene_registry[opts->scene].name);
    }
    return ok;
}

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

/* The scene's parameters given on the command line, by option id. */
typedef struct given_parameter {
    int option;
    const char *text;
} given_parameter;

/* Checks the parameters given against the scene chosen; false after one
 * line on stderr. */
static bool apply_parameters(const scene_command *command, options *opts, const given_parameter *given, int count)
{
    scene_default_values(opts->scene, opts->values);
    for (int g = 0; g < count; ++g) {
        const char *name = command->options[given[g].option].name;
        int p = scene_find_parameter(opts->scene, name);
        if (p < 0) {
            cli_usage_error(&command->command, "--%s does not apply to scene %s", name,
                            scene_registry[opts->scene].name);
            return false;
        }
        if (!check_parameter(&command->command, opts, p, given[g].text, &opts->values[p])) {
            return false;
        }
    }
    return true;
}

/* The trace's path, DIR/NAME.csv; false after one line on stderr. */
static bool trace_path_for(const cli_command *command, options *opts)
{
    size_t length = strlen(opts->out_dir);
    const char *separator = opts->out_dir[length - 1] == '/' ? "" : "/";
    int written = snprintf(opts->trace_path, sizeof opts->trace_path, "%s%s%s.csv", opts->out_dir, separator,
                           scene_registry[opts->scene].name);
    if (written < 0 || (size_t)written >= sizeof opts->trace_path) {
        cli_usage_error(command, "--out %s: the path of the trace is too long", opts->out_dir);
        return false;
    }
    return true;
}

/* Parses the arguments after `sinew scene`: one scene name and options,
 * in any order. */
static parse_result parse_scene_arguments(const scene_command *command, int argc, char **argv, options *opts)
{
    *opts = (options){.scene = SCENE_KIND_COUNT, .duration = 10.0, .hz = 60.0, .position_iterations = -1};
    given_parameter *given = malloc(((size_t)argc + 1) * sizeof *given);
    if (given == NULL) {
        fputs("sinew scene: out of memory\n", stderr);
        return PARSE_ERROR;
    }
    int given_count = 0;
    cli_parser parser;
    cli_parser_start(&parser, &command->command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_DURATION:
            opts->duration = value.number;
            break;
        case OPT_HZ:
            opts->hz = value.number;
            break;
        case OPT_SUBSTEPS:
            opts->substeps = (int)value.integer;
            break;
        case OPT_VELOCITY_ITERATIONS:
            opts->velocity_iterations = (int)value.integer;
            break;
        case OPT_POSITION_ITERATIONS:
            opts->position_iterations = (int)value.integer;
            break;
        case OPT_OUT:
            opts->out_dir = value.text;
            break;
        default:
            given[given_count++] = (given_parameter){id, value.text};
            break;
        }
    }
    const char *name = id == CLI_END && parser.operand_count == 1 ? parser.operands[0] : NULL;
    cli_parser_finish(&parser);
    parse_result result = id == CLI_HELP ? PARSE_HELP : id == CLI_END ? PARSE_OK : PARSE_ERROR;
    if (result == PARSE_OK && name == NULL) {
        cli_usage_error(&command->command, "missing the scene's name");
        result = PARSE_ERROR;
    } else if (result == PARSE_OK && !scene_kind_from_name(name, &opts->scene)) {
        char names[256];
        scene_list_names(names, sizeof names);
        cli_usage_error(&command->command, "unknown scene \"%s\" (%s)", name, names);
        result = PARSE_ERROR;
    }
    if (result == PARSE_OK && !apply_parameters(command, opts, given, given_count)) {
        result = PARSE_ERROR;
    }
    free(given);
    if (result != PARSE_OK) {
        return result;
    }
    /* The step count is rounded; fewer than one step is a mistake. */
    if (opts->duration * opts->hz < 0.5 || opts->duration * opts->hz > 1e9) {
        cli_usage_error(&command->command, "--duration %g at --hz %g is %s", opts->duration, opts->hz,
                        opts->duration * opts->hz < 0.5 ? "less than one step" : "more than 1e9 steps");
        return PARSE_ERROR;
    }
    if (opts->out_dir != NULL && !trace_path_for(&command->command, opts)) {
        return PARSE_ERROR;
    }
    return PARSE_OK;
}

/* --------------------------------------------------------- scene setup */

/* The scene and where its dynamic bodies started. */
typedef struct simulation {
    scene_instance scene;
    rb_vec2 *start_positions; /* m, of each dynamic body's origin */
} simulation;

static void simulation_destroy(simulation *sim)
{
    scene_instance_destroy(&sim->scene);
    free(sim->start_positions);
    sim->start_positions = NULL;
}

/* Reports an engine failure; a rejected argument is a usage error. */
static int engine_failure(const char *what)
{
    rb_status status = rb_last_status();
    fprintf(stderr, "sinew scene: %s failed: %s (%s)\n", what, user_error(), rb_status_name(status));
    return status == RB_ERR_INVALID_ARGUMENT ? EXIT_USAGE : EXIT_FAILURE;
}

/* Builds the scene with the options' solver settings. Returns 0 or an
 * exit status. */
static int simulation_create(const options *opts, simulation *sim)
{
    *sim = (simulation){.start_positions = NULL};
    rb_world_def def = scene_world_def(opts->scene);
    if (opts->substeps > 0) {
        def.solver.substeps = opts->substeps;
    }
    if (opts->velocity_iterations > 0) {
        def.solver.velocity_iterations = opts->velocity_iterations;
    }
    if (opts->position_iterations >= 0) {
        def.solver.position_iterations = opts->position_iterations;
    }
    if (scene_instance_create(opts->scene, opts->values, &def, &sim->scene) != RB_OK) {
        return engine_failure("building the scene");
    }
    const scene_instance *scene = &sim->scene;
    sim->start_positions = malloc(((size_t)scene->body_count + 1) * sizeof *sim->start_positions);
    if (sim->start_positions == NULL) {
        fputs("sinew scene: out of memory\n", stderr);
        simulation_destroy(sim);
        return EXIT_FAILURE;
    }
    for (int k = 0; k < scene->body_count; ++k) {
        sim->start_positions[k] = rb_body_position(scene->world, scene->bodies[k]);
    }
    return 0;
}

/* ------------------------------------------------------- trace writer */

/* The trace is an atomic_file (io/atomic_file.h), so an interrupted or
 * failed run leaves no half-written trace; its stream is NULL when no
 * trace was asked for. */

static bool trace_open(atomic_file *trace, const char *path)
{
    *trace = (atomic_file){.stream = NULL};
    if (path == NULL) {
        return true;
    }
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_open(trace, path, error, sizeof error)) {
        fprintf(stderr, "sinew scene: --out: %s\n", error);
        return false;
    }
    if (fputs("time_s,body,x_m,y_m,angle_deg,vx_m_s,vy_m_s,omega_deg_s\n", trace->stream) == EOF) {
        fprintf(stderr, "sinew scene: cannot write %s: %s\n", trace->temp_path, strerror(errno));
        return false;
    }
    return true;
}

/* One row per dynamic body; `body` is the body's place in the scene's
 * creation order. Angles are in degrees, as everywhere on sinew's
 * command line and in `sinew run`'s CSV. Ten significant digits resolve 1e-9 of a metre-sized
 * value, below any physical effect the trace is read for. A failed write
 * stops the run at once rather than at the commit. */
static bool trace_write_step(atomic_file *trace, const simulation *sim, double time)
{
    if (trace->stream == NULL) {
        return true;
    }
    for (int k = 0; k < sim->scene.body_count; ++k) {
        rb_body_id body = sim->scene.bodies[k];
        rb_vec2 position = rb_body_position(sim->scene.world, body);
        rb_vec2 velocity = rb_body_linear_velocity(sim->scene.world, body);
        if (fprintf(trace->stream, "%.10g,%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", time, k, position.x, position.y,
                    DEGREES * rb_body_angle(sim->scene.world, body), velocity.x, velocity.y,
                    DEGREES * rb_body_angular_velocity(sim->scene.world, body)) < 0) {
            fprintf(stderr, "sinew scene: cannot write %s: %s\n", trace->temp_path, strerror(errno));
            return false;
        }
    }
    return true;
}

/* Renames the trace into place, then writes its sidecar
 * (io/provenance.h): the scene as built, its step rate and steps. */
static bool trace_commit(atomic_file *trace, const simulation *sim, const options *opts, long steps)
{
    if (trace->stream == NULL) {
        return true;
    }
    char error[ATOMIC_FILE_ERROR_SIZE];
    json_t *settings = provenance_scene_settings(&sim->scene);
    if (settings == NULL || json_object_set_new(settings, "frame_rate_hz", json_real(opts->hz)) != 0 ||
        json_object_set_new(settings, "steps", json_integer(steps)) != 0 ||
        json_object_set_new(settings, "duration_s", json_real((double)steps / opts->hz)) != 0) {
        json_decref(settings);
        atomic_file_abandon(trace);
        fputs("sinew scene: out of memory\n", stderr);
        return false;
    }
    const bool committed = atomic_file_commit(trace, error, sizeof error);
    if (!committed) {
        json_decref(settings);
    }
    if (!committed || !provenance_write_sidecar(opts->trace_path, settings, error, sizeof error)) {
        fprintf(stderr, "sinew scene: --out: %s\n", error);
        return false;
    }
    return true;
}

/* ------------------------------------------------------------ run loop */

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Kinetic plus gravitational potential energy of the dynamic bodies (J):
 * ½·m·v² + ½·I·ω² − m·g·c, with c the centre of mass. */
static double mechanical_energy(const simulation *sim)
{
    rb_vec2 gravity = rb_world_gravity(sim->scene.world);
    double energy = 0.0;
    for (int k = 0; k < sim->scene.body_count; ++k) {
        rb_body_id body = sim->scene.bodies[k];
        double mass = rb_body_mass(sim->scene.world, body);
        double inertia = rb_body_rotational_inertia(sim->scene.world, body);
        rb_vec2 velocity = rb_body_linear_velocity(sim->scene.world, body);
        double omega = rb_body_angular_velocity(sim->scene.world, body);
        rb_vec2 center = rb_body_world_center(sim->scene.world, body);
        energy +=
            0.5 * mass * rb_dot(velocity, velocity) + 0.5 * inertia * omega * omega - mass * rb_dot(gravity, center);
    }
    return energy;
}

typedef struct run_result {
    long steps;
    double step_seconds;    /* s, summed time inside rb_world_step */
    double wall_seconds;    /* s, the whole loop, trace included */
    double max_penetration; /* m, deepest overlap after any step */
    double start_energy;    /* J */
} run_result;

/* Steps the scene for the options' duration, writing the trace. Returns 0
 * or an exit status. */
static int run(const options *opts, simulation *sim, run_result *result)
{
    const double dt = 1.0 / opts->hz;
    *result = (run_result){.steps = lround(opts->duration * opts->hz), .start_energy = mechanical_energy(sim)};
    atomic_file trace;
    if (!trace_open(&trace, opts->out_dir != NULL ? opts->trace_path : NULL)) {
        atomic_file_abandon(&trace);
        return EXIT_FAILURE;
    }
    const double loop_start = now_seconds();
    for (long step = 1; step <= result->steps; ++step) {
        if (scene_instance_before_step(&sim->scene) != RB_OK) {
            atomic_file_abandon(&trace);
            return engine_failure("preparing the step");
        }
        const double step_start = now_seconds();
        rb_status status = rb_world_step(sim->scene.world, dt);
        result->step_seconds += now_seconds() - step_start;
        if (status != RB_OK) {
            atomic_file_abandon(&trace);
            return engine_failure("stepping the scene");
        }
        result->max_penetration = fmax(result->max_penetration, rb_world_statistics(sim->scene.world).max_penetration);
        /* step·dt rather than a running sum, which would drift by rounding. */
        if (!trace_write_step(&trace, sim, (double)step * dt)) {
            atomic_file_abandon(&trace);
            return EXIT_FAILURE;
        }
    }
    if (!trace_commit(&trace, sim, opts, result->steps)) {
        return EXIT_FAILURE;
    }
    result->wall_seconds = now_seconds() - loop_start;
    return 0;
}

/* ------------------------------------------------------------- summary */

/* How many bodies moved more than 0.25 m sideways, the peers' collapse
 * indicator (a box shifted by a quarter of its width has left its place;
 * a tall stack settling vertically is not counted). */
static int count_moved_sideways(const simulation *sim, double *max_shift)
{
    int moved = 0;
    *max_shift = 0.0;
    for (int k = 0; k < sim->scene.body_count; ++k) {
        double shift = fabs(rb_body_position(sim->scene.world, sim->scene.bodies[k]).x - sim->start_positions[k].x);
        moved += shift > 0.25;
        *max_shift = fmax(*max_shift, shift);
    }
    return moved;
}

static void print_top_box(const simulation *sim, rb_body_id top)
{
    rb_vec2 start = sim->start_positions[sim->scene.body_count - 1];
    rb_vec2 end = rb_body_position(sim->scene.world, top);
    double max_shift;
    int moved = count_moved_sideways(sim, &max_shift);
    printf("top box      (%.4f, %.4f) m, drift (%+.2e, %+.2e) m\n", end.x, end.y, end.x - start.x, end.y - start.y);
    printf("moved boxes  %d moved > 0.25 m sideways (largest shift %.3g m)\n", moved, max_shift);
}

static void print_energy(const simulation *sim, const run_result *result)
{
    double end = mechanical_energy(sim);
    printf("energy       %.6g J at the start, %.6g J at the end (%+.3g%%)\n", result->start_energy, end,
           result->start_energy != 0.0 ? 100.0 * (end - result->start_energy) / fabs(result->start_energy) : 0.0);
}

/* Balls whose centre left the box's interior: any is an engine failure. */
static int count_escaped_balls(const simulation *sim)
{
    int escaped = 0;
    for (int k = 0; k < sim->scene.body_count; ++k) {
        rb_vec2 p = rb_body_position(sim->scene.world, sim->scene.bodies[k]);
        escaped += !(p.x >= 0.0 && p.x <= SCENE_BALLS_WIDTH && p.y >= 0.0 && p.y <= SCENE_BALLS_HEIGHT);
    }
    return escaped;
}

static void print_scene_figures(const options *opts, const simulation *sim, const run_result *result)
{
    switch (sim->scene.kind) {
    case SCENE_PYRAMID:
        print_top_box(sim, sim->scene.ids.pyramid.top);
        break;
    case SCENE_STACK:
        print_top_box(sim, sim->scene.ids.stack.top);
        break;
    case SCENE_BALLS:
        print_energy(sim, result);
        printf("escaped      %d of %d balls outside the box\n", count_escaped_balls(sim), sim->scene.body_count);
        break;
    case SCENE_INCLINE: {
        /* Coulomb's prediction while the box is on the plank: at rest when
         * tan(angle) <= mu, else s = ½·g·(sin − mu·cos)·t². */
        const scene_incline *incline = &sim->scene.ids.incline;
        double slid = rb_dot(rb_sub(rb_body_position(sim->scene.world, incline->box), sim->start_positions[0]),
                             incline->slope_direction);
        double g = rb_length(rb_world_gravity(sim->scene.world));
        double angle = opts->values[0].number / DEGREES, friction = opts->values[1].number;
        double acceleration = fmax(0.0, g * (sin(angle) - friction * cos(angle)));
        double t = (double)result->steps / opts->hz;
        printf("slid         %.4f m down the slope (Coulomb: %.4f m while on the plank)\n", slid,
               0.5 * acceleration * t * t);
        break;
    }
    case SCENE_DROP: {
        double bottom = rb_body_position(sim->scene.world, sim->scene.ids.drop.ball).y - sim->scene.ids.drop.radius;
        print_energy(sim, result);
        printf("ball         lowest point %.4f m above the ground at the end\n", bottom);
        break;
    }
    case SCENE_PENDULUM: {
        /* From straight down, counter-clockwise: released at +90°. */
        rb_vec2 bob = rb_body_position(sim->scene.world, sim->scene.ids.pendulum.bob);
        print_energy(sim, result);
        printf("bob          at %.2f deg from straight down at the end\n", DEGREES * atan2(bob.x, -bob.y));
        break;
    }
    case SCENE_CHAIN:
    case SCENE_JOINT_GRID:
        /* The peers' figure of merit for jointed scenes. */
        printf("joints       largest gap between a joint's anchors %.4g m at the end\n",
               rb_world_statistics(sim->scene.world).max_joint_gap);
        break;
    case SCENE_KIND_COUNT:
        break;
    }
}

static void print_summary(const options *opts, const simulation *sim, const run_result *result)
{
    rb_statistics stats = rb_world_statistics(sim->scene.world);
    rb_solver_settings solver = rb_world_solver_settings(sim->scene.world);
    const scene_entry *entry = &scene_registry[sim->scene.kind];
    printf("scene        %s", entry->name);
    for (int p = 0; p < entry->parameter_count; ++p) {
        const scene_parameter *parameter = &entry->parameters[p];
        printf("%s%s ", p == 0 ? " (" : ", ", parameter->name);
        if (parameter->kind == SCENE_SEED) {
            printf("%llu", (unsigned long long)opts->values[p].seed);
        } else {
            printf("%g%s%s", opts->values[p].number, parameter->unit[0] != '\0' ? " " : "", parameter->unit);
        }
    }
    printf("%s\n", entry->parameter_count > 0 ? ")" : "");
    printf("bodies       %d dynamic, %d in all\n", sim->scene.body_count, stats.body_count);
    printf("steps        %ld at %g Hz; substeps %d, velocity iterations %d, position iterations %d\n", result->steps,
           opts->hz, solver.substeps, solver.velocity_iterations, solver.position_iterations);
    printf("simulated    %g s\n", (double)result->steps / opts->hz);
    printf("wall time    %.3f s; %.4f ms per step in rb_world_step\n", result->wall_seconds,
           1e3 * result->step_seconds / (double)result->steps);
    printf("contacts     %d at the end\n", stats.contact_count);
    printf("penetration  %.4g m at most over the run, %.4g m at the end\n", result->max_penetration,
           stats.max_penetration);
    print_scene_figures(opts, sim, result);
    printf("trace        %s\n", opts->out_dir != NULL ? opts->trace_path : "(none; use --out DIR)");
}

/* ------------------------------------------------------------- command */

int cmd_scene(int argc, char **argv)
{
    /* Static: it holds the help of every scene's options. */
    static scene_command command;
    build_command(&command);
    options opts;
    switch (parse_scene_arguments(&command, argc, argv, &opts)) {
    case PARSE_HELP:
        print_help(&command);
        return EXIT_SUCCESS;
    case PARSE_ERROR:
        return EXIT_USAGE;
    case PARSE_OK:
        break;
    }
    simulation sim;
    int code = simulation_create(&opts, &sim);
    if (code != 0) {
        return code;
    }
    run_result result;
    code = run(&opts, &sim, &result);
    if (code == 0) {
        print_summary(&opts, &sim, &result);
    }
    simulation_destroy(&sim);
    return code;
}
