/* SPDX-License-Identifier: MIT */
/* The torque actuator: exertion · peak torque on one body, its reaction on
 * another or on the world (torque_actuator.h). */
#include <math.h>
#include <stdlib.h>

#include "arguments.h"
#include "mu/torque_actuator.h"

struct mu_torque_actuator {
    rb_body_id body;
    rb_body_id reaction_body; /* null: the world */
    double peak_torque;
    double exertion;
};

mu_torque_actuator_def mu_default_torque_actuator_def(void)
{
    return (mu_torque_actuator_def){.body = {0}, .reaction_body = {0}, .peak_torque = 0.0};
}

static bool same_body(rb_body_id a, rb_body_id b)
{
    return a.index == b.index && a.generation == b.generation && a.world == b.world;
}

rb_status mu_torque_actuator_create(const rb_world *world, const mu_torque_actuator_def *def, mu_torque_actuator **out)
{
    const char *f = "mu_torque_actuator_create";
    if (world == NULL || def == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: world, def and out must not be NULL", f);
    }
    *out = NULL;
    if (!rb_body_is_valid(world, def->body)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: def.body is not a body of this world", f);
    }
    if (!rb_body_id_is_null(def->reaction_body)) {
        if (!rb_body_is_valid(world, def->reaction_body)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "%s: def.reaction_body is not a body of this world (the null id for the world)", f);
        }
        if (same_body(def->body, def->reaction_body)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: def.reaction_body is def.body, expected another body",
                                   f);
        }
    }
    if (!isfinite(def->peak_torque)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: def.peak_torque is %g N·m, expected a finite number", f,
                               def->peak_torque);
    }
    mu_torque_actuator *actuator = calloc(1, sizeof *actuator);
    if (actuator == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    }
    actuator->body = def->body;
    actuator->reaction_body = def->reaction_body;
    actuator->peak_torque = def->peak_torque;
    *out = actuator;
    return RB_OK;
}

void mu_torque_actuator_destroy(mu_torque_actuator *actuator) { free(actuator); }

rb_status mu_torque_actuator_set_exertion(mu_torque_actuator *actuator, double exertion)
{
    if (actuator == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_torque_actuator_set_exertion: actuator is NULL");
    }
    if (!(exertion >= 0.0 && exertion <= 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_torque_actuator_set_exertion: exertion is %g, expected 0 to 1", exertion);
    }
    actuator->exertion = exertion;
    return RB_OK;
}

double mu_torque_actuator_exertion(const mu_torque_actuator *actuator)
{
    return mu_refuse_null("mu_torque_actuator_exertion", "actuator", actuator) ? NAN : actuator->exertion;
}

double mu_torque_actuator_torque(const mu_torque_actuator *actuator)
{
    return mu_refuse_null("mu_torque_actuator_torque", "actuator", actuator)
               ? NAN
               : actuator->exertion * actuator->peak_torque;
}

double mu_torque_actuator_peak_torque(const mu_torque_actuator *actuator)
{
    return mu_refuse_null("mu_torque_actuator_peak_torque", "actuator", actuator) ? NAN : actuator->peak_torque;
}

double mu_torque_actuator_power(const mu_torque_actuator *actuator, const rb_world *world)
{
    const char *f = "mu_torque_actuator_power";
    if (mu_refuse_null(f, "actuator", actuator) || mu_refuse_null(f, "world", world)) {
        return NAN;
    }
    if (!rb_body_is_valid(world, actuator->body) ||
        (!rb_body_id_is_null(actuator->reaction_body) && !rb_body_is_valid(world, actuator->reaction_body))) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: a body of the actuator is no longer in the world", f);
        return NAN;
    }
    double spin = rb_body_angular_velocity(world, actuator->body);
    if (!rb_body_id_is_null(actuator->reaction_body)) {
        spin -= rb_body_angular_velocity(world, actuator->reaction_body);
    }
    return mu_torque_actuator_torque(actuator) * spin;
}

rb_status mu_torque_actuator_apply(const mu_torque_actuator *actuator, rb_world *world)
{
    if (actuator == NULL || world == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_torque_actuator_apply: actuator and world must not be NULL");
    }
    const double torque = mu_torque_actuator_torque(actuator);
    rb_status status = rb_body_apply_torque(world, actuator->body, torque);
    if (status == RB_OK && !rb_body_id_is_null(actuator->reaction_body)) {
        status = rb_body_apply_torque(world, actuator->reaction_body, -torque);
    }
    return status;
}
