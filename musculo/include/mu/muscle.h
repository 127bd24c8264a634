/* The Hill muscle (report §5.4; framework.md §4), pulling along a path of
 * body points through an engine cable.
 *
 * Sign convention: velocities are lengthening velocities, negative while
 * the muscle shortens; ṽ = v/Vmax. The tendon is rigid: its length is
 * fixed at creation, so the belly's velocity is the path's.
 *
 * Each substep: mu_muscle_prepare, before the substep, sets the cable's
 * tension law from the muscle's state; mu_muscle_measure, after it, reads
 * the force the implicit solve produced and fills the readout. Called
 * from the engine's substep callback, both happen at the start of each
 * substep (mu_muscle_advance), and the last substep is measured after
 * the step.
 */
#ifndef MU_MUSCLE_H
#define MU_MUSCLE_H

#include <stdbool.h>

#include "mu/curves.h"
#include "rb/rb.h"

typedef struct mu_muscle mu_muscle;

typedef struct mu_muscle_def {
    int point_count;                           /* 2 .. RB_MAX_CABLE_POINTS: origin, via points, insertion */
    rb_body_id bodies[RB_MAX_CABLE_POINTS];    /* the body of each path point */
    rb_vec2 local_points[RB_MAX_CABLE_POINTS]; /* m, each point in its body's frame */
    double rest_length;                        /* m, > 0: belly length of maximal active force */
    /* Maximal isometric force: max_force if > 0, else the belly's circular
     * cross-section π·rest_width²/4 times specific_tension. */
    double max_force;        /* N, >= 0 */
    double rest_width;       /* m, > 0 when max_force is 0 */
    double specific_tension; /* N/m², > 0 when max_force is 0; the seed's code uses 1.5e6 */
    double max_velocity;     /* m/s, > 0: shortening speed at which the force vanishes (the seed: 0.25) */
    /* The tendon: tendon_length if >= 0, else path length minus
     * rest_length·start_normalized_length, never below 0. */
    double tendon_length;           /* m, or -1 */
    double start_normalized_length; /* > 0, default 1 */
    double tension_gain;            /* per substep, > 0: the tension controller's gain (the seed: 0.08) */
    const mu_curves *curves;        /* not owned; must outlive the muscle */
} mu_muscle_def;

mu_muscle_def mu_default_muscle_def(void);

/* Everything the muscle reports after a substep. */
typedef struct mu_muscle_readout {
    double activation;             /* 0 .. 1 */
    double target_tension;         /* N; negative when under activation control */
    double length;                 /* m, belly length (path minus tendon) */
    double normalized_length;      /* length / rest_length */
    double velocity;               /* m/s, lengthening */
    double normalized_velocity;    /* velocity / max_velocity */
    double contraction;            /* m, rest_length - length */
    double normalized_contraction; /* contraction / rest_length */
    double active_force;           /* N, >= 0 */
    double passive_force;          /* N, >= 0 */
    double total_force;            /* N, the tension the path carried */
} mu_muscle_readout;

rb_status mu_muscle_create(rb_world *world, const mu_muscle_def *def, mu_muscle **out);
/* Removes the muscle's cable from the world (if the world still holds
 * it) and frees the muscle. Accepts NULL. */
void mu_muscle_destroy(mu_muscle *muscle, rb_world *world);

/* Sets the activation (clamped to [0, 1]) and switches tension control off. */
rb_status mu_muscle_set_activation(mu_muscle *muscle, double activation);
/* Switches tension control on: each substep the activation moves by
 * gain·(target - active force)/max force, clamped to [0, 1]; a target of 0
 * drives it to 0. */
rb_status mu_muscle_set_target_tension(mu_muscle *muscle, double target);

double mu_muscle_max_force(const mu_muscle *muscle);     /* N */
double mu_muscle_tendon_length(const mu_muscle *muscle); /* m */
rb_cable_id mu_muscle_cable(const mu_muscle *muscle);

rb_status mu_muscle_prepare(mu_muscle *muscle, rb_world *world, double h);
rb_status mu_muscle_measure(mu_muscle *muscle, const rb_world *world);
/* mu_muscle_measure then mu_muscle_prepare, reading the path once: for
 * the start of every substep but the first, when the state the last
 * substep left is the one the next starts from. */
rb_status mu_muscle_advance(mu_muscle *muscle, rb_world *world, double h);
mu_muscle_readout mu_muscle_read(const mu_muscle *muscle);

#endif
