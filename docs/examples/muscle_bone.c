/* SPDX-License-Identifier: MIT */
/* A muscle pulling a bone through the substep callback: the engine (librb)
 * and the muscle layer (libmu) used directly, without a model file.
 *
 * A forearm (a 0.3 m × 0.04 m box, 1.5 kg) is pinned at the elbow to a
 * fixed upper arm and rests against a lower limit 60° below horizontal. A
 * Hill muscle runs from 0.3 m above the elbow to 5 cm along the forearm.
 * At activation 0 it only holds passive force and the forearm stays down;
 * at activation 1 it flexes the elbow.
 *
 * The engine splits each step into substeps and calls our function at the
 * start of each: there the muscle reads the path's length and velocity and
 * hands the engine its tension law for the substep (mu_muscle_prepare, or
 * mu_muscle_advance after the first), so the solver applies the muscle's
 * force implicitly with the bodies' motion. After the step the last
 * substep is measured (mu_muscle_measure). The program exits 0 when the
 * elbow flexes by more than 30° within a second of activation.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "mu/mu.h"

static void check(rb_status status)
{
    if (status != RB_OK) {
        fprintf(stderr, "muscle_bone: %s\n", rb_last_error());
        exit(EXIT_FAILURE);
    }
}

typedef struct arm {
    mu_muscle *muscle;
    rb_status status; /* the first failure inside the callback */
} arm;

/* The engine's substep callback: the muscle sets its law for substep
 * `substep` of length h. It may not change the world (the engine refuses
 * with RB_ERR_LOCKED), only read it and set cable laws. */
static void update_muscle(rb_world *world, int substep, double h, void *context)
{
    arm *a = context;
    rb_status status = substep == 0 ? mu_muscle_prepare(a->muscle, world, h) : mu_muscle_advance(a->muscle, world, h);
    if (a->status == RB_OK) {
        a->status = status;
    }
}

/* One step of 1/60 s, then the last substep's measurement. */
static void step(rb_world *world, arm *a)
{
    check(rb_world_step(world, 1.0 / 60.0));
    check(a->status);
    check(mu_muscle_measure(a->muscle, world));
}

int main(void)
{
    rb_world_def world_def = rb_default_world_def();
    rb_world *world = NULL;
    check(rb_world_create(&world_def, &world));

    rb_body_def upper_def = rb_default_body_def(); /* static: the upper arm, elbow at the origin */
    rb_body_id upper_arm;
    check(rb_body_create(world, &upper_def, &upper_arm));

    rb_body_def forearm_def = rb_default_body_def();
    forearm_def.type = RB_BODY_DYNAMIC;
    forearm_def.position = rb_v2(0.15, 0.0); /* horizontal, its left end at the elbow */
    rb_body_id forearm;
    check(rb_body_create(world, &forearm_def, &forearm));
    rb_polygon box;
    check(rb_make_box(0.15, 0.02, &box));
    rb_shape_def shape_def = rb_default_shape_def();
    shape_def.density = 125.0; /* kg/m²: 0.012 m² of bone, 1.5 kg */
    rb_shape_id shape;
    check(rb_shape_create_polygon(world, forearm, &shape_def, &box, &shape));

    rb_revolute_joint_def elbow_def = rb_default_revolute_joint_def();
    check(rb_revolute_joint_def_at(&elbow_def, world, upper_arm, forearm, rb_v2(0.0, 0.0)));
    elbow_def.enable_lower_limit = true;
    elbow_def.lower_angle = -60.0 * RB_PI / 180.0;
    rb_joint_id elbow;
    check(rb_revolute_joint_create(world, &elbow_def, &elbow));

    mu_curves *curves = NULL;
    check(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &curves));
    mu_muscle_def muscle_def = mu_default_muscle_def();
    muscle_def.point_count = 2;
    muscle_def.bodies[0] = upper_arm;
    muscle_def.local_points[0] = rb_v2(0.0, 0.3);
    muscle_def.bodies[1] = forearm;
    muscle_def.local_points[1] = rb_v2(-0.10, 0.0); /* 5 cm from the elbow */
    muscle_def.rest_length = 0.2;                   /* m; the tendon takes the rest of the path */
    muscle_def.max_force = 500.0;                   /* N */
    muscle_def.max_velocity = 1.0;                  /* m/s */
    muscle_def.curves = curves;
    arm a = {.status = RB_OK};
    check(mu_muscle_create(world, &muscle_def, &a.muscle));
    check(rb_world_set_substep_callback(world, update_muscle, &a));

    /* One second at rest: the forearm falls onto its limit. */
    for (int i = 0; i < 60; ++i) {
        step(world, &a);
    }
    double rest_angle = rb_revolute_joint_angle(world, elbow) * 180.0 / RB_PI;

    /* One second at full activation. */
    check(mu_muscle_set_activation(a.muscle, 1.0));
    double peak_force = 0.0;
    for (int i = 0; i < 60; ++i) {
        step(world, &a);
        peak_force = fmax(peak_force, mu_muscle_read(a.muscle).total_force);
    }
    double flexed_angle = rb_revolute_joint_angle(world, elbow) * 180.0 / RB_PI;

    mu_muscle_destroy(a.muscle, world);
    mu_curves_destroy(curves);
    rb_world_destroy(world);

    printf("muscle_bone: elbow %.1f° at rest, %.1f° after 1 s of activation (peak tension %.0f N)\n", rest_angle,
           flexed_angle, peak_force);
    return flexed_angle - rest_angle > 30.0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
