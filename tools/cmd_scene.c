/* SPDX-License-Identifier: MIT */
/* `sinew scene NAME [options]`: run one of the engine scenes, print a
 * summary.
 *
 * The file reads top to bottom: the usage text; option parsing (every
 * value is checked and a bad one exits with status 2 and a message naming
 * the option); scene setup; the CSV trace writer (rows go to a temporary
 * file renamed over the target at the end, so an interrupted run never
 * leaves a half-written trace); the run loop; the summary.
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
#include "commands.h"
#include "io/atomic_file.h"
#include "rb/rb.h"
#include "scenes/scenes.h"

/* ---------------------------------------------------------------- usage */

static const char usage_text[] =
    "usage: sinew scene NAME [options]\n"
    "\n"
    "Runs an engine scene and prints a summary.\n"
    "NAME is one of: pyramid, stack, balls, incline, drop.\n"
    "\n"
    "options (every number must be finite; counts are integers):\n"
    "  --base N                  pyramid: boxes in the bottom row, 1 .. 1000 (default 20)\n"
    "  --count N                 stack: boxes, 1 .. 1000 (default 10);\n"
    "                            balls: balls, 1 .. 1000 (default 50)\n"
    "  --seed N                  balls: random seed, 0 .. 2^64-1 (default 1)\n"
    "  --angle RAD               incline: plank angle, 0 .. 1.4 rad (default 0.4)\n"
    "  --friction MU             incline: friction coefficient, 0 .. 100 (default 0.6)\n"
    "  --height M                drop: height of the ball above the ground, > 0 .. 1000 m (default 1)\n"
    "  --restitution E           drop: restitution, 0 .. 1 (default 0.5)\n"
    "  --seconds S               simulated time, > 0 .. 1e6 s (default 10)\n"
    "  --hz H                    steps per second, 0.1 .. 1e6 (default 60)\n"
    "  --substeps N              substeps per step, 1 .. 1000 (default: engine's)\n"
    "  --velocity-iterations N   1 .. 1000 (default: engine's)\n"
    "  --position-iterations N   0 .. 1000 (default: engine's)\n"
    "  --csv FILE                write a trace, one row per step per dynamic body:\n"
    "                            time_s,body,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s\n"
    "  --help                    print this text\n"
    "\n"
    "Gravity is (0, -10) m/s^2 for pyramid (as the peer benchmarks), (0, -9.81) for balls\n"
    "(as the seed) and the engine's default for the others.\n";

static int usage_error(const char *format, const char *detail)
{
    fputs("sinew: ", stderr);
    fprintf(stderr, format, detail);
    fputs("\n(run `sinew scene --help` for the options)\n", stderr);
    return EXIT_USAGE;
}

/* ------------------------------------------------------ option parsing */

typedef enum scene_kind {
    SCENE_PYRAMID,
    SCENE_STACK,
    SCENE_BALLS,
    SCENE_INCLINE,
    SCENE_DROP,
    SCENE_KIND_COUNT,
} scene_kind;

static const char *const scene_names[SCENE_KIND_COUNT] = {"pyramid", "stack", "balls", "incline", "drop"};

typedef struct options {
    scene_kind scene;
    int base;                /* pyramid bottom row, 1 .. 1000 */
    int count;               /* stack boxes or balls, 1 .. 1000 */
    uint64_t seed;           /* balls */
    double angle;            /* rad, 0 .. 1.4 (incline) */
    double friction;         /* 0 .. 100 (incline) */
    double height;           /* m, (0, 1000] (drop) */
    double restitution;      /* 0 .. 1 (drop) */
    double seconds;          /* s, (0, 1e6] */
    double hz;               /* 1/s, 0.1 .. 1e6 */
    int substeps;            /* 1 .. 1000, or 0 for the engine default */
    int velocity_iterations; /* 1 .. 1000, or 0 for the engine default */
    int position_iterations; /* 0 .. 1000, or -1 for the engine default */
    const char *csv_path;    /* NULL: no trace */
} options;

/* Which scenes an option applies to, as a bit mask of scene kinds. */
#define FOR_SCENE(kind) (1u << (kind))
#define FOR_ALL_SCENES ((1u << SCENE_KIND_COUNT) - 1u)

typedef enum value_kind { VALUE_INT, VALUE_DOUBLE, VALUE_SEED, VALUE_PATH } value_kind;

typedef struct option_spec {
    const char *name;
    value_kind kind;
    unsigned scenes;
    double min, max; /* accepted range, inclusive except where min_open */
    bool min_open;   /* the value must be > min */
    size_t offset;   /* where the value goes in `options` */
} option_spec;

static const option_spec option_specs[] = {
    {"--base", VALUE_INT, FOR_SCENE(SCENE_PYRAMID), 1, 1000, false, offsetof(options, base)},
    {"--count", VALUE_INT, FOR_SCENE(SCENE_STACK) | FOR_SCENE(SCENE_BALLS), 1, 1000, false, offsetof(options, count)},
    {"--seed", VALUE_SEED, FOR_SCENE(SCENE_BALLS), 0, 0, false, offsetof(options, seed)},
    {"--angle", VALUE_DOUBLE, FOR_SCENE(SCENE_INCLINE), 0.0, 1.4, false, offsetof(options, angle)},
    {"--friction", VALUE_DOUBLE, FOR_SCENE(SCENE_INCLINE), 0.0, 100.0, false, offsetof(options, friction)},
    {"--height", VALUE_DOUBLE, FOR_SCENE(SCENE_DROP), 0.0, 1000.0, true, offsetof(options, height)},
    {"--restitution", VALUE_DOUBLE, FOR_SCENE(SCENE_DROP), 0.0, 1.0, false, offsetof(options, restitution)},
    {"--seconds", VALUE_DOUBLE, FOR_ALL_SCENES, 0.0, 1e6, true, offsetof(options, seconds)},
    {"--hz", VALUE_DOUBLE, FOR_ALL_SCENES, 0.1, 1e6, false, offsetof(options, hz)},
    {"--substeps", VALUE_INT, FOR_ALL_SCENES, 1, 1000, false, offsetof(options, substeps)},
    {"--velocity-iterations", VALUE_INT, FOR_ALL_SCENES, 1, 1000, false, offsetof(options, velocity_iterations)},
    {"--position-iterations", VALUE_INT, FOR_ALL_SCENES, 0, 1000, false, offsetof(options, position_iterations)},
    {"--csv", VALUE_PATH, FOR_ALL_SCENES, 0, 0, false, offsetof(options, csv_path)},
};
enum { OPTION_COUNT = sizeof option_specs / sizeof option_specs[0] };

static options default_options(void)
{
    return (options){
        .scene = SCENE_KIND_COUNT,
        .base = 20,
        .count = 0, /* per scene, filled in after parsing */
        .seed = 1,
        .angle = 0.4,
        .friction = 0.6,
        .height = 1.0,
        .restitution = 0.5,
        .seconds = 10.0,
        .hz = 60.0,
        .substeps = 0,
        .velocity_iterations = 0,
        .position_iterations = -1,
        .csv_path = NULL,
    };
}

/* Parses `text` as the value of option `spec` into `opts`; on a bad value
 * prints a message naming the option and returns false. */
static bool parse_value(const option_spec *spec, const char *text, options *opts)
{
    char *target = (char *)opts + spec->offset;
    char error[OPTION_ERROR_SIZE];
    bool ok = false;
    switch (spec->kind) {
    case VALUE_INT:
        ok = option_parse_int(spec->name, text, (long)spec->min, (long)spec->max, (int *)(void *)target, error,
                              sizeof error);
        break;
    case VALUE_DOUBLE:
        ok = option_parse_double(spec->name, text, spec->min, spec->min_open, spec->max, (double *)(void *)target,
                                 error, sizeof error);
        break;
    case VALUE_SEED:
        ok = option_parse_u64(spec->name, text, (uint64_t *)(void *)target, error, sizeof error);
        break;
    case VALUE_PATH:
        ok = option_parse_path(spec->name, text, (const char **)(void *)target, error, sizeof error);
        break;
    }
    if (!ok) {
        fprintf(stderr, "sinew: %s\n", error);
    }
    return ok;
}

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

/* Parses the arguments after `sinew scene`: one scene name and options,
 * each `--name value` or `--name=value`, in any order. */
static parse_result parse_scene_arguments(int argc, char **argv, options *opts)
{
    *opts = default_options();
    const char *name = NULL;
    bool given[OPTION_COUNT] = {false};
    for (int i = 0; i < argc; ++i) {
        const char *argument = argv[i];
        if (strcmp(argument, "--help") == 0 || strcmp(argument, "-h") == 0) {
            return PARSE_HELP;
        }
        if (strncmp(argument, "--", 2) != 0) {
            if (name != NULL) {
                usage_error("unexpected argument \"%s\": give one scene name", argument);
                return PARSE_ERROR;
            }
            name = argument;
            continue;
        }
        const char *equals = strchr(argument, '=');
        size_t name_length = equals != NULL ? (size_t)(equals - argument) : strlen(argument);
        int found = -1;
        for (int k = 0; k < OPTION_COUNT; ++k) {
            if (strlen(option_specs[k].name) == name_length &&
                strncmp(argument, option_specs[k].name, name_length) == 0) {
                found = k;
            }
        }
        if (found < 0) {
            usage_error("unknown option \"%s\"", argument);
            return PARSE_ERROR;
        }
        const char *value = NULL;
        if (equals != NULL) {
            value = equals + 1;
        } else if (i + 1 < argc && strncmp(argv[i + 1], "--", 2) != 0) {
            value = argv[++i];
        } else {
            usage_error("%s needs a value", option_specs[found].name);
            return PARSE_ERROR;
        }
        if (!parse_value(&option_specs[found], value, opts)) {
            return PARSE_ERROR;
        }
        given[found] = true;
    }
    if (name == NULL) {
        usage_error("%s", "missing the scene name (pyramid, stack, balls, incline or drop)");
        return PARSE_ERROR;
    }
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        if (strcmp(name, scene_names[k]) == 0) {
            opts->scene = (scene_kind)k;
        }
    }
    if (opts->scene == SCENE_KIND_COUNT) {
        usage_error("unknown scene \"%s\" (pyramid, stack, balls, incline or drop)", name);
        return PARSE_ERROR;
    }
    for (int k = 0; k < OPTION_COUNT; ++k) {
        if (given[k] && (option_specs[k].scenes & FOR_SCENE(opts->scene)) == 0) {
            fprintf(stderr, "sinew: %s does not apply to scene %s\n", option_specs[k].name, name);
            fputs("(run `sinew scene --help` for the options)\n", stderr);
            return PARSE_ERROR;
        }
    }
    if (opts->count == 0) {
        opts->count = opts->scene == SCENE_BALLS ? 50 : 10;
    }
    /* The step count is rounded; fewer than one step is a mistake. */
    if (opts->seconds * opts->hz < 0.5) {
        fprintf(stderr, "sinew: --seconds %g at --hz %g is less than one step\n", opts->seconds, opts->hz);
        return PARSE_ERROR;
    }
    if (opts->seconds * opts->hz > 1e9) {
        fprintf(stderr, "sinew: --seconds %g at --hz %g is more than 1e9 steps\n", opts->seconds, opts->hz);
        return PARSE_ERROR;
    }
    return PARSE_OK;
}

/* --------------------------------------------------------- scene setup */

/* One scene in its world, and the dynamic bodies the run traces and
 * measures, in creation order. */
typedef struct simulation {
    rb_world *world;
    scene_kind kind;
    union {
        scene_pyramid pyramid;
        scene_stack stack;
        scene_balls balls;
        scene_incline incline;
        scene_drop drop;
    } scene;
    rb_body_id *bodies;
    rb_vec2 *start_positions; /* m, of each body's origin */
    int body_count;
} simulation;

static void simulation_destroy(simulation *sim)
{
    rb_world_destroy(sim->world);
    free(sim->bodies);
    free(sim->start_positions);
    *sim = (simulation){.world = NULL};
}

/* Fills sim->bodies from the scene's ids. */
static bool collect_bodies(simulation *sim)
{
    int count = 0;
    switch (sim->kind) {
    case SCENE_PYRAMID:
        count = sim->scene.pyramid.box_count;
        break;
    case SCENE_STACK:
        count = sim->scene.stack.count;
        break;
    case SCENE_BALLS:
        count = sim->scene.balls.count;
        break;
    case SCENE_INCLINE:
    case SCENE_DROP:
    case SCENE_KIND_COUNT:
        count = 1;
        break;
    }
    sim->bodies = malloc((size_t)count * sizeof *sim->bodies);
    sim->start_positions = malloc((size_t)count * sizeof *sim->start_positions);
    if (sim->bodies == NULL || sim->start_positions == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    for (int k = 0; k < count; ++k) {
        switch (sim->kind) {
        case SCENE_PYRAMID:
            sim->bodies[k] = scene_body_at(sim->scene.pyramid.first_box, k);
            break;
        case SCENE_STACK:
            sim->bodies[k] = scene_body_at(sim->scene.stack.first_box, k);
            break;
        case SCENE_BALLS:
            sim->bodies[k] = sim->scene.balls.balls[k];
            break;
        case SCENE_INCLINE:
            sim->bodies[k] = sim->scene.incline.box;
            break;
        case SCENE_DROP:
        case SCENE_KIND_COUNT:
            sim->bodies[k] = sim->scene.drop.ball;
            break;
        }
        sim->start_positions[k] = rb_body_position(sim->world, sim->bodies[k]);
    }
    sim->body_count = count;
    return true;
}

/* Reports an engine failure; a rejected argument is a usage error. */
static int engine_failure(const char *what)
{
    rb_status status = rb_last_status();
    fprintf(stderr, "sinew: %s failed: %s (%s)\n", what, rb_last_error(), rb_status_name(status));
    return status == RB_ERR_INVALID_ARGUMENT ? EXIT_USAGE : EXIT_FAILURE;
}

/* Creates the world with the options' gravity and solver settings and
 * builds the scene in it. Returns 0 or an exit status. */
static int simulation_create(const options *opts, simulation *sim)
{
    *sim = (simulation){.kind = opts->scene};
    rb_world_def def = rb_default_world_def();
    if (opts->scene == SCENE_PYRAMID) {
        def.gravity = rb_v2(0.0, -10.0); /* the peers' gravity, shared/peers/README.md */
    } else if (opts->scene == SCENE_BALLS) {
        def.gravity = rb_v2(0.0, -9.81); /* the seed's, shared/spec/models.md */
    }
    if (opts->substeps > 0) {
        def.solver.substeps = opts->substeps;
    }
    if (opts->velocity_iterations > 0) {
        def.solver.velocity_iterations = opts->velocity_iterations;
    }
    if (opts->position_iterations >= 0) {
        def.solver.position_iterations = opts->position_iterations;
    }
    if (rb_world_create(&def, &sim->world) != RB_OK) {
        return engine_failure("creating the world");
    }
    rb_status status = RB_OK;
    switch (opts->scene) {
    case SCENE_PYRAMID:
        status = scene_pyramid_create(sim->world, opts->base, &sim->scene.pyramid);
        break;
    case SCENE_STACK:
        status = scene_stack_create(sim->world, opts->count, &sim->scene.stack);
        break;
    case SCENE_BALLS:
        status = scene_balls_create(sim->world, opts->count, opts->seed, &sim->scene.balls);
        break;
    case SCENE_INCLINE:
        status = scene_incline_create(sim->world, opts->angle, opts->friction, &sim->scene.incline);
        break;
    case SCENE_DROP:
    case SCENE_KIND_COUNT:
        status = scene_drop_create(sim->world, opts->height, opts->restitution, &sim->scene.drop);
        break;
    }
    if (status != RB_OK) {
        int code = engine_failure("building the scene");
        simulation_destroy(sim);
        return code;
    }
    if (!collect_bodies(sim)) {
        simulation_destroy(sim);
        return EXIT_FAILURE;
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
        fprintf(stderr, "sinew: --csv: %s\n", error);
        return false;
    }
    if (fputs("time_s,body,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s\n", trace->stream) == EOF) {
        fprintf(stderr, "sinew: cannot write %s: %s\n", trace->temp_path, strerror(errno));
        return false;
    }
    return true;
}

/* One row per dynamic body; `body` is the body's place in the scene's
 * creation order. Ten significant digits resolve 1e-9 of a metre-sized
 * value, below any physical effect the trace is read for. A failed write
 * stops the run at once rather than at the commit. */
static bool trace_write_step(atomic_file *trace, const simulation *sim, double time)
{
    if (trace->stream == NULL) {
        return true;
    }
    for (int k = 0; k < sim->body_count; ++k) {
        rb_body_id body = sim->bodies[k];
        rb_vec2 position = rb_body_position(sim->world, body);
        rb_vec2 velocity = rb_body_linear_velocity(sim->world, body);
        if (fprintf(trace->stream, "%.10g,%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", time, k, position.x, position.y,
                    rb_body_angle(sim->world, body), velocity.x, velocity.y,
                    rb_body_angular_velocity(sim->world, body)) < 0) {
            fprintf(stderr, "sinew: cannot write %s: %s\n", trace->temp_path, strerror(errno));
            return false;
        }
    }
    return true;
}

static bool trace_commit(atomic_file *trace)
{
    if (trace->stream == NULL) {
        return true;
    }
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_commit(trace, error, sizeof error)) {
        fprintf(stderr, "sinew: --csv: %s\n", error);
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
    rb_vec2 gravity = rb_world_gravity(sim->world);
    double energy = 0.0;
    for (int k = 0; k < sim->body_count; ++k) {
        rb_body_id body = sim->bodies[k];
        double mass = rb_body_mass(sim->world, body);
        double inertia = rb_body_rotational_inertia(sim->world, body);
        rb_vec2 velocity = rb_body_linear_velocity(sim->world, body);
        double omega = rb_body_angular_velocity(sim->world, body);
        rb_vec2 center = rb_body_world_center(sim->world, body);
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
    *result = (run_result){.steps = lround(opts->seconds * opts->hz), .start_energy = mechanical_energy(sim)};
    atomic_file trace;
    if (!trace_open(&trace, opts->csv_path)) {
        atomic_file_abandon(&trace);
        return EXIT_FAILURE;
    }
    const double loop_start = now_seconds();
    for (long step = 1; step <= result->steps; ++step) {
        if (sim->kind == SCENE_BALLS && scene_balls_apply_drag(sim->world, &sim->scene.balls) != RB_OK) {
            atomic_file_abandon(&trace);
            return engine_failure("applying the balls' drag");
        }
        const double step_start = now_seconds();
        rb_status status = rb_world_step(sim->world, dt);
        result->step_seconds += now_seconds() - step_start;
        if (status != RB_OK) {
            atomic_file_abandon(&trace);
            return engine_failure("rb_world_step");
        }
        result->max_penetration = fmax(result->max_penetration, rb_world_statistics(sim->world).max_penetration);
        /* step·dt rather than a running sum, which would drift by rounding. */
        if (!trace_write_step(&trace, sim, (double)step * dt)) {
            atomic_file_abandon(&trace);
            return EXIT_FAILURE;
        }
    }
    if (!trace_commit(&trace)) {
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
    for (int k = 0; k < sim->body_count; ++k) {
        double shift = fabs(rb_body_position(sim->world, sim->bodies[k]).x - sim->start_positions[k].x);
        moved += shift > 0.25;
        *max_shift = fmax(*max_shift, shift);
    }
    return moved;
}

static void print_top_box(const simulation *sim, rb_body_id top)
{
    rb_vec2 start = sim->start_positions[sim->body_count - 1];
    rb_vec2 end = rb_body_position(sim->world, top);
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
    for (int k = 0; k < sim->body_count; ++k) {
        rb_vec2 p = rb_body_position(sim->world, sim->bodies[k]);
        escaped += !(p.x >= 0.0 && p.x <= SCENE_BALLS_WIDTH && p.y >= 0.0 && p.y <= SCENE_BALLS_HEIGHT);
    }
    return escaped;
}

static void print_scene_figures(const options *opts, const simulation *sim, const run_result *result)
{
    switch (sim->kind) {
    case SCENE_PYRAMID:
        print_top_box(sim, sim->scene.pyramid.top);
        break;
    case SCENE_STACK:
        print_top_box(sim, sim->scene.stack.top);
        break;
    case SCENE_BALLS:
        print_energy(sim, result);
        printf("escaped      %d of %d balls outside the box\n", count_escaped_balls(sim), sim->body_count);
        break;
    case SCENE_INCLINE: {
        /* Coulomb's prediction while the box is on the plank: at rest when
         * tan(angle) <= mu, else s = ½·g·(sin − mu·cos)·t². */
        const scene_incline *incline = &sim->scene.incline;
        double slid = rb_dot(rb_sub(rb_body_position(sim->world, incline->box), sim->start_positions[0]),
                             incline->slope_direction);
        double g = rb_length(rb_world_gravity(sim->world));
        double acceleration = fmax(0.0, g * (sin(opts->angle) - opts->friction * cos(opts->angle)));
        double t = (double)result->steps / opts->hz;
        printf("slid         %.4f m down the slope (Coulomb: %.4f m while on the plank)\n", slid,
               0.5 * acceleration * t * t);
        break;
    }
    case SCENE_DROP:
    case SCENE_KIND_COUNT: {
        double bottom = rb_body_position(sim->world, sim->scene.drop.ball).y - sim->scene.drop.radius;
        print_energy(sim, result);
        printf("ball         lowest point %.4f m above the ground at the end\n", bottom);
        break;
    }
    }
}

static void print_summary(const options *opts, const simulation *sim, const run_result *result)
{
    rb_statistics stats = rb_world_statistics(sim->world);
    rb_solver_settings solver = rb_world_solver_settings(sim->world);
    printf("scene        %s", scene_names[sim->kind]);
    switch (sim->kind) {
    case SCENE_PYRAMID:
        printf(" (base %d)\n", opts->base);
        break;
    case SCENE_STACK:
        printf(" (%d boxes)\n", opts->count);
        break;
    case SCENE_BALLS:
        printf(" (%d balls, seed %llu)\n", opts->count, (unsigned long long)opts->seed);
        break;
    case SCENE_INCLINE:
        printf(" (angle %g rad, friction %g)\n", opts->angle, opts->friction);
        break;
    case SCENE_DROP:
    case SCENE_KIND_COUNT:
        printf(" (height %g m, restitution %g)\n", opts->height, opts->restitution);
        break;
    }
    printf("bodies       %d dynamic, %d in all\n", sim->body_count, stats.body_count);
    printf("steps        %ld at %g Hz; substeps %d, velocity iterations %d, position iterations %d\n", result->steps,
           opts->hz, solver.substeps, solver.velocity_iterations, solver.position_iterations);
    printf("simulated    %g s\n", (double)result->steps / opts->hz);
    printf("wall time    %.3f s; %.4f ms per step in rb_world_step\n", result->wall_seconds,
           1e3 * result->step_seconds / (double)result->steps);
    printf("contacts     %d at the end\n", stats.contact_count);
    printf("penetration  %.4g m at most over the run, %.4g m at the end\n", result->max_penetration,
           stats.max_penetration);
    print_scene_figures(opts, sim, result);
    printf("trace        %s\n", opts->csv_path != NULL ? opts->csv_path : "(none; use --csv FILE)");
}

/* ------------------------------------------------------------- command */

int cmd_scene(int argc, char **argv)
{
    options opts;
    switch (parse_scene_arguments(argc, argv, &opts)) {
    case PARSE_HELP:
        fputs(usage_text, stdout);
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
