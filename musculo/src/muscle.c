/* SPDX-License-Identifier: MIT */
/* The Hill muscle: contractile and parallel elastic elements in parallel,
 * a tendon in series, on an engine cable.
 *
 *   F = Fmax·(a·f_L(l̃)·f_V(ṽ) + f_P(l̃))·cos α     (Hill 1938; Zajac 1989)
 *
 * Rigid tendon (as in Castanyer's, "Implementació d'un model computacional
 * de sistemes musculoesquelètics", 2023-24): the fibre follows the path. The
 * force-velocity term makes F depend on the lengthening speed v with
 * slope c = Fmax·a·f_L·f_V'(ṽ)/Vmax, a damper stiff enough that an
 * explicit force diverges at 600 Hz: the arm's Biceps Long (Fmax 712.9 N,
 * Vmax 0.25 m/s, the tables' f_V' of 12 at ṽ = 0) gives 34 kN·s/m at full
 * activation and optimal length. So the muscle does not apply F itself: it linearizes
 * F about the present velocity, F(v') ≈ F(v) + c·(v' - v), and hands the
 * cable the law T = T0 + c·v' with T0 = F(v) - c·v, which the solver
 * takes implicitly with the bodies' motion. With pennation the fibre
 * moves at v_f = L'·cos α (pennation.h), so c gains cos² α.
 *
 * Compliant tendon: the fibre length is a state (fibre_tendon.h). Each
 * substep solves the fibre's backward-Euler step against the path length
 * predicted from its present speed, L + h·L', and hands the cable the
 * linearization of that balanced tension in the path's speed: its slope
 * is the series combination of the tendon's k_T·h (the spring's
 * backward-Euler stiffness over the substep, as Box2D v3's soft springs
 * take it) and the fibre's damping, so the stiff tendon too is taken
 * implicitly with the bodies. After the step the fibre takes its
 * backward-Euler step against the path length the bodies reached.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "arguments.h"
#include "fibre_tendon.h"
#include "mu/muscle.h"

/* A compliant muscle's fibre is never shorter than this fraction of its
 * optimal length (far below the 0.4-0.5 where f_L reaches 0), so the
 * balance never meets a vanishing fibre. */
#define MIN_FIBRE_FRACTION 0.01

/* What a measure finds, kept as found: the readout (mu_muscle_read) is
 * made from it when asked, not in each of the substeps that overwrite it
 * unread. The state the measure saw is kept with it, for the prepare that
 * follows changes the activation. */
typedef struct measured {
    double path;                   /* m */
    double fibre_length;           /* m */
    double velocity;               /* m/s, the fibre's */
    double active, passive, total; /* N along the path */
    double activation, excitation, target_tension, calcium;
} measured;

struct mu_muscle {
    rb_cable_id cable;
    double rest_length, max_force, max_velocity, tendon_length, tension_gain;
    const mu_curves *curves;
    mu_curve_hint hint; /* where this muscle's last curve look-ups fell */
    double width;       /* w = l_opt·sin α_opt, m */
    double activation;
    double excitation;
    bool activation_dynamics;
    mu_activation_model activation_model;
    mu_activation_params activation_params;
    mu_calcium_force_params calcium_force_params;
    double calcium; /* the two-stage dynamics' calcium stage */
    bool compliant;
    mu_fibre_tendon unit;         /* the compliant tendon's fibre-tendon pair */
    double fibre_length;          /* m: the compliant fibre's state */
    double fibre_velocity;        /* m/s: its velocity over the last substep */
    mu_fibre_tendon_step step;    /* the balance solved in prepare */
    double substep;               /* s: h of the pending step, 0 when none */
    double target_tension;        /* < 0: activation control */
    double base_tension, damping; /* the law handed to the cable this substep */
    double path_speed;            /* m/s: the path's lengthening speed at the last measure */
    measured last;                /* what the last measure found: the readout's inputs */
};

mu_muscle_def mu_default_muscle_def(void)
{
    return (mu_muscle_def){
        .specific_tension = 1.5e6,
        .max_velocity = 0.25,
        .tendon_length = -1.0,
        .start_normalized_length = 1.0,
        .tension_gain = 0.08,
        .activation_time = 0.010,
        .deactivation_time = 0.040,
        .calcium_force = mu_calcium_force_times_of(MU_FIBRE_FAST),
        .tendon_strain_at_max_force = MU_DEFAULT_TENDON_STRAIN_AT_MAX_FORCE,
        .fibre_damping = 0.1,
    };
}

static rb_status check_def(const mu_muscle_def *def)
{
    const char *f = "mu_muscle_create";
    if (def == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: def is NULL", f);
    }
    if (def->curves == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: curves is NULL", f);
    }
    if (!(def->point_count >= 2 && def->point_count <= RB_MAX_CABLE_POINTS)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: point_count is %d, expected 2 .. %d", f, def->point_count,
                               RB_MAX_CABLE_POINTS);
    }
    for (int i = 0; i < def->point_count; ++i) {
        if (!isfinite(def->local_points[i].x) || !isfinite(def->local_points[i].y)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: local_points[%d] is (%g, %g), expected finite", f, i,
                                   def->local_points[i].x, def->local_points[i].y);
        }
    }
    if (!(def->rest_length > 0.0 && isfinite(def->rest_length))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: rest_length is %g m, expected > 0", f, def->rest_length);
    }
    if (!(def->max_force >= 0.0 && isfinite(def->max_force))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: max_force is %g N, expected >= 0", f, def->max_force);
    }
    if (def->max_force == 0.0 && !(def->rest_width > 0.0 && isfinite(def->rest_width) && def->specific_tension > 0.0 &&
                                   isfinite(def->specific_tension))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: without max_force, rest_width (%g m) and specific_tension (%g N/m²) must be > 0", f,
                               def->rest_width, def->specific_tension);
    }
    if (!(def->max_velocity > 0.0 && isfinite(def->max_velocity))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: max_velocity is %g m/s, expected > 0", f,
                               def->max_velocity);
    }
    if (!(def->start_normalized_length > 0.0 && isfinite(def->start_normalized_length)) ||
        !isfinite(def->tendon_length)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: start_normalized_length %g must be > 0 and tendon_length %g finite", f,
                               def->start_normalized_length, def->tendon_length);
    }
    if (!(def->tension_gain > 0.0 && isfinite(def->tension_gain))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: tension_gain is %g, expected > 0", f, def->tension_gain);
    }
    if (!(def->pennation_angle >= 0.0 && def->pennation_angle < MU_MAX_PENNATION_ANGLE)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: pennation_angle is %g rad, expected 0 to below %g", f,
                               def->pennation_angle, MU_MAX_PENNATION_ANGLE);
    }
    if (def->activation_dynamics && !(def->activation_time > 0.0 && isfinite(def->activation_time) &&
                                      def->deactivation_time > 0.0 && isfinite(def->deactivation_time))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: activation_time %g s and deactivation_time %g s, expected both finite and > 0", f,
                               def->activation_time, def->deactivation_time);
    }
    if (def->activation_dynamics && def->activation_model != MU_ACTIVATION_FIRST_ORDER &&
        def->activation_model != MU_ACTIVATION_CALCIUM_FORCE) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: activation_model is %d, expected %d or %d", f,
                               (int)def->activation_model, (int)MU_ACTIVATION_FIRST_ORDER,
                               (int)MU_ACTIVATION_CALCIUM_FORCE);
    }
    if (def->activation_dynamics && def->activation_model == MU_ACTIVATION_CALCIUM_FORCE) {
        const mu_calcium_force_times *t = &def->calcium_force;
        const double times[4] = {t->calcium_rise_time, t->calcium_decay_time, t->force_rise_time, t->force_decay_time};
        for (int i = 0; i < 4; ++i) {
            if (!(times[i] > 0.0 && isfinite(times[i]))) {
                return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                       "%s: calcium_force: calcium_rise_time %g s, calcium_decay_time %g s, "
                                       "force_rise_time %g s, force_decay_time %g s, expected each finite and > 0",
                                       f, times[0], times[1], times[2], times[3]);
            }
        }
    }
    if (def->compliant_tendon && !(def->tendon_strain_at_max_force > 0.0 && def->tendon_strain_at_max_force <= 1.0 &&
                                   def->fibre_damping > 0.0 && isfinite(def->fibre_damping))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: tendon_strain_at_max_force %g and fibre_damping %g, expected (0, 1] and finite > 0",
                               f, def->tendon_strain_at_max_force, def->fibre_damping);
    }
    return RB_OK;
}

/* The belly's extent along the path, √(l² - w²), of a fibre of length l
 * (raised to the shortest fibre); l itself without pennation. */
static double belly_extent(double fibre_length, double width)
{
    if (width == 0.0) {
        return fibre_length;
    }
    const double l = fmax(fibre_length, mu_pennation_min_fibre_length(width));
    return sqrt(l * l - width * width);
}

/* cos α of a fibre of length l, 1 without pennation. */
static double pennation_cosine(double fibre_length, double width)
{
    return width == 0.0 ? 1.0
                        : belly_extent(fibre_length, width) / fmax(fibre_length, mu_pennation_min_fibre_length(width));
}

/* The rigid tendon's fibre: the belly itself without pennation (the
 * original's, any sign), else √(x² + w²). */
static double rigid_fibre_length(const mu_muscle *muscle, double path)
{
    const double belly = path - muscle->tendon_length;
    return muscle->width > 0.0 ? mu_pennation_fibre_length(belly, muscle->width) : belly;
}

static void record_measure(mu_muscle *muscle, double path, double fibre_length, double velocity, double active,
                           double passive, double total)
{
    muscle->last = (measured){
        .path = path,
        .fibre_length = fibre_length,
        .velocity = velocity,
        .active = active,
        .passive = passive,
        .total = total,
        .activation = muscle->activation,
        .excitation = muscle->excitation,
        .target_tension = muscle->target_tension,
        .calcium = muscle->calcium,
    };
}

/* The readout of the last measure. */
static mu_muscle_readout readout_of(const mu_muscle *muscle)
{
    const measured *m = &muscle->last;
    const double contraction = muscle->rest_length - m->fibre_length;
    const double tendon =
        muscle->compliant ? m->path - belly_extent(m->fibre_length, muscle->width) : muscle->tendon_length;
    return (mu_muscle_readout){
        .activation = m->activation,
        .target_tension = m->target_tension,
        .length = m->path - tendon,
        .normalized_length = m->fibre_length / muscle->rest_length,
        .velocity = m->velocity,
        .normalized_velocity = m->velocity / muscle->max_velocity,
        .contraction = contraction,
        .normalized_contraction = contraction / muscle->rest_length,
        .active_force = m->active,
        .passive_force = m->passive,
        .total_force = m->total,
        .excitation = m->excitation,
        .fibre_length = m->fibre_length,
        .tendon_length = tendon,
        .pennation_angle = muscle->width > 0.0 ? mu_pennation_angle(m->fibre_length, muscle->width) : 0.0,
        .calcium = muscle->activation_model == MU_ACTIVATION_CALCIUM_FORCE ? m->calcium : m->activation,
    };
}

/* A compliant muscle's measure at its fibre state, carrying `total`. */
static void record_compliant_measure(mu_muscle *muscle, double path, double total)
{
    const mu_fibre_forces forces =
        mu_fibre_forces_at(&muscle->unit, muscle->fibre_length, muscle->fibre_velocity, muscle->activation);
    record_measure(muscle, path, muscle->fibre_length, muscle->fibre_velocity, forces.active, forces.passive, total);
}

/* The compliant tendon's fibre-tendon pair, once the muscle's lengths are
 * known. */
static rb_status set_up_compliant(mu_muscle *muscle, const mu_muscle_def *def, double path)
{
    if (!(muscle->tendon_length > 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_muscle_create: a compliant tendon needs a slack length > 0, got %g m (path %g m)",
                               muscle->tendon_length, path);
    }
    muscle->compliant = true;
    muscle->unit = (mu_fibre_tendon){
        .curves = muscle->curves,
        .max_force = muscle->max_force,
        .optimal_length = muscle->rest_length,
        .max_velocity = muscle->max_velocity,
        .width = muscle->width,
        .min_fibre_length =
            fmax(mu_pennation_min_fibre_length(muscle->width), MIN_FIBRE_FRACTION * muscle->rest_length),
        .slack_length = muscle->tendon_length,
        .strain_at_max_force = def->tendon_strain_at_max_force,
        .damping = def->fibre_damping,
    };
    muscle->fibre_length = mu_fibre_tendon_static_length(&muscle->unit, path, muscle->activation);
    muscle->fibre_velocity = 0.0;
    record_compliant_measure(muscle, path, mu_fibre_tendon_tension(&muscle->unit, path, muscle->fibre_length));
    return RB_OK;
}

rb_status mu_muscle_create(rb_world *world, const mu_muscle_def *def, mu_muscle **out)
{
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_muscle_create: out is NULL");
    }
    *out = NULL;
    if (mu_refuse_null("mu_muscle_create", "world", world)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    rb_status status = check_def(def);
    if (status != RB_OK) {
        return status;
    }
    rb_cable_def cable_def = rb_default_cable_def();
    cable_def.point_count = def->point_count;
    for (int i = 0; i < def->point_count && i < RB_MAX_CABLE_POINTS; ++i) {
        cable_def.bodies[i] = def->bodies[i];
        cable_def.local_points[i] = def->local_points[i];
    }
    rb_cable_id cable;
    status = rb_cable_create(world, &cable_def, &cable);
    if (status != RB_OK) {
        return status;
    }
    mu_muscle *muscle = calloc(1, sizeof *muscle);
    if (muscle == NULL) {
        rb_cable_destroy(world, cable);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_muscle_create: out of memory");
    }
    muscle->cable = cable;
    muscle->rest_length = def->rest_length;
    muscle->max_force = def->max_force > 0.0 ? def->max_force
                                             : 0.25 * RB_PI * def->rest_width * def->rest_width * def->specific_tension;
    muscle->max_velocity = def->max_velocity;
    muscle->tension_gain = def->tension_gain;
    muscle->curves = def->curves;
    muscle->target_tension = -1.0;
    muscle->width = def->pennation_angle > 0.0 ? mu_pennation_width(def->rest_length, def->pennation_angle) : 0.0;
    muscle->activation_dynamics = def->activation_dynamics;
    muscle->activation_model = def->activation_dynamics ? def->activation_model : MU_ACTIVATION_FIRST_ORDER;
    muscle->calcium_force_params = (mu_calcium_force_params){.excitation = 0.0, .times = def->calcium_force};
    muscle->activation_params = (mu_activation_params){
        .excitation = 0.0,
        .activation_time = def->activation_time,
        .deactivation_time = def->deactivation_time,
    };
    double path = rb_cable_length(world, cable);
    muscle->tendon_length =
        def->tendon_length >= 0.0
            ? def->tendon_length
            : fmax(path - belly_extent(def->rest_length * def->start_normalized_length, muscle->width), 0.0);
    status = def->compliant_tendon ? set_up_compliant(muscle, def, path) : mu_muscle_measure(muscle, world);
    if (status != RB_OK) {
        /* Destroying the cable clears the error: keep its message. */
        char message[512];
        snprintf(message, sizeof message, "%s", rb_last_error());
        mu_muscle_destroy(muscle, world);
        return rb_report_error(status, "%s", message);
    }
    *out = muscle;
    return RB_OK;
}

void mu_muscle_destroy(mu_muscle *muscle, rb_world *world)
{
    if (muscle == NULL) {
        return;
    }
    if (world != NULL && rb_cable_is_valid(world, muscle->cable)) {
        rb_cable_destroy(world, muscle->cable);
    }
    free(muscle);
}

rb_status mu_muscle_set_activation(mu_muscle *muscle, double activation)
{
    const char *f = "mu_muscle_set_activation";
    if (mu_refuse_null(f, "muscle", muscle) || mu_refuse_non_finite(f, "activation", activation)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const double clamped = fmin(fmax(activation, 0.0), 1.0);
    if (muscle->activation_dynamics) {
        muscle->excitation = clamped;
    } else {
        muscle->activation = clamped;
        muscle->excitation = clamped;
    }
    muscle->target_tension = -1.0;
    return RB_OK;
}

rb_status mu_muscle_set_target_tension(mu_muscle *muscle, double target)
{
    const char *f = "mu_muscle_set_target_tension";
    if (mu_refuse_null(f, "muscle", muscle)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    if (!(target >= 0.0 && isfinite(target))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: target is %g N, expected a finite tension >= 0", f,
                               target);
    }
    muscle->target_tension = target;
    return RB_OK;
}

double mu_muscle_max_force(const mu_muscle *muscle)
{
    return mu_refuse_null("mu_muscle_max_force", "muscle", muscle) ? NAN : muscle->max_force;
}
double mu_muscle_tendon_length(const mu_muscle *muscle)
{
    return mu_refuse_null("mu_muscle_tendon_length", "muscle", muscle) ? NAN : muscle->tendon_length;
}
rb_cable_id mu_muscle_cable(const mu_muscle *muscle)
{
    return mu_refuse_null("mu_muscle_cable", "muscle", muscle) ? (rb_cable_id){0} : muscle->cable;
}

/* Castanyer's proportional controller on the active force, once per
 * substep, on the excitation when there is one. */
static void control_tension(mu_muscle *muscle)
{
    const double error = muscle->target_tension - muscle->last.active;
    const double change = muscle->tension_gain * error / muscle->max_force;
    if (muscle->activation_dynamics) {
        muscle->excitation = fmin(fmax(muscle->excitation + change, 0.0), 1.0);
    } else {
        muscle->activation = fmin(fmax(muscle->activation + change, 0.0), 1.0);
        muscle->excitation = muscle->activation;
    }
}

/* The path as the muscle reads it at the start of a substep and, for a
 * rigid tendon, the fibre the path fixes. Within mu_muscle_advance the
 * measure of the substep that ended and the law of the next one share
 * it: the fibre's length, pennation and parallel elastic force depend on
 * the pose alone, not on the activation the law then updates. */
typedef struct path_reading {
    double path;    /* m */
    double speed;   /* m/s, < 0 while shortening */
    double tension; /* N: what the cable carried in the substep that ended */
    /* Rigid tendon only: */
    double fibre_length; /* m */
    double normalized;   /* l̃ = fibre length / optimal length */
    double cosine;       /* cos α */
    double passive;      /* N along the path: Fmax·f_P(l̃)·cos α */
} path_reading;

static rb_status read_path(mu_muscle *muscle, const rb_world *world, path_reading *reading)
{
    rb_cable_reading cable;
    rb_status status = rb_cable_read(world, muscle->cable, &cable);
    *reading = (path_reading){.path = cable.length, .speed = cable.lengthening_speed, .tension = cable.tension};
    if (status == RB_OK && !muscle->compliant) {
        reading->fibre_length = rigid_fibre_length(muscle, reading->path);
        reading->cosine = pennation_cosine(reading->fibre_length, muscle->width);
        reading->normalized = reading->fibre_length / muscle->rest_length;
        reading->passive = muscle->max_force *
                           mu_curve_passive_length_hinted(muscle->curves, &muscle->hint, reading->normalized) *
                           reading->cosine;
    }
    return status;
}

/* The rigid tendon's law: the force at the present velocity and its
 * slope in the path's speed (see the top of this file). */
static void prepare_rigid(mu_muscle *muscle, const path_reading *reading)
{
    const double speed = reading->speed;
    const double cosine = reading->cosine;
    const double l = reading->normalized;
    const double v = speed * cosine / muscle->max_velocity;
    const double fl = mu_curve_active_length_hinted(muscle->curves, &muscle->hint, l);
    double fv_slope = 0.0;
    const double fv = mu_curve_velocity_and_slope_hinted(muscle->curves, &muscle->hint, v, &fv_slope);
    const double active = muscle->max_force * muscle->activation * fl * fv * cosine;
    const double passive = reading->passive;
    muscle->damping = muscle->max_force * muscle->activation * fl * fv_slope / muscle->max_velocity * cosine * cosine;
    muscle->base_tension = active + passive - muscle->damping * speed;
}

/* The activation dynamics over h under the present excitation. */
static void advance_activation(mu_muscle *muscle, double h)
{
    if (muscle->activation_model == MU_ACTIVATION_CALCIUM_FORCE) {
        mu_calcium_force_state state = {.calcium = muscle->calcium, .activation = muscle->activation};
        muscle->calcium_force_params.excitation = muscle->excitation;
        /* Cannot fail: checked times, an excitation clamped to [0, 1], a
         * state the step keeps in [0, 1] and h > 0 checked by the caller. */
        (void)mu_calcium_force_step(&state, h, &muscle->calcium_force_params);
        muscle->calcium = state.calcium;
        muscle->activation = state.activation;
        return;
    }
    muscle->activation_params.excitation = muscle->excitation;
    muscle->activation = mu_activation_step(muscle->activation, h, &muscle->activation_params);
}

/* mu_muscle_prepare at the path's length and lengthening speed now. */
static rb_status prepare_at(mu_muscle *muscle, rb_world *world, double h, const path_reading *reading)
{
    const double path = reading->path;
    const double speed = reading->speed;
    if (muscle->target_tension >= 0.0) {
        control_tension(muscle);
    }
    if (muscle->activation_dynamics) {
        advance_activation(muscle, h);
    }
    if (muscle->compliant) {
        muscle->step = mu_fibre_tendon_solve(&muscle->unit, muscle->fibre_length, muscle->activation, path + h * speed,
                                             h, muscle->fibre_velocity);
        muscle->substep = h;
        muscle->damping = muscle->step.path_damping;
        muscle->base_tension = muscle->step.tension - muscle->damping * speed;
    } else {
        prepare_rigid(muscle, reading);
    }
    return rb_cable_set_tension_law(world, muscle->cable, muscle->base_tension, muscle->damping);
}

/* The compliant fibre after the step: the backward-Euler step again, now
 * against the path length the bodies reached, from the velocity that
 * balances the tension the solver applied (to first order about the
 * balance solved in prepare). Solving again rather than taking that
 * first-order velocity keeps the fibre and the tendon consistent with the
 * path: a stiff tendon's toe turns a small error in the fibre's length
 * into a large force. */
static void advance_fibre(mu_muscle *muscle, double path, double tension)
{
    const double h = muscle->substep;
    const double guess = muscle->step.velocity + (tension - muscle->step.tension) * muscle->step.velocity_per_tension;
    const mu_fibre_tendon_step step =
        mu_fibre_tendon_solve(&muscle->unit, muscle->fibre_length, muscle->activation, path, h, guess);
    const double moved = fmax(muscle->fibre_length + h * step.velocity, muscle->unit.min_fibre_length);
    muscle->fibre_velocity = (moved - muscle->fibre_length) / h;
    muscle->fibre_length = moved;
    muscle->substep = 0.0;
}

/* mu_muscle_measure at the path's length and lengthening speed now. */
static void measure_at(mu_muscle *muscle, const path_reading *reading)
{
    const double path = reading->path;
    const double speed = reading->speed;
    /* The tension the solver applied: the law at the velocity it solved
     * for, which the iterations reach only approximately when the muscle
     * shares its bodies with joints and other muscles. (Evaluating the
     * law at the end velocity instead would amplify a residual of a few
     * mm/s by the 10⁴-10⁵ N·s/m of the force-velocity slope.) */
    const double total = reading->tension;
    muscle->path_speed = speed;
    if (muscle->compliant) {
        if (muscle->substep > 0.0) {
            advance_fibre(muscle, path, total);
        }
        record_compliant_measure(muscle, path, total);
        return;
    }
    const double passive = reading->passive;
    /* The active part, never below 0: fmax(total - passive, 0) as a
     * comparison (the same value, NaN and -0 included), without libm's call
     * once a substep. */
    const double active = total - passive > 0.0 ? total - passive : 0.0;
    record_measure(muscle, path, reading->fibre_length, speed * reading->cosine, active, passive, total);
}

static inline rb_status check_prepare(const mu_muscle *muscle, const rb_world *world, double h, const char *function)
{
    if (mu_refuse_null(function, "muscle", muscle) || mu_refuse_null(function, "world", world)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    if (!(h > 0.0 && isfinite(h))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: h is %g s, expected a finite substep > 0", function, h);
    }
    return RB_OK;
}

rb_status mu_muscle_prepare(mu_muscle *muscle, rb_world *world, double h)
{
    rb_status status = check_prepare(muscle, world, h, "mu_muscle_prepare");
    path_reading reading;
    if (status == RB_OK) {
        status = read_path(muscle, world, &reading);
    }
    return status != RB_OK ? status : prepare_at(muscle, world, h, &reading);
}

rb_status mu_muscle_measure(mu_muscle *muscle, const rb_world *world)
{
    if (mu_refuse_null("mu_muscle_measure", "muscle", muscle) || mu_refuse_null("mu_muscle_measure", "world", world)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    path_reading reading;
    rb_status status = read_path(muscle, world, &reading);
    if (status == RB_OK) {
        measure_at(muscle, &reading);
    }
    return status;
}

rb_status mu_muscle_advance(mu_muscle *muscle, rb_world *world, double h)
{
    rb_status status = check_prepare(muscle, world, h, "mu_muscle_advance");
    path_reading reading;
    if (status == RB_OK) {
        status = read_path(muscle, world, &reading);
    }
    if (status != RB_OK) {
        return status;
    }
    measure_at(muscle, &reading);
    return prepare_at(muscle, world, h, &reading);
}

rb_status mu_muscle_solve_equilibrium(mu_muscle *muscle, const rb_world *world)
{
    const char *f = "mu_muscle_solve_equilibrium";
    if (mu_refuse_null(f, "muscle", muscle) || mu_refuse_null(f, "world", world)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    double path = 0.0;
    double speed = 0.0;
    rb_status status = rb_cable_state(world, muscle->cable, &path, &speed);
    if (status != RB_OK) {
        return status;
    }
    if (muscle->compliant) {
        muscle->fibre_length = mu_fibre_tendon_static_length(&muscle->unit, path, muscle->activation);
        muscle->fibre_velocity = 0.0;
        muscle->substep = 0.0;
        record_compliant_measure(muscle, path, mu_fibre_tendon_tension(&muscle->unit, path, muscle->fibre_length));
        return RB_OK;
    }
    const double fibre_length = rigid_fibre_length(muscle, path);
    const double cosine = pennation_cosine(fibre_length, muscle->width);
    const double l = fibre_length / muscle->rest_length;
    const double active = muscle->max_force * muscle->activation * mu_curve_active_length(muscle->curves, l) *
                          mu_curve_velocity(muscle->curves, 0.0) * cosine;
    const double passive = muscle->max_force * mu_curve_passive_length(muscle->curves, l) * cosine;
    record_measure(muscle, path, fibre_length, 0.0, active, passive, active + passive);
    return RB_OK;
}

double mu_muscle_path_speed(const mu_muscle *muscle)
{
    return mu_refuse_null("mu_muscle_path_speed", "muscle", muscle) ? NAN : muscle->path_speed;
}

double mu_muscle_tension(const mu_muscle *muscle)
{
    return mu_refuse_null("mu_muscle_tension", "muscle", muscle) ? NAN : muscle->last.total;
}

mu_muscle_readout mu_muscle_read(const mu_muscle *muscle)
{
    return mu_refuse_null("mu_muscle_read", "muscle", muscle) ? mu_nan_readout() : readout_of(muscle);
}

rb_status mu_muscle_isometric_forces(const mu_muscle *muscle, const rb_world *world, double activation, double *active,
                                     double *passive)
{
    const char *f = "mu_muscle_isometric_forces";
    if (mu_refuse_null(f, "muscle", muscle) || mu_refuse_null(f, "world", world) ||
        mu_refuse_null(f, "active", active) || mu_refuse_null(f, "passive", passive)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    if (!(activation >= 0.0 && activation <= 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: activation is %g, expected 0 .. 1", f, activation);
    }
    const double path = rb_cable_length(world, muscle->cable);
    if (!isfinite(path)) {
        return RB_ERR_INVALID_ARGUMENT; /* rb_cable_length reported why */
    }
    if (muscle->compliant) {
        /* The fibre where its force along the tendon balances the tendon's. */
        const double fibre = mu_fibre_tendon_static_length(&muscle->unit, path, activation);
        const mu_fibre_forces forces = mu_fibre_forces_at(&muscle->unit, fibre, 0.0, activation);
        *active = forces.active;
        *passive = forces.passive;
        return RB_OK;
    }
    const double fibre_length = rigid_fibre_length(muscle, path);
    const double cosine = pennation_cosine(fibre_length, muscle->width);
    const double l = fibre_length / muscle->rest_length;
    *active = muscle->max_force * activation * mu_curve_active_length(muscle->curves, l) *
              mu_curve_velocity(muscle->curves, 0.0) * cosine;
    *passive = muscle->max_force * mu_curve_passive_length(muscle->curves, l) * cosine;
    return RB_OK;
}

rb_status mu_muscle_forces_at_speed(const mu_muscle *muscle, const rb_world *world, double path_speed,
                                    double *active_per_activation, double *passive)
{
    const char *f = "mu_muscle_forces_at_speed";
    if (mu_refuse_null(f, "muscle", muscle) || mu_refuse_null(f, "world", world) ||
        mu_refuse_non_finite(f, "path_speed", path_speed) ||
        mu_refuse_null(f, "active_per_activation", active_per_activation) || mu_refuse_null(f, "passive", passive)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    if (muscle->compliant) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: the muscle has a compliant tendon, whose fibre length is a state of its own and "
                               "not fixed by the pose; expected a rigid tendon",
                               f);
    }
    const double path = rb_cable_length(world, muscle->cable);
    if (!isfinite(path)) {
        return RB_ERR_INVALID_ARGUMENT; /* rb_cable_length reported why */
    }
    const double fibre_length = rigid_fibre_length(muscle, path);
    const double cosine = pennation_cosine(fibre_length, muscle->width);
    const double l = fibre_length / muscle->rest_length;
    const double v = path_speed * cosine / muscle->max_velocity;
    *active_per_activation =
        muscle->max_force * mu_curve_active_length(muscle->curves, l) * mu_curve_velocity(muscle->curves, v) * cosine;
    *passive = muscle->max_force * mu_curve_passive_length(muscle->curves, l) * cosine;
    return RB_OK;
}
