/* SPDX-License-Identifier: MIT */
/* bench_engine: time sinew's engine on the peer benchmark scenes, and
 * on a scaling sweep.
 *
 * The peer harnesses' protocol (docs/benchmarks.md), so the figures compare with
 * box2d24_bench and chipmunk_bench run on the same machine: dt = 1/60 s,
 * `warmup` untimed steps, then `steps` steps each timed alone with
 * clock_gettime(CLOCK_MONOTONIC); gravity (0, -10), friction 0.6,
 * restitution 0, no sleeping. The whole run is repeated `runs` times,
 * each in a fresh world; the report gives the median over runs of each
 * run's median step time, and likewise of each run's 10th and 90th
 * percentiles (percentile indices as the peers: n/2, n/10, 9n/10 of the
 * sorted times), and of each run's median time in the collide phases
 * (pairs and narrow phase) and in the solver (everything from preparing
 * the constraints to storing the impulses), from rb_world_profile().
 *
 * Scenes (models/scenes): pyramid20 and pyramid100 (the peers' pyramid,
 * base 20 and 100), many_pyramids (10 pyramids of base 20 side by side,
 * 2,100 boxes), joint_grid (the peers' 100 x 100 net), chain_hang and
 * chain_swing (the peers' 40-link chain with a 100:1 end box), balls (the
 * original report's 50 balls, seed 1, gravity (0, -9.81), drag applied before each
 * step outside the timing), rain (300 balls falling a few at a time on
 * the base-100 pyramid, seed 1: the broad phase's searches around the
 * shapes that moved), and the sweep: pyramids of 105, 300, 1,035,
 * 3,003 and 10,011 boxes, whose log-log slope of time per step against
 * bodies between 1,000 and 10,000 is printed (1 for linear cost).
 *
 * Accuracy over every step of a run (warm-up included): the deepest
 * overlap and the largest joint gap left after a step
 * (rb_world_statistics). What holds: a pyramid stands when no box moved
 * more than 0.25 m sideways; the joint grid when every body is finite and
 * no gap exceeded 0.5 m; a chain when no gap exceeded 0.05 m; the rain
 * when every body is finite (the boxes it knocks more than 0.25 m
 * sideways are counted, as for a pyramid).
 *
 * Prints one `engine=sinew scene=... median_ms=...` line per scene and
 * solver, and writes a CSV (header row; written to a temporary name and
 * renamed). Exit status: 0 success, 1 failure, 2 bad command line.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/options.h"
#include "io/atomic_file.h"
#include "rb/rb.h"
#include "scenes/scenes.h"

enum {
    OPT_SCENE,
    OPT_SOLVER,
    OPT_RUNS,
    OPT_STEPS,
    OPT_WARMUP,
    OPT_VEL,
    OPT_POS,
    OPT_SUBSTEPS,
    OPT_GRID,
    OPT_CSV,
    OPT_QUICK
};

static const cli_option options_table[] = {
    {.name = "scene",
     .id = OPT_SCENE,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "pyramid20, pyramid100, many_pyramids, joint_grid, chain_hang, chain_swing,\n"
             "balls, rain, sweep (pyramids of 105 .. 10,011 boxes), peers (the peers' five\n"
             "scenes), all (all but the sweep), or everything",
     .fallback = "all"},
    {.name = "solver",
     .id = OPT_SOLVER,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "soft_step, ngs, baumgarte or all",
     .fallback = "the engine's"},
    {.name = "runs",
     .id = OPT_RUNS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "repetitions of the whole run",
     .min = 1,
     .max = 1000,
     .fallback = "5"},
    {.name = "steps",
     .id = OPT_STEPS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "timed steps per run",
     .min = 1,
     .max = 1000000,
     .fallback = "300"},
    {.name = "warmup",
     .id = OPT_WARMUP,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "untimed steps before them",
     .min = 0,
     .max = 1000000,
     .fallback = "60"},
    {.name = "vel",
     .id = OPT_VEL,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "velocity iterations",
     .min = 1,
     .max = 1000,
     .fallback = "the engine's"},
    {.name = "pos",
     .id = OPT_POS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "position iterations (NGS) or relax passes (soft step)",
     .min = 0,
     .max = 1000,
     .fallback = "the engine's"},
    {.name = "substeps",
     .id = OPT_SUBSTEPS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "substeps per step",
     .min = 1,
     .max = 1000,
     .fallback = "the engine's"},
    {.name = "grid",
     .id = OPT_GRID,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "the joint grid's side (as Box2D v3's harness's --grid)",
     .min = 2,
     .max = 1000,
     .fallback = "100"},
    {.name = "csv",
     .id = OPT_CSV,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "results",
     .fallback = "bench_engine.csv"},
    {.name = "quick",
     .id = OPT_QUICK,
     .kind = CLI_FLAG,
     .help = "smoke test: 1 run, 10 warm-up and 20 timed steps\n(explicit --runs, --warmup, --steps still win)"},
};

static const cli_command command = {
    .name = "bench_engine",
    .operands = "[options]",
    .about = "Times rb_world_step on the peer benchmark scenes (docs/benchmarks.md) and a scaling sweep.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
};

#define BENCH_DT (1.0 / 60.0)       /* s, the peers' step */
#define BENCH_PEER_GRAVITY (-10.0)  /* m/s², the peers' */
#define BENCH_BALLS_GRAVITY (-9.81) /* m/s², the original's */
#define BENCH_BALLS_COUNT 50
#define BENCH_BALLS_SEED 1
#define BENCH_RAIN_BASE 100
#define BENCH_RAIN_BALLS 300
#define BENCH_RAIN_SEED 1
#define BENCH_MOVED_THRESHOLD 0.25 /* m, the peers' collapse indicator */
#define BENCH_GRID_MAX_GAP 0.5     /* m: a wider gap is a torn net */
#define BENCH_CHAIN_MAX_GAP 0.05   /* m, the bar for the swinging chain */
#define BENCH_CHAIN_LINKS 40
#define BENCH_CHAIN_HEAVY_DENSITY 20.0 /* kg/m², 100 x a link */
#define BENCH_GRID_SIZE 100
#define BENCH_MANY_PYRAMIDS 10
#define BENCH_MANY_PYRAMIDS_BASE 20
/* The sweep's slope is fitted between these body counts. */
#define BENCH_SLOPE_FROM 1000
#define BENCH_SLOPE_TO 10100

/* ------------------------------------------------------------- options */

typedef enum bench_kind {
    KIND_PYRAMID,
    KIND_MANY_PYRAMIDS,
    KIND_JOINT_GRID,
    KIND_CHAIN,
    KIND_BALLS,
    KIND_RAIN
} bench_kind;

typedef struct bench_scene {
    const char *name;
    bench_kind kind;
    int size;   /* pyramid base, chain layout (scene_chain_layout); the grid's is --grid */
    bool peer;  /* one of the peers' scenes */
    bool sweep; /* one of the scaling sweep's pyramids */
} bench_scene;

static const bench_scene bench_scenes[] = {
    {"pyramid20", KIND_PYRAMID, 20, true, false},
    {"pyramid100", KIND_PYRAMID, 100, true, false},
    {"many_pyramids", KIND_MANY_PYRAMIDS, BENCH_MANY_PYRAMIDS_BASE, false, false},
    {"joint_grid", KIND_JOINT_GRID, 0, true, false}, /* of side --grid */
    {"chain_hang", KIND_CHAIN, SCENE_CHAIN_HANG, true, false},
    {"chain_swing", KIND_CHAIN, SCENE_CHAIN_SWING, true, false},
    {"balls", KIND_BALLS, BENCH_BALLS_COUNT, false, false},
    {"rain", KIND_RAIN, BENCH_RAIN_BASE, false, false},
    {"sweep105", KIND_PYRAMID, 14, false, true},
    {"sweep300", KIND_PYRAMID, 24, false, true},
    {"sweep1035", KIND_PYRAMID, 45, false, true},
    {"sweep3003", KIND_PYRAMID, 77, false, true},
    {"sweep10011", KIND_PYRAMID, 141, false, true},
};
enum { BENCH_SCENE_COUNT = sizeof bench_scenes / sizeof bench_scenes[0] };

typedef struct bench_options {
    bool scenes[BENCH_SCENE_COUNT];     /* which to run */
    bool solvers[RB_SOLVER_TYPE_COUNT]; /* with which solvers */
    int runs;                           /* 1 .. 1000 */
    int steps;                          /* timed steps per run, 1 .. 1e6 */
    int warmup;                         /* 0 .. 1e6 */
    int velocity_iterations;            /* 1 .. 1000, or 0 for the engine default */
    int position_iterations;            /* 0 .. 1000, or -1 for the engine default */
    int substeps;                       /* 1 .. 1000, or 0 for the engine default */
    int grid;                           /* the joint grid's side, 2 .. 1000 */
    const char *csv_path;
} bench_options;

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

static bool select_scenes(const char *name, bench_options *opts)
{
    bool any = false;
    for (int k = 0; k < BENCH_SCENE_COUNT; ++k) {
        const bench_scene *scene = &bench_scenes[k];
        bool everything = strcmp(name, "everything") == 0;
        bool all = strcmp(name, "all") == 0 && !scene->sweep;
        bool peers = strcmp(name, "peers") == 0 && scene->peer;
        bool sweep = strcmp(name, "sweep") == 0 && scene->sweep;
        opts->scenes[k] = everything || all || peers || sweep || strcmp(name, scene->name) == 0;
        any = any || opts->scenes[k];
    }
    if (!any) {
        fprintf(stderr,
                "bench_engine: --scene expects pyramid20, pyramid100, many_pyramids, joint_grid, chain_hang, "
                "chain_swing, balls, rain, sweep, peers, all or everything, got \"%s\"\n",
                name);
    }
    return any;
}

static bool select_solvers(const char *name, bench_options *opts)
{
    rb_solver_type type = rb_default_solver_settings().type;
    bool every = name != NULL && strcmp(name, "all") == 0;
    if (name != NULL && !every && rb_solver_type_from_name(name, &type) != RB_OK) {
        fprintf(stderr, "bench_engine: --solver: %s (or all)\n", rb_last_error());
        return false;
    }
    for (int t = 0; t < RB_SOLVER_TYPE_COUNT; ++t) {
        opts->solvers[t] = every || t == (int)type;
    }
    return true;
}

static parse_result parse_options(int argc, char **argv, bench_options *opts)
{
    *opts = (bench_options){.runs = -1,
                            .steps = -1,
                            .warmup = -1,
                            .position_iterations = -1,
                            .grid = BENCH_GRID_SIZE,
                            .csv_path = "bench_engine.csv"};
    bool quick = false;
    const char *scene = "all";
    const char *solver = NULL;
    cli_parser parser;
    cli_parser_start(&parser, &command, argc - 1, argv + 1);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_SCENE:
            scene = value.text;
            break;
        case OPT_SOLVER:
            solver = value.text;
            break;
        case OPT_RUNS:
            opts->runs = (int)value.integer;
            break;
        case OPT_STEPS:
            opts->steps = (int)value.integer;
            break;
        case OPT_WARMUP:
            opts->warmup = (int)value.integer;
            break;
        case OPT_VEL:
            opts->velocity_iterations = (int)value.integer;
            break;
        case OPT_POS:
            opts->position_iterations = (int)value.integer;
            break;
        case OPT_SUBSTEPS:
            opts->substeps = (int)value.integer;
            break;
        case OPT_GRID:
            opts->grid = (int)value.integer;
            break;
        case OPT_CSV:
            opts->csv_path = value.text;
            break;
        default:
            quick = true;
            break;
        }
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? PARSE_HELP : PARSE_ERROR;
    }
    if (!select_scenes(scene, opts) || !select_solvers(solver, opts)) {
        return PARSE_ERROR;
    }
    if (opts->runs < 0) {
        opts->runs = quick ? 1 : 5;
    }
    if (opts->warmup < 0) {
        opts->warmup = quick ? 10 : 60;
    }
    if (opts->steps < 0) {
        opts->steps = quick ? 20 : 300;
    }
    return PARSE_OK;
}

/* ---------------------------------------------------------- statistics */

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a;
    double y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The peers' percentile: element floor(n·q) of the sorted values. */
static double sorted_percentile(const double *sorted, int n, int numerator, int denominator)
{
    return sorted[((long)n * numerator) / denominator];
}

/* The median of n values (sorted in place), averaging the middle two
 * when n is even. */
static double median(double *values, int n)
{
    qsort(values, (size_t)n, sizeof *values, compare_doubles);
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/* ---------------------------------------------------------------- runs */

/* Figures of one scene and solver over all its runs. */
typedef struct bench_result {
    int scene;                 /* index in bench_scenes */
    int bodies;                /* dynamic bodies */
    int contacts;              /* at the end of the last run */
    int joints;                /* likewise */
    rb_solver_settings solver; /* as used */
    double median_ms, p10_ms, p90_ms;
    double collide_ms, solve_ms; /* medians over runs of each run's median */
    size_t bytes;                /* the world's heap at the end of the last run */
    double max_penetration;      /* m, worst after any step of any run */
    double max_joint_gap;        /* m, likewise */
    double top_x, top_y;         /* m, pyramids' last top box at the end of the last run */
    int moved_boxes;             /* pyramids and rain: boxes moved > 0.25 m sideways in the last run */
    double max_shift;            /* m, largest sideways shift of a box */
    bool finite;                 /* every body's position finite at the end of every run */
    int escaped;                 /* balls outside the box at the end of the last run */
    bool holds;                  /* what the scene must keep, kept (see the top of the file) */
    double allocations_per_step; /* heap allocations per timed step, worst run */
    bool deterministic;          /* every run ended in the same state */
    uint64_t state_hash;         /* rb_world_state_hash at the end of the first run */
} bench_result;

/* The state of one scene in one run. */
typedef struct bench_world {
    rb_world *world;
    scene_pyramid pyramid;
    scene_balls balls;
    scene_joint_grid grid;
    scene_chain chain;
    scene_rain rain;
    rb_body_id first_body; /* the scene's dynamic bodies are a run of ids from it */
    int body_count;
    double *start_x; /* m, the dynamic bodies' start x */
} bench_world;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e3 * (double)ts.tv_sec + 1e-6 * (double)ts.tv_nsec;
}

static bool engine_failed(const char *what)
{
    fprintf(stderr, "bench_engine: %s failed: %s (%s)\n", what, rb_last_error(), rb_status_name(rb_last_status()));
    return false;
}

static rb_status build_scene(const bench_scene *scene, const bench_options *opts, bench_world *bw)
{
    rb_status status = RB_OK;
    switch (scene->kind) {
    case KIND_PYRAMID:
        status = scene_pyramid_create(bw->world, scene->size, &bw->pyramid);
        bw->first_body = bw->pyramid.first_box;
        bw->body_count = bw->pyramid.box_count;
        break;
    case KIND_MANY_PYRAMIDS:
        status = scene_many_pyramids_create(bw->world, BENCH_MANY_PYRAMIDS, scene->size, &bw->pyramid);
        bw->first_body = bw->pyramid.first_box;
        bw->body_count = bw->pyramid.box_count;
        break;
    case KIND_JOINT_GRID:
        status = scene_joint_grid_create(bw->world, opts->grid, &bw->grid);
        bw->first_body = bw->grid.first_body;
        bw->body_count = opts->grid * opts->grid;
        break;
    case KIND_CHAIN:
        status = scene_chain_create(bw->world, BENCH_CHAIN_LINKS, BENCH_CHAIN_HEAVY_DENSITY,
                                    (scene_chain_layout)scene->size, &bw->chain);
        bw->first_body = scene_body_at(bw->chain.pin, 1);
        bw->body_count = BENCH_CHAIN_LINKS + 1;
        break;
    case KIND_BALLS:
        status = scene_balls_create(bw->world, scene->size, BENCH_BALLS_SEED, &bw->balls);
        bw->first_body = bw->balls.balls[0];
        bw->body_count = bw->balls.count;
        break;
    case KIND_RAIN:
        status = scene_rain_create(bw->world, scene->size, BENCH_RAIN_BALLS, BENCH_RAIN_SEED, &bw->rain);
        bw->first_body = bw->rain.pyramid.first_box;
        bw->body_count = bw->rain.pyramid.box_count;
        break;
    }
    return status;
}

static bool bench_world_create(const bench_scene *scene, rb_solver_type solver, const bench_options *opts,
                               bench_world *bw)
{
    *bw = (bench_world){.world = NULL};
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, scene->kind == KIND_BALLS ? BENCH_BALLS_GRAVITY : BENCH_PEER_GRAVITY);
    def.enable_sleep = false; /* as the peers run: every body simulated every step */
    def.solver.type = solver;
    if (opts->velocity_iterations > 0) {
        def.solver.velocity_iterations = opts->velocity_iterations;
    }
    if (opts->position_iterations >= 0) {
        def.solver.position_iterations = opts->position_iterations;
        def.solver.relax_iterations = opts->position_iterations;
    }
    if (opts->substeps > 0) {
        def.solver.substeps = opts->substeps;
    }
    if (rb_world_create(&def, &bw->world) != RB_OK) {
        return engine_failed("rb_world_create");
    }
    if (build_scene(scene, opts, bw) != RB_OK) {
        return engine_failed("building the scene");
    }
    bw->start_x = malloc((size_t)bw->body_count * sizeof *bw->start_x);
    if (bw->start_x == NULL) {
        fputs("bench_engine: out of memory\n", stderr);
        return false;
    }
    for (int k = 0; k < bw->body_count; ++k) {
        bw->start_x[k] = rb_body_position(bw->world, scene_body_at(bw->first_body, k)).x;
    }
    return true;
}

static void bench_world_destroy(bench_world *bw)
{
    rb_world_destroy(bw->world);
    free(bw->start_x);
    *bw = (bench_world){.world = NULL};
}

/* One step, its wall time and its profile's collide and solve times. */
static bool bench_step(const bench_scene *scene, bench_world *bw, double *elapsed_ms, double *collide_ms,
                       double *solve_ms)
{
    if (scene->kind == KIND_BALLS && scene_balls_apply_drag(bw->world, &bw->balls) != RB_OK) {
        return engine_failed("scene_balls_apply_drag");
    }
    double start = now_ms();
    rb_status status = rb_world_step(bw->world, BENCH_DT);
    *elapsed_ms = now_ms() - start;
    rb_profile profile = rb_world_profile(bw->world);
    *collide_ms = profile.pairs + profile.collide;
    *solve_ms = profile.prepare + profile.substep_callback + profile.integrate_velocities + profile.warm_start +
                profile.solve_velocities + profile.integrate_positions + profile.correct_positions + profile.relax +
                profile.restitution + profile.store_impulses;
    return status == RB_OK || engine_failed("rb_world_step");
}

/* The end-of-run figures, kept from the last run. */
static void measure_scene(const bench_scene *scene, const bench_world *bw, bench_result *result)
{
    rb_world *world = bw->world;
    rb_statistics statistics = rb_world_statistics(world);
    result->contacts = statistics.contact_count;
    result->joints = statistics.joint_count;
    result->solver = rb_world_solver_settings(world);
    result->bodies = bw->body_count;
    result->bytes = rb_world_bytes_in_use(world);
    result->moved_boxes = 0;
    result->max_shift = 0.0;
    result->escaped = 0;
    for (int k = 0; k < bw->body_count; ++k) {
        rb_vec2 p = rb_body_position(world, scene_body_at(bw->first_body, k));
        double shift = fabs(p.x - bw->start_x[k]);
        result->finite = result->finite && rb_vec2_is_finite(p);
        result->moved_boxes += !(shift <= BENCH_MOVED_THRESHOLD);
        result->max_shift = fmax(result->max_shift, shift);
        if (scene->kind == KIND_BALLS) {
            result->escaped += !(p.x >= 0.0 && p.x <= SCENE_BALLS_WIDTH && p.y >= 0.0 && p.y <= SCENE_BALLS_HEIGHT);
        }
    }
    if (scene->kind == KIND_PYRAMID || scene->kind == KIND_MANY_PYRAMIDS) {
        rb_vec2 top = rb_body_position(world, bw->pyramid.top);
        result->top_x = top.x;
        result->top_y = top.y;
    }
    switch (scene->kind) {
    case KIND_PYRAMID:
    case KIND_MANY_PYRAMIDS:
        result->holds = result->finite && result->moved_boxes == 0;
        break;
    case KIND_JOINT_GRID:
        result->holds = result->finite && result->max_joint_gap <= BENCH_GRID_MAX_GAP;
        break;
    case KIND_CHAIN:
        result->holds = result->finite && result->max_joint_gap <= BENCH_CHAIN_MAX_GAP;
        break;
    case KIND_BALLS:
        result->holds = result->finite && result->escaped == 0;
        break;
    case KIND_RAIN:
        result->holds = result->finite;
        break;
    }
}

/* The scratch of one scene's runs: `steps` step times, collide and solve
 * times, and each run's medians and percentiles. */
typedef struct bench_scratch {
    double *times, *collide, *solve;
    double *run_median, *run_p10, *run_p90, *run_collide, *run_solve;
} bench_scratch;

/* Steps the world once, keeping the worst overlap and joint gap. */
static bool measured_step(const bench_scene *scene, bench_world *bw, bench_result *result, double *elapsed_ms,
                          double *collide_ms, double *solve_ms)
{
    if (!bench_step(scene, bw, elapsed_ms, collide_ms, solve_ms)) {
        return false;
    }
    rb_statistics statistics = rb_world_statistics(bw->world);
    result->max_penetration = fmax(result->max_penetration, statistics.max_penetration);
    result->max_joint_gap = fmax(result->max_joint_gap, statistics.max_joint_gap);
    return true;
}

/* Runs one scene with one solver `runs` times. */
static bool bench_scene_run(int scene_index, rb_solver_type solver, const bench_options *opts,
                            const bench_scratch *scratch, bench_result *result)
{
    const bench_scene *scene = &bench_scenes[scene_index];
    *result = (bench_result){.scene = scene_index, .deterministic = true, .finite = true};
    uint64_t first_hash = 0;
    for (int run = 0; run < opts->runs; ++run) {
        bench_world bw;
        bool ok = bench_world_create(scene, solver, opts, &bw);
        double ignored[3];
        for (int step = 0; ok && step < opts->warmup; ++step) {
            ok = measured_step(scene, &bw, result, &ignored[0], &ignored[1], &ignored[2]);
        }
        uint64_t allocations_before = rb_allocation_count();
        for (int step = 0; ok && step < opts->steps; ++step) {
            ok = measured_step(scene, &bw, result, &scratch->times[step], &scratch->collide[step],
                               &scratch->solve[step]);
        }
        uint64_t allocations = rb_allocation_count() - allocations_before;
        if (!ok) {
            bench_world_destroy(&bw);
            return false;
        }
        result->allocations_per_step = fmax(result->allocations_per_step, (double)allocations / opts->steps);
        uint64_t hash = rb_world_state_hash(bw.world);
        if (run == 0) {
            first_hash = hash;
        }
        result->deterministic = result->deterministic && hash == first_hash;
        result->state_hash = first_hash;
        measure_scene(scene, &bw, result);
        bench_world_destroy(&bw);

        qsort(scratch->times, (size_t)opts->steps, sizeof *scratch->times, compare_doubles);
        scratch->run_median[run] = sorted_percentile(scratch->times, opts->steps, 1, 2);
        scratch->run_p10[run] = sorted_percentile(scratch->times, opts->steps, 1, 10);
        scratch->run_p90[run] = sorted_percentile(scratch->times, opts->steps, 9, 10);
        scratch->run_collide[run] = median(scratch->collide, opts->steps);
        scratch->run_solve[run] = median(scratch->solve, opts->steps);
    }
    result->median_ms = median(scratch->run_median, opts->runs);
    result->p10_ms = median(scratch->run_p10, opts->runs);
    result->p90_ms = median(scratch->run_p90, opts->runs);
    result->collide_ms = median(scratch->run_collide, opts->runs);
    result->solve_ms = median(scratch->run_solve, opts->runs);
    return true;
}

/* ------------------------------------------------------------- reports */

static void print_result(const bench_options *opts, const bench_result *r)
{
    const bench_scene *scene = &bench_scenes[r->scene];
    const rb_solver_settings *s = &r->solver;
    printf("engine=sinew scene=%s solver=%s bodies=%d contacts=%d joints=%d vel_iters=%d pos_iters=%d "
           "relax_iters=%d substeps=%d warmup=%d timed_steps=%d runs=%d median_ms=%.4f p10_ms=%.4f p90_ms=%.4f "
           "collide_ms=%.4f solve_ms=%.4f max_penetration=%.4g max_joint_gap=%.4g",
           scene->name, rb_solver_type_name(s->type), r->bodies, r->contacts, r->joints, s->velocity_iterations,
           s->position_iterations, s->relax_iterations, s->substeps, opts->warmup, opts->steps, opts->runs,
           r->median_ms, r->p10_ms, r->p90_ms, r->collide_ms, r->solve_ms, r->max_penetration, r->max_joint_gap);
    if (scene->kind == KIND_PYRAMID || scene->kind == KIND_MANY_PYRAMIDS) {
        printf(" top_x=%.4f top_y=%.4f", r->top_x, r->top_y);
    }
    if (scene->kind == KIND_PYRAMID || scene->kind == KIND_MANY_PYRAMIDS || scene->kind == KIND_RAIN) {
        printf(" lateral_gt_0.25=%d max_abs_dx=%.3f", r->moved_boxes, r->max_shift);
    }
    if (scene->kind == KIND_BALLS) {
        printf(" escaped=%d", r->escaped);
    }
    printf(" holds=%s bytes=%zu allocations_per_step=%.3g deterministic=%s state_hash=%016" PRIx64 "\n",
           r->holds ? "yes" : "no", r->bytes, r->allocations_per_step, r->deterministic ? "yes" : "no", r->state_hash);
}

/* The log-log slope of time per step against bodies, least squares over
 * the sweep's results between BENCH_SLOPE_FROM and BENCH_SLOPE_TO bodies
 * with the given solver; NAN with fewer than two. */
static double sweep_slope(const bench_result *results, int count, rb_solver_type solver)
{
    double sx = 0.0;
    double sy = 0.0;
    double sxx = 0.0;
    double sxy = 0.0;
    int n = 0;
    for (int k = 0; k < count; ++k) {
        const bench_result *r = &results[k];
        if (!bench_scenes[r->scene].sweep || r->solver.type != solver || r->bodies < BENCH_SLOPE_FROM ||
            r->bodies > BENCH_SLOPE_TO) {
            continue;
        }
        double x = log((double)r->bodies);
        double y = log(r->median_ms);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        n += 1;
    }
    if (n < 2) {
        return NAN;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/* The CSV rows; fields that do not apply to a scene are left empty. A
 * failed write shows in the stream's error flag, which atomic_file_commit
 * checks. */
static void write_csv(FILE *file, const bench_options *opts, const bench_result *results, int count)
{
    fputs("scene,solver,velocity_iterations,position_iterations,relax_iterations,substeps,bodies,contacts,joints,"
          "runs,median_ms,p10_ms,p90_ms,collide_ms,solve_ms,bytes,allocations_per_step,max_penetration_m,"
          "max_joint_gap_m,moved_boxes,holds,deterministic\n",
          file);
    for (int k = 0; k < count; ++k) {
        const bench_result *r = &results[k];
        const bench_scene *scene = &bench_scenes[r->scene];
        const rb_solver_settings *s = &r->solver;
        fprintf(file, "%s,%s,%d,%d,%d,%d,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%zu,%.6g,%.6g,%.6g,", scene->name,
                rb_solver_type_name(s->type), s->velocity_iterations, s->position_iterations, s->relax_iterations,
                s->substeps, r->bodies, r->contacts, r->joints, opts->runs, r->median_ms, r->p10_ms, r->p90_ms,
                r->collide_ms, r->solve_ms, r->bytes, r->allocations_per_step, r->max_penetration, r->max_joint_gap);
        if (scene->kind == KIND_PYRAMID || scene->kind == KIND_MANY_PYRAMIDS || scene->kind == KIND_RAIN) {
            fprintf(file, "%d", r->moved_boxes);
        }
        fprintf(file, ",%s,%s\n", r->holds ? "yes" : "no", r->deterministic ? "yes" : "no");
    }
}

static void free_scratch(bench_scratch *scratch)
{
    free(scratch->times);
    free(scratch->collide);
    free(scratch->solve);
    free(scratch->run_median);
    *scratch = (bench_scratch){.times = NULL};
}

static bool allocate_scratch(const bench_options *opts, bench_scratch *scratch)
{
    size_t steps = (size_t)opts->steps;
    size_t runs = (size_t)opts->runs;
    *scratch = (bench_scratch){
        .times = malloc(steps * sizeof(double)),
        .collide = malloc(steps * sizeof(double)),
        .solve = malloc(steps * sizeof(double)),
        .run_median = malloc(5 * runs * sizeof(double)),
    };
    if (scratch->times == NULL || scratch->collide == NULL || scratch->solve == NULL || scratch->run_median == NULL) {
        free_scratch(scratch);
        return false;
    }
    scratch->run_p10 = scratch->run_median + runs;
    scratch->run_p90 = scratch->run_median + 2 * runs;
    scratch->run_collide = scratch->run_median + 3 * runs;
    scratch->run_solve = scratch->run_median + 4 * runs;
    return true;
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
    /* Opened before the runs, so that a bad path fails at once; written
     * through an atomic_file (io/atomic_file.h), so an interrupted or
     * failed run leaves no half-written CSV. */
    atomic_file csv;
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_open(&csv, opts.csv_path, error, sizeof error)) {
        fprintf(stderr, "bench_engine: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    bench_scratch scratch;
    if (!allocate_scratch(&opts, &scratch)) {
        fputs("bench_engine: out of memory\n", stderr);
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    bench_result results[BENCH_SCENE_COUNT * RB_SOLVER_TYPE_COUNT];
    int count = 0;
    bool ok = true;
    for (int k = 0; ok && k < BENCH_SCENE_COUNT; ++k) {
        for (int t = 0; ok && t < RB_SOLVER_TYPE_COUNT; ++t) {
            if (!opts.scenes[k] || !opts.solvers[t]) {
                continue;
            }
            ok = bench_scene_run(k, (rb_solver_type)t, &opts, &scratch, &results[count]);
            if (ok) {
                print_result(&opts, &results[count]);
                fflush(stdout);
                if (!results[count].deterministic) {
                    fprintf(stderr, "bench_engine: warning: %s ended in different states across runs\n",
                            bench_scenes[k].name);
                }
                count += 1;
            }
        }
    }
    free_scratch(&scratch);
    if (!ok) {
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    for (int t = 0; t < RB_SOLVER_TYPE_COUNT; ++t) {
        double slope = sweep_slope(results, count, (rb_solver_type)t);
        if (opts.solvers[t] && !isnan(slope)) {
            printf("sweep solver=%s log_log_slope_%d_to_%d_bodies=%.3f\n", rb_solver_type_name((rb_solver_type)t),
                   BENCH_SLOPE_FROM, BENCH_SLOPE_TO - 100, slope);
        }
    }
    write_csv(csv.stream, &opts, results, count);
    if (!atomic_file_commit(&csv, error, sizeof error)) {
        fprintf(stderr, "bench_engine: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("csv=%s\n", opts.csv_path);
    return EXIT_SUCCESS;
}
