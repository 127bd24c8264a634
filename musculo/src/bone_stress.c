/* SPDX-License-Identifier: MIT */
/* Bone stress by the method of sections (mu/bone_stress.h). */
#include <math.h>
#include <stdlib.h>

#include "arguments.h"
#include "mu/bone_stress.h"
#include "mu/model_desc.h"
#include "mu/muscle.h"
#include "mu/torque_actuator.h"

#define DEGREES (180.0 / RB_PI)
/* The defaults of a description made in code (model_desc.h, model_schema.c). */
#define DEFAULT_WALL_FRACTION 0.25
#define DEFAULT_MODULUS 17e9
#define DEFAULT_TENSILE_STRENGTH 133e6
#define DEFAULT_COMPRESSIVE_STRENGTH 193e6
/* Loads closer than this fraction of a bone's length are at one point
 * (gather): some 10⁴ roundings of a coordinate, a picometre on a 0.4 m
 * bone. */
#define COINCIDENT 1e-12
/* The weight disc (model.c): iron, 0.10 m deep. */
#define DISC_AREA_DENSITY (7874.0 * 0.10)

/* A force at a point and a couple, on one part. */
typedef struct point_load {
    int part;
    rb_vec2 point; /* m, world */
    rb_vec2 force; /* N */
    double couple; /* N·m */
    double s;      /* m along the bone being read (gather), clamped to its ends */
} point_load;

/* One rigid body's loads and motion, and the field per unit mass
 * f(p) = f0 + ω²(p - C) - β k×(p - C) (mu/bone_stress.h). */
typedef struct body_loads {
    int body;
    point_load *loads;
    int count, capacity;
    rb_vec2 centre;       /* C, m */
    rb_vec2 f0;           /* m/s²: g - a_c - c·v_c */
    rb_vec2 acceleration; /* a_c, m/s² */
    double alpha;         /* rad/s² */
    double omega2;        /* 1/s² */
    double beta;          /* 1/s²: α + c·ω */
    int disc_part;        /* the part carrying the merged weight disc, or -1 */
    double disc_mass, disc_inertia;
    rb_vec2 disc_centre;
} body_loads;

static rb_vec2 part_point(const mu_model *model, int part, rb_vec2 local)
{
    return rb_add(mu_model_part_centre(model, part),
                  rb_rotate(rb_rot_from_angle(mu_model_part_angle(model, part) / DEGREES), local));
}

static int part_of(const mu_model_desc *desc, mu_model_ref ref)
{
    return ref.kind == MU_MODEL_NAIL ? ref.index : desc->nail_count + ref.index;
}

static bool on_body(const mu_model *model, const body_loads *b, int part)
{
    return mu_model_part_body(model, part) == b->body;
}

static bool add_load(body_loads *b, int part, rb_vec2 point, rb_vec2 force, double couple)
{
    if (b->count == b->capacity) {
        const int capacity = 2 * b->capacity + 16;
        point_load *grown = realloc(b->loads, (size_t)capacity * sizeof *grown);
        if (grown == NULL) {
            return false;
        }
        b->loads = grown;
        b->capacity = capacity;
    }
    b->loads[b->count++] = (point_load){part, point, force, couple, 0.0};
    return true;
}

/* A joint's reaction: (force, torque) on part B at its anchor, the
 * opposite on part A, each when it is on the body. */
static bool add_joint(const mu_model *model, body_loads *b, rb_joint_id joint, int part_a, int part_b, rb_vec2 anchor)
{
    if (rb_joint_id_is_null(joint)) {
        return true;
    }
    const rb_world *world = mu_model_world_to_read(model);
    const rb_vec2 force = rb_joint_reaction_force(world, joint);
    const double torque = rb_joint_reaction_torque(world, joint);
    bool ok = true;
    if (part_b >= 0 && on_body(model, b, part_b)) {
        ok = add_load(b, part_b, anchor, force, torque);
    }
    if (ok && part_a >= 0 && on_body(model, b, part_a)) {
        ok = add_load(b, part_a, anchor, rb_neg(force), -torque);
    }
    return ok;
}

/* Each path point on the body is pulled towards its neighbours on the path
 * with the cable's tension. */
static bool add_muscles(const mu_model *model, body_loads *b)
{
    const mu_model_desc *desc = mu_model_description(model);
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        const mu_model_muscle *muscle = &desc->muscles[mu_model_muscle_description_index(model, m)];
        /* What the solver applied in the last substep (rb/cable.h). */
        const double tension =
            rb_cable_tension(mu_model_world_to_read(model), mu_muscle_cable(mu_model_built_muscle(model, m)));
        for (int k = 0; k < muscle->point_count; ++k) {
            const int part = part_of(desc, muscle->path[k].body);
            if (!on_body(model, b, part)) {
                continue;
            }
            const rb_vec2 here = part_point(model, part, muscle->path[k].point);
            rb_vec2 pull = rb_v2(0.0, 0.0);
            for (int n = k - 1; n <= k + 1; n += 2) {
                if (n >= 0 && n < muscle->point_count) {
                    const rb_vec2 there = part_point(model, part_of(desc, muscle->path[n].body), muscle->path[n].point);
                    pull = rb_add(pull, rb_scale(tension, rb_normalize(rb_sub(there, here))));
                }
            }
            if (!add_load(b, part, here, pull, 0.0)) {
                return false;
            }
        }
    }
    return true;
}

/* A torque muscle's torque on its bone, the opposite on its reaction
 * bone (a couple: placed at the bone's centre, where it acts alike). */
static bool add_torque_muscles(const mu_model *model, body_loads *b)
{
    const mu_model_desc *desc = mu_model_description(model);
    for (int t = 0; t < mu_model_torque_muscle_count(model); ++t) {
        mu_model_ref ref;
        if (!mu_model_desc_find(desc, mu_model_torque_muscle_name(model, t), &ref)) {
            return false;
        }
        const mu_model_torque_muscle *muscle = &desc->torque_muscles[ref.index];
        const double torque = mu_torque_actuator_torque(mu_model_torque_actuator(model, t));
        const int part = part_of(desc, muscle->body);
        bool ok =
            !on_body(model, b, part) || add_load(b, part, mu_model_part_centre(model, part), rb_v2(0.0, 0.0), torque);
        if (ok && muscle->has_reaction_body) {
            const int reaction = part_of(desc, muscle->reaction_body);
            ok = !on_body(model, b, reaction) ||
                 add_load(b, reaction, mu_model_part_centre(model, reaction), rb_v2(0.0, 0.0), -torque);
        }
        if (!ok) {
            return false;
        }
    }
    return true;
}

/* The weight disc: merged into its carrier, a point mass of the body;
 * kept as a body of its own, its weld's reaction on the carrier. */
static bool add_weight(const mu_model *model, body_loads *b)
{
    const mu_model_desc *desc = mu_model_description(model);
    b->disc_part = -1;
    if (!desc->has_weight) {
        return true;
    }
    const int carrier = part_of(desc, desc->weight.body);
    if (!on_body(model, b, carrier)) {
        return true;
    }
    /* The disc's centre in the carrier's frame, from the start pose. */
    const mu_model_bone *bone = &desc->bones[desc->weight.body.index];
    const rb_vec2 local =
        desc->weight.body.kind == MU_MODEL_NAIL
            ? rb_sub(desc->weight.position, desc->nails[desc->weight.body.index].position)
            : rb_rotate(rb_rot_from_angle(-bone->angle / DEGREES), rb_sub(desc->weight.position, bone->centre));
    const rb_vec2 centre = part_point(model, carrier, local);
    const rb_joint_id weld = mu_model_weight_joint(model);
    if (!rb_joint_id_is_null(weld)) {
        return add_joint(model, b, weld, carrier, -1, centre);
    }
    const double mass = mu_model_weight_mass(model);
    if (mass > 0.0) {
        b->disc_part = carrier;
        b->disc_mass = mass;
        b->disc_inertia = 0.5 * mass * mass / (DISC_AREA_DENSITY * RB_PI); /* m·r²/2, r² = m/(ρ_A·π) */
        b->disc_centre = centre;
    }
    return true;
}

/* Newton's law for the whole body gives its acceleration; the field per
 * unit mass follows (mu/bone_stress.h). */
static void solve_motion(const mu_model *model, body_loads *b)
{
    const rb_world *world = mu_model_world_to_read(model);
    const rb_body_id id = mu_model_body(model, b->body);
    const double mass = rb_body_mass(world, id);
    const double inertia = rb_body_rotational_inertia(world, id);
    const rb_vec2 v = rb_body_linear_velocity(world, id);
    const double omega = rb_body_angular_velocity(world, id);
    b->centre = rb_body_world_center(world, id);
    rb_vec2 force = rb_v2(0.0, 0.0);
    double moment = 0.0;
    for (int i = 0; i < b->count; ++i) {
        force = rb_add(force, b->loads[i].force);
        moment += rb_cross(rb_sub(b->loads[i].point, b->centre), b->loads[i].force) + b->loads[i].couple;
    }
    const double linear_damping = rb_body_linear_damping(world, id);
    const double angular_damping = rb_body_angular_damping(world, id);
    const rb_vec2 gravity = rb_scale(rb_body_gravity_scale(world, id), rb_world_gravity(world));
    const rb_vec2 a = rb_add(rb_scale(1.0 / mass, force), rb_sub(gravity, rb_scale(linear_damping, v)));
    const double alpha = inertia > 0.0 ? moment / inertia - angular_damping * omega : 0.0;
    b->acceleration = a;
    b->alpha = alpha;
    b->f0 = rb_sub(rb_sub(gravity, a), rb_scale(linear_damping, v));
    b->omega2 = omega * omega;
    b->beta = alpha + angular_damping * omega;
}

/* Collects every load on body `body`; false on memory. */
static bool collect(const mu_model *model, int body, body_loads *b)
{
    *b = (body_loads){.body = body, .disc_part = -1};
    const mu_model_desc *desc = mu_model_description(model);
    bool ok = true;
    for (int h = 0; ok && h < mu_model_hinge_count(model); ++h) {
        const mu_model_hinge *hinge = &desc->hinges[h];
        const int a = part_of(desc, hinge->body_a);
        const int bb = part_of(desc, hinge->body_b);
        ok = add_joint(model, b, mu_model_hinge_joint(model, h), a, bb, part_point(model, bb, hinge->anchor_b));
    }
    for (int g = 0; ok && g < mu_model_glue_count(model); ++g) {
        const int a = part_of(desc, desc->glues[g].body_a);
        const int bb = part_of(desc, desc->glues[g].body_b);
        ok = add_joint(model, b, mu_model_glue_joint(model, g), a, bb, mu_model_part_centre(model, bb));
    }
    ok = ok && add_muscles(model, b) && add_torque_muscles(model, b) && add_weight(model, b);
    if (ok) {
        solve_motion(model, b);
    }
    return ok;
}

static rb_vec2 field(const body_loads *b, rb_vec2 p)
{
    const rb_vec2 r = rb_sub(p, b->centre);
    return rb_add(b->f0, rb_sub(rb_scale(b->omega2, r), rb_scale(b->beta, rb_cross_sv(1.0, r))));
}

/* A resultant: force and moment about `about`. */
typedef struct wrench {
    rb_vec2 force;
    double moment;
} wrench;

static void add_force(wrench *w, rb_vec2 about, rb_vec2 point, rb_vec2 force, double couple)
{
    w->force = rb_add(w->force, force);
    w->moment += rb_cross(rb_sub(point, about), force) + couple;
}

/* The spread loads over the piece of bone part `part` with centroid q,
 * mass m and polar inertia i about q. */
static void add_spread(wrench *w, const body_loads *b, rb_vec2 about, rb_vec2 q, double m, double i)
{
    add_force(w, about, q, rb_scale(m, field(b, q)), -b->beta * i);
}

/* ---- one bone ------------------------------------------------------------------------- */

typedef struct bone_frame {
    int part;
    rb_vec2 centre, axis; /* world; axis along the long side */
    double length, width, mass;
} bone_frame;

static bone_frame frame_of(const mu_model *model, int bone)
{
    const mu_model_desc *desc = mu_model_description(model);
    const mu_model_bone *d = &desc->bones[bone];
    const bool along_x = d->size.x >= d->size.y;
    const int part = desc->nail_count + bone;
    return (bone_frame){
        .part = part,
        .centre = mu_model_part_centre(model, part),
        .axis = rb_rotate(rb_rot_from_angle(mu_model_part_angle(model, part) / DEGREES),
                          along_x ? rb_v2(1.0, 0.0) : rb_v2(0.0, 1.0)),
        .length = along_x ? d->size.x : d->size.y,
        .width = along_x ? d->size.y : d->size.x,
        .mass = d->density * d->size.x * d->size.y * d->depth,
    };
}

/* The point loads on one bone, each with its coordinate along the axis. */
typedef struct bone_loads {
    bone_frame frame;
    const body_loads *body; /* its rigid body's (collect) */
    point_load *loads;      /* every load on the body (module comment), by s */
    double *s;              /* each load's coordinate along the axis, ascending */
    wrench *tail;           /* tail[i]: loads i .. count - 1 about the bone's centre */
    int count;
} bone_loads;

static double along(const bone_frame *f, rb_vec2 point)
{
    const double s = rb_dot(rb_sub(point, f->centre), f->axis);
    return fmax(-0.5 * f->length, fmin(0.5 * f->length, s));
}

static void free_bone(bone_loads *l)
{
    free(l->loads);
    free(l->s);
    free(l->tail);
}

/* Orders loads by their coordinate along the bone. */
static int by_coordinate(const void *a, const void *b)
{
    const double sa = ((const point_load *)a)->s, sb = ((const point_load *)b)->s;
    return (sa > sb) - (sa < sb);
}

/* No body's loads collected yet: where gather collects them. */
#define NO_BODY ((body_loads){.body = -1, .disc_part = -1})

/* RB_OK and the loads; ABSENT (no error recorded) for a bone not built or
 * fixed to the ground; else the error. `body` holds the loads of the
 * bone's rigid body: collected into it unless it holds them already (the
 * bones glued into one body share them); the caller frees body->loads. */
#define ABSENT ((rb_status)-1)
static rb_status gather(const mu_model *model, int bone, const char *f, body_loads *body, bone_loads *l)
{
    *l = (bone_loads){.loads = NULL};
    if (mu_refuse_null(f, "model", model) ||
        mu_refuse_index(f, "bone", bone, mu_model_description(model)->bone_count)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const mu_model_desc *desc = mu_model_description(model);
    const int index = mu_model_part_body(model, desc->nail_count + bone);
    if (index < 0 || rb_body_mass(mu_model_world_to_read(model), mu_model_body(model, index)) <= 0.0) {
        return ABSENT;
    }
    l->frame = frame_of(model, bone);
    const int parts = mu_model_part_count(model);
    bool ok = true;
    if (body->body != index) {
        free(body->loads);
        ok = collect(model, index, body);
        body->body = ok ? index : -1;
    }
    l->body = body;
    const int most = body->count + parts + 1;
    l->loads = ok ? malloc((size_t)most * sizeof *l->loads) : NULL;
    l->s = ok ? malloc((size_t)most * sizeof *l->s) : NULL;
    l->tail = ok ? malloc(((size_t)most + 1) * sizeof *l->tail) : NULL;
    if (l->loads == NULL || l->s == NULL || l->tail == NULL) {
        free_bone(l);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    }
    /* The bone's own loads, and those of every part glued to it (the rest
     * of its rigid body), each at its point; the other parts' spread loads
     * and the disc's as one force and couple at their centres. */
    for (int i = 0; i < body->count; ++i) {
        l->loads[l->count++] = body->loads[i];
    }
    for (int p = desc->nail_count; p < parts; ++p) {
        if (p != l->frame.part && on_body(model, body, p)) {
            const bone_frame glued = frame_of(model, p - desc->nail_count);
            wrench w = {{0.0, 0.0}, 0.0};
            add_spread(&w, body, glued.centre, glued.centre, glued.mass,
                       glued.mass * (glued.length * glued.length + glued.width * glued.width) / 12.0);
            l->loads[l->count++] = (point_load){p, glued.centre, w.force, w.moment, 0.0};
        }
    }
    if (body->disc_part >= 0) {
        wrench w = {{0.0, 0.0}, 0.0};
        add_spread(&w, body, body->disc_centre, body->disc_centre, body->disc_mass, body->disc_inertia);
        l->loads[l->count++] = (point_load){body->disc_part, body->disc_centre, w.force, w.moment, 0.0};
    }
    /* Sorted along the axis, with the sums of the loads from each on: a
     * section's loads beyond it are then one tail. */
    for (int i = 0; i < l->count; ++i) {
        l->loads[i].s = along(&l->frame, l->loads[i].point);
    }
    qsort(l->loads, (size_t)l->count, sizeof *l->loads, by_coordinate);
    /* Loads given at one point (a weight on a hinge's pin, a muscle at a
     * joint's anchor) reach here from different bodies' frames, and
     * rounding may set them a few units in the last place apart: a
     * section between them would carry one without the other. Loads
     * closer than COINCIDENT of the bone's length are at one point. */
    for (int i = 1; i < l->count; ++i) {
        if (l->loads[i].s - l->loads[i - 1].s <= COINCIDENT * l->frame.length) {
            l->loads[i].s = l->loads[i - 1].s;
        }
    }
    l->tail[l->count] = (wrench){{0.0, 0.0}, 0.0};
    for (int i = l->count - 1; i >= 0; --i) {
        l->s[i] = l->loads[i].s;
        l->tail[i] = l->tail[i + 1];
        add_force(&l->tail[i], l->frame.centre, l->loads[i].point, l->loads[i].force, l->loads[i].couple);
    }
    return RB_OK;
}

static mu_bone_section nan_section(double s) { return (mu_bone_section){s, NAN, NAN, NAN, NAN, NAN}; }

/* The wrench about the section's centre of every load beyond s. */
static wrench beyond(const bone_loads *l, double s, bool include_at_s)
{
    const bone_frame *f = &l->frame;
    const rb_vec2 q = rb_add(f->centre, rb_scale(s, f->axis));
    /* The first load beyond the cut: s_i > s, or s_i >= s including s. */
    int low = 0, high = l->count;
    while (low < high) {
        const int mid = (low + high) / 2;
        if (l->s[mid] > s || (include_at_s && l->s[mid] == s)) {
            high = mid;
        } else {
            low = mid + 1;
        }
    }
    /* Moved from the centre to q: M_q = M_centre - (q - centre)×F. */
    wrench w = l->tail[low];
    w.moment -= rb_cross(rb_sub(q, f->centre), w.force);
    /* The piece from s to L/2: a box of length piece and the bone's width. */
    const double piece = 0.5 * f->length - s;
    if (piece > 0.0) {
        const double m = f->mass * piece / f->length;
        const rb_vec2 centroid = rb_add(q, rb_scale(0.5 * piece, f->axis));
        add_spread(&w, l->body, q, centroid, m, m * (piece * piece + f->width * f->width) / 12.0);
    }
    return w;
}

static mu_bone_section section_of(const bone_loads *l, const mu_bone_beam *beam, double s, bool include_at_s)
{
    const wrench w = beyond(l, s, include_at_s);
    const double n = rb_dot(w.force, l->frame.axis);
    const double bending = fabs(w.moment) * 0.5 * beam->outer_diameter / beam->second_moment;
    const double tension = n / beam->area + bending;
    const double compression = n / beam->area - bending;
    double safety = INFINITY;
    if (tension > 0.0) {
        safety = fmin(safety, beam->tensile_strength / tension);
    }
    if (compression < 0.0) {
        safety = fmin(safety, beam->compressive_strength / -compression);
    }
    return (mu_bone_section){
        .s = s,
        .axial_force = n,
        .shear_force = rb_cross(l->frame.axis, w.force),
        .bending_moment = w.moment,
        .stress = fabs(tension) >= fabs(compression) ? tension : compression,
        .safety_factor = safety,
    };
}

/* One bone's loads and its body's, for a readout of that bone alone. */
typedef struct one_bone {
    body_loads body;
    bone_loads bone;
} one_bone;

static rb_status gather_one(const mu_model *model, int bone, const char *f, one_bone *one)
{
    one->body = NO_BODY;
    const rb_status status = gather(model, bone, f, &one->body, &one->bone);
    if (status != RB_OK) {
        free(one->body.loads);
    }
    return status;
}

static void free_one(one_bone *one)
{
    free_bone(&one->bone);
    free(one->body.loads);
}

/* ---- the API -------------------------------------------------------------------------- */

static double or_default(double value, double fallback) { return value > 0.0 ? value : fallback; }

static mu_bone_beam beam_of(const mu_model_bone *d)
{
    const double length = fmax(d->size.x, d->size.y);
    const double outer = fmin(d->size.x, d->size.y);
    const double wall = or_default(d->wall_thickness, DEFAULT_WALL_FRACTION * outer);
    const double inner = outer - 2.0 * wall;
    const double outer2 = outer * outer, inner2 = inner * inner;
    return (mu_bone_beam){
        .length = length,
        .outer_diameter = outer,
        .wall_thickness = wall,
        .area = RB_PI * (outer2 - inner2) / 4.0,
        .second_moment = RB_PI * (outer2 * outer2 - inner2 * inner2) / 64.0,
        .youngs_modulus = or_default(d->youngs_modulus, DEFAULT_MODULUS),
        .tensile_strength = or_default(d->tensile_strength, DEFAULT_TENSILE_STRENGTH),
        .compressive_strength = or_default(d->compressive_strength, DEFAULT_COMPRESSIVE_STRENGTH),
    };
}

mu_bone_beam mu_model_bone_beam(const mu_model *model, int bone)
{
    const char *f = "mu_model_bone_beam";
    if (mu_refuse_null(f, "model", model) ||
        mu_refuse_index(f, "bone", bone, mu_model_description(model)->bone_count)) {
        return (mu_bone_beam){NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
    }
    return beam_of(&mu_model_description(model)->bones[bone]);
}

mu_bone_section mu_model_bone_section(const mu_model *model, int bone, double s, bool include_at_s)
{
    one_bone one;
    if (mu_refuse_non_finite("mu_model_bone_section", "s", s) ||
        gather_one(model, bone, "mu_model_bone_section", &one) != RB_OK) {
        return nan_section(s);
    }
    const mu_bone_beam beam = beam_of(&mu_model_description(model)->bones[bone]);
    const mu_bone_section section = section_of(&one.bone, &beam, s, include_at_s);
    free_one(&one);
    return section;
}

rb_status mu_model_bone_sections(const mu_model *model, int bone, int count, mu_bone_section *sections)
{
    const char *f = "mu_model_bone_sections";
    if (mu_refuse_null(f, "sections", sections) || mu_refuse_index(f, "count", count - 1, MU_MODEL_MAX_OBJECTS)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    one_bone one;
    const rb_status status = gather_one(model, bone, f, &one);
    if (status == ABSENT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: bone %d is not built or is fixed to the ground", f, bone);
    }
    if (status != RB_OK) {
        return status;
    }
    const mu_bone_beam beam = beam_of(&mu_model_description(model)->bones[bone]);
    for (int k = 0; k < count; ++k) {
        sections[k] = section_of(&one.bone, &beam, beam.length * ((k + 0.5) / count - 0.5), false);
    }
    free_one(&one);
    return RB_OK;
}

static void keep_worse(mu_bone_section *worst, mu_bone_section candidate)
{
    if (candidate.safety_factor < worst->safety_factor ||
        (isinf(worst->safety_factor) && fabs(candidate.stress) > fabs(worst->stress))) {
        *worst = candidate;
    }
}

/* The worst of the sections mu/bone_stress.h lists. */
static mu_bone_stress worst_of(const mu_model *model, int bone, const bone_loads *l)
{
    const mu_bone_beam beam = beam_of(&mu_model_description(model)->bones[bone]);
    const double half = 0.5 * beam.length;
    mu_bone_section worst = section_of(l, &beam, half, false);
    for (int j = 0; j <= MU_BONE_STRESS_SECTIONS; ++j) {
        const double s = -half + beam.length * j / MU_BONE_STRESS_SECTIONS;
        keep_worse(&worst, section_of(l, &beam, s, false)); /* a load at s: both sides below */
    }
    for (int i = 0; i < l->count; ++i) {
        keep_worse(&worst, section_of(l, &beam, l->s[i], false));
        keep_worse(&worst, section_of(l, &beam, l->s[i], true));
    }
    return (mu_bone_stress){worst, worst.stress / beam.youngs_modulus};
}

static mu_bone_stress nan_stress(void) { return (mu_bone_stress){nan_section(NAN), NAN}; }

mu_bone_stress mu_model_bone_stress(const mu_model *model, int bone)
{
    one_bone one;
    if (gather_one(model, bone, "mu_model_bone_stress", &one) != RB_OK) {
        return nan_stress();
    }
    const mu_bone_stress stress = worst_of(model, bone, &one.bone);
    free_one(&one);
    return stress;
}

rb_status mu_model_bone_stresses(const mu_model *model, mu_bone_stress *stresses)
{
    const char *f = "mu_model_bone_stresses";
    if (mu_refuse_null(f, "model", model)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const mu_model_desc *desc = mu_model_description(model);
    if (desc->bone_count > 0 && mu_refuse_null(f, "stresses", stresses)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    /* Each rigid body's loads, collected for its first bone and shared by
     * the bones glued to it. */
    const int body_count = mu_model_body_count(model);
    body_loads *bodies = malloc(((size_t)body_count + 1) * sizeof *bodies);
    if (bodies == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    }
    for (int i = 0; i < body_count; ++i) {
        bodies[i] = NO_BODY;
    }
    rb_status status = RB_OK;
    for (int b = 0; status == RB_OK && b < desc->bone_count; ++b) {
        stresses[b] = nan_stress();
        const int body = mu_model_part_body(model, desc->nail_count + b);
        if (body < 0) {
            continue; /* not built */
        }
        bone_loads l;
        status = gather(model, b, f, &bodies[body], &l);
        if (status == RB_OK) {
            stresses[b] = worst_of(model, b, &l);
            free_bone(&l);
        } else if (status == ABSENT) {
            status = RB_OK; /* fixed to the ground */
        }
    }
    for (int i = 0; i < body_count; ++i) {
        free(bodies[i].loads);
    }
    free(bodies);
    return status;
}

rb_status mu_model_bone_balance(const mu_model *model, int bone, rb_vec2 *force, double *moment, double *load_scale)
{
    const char *f = "mu_model_bone_balance";
    if (mu_refuse_null(f, "force", force) || mu_refuse_null(f, "moment", moment) ||
        mu_refuse_null(f, "load_scale", load_scale)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    one_bone one;
    const rb_status status = gather_one(model, bone, f, &one);
    if (status == ABSENT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: bone %d is not built or is fixed to the ground", f, bone);
    }
    if (status != RB_OK) {
        return status;
    }
    /* Every load: the section at the near end, all of them beyond it. */
    const wrench w = beyond(&one.bone, -0.5 * one.bone.frame.length, true);
    const rb_vec2 end = rb_sub(one.bone.frame.centre, rb_scale(0.5 * one.bone.frame.length, one.bone.frame.axis));
    *force = w.force;
    *moment = w.moment + rb_cross(rb_sub(end, one.bone.frame.centre), w.force);
    *load_scale = one.bone.frame.mass * rb_length(rb_world_gravity(mu_model_world_to_read(model)));
    for (int i = 0; i < one.bone.count; ++i) {
        *load_scale += rb_length(one.bone.loads[i].force);
    }
    free_one(&one);
    return RB_OK;
}

rb_status mu_model_bone_acceleration(const mu_model *model, int bone, rb_vec2 *acceleration, double *alpha)
{
    const char *f = "mu_model_bone_acceleration";
    if (mu_refuse_null(f, "acceleration", acceleration) || mu_refuse_null(f, "alpha", alpha)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    one_bone one;
    const rb_status status = gather_one(model, bone, f, &one);
    if (status == ABSENT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: bone %d is not built or is fixed to the ground", f, bone);
    }
    if (status == RB_OK) {
        *acceleration = one.bone.body->acceleration;
        *alpha = one.bone.body->alpha;
        free_one(&one);
    }
    return status;
}
