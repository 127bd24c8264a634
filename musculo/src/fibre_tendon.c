/* SPDX-License-Identifier: MIT */
/* The damped fibre-tendon equilibrium (fibre_tendon.h): the balance, its
 * static solution by bisection, and the substep's backward-Euler step by
 * a safeguarded Newton iteration.
 *
 * The Newton iteration keeps a bracket [lo, hi] with g(lo) <= 0 <= g(hi)
 * and takes the bisection whenever the Newton step would leave it, so it
 * converges for any residual that changes sign (Press et al., "Numerical
 * Recipes", 3rd ed., 2007, §9.4, rtsafe). Its slope is
 *   g'(v) ≈ ∂G/∂v + k_T·h·X'(l_f),
 *   ∂G/∂v = Fmax·cos α·(a·f_L·f_V'(ṽ) + β)/Vmax,  X' = l_f/X = 1/cos α,
 * leaving out the terms h·∂G/∂l_f of the length curves and the angle,
 * which are a few per cent of g' at a substep (h·|f_L'|/l_opt against
 * β/Vmax): Newton then converges linearly at that ratio, and the bracket
 * keeps it safe. ∂G/∂v >= Fmax·cos α·β/Vmax > 0, so no division is ever
 * by zero.
 */
#include <math.h>

#include "fibre_tendon.h"
#include "mu/tendon.h"

/* Iteration limits: bisection halves the bracket each time, so 200 steps
 * reach any double's resolution from any finite bracket. */
#define MAX_ITERATIONS 200
#define MAX_EXPANSIONS 64

/* The fibre length, raised to the shortest fibre. */
static double fibre(const mu_fibre_tendon *unit, double fibre_length)
{
    return fmax(fibre_length, unit->min_fibre_length);
}

/* X(l_f) = √(l_f² - w²), the belly's extent along the line of action. */
static double belly_extent(const mu_fibre_tendon *unit, double fibre_length)
{
    return unit->width > 0.0 ? sqrt(fibre_length * fibre_length - unit->width * unit->width) : fibre_length;
}

mu_fibre_forces mu_fibre_forces_at(const mu_fibre_tendon *unit, double fibre_length, double velocity, double activation)
{
    const double l = fibre(unit, fibre_length);
    const double cos_angle = belly_extent(unit, l) / l;
    const double normalized = l / unit->optimal_length;
    const double v = velocity / unit->max_velocity;
    const double scale = unit->max_force * cos_angle;
    return (mu_fibre_forces){
        .active =
            scale * activation * mu_curve_active_length(unit->curves, normalized) * mu_curve_velocity(unit->curves, v),
        .passive = scale * mu_curve_passive_length(unit->curves, normalized),
        .damping = scale * unit->damping * v,
        .cos_angle = cos_angle,
    };
}

static double strain(const mu_fibre_tendon *unit, double path_length, double fibre_length)
{
    return (path_length - belly_extent(unit, fibre(unit, fibre_length)) - unit->slack_length) / unit->slack_length;
}

double mu_fibre_tendon_tension(const mu_fibre_tendon *unit, double path_length, double fibre_length)
{
    return unit->max_force * mu_tendon_force(strain(unit, path_length, fibre_length), unit->strain_at_max_force);
}

/* k_T = dF_T/dl_T, N/m. */
static double tendon_stiffness(const mu_fibre_tendon *unit, double path_length, double fibre_length)
{
    return unit->max_force * mu_tendon_stiffness(strain(unit, path_length, fibre_length), unit->strain_at_max_force) /
           unit->slack_length;
}

/* The static residual: fibre minus tendon, at v = 0. */
static double static_residual(const mu_fibre_tendon *unit, double path_length, double activation, double fibre_length)
{
    const mu_fibre_forces forces = mu_fibre_forces_at(unit, fibre_length, 0.0, activation);
    return forces.active + forces.passive - mu_fibre_tendon_tension(unit, path_length, fibre_length);
}

double mu_fibre_tendon_static_length(const mu_fibre_tendon *unit, double path_length, double activation)
{
    /* The fibre that leaves the tendon exactly slack: X(l) = L - l_s. */
    const double extent = path_length - unit->slack_length;
    const double shortest = unit->min_fibre_length;
    if (!(extent > belly_extent(unit, shortest))) {
        return shortest; /* the tendon is slack even with the shortest fibre */
    }
    double hi = sqrt(extent * extent + unit->width * unit->width);
    /* There the tendon pulls nothing and the fibre pulls >= 0. */
    if (static_residual(unit, path_length, activation, hi) <= 0.0) {
        return hi;
    }
    double lo = shortest;
    if (static_residual(unit, path_length, activation, lo) >= 0.0) {
        return lo; /* the fibre outpulls the tendon down to the shortest fibre */
    }
    for (int i = 0; i < MAX_ITERATIONS; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) {
            break; /* adjacent doubles */
        }
        const double r = static_residual(unit, path_length, activation, mid);
        if (r == 0.0) {
            return mid;
        }
        if (r < 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

/* The dynamic residual g(v) and its slope parts at a trial velocity. */
typedef struct trial {
    double residual;      /* G - T, N */
    double tension;       /* T, N */
    double fibre_slope;   /* ∂G/∂v, N·s/m */
    double tendon_slope;  /* k_T·h·X' (0 at the shortest fibre), N·s/m */
    double tendon_spring; /* k_T, N/m */
    double extent_slope;  /* X' */
} trial;

static trial evaluate(const mu_fibre_tendon *unit, double fibre_length, double activation, double path_length, double h,
                      double v)
{
    const double moved = fibre_length + h * v;
    const double l = fibre(unit, moved);
    const mu_fibre_forces forces = mu_fibre_forces_at(unit, l, v, activation);
    const double normalized = l / unit->optimal_length;
    const double slope = mu_curve_velocity_slope(unit->curves, v / unit->max_velocity);
    const double spring = tendon_stiffness(unit, path_length, l);
    const double extent_slope = 1.0 / forces.cos_angle;
    trial t = {
        .tension = mu_fibre_tendon_tension(unit, path_length, l),
        .fibre_slope = unit->max_force * forces.cos_angle *
                       (activation * mu_curve_active_length(unit->curves, normalized) * slope + unit->damping) /
                       unit->max_velocity,
        .tendon_slope = moved > unit->min_fibre_length ? spring * h * extent_slope : 0.0,
        .tendon_spring = spring,
        .extent_slope = extent_slope,
    };
    t.residual = forces.active + forces.passive + forces.damping - t.tension;
    return t;
}

mu_fibre_tendon_step mu_fibre_tendon_solve(const mu_fibre_tendon *unit, double fibre_length, double activation,
                                           double path_length, double h, double velocity_guess)
{
    const double tolerance = 1e-12 * unit->max_velocity;
    double v = isfinite(velocity_guess) ? velocity_guess : 0.0;
    trial t = evaluate(unit, fibre_length, activation, path_length, h, v);
    /* Bracket the root: g rises with v, so step away from v against the
     * residual's sign, doubling, until it changes sign. */
    double lo = v;
    double hi = v;
    double step = unit->max_velocity;
    for (int i = 0; i < MAX_EXPANSIONS && t.residual != 0.0; ++i) {
        const double probe = t.residual > 0.0 ? lo - step : hi + step;
        const double r = evaluate(unit, fibre_length, activation, path_length, h, probe).residual;
        if (t.residual > 0.0) {
            hi = lo;
            lo = probe;
            if (r <= 0.0) {
                break;
            }
        } else {
            lo = hi;
            hi = probe;
            if (r >= 0.0) {
                break;
            }
        }
        step *= 2.0;
    }
    for (int i = 0; i < MAX_ITERATIONS && t.residual != 0.0 && hi - lo > tolerance; ++i) {
        if (t.residual < 0.0) {
            lo = v;
        } else {
            hi = v;
        }
        double next = v - t.residual / (t.fibre_slope + t.tendon_slope);
        if (!(next > lo && next < hi)) {
            next = 0.5 * (lo + hi);
        }
        const double change = fabs(next - v);
        v = next;
        t = evaluate(unit, fibre_length, activation, path_length, h, v);
        if (change <= tolerance) {
            break;
        }
    }
    /* The tension's answer to the path's speed s, from
     * T = F_T(L + h·s - X(l_f + h·v)) and G(v) = T:
     *   dT/ds = k_T·h·(1 - X'·dv/ds),  dv/ds = (dT/ds)/(∂G/∂v),
     * so dT/ds = k_T·h·∂G/∂v/(∂G/∂v + k_T·h·X'): the springs k_T·h and
     * ∂G/∂v/X' in series (the denominator is at least ∂G/∂v > 0). As
     * k_T → ∞ it tends to ∂G/∂v·cos α, the rigid tendon's damping. */
    const double spring_h = t.tendon_slope > 0.0 ? t.tendon_spring * h : 0.0;
    return (mu_fibre_tendon_step){
        .velocity = v,
        .tension = t.tension,
        .velocity_per_tension = 1.0 / t.fibre_slope,
        .path_damping = spring_h * t.fibre_slope / (t.fibre_slope + spring_h * t.extent_slope),
    };
}
