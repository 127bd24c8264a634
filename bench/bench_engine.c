/* bench_engine: time sinew's engine on the peer benchmark scenes.
 *
 * Protocol of shared/peers/README.md, so the figures compare with
 * box2d24_bench and chipmunk_bench run on the same machine: dt = 1/60 s,
 * `warmup` untimed steps, then `steps` steps each timed alone with
 * clock_gettime(CLOCK_MONOTONIC); the pyramid under gravity (0, -10),
 * friction 0.6, restitution 0, no sleeping. The whole run is repeated
 * `runs` times, each in a fresh world; the report gives the median over
 * runs of each run's median step time, and likewise of each run's 10th
 * and 90th percentiles (percentile indices as the peers: n/2, n/10,
 * 9n/10 of the sorted times).
 *
 * Scenes: pyramid20 and pyramid100 (the peers' pyramid, base 20 and 100)
 * and balls (the seed's 50 balls, seed 1, gravity (0, -9.81), drag
 * applied before each step outside the timing).
 *
 * Prints one `engine=sinew scene=... median_ms=... p10_ms=... p90_ms=...`
 * line per scene and writes a CSV (header row; written to a temporary name
 * and renamed). Exit status: 0 success, 1 failure, 2 bad command line.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/option_value.h"
#include "io/atomic_file.h"
#include "rb/rb.h"
#include "scenes/scenes.h"

enum { EXIT_USAGE = 2 };

static const char usage_text[] = "usage: bench_engine [options]\n"
                                 "\n"
                                 "Times rb_world_step on the peer benchmark scenes (shared/peers/README.md).\n"
                                 "\n"
                                 "  --scene NAME    pyramid20, pyramid100, balls or all (default all)\n"
                                 "  --runs N        repetitions of the whole run, 1 .. 1000 (default 5)\n"
                                 "  --steps N       timed steps per run, 1 .. 1000000 (default 300)\n"
                                 "  --warmup N      untimed steps before them, 0 .. 1000000 (default 60)\n"
                                 "  --vel N         velocity iterations, 1 .. 1000 (default: engine's)\n"
                                 "  --pos N         position iterations, 0 .. 1000 (default: engine's)\n"
                                 "  --substeps N    substeps per step, 1 .. 1000 (default: engine's)\n"
                                 "  --csv FILE      results (default bench_engine.csv)\n"
                                 "  --quick         smoke test: 1 run, 10 warm-up and 20 timed steps\n"
                                 "                  (explicit --runs, --warmup, --steps still win)\n"
                                 "  --help          print this text\n";

#define BENCH_DT (1.0 / 60.0)         /* s, the peers' step */
#define BENCH_PYRAMID_GRAVITY (-10.0) /* m/s², the peers' */
#define BENCH_BALLS_GRAVITY (-9.81)   /* m/s², the seed's */
#define BENCH_BALLS_COUNT 50
#define BENCH_BALLS_SEED 1
#define BENCH_MOVED_THRESHOLD 0.25 /* m, the peers' collapse indicator */

/* ------------------------------------------------------------- options */

typedef enum bench_scene { BENCH_PYRAMID20, BENCH_PYRAMID100, BENCH_BALLS, BENCH_SCENE_COUNT } bench_scene;

static const char *const bench_scene_names[BENCH_SCENE_COUNT] = {"pyramid20", "pyramid100", "balls"};
static const int bench_scene_bases[BENCH_SCENE_COUNT] = {20, 100, 0};

typedef struct bench_options {
    bool scenes[BENCH_SCENE_COUNT]; /* which to run */
    int runs;                       /* 1 .. 1000 */
    int steps;                      /* timed steps per run, 1 .. 1e6 */
    int warmup;                     /* 0 .. 1e6 */
    int velocity_iterations;        /* 1 .. 1000, or 0 for the engine default */
    int position_iterations;        /* 0 .. 1000, or -1 for the engine default */
    int substeps;                   /* 1 .. 1000, or 0 for the engine default */
    const char *csv_path;
} bench_options;

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

static parse_result parse_options(int argc, char **argv, bench_options *opts)
{
    *opts = (bench_options){
        .runs = -1, .steps = -1, .warmup = -1, .position_iterations = -1, .csv_path = "bench_engine.csv"};
    bool quick = false;
    const char *scene = "all";
    for (int i = 1; i < argc; ++i) {
        const char *option = argv[i];
        if (strcmp(option, "--help") == 0 || strcmp(option, "-h") == 0) {
            return PARSE_HELP;
        }
        if (strcmp(option, "--quick") == 0) {
            quick = true;
            continue;
        }
        static const char *const with_value[] = {"--scene", "--runs", "--steps",    "--warmup",
                                                 "--vel",   "--pos",  "--substeps", "--csv"};
        const char *value = option_take_value(argc, argv, &i, "bench_engine", with_value,
                                              sizeof with_value / sizeof with_value[0], usage_text);
        if (value == NULL) {
            return PARSE_ERROR;
        }
        char error[OPTION_ERROR_SIZE];
        bool ok = true;
        if (strcmp(option, "--scene") == 0) {
            scene = value;
        } else if (strcmp(option, "--runs") == 0) {
            ok = option_parse_int(option, value, 1, 1000, &opts->runs, error, sizeof error);
        } else if (strcmp(option, "--steps") == 0) {
            ok = option_parse_int(option, value, 1, 1000000, &opts->steps, error, sizeof error);
        } else if (strcmp(option, "--warmup") == 0) {
            ok = option_parse_int(option, value, 0, 1000000, &opts->warmup, error, sizeof error);
        } else if (strcmp(option, "--vel") == 0) {
            ok = option_parse_int(option, value, 1, 1000, &opts->velocity_iterations, error, sizeof error);
        } else if (strcmp(option, "--pos") == 0) {
            ok = option_parse_int(option, value, 0, 1000, &opts->position_iterations, error, sizeof error);
        } else if (strcmp(option, "--substeps") == 0) {
            ok = option_parse_int(option, value, 1, 1000, &opts->substeps, error, sizeof error);
        } else {
            ok = option_parse_path(option, value, &opts->csv_path, error, sizeof error);
        }
        if (!ok) {
            fprintf(stderr, "bench_engine: %s\n", error);
            return PARSE_ERROR;
        }
    }
    bool all = strcmp(scene, "all") == 0;
    bool any = all;
    for (int k = 0; k < BENCH_SCENE_COUNT; ++k) {
        opts->scenes[k] = all || strcmp(scene, bench_scene_names[k]) == 0;
        any = any || opts->scenes[k];
    }
    if (!any) {
        fprintf(stderr, "bench_engine: --scene expects pyramid20, pyramid100, balls or all, got \"%s\"\n", scene);
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

/* Figures of one scene over all its runs. */
typedef struct bench_result {
    bench_scene scene;
    int bodies;                /* dynamic bodies */
    int contacts;              /* at the end of the last run */
    rb_solver_settings solver; /* as used */
    double median_ms, p10_ms, p90_ms;
    double top_x0, top_x, top_y0, top_y; /* m, pyramid's top box, start and end of the last run */
    int moved_boxes;                     /* pyramid: boxes moved > 0.25 m sideways in the last run */
    double max_shift;                    /* m, largest sideways shift of a box */
    int escaped;                         /* balls outside the box at the end of the last run */
    double allocations_per_step;         /* heap allocations per timed step, worst run */
    bool deterministic;                  /* every run ended in the same state */
} bench_result;

/* The state of one scene in one run. */
typedef struct bench_world {
    rb_world *world;
    scene_pyramid pyramid;
    scene_balls balls;
    double *start_x;   /* m, pyramid boxes' start x */
    rb_vec2 top_start; /* m, pyramid top box's start position */
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

static bool bench_world_create(bench_scene scene, const bench_options *opts, bench_world *bw)
{
    *bw = (bench_world){.world = NULL};
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, scene == BENCH_BALLS ? BENCH_BALLS_GRAVITY : BENCH_PYRAMID_GRAVITY);
    def.enable_sleep = false; /* as the peers run: every body simulated every step */
    if (opts->velocity_iterations > 0) {
        def.solver.velocity_iterations = opts->velocity_iterations;
    }
    if (opts->position_iterations >= 0) {
        def.solver.position_iterations = opts->position_iterations;
    }
    if (opts->substeps > 0) {
        def.solver.substeps = opts->substeps;
    }
    if (rb_world_create(&def, &bw->world) != RB_OK) {
        return engine_failed("rb_world_create");
    }
    if (scene == BENCH_BALLS) {
        if (scene_balls_create(bw->world, BENCH_BALLS_COUNT, BENCH_BALLS_SEED, &bw->balls) != RB_OK) {
            return engine_failed("scene_balls_create");
        }
        return true;
    }
    if (scene_pyramid_create(bw->world, bench_scene_bases[scene], &bw->pyramid) != RB_OK) {
        return engine_failed("scene_pyramid_create");
    }
    bw->start_x = malloc((size_t)bw->pyramid.box_count * sizeof *bw->start_x);
    if (bw->start_x == NULL) {
        fputs("bench_engine: out of memory\n", stderr);
        return false;
    }
    for (int k = 0; k < bw->pyramid.box_count; ++k) {
        bw->start_x[k] = rb_body_position(bw->world, scene_body_at(bw->pyramid.first_box, k)).x;
    }
    bw->top_start = rb_body_position(bw->world, bw->pyramid.top);
    return true;
}

static void bench_world_destroy(bench_world *bw)
{
    rb_world_destroy(bw->world);
    free(bw->start_x);
    *bw = (bench_world){.world = NULL};
}

static bool bench_step(bench_scene scene, bench_world *bw, double *elapsed_ms)
{
    if (scene == BENCH_BALLS && scene_balls_apply_drag(bw->world, &bw->balls) != RB_OK) {
        return engine_failed("scene_balls_apply_drag");
    }
    double start = now_ms();
    rb_status status = rb_world_step(bw->world, BENCH_DT);
    *elapsed_ms = now_ms() - start;
    return status == RB_OK || engine_failed("rb_world_step");
}

/* The end-of-run figures, kept from the last run. */
static void measure_scene(bench_scene scene, const bench_world *bw, bench_result *result)
{
    rb_world *world = bw->world;
    result->contacts = rb_world_statistics(world).contact_count;
    result->solver = rb_world_solver_settings(world);
    if (scene == BENCH_BALLS) {
        result->bodies = bw->balls.count;
        result->escaped = 0;
        for (int k = 0; k < bw->balls.count; ++k) {
            rb_vec2 p = rb_body_position(world, bw->balls.balls[k]);
            result->escaped += !(p.x >= 0.0 && p.x <= SCENE_BALLS_WIDTH && p.y >= 0.0 && p.y <= SCENE_BALLS_HEIGHT);
        }
        return;
    }
    const scene_pyramid *pyramid = &bw->pyramid;
    result->bodies = pyramid->box_count;
    result->top_x0 = bw->top_start.x;
    result->top_y0 = bw->top_start.y;
    rb_vec2 top = rb_body_position(world, pyramid->top);
    result->top_x = top.x;
    result->top_y = top.y;
    result->moved_boxes = 0;
    result->max_shift = 0.0;
    for (int k = 0; k < pyramid->box_count; ++k) {
        double shift = fabs(rb_body_position(world, scene_body_at(pyramid->first_box, k)).x - bw->start_x[k]);
        result->moved_boxes += shift > BENCH_MOVED_THRESHOLD;
        result->max_shift = fmax(result->max_shift, shift);
    }
}

/* Runs one scene `runs` times. `times` has room for `steps` values,
 * `run_stats` for 3·runs. */
static bool bench_scene_run(bench_scene scene, const bench_options *opts, double *times, double *run_stats,
                            bench_result *result)
{
    *result = (bench_result){.scene = scene, .deterministic = true};
    double *run_medians = run_stats;
    double *run_p10 = run_stats + opts->runs;
    double *run_p90 = run_stats + 2 * opts->runs;
    uint64_t first_hash = 0;
    for (int run = 0; run < opts->runs; ++run) {
        bench_world bw;
        bool ok = bench_world_create(scene, opts, &bw);
        double ignored;
        for (int step = 0; ok && step < opts->warmup; ++step) {
            ok = bench_step(scene, &bw, &ignored);
        }
        uint64_t allocations_before = rb_allocation_count();
        for (int step = 0; ok && step < opts->steps; ++step) {
            ok = bench_step(scene, &bw, &times[step]);
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
        measure_scene(scene, &bw, result);
        bench_world_destroy(&bw);

        qsort(times, (size_t)opts->steps, sizeof *times, compare_doubles);
        run_medians[run] = sorted_percentile(times, opts->steps, 1, 2);
        run_p10[run] = sorted_percentile(times, opts->steps, 1, 10);
        run_p90[run] = sorted_percentile(times, opts->steps, 9, 10);
    }
    result->median_ms = median(run_medians, opts->runs);
    result->p10_ms = median(run_p10, opts->runs);
    result->p90_ms = median(run_p90, opts->runs);
    return true;
}

/* ------------------------------------------------------------- reports */

static void print_result(const bench_options *opts, const bench_result *r)
{
    if (r->scene == BENCH_BALLS) {
        printf("engine=sinew scene=balls count=%d seed=%d", r->bodies, BENCH_BALLS_SEED);
    } else {
        printf("engine=sinew scene=pyramid base=%d", bench_scene_bases[r->scene]);
    }
    printf(" bodies=%d vel_iters=%d pos_iters=%d substeps=%d warmup=%d timed_steps=%d runs=%d"
           " median_ms=%.4f p10_ms=%.4f p90_ms=%.4f",
           r->bodies, r->solver.velocity_iterations, r->solver.position_iterations, r->solver.substeps, opts->warmup,
           opts->steps, opts->runs, r->median_ms, r->p10_ms, r->p90_ms);
    if (r->scene == BENCH_BALLS) {
        printf(" escaped=%d", r->escaped);
    } else {
        printf(" top_y0=%.4f top_y=%.4f top_x0=%.4f top_x=%.4f lateral_gt_0.25=%d max_abs_dx=%.3f", r->top_y0, r->top_y,
               r->top_x0, r->top_x, r->moved_boxes, r->max_shift);
    }
    printf(" contacts=%d allocations_per_step=%.3g deterministic=%s\n", r->contacts, r->allocations_per_step,
           r->deterministic ? "yes" : "no");
}

/* The CSV rows of the scenes run; fields that do not apply to a scene are
 * left empty. A failed write shows in the stream's error flag, which
 * atomic_file_commit checks. */
static void write_csv(FILE *file, const bench_options *opts, const bench_result *results, int count)
{
    fputs("scene,base,bodies,contacts,velocity_iterations,position_iterations,substeps,runs,median_ms,p10_ms,"
          "p90_ms,top_x,top_y,moved_boxes,allocations_per_step\n",
          file);
    for (int k = 0; k < count; ++k) {
        const bench_result *r = &results[k];
        const rb_solver_settings *s = &r->solver;
        if (r->scene == BENCH_BALLS) {
            fprintf(file, "balls,,%d,%d,%d,%d,%d,%d,%.6g,%.6g,%.6g,,,,%.6g\n", r->bodies, r->contacts,
                    s->velocity_iterations, s->position_iterations, s->substeps, opts->runs, r->median_ms, r->p10_ms,
                    r->p90_ms, r->allocations_per_step);
        } else {
            fprintf(file, "pyramid,%d,%d,%d,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6f,%.6f,%d,%.6g\n",
                    bench_scene_bases[r->scene], r->bodies, r->contacts, s->velocity_iterations, s->position_iterations,
                    s->substeps, opts->runs, r->median_ms, r->p10_ms, r->p90_ms, r->top_x, r->top_y, r->moved_boxes,
                    r->allocations_per_step);
        }
    }
}

int main(int argc, char **argv)
{
    bench_options opts;
    switch (parse_options(argc, argv, &opts)) {
    case PARSE_HELP:
        fputs(usage_text, stdout);
        return EXIT_SUCCESS;
    case PARSE_ERROR:
        return EXIT_USAGE;
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
    double *times = malloc((size_t)opts.steps * sizeof *times);
    double *run_stats = malloc(3 * (size_t)opts.runs * sizeof *run_stats);
    if (times == NULL || run_stats == NULL) {
        fputs("bench_engine: out of memory\n", stderr);
        free(times);
        free(run_stats);
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    bench_result results[BENCH_SCENE_COUNT];
    int count = 0;
    bool ok = true;
    for (int k = 0; ok && k < BENCH_SCENE_COUNT; ++k) {
        if (!opts.scenes[k]) {
            continue;
        }
        ok = bench_scene_run((bench_scene)k, &opts, times, run_stats, &results[count]);
        if (ok) {
            print_result(&opts, &results[count]);
            fflush(stdout);
            if (!results[count].deterministic) {
                fprintf(stderr, "bench_engine: warning: %s ended in different states across runs\n",
                        bench_scene_names[k]);
            }
            count += 1;
        }
    }
    free(times);
    free(run_stats);
    if (!ok) {
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    write_csv(csv.stream, &opts, results, count);
    if (!atomic_file_commit(&csv, error, sizeof error)) {
        fprintf(stderr, "bench_engine: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("csv=%s\n", opts.csv_path);
    return EXIT_SUCCESS;
}
