/* SPDX-License-Identifier: MIT */
/* The viewer's core without GTK (tools/viewer/core): the view transform,
 * the history ring, the simulation's loads, controls and drag, the live
 * graphs' CSV export and the canvas drawn with Cairo.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <cairo.h>
#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "canvas_draw.h"
#include "history.h"
#include "live_graph.h"
#include "load_arrows.h"
#include "simulation.h"
#include "stress_colours.h"
#include "test_support.h"
#include "view_transform.h"

static void make_temp_dir(char *path, size_t size)
{
    snprintf(path, size, "/tmp/sinew-viewer-XXXXXX");
    cr_assert_not_null(mkdtemp(path), "mkdtemp failed");
}

static simulation load_arm(void)
{
    simulation sim;
    simulation_init(&sim);
    mu_model_options options = mu_default_model_options();
    options.weight_index = 1; /* 1 kg */
    char error[SIMULATION_ERROR_SIZE];
    cr_assert(simulation_load_model(&sim, "arm", &options, error, sizeof error), "load arm: %s", error);
    return sim;
}

Test(view_transform, zooming_keeps_the_point_under_the_cursor)
{
    view_transform view = view_transform_make(rb_v2(1.0, 2.0), 100.0);
    view_transform_resize(&view, 800.0, 600.0);
    expect_vec_near(view_world_to_screen(&view, rb_v2(1.0, 2.0)), rb_v2(400.0, 300.0), 1e-12, "centre");
    expect_vec_near(view_world_to_screen(&view, rb_v2(2.0, 3.0)), rb_v2(500.0, 200.0), 1e-12, "y up");
    rb_vec2 cursor = rb_v2(123.0, 456.0);
    rb_vec2 under = view_screen_to_world(&view, cursor);
    view_zoom_about(&view, cursor, 1.7);
    expect_near(view.scale, 170.0, 1e-12, "scale");
    expect_vec_near(view_screen_to_world(&view, cursor), under, 1e-12, "point under the cursor");
    view_pan(&view, rb_v2(17.0, -5.0));
    expect_vec_near(view_screen_to_world(&view, rb_add(cursor, rb_v2(17.0, -5.0))), under, 1e-12, "panned");
    view_zoom_about(&view, cursor, 1e9);
    expect_near(view.scale, VIEW_MAX_SCALE, 0.0, "zoom clamped");
    view_reset(&view);
    expect_near(view.scale, 100.0, 0.0, "reset scale");
    expect_vec_near(view.centre, rb_v2(1.0, 2.0), 0.0, "reset centre");
}

Test(history, keeps_the_last_samples_oldest_first)
{
    history samples;
    cr_assert(history_init(&samples, 2, 3));
    for (int k = 0; k < 5; ++k) {
        mu_muscle_readout readouts[2] = {{.activation = k}, {.total_force = 10.0 * k}};
        history_record(&samples, 0.1 * k, readouts);
    }
    double times[3], values[3];
    cr_assert_eq(history_series(&samples, 1, HISTORY_TOTAL_FORCE, times, values), 3);
    for (int k = 0; k < 3; ++k) {
        expect_near(times[k], 0.1 * (k + 2), 1e-12, "time");
        expect_near(values[k], 10.0 * (k + 2), 1e-12, "force");
    }
    history_series(&samples, 0, HISTORY_ACTIVATION, times, values);
    expect_near(values[0], 2.0, 0.0, "activation");
    history_free(&samples);
}

Test(simulation, a_pulse_lasts_one_frame_and_the_biceps_flex_the_elbow)
{
    simulation sim = load_arm();
    char error[SIMULATION_ERROR_SIZE];
    cr_expect_str_eq(sim.target, "Biceps Short + Biceps Long", "the first group is the target");
    for (int k = 0; k < 120; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
    }
    double settled = mu_model_hinge_angle(sim.model, 1);
    cr_assert(simulation_select(&sim, "Biceps Short", error, sizeof error), "%s", error);
    simulation_pulse(&sim);
    cr_assert(simulation_step(&sim, error, sizeof error));
    cr_expect_gt(mu_model_muscle_readout(sim.model, 0).activation, 0.99, "pulsed frame");
    cr_assert(simulation_step(&sim, error, sizeof error));
    cr_expect_eq(mu_model_muscle_readout(sim.model, 0).activation, 0.0, "back to the command after one frame");
    cr_assert(simulation_select(&sim, "Biceps Short + Biceps Long", error, sizeof error));
    cr_assert(simulation_set_activation(&sim, 1.0, error, sizeof error));
    for (int k = 0; k < 60; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
    }
    cr_expect_gt(mu_model_hinge_angle(sim.model, 1), settled + 30.0, "elbow from %g", settled);
    cr_expect_not(simulation_select(&sim, "Bicep", error, sizeof error), "unknown muscle");
    cr_expect_not(simulation_set_tension(&sim, -1.0, error, sizeof error), "negative tension");
    simulation_free(&sim);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

Test(simulation, a_model_that_fails_leaves_the_previous_one)
{
    char dir[64], path[128], error[SIMULATION_ERROR_SIZE];
    make_temp_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/bad.json", dir);
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file);
    fputs("{\"name\": \"bad\", \"bones\": [{\"name\": \"b\", \"colour\": 1}]}\n", file);
    fclose(file);
    simulation sim = load_arm();
    mu_model_options options = mu_default_model_options();
    cr_expect_not(simulation_load_model(&sim, path, &options, error, sizeof error));
    cr_expect(strstr(error, "bad.json") != NULL, "the message names the file: %s", error);
    cr_expect_eq(sim.kind, SIMULATION_MODEL);
    cr_expect_str_eq(sim.model_argument, "arm");
    cr_expect_not(simulation_load_model(&sim, "no-such-model", &options, error, sizeof error));
    cr_expect(simulation_step(&sim, error, sizeof error), "the arm still runs");
    cr_expect(simulation_choose_weight(&sim, 5.0, &options, error, sizeof error));
    cr_expect_eq(options.weight_index, 2);
    cr_expect_not(simulation_choose_weight(&sim, 3.0, &options, error, sizeof error));
    cr_expect(strstr(error, "50") != NULL, "the choices are listed: %s", error);
    cr_expect(simulation_choose_variant(&sim, "All Biceps", &options, error, sizeof error));
    cr_expect_eq(options.variant, 2);
    cr_expect(simulation_reload(&sim, &options, error, sizeof error), "%s", error);
    cr_expect_eq(mu_model_muscle_count(sim.model), 2);
    simulation_free(&sim);
    unlink(path);
    rmdir(dir);
}

Test(simulation, every_scene_loads_and_steps)
{
    simulation sim;
    simulation_init(&sim);
    char error[SIMULATION_ERROR_SIZE];
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        scene_kind kind;
        cr_assert(scene_kind_from_name(scene_registry[k].name, &kind));
        cr_assert_eq(kind, k);
        cr_assert(simulation_load_scene(&sim, kind, error, sizeof error), "%s", error);
        cr_expect_gt(sim.scene.body_count, 0, "%s has bodies that move", scene_registry[k].name);
        for (int frame = 0; frame < 3; ++frame) {
            cr_assert(simulation_step(&sim, error, sizeof error), "%s: %s", scene_registry[kind].name, error);
        }
        expect_near(simulation_time(&sim), 3.0 / 60.0, 1e-12, "scene time");
    }
    simulation_free(&sim);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

Test(simulation, dragging_a_bone_pulls_it)
{
    simulation sim = load_arm();
    char error[SIMULATION_ERROR_SIZE];
    int hand = -1;
    for (int k = 0; k < mu_model_part_count(sim.model); ++k) {
        if (strcmp(mu_model_part_name(sim.model, k), "Hand") == 0) {
            hand = k;
        }
    }
    cr_assert_geq(hand, 0);
    rb_vec2 grip = mu_model_part_centre(sim.model, hand);
    cr_assert(simulation_drag_begin(&sim, grip), "the hand is picked");
    rb_vec2 target = rb_add(grip, rb_v2(0.0, 0.2));
    simulation_drag_move(&sim, target);
    for (int k = 0; k < 60; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
    }
    cr_expect_gt(mu_model_part_centre(sim.model, hand).y, grip.y + 0.05, "the hand was lifted");
    simulation_drag_end(&sim);
    cr_expect_not(sim.dragging);
    cr_expect_not(simulation_drag_begin(&sim, rb_v2(50.0, 50.0)), "nothing to pick there");
    simulation_free(&sim);
}

Test(live_graph, exports_its_channels_as_csv)
{
    simulation sim = load_arm();
    char error[CHART_ERROR_SIZE], dir[64], path[128];
    history samples;
    cr_assert(history_init(&samples, mu_model_muscle_count(sim.model), 10));
    for (int k = 0; k < 4; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error));
        mu_muscle_readout readouts[8];
        for (int m = 0; m < mu_model_muscle_count(sim.model); ++m) {
            readouts[m] = mu_model_muscle_readout(sim.model, m);
        }
        history_record(&samples, simulation_time(&sim), readouts);
    }
    live_graph graph;
    live_graph_select(&graph, LIVE_GRAPH_SELECTED_FORCES, &sim);
    cr_assert_eq(graph.channel_count, 3, "active, passive, total of the selected muscle");
    cr_expect_str_eq(graph.channels[1].label, "Biceps Short passive");
    make_temp_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/forces.csv", dir);
    cr_assert(live_graph_write_csv(&graph, &samples, path, error, sizeof error), "%s", error);
    FILE *file = fopen(path, "r");
    cr_assert_not_null(file);
    char header[512];
    cr_assert_not_null(fgets(header, sizeof header, file));
    cr_expect_str_eq(header,
                     "time_s,Biceps Short.active_force_N,Biceps Short.passive_force_N,Biceps Short.total_force_N\n");
    int rows = 0;
    char line[512];
    while (fgets(line, sizeof line, file) != NULL) {
        ++rows;
    }
    fclose(file);
    cr_expect_eq(rows, 4);
    cr_expect_not(live_graph_write_csv(&graph, &samples, "/nonexistent-dir/x.csv", error, sizeof error));
    cr_expect(strstr(error, "/nonexistent-dir/x.csv") != NULL, "the message names the path: %s", error);
    live_graph_select(&graph, LIVE_GRAPH_ACTIVATION, &sim);
    cr_expect_eq(graph.channel_count, 5, "every muscle of the arm");
    unlink(path);
    rmdir(dir);
    history_free(&samples);
    simulation_free(&sim);
}

/* Pixels of `colour` (0xRRGGBB) within `tolerance` per channel. */
static long count_colour(cairo_surface_t *surface, uint32_t colour, int tolerance)
{
    cairo_surface_flush(surface);
    const unsigned char *data = cairo_image_surface_get_data(surface);
    int stride = cairo_image_surface_get_stride(surface);
    long count = 0;
    for (int y = 0; y < cairo_image_surface_get_height(surface); ++y) {
        const uint32_t *row = (const uint32_t *)(data + (size_t)y * (size_t)stride);
        for (int x = 0; x < cairo_image_surface_get_width(surface); ++x) {
            bool near = true;
            for (int shift = 0; shift <= 16; shift += 8) {
                near = near && abs((int)((row[x] >> shift) & 0xff) - (int)((colour >> shift) & 0xff)) <= tolerance;
            }
            count += near;
        }
    }
    return count;
}

Test(canvas_draw, draws_the_bones_and_the_weight)
{
    simulation sim = load_arm();
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300);
    cairo_t *cr = cairo_create(surface);
    /* The arm starts horizontal, from the shoulder to the fingers. */
    rb_vec2 centre = rb_scale(0.5, rb_add(mu_model_part_centre(sim.model, 0),
                                          mu_model_part_centre(sim.model, mu_model_part_count(sim.model) - 1)));
    view_transform view = view_transform_make(centre, 500.0);
    view_transform_resize(&view, 400.0, 300.0);
    canvas_overlays overlays = {.joints = true, .aabbs = true};
    canvas_draw(cr, &view, &sim, &overlays);
    cr_expect_gt(count_colour(surface, CANVAS_BONE, 1), 1000, "ivory bones");
    cr_expect_gt(count_colour(surface, CANVAS_WEIGHT, 1), 10, "the weight");
    cr_expect_gt(count_colour(surface, CANVAS_BACKGROUND, 0), 400 * 300 / 2, "the background");
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    simulation_free(&sim);
}

/* The "colours" overlay draws the pyramid's contact points in their
 * solver colours (rb_constraint_colour_rgb), none in the plain contact
 * red; the plain "contacts" overlay draws them all red. */
static void count_contact_colours(bool colours, long *first_colour, long *plain_red)
{
    simulation sim = {0};
    char error[SIMULATION_ERROR_SIZE];
    cr_assert(simulation_load_scene(&sim, SCENE_PYRAMID, error, sizeof error), "%s", error);
    for (int k = 0; k < 2; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
    }
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300);
    cairo_t *cr = cairo_create(surface);
    view_transform view = view_transform_make(rb_v2(0.0, 10.0), 13.0);
    view_transform_resize(&view, 400.0, 300.0);
    canvas_overlays overlays = {.contact_points = !colours, .contact_colours = colours};
    canvas_draw(cr, &view, &sim, &overlays);
    *first_colour = count_colour(surface, rb_constraint_colour_rgb(0), 1);
    *plain_red = count_colour(surface, RB_COLOR_CONTACT_POINT, 1);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    simulation_free(&sim);
}

Test(canvas_draw, the_colours_overlay_shows_the_solver_colours)
{
    long first_colour = 0;
    long plain_red = 0;
    count_contact_colours(true, &first_colour, &plain_red);
    cr_expect_gt(first_colour, 100, "pixels of colour 0: %ld", first_colour);
    cr_expect_eq(plain_red, 0, "pixels in the plain contact red: %ld", plain_red);
    count_contact_colours(false, &first_colour, &plain_red);
    cr_expect_eq(first_colour, 0, "pixels of colour 0 without the overlay: %ld", first_colour);
    cr_expect_gt(plain_red, 100, "pixels in the plain contact red: %ld", plain_red);
}

Test(simulation, a_model_runs_on_after_the_engine_panel_changes_its_solver)
{
    simulation sim = load_arm();
    char error[SIMULATION_ERROR_SIZE];
    rb_world *world = simulation_world(&sim);
    for (int type = 0; type < RB_SOLVER_TYPE_COUNT; ++type) {
        rb_solver_settings settings = rb_world_solver_settings(world);
        settings.type = (rb_solver_type)type;
        settings.substeps = 3 + type;
        settings.velocity_iterations = 2;
        settings.warm_starting = type % 2 == 0;
        cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
        for (int k = 0; k < 30; ++k) {
            cr_assert(simulation_step(&sim, error, sizeof error), "%s: %s", rb_solver_type_name(settings.type), error);
        }
        cr_expect_eq(rb_world_statistics(world).velocity_iterations, 2 * settings.substeps);
        double elbow = mu_model_hinge_angle(sim.model, 1);
        cr_expect(isfinite(elbow) && elbow > -10.5 && elbow < 150.5, "%s: elbow at %g°",
                  rb_solver_type_name(settings.type), elbow);
    }
    simulation_free(&sim);
}

/* Where a value falls in a range, 0 at its min, 1 at its max. */
static double fraction_in(chart_range range, double value) { return (value - range.min) / (range.max - range.min); }

/* A line at the data's least or greatest value is drawn inside the plot,
 * off its frame: at least LIVE_GRAPH_HEADROOM / (1 + 2 LIVE_GRAPH_HEADROOM)
 * of the height (5.4 %, 11 px of a 200 px plot) from either edge. */
Test(live_graph, ranges_leave_headroom_so_a_constant_line_shows)
{
    const double inside = LIVE_GRAPH_HEADROOM / (1.0 + 2.0 * LIVE_GRAPH_HEADROOM) - 1e-12;
    /* A constant activation of 1, then of 0: the graph keeps 0 .. 1 with room
     * above and below, 1 and 0 at the same places. */
    chart_range full = live_graph_y_range(LIVE_GRAPH_ACTIVATION, 1.0, 1.0);
    cr_expect(full.fixed && full.min < 0.0 && full.max > 1.0, "[%g, %g]", full.min, full.max);
    cr_expect_geq(1.0 - fraction_in(full, 1.0), inside, "activation 1 at %g of the height", fraction_in(full, 1.0));
    cr_expect_geq(fraction_in(full, 0.0), inside, "activation 0 at %g of the height", fraction_in(full, 0.0));
    chart_range rest = live_graph_y_range(LIVE_GRAPH_ACTIVATION, 0.0, 0.0);
    cr_expect(rest.min == full.min && rest.max == full.max, "[%g, %g] for 0, [%g, %g] for 1", rest.min, rest.max,
              full.min, full.max);
    /* Tensions of 0 .. 100 N: 6 N of room either side. */
    chart_range tension = live_graph_y_range(LIVE_GRAPH_TENSION, 0.0, 100.0);
    cr_expect_float_eq(tension.min, -6.0, 1e-12);
    cr_expect_float_eq(tension.max, 106.0, 1e-12);
    /* A constant tension, at 250 N or at 0 N: the line in the middle. */
    const double constants[] = {250.0, 0.0, -3e-5};
    for (size_t k = 0; k < sizeof constants / sizeof constants[0]; ++k) {
        chart_range range = live_graph_y_range(LIVE_GRAPH_TENSION, constants[k], constants[k]);
        cr_expect(range.fixed && range.min < range.max, "%g: [%g, %g]", constants[k], range.min, range.max);
        cr_expect_float_eq(fraction_in(range, constants[k]), 0.5, 1e-9, "%g at %g of the height", constants[k],
                           fraction_in(range, constants[k]));
    }
    /* Nothing shown yet, or values at the ends of a double: a finite range. */
    const double ends[][2] = {{NAN, NAN}, {INFINITY, -INFINITY}, {-DBL_MAX, DBL_MAX}, {DBL_MAX, DBL_MAX}};
    for (size_t k = 0; k < sizeof ends / sizeof ends[0]; ++k) {
        for (int kind = 0; kind < LIVE_GRAPH_COUNT; ++kind) {
            chart_range range = live_graph_y_range((live_graph_kind)kind, ends[k][0], ends[k][1]);
            cr_expect(range.fixed && isfinite(range.min) && isfinite(range.max) && range.min < range.max,
                      "[%g, %g], graph %d: [%g, %g]", ends[k][0], ends[k][1], kind, range.min, range.max);
        }
    }
}

/* The leg at 200 kg: the weight's disc, larger than the shank, is drawn
 * under the bones, so they show as many ivory pixels as without the
 * weight (level 3 builds no weight; the pose at t = 0 is the same). */
static long leg_bone_pixels(int level, long *rim)
{
    simulation sim;
    simulation_init(&sim);
    mu_model_options options = mu_default_model_options();
    options.weight_index = 3; /* 200 kg */
    options.level = level;
    char error[SIMULATION_ERROR_SIZE];
    cr_assert(simulation_load_model(&sim, "leg", &options, error, sizeof error), "load leg: %s", error);
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 400);
    cairo_t *cr = cairo_create(surface);
    view_transform view = view_transform_make(mu_model_part_centre(sim.model, 0), 300.0);
    view_transform_resize(&view, 400.0, 400.0);
    canvas_overlays overlays = {.joints = false};
    canvas_draw(cr, &view, &sim, &overlays);
    long bone = count_colour(surface, CANVAS_BONE, 1);
    *rim = count_colour(surface, CANVAS_WEIGHT, 1);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    simulation_free(&sim);
    return bone;
}

Test(canvas_draw, bones_stay_visible_under_a_heavy_weight)
{
    long rim_with = 0, rim_without = 0;
    long with_weight = leg_bone_pixels(4, &rim_with), without = leg_bone_pixels(3, &rim_without);
    cr_assert_gt(without, 1000, "ivory bones of the leg: %ld pixels", without);
    cr_expect_gt(rim_with, 100, "the weight's rim: %ld pixels", rim_with);
    cr_expect_eq(rim_without, 0, "no weight at level 3: %ld pixels", rim_without);
    cr_expect_geq(with_weight, without * 95 / 100, "bones with the weight: %ld pixels, without: %ld", with_weight,
                  without);
}

/* ---- joint-load arrows ------------------------------------------------------------ */

Test(load_arrows, the_scale_is_a_round_step_that_keeps_the_largest_arrow_short)
{
    /* 120 px / 230 N = 0.52 px/N, rounded down to 0.5. */
    cr_expect_float_eq(load_arrow_scale(230.0), 0.5, 1e-15);
    cr_expect_float_eq(load_arrow_scale(1.0), 100.0, 1e-12);
    cr_expect_float_eq(load_arrow_scale(24.0), 5.0, 1e-15);
    cr_expect_eq(load_arrow_scale(0.0), 0.0);
    cr_expect_eq(load_arrow_scale(NAN), 0.0);
    for (double force = 0.013; force < 1e6; force *= 1.37) {
        const double px = force * load_arrow_scale(force);
        cr_expect(px <= LOAD_ARROW_MAX_PX * (1.0 + 1e-12) && px > LOAD_ARROW_MAX_PX / 2.5, "%g N drawn %g px", force,
                  px);
        double length = 0.0;
        const double legend = load_arrow_legend_force(load_arrow_scale(force), &length);
        cr_expect(length >= 40.0 - 1e-9 && length <= 100.0 + 1e-9, "legend %g N is %g px", legend, length);
    }
}

Test(load_arrows, an_arrow_leaving_the_canvas_is_cut_at_its_margin)
{
    bool cut = true;
    rb_vec2 tip = load_arrow_clip(rb_v2(100.0, 100.0), rb_v2(150.0, 80.0), 400.0, 300.0, &cut);
    cr_expect(!cut && tip.x == 150.0 && tip.y == 80.0);
    /* Right and up past the corner: cut where it first meets the margin. */
    tip = load_arrow_clip(rb_v2(380.0, 50.0), rb_v2(420.0, 10.0), 400.0, 300.0, &cut);
    cr_expect(cut);
    expect_vec_near(tip, rb_v2(392.0, 38.0), 1e-12, "cut at x = 400 - 8");
    tip = load_arrow_clip(rb_v2(50.0, 280.0), rb_v2(50.0, 900.0), 400.0, 300.0, &cut);
    cr_expect(cut);
    expect_vec_near(tip, rb_v2(50.0, 292.0), 1e-12, "cut at y = 300 - 8");
}

/* The "reactions" overlay draws the model's joint loads in orange with a
 * legend; without it there is no orange. */
Test(load_arrows, the_reactions_overlay_draws_labelled_loads)
{
    simulation sim = load_arm();
    char error[SIMULATION_ERROR_SIZE];
    for (int k = 0; k < 10; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
    }
    long orange[2];
    for (int on = 0; on < 2; ++on) {
        cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300);
        cairo_t *cr = cairo_create(surface);
        view_transform view = view_transform_make(mu_model_part_centre(sim.model, 2), 500.0);
        view_transform_resize(&view, 400.0, 300.0);
        canvas_overlays overlays = {.joint_reactions = on == 1};
        canvas_draw(cr, &view, &sim, &overlays);
        orange[on] = count_colour(surface, 0xcc5900, 2);
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
    cr_expect_eq(orange[0], 0, "no load arrows without the overlay");
    cr_expect_gt(orange[1], 80, "the legend's bar and the arrows (%ld px)", orange[1]);
    simulation_free(&sim);
}

/* Green unloaded, yellow at half the strength, red at and past it. */
Test(stress_colours, run_from_green_through_yellow_to_red)
{
    double rgb[3];
    stress_colour(INFINITY, rgb);
    cr_expect(rgb[1] > 0.6 && rgb[0] < 0.2, "unloaded: green (%g, %g, %g)", rgb[0], rgb[1], rgb[2]);
    stress_colour(2.0, rgb);
    cr_expect(rgb[0] > 0.9 && rgb[1] > 0.75 && rgb[2] < 0.15, "half: yellow (%g, %g, %g)", rgb[0], rgb[1], rgb[2]);
    stress_colour(1.0, rgb);
    cr_expect(rgb[0] > 0.8 && rgb[1] < 0.15, "at the strength: red (%g, %g, %g)", rgb[0], rgb[1], rgb[2]);
    double past[3];
    stress_colour(0.25, past);
    cr_expect(past[0] == rgb[0] && past[1] == rgb[1] && past[2] == rgb[2], "past it: red too");
}

/* The reactions overlay colours each moving bone along its axis. */
Test(stress_colours, the_reactions_overlay_colours_the_bones)
{
    simulation sim = load_arm();
    char error[SIMULATION_ERROR_SIZE];
    for (int k = 0; k < 10; ++k) {
        cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
    }
    long greenish[2];
    for (int on = 0; on < 2; ++on) {
        cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300);
        cairo_t *cr = cairo_create(surface);
        view_transform view = view_transform_make(mu_model_part_centre(sim.model, 2), 500.0);
        view_transform_resize(&view, 400.0, 300.0);
        canvas_overlays overlays = {.joint_reactions = on == 1};
        canvas_draw(cr, &view, &sim, &overlays);
        /* The arm holding 1 kg uses a few per cent of its strength: green. */
        greenish[on] = count_colour(surface, 0x26a640, 24);
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
    cr_expect_eq(greenish[0], 0, "no stress colours without the overlay");
    cr_expect_gt(greenish[1], 200, "the bones' strips (%ld px)", greenish[1]);
    simulation_free(&sim);
}
