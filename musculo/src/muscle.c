/* The Hill muscle: contractile and parallel elastic elements in parallel,
 * a rigid tendon in series, on an engine cable.
 *
 *   F = Fmax·(a·f_L(l̃)·f_V(ṽ) + f_P(l̃))     (Hill 1938; Zajac 1989)
 *
 * The force-velocity term makes F depend on the lengthening speed v with
 * slope c = Fmax·a·f_L·f_V'(ṽ)/Vmax, a damper stiff enough (about 86 kN·s/m
 * for the biceps) that an explicit force diverges at 600 Hz
 * (framework.md §4). So the muscle does not apply F itself: it linearizes
 * F about the present velocity, F(v') ≈ F(v) + c·(v' - v), and hands the
 * cable the law T = T0 + c·v' with T0 = F(v) - c·v, which the solver
 * takes implicitly with the bodies' motion. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "mu/muscle.h"

struct mu_muscle {
    rb_cable_id cable;
    double rest_length, max_force, max_velocity, tendon_length, tension_gain;
    const mu_curves *curves;
    mu_curve_hint hint; /* where this muscle's last curve look-ups fell */
    double activation;
    double target_tension;        /* < 0: activation control */
    double base_tension, damping; /* the law handed to the cable this substep */
    mu_muscle_readout readout;
};

mu_muscle_def mu_default_muscle_def(void)
{
    return (mu_muscle_def){
        .specific_tension = 1.5e6,
        .max_velocity = 0.25,
        .tendon_length = -1.0,
        .start_normalized_length = 1.0,
        .tension_gain = 0.08,
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
    return RB_OK;
}

rb_status mu_muscle_create(rb_world *world, const mu_muscle_def *def, mu_muscle **out)
{
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_muscle_create: out is NULL");
    }
    *out = NULL;
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
    double path = rb_cable_length(world, cable);
    muscle->tendon_length = def->tendon_length >= 0.0
                                ? def->tendon_length
                                : fmax(path - def->rest_length * def->start_normalized_length, 0.0);
    *out = muscle;
    return mu_muscle_measure(muscle, world);
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
    if (muscle == NULL || !isfinite(activation)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_muscle_set_activation: expected a muscle and a finite activation, got %g",
                               activation);
    }
    muscle->activation = fmin(fmax(activation, 0.0), 1.0);
    muscle->target_tension = -1.0;
    return RB_OK;
}

rb_status mu_muscle_set_target_tension(mu_muscle *muscle, double target)
{
    if (muscle == NULL || !(target >= 0.0 && isfinite(target))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_muscle_set_target_tension: expected a muscle and a tension >= 0 N, got %g", target);
    }
    muscle->target_tension = target;
    return RB_OK;
}

double mu_muscle_max_force(const mu_muscle *muscle) { return muscle->max_force; }
double mu_muscle_tendon_length(const mu_muscle *muscle) { return muscle->tendon_length; }
rb_cable_id mu_muscle_cable(const mu_muscle *muscle) { return muscle->cable; }

/* The belly's length (path minus tendon) and lengthening speed now. */
static rb_status read_belly(const mu_muscle *muscle, const rb_world *world, double *length, double *velocity)
{
    double path = 0.0;
    rb_status status = rb_cable_state(world, muscle->cable, &path, velocity);
    *length = path - muscle->tendon_length;
    return status;
}

static double passive_force(mu_muscle *muscle, double length)
{
    return muscle->max_force *
           mu_curve_passive_length_hinted(muscle->curves, &muscle->hint, length / muscle->rest_length);
}

/* Sets the cable's tension law for the next substep from the belly's
 * state now. */
static rb_status set_tension_law(mu_muscle *muscle, rb_world *world, double length, double velocity, double passive)
{
    if (muscle->target_tension >= 0.0) {
        /* The seed's proportional controller on the active force, once per
         * substep (report annex C.7). */
        double error = muscle->target_tension - muscle->readout.active_force;
        muscle->activation =
            fmin(fmax(muscle->activation + muscle->tension_gain * error / muscle->max_force, 0.0), 1.0);
    }
    double l = length / muscle->rest_length;
    double v = velocity / muscle->max_velocity;
    double fl = mu_curve_active_length_hinted(muscle->curves, &muscle->hint, l);
    double active =
        muscle->max_force * muscle->activation * fl * mu_curve_velocity_hinted(muscle->curves, &muscle->hint, v);
    muscle->damping = muscle->max_force * muscle->activation * fl *
                      mu_curve_velocity_slope_hinted(muscle->curves, &muscle->hint, v) / muscle->max_velocity;
    muscle->base_tension = active + passive - muscle->damping * velocity;
    return rb_cable_set_tension_law(world, muscle->cable, muscle->base_tension, muscle->damping);
}

/* Fills the readout from the belly's state after a substep. The total is
 * the tension the solver applied: the law at the velocity it solved for,
 * which the iterations reach only approximately when the muscle shares
 * its bodies with joints and other muscles. (Evaluating the law at the
 * end velocity instead would amplify a residual of a few mm/s by the
 * 10⁴-10⁵ N·s/m of the force-velocity slope.) */
static void fill_readout(mu_muscle *muscle, const rb_world *world, double length, double velocity, double passive)
{
    double total = rb_cable_tension(world, muscle->cable);
    muscle->readout = (mu_muscle_readout){
        .activation = muscle->activation,
        .target_tension = muscle->target_tension,
        .length = length,
        .normalized_length = length / muscle->rest_length,
        .velocity = velocity,
        .normalized_velocity = velocity / muscle->max_velocity,
        .contraction = muscle->rest_length - length,
        .normalized_contraction = (muscle->rest_length - length) / muscle->rest_length,
        .active_force = fmax(total - passive, 0.0),
        .passive_force = passive,
        .total_force = total,
    };
}

rb_status mu_muscle_prepare(mu_muscle *muscle, rb_world *world, double h)
{
    (void)h;
    double length = 0.0;
    double velocity = 0.0;
    rb_status status = read_belly(muscle, world, &length, &velocity);
    return status != RB_OK ? status : set_tension_law(muscle, world, length, velocity, passive_force(muscle, length));
}

rb_status mu_muscle_measure(mu_muscle *muscle, const rb_world *world)
{
    double length = 0.0;
    double velocity = 0.0;
    rb_status status = read_belly(muscle, world, &length, &velocity);
    if (status == RB_OK) {
        fill_readout(muscle, world, length, velocity, passive_force(muscle, length));
    }
    return status;
}

rb_status mu_muscle_advance(mu_muscle *muscle, rb_world *world, double h)
{
    (void)h;
    double length = 0.0;
    double velocity = 0.0;
    rb_status status = read_belly(muscle, world, &length, &velocity);
    if (status != RB_OK) {
        return status;
    }
    double passive = passive_force(muscle, length);
    fill_readout(muscle, world, length, velocity, passive);
    return set_tension_law(muscle, world, length, velocity, passive);
}

mu_muscle_readout mu_muscle_read(const mu_muscle *muscle) { return muscle->readout; }
