/* SPDX-License-Identifier: MIT */
/* bench_solver: what the solver's iteration settings buy in joint accuracy
 * and cost in time.
 *
 * Scenes (gravity (0, -10) m/s², dt = 1/60 s, no sleeping):
 *   chain_hang, chain_swing  the peers' chain (docs/benchmarks.md): 40
 *       links and a 100:1 heavy box, hanging at rest or released from the
 *       horizontal; 300 steps (5 s), every one timed. The gaps are the
 *       peers' figures with their --warmup 0 --steps 300: the worst over
 *       0-5 s and the one at 5 s.
 *   pendulum  a small dense circle (radius 0.05 m, 1000 kg/m²) whose centre
 *       hangs 1 m from a static pivot on a revolute joint, released from
 *       the horizontal (90°) at rest; 1200 steps (20 s), every one timed.
 *       Its figure is the drift of the mechanical energy,
 *       |E - E0| / E0, the potential energy measured from the lowest
 *       position so that E0 = m·g·L: the largest over the run and the last.
 *   joint_grid  the peers' joint grid, 100 × 100: 60 untimed warm-up steps,
 *       then 60 timed (10 and 10 with --quick).
 *   chain10  the joint tests' chain (tests/test_joints.c): 10 light links of
 *       the peers' chain, no heavy box, released from the horizontal;
 *       3600 steps (60 s), every one timed. The joint tests ask the
 *       default settings for a worst gap under 5 mm.
 *   cantilever  two planks welded out from a wall (scene_cantilever);
 *       120 steps (2 s), every one timed. Its figure besides the gaps is
 *       the tip sag: the largest distance of the outer plank's centre from
 *       where it started, which the joint tests keep within the linear
 *       slop (5 mm) at the default settings.
 * The joint gap is rb_world_statistics().max_joint_gap after each step
 * (warm-up included): the largest distance between a joint's two anchors.
 *
 * The sweep, around Box2D 2.4's settings (8 velocity, 3 position
 * iterations, 1 substep) rather than across the full cross product, for
 * each correction method:
 *   velocity iterations 1, 2, 4, 8, 16, 32 (position 3, 1 substep);
 *   position iterations 1, 2, 4, 8 (velocity 8, 1 substep; NGS passes,
 *       or the soft step's relax passes);
 *   substeps 2, 4, 8 at 8 velocity iterations each (position 3): more
 *       work per step;
 *   the diagonal substeps × velocity iterations = 8: 2 × 4, 4 × 2, 8 × 1
 *       (position 3 per substep): the same velocity work per step split
 *       differently;
 *   and last the engine's defaults (rb_default_solver_settings), unless
 *       already run.
 * Baumgarte has no position pass, so its rows run with 0 position
 * iterations and skip that axis. Each setting appears once: at most 17
 * settings under NGS, 13 under Baumgarte. --vel, --pos, --substeps or
 * --single run one setting instead: the engine's defaults with those
 * fields replaced.
 *
 * Timing: each setting runs `runs` times, each in a fresh world; a run's
 * figure is the median of its timed steps, the row's the median over runs
 * (the mean of the middle two for an even count). The gaps and energy
 * figures come from the last run (runs are deterministic). A run stops at
 * the first step whose gap passes BENCH_DIVERGED_GAP or whose gap or
 * energy is not finite: its row then says diverged=yes and covers the
 * steps done (an exploding world can take seconds a step, all of them
 * meaningless). finite=yes says that every body's pose and velocity were
 * finite at the end.
 *
 * Prints a table and writes a CSV (header row; written to a temporary name
 * and renamed). Exit status: 0 success, 1 failure, 2 bad command line.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <assert.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/options.h"
#include "io/atomic_file.h"
#include "rb/rb.h"
#include "scenes/scenes.h"

enum { OPT_SCENE, OPT_METHOD, OPT_RUNS, OPT_CSV, OPT_QUICK, OPT_SINGLE, OPT_VEL, OPT_POS, OPT_SUBSTEPS, OPT_NO_TREES };

static const cli_option options_table[] = {
    {.name = "scene",
     .id = OPT_SCENE,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "chain_hang, chain_swing, pendulum, joint_grid, chain10, cantilever or all",
     .fallback = "all"},
    {.name = "method",
     .id = OPT_METHOD,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "solver: soft_step, ngs, baumgarte or all",
     .fallback = "all for the sweep,\nthe engine's for --single"},
    {.name = "runs",
     .id = OPT_RUNS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "repetitions of each setting",
     .min = 1,
     .max = 1000,
     .fallback = "3"},
    {.name = "csv",
     .id = OPT_CSV,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "results",
     .fallback = "bench_solver.csv"},
    {.name = "quick",
     .id = OPT_QUICK,
     .kind = CLI_FLAG,
     .help = "smoke test: 1 run, joint grid 10 warm-up + 10 timed steps\n(an explicit --runs still wins)"},
    {.name = "no-trees",
     .id = OPT_NO_TREES,
     .kind = CLI_FLAG,
     .help = "NGS and the soft step solve every pin by Gauss-Seidel (rb_solver_settings.tree_pins\nfalse), to see how "
             "mass ratios "
             "defeat it"},
    {.name = "single",
     .id = OPT_SINGLE,
     .kind = CLI_FLAG,
     .help = "one setting instead of the sweep: the engine's default solver settings"},
    {.name = "vel",
     .id = OPT_VEL,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "velocity iterations (implies --single)",
     .min = 1,
     .max = 1000},
    {.name = "pos",
     .id = OPT_POS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "position iterations (implies --single)",
     .min = 0,
     .max = 1000},
    {.name = "substeps",
     .id = OPT_SUBSTEPS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "substeps per step (implies --single)",
     .min = 1,
     .max = 1000},
};

static const cli_command command = {
    .name = "bench_solver",
    .operands = "[options]",
    .about = "Sweeps the solver's velocity iterations, position iterations and substeps on the chain\n"
             "(hanging, swinging), a pendulum, the joint grid, a 10-link chain and a welded cantilever;\n"
             "reports time per step, joint gaps, the pendulum's energy drift and the cantilever's sag.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
};

#define BENCH_DT (1.0 / 60.0) /* s, the peers' step */
#define BENCH_GRAVITY (-10.0) /* m/s², the peers' */
/* m: a joint gap beyond this has torn the scene apart (the chain is 20.5 m
 * long, the grid 100 m wide). */
#define BENCH_DIVERGED_GAP 1000.0

#define CHAIN_LINKS 40
#define CHAIN_HEAVY_DENSITY 20.0 /* kg/m²: 5 kg, 100× a link */
#define CHAIN_STEPS 300          /* 5 s, the peers' gap window */

#define PENDULUM_LENGTH 1.0     /* m, pivot to the bob's centre */
#define PENDULUM_RADIUS 0.05    /* m: small beside the length, so nearly a point mass */
#define PENDULUM_DENSITY 1000.0 /* kg/m²; the motion does not depend on it */
#define PENDULUM_STEPS 1200     /* 20 s, about ten swings */

#define CHAIN10_LINKS 10
#define CHAIN10_STEPS 3600   /* 60 s, as the joint test */
#define CANTILEVER_STEPS 120 /* 2 s, as the joint test */

#define GRID_N 100
#define GRID_WARMUP 60
#define GRID_STEPS 60
#define GRID_QUICK_WARMUP 10
#define GRID_QUICK_STEPS 10

/* The centre of the sweep: Box2D 2.4's settings, the peers' default. */
#define SWEEP_VELOCITY 8
#define SWEEP_POSITION 3
#define SWEEP_SUBSTEPS 1
/* Velocity iterations per step held constant along the diagonal. */
#define SWEEP_DIAGONAL_BUDGET 8
/* Room for every solver's axes: at most 6 + 4 + 4 + 3 + 1 settings each. */
#define SWEEP_MAX_SETTINGS (18 * RB_SOLVER_TYPE_COUNT)

/* ------------------------------------------------------------- options */

typedef enum bench_scene {
    BENCH_CHAIN_HANG,
    BENCH_CHAIN_SWING,
    BENCH_PENDULUM,
    BENCH_JOINT_GRID,
    BENCH_CHAIN10,
    BENCH_CANTILEVER,
    BENCH_SCENE_COUNT
} bench_scene;

static const char *const bench_scene_names[BENCH_SCENE_COUNT] = {"chain_hang", "chain_swing", "pendulum",
                                                                 "joint_grid", "chain10",     "cantilever"};

typedef struct bench_options {
    bool scenes[BENCH_SCENE_COUNT];
    bool methods[RB_SOLVER_TYPE_COUNT];
    bool single;             /* one setting instead of the sweep */
    int velocity_iterations; /* single: 1 .. 1000, or 0 for the engine default */
    int position_iterations; /* single: 0 .. 1000, or -1 for the engine default */
    int substeps;            /* single: 1 .. 1000, or 0 for the engine default */
    int runs;                /* 1 .. 1000 */
    int grid_warmup, grid_steps;
    const char *csv_path;
    bool no_trees; /* --no-trees: tree_pins off */
} bench_options;

static const char *method_name(rb_solver_type method) { return rb_solver_type_name(method); }

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

/* Applies --scene and --method; called once every option is read, so
 * that --single, which changes --method's default, is known. */
static bool parse_names(const char *scene, const char *method, bench_options *opts)
{
    bool all = strcmp(scene, "all") == 0;
    bool any = all;
    for (int k = 0; k < BENCH_SCENE_COUNT; ++k) {
        opts->scenes[k] = all || strcmp(scene, bench_scene_names[k]) == 0;
        any = any || opts->scenes[k];
    }
    if (!any) {
        fprintf(stderr,
                "bench_solver: --scene expects chain_hang, chain_swing, pendulum, joint_grid, chain10, cantilever "
                "or all, got \"%s\"\n",
                scene);
        return false;
    }
    if (method == NULL) {
        /* The sweep compares every solver; one setting is the engine's. */
        for (int t = 0; t < RB_SOLVER_TYPE_COUNT; ++t) {
            opts->methods[t] = !opts->single;
        }
        opts->methods[rb_default_solver_settings().type] = true;
        return true;
    }
    bool every = strcmp(method, "all") == 0;
    rb_solver_type type = RB_SOLVER_TYPE_COUNT;
    if (!every && rb_solver_type_from_name(method, &type) != RB_OK) {
        fprintf(stderr, "bench_solver: --method: %s (or all)\n", rb_last_error());
        return false;
    }
    for (int t = 0; t < RB_SOLVER_TYPE_COUNT; ++t) {
        opts->methods[t] = every || t == (int)type;
    }
    return true;
}

static parse_result parse_options(int argc, char **argv, bench_options *opts)
{
    *opts = (bench_options){.position_iterations = -1, .runs = -1, .csv_path = "bench_solver.csv"};
    bool quick = false;
    const char *scene = "all";
    const char *method = NULL;
    cli_parser parser;
    cli_parser_start(&parser, &command, argc - 1, argv + 1);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_SCENE:
            scene = value.text;
            break;
        case OPT_METHOD:
            method = value.text;
            break;
        case OPT_RUNS:
            opts->runs = (int)value.integer;
            break;
        case OPT_CSV:
            opts->csv_path = value.text;
            break;
        case OPT_QUICK:
            quick = true;
            break;
        case OPT_SINGLE:
            opts->single = true;
            break;
        case OPT_NO_TREES:
            opts->no_trees = true;
            break;
        case OPT_VEL:
            opts->velocity_iterations = (int)value.integer;
            opts->single = true;
            break;
        case OPT_POS:
            opts->position_iterations = (int)value.integer;
            opts->single = true;
            break;
        default:
            opts->substeps = (int)value.integer;
            opts->single = true;
            break;
        }
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? PARSE_HELP : PARSE_ERROR;
    }
    if (!parse_names(scene, method, opts)) {
        return PARSE_ERROR;
    }
    if (opts->runs < 0) {
        opts->runs = quick ? 1 : 3;
    }
    opts->grid_warmup = quick ? GRID_QUICK_WARMUP : GRID_WARMUP;
    opts->grid_steps = quick ? GRID_QUICK_STEPS : GRID_STEPS;
    return PARSE_OK;
}

/* ------------------------------------------------------------ settings */

typedef struct bench_setting {
    rb_solver_type method;
    int velocity_iterations, position_iterations, substeps;
} bench_setting;

/* Appends `setting` unless it is already in the list. */
static void add_setting(bench_setting *list, int *count, bench_setting setting)
{
    for (int k = 0; k < *count; ++k) {
        const bench_setting *s = &list[k];
        if (s->method == setting.method && s->velocity_iterations == setting.velocity_iterations &&
            s->position_iterations == setting.position_iterations && s->substeps == setting.substeps) {
            return;
        }
    }
    assert(*count < SWEEP_MAX_SETTINGS);
    list[(*count)++] = setting;
}

/* The settings to run, in order (file comment: the sweep). Returns how
 * many; `list` has room for SWEEP_MAX_SETTINGS. */
static int build_settings(const bench_options *opts, bench_setting *list)
{
    static const int velocity_axis[] = {1, 2, 4, 8, 16, 32};
    static const int position_axis[] = {1, 2, 4, 8};
    static const int substep_axis[] = {1, 2, 4, 8};
    const rb_solver_settings defaults = rb_default_solver_settings();
    /* The engine's default first, then NGS, Box2D 2.4's method. */
    static const rb_solver_type method_order[] = {RB_SOLVER_SOFT_STEP, RB_SOLVER_NGS, RB_SOLVER_BAUMGARTE};
    int count = 0;
    for (size_t m = 0; m < sizeof method_order / sizeof method_order[0]; ++m) {
        const rb_solver_type method = method_order[m];
        if (!opts->methods[method]) {
            continue;
        }
        /* Baumgarte corrects inside the velocity iterations: position
         * iterations would do nothing, so its rows say 0. A soft step's
         * second kind of pass is its relax pass, in the same column. */
        const bool ngs = method != RB_SOLVER_BAUMGARTE;
        if (opts->single) {
            const int position = opts->position_iterations >= 0  ? opts->position_iterations
                                 : method == RB_SOLVER_SOFT_STEP ? defaults.relax_iterations
                                 : ngs                           ? defaults.position_iterations
                                                                 : 0;
            add_setting(list, &count,
                        (bench_setting){
                            .method = method,
                            .velocity_iterations = opts->velocity_iterations > 0 ? opts->velocity_iterations
                                                                                 : defaults.velocity_iterations,
                            .position_iterations = position,
                            .substeps = opts->substeps > 0 ? opts->substeps : defaults.substeps,
                        });
            continue;
        }
        const bench_setting centre = {method, SWEEP_VELOCITY, ngs ? SWEEP_POSITION : 0, SWEEP_SUBSTEPS};
        for (size_t k = 0; k < sizeof velocity_axis / sizeof velocity_axis[0]; ++k) {
            bench_setting s = centre;
            s.velocity_iterations = velocity_axis[k];
            add_setting(list, &count, s);
        }
        for (size_t k = 0; ngs && k < sizeof position_axis / sizeof position_axis[0]; ++k) {
            bench_setting s = centre;
            s.position_iterations = position_axis[k];
            add_setting(list, &count, s);
        }
        for (size_t k = 0; k < sizeof substep_axis / sizeof substep_axis[0]; ++k) {
            bench_setting s = centre;
            s.substeps = substep_axis[k];
            add_setting(list, &count, s);
        }
        for (size_t k = 0; k < sizeof substep_axis / sizeof substep_axis[0]; ++k) {
            bench_setting s = centre;
            s.substeps = substep_axis[k];
            s.velocity_iterations = SWEEP_DIAGONAL_BUDGET / substep_axis[k];
            add_setting(list, &count, s);
        }
        add_setting(list, &count,
                    (bench_setting){method, defaults.velocity_iterations,
                                    method == RB_SOLVER_SOFT_STEP ? defaults.relax_iterations
                                    : ngs                         ? defaults.position_iterations
                                                                  : 0,
                                    defaults.substeps});
    }
    return count;
}

/* --------------------------------------------------------------- scenes */

/* One scene in one world. */
typedef struct bench_world {
    bench_scene scene;
    rb_world *world;
    scene_chain chain;
    scene_joint_grid grid;
    scene_cantilever cantilever;
    rb_vec2 tip_start; /* m, the cantilever's outer plank's centre at the start */
    rb_body_id bob;    /* pendulum */
    double energy0;    /* J, pendulum's energy at release */
    int warmup_steps;  /* untimed */
    int timed_steps;
} bench_world;

static bool engine_failed(const char *what)
{
    fprintf(stderr, "bench_solver: %s failed: %s (%s)\n", what, rb_last_error(), rb_status_name(rb_last_status()));
    return false;
}

/* The bob hangs on a static pivot at the origin; it starts at (L, 0), the
 * rod horizontal, at rest. The joint is at the pivot, so the bob turns
 * with the rod: a rigid pendulum whose rotational energy is kept in E. */
static bool create_pendulum(bench_world *bw)
{
    rb_body_def pivot_def = rb_default_body_def();
    pivot_def.type = RB_BODY_STATIC;
    rb_body_id pivot;
    if (rb_body_create(bw->world, &pivot_def, &pivot) != RB_OK) {
        return engine_failed("rb_body_create (pivot)");
    }
    rb_body_def bob_def = rb_default_body_def();
    bob_def.type = RB_BODY_DYNAMIC;
    bob_def.position = rb_v2(PENDULUM_LENGTH, 0.0);
    if (rb_body_create(bw->world, &bob_def, &bw->bob) != RB_OK) {
        return engine_failed("rb_body_create (bob)");
    }
    rb_shape_def material = rb_default_shape_def();
    material.density = PENDULUM_DENSITY;
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = PENDULUM_RADIUS};
    rb_shape_id shape;
    if (rb_shape_create_circle(bw->world, bw->bob, &material, &circle, &shape) != RB_OK) {
        return engine_failed("rb_shape_create_circle (bob)");
    }
    rb_revolute_joint_def joint_def = rb_default_revolute_joint_def();
    rb_joint_id joint;
    if (rb_revolute_joint_def_at(&joint_def, bw->world, pivot, bw->bob, rb_v2(0.0, 0.0)) != RB_OK ||
        rb_revolute_joint_create(bw->world, &joint_def, &joint) != RB_OK) {
        return engine_failed("the pendulum's revolute joint");
    }
    return true;
}

/* Mechanical energy of the bob (J): kinetic, of its centre and its spin,
 * plus potential measured from its lowest position, L below the pivot. */
static double pendulum_energy(const rb_world *world, rb_body_id bob)
{
    const double mass = rb_body_mass(world, bob);
    const double inertia = rb_body_rotational_inertia(world, bob);
    const rb_vec2 velocity = rb_body_linear_velocity(world, bob);
    const double omega = rb_body_angular_velocity(world, bob);
    const double height = rb_body_world_center(world, bob).y + PENDULUM_LENGTH;
    return 0.5 * mass * rb_length_squared(velocity) + 0.5 * inertia * omega * omega - mass * BENCH_GRAVITY * height;
}

static bool bench_world_create(bench_scene scene, const bench_setting *setting, const bench_options *opts,
                               bench_world *bw)
{
    *bw = (bench_world){.scene = scene, .world = NULL};
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, BENCH_GRAVITY);
    def.enable_sleep = false; /* as the peers run: every body simulated every step */
    def.solver.type = setting->method;
    def.solver.relax_iterations = setting->position_iterations;
    def.solver.velocity_iterations = setting->velocity_iterations;
    def.solver.position_iterations = setting->position_iterations;
    def.solver.substeps = setting->substeps;
    def.solver.tree_pins = !opts->no_trees;
    if (rb_world_create(&def, &bw->world) != RB_OK) {
        return engine_failed("rb_world_create");
    }
    switch (scene) {
    case BENCH_CHAIN_HANG:
    case BENCH_CHAIN_SWING:
        bw->timed_steps = CHAIN_STEPS;
        if (scene_chain_create(bw->world, CHAIN_LINKS, CHAIN_HEAVY_DENSITY,
                               scene == BENCH_CHAIN_HANG ? SCENE_CHAIN_HANG : SCENE_CHAIN_SWING, &bw->chain) != RB_OK) {
            return engine_failed("scene_chain_create");
        }
        return true;
    case BENCH_PENDULUM:
        bw->timed_steps = PENDULUM_STEPS;
        if (!create_pendulum(bw)) {
            return false;
        }
        bw->energy0 = pendulum_energy(bw->world, bw->bob);
        return true;
    case BENCH_JOINT_GRID:
        bw->warmup_steps = opts->grid_warmup;
        bw->timed_steps = opts->grid_steps;
        if (scene_joint_grid_create(bw->world, GRID_N, &bw->grid) != RB_OK) {
            return engine_failed("scene_joint_grid_create");
        }
        return true;
    case BENCH_CHAIN10:
        bw->timed_steps = CHAIN10_STEPS;
        if (scene_chain_create(bw->world, CHAIN10_LINKS, 0.0, SCENE_CHAIN_SWING, &bw->chain) != RB_OK) {
            return engine_failed("scene_chain_create");
        }
        return true;
    case BENCH_CANTILEVER:
        bw->timed_steps = CANTILEVER_STEPS;
        if (scene_cantilever_create(bw->world, &bw->cantilever) != RB_OK) {
            return engine_failed("scene_cantilever_create");
        }
        bw->tip_start = rb_body_world_center(bw->world, bw->cantilever.plank2);
        return true;
    case BENCH_SCENE_COUNT:
        break;
    }
    return false;
}

static bool body_is_finite(const rb_world *world, rb_body_id body)
{
    const rb_vec2 p = rb_body_position(world, body);
    const rb_vec2 v = rb_body_linear_velocity(world, body);
    return isfinite(p.x) && isfinite(p.y) && isfinite(rb_body_angle(world, body)) && isfinite(v.x) && isfinite(v.y) &&
           isfinite(rb_body_angular_velocity(world, body));
}

/* Whether every body of the scene has a finite pose and velocity. */
static bool scene_is_finite(const bench_world *bw)
{
    bool finite = true;
    switch (bw->scene) {
    case BENCH_CHAIN_HANG:
    case BENCH_CHAIN_SWING:
    case BENCH_CHAIN10:
        /* Body B of each joint: every link and the heavy box. */
        for (int k = 0; finite && k < bw->chain.joint_count; ++k) {
            finite = body_is_finite(bw->world, rb_joint_body_b(bw->world, bw->chain.joints[k]));
        }
        break;
    case BENCH_PENDULUM:
        finite = body_is_finite(bw->world, bw->bob);
        break;
    case BENCH_JOINT_GRID:
        for (int k = 0; finite && k < bw->grid.n * bw->grid.n; ++k) {
            finite = body_is_finite(bw->world, scene_body_at(bw->grid.first_body, k));
        }
        break;
    case BENCH_CANTILEVER:
        finite = body_is_finite(bw->world, bw->cantilever.plank1) && body_is_finite(bw->world, bw->cantilever.plank2);
        break;
    case BENCH_SCENE_COUNT:
        break;
    }
    return finite;
}

/* ----------------------------------------------------------------- runs */

/* Figures of one scene at one setting. */
typedef struct bench_row {
    bench_scene scene;
    bench_setting setting;
    int warmup_steps;              /* planned */
    int timed_done;                /* timed steps done in the last run */
    double median_ms;              /* NAN when no timed step was done */
    double worst_gap, final_gap;   /* m */
    double drift_max, drift_final; /* pendulum: |E - E0| / E0 */
    double sag_max;                /* m, cantilever: the outer plank's largest distance from its start */
    bool finite;                   /* every body's state finite at the end of the last run */
    bool diverged;                 /* the last run stopped early (file comment) */
} bench_row;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e3 * (double)ts.tv_sec + 1e-6 * (double)ts.tv_nsec;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a;
    double y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n values (sorted in place), averaging the middle two
 * when n is even; NAN for none. */
static double median(double *values, int n)
{
    if (n == 0) {
        return NAN;
    }
    qsort(values, (size_t)n, sizeof *values, compare_doubles);
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/* The larger of a running worst and a new value, a NaN sticking once
 * seen: a blown-up run must not look accurate. */
static double worse(double worst, double value) { return isnan(worst) || value <= worst ? worst : value; }

/* One run of the row's scene and setting in a fresh world; fills the
 * row's figures and *run_median. `times` has room for the timed steps. */
static bool run_once(const bench_options *opts, double *times, bench_row *row, double *run_median)
{
    bench_world bw;
    if (!bench_world_create(row->scene, &row->setting, opts, &bw)) {
        rb_world_destroy(bw.world);
        return false;
    }
    row->warmup_steps = bw.warmup_steps;
    row->worst_gap = row->final_gap = 0.0;
    row->drift_max = row->drift_final = 0.0;
    row->sag_max = 0.0;
    row->diverged = false;
    int timed = 0;
    for (int step = 0; step < bw.warmup_steps + bw.timed_steps; ++step) {
        const double start = now_ms();
        const rb_status status = rb_world_step(bw.world, BENCH_DT);
        const double elapsed = now_ms() - start;
        if (status != RB_OK) {
            engine_failed("rb_world_step"); /* before the world goes, while its message holds */
            rb_world_destroy(bw.world);
            return false;
        }
        if (step >= bw.warmup_steps) {
            times[timed++] = elapsed;
        }
        row->final_gap = rb_world_statistics(bw.world).max_joint_gap;
        row->worst_gap = worse(row->worst_gap, row->final_gap);
        if (row->scene == BENCH_PENDULUM) {
            row->drift_final = fabs(pendulum_energy(bw.world, bw.bob) - bw.energy0) / bw.energy0;
            row->drift_max = worse(row->drift_max, row->drift_final);
        }
        if (row->scene == BENCH_CANTILEVER) {
            const rb_vec2 tip = rb_body_world_center(bw.world, bw.cantilever.plank2);
            row->sag_max = worse(row->sag_max, rb_distance(tip, bw.tip_start));
        }
        /* Written so that NaN stops the run too. */
        if (!(row->final_gap <= BENCH_DIVERGED_GAP) || !isfinite(row->drift_final)) {
            row->diverged = true;
            break;
        }
    }
    row->finite = scene_is_finite(&bw);
    row->timed_done = timed;
    *run_median = median(times, timed);
    rb_world_destroy(bw.world);
    return true;
}

/* Runs one row `runs` times; `times` has room for every timed step of
 * the scene, `run_medians` for `runs` values. */
static bool run_row(const bench_options *opts, double *times, double *run_medians, bench_row *row)
{
    int counted = 0;
    for (int run = 0; run < opts->runs; ++run) {
        double run_median;
        if (!run_once(opts, times, row, &run_median)) {
            return false;
        }
        if (!isnan(run_median)) {
            run_medians[counted++] = run_median;
        }
    }
    row->median_ms = median(run_medians, counted);
    return true;
}

/* ------------------------------------------------------------- reports */

static void print_table_header(void)
{
    printf("%-11s %-9s %4s %4s %4s %10s %13s %13s %10s %11s %10s %6s %8s\n", "scene", "method", "vel", "pos", "sub",
           "ms/step", "worst gap m", "final gap m", "drift max", "drift final", "sag m", "finite", "diverged");
}

static void print_row(const bench_row *r)
{
    const bench_setting *s = &r->setting;
    printf("%-11s %-9s %4d %4d %4d", bench_scene_names[r->scene], method_name(s->method), s->velocity_iterations,
           s->position_iterations, s->substeps);
    if (isnan(r->median_ms)) {
        printf(" %10s", "-"); /* diverged before any timed step */
    } else {
        printf(" %10.4f", r->median_ms);
    }
    printf(" %13.3e %13.3e", r->worst_gap, r->final_gap);
    if (r->scene == BENCH_PENDULUM) {
        printf(" %10.3e %11.3e", r->drift_max, r->drift_final);
    } else {
        printf(" %10s %11s", "-", "-");
    }
    if (r->scene == BENCH_CANTILEVER) {
        printf(" %10.3e", r->sag_max);
    } else {
        printf(" %10s", "-");
    }
    printf(" %6s %8s\n", r->finite ? "yes" : "no", r->diverged ? "yes" : "no");
}

/* The CSV rows. The energy drift is empty except for the pendulum, the
 * sag except for the cantilever, the median when no timed step was
 * done. A failed write shows in the
 * stream's error flag, which atomic_file_commit checks. */
static void write_csv(FILE *file, const bench_options *opts, const bench_row *rows, int count)
{
    fputs("scene,correction,velocity_iterations,position_iterations,substeps,runs,warmup_steps,timed_steps,"
          "median_ms,worst_gap_m,final_gap_m,energy_drift_max,energy_drift_final,tip_sag_m,finite,diverged\n",
          file);
    for (int k = 0; k < count; ++k) {
        const bench_row *r = &rows[k];
        const bench_setting *s = &r->setting;
        fprintf(file, "%s,%s,%d,%d,%d,%d,%d,%d,", bench_scene_names[r->scene], method_name(s->method),
                s->velocity_iterations, s->position_iterations, s->substeps, opts->runs, r->warmup_steps,
                r->timed_done);
        if (!isnan(r->median_ms)) {
            fprintf(file, "%.6g", r->median_ms);
        }
        fprintf(file, ",%.6g,%.6g,", r->worst_gap, r->final_gap);
        if (r->scene == BENCH_PENDULUM) {
            fprintf(file, "%.6g,%.6g", r->drift_max, r->drift_final);
        } else {
            fputc(',', file);
        }
        fputc(',', file);
        if (r->scene == BENCH_CANTILEVER) {
            fprintf(file, "%.6g", r->sag_max);
        }
        fprintf(file, ",%s,%s\n", r->finite ? "yes" : "no", r->diverged ? "yes" : "no");
    }
}

int main(int argc, char **argv)
{
    bench_options opts;
    switch (parse_options(argc, argv, &opts)) {
    case PARSE_HELP:
        cli_print_help(&command, stdout);
        return EXIT_SUCCESS;
    case PARSE_ERROR:
        return CLI_EXIT_USAGE;
    case PARSE_OK:
        break;
    }
    bench_setting settings[SWEEP_MAX_SETTINGS];
    const int setting_count = build_settings(&opts, settings);
    /* Opened before the runs, so that a bad path fails at once; written
     * through an atomic_file (io/atomic_file.h), so an interrupted or
     * failed run leaves no half-written CSV. */
    atomic_file csv;
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_open(&csv, opts.csv_path, error, sizeof error)) {
        fprintf(stderr, "bench_solver: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    const int scene_steps[] = {CHAIN_STEPS, PENDULUM_STEPS, CHAIN10_STEPS, CANTILEVER_STEPS};
    int most_steps = 0;
    for (size_t k = 0; k < sizeof scene_steps / sizeof scene_steps[0]; ++k) {
        most_steps = scene_steps[k] > most_steps ? scene_steps[k] : most_steps;
    }
    const int max_steps = most_steps > opts.grid_steps ? most_steps : opts.grid_steps;
    double *times = malloc((size_t)max_steps * sizeof *times);
    double *run_medians = malloc((size_t)opts.runs * sizeof *run_medians);
    bench_row *rows = malloc((size_t)(BENCH_SCENE_COUNT * setting_count) * sizeof *rows);
    bool ok = times != NULL && run_medians != NULL && rows != NULL;
    if (!ok) {
        fputs("bench_solver: out of memory\n", stderr);
    }
    int count = 0;
    for (int scene = 0; ok && scene < BENCH_SCENE_COUNT; ++scene) {
        if (!opts.scenes[scene]) {
            continue;
        }
        print_table_header();
        for (int k = 0; ok && k < setting_count; ++k) {
            rows[count] = (bench_row){.scene = (bench_scene)scene, .setting = settings[k]};
            ok = run_row(&opts, times, run_medians, &rows[count]);
            if (ok) {
                print_row(&rows[count]);
                fflush(stdout);
                count += 1;
            }
        }
        printf("\n");
    }
    free(times);
    free(run_medians);
    if (!ok) {
        free(rows);
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    write_csv(csv.stream, &opts, rows, count);
    free(rows);
    if (!atomic_file_commit(&csv, error, sizeof error)) {
        fprintf(stderr, "bench_solver: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("runs=%d csv=%s\n", opts.runs, opts.csv_path);
    return EXIT_SUCCESS;
}
