/* SPDX-License-Identifier: MIT */
/* Building a model from its description, and stepping it. */
#define _POSIX_C_SOURCE 200809L /* locale_t in c_locale.h */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arguments.h"
#include "c_locale.h"
#include "mu/model.h"
#include "mu/motor_pool.h"
#include "mu/torque_actuator.h"

/* The constants of Castanyer's framework ("Implementació d'un model
 * computacional de sistemes musculoesquelètics", 2023-24). */
#define BONE_FRICTION 8.0 /* the original's; bones are sensors, so it never acts */
#define BONE_RESTITUTION 0.5
#define NAIL_HALF_EXTENT 0.0025 /* m: the original's tiny box */
#define IRON_DENSITY 7874.0     /* kg/m³ */
#define WEIGHT_DEPTH 0.10       /* m */
#define DEGREES (180.0 / RB_PI)
#define WARNINGS_SIZE 4096

/* A nail or a bone as built: the engine body it became part of, and its
 * own frame (centre, angle) in that body's frame. */
typedef struct part {
    bool built;
    int body; /* index into model->bodies */
    rb_transform offset;
} part;

struct mu_model {
    const mu_model_desc *desc;
    mu_model_options options;
    rb_world *world;
    mu_curves *curves[2]; /* by mu_model_curve_set */
    rb_body_id *bodies;
    int body_count;
    part *parts; /* nails first, then bones */
    int part_count;
    mu_muscle **muscles; /* by description index; NULL when not built */
    int *built_muscles;  /* description indices of the built muscles */
    int built_muscle_count;
    /* The built torque muscles, each a motor pool driving an actuator. */
    int *built_torque_muscles; /* description indices */
    mu_motor_pool **pools;
    mu_torque_actuator **actuators;
    int built_torque_muscle_count;
    rb_joint_id *hinges;     /* by description index; null id when not built */
    rb_joint_id *welds;      /* by glue index: the weld kept with weld_glues; null id when merged or not built */
    rb_joint_id weight_weld; /* the weight's weld with weld_glues; null id otherwise */
    int joint_count;
    long substeps_taken;      /* since creation; the time is counted, not summed, so it does not drift */
    rb_status substep_status; /* the first error of the muscles' updates in this step */
    char substep_error[512];  /* its message, which later engine calls of the step would clear */
    char warnings[WARNINGS_SIZE];
    char failure[512];      /* mu_model_failure: the first sign the run has failed, "" until then */
    mu_model_energy energy; /* mu_model_energy_account */
    bool energy_started;    /* the account holds a start */
    rb_vec2 energy_gravity; /* m/s², the gravity the account started with */
    double work_rate_h;     /* s, the substep over which the bodies' present velocities acted */
};

mu_model_options mu_default_model_options(void) { return (mu_model_options){.level = 4}; }

static int part_of(const mu_model_desc *desc, mu_model_ref ref)
{
    return ref.kind == MU_MODEL_NAIL ? ref.index : desc->nail_count + ref.index;
}

static void warn(mu_model *model, const char *format, ...)
{
    size_t used = strlen(model->warnings);
    /* Numbers with a '.' whatever the program's locale (c_locale.h). */
    mu_c_locale_scope scope = mu_c_locale_begin();
    va_list args;
    va_start(args, format);
    vsnprintf(model->warnings + used, sizeof model->warnings - used, format, args);
    va_end(args);
    mu_c_locale_end(scope);
    used = strlen(model->warnings);
    if (used + 1 < sizeof model->warnings) {
        model->warnings[used] = '\n';
        model->warnings[used + 1] = '\0';
    }
}

/* The error just reported without the name of the function that
 * reported it ("rb_cable_create: points 0 and 1 coincide" gives "points 0
 * and 1 coincide"): a user knows the model file's objects, not the
 * engine's functions. */
static const char *problem_of_last_error(void)
{
    const char *message = rb_last_error();
    const size_t name = strspn(message, "abcdefghijklmnopqrstuvwxyz0123456789_");
    const bool function =
        (strncmp(message, "rb_", 3) == 0 || strncmp(message, "mu_", 3) == 0) && strncmp(message + name, ": ", 2) == 0;
    return function ? message + name + 2 : message;
}

static const char *source_of(const mu_model_desc *desc) { return desc->source != NULL ? desc->source : desc->name; }

/* Reports, with `status`, that the object `format...` ("muscle \"Biceps\"
 * (muscles[0])") could not be built: "FILE: OBJECT in variant \"V\" cannot
 * be built: PROBLEM". */
static rb_status build_failed(const mu_model *model, rb_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static rb_status build_failed(const mu_model *model, rb_status status, const char *format, ...)
{
    char problem[512], object[256];
    snprintf(problem, sizeof problem, "%s", problem_of_last_error());
    va_list args;
    va_start(args, format);
    vsnprintf(object, sizeof object, format, args);
    va_end(args);
    return rb_report_error(status, "%s: %s in variant \"%s\" cannot be built: %s", source_of(model->desc), object,
                           model->desc->variants[model->options.variant].name, problem);
}

/* "nail \"Nail\" (nails[0])" or "bone \"Humerus\" (bones[1])". */
static rb_status part_failed(const mu_model *model, rb_status status, int part_index)
{
    const mu_model_desc *desc = model->desc;
    if (part_index < desc->nail_count) {
        return build_failed(model, status, "nail \"%s\" (nails[%d])", desc->nails[part_index].name, part_index);
    }
    const int bone = part_index - desc->nail_count;
    return build_failed(model, status, "bone \"%s\" (bones[%d])", desc->bones[bone].name, bone);
}

/* A part's pose in the model, placement included. */
static rb_transform part_pose(const mu_model_desc *desc, int part_index)
{
    if (part_index < desc->nail_count) {
        return (rb_transform){rb_add(desc->nails[part_index].position, desc->placement), rb_rot_identity()};
    }
    const mu_model_bone *bone = &desc->bones[part_index - desc->nail_count];
    return (rb_transform){rb_add(bone->centre, desc->placement), rb_rot_from_angle(bone->angle / DEGREES)};
}

/* ---- union-find over the parts glued together ---------------------------------- */

static int find_root(int *parent, int i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

static void unite(int *parent, int a, int b)
{
    int ra = find_root(parent, a);
    int rb = find_root(parent, b);
    /* The lower index is the root, so the body takes the first part's frame. */
    if (ra < rb) {
        parent[rb] = ra;
    } else if (rb < ra) {
        parent[ra] = rb;
    }
}

/* ---- bodies ----------------------------------------------------------------------- */

/* The damping of a part's body, linear and angular, in 1/s: a bone's own,
 * or the model's for a nail (static, where damping does nothing). */
static double part_damping(const mu_model_desc *desc, int part_index)
{
    return part_index < desc->nail_count ? desc->damping : desc->bones[part_index - desc->nail_count].damping;
}

static bool part_is_static(const mu_model_desc *desc, int part_index)
{
    return part_index < desc->nail_count || desc->bones[part_index - desc->nail_count].is_static;
}

static rb_status add_part_shape(mu_model *model, int part_index)
{
    const mu_model_desc *desc = model->desc;
    const part *p = &model->parts[part_index];
    rb_body_id body = model->bodies[p->body];
    rb_shape_def shape = rb_default_shape_def();
    rb_polygon box;
    rb_status status;
    double angle = rb_rot_angle(p->offset.q);
    if (part_index < desc->nail_count) {
        shape.friction = 0.9;
        shape.restitution = 0.5;
        shape.density = 0.0;
        status = rb_make_offset_box(NAIL_HALF_EXTENT, NAIL_HALF_EXTENT, p->offset.p, angle, &box);
    } else {
        const mu_model_bone *bone = &desc->bones[part_index - desc->nail_count];
        shape.friction = BONE_FRICTION;
        shape.restitution = BONE_RESTITUTION;
        shape.is_sensor = true;
        status = rb_area_density_from_volume(bone->density, bone->depth, &shape.density);
        if (status == RB_OK) {
            status = rb_make_offset_box(0.5 * bone->size.x, 0.5 * bone->size.y, p->offset.p, angle, &box);
        }
    }
    rb_shape_id id;
    return status != RB_OK ? status : rb_shape_create_polygon(model->world, body, &shape, &box, &id);
}

static rb_status build_bodies(mu_model *model, bool merge)
{
    const mu_model_desc *desc = model->desc;
    const mu_model_variant *variant = &desc->variants[model->options.variant];
    int *parent = malloc((size_t)model->part_count * sizeof *parent);
    int *body_of_root = malloc((size_t)model->part_count * sizeof *body_of_root);
    model->bodies = malloc((size_t)model->part_count * sizeof *model->bodies);
    if (parent == NULL || body_of_root == NULL || model->bodies == NULL) {
        free(parent);
        free(body_of_root);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_create: out of memory");
    }
    for (int i = 0; i < model->part_count; ++i) {
        parent[i] = i;
        body_of_root[i] = -1;
        bool is_nail = i < desc->nail_count;
        model->parts[i].built = is_nail || mu_model_variant_has_bone(variant, i - desc->nail_count);
    }
    if (merge) {
        for (int g = 0; g < desc->glue_count; ++g) {
            int a = part_of(desc, desc->glues[g].body_a);
            int b = part_of(desc, desc->glues[g].body_b);
            if (model->parts[a].built && model->parts[b].built) {
                unite(parent, a, b);
            }
        }
    }
    /* A component with a static member is static as a whole. */
    bool *is_static = calloc((size_t)model->part_count, sizeof *is_static);
    if (is_static == NULL) {
        free(parent);
        free(body_of_root);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_create: out of memory");
    }
    for (int i = 0; i < model->part_count; ++i) {
        if (model->parts[i].built && part_is_static(desc, i)) {
            is_static[find_root(parent, i)] = true;
        }
    }
    rb_status status = RB_OK;
    for (int i = 0; i < model->part_count && status == RB_OK; ++i) {
        if (!model->parts[i].built) {
            continue;
        }
        int root = find_root(parent, i);
        rb_transform root_pose = part_pose(desc, root);
        if (body_of_root[root] < 0) {
            rb_body_def def = rb_default_body_def();
            def.type = is_static[root] ? RB_BODY_STATIC : RB_BODY_DYNAMIC;
            def.position = root_pose.p;
            def.angle = rb_rot_angle(root_pose.q);
            /* Glued parts take the first one's damping, as they take its frame. */
            def.linear_damping = part_damping(desc, root);
            def.angular_damping = part_damping(desc, root);
            def.bullet = true;
            status = rb_body_create(model->world, &def, &model->bodies[model->body_count]);
            body_of_root[root] = model->body_count++;
        }
        model->parts[i].body = body_of_root[root];
        model->parts[i].offset = rb_inv_mul_transforms(root_pose, part_pose(desc, i));
        if (status == RB_OK) {
            status = add_part_shape(model, i);
        }
        if (status != RB_OK) {
            status = part_failed(model, status, i);
        }
    }
    free(is_static);
    free(parent);
    free(body_of_root);
    return status;
}

/* ---- joints ------------------------------------------------------------------------ */

static rb_vec2 local_anchor(const mu_model *model, int part_index, rb_vec2 point)
{
    return rb_transform_point(model->parts[part_index].offset, point);
}

static rb_status build_hinges(mu_model *model)
{
    const mu_model_desc *desc = model->desc;
    for (int h = 0; h < desc->hinge_count; ++h) {
        const mu_model_hinge *hinge = &desc->hinges[h];
        int a = part_of(desc, hinge->body_a);
        int b = part_of(desc, hinge->body_b);
        if (!model->parts[a].built || !model->parts[b].built) {
            continue;
        }
        if (model->parts[a].body == model->parts[b].body) {
            warn(model, "hinge '%s' joins two parts glued into one body; it does nothing", hinge->name);
            continue;
        }
        /* The file's joint angle is angle(bone B) - angle(bone A); each
         * bone's angle is its body's plus its offset in the body. */
        double phi_a = rb_rot_angle(model->parts[a].offset.q);
        double phi_b = rb_rot_angle(model->parts[b].offset.q);
        rb_revolute_joint_def def = rb_default_revolute_joint_def();
        def.body_a = model->bodies[model->parts[a].body];
        def.body_b = model->bodies[model->parts[b].body];
        def.local_anchor_a = local_anchor(model, a, hinge->anchor_a);
        def.local_anchor_b = local_anchor(model, b, hinge->anchor_b);
        def.reference_angle = phi_a - phi_b;
        def.enable_lower_limit = hinge->has_lower;
        def.enable_upper_limit = hinge->has_upper;
        def.lower_angle = hinge->lower / DEGREES;
        def.upper_angle = hinge->upper / DEGREES;
        rb_status status = rb_revolute_joint_create(model->world, &def, &model->hinges[h]);
        if (status != RB_OK) {
            return build_failed(model, status, "hinge \"%s\" (hinges[%d])", hinge->name, h);
        }
        model->joint_count++;
    }
    return RB_OK;
}

/* With weld_glues: a weld joint for each glue between two built parts of
 * different bodies, anchored at part B's centre. */
static rb_status build_welds(mu_model *model)
{
    const mu_model_desc *desc = model->desc;
    for (int g = 0; g < desc->glue_count; ++g) {
        int a = part_of(desc, desc->glues[g].body_a);
        int b = part_of(desc, desc->glues[g].body_b);
        if (!model->parts[a].built || !model->parts[b].built || model->parts[a].body == model->parts[b].body) {
            continue;
        }
        rb_weld_joint_def def = rb_default_weld_joint_def();
        rb_body_id body_a = model->bodies[model->parts[a].body];
        rb_body_id body_b = model->bodies[model->parts[b].body];
        rb_status status = rb_weld_joint_def_at(&def, model->world, body_a, body_b, part_pose(desc, b).p);
        if (status == RB_OK) {
            status = rb_weld_joint_create(model->world, &def, &model->welds[g]);
        }
        if (status != RB_OK) {
            return build_failed(model, status, "glue \"%s\" (glues[%d])", desc->glues[g].name, g);
        }
        model->joint_count++;
    }
    return RB_OK;
}

/* ---- the weight -------------------------------------------------------------------- */

static rb_status build_weight(mu_model *model, bool merge)
{
    const mu_model_desc *desc = model->desc;
    if (!desc->has_weight) {
        return RB_OK;
    }
    const mu_model_weight *weight = &desc->weight;
    if (model->options.weight_index < 0 || model->options.weight_index >= weight->mass_count) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_create: weight index %d, expected 0 .. %d",
                               model->options.weight_index, weight->mass_count - 1);
    }
    double mass = weight->masses[model->options.weight_index];
    int carrier = part_of(desc, weight->body);
    if (mass <= 0.0 || !model->parts[carrier].built) {
        return RB_OK;
    }
    /* An iron disc of the given depth: m = ρ·π·r²·depth. */
    double area_density = IRON_DENSITY * WEIGHT_DEPTH;
    double radius = sqrt(mass / (area_density * RB_PI));
    rb_vec2 centre = rb_add(weight->position, desc->placement);
    rb_shape_def shape = rb_default_shape_def();
    shape.density = area_density;
    shape.is_sensor = true;
    rb_body_id carrier_body = model->bodies[model->parts[carrier].body];
    rb_shape_id id;
    if (merge) {
        rb_circle disc = {rb_body_local_point(model->world, carrier_body, centre), radius};
        rb_status status = rb_shape_create_circle(model->world, carrier_body, &shape, &disc, &id);
        return status == RB_OK ? RB_OK : build_failed(model, status, "weight \"%s\" of %g kg", weight->name, mass);
    }
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = centre;
    /* Welded to its carrier, the disc moves as the carrier does, damped alike. */
    def.linear_damping = part_damping(desc, carrier);
    def.angular_damping = part_damping(desc, carrier);
    rb_body_id body;
    rb_status status = rb_body_create(model->world, &def, &body);
    rb_circle disc = {{0.0, 0.0}, radius};
    if (status == RB_OK) {
        status = rb_shape_create_circle(model->world, body, &shape, &disc, &id);
    }
    rb_weld_joint_def weld = rb_default_weld_joint_def();
    if (status == RB_OK) {
        status = rb_weld_joint_def_at(&weld, model->world, carrier_body, body, centre);
    }
    if (status == RB_OK) {
        status = rb_weld_joint_create(model->world, &weld, &model->weight_weld);
    }
    if (status != RB_OK) {
        return build_failed(model, status, "weight \"%s\" of %g kg", weight->name, mass);
    }
    model->joint_count++;
    return RB_OK;
}

/* ---- muscles ------------------------------------------------------------------------- */

static rb_status build_muscles(mu_model *model)
{
    const mu_model_desc *desc = model->desc;
    const mu_model_variant *variant = &desc->variants[model->options.variant];
    for (int m = 0; m < desc->muscle_count; ++m) {
        if (!mu_model_variant_has_muscle(variant, m)) {
            continue;
        }
        const mu_model_muscle *muscle = &desc->muscles[m];
        mu_muscle_def def = mu_default_muscle_def();
        def.point_count = muscle->point_count;
        for (int i = 0; i < muscle->point_count; ++i) {
            int p = part_of(desc, muscle->path[i].body);
            def.bodies[i] = model->bodies[model->parts[p].body];
            def.local_points[i] = local_anchor(model, p, muscle->path[i].point);
        }
        def.rest_length = muscle->rest_length;
        def.max_force = muscle->max_force;
        def.rest_width = muscle->rest_width;
        def.specific_tension = muscle->specific_tension;
        def.max_velocity = muscle->max_velocity;
        def.start_normalized_length = muscle->start_normalized_length;
        def.tendon_length = muscle->tendon_length;
        def.curves = model->curves[muscle->curves];
        def.pennation_angle = muscle->pennation_angle / DEGREES;
        def.activation_dynamics = muscle->activation_dynamics;
        def.activation_time = muscle->activation_time;
        def.deactivation_time = muscle->deactivation_time;
        def.activation_model = muscle->activation_model;
        def.calcium_force = muscle->calcium_force;
        def.compliant_tendon = muscle->compliant_tendon;
        def.tendon_strain_at_max_force = muscle->tendon_strain_at_max_force;
        def.fibre_damping = muscle->fibre_damping;
        rb_status status = mu_muscle_create(model->world, &def, &model->muscles[m]);
        if (status != RB_OK) {
            return build_failed(model, status, "muscle \"%s\" (muscles[%d])", muscle->name, m);
        }
        model->built_muscles[model->built_muscle_count++] = m;
        mu_muscle_readout r = mu_muscle_read(model->muscles[m]);
        /* (A compliant tendon's fibre starts in equilibrium, not at the
         * start length, and its slack length was checked at load.) */
        if (muscle->tendon_length < 0.0 && !muscle->compliant_tendon &&
            fabs(r.normalized_length - muscle->start_normalized_length) > 1e-9) {
            warn(model,
                 "muscle '%s': its path is shorter than rest length × start normalized length (%.4f m), so its "
                 "tendon has length 0 and its belly starts at %.3f of its rest length, not %.3f",
                 muscle->name, muscle->rest_length * muscle->start_normalized_length, r.normalized_length,
                 muscle->start_normalized_length);
        }
    }
    return RB_OK;
}

/* Whether the torque muscle's bones exist in the built variant. */
static bool torque_muscle_in_variant(const mu_model_variant *variant, const mu_model_torque_muscle *muscle)
{
    return mu_model_variant_has_bone(variant, muscle->body.index) &&
           (!muscle->has_reaction_body || muscle->reaction_body.kind == MU_MODEL_NAIL ||
            mu_model_variant_has_bone(variant, muscle->reaction_body.index));
}

static rb_status build_torque_muscles(mu_model *model)
{
    const mu_model_desc *desc = model->desc;
    const mu_model_variant *variant = &desc->variants[model->options.variant];
    for (int t = 0; t < desc->torque_muscle_count; ++t) {
        const mu_model_torque_muscle *muscle = &desc->torque_muscles[t];
        if (!torque_muscle_in_variant(variant, muscle)) {
            continue;
        }
        const int built = model->built_torque_muscle_count;
        mu_torque_actuator_def def = mu_default_torque_actuator_def();
        def.body = model->bodies[model->parts[part_of(desc, muscle->body)].body];
        if (muscle->has_reaction_body) {
            def.reaction_body = model->bodies[model->parts[part_of(desc, muscle->reaction_body)].body];
        }
        def.peak_torque = muscle->peak_torque;
        /* A file's pool was read at load; a generated one is made here. */
        rb_status status = muscle->strengths != NULL
                               ? mu_motor_pool_create(muscle->strengths, muscle->neurons, &model->pools[built])
                               : mu_motor_pool_create_exponential(muscle->neurons, muscle->weakest, muscle->strongest,
                                                                  &model->pools[built]);
        if (status == RB_OK) {
            status = mu_torque_actuator_create(model->world, &def, &model->actuators[built]);
        }
        if (status != RB_OK) {
            mu_motor_pool_destroy(model->pools[built]);
            model->pools[built] = NULL;
            return build_failed(model, status, "torque muscle \"%s\" (torque_muscles[%d])", muscle->name, t);
        }
        model->built_torque_muscles[built] = t;
        model->built_torque_muscle_count++;
        mu_motor_pool_recruit(model->pools[built], muscle->recruited);
        mu_motor_pool_drive_torque(model->pools[built], model->actuators[built]);
    }
    return RB_OK;
}

/* ---- creation ---------------------------------------------------------------------- */

static rb_status allocate(mu_model *model)
{
    const mu_model_desc *desc = model->desc;
    model->part_count = desc->nail_count + desc->bone_count;
    model->parts = calloc((size_t)model->part_count + 1, sizeof *model->parts);
    model->muscles = calloc((size_t)desc->muscle_count + 1, sizeof *model->muscles);
    model->built_muscles = calloc((size_t)desc->muscle_count + 1, sizeof *model->built_muscles);
    model->hinges = calloc((size_t)desc->hinge_count + 1, sizeof *model->hinges);
    model->welds = calloc((size_t)desc->glue_count + 1, sizeof *model->welds);
    model->built_torque_muscles = calloc((size_t)desc->torque_muscle_count + 1, sizeof *model->built_torque_muscles);
    model->pools = calloc((size_t)desc->torque_muscle_count + 1, sizeof *model->pools);
    model->actuators = calloc((size_t)desc->torque_muscle_count + 1, sizeof *model->actuators);
    if (model->parts == NULL || model->muscles == NULL || model->built_muscles == NULL || model->hinges == NULL ||
        model->welds == NULL || model->built_torque_muscles == NULL || model->pools == NULL ||
        model->actuators == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_create: out of memory");
    }
    return RB_OK;
}

static rb_status measure_muscles(mu_model *model)
{
    rb_status status = RB_OK;
    for (int i = 0; status == RB_OK && i < model->built_muscle_count; ++i) {
        status = mu_muscle_measure(model->muscles[model->built_muscles[i]], model->world);
    }
    return status;
}

/* ---- the energy account (mu_model_energy_account) --------------------- */

/* J: kinetic energy plus potential energy in gravity of the moving bodies. */
static double mechanical_energy(const mu_model *model)
{
    const rb_vec2 g = rb_world_gravity(model->world);
    double energy = 0.0;
    for (int b = 0; b < model->body_count; ++b) {
        const rb_mass_data mass = rb_body_mass_data(model->world, model->bodies[b]);
        if (mass.mass == 0.0) {
            continue; /* static: neither moves nor falls */
        }
        const rb_vec2 v = rb_body_linear_velocity(model->world, model->bodies[b]);
        const double w = rb_body_angular_velocity(model->world, model->bodies[b]);
        const rb_vec2 x = rb_body_world_center(model->world, model->bodies[b]);
        energy += 0.5 * mass.mass * rb_dot(v, v) + 0.5 * mass.rotational_inertia * w * w - mass.mass * rb_dot(g, x);
    }
    return energy;
}

/* W: the rate at which the muscles and torque muscles do work on the
 * bodies at their present velocities. A cable's tension T shortening it
 * at −L' does T·(−L'); a torque τ turning its body against its reaction
 * body at Δω does τ·Δω. The engine moves the bodies with the velocities
 * a substep ends with (semi-implicit Euler), so that rate times the
 * substep is the work of the substep. The muscles have just been
 * measured at these velocities (their readout's total force is the
 * cable's T, and they keep the L' they read), so their paths are not
 * read again. */
static double work_rate(const mu_model *model)
{
    double rate = 0.0;
    for (int i = 0; i < model->built_muscle_count; ++i) {
        const mu_muscle *muscle = model->muscles[model->built_muscles[i]];
        rate -= mu_muscle_tension(muscle) * mu_muscle_path_speed(muscle);
    }
    for (int t = 0; t < model->built_torque_muscle_count; ++t) {
        rate += mu_torque_actuator_power(model->actuators[t], model->world);
    }
    return rate;
}

/* Adds the work of the substep that just ended (of work_rate_h s) to the
 * account; called once the muscles have measured that substep: as every
 * substep after the first starts, and after the step's last. */
static void account_substep_work(mu_model *model)
{
    if (model->energy_started && model->work_rate_h > 0.0) {
        const double work = model->work_rate_h * work_rate(model);
        model->energy.muscle_work += work;
        model->energy.muscle_work_gross += fabs(work);
    }
    model->work_rate_h = 0.0;
}

/* After a step: the energy now, and the account started again when it
 * had not started or something outside the model acted on its world. */
static void account_energy(mu_model *model)
{
    const rb_vec2 g = rb_world_gravity(model->world);
    const bool outside = rb_world_statistics(model->world).joint_count != model->joint_count;
    model->energy.mechanical = mechanical_energy(model);
    if (!model->energy_started || outside || g.x != model->energy_gravity.x || g.y != model->energy_gravity.y) {
        model->energy.at_start = model->energy.mechanical;
        model->energy.muscle_work = 0.0;
        model->energy.muscle_work_gross = 0.0;
        model->energy_gravity = g;
        model->energy_started = !outside;
    }
    model->energy.created = model->energy.mechanical - model->energy.at_start - model->energy.muscle_work;
}

mu_model_energy mu_model_energy_account(const mu_model *model)
{
    if (mu_refuse_null("mu_model_energy_account", "model", model)) {
        return (mu_model_energy){NAN, NAN, NAN, NAN, NAN};
    }
    return model->energy;
}

/* The engine's substep callback: each substep after the first starts by
 * reading what the previous one did to the muscles (and, from that
 * reading, the work it did); then every muscle sets its cable's tension
 * law from its state now. The first error is kept for mu_model_step to
 * report, since the step cannot stop midway. */
static void update_muscles(rb_world *world, int substep, double h, void *context)
{
    mu_model *model = context;
    rb_status status = RB_OK;
    int failed = -1;
    for (int i = 0; status == RB_OK && i < model->built_muscle_count; ++i) {
        mu_muscle *muscle = model->muscles[model->built_muscles[i]];
        status = substep > 0 ? mu_muscle_advance(muscle, world, h) : mu_muscle_prepare(muscle, world, h);
        failed = status != RB_OK ? model->built_muscles[i] : failed;
    }
    account_substep_work(model);
    model->work_rate_h = h;
    if (model->substep_status == RB_OK && status != RB_OK) {
        model->substep_status = status;
        /* Named now, in the user's terms: the engine calls left in the step clear the message. */
        mu_c_locale_scope scope = mu_c_locale_begin();
        snprintf(model->substep_error, sizeof model->substep_error, "%s: muscle \"%s\" (muscles[%d]) at t = %.6g s: %s",
                 source_of(model->desc), model->desc->muscles[failed].name, failed, mu_model_time(model) + substep * h,
                 problem_of_last_error());
        mu_c_locale_end(scope);
    }
}

static rb_status create_world_and_curves(mu_model *model)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = model->desc->gravity;
    /* One engine step per frame, split into the model's substeps (600 Hz
     * for the built-in models); the muscles update at the start of each substep from
     * the substep callback. At 600 Hz, 4 velocity and 1 position pass
     * give the motion the original's 8 and 3 give (the arm's biceps holds the
     * elbow at 134.5 degrees either way, the model tests pass) for 70 %
     * of the time. */
    def.enable_profile = false; /* a tenth of a small model's step */
    def.solver.substeps = model->desc->substeps;
    def.solver.velocity_iterations = 4;
    def.solver.position_iterations = 1;
    rb_status status = rb_world_create(&def, &model->world);
    if (status == RB_OK) {
        status = rb_world_set_substep_callback(model->world, update_muscles, model);
    }
    if (status == RB_OK) {
        status = mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &model->curves[MU_MODEL_CURVES_TABULATED]);
    }
    if (status == RB_OK) {
        mu_analytic_curves analytic = mu_default_analytic_curves();
        status = mu_curves_create_analytic(&analytic, &model->curves[MU_MODEL_CURVES_ANALYTIC]);
    }
    return status;
}

rb_status mu_model_create(const mu_model_desc *desc, const mu_model_options *options, mu_model **out)
{
    if (out == NULL || desc == NULL || options == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_create: desc, options and out must not be NULL");
    }
    *out = NULL;
    if (options->level < 0 || options->level > 4) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_create: level %d, expected 0 .. 4", options->level);
    }
    if (options->variant < 0 || options->variant >= desc->variant_count) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_create: variant %d, expected 0 .. %d",
                               options->variant, desc->variant_count - 1);
    }
    if (desc->has_weight &&
        mu_refuse_index("mu_model_create", "weight_index", options->weight_index, desc->weight.mass_count)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    mu_model *model = calloc(1, sizeof *model);
    if (model == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_create: out of memory");
    }
    model->desc = desc;
    model->options = *options;
    bool merge = !options->weld_glues && options->level >= 2;
    rb_status status = allocate(model);
    if (status == RB_OK) {
        status = create_world_and_curves(model);
    }
    if (status == RB_OK && options->level >= 1) {
        status = build_bodies(model, merge);
    }
    if (status == RB_OK && options->level >= 2) {
        status = build_hinges(model);
    }
    if (status == RB_OK && options->level >= 2 && !merge) {
        status = build_welds(model);
    }
    if (status == RB_OK && options->level >= 3) {
        status = build_muscles(model);
    }
    if (status == RB_OK && options->level >= 3) {
        status = build_torque_muscles(model);
    }
    if (status == RB_OK && options->level >= 4) {
        status = build_weight(model, merge);
    }
    if (status != RB_OK) {
        /* Destroying the world clears the engine's last error: the
         * message of the failed build is kept across it. */
        char message[512];
        snprintf(message, sizeof message, "%s", rb_last_error());
        mu_model_destroy(model);
        return rb_report_error(status, "%s", message);
    }
    *out = model;
    return RB_OK;
}

void mu_model_destroy(mu_model *model)
{
    if (model == NULL) {
        return;
    }
    for (int m = 0; m < model->desc->muscle_count && model->muscles != NULL; ++m) {
        mu_muscle_destroy(model->muscles[m], model->world);
    }
    for (int t = 0; t < model->built_torque_muscle_count; ++t) {
        mu_motor_pool_destroy(model->pools[t]);
        mu_torque_actuator_destroy(model->actuators[t]);
    }
    free(model->built_torque_muscles);
    free(model->pools);
    free(model->actuators);
    rb_world_destroy(model->world);
    mu_curves_destroy(model->curves[0]);
    mu_curves_destroy(model->curves[1]);
    free(model->bodies);
    free(model->parts);
    free(model->muscles);
    free(model->built_muscles);
    free(model->hinges);
    free(model->welds);
    free(model);
}

/* ---- running ------------------------------------------------------------------------- */

rb_world *mu_model_world(mu_model *model)
{
    return mu_refuse_null("mu_model_world", "model", model) ? NULL : model->world;
}
const rb_world *mu_model_world_to_read(const mu_model *model)
{
    return mu_refuse_null("mu_model_world_to_read", "model", model) ? NULL : model->world;
}
const mu_model_desc *mu_model_description(const mu_model *model)
{
    return mu_refuse_null("mu_model_description", "model", model) ? NULL : model->desc;
}
double mu_model_time(const mu_model *model)
{
    if (mu_refuse_null("mu_model_time", "model", model)) {
        return NAN;
    }
    return (double)model->substeps_taken / (model->desc->frame_rate * model->desc->substeps);
}
double mu_model_frame_duration(const mu_model *model)
{
    return mu_refuse_null("mu_model_frame_duration", "model", model) ? NAN : 1.0 / model->desc->frame_rate;
}
double mu_model_substep_duration(const mu_model *model)
{
    if (mu_refuse_null("mu_model_substep_duration", "model", model)) {
        return NAN;
    }
    return 1.0 / (model->desc->frame_rate * model->desc->substeps);
}

/* The name of body `b`: that of its first part (a body merged from glued
 * parts carries several). */
static const char *body_name(const mu_model *model, int b)
{
    for (int p = 0; p < model->part_count; ++p) {
        if (model->parts[p].built && model->parts[p].body == b) {
            return mu_model_part_name(model, p);
        }
    }
    return "(a body)";
}

/* Keeps in model->failure the first sign, after a step, that the run no
 * longer describes a body: a non-finite or runaway pose or speed, a
 * hinge torn open, or energy no muscle gave (MU_MODEL_MAX_HINGE_GAP and
 * the others, in mu/model.h).
 * The engine's solver answers forces it cannot hold (a huge weight, a
 * huge Fmax) with joints that stretch rather than with an error, so this
 * is where a run is told it has left physics. */
static void watch(mu_model *model)
{
    if (model->failure[0] != '\0') {
        return;
    }
    double t = mu_model_time(model);
    mu_c_locale_scope scope = mu_c_locale_begin();
    for (int h = 0; h < model->desc->hinge_count && model->failure[0] == '\0'; ++h) {
        if (rb_joint_id_is_null(model->hinges[h])) {
            continue;
        }
        double gap = rb_distance(rb_joint_world_anchor_a(model->world, model->hinges[h]),
                                 rb_joint_world_anchor_b(model->world, model->hinges[h]));
        if (!(gap <= MU_MODEL_MAX_HINGE_GAP)) {
            snprintf(model->failure, sizeof model->failure,
                     "t = %.4f s: hinge \"%s\" opened by %.3g m (more than %g m): the joints cannot hold the "
                     "forces",
                     t, model->desc->hinges[h].name, gap, MU_MODEL_MAX_HINGE_GAP);
        }
    }
    for (int b = 0; b < model->body_count && model->failure[0] == '\0'; ++b) {
        double speed = rb_length(rb_body_linear_velocity(model->world, model->bodies[b]));
        double spin = fabs(rb_body_angular_velocity(model->world, model->bodies[b]));
        if (!(speed <= MU_MODEL_MAX_SPEED)) {
            snprintf(model->failure, sizeof model->failure, "t = %.4f s: \"%s\" moves at %.3g m/s (more than %g m/s)",
                     t, body_name(model, b), speed, MU_MODEL_MAX_SPEED);
        } else if (!(spin <= MU_MODEL_MAX_ANGULAR_SPEED)) {
            snprintf(model->failure, sizeof model->failure,
                     "t = %.4f s: \"%s\" turns at %.3g rad/s (more than %g rad/s)", t, body_name(model, b), spin,
                     MU_MODEL_MAX_ANGULAR_SPEED);
        }
    }
    const mu_model_energy *energy = &model->energy;
    if (model->failure[0] == '\0' && !(energy->created <= MU_MODEL_MAX_CREATED_ENERGY + energy->muscle_work_gross)) {
        snprintf(model->failure, sizeof model->failure,
                 "t = %.4f s: the bodies gained %.3g J that no muscle gave them (more than %g J plus the muscles' "
                 "%.3g J of work): the solver, or something outside the model, added energy",
                 t, energy->created, MU_MODEL_MAX_CREATED_ENERGY, energy->muscle_work_gross);
    }
    mu_c_locale_end(scope);
}

/* Steps the world by `substeps` of the model's substeps, as one engine
 * step (the muscles update from the substep callback), then reads the
 * muscles. */
static rb_status advance(mu_model *model, int substeps)
{
    model->substep_status = RB_OK;
    /* Torques hold over every substep of the step (rb_body_apply_torque). */
    for (int t = 0; t < model->built_torque_muscle_count; ++t) {
        rb_status applied = mu_torque_actuator_apply(model->actuators[t], model->world);
        if (applied != RB_OK) {
            return applied;
        }
    }
    rb_status status = rb_world_step(model->world, substeps * mu_model_substep_duration(model));
    if (status == RB_OK && model->substep_status != RB_OK) {
        status = rb_report_error(model->substep_status, "%s", model->substep_error);
    }
    if (status == RB_OK) {
        status = measure_muscles(model);
    }
    if (status == RB_OK) {
        model->substeps_taken += substeps;
        account_substep_work(model);
        account_energy(model);
        watch(model);
    }
    return status;
}

rb_status mu_model_substep(mu_model *model)
{
    if (model == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_substep: model is NULL");
    }
    /* One engine step of one substep: the same solve as a substep of a
     * frame, with collision run before it rather than once per frame. */
    rb_solver_settings frame = rb_world_solver_settings(model->world);
    rb_solver_settings single = frame;
    single.substeps = 1;
    rb_status status = rb_world_set_solver_settings(model->world, &single);
    if (status == RB_OK) {
        status = advance(model, 1);
        rb_status restored = rb_world_set_solver_settings(model->world, &frame);
        status = status == RB_OK ? restored : status;
    }
    return status;
}

rb_status mu_model_step(mu_model *model)
{
    if (model == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_step: model is NULL");
    }
    return advance(model, model->desc->substeps);
}

/* Applies `set` to every built muscle of the muscle or group `name`. */
static rb_status for_each_muscle(mu_model *model, const char *name, const char *function,
                                 rb_status (*set)(mu_muscle *, double), double value)
{
    if (mu_refuse_null(function, "model", model) || mu_refuse_null(function, "name", name) ||
        mu_refuse_non_finite(function, set == mu_muscle_set_activation ? "activation" : "newtons", value)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    mu_model_ref ref;
    if (!mu_model_desc_find(model->desc, name, &ref) || (ref.kind != MU_MODEL_MUSCLE && ref.kind != MU_MODEL_GROUP)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: no muscle or group named '%s'", function, name);
    }
    int count = ref.kind == MU_MODEL_MUSCLE ? 1 : model->desc->groups[ref.index].muscle_count;
    for (int i = 0; i < count; ++i) {
        int m = ref.kind == MU_MODEL_MUSCLE ? ref.index : model->desc->groups[ref.index].muscles[i];
        if (model->muscles[m] != NULL) {
            rb_status status = set(model->muscles[m], value);
            if (status != RB_OK) {
                return status;
            }
        }
    }
    return RB_OK;
}

rb_status mu_model_set_activation(mu_model *model, const char *name, double activation)
{
    return for_each_muscle(model, name, "mu_model_set_activation", mu_muscle_set_activation, activation);
}

rb_status mu_model_set_tension(mu_model *model, const char *name, double newtons)
{
    return for_each_muscle(model, name, "mu_model_set_tension", mu_muscle_set_target_tension, newtons);
}

/* Whether `index` is refused as a built muscle's (NULL model included). */
static bool refuse_built(const mu_model *model, int index, const char *function)
{
    return mu_refuse_null(function, "model", model) ||
           mu_refuse_index(function, "index", index, model->built_muscle_count);
}

rb_status mu_model_set_activation_at(mu_model *model, int index, double activation)
{
    const char *f = "mu_model_set_activation_at";
    if (refuse_built(model, index, f) || mu_refuse_non_finite(f, "activation", activation)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    return mu_muscle_set_activation(model->muscles[model->built_muscles[index]], activation);
}

rb_status mu_model_set_tension_at(mu_model *model, int index, double newtons)
{
    const char *f = "mu_model_set_tension_at";
    if (refuse_built(model, index, f) || mu_refuse_non_finite(f, "newtons", newtons)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    return mu_muscle_set_target_tension(model->muscles[model->built_muscles[index]], newtons);
}

double mu_model_group_activation(const mu_model *model, const char *name)
{
    const char *f = "mu_model_group_activation";
    if (mu_refuse_null(f, "model", model) || mu_refuse_null(f, "name", name)) {
        return NAN;
    }
    mu_model_ref ref;
    if (!mu_model_desc_find(model->desc, name, &ref) || (ref.kind != MU_MODEL_MUSCLE && ref.kind != MU_MODEL_GROUP)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: no muscle or group named '%s'", f, name);
        return NAN;
    }
    int count = ref.kind == MU_MODEL_MUSCLE ? 1 : model->desc->groups[ref.index].muscle_count;
    double sum = 0.0;
    int built = 0;
    for (int i = 0; i < count; ++i) {
        int m = ref.kind == MU_MODEL_MUSCLE ? ref.index : model->desc->groups[ref.index].muscles[i];
        if (model->muscles[m] != NULL) {
            sum += mu_muscle_read(model->muscles[m]).activation;
            ++built;
        }
    }
    return built > 0 ? sum / built : 0.0;
}

rb_status mu_model_set_gravity(mu_model *model, rb_vec2 gravity)
{
    const char *f = "mu_model_set_gravity";
    if (mu_refuse_null(f, "model", model) || mu_refuse_non_finite(f, "gravity.x", gravity.x) ||
        mu_refuse_non_finite(f, "gravity.y", gravity.y)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    return rb_world_set_gravity(model->world, gravity);
}

int mu_model_muscle_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_muscle_count", "model", model) ? 0 : model->built_muscle_count;
}
const char *mu_model_muscle_name(const mu_model *model, int index)
{
    return refuse_built(model, index, "mu_model_muscle_name") ? NULL
                                                              : model->desc->muscles[model->built_muscles[index]].name;
}
mu_muscle_readout mu_model_muscle_readout(const mu_model *model, int index)
{
    return refuse_built(model, index, "mu_model_muscle_readout")
               ? mu_nan_readout()
               : mu_muscle_read(model->muscles[model->built_muscles[index]]);
}
const mu_muscle *mu_model_built_muscle(const mu_model *model, int index)
{
    return refuse_built(model, index, "mu_model_built_muscle") ? NULL : model->muscles[model->built_muscles[index]];
}
const char *mu_model_failure(const mu_model *model)
{
    if (mu_refuse_null("mu_model_failure", "model", model)) {
        return NULL;
    }
    return model->failure[0] != '\0' ? model->failure : NULL;
}
const char *mu_model_warnings(const mu_model *model)
{
    return mu_refuse_null("mu_model_warnings", "model", model) ? NULL : model->warnings;
}

int mu_model_hinge_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_hinge_count", "model", model) ? 0 : model->desc->hinge_count;
}
/* Whether `index` is refused as a hinge's (NULL model included). */
static bool refuse_hinge(const mu_model *model, int index, const char *function)
{
    return mu_refuse_null(function, "model", model) ||
           mu_refuse_index(function, "index", index, model->desc->hinge_count);
}
const char *mu_model_hinge_name(const mu_model *model, int index)
{
    return refuse_hinge(model, index, "mu_model_hinge_name") ? NULL : model->desc->hinges[index].name;
}
double mu_model_hinge_angle(const mu_model *model, int index)
{
    if (refuse_hinge(model, index, "mu_model_hinge_angle") || rb_joint_id_is_null(model->hinges[index])) {
        return NAN;
    }
    /* The engine's reference angle holds the bones' offsets in their
     * bodies, so its joint angle is already angle(bone B) - angle(bone A). */
    return rb_revolute_joint_angle(model->world, model->hinges[index]) * DEGREES;
}

int mu_model_part_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_part_count", "model", model) ? 0 : model->part_count;
}
/* Whether `index` is refused as a part's (NULL model included). */
static bool refuse_part(const mu_model *model, int index, const char *function)
{
    return mu_refuse_null(function, "model", model) || mu_refuse_index(function, "index", index, model->part_count);
}
const char *mu_model_part_name(const mu_model *model, int index)
{
    if (refuse_part(model, index, "mu_model_part_name")) {
        return NULL;
    }
    const mu_model_desc *desc = model->desc;
    return index < desc->nail_count ? desc->nails[index].name : desc->bones[index - desc->nail_count].name;
}

static rb_transform part_world_pose(const mu_model *model, int index)
{
    const part *p = &model->parts[index];
    return rb_mul_transforms(rb_body_transform(model->world, model->bodies[p->body]), p->offset);
}

rb_vec2 mu_model_part_centre(const mu_model *model, int index)
{
    if (refuse_part(model, index, "mu_model_part_centre")) {
        return rb_v2(NAN, NAN);
    }
    return model->parts[index].built ? part_world_pose(model, index).p : rb_v2(NAN, NAN);
}

double mu_model_part_angle(const mu_model *model, int index)
{
    if (refuse_part(model, index, "mu_model_part_angle")) {
        return NAN;
    }
    return model->parts[index].built ? rb_rot_angle(part_world_pose(model, index).q) * DEGREES : NAN;
}

int mu_model_body_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_body_count", "model", model) ? 0 : model->body_count;
}
int mu_model_joint_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_joint_count", "model", model) ? 0 : model->joint_count;
}

/* ---- torque muscles ------------------------------------------------------------------ */

int mu_model_torque_muscle_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_torque_muscle_count", "model", model) ? 0 : model->built_torque_muscle_count;
}

static int find_torque_muscle(const mu_model *model, const char *name, const char *function)
{
    if (mu_refuse_null(function, "name", name)) {
        return -1;
    }
    for (int t = 0; t < model->built_torque_muscle_count; ++t) {
        if (strcmp(model->desc->torque_muscles[model->built_torque_muscles[t]].name, name) == 0) {
            return t;
        }
    }
    /* The names a caller may use, in the model's order: "A", "B" (the
     * engine's message holds 512 bytes, so a long list is cut short). */
    char names[320] = "";
    size_t used = 0;
    for (int t = 0; t < model->built_torque_muscle_count && used < sizeof names; ++t) {
        const char *other = model->desc->torque_muscles[model->built_torque_muscles[t]].name;
        const int written = snprintf(names + used, sizeof names - used, "%s\"%s\"", t > 0 ? ", " : "", other);
        used += written > 0 ? (size_t)written : 0;
    }
    if (used >= sizeof names) {
        /* Cut at the start of a UTF-8 character, room left for ", …". */
        size_t cut = sizeof names - sizeof ", …";
        while (cut > 0 && ((unsigned char)names[cut] & 0xc0u) == 0x80u) {
            --cut;
        }
        snprintf(names + cut, sizeof names - cut, ", …");
    }
    if (model->built_torque_muscle_count == 0) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "%s: no torque muscle named \"%s\": this model builds no torque muscle (in this variant "
                        "and level)",
                        function, name);
    } else {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "%s: no torque muscle named \"%s\" is built in this model, expected %s%s", function, name,
                        model->built_torque_muscle_count == 1 ? "" : "one of ", names);
    }
    return -1;
}

static bool torque_index_ok(const mu_model *model, int index, const char *function)
{
    return !mu_refuse_null(function, "model", model) &&
           !mu_refuse_index(function, "index", index, model->built_torque_muscle_count);
}

const char *mu_model_torque_muscle_name(const mu_model *model, int index)
{
    if (!torque_index_ok(model, index, "mu_model_torque_muscle_name")) {
        return NULL;
    }
    return model->desc->torque_muscles[model->built_torque_muscles[index]].name;
}

/* Recruits `neurons` of torque muscle `index` (checked), refusing a count
 * outside its pool rather than clamping it. */
static rb_status recruit(mu_model *model, int index, int neurons, const char *function)
{
    if (mu_refuse_index(function, "neurons", neurons, mu_motor_pool_neuron_count(model->pools[index]) + 1)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    mu_motor_pool_recruit(model->pools[index], neurons);
    return mu_motor_pool_drive_torque(model->pools[index], model->actuators[index]);
}

rb_status mu_model_recruit_at(mu_model *model, int index, int neurons)
{
    const char *f = "mu_model_recruit_at";
    return torque_index_ok(model, index, f) ? recruit(model, index, neurons, f) : RB_ERR_INVALID_ARGUMENT;
}

rb_status mu_model_recruit(mu_model *model, const char *name, int neurons)
{
    const char *f = "mu_model_recruit";
    if (mu_refuse_null(f, "model", model)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const int index = find_torque_muscle(model, name, f);
    return index < 0 ? RB_ERR_INVALID_ARGUMENT : recruit(model, index, neurons, f);
}

const mu_motor_pool *mu_model_motor_pool(const mu_model *model, int index)
{
    return torque_index_ok(model, index, "mu_model_motor_pool") ? model->pools[index] : NULL;
}

const mu_torque_actuator *mu_model_torque_actuator(const mu_model *model, int index)
{
    return torque_index_ok(model, index, "mu_model_torque_actuator") ? model->actuators[index] : NULL;
}

/* ---- the engine objects behind the names --------------------------------------------- */

rb_joint_id mu_model_hinge_joint(const mu_model *model, int index)
{
    return refuse_hinge(model, index, "mu_model_hinge_joint") ? (rb_joint_id){0} : model->hinges[index];
}

int mu_model_glue_count(const mu_model *model)
{
    return mu_refuse_null("mu_model_glue_count", "model", model) ? 0 : model->desc->glue_count;
}

static bool refuse_glue(const mu_model *model, int index, const char *function)
{
    return mu_refuse_null(function, "model", model) ||
           mu_refuse_index(function, "index", index, model->desc->glue_count);
}

const char *mu_model_glue_name(const mu_model *model, int index)
{
    return refuse_glue(model, index, "mu_model_glue_name") ? NULL : model->desc->glues[index].name;
}

rb_joint_id mu_model_glue_joint(const mu_model *model, int index)
{
    return refuse_glue(model, index, "mu_model_glue_joint") ? (rb_joint_id){0} : model->welds[index];
}

rb_joint_id mu_model_weight_joint(const mu_model *model)
{
    return mu_refuse_null("mu_model_weight_joint", "model", model) ? (rb_joint_id){0} : model->weight_weld;
}

double mu_model_weight_mass(const mu_model *model)
{
    if (mu_refuse_null("mu_model_weight_mass", "model", model)) {
        return NAN;
    }
    const mu_model_desc *desc = model->desc;
    if (!desc->has_weight || !model->parts[part_of(desc, desc->weight.body)].built) {
        return 0.0;
    }
    return desc->weight.masses[model->options.weight_index];
}

rb_body_id mu_model_body(const mu_model *model, int index)
{
    if (mu_refuse_null("mu_model_body", "model", model) ||
        mu_refuse_index("mu_model_body", "index", index, model->body_count)) {
        return (rb_body_id){0};
    }
    return model->bodies[index];
}

int mu_model_part_body(const mu_model *model, int index)
{
    if (refuse_part(model, index, "mu_model_part_body")) {
        return -1;
    }
    return model->parts[index].built ? model->parts[index].body : -1;
}

int mu_model_muscle_description_index(const mu_model *model, int index)
{
    return refuse_built(model, index, "mu_model_muscle_description_index") ? -1 : model->built_muscles[index];
}

mu_muscle *mu_model_muscle_at(mu_model *model, int index)
{
    return refuse_built(model, index, "mu_model_muscle_at") ? NULL : model->muscles[model->built_muscles[index]];
}
