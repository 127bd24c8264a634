/* SPDX-License-Identifier: MIT */
/* Reads a model file into a mu_model_desc, section by section: nails and
 * bones first, so that the joints, the weight and the muscles after them
 * can name them; muscles before the groups and variants that list them.
 * The first problem found stops the read. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "data_file.h"
#include "model_schema.h"
#include "mu/geometry_lengths.h"
#include "mu/motor_pool.h"
#include "mu/muscle.h"
#include "mu/muscle_statics.h"
#include "name_index.h"
#include "pool_profile.h"
#include "rb/geometry.h"

/* The defaults of Castanyer's framework ("Implementació d'un model
 * computacional de sistemes musculoesquelètics", 2023-24). */
#define DEFAULT_GRAVITY_Y (-9.8)       /* m/s² */
#define DEFAULT_FRAME_RATE 60.0        /* Hz */
#define DEFAULT_SUBSTEPS 10            /* per frame */
#define DEFAULT_BONE_DENSITY 1900.0    /* kg/m³ */
#define DEFAULT_BONE_DAMPING 8.0       /* 1/s, linear and angular */
#define DEFAULT_SPECIFIC_TENSION 1.5e6 /* N/m², the original code's (its report's table says 3e5) */
#define DEFAULT_MAX_VELOCITY 0.25      /* m/s */
#define DEFAULT_START_NORMALIZED_LENGTH 1.0
#define DEFAULT_SYMMETRY 0.5
/* Pennation at optimal length: physiological angles lie below about 30°
 * (Lieber and Fridén 2000); the model's cap is 84.26° (pennation.h). */
#define MAX_PENNATION_DEGREES 80.0
#define DEGREES (180.0 / RB_PI)
/* The original's named minimal and maximal normalized lengths: the range
 * its muscles work in. */
#define MIN_START_NORMALIZED_LENGTH 0.5
#define MAX_START_NORMALIZED_LENGTH 1.5
/* A hinge limit beyond a full turn is a mistake, usually the original's ±999°
 * for "no limit", which the format says by leaving the limit out. */
#define MAX_LIMIT_DEGREES 360.0
#define MAX_SUBSTEPS 1000

/* The ranges of the numbers the simulation can take. JSON numbers are
 * finite, but a finite 1e200 still overflows a force, a mass or a path
 * length to infinity, and 1e-300 divides to it; within these ranges every
 * product the model forms stays finite. Each is wide of what bodies and
 * muscles have (a bone of 1 mm to 100 m, a muscle force of 1 mN to 1 MN),
 * yet narrow enough that the solver still runs on what they give
 * (tests/test_model_ranges.c runs every end of every range). */
/* m: a model within 100 m of its origin, whose bones are at most 100 m long. */
static const mu_json_bounds coordinate = {-100.0, 100.0, false, false};
/* m/s²: 100 g. */
static const mu_json_bounds gravity_component = {-1e3, 1e3, false, false};
/* Hz: a frame is a row of the CSV. */
static const mu_json_bounds frame_rate = {1.0, 1e3, false, false};
/* m: a bone's extents and depth, a muscle's rest length. */
static const mu_json_bounds extent = {1e-3, 100.0, false, false};
static const mu_json_bounds angle_degrees = {-MAX_LIMIT_DEGREES, MAX_LIMIT_DEGREES, false, false};
/* kg/m³: from cork (about 100) down to 1, up to 5 times osmium's 22,590. */
static const mu_json_bounds density = {1.0, 1e5, false, false};
/* 1/s: a bone's velocity decays as exp(-c·t); 1000/s stops it within a
 * few milliseconds, and v/(1 + h·c) stays stable for any c. */
static const mu_json_bounds damping = {0.0, 1e3, false, false};
/* Pa: from soft tissue (1 MPa) to a thousand times cortical bone's 17 GPa. */
static const mu_json_bounds modulus = {1e6, 1e12, false, false};
/* Pa: 0.1 MPa (cancellous bone's weakest) to 10 GPa (fifty times cortical bone's). */
static const mu_json_bounds strength = {1e5, 1e10, false, false};
/* m: drawn size only, but a huge circle stalls the drawing. */
static const mu_json_bounds radius = {0.0, 100.0, true, false};
/* kg: 0 for no weight; a million kilograms tears the arm apart (which
 * mu_model_failure reports), but stays finite. */
static const mu_json_bounds weight_mass = {0.0, 1e6, false, false};
static const mu_json_bounds rest_length = {1e-3, 10.0, false, false};
static const mu_json_bounds rest_width = {1e-4, 1.0, false, false};
/* N/m²: physiological values are 2e5 to 1e6. */
static const mu_json_bounds specific_tension = {1e3, 1e7, false, false};
static const mu_json_bounds max_force = {1e-3, 1e6, false, false};
/* m/s, and rest lengths per second (physiology's about 10). */
static const mu_json_bounds max_velocity = {1e-3, 100.0, false, false};
static const mu_json_bounds max_velocity_rest_lengths = {0.1, 1e3, false, false};
static const mu_json_bounds tendon_length = {0.0, 100.0, false, false};
/* s: activation and deactivation time constants. */
static const mu_json_bounds time_constant = {1e-4, 10.0, false, false};
/* Tendon strain at Fmax: physiological values are 0.03 to 0.1. */
static const mu_json_bounds tendon_strain = {1e-3, 1.0, false, false};
static const mu_json_bounds fibre_damping = {1e-3, 10.0, false, false};
/* N·m: three times the strongest human joint torque (knee extension,
 * about 300 N·m); and a motor neuron's strength (any unit: only their
 * ratios count). */
static const mu_json_bounds peak_torque = {-1e3, 1e3, false, false};
static const mu_json_bounds neuron_strength = {1e-6, 1e6, false, false};
/* Hz, frame_rate × substeps: a substep of 1/60 s at most (every_field.json
 * at 30 Hz opens its hinges by 9 cm; the built-in models take 600 Hz), and
 * of 10 µs at least, which bounds the work a simulated second costs. */
#define MIN_SUBSTEP_RATE 60.0
/* m: a hinge pins its anchors together, so the solver snaps them together
 * at the first step; a gap wider than rounding is a mistake in the file
 * (every_field.json with one anchor 100 m off comes apart). */
#define MAX_HINGE_GAP 0.01
#define MAX_SUBSTEP_RATE 1e5

/* Fails unless `value`, derived from the member `key` at the current
 * path, lies within `bounds`, the range of the value it stands for. */
static rb_status check_derived(mu_json_reader *reader, const char *key, double value, mu_json_bounds bounds,
                               const char *what)
{
    bool above = bounds.lower_open ? value > bounds.lower : value >= bounds.lower;
    bool below = bounds.upper_open ? value < bounds.upper : value <= bounds.upper;
    if (above && below) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    return mu_json_fail(reader, MU_JSON_AT_VALUE, "%s is %g, expected a value in [%g, %g]", what, value, bounds.lower,
                        bounds.upper);
}

static const char *const kind_singular[] = {"nail",   "bone",   "hinge", "glue",
                                            "weight", "muscle", "group", "torque muscle"};
static const char *const kind_list[] = {"nails",  "bones",   "hinges", "glues",
                                        "weight", "muscles", "groups", "torque_muscles"};

static rb_status out_of_memory(void)
{
    return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_desc_load: out of memory");
}

static rb_status copy_string(const char *text, char **out)
{
    size_t size = strlen(text) + 1;
    *out = malloc(size);
    if (*out == NULL) {
        return out_of_memory();
    }
    memcpy(*out, text, size);
    return RB_OK;
}

/* Fails after a calloc of `count` items that returned NULL (0 items may
 * give NULL and are no failure). */
static rb_status check_allocation(const void *items, size_t count)
{
    return items == NULL && count > 0 ? out_of_memory() : RB_OK;
}

/* "where" names the object a name already belongs to: "bones[2]", "weight". */
static void format_ref(mu_model_ref ref, char *buffer, size_t size)
{
    if (ref.kind == MU_MODEL_WEIGHT) {
        snprintf(buffer, size, "weight");
    } else {
        snprintf(buffer, size, "%s[%d]", kind_list[ref.kind], ref.index);
    }
}

/* Reads the required string "name" of `object` (`what` in messages). A
 * name heads CSV columns and shows in the viewer and in messages, so a
 * control character (a line break, a tab, DEL) is refused: it would split
 * a CSV header that sinew could not read back. */
static rb_status read_name(mu_json_reader *reader, const json_t *object, const char *what, const char **out)
{
    MU_JSON_TRY(mu_json_read_string(reader, object, "name", MU_JSON_REQUIRED, what, out));
    for (const unsigned char *c = (const unsigned char *)*out; *c != '\0'; ++c) {
        if (*c < 0x20 || *c == 0x7f) {
            mu_json_push_key(reader, "name");
            return mu_json_fail(reader, MU_JSON_AT_VALUE,
                                "%s has the control character 0x%02x, expected printable text (no line break or tab)",
                                what, *c);
        }
    }
    return RB_OK;
}

/* Reads the required "name" of an object of the shared namespace and
 * copies it to *out, failing if another object has it already. */
static rb_status read_object_name(mu_json_reader *reader, const json_t *object, mu_model_desc *desc, mu_model_ref ref,
                                  char **out)
{
    const char *name;
    MU_JSON_TRY(read_name(reader, object, "the object's name", &name));
    mu_model_ref other;
    if (mu_model_desc_find(desc, name, &other)) {
        char where[32];
        format_ref(other, where, sizeof where);
        mu_json_push_key(reader, "name");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "\"%s\" is already the name of %s, expected a name that no other nail, bone, hinge, "
                            "glue, weight, muscle, group or torque muscle has",
                            name, where);
    }
    MU_JSON_TRY(copy_string(name, out));
    return mu_name_index_add(&desc->object_names, *out, (int)ref.kind, ref.index);
}

/* Reads the member `key`, the name of a nail or a bone. */
static rb_status read_body(mu_json_reader *reader, const json_t *object, const char *key, const mu_model_desc *desc,
                           mu_model_ref *out)
{
    const char *what = "the name of a nail or bone";
    const char *name;
    MU_JSON_TRY(mu_json_read_string(reader, object, key, MU_JSON_REQUIRED, what, &name));
    mu_json_push_key(reader, key);
    if (!mu_model_desc_find(desc, name, out)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "no nail or bone is named \"%s\", expected %s", name, what);
    }
    if (out->kind != MU_MODEL_NAIL && out->kind != MU_MODEL_BONE) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is a %s, expected %s", name, kind_singular[out->kind],
                            what);
    }
    mu_json_pop(reader);
    return RB_OK;
}

/* Reads body_a and body_b of a joint, which must differ. */
static rb_status read_body_pair(mu_json_reader *reader, const json_t *object, const mu_model_desc *desc,
                                mu_model_ref *body_a, mu_model_ref *body_b)
{
    MU_JSON_TRY(read_body(reader, object, "body_a", desc, body_a));
    MU_JSON_TRY(read_body(reader, object, "body_b", desc, body_b));
    if (body_a->kind == body_b->kind && body_a->index == body_b->index) {
        mu_json_push_key(reader, "body_b");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is body_a too, expected a different body",
                            mu_model_desc_name_of(desc, *body_b));
    }
    return RB_OK;
}

/* Reads the element at the current path, the name of an object of `kind`,
 * and fails if `seen` (one flag per object of the kind) marks it already
 * listed; marks it. */
static rb_status read_member_ref(mu_json_reader *reader, const json_t *value, const mu_model_desc *desc,
                                 mu_model_kind kind, bool *seen, int *out)
{
    char what[32];
    snprintf(what, sizeof what, "the name of a %s", kind_singular[kind]);
    const char *name;
    MU_JSON_TRY(mu_json_expect_string(reader, value, what, &name));
    mu_model_ref ref;
    if (!mu_model_desc_find(desc, name, &ref) || ref.kind != kind) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "no %s is named \"%s\", expected %s", kind_singular[kind], name,
                            what);
    }
    if (seen[ref.index]) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is listed twice, expected each %s once", name,
                            kind_singular[kind]);
    }
    seen[ref.index] = true;
    *out = ref.index;
    return RB_OK;
}

/* Reads the list `key` of min_count or more names of muscles or bones
 * (`kind`) into *indices, *count of them, each once. */
static rb_status read_name_list(mu_json_reader *reader, const json_t *object, const char *key, mu_model_kind kind,
                                const mu_model_desc *desc, size_t min_count, int **indices, int *count)
{
    char what[32];
    snprintf(what, sizeof what, "%s names", kind_singular[kind]);
    const json_t *names;
    MU_JSON_TRY(
        mu_json_read_array(reader, object, key, MU_JSON_REQUIRED, min_count, MU_MODEL_MAX_OBJECTS, what, &names));
    *indices = calloc(json_array_size(names), sizeof **indices);
    MU_JSON_TRY(check_allocation(*indices, json_array_size(names)));
    /* Flags, not a scan of the names before: a list of 65,535 names stays linear. */
    const int objects = kind == MU_MODEL_MUSCLE ? desc->muscle_count : desc->bone_count;
    bool *seen = calloc((size_t)objects + 1, sizeof *seen);
    MU_JSON_TRY(check_allocation(seen, 1));
    mu_json_push_key(reader, key);
    rb_status status = RB_OK;
    for (size_t i = 0; i < json_array_size(names) && status == RB_OK; ++i) {
        mu_json_push_index(reader, i);
        status = read_member_ref(reader, json_array_get(names, i), desc, kind, seen, &(*indices)[i]);
        if (status == RB_OK) {
            ++*count;
            mu_json_pop(reader);
        }
    }
    free(seen);
    if (status == RB_OK) {
        mu_json_pop(reader);
    }
    return status;
}

/* ---- one object of each kind ------------------------------------------ */

static rb_status parse_nail(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name", "position", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_nail *nail = &desc->nails[desc->nail_count++];
    MU_JSON_TRY(
        read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_NAIL, desc->nail_count - 1}, &nail->name));
    return mu_json_read_vec2(reader, object, "position", MU_JSON_REQUIRED, coordinate, "the nail's position in m",
                             &nail->position);
}

/* Cortical bone (docs/loads.md, "Bone stress"): Reilly and Burstein, "The
 * elastic and ultimate properties of compact bone tissue", 1975,
 * longitudinal specimens of human femur, as quoted in the literature. */
#define DEFAULT_CORTICAL_MODULUS 17e9               /* Pa */
#define DEFAULT_CORTICAL_TENSILE_STRENGTH 133e6     /* Pa */
#define DEFAULT_CORTICAL_COMPRESSIVE_STRENGTH 193e6 /* Pa */
/* The wall: a quarter of the outer diameter (canal half of it). */
#define DEFAULT_WALL_FRACTION 0.25

/* The bone as a beam (bone_stress.h): the cortical tube's wall, at most
 * the radius of the smaller extent, and the material's constants. */
static rb_status parse_beam(mu_json_reader *reader, const json_t *object, mu_model_bone *bone)
{
    const double diameter = bone->size.x < bone->size.y ? bone->size.x : bone->size.y;
    const mu_json_bounds wall = {1e-5, 0.5 * diameter, false, false};
    bone->wall_thickness = DEFAULT_WALL_FRACTION * diameter;
    MU_JSON_TRY(mu_json_read_number(reader, object, "wall_thickness", MU_JSON_OPTIONAL, wall,
                                    "the cortical wall's thickness in m (at most half the bone's smaller extent)",
                                    &bone->wall_thickness));
    bone->youngs_modulus = DEFAULT_CORTICAL_MODULUS;
    MU_JSON_TRY(mu_json_read_number(reader, object, "youngs_modulus", MU_JSON_OPTIONAL, modulus,
                                    "the bone's Young's modulus in Pa", &bone->youngs_modulus));
    bone->tensile_strength = DEFAULT_CORTICAL_TENSILE_STRENGTH;
    MU_JSON_TRY(mu_json_read_number(reader, object, "tensile_strength", MU_JSON_OPTIONAL, strength,
                                    "the bone's ultimate tensile strength in Pa", &bone->tensile_strength));
    bone->compressive_strength = DEFAULT_CORTICAL_COMPRESSIVE_STRENGTH;
    return mu_json_read_number(reader, object, "compressive_strength", MU_JSON_OPTIONAL, strength,
                               "the bone's ultimate compressive strength in Pa", &bone->compressive_strength);
}

static rb_status parse_bone(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name",
                                       "centre",
                                       "size",
                                       "angle",
                                       "depth",
                                       "static",
                                       "density",
                                       "damping",
                                       "wall_thickness",
                                       "youngs_modulus",
                                       "tensile_strength",
                                       "compressive_strength",
                                       NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_bone *bone = &desc->bones[desc->bone_count++];
    MU_JSON_TRY(
        read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_BONE, desc->bone_count - 1}, &bone->name));
    MU_JSON_TRY(mu_json_read_vec2(reader, object, "centre", MU_JSON_REQUIRED, coordinate, "the bone's centre in m",
                                  &bone->centre));
    MU_JSON_TRY(mu_json_read_vec2(reader, object, "size", MU_JSON_REQUIRED, extent, "the bone's x and y extents in m",
                                  &bone->size));
    MU_JSON_TRY(mu_json_read_number(reader, object, "angle", MU_JSON_OPTIONAL, angle_degrees,
                                    "the bone's angle in degrees", &bone->angle));
    bone->depth = bone->size.x < bone->size.y ? bone->size.x : bone->size.y;
    MU_JSON_TRY(
        mu_json_read_number(reader, object, "depth", MU_JSON_OPTIONAL, extent, "the bone's depth in m", &bone->depth));
    MU_JSON_TRY(
        mu_json_read_bool(reader, object, "static", MU_JSON_OPTIONAL, "whether the bone is static", &bone->is_static));
    bone->density = DEFAULT_BONE_DENSITY;
    MU_JSON_TRY(mu_json_read_number(reader, object, "density", MU_JSON_OPTIONAL, density, "the bone's density in kg/m³",
                                    &bone->density));
    bone->damping = desc->damping;
    MU_JSON_TRY(mu_json_read_number(reader, object, "damping", MU_JSON_OPTIONAL, damping, "the bone's damping in 1/s",
                                    &bone->damping));
    return parse_beam(reader, object, bone);
}

/* Where `point`, in the frame of the nail or bone `body`, is at the model's
 * start pose (before placement, which moves every point alike). */
static rb_vec2 start_point(const mu_model_desc *desc, mu_model_ref body, rb_vec2 point)
{
    if (body.kind == MU_MODEL_NAIL) {
        return rb_add(desc->nails[body.index].position, point);
    }
    const mu_model_bone *bone = &desc->bones[body.index];
    return rb_add(bone->centre, rb_rotate(rb_rot_from_angle(bone->angle / DEGREES), point));
}

static rb_status parse_hinge(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name",   "body_a", "anchor_a", "body_b", "anchor_b",
                                       "radius", "lower",  "upper",    NULL};
    const mu_json_bounds limit = {-MAX_LIMIT_DEGREES, MAX_LIMIT_DEGREES, false, false};
    const char *limit_what = "a joint angle limit in degrees, left out for no limit";
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_hinge *hinge = &desc->hinges[desc->hinge_count++];
    MU_JSON_TRY(
        read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_HINGE, desc->hinge_count - 1}, &hinge->name));
    MU_JSON_TRY(read_body_pair(reader, object, desc, &hinge->body_a, &hinge->body_b));
    MU_JSON_TRY(mu_json_read_vec2(reader, object, "anchor_a", MU_JSON_REQUIRED, coordinate,
                                  "the pin in body A's frame, in m", &hinge->anchor_a));
    MU_JSON_TRY(mu_json_read_vec2(reader, object, "anchor_b", MU_JSON_REQUIRED, coordinate,
                                  "the pin in body B's frame, in m", &hinge->anchor_b));
    const double gap = rb_distance(start_point(desc, hinge->body_a, hinge->anchor_a),
                                   start_point(desc, hinge->body_b, hinge->anchor_b));
    if (gap > MAX_HINGE_GAP) {
        mu_json_push_key(reader, "anchor_b");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "the anchors are %g m apart at the start pose, expected them to meet (within %g m)", gap,
                            MAX_HINGE_GAP);
    }
    MU_JSON_TRY(mu_json_read_number(reader, object, "radius", MU_JSON_REQUIRED, radius, "the hinge's drawn radius in m",
                                    &hinge->radius));
    hinge->has_lower = json_object_get(object, "lower") != NULL;
    hinge->has_upper = json_object_get(object, "upper") != NULL;
    MU_JSON_TRY(mu_json_read_number(reader, object, "lower", MU_JSON_OPTIONAL, limit, limit_what, &hinge->lower));
    MU_JSON_TRY(mu_json_read_number(reader, object, "upper", MU_JSON_OPTIONAL, limit, limit_what, &hinge->upper));
    if (hinge->has_lower && hinge->has_upper && hinge->lower > hinge->upper) {
        mu_json_push_key(reader, "lower");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "%g is above upper (%g), expected lower <= upper", hinge->lower,
                            hinge->upper);
    }
    return RB_OK;
}

static rb_status parse_glue(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name", "body_a", "body_b", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_glue *glue = &desc->glues[desc->glue_count++];
    MU_JSON_TRY(
        read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_GLUE, desc->glue_count - 1}, &glue->name));
    return read_body_pair(reader, object, desc, &glue->body_a, &glue->body_b);
}

static rb_status parse_path_point(mu_json_reader *reader, const json_t *object, const mu_model_desc *desc,
                                  mu_model_path_point *point)
{
    static const char *const keys[] = {"body", "point", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    MU_JSON_TRY(read_body(reader, object, "body", desc, &point->body));
    return mu_json_read_vec2(reader, object, "point", MU_JSON_REQUIRED, coordinate,
                             "the point in the body's frame, in m", &point->point);
}

/* ---- a muscle's force from its architecture (Castanyer's report §2.2) ---- */

/* m³: a muscle of a cubic millimetre to 100 litres (the largest human
 * muscles hold under a litre), and m²: 0.01 mm² to 1000 cm². */
static const mu_json_bounds muscle_volume = {1e-9, 0.1, false, false};
static const mu_json_bounds cross_section = {1e-8, 0.1, false, false};
/* Sarcomeres in series: 500 to 5 million are fibres of 1 mm to 10 m at
 * the optimal 2 µm, the rest length's range. A measured sarcomere length
 * of 1 to 5 µm: wide of the lengths at which the filaments still overlap
 * and pull (about 1.3 to 4 µm). */
static const mu_json_bounds sarcomere_count = {500.0, 5e6, false, false};
static const mu_json_bounds sarcomere_length = {1e-6, 5e-6, false, false};

/* max_force, rest_width and architecture: each alone gives the force. */
static rb_status check_one_force(mu_json_reader *reader, const json_t *object, bool has_max_force,
                                 bool has_architecture)
{
    const char *other = has_max_force                                   ? "max_force"
                        : json_object_get(object, "rest_width") != NULL ? "rest_width"
                                                                        : NULL;
    if (has_architecture && other != NULL) {
        mu_json_push_key(reader, "architecture");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given with %s, expected one of max_force, rest_width or architecture to give the "
                            "maximal force",
                            other);
    }
    return RB_OK;
}

/* Fails at `key` of the current object, given where it does not belong. */
static rb_status refuse_key(mu_json_reader *reader, const json_t *object, const char *key, const char *expected)
{
    if (json_object_get(object, key) == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    return mu_json_fail(reader, MU_JSON_AT_VALUE, "%s", expected);
}

/* The architecture's inputs: volume with a fibre length (given, as
 * sarcomeres, measured with its sarcomere length, or else the rest
 * length), or the anatomical cross-section with the muscle's pennation
 * angle. derive_muscle_force turns them into the force. */
static rb_status parse_muscle_architecture(mu_json_reader *reader, const json_t *object,
                                           mu_model_architecture *architecture)
{
    static const char *const keys[] = {"volume",     "anatomical_cross_section", "fibre_length",
                                       "sarcomeres", "sarcomere_length",         NULL};
    mu_json_push_key(reader, "architecture");
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    architecture->given = true;
    MU_JSON_TRY(mu_json_read_number(reader, object, "volume", MU_JSON_OPTIONAL, muscle_volume,
                                    "the muscle's volume in m³", &architecture->volume));
    MU_JSON_TRY(mu_json_read_number(reader, object, "anatomical_cross_section", MU_JSON_OPTIONAL, cross_section,
                                    "the muscle's anatomical cross-section in m²",
                                    &architecture->anatomical_cross_section));
    if (architecture->volume == 0.0 && architecture->anatomical_cross_section == 0.0) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "missing key \"volume\", expected the muscle's volume in m³ (PCSA = volume / fibre "
                            "length) or its anatomical_cross_section in m² (PCSA = it / cos(pennation_angle))");
    }
    if (architecture->volume > 0.0) {
        MU_JSON_TRY(refuse_key(reader, object, "anatomical_cross_section",
                               "given with volume, expected one of volume (with a fibre length) or "
                               "anatomical_cross_section (with the pennation angle)"));
    } else {
        const char *expected = "given with anatomical_cross_section, expected a fibre length only with volume";
        MU_JSON_TRY(refuse_key(reader, object, "fibre_length", expected));
        MU_JSON_TRY(refuse_key(reader, object, "sarcomeres", expected));
        MU_JSON_TRY(refuse_key(reader, object, "sarcomere_length", expected));
    }
    MU_JSON_TRY(mu_json_read_number(reader, object, "fibre_length", MU_JSON_OPTIONAL, rest_length,
                                    "the fibres' length in m", &architecture->measured_fibre_length));
    MU_JSON_TRY(mu_json_read_number(reader, object, "sarcomeres", MU_JSON_OPTIONAL, sarcomere_count,
                                    "the number of sarcomeres in series in a fibre", &architecture->sarcomeres));
    MU_JSON_TRY(mu_json_read_number(reader, object, "sarcomere_length", MU_JSON_OPTIONAL, sarcomere_length,
                                    "the sarcomere length measured with fibre_length, in m",
                                    &architecture->sarcomere_length));
    if (architecture->sarcomeres > 0.0) {
        MU_JSON_TRY(refuse_key(reader, object, "fibre_length",
                               "given with sarcomeres, expected one of fibre_length or sarcomeres"));
    }
    if (architecture->sarcomere_length > 0.0 && architecture->measured_fibre_length == 0.0) {
        mu_json_push_key(reader, "sarcomere_length");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given without fibre_length, expected it with the fibre length it was measured in");
    }
    mu_json_pop(reader);
    return RB_OK;
}

/* The force the architecture gives, Fmax = specific_tension · PCSA
 * (muscle_statics.h), into max_force; after derive_muscle_lengths, since
 * the fibre length may be the rest length, which tendon_fraction derives. */
static rb_status derive_muscle_force(mu_json_reader *reader, mu_model_muscle *muscle)
{
    mu_model_architecture *architecture = &muscle->architecture;
    if (!architecture->given) {
        return RB_OK;
    }
    if (architecture->volume > 0.0) {
        double fibre = muscle->rest_length;
        if (architecture->sarcomeres > 0.0) {
            fibre = mu_fibre_length_from_sarcomeres(architecture->sarcomeres);
        } else if (architecture->sarcomere_length > 0.0) {
            fibre = mu_fibre_length_normalized(architecture->measured_fibre_length, architecture->sarcomere_length);
        } else if (architecture->measured_fibre_length > 0.0) {
            fibre = architecture->measured_fibre_length;
        }
        architecture->fibre_length = fibre;
        MU_JSON_TRY(check_derived(reader, "architecture", fibre, rest_length,
                                  "the optimal fibre length PCSA divides the volume by, in m,"));
        architecture->pcsa = mu_pcsa_from_volume(architecture->volume, fibre);
    } else {
        architecture->pcsa =
            mu_pcsa_from_anatomical(architecture->anatomical_cross_section, muscle->pennation_angle / DEGREES);
    }
    muscle->max_force = mu_max_force_from_pcsa(architecture->pcsa, muscle->specific_tension);
    return check_derived(reader, "architecture", muscle->max_force, max_force,
                         "the maximal force specific_tension·PCSA in N");
}

/* The muscle's force: max_force, rest_width with specific_tension, or
 * architecture with specific_tension (parse_muscle_architecture). */
static rb_status parse_muscle_force(mu_json_reader *reader, const json_t *object, mu_model_muscle *muscle)
{
    MU_JSON_TRY(mu_json_read_number(reader, object, "max_force", MU_JSON_OPTIONAL, max_force,
                                    "the maximal isometric force in N", &muscle->max_force));
    bool has_max_force = muscle->max_force > 0.0;
    const json_t *architecture = json_object_get(object, "architecture");
    MU_JSON_TRY(check_one_force(reader, object, has_max_force, architecture != NULL));
    MU_JSON_TRY(mu_json_read_number(reader, object, "rest_width", MU_JSON_OPTIONAL, rest_width,
                                    "the belly's width at rest in m", &muscle->rest_width));
    if (!has_max_force && architecture == NULL && muscle->rest_width == 0.0) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "missing key \"rest_width\", expected the belly's width at rest in m, max_force or "
                            "architecture");
    }
    muscle->specific_tension = DEFAULT_SPECIFIC_TENSION;
    MU_JSON_TRY(mu_json_read_number(reader, object, "specific_tension", MU_JSON_OPTIONAL, specific_tension,
                                    "the specific tension in N/m²", &muscle->specific_tension));
    if (has_max_force && json_object_get(object, "specific_tension") != NULL) {
        mu_json_push_key(reader, "specific_tension");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given with max_force, expected either max_force or rest_width with specific_tension");
    }
    if (has_max_force) {
        return RB_OK;
    }
    if (architecture != NULL) {
        return parse_muscle_architecture(reader, architecture, &muscle->architecture);
    }
    /* The force mu_muscle_def derives: the circular cross-section times the tension. */
    const double force = RB_PI * muscle->rest_width * muscle->rest_width / 4.0 * muscle->specific_tension;
    return check_derived(reader, "rest_width", force, max_force,
                         "the maximal force π·rest_width²/4·specific_tension in N");
}

/* Vmax: max_velocity in m/s (the original's), or max_velocity_rest_lengths in
 * rest lengths per second (as physiology states it, e.g. 10 /s), stored
 * in m/s by parse_muscle once the rest length is known (it may be derived
 * from the path). */
static rb_status parse_muscle_velocity(mu_json_reader *reader, const json_t *object, mu_model_muscle *muscle,
                                       double *rest_lengths_per_second)
{
    muscle->max_velocity = DEFAULT_MAX_VELOCITY;
    MU_JSON_TRY(mu_json_read_number(reader, object, "max_velocity", MU_JSON_OPTIONAL, max_velocity,
                                    "the maximal shortening speed in m/s", &muscle->max_velocity));
    *rest_lengths_per_second = 0.0;
    MU_JSON_TRY(
        mu_json_read_number(reader, object, "max_velocity_rest_lengths", MU_JSON_OPTIONAL, max_velocity_rest_lengths,
                            "the maximal shortening speed in rest lengths per second", rest_lengths_per_second));
    if (*rest_lengths_per_second > 0.0 && json_object_get(object, "max_velocity") != NULL) {
        mu_json_push_key(reader, "max_velocity_rest_lengths");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given with max_velocity, expected either max_velocity (m/s) or "
                            "max_velocity_rest_lengths (rest lengths per second)");
    }
    return RB_OK;
}

/* Where the belly starts: start_normalized_length or tendon_length. */
static rb_status parse_muscle_start(mu_json_reader *reader, const json_t *object, mu_model_muscle *muscle)
{
    const mu_json_bounds normalized = {MIN_START_NORMALIZED_LENGTH, MAX_START_NORMALIZED_LENGTH, false, false};
    muscle->start_normalized_length = DEFAULT_START_NORMALIZED_LENGTH;
    MU_JSON_TRY(mu_json_read_number(reader, object, "start_normalized_length", MU_JSON_OPTIONAL, normalized,
                                    "the belly's length at creation over its rest length",
                                    &muscle->start_normalized_length));
    muscle->tendon_length = -1.0;
    MU_JSON_TRY(mu_json_read_number(reader, object, "tendon_length", MU_JSON_OPTIONAL, tendon_length,
                                    "the tendon's length in m", &muscle->tendon_length));
    if (muscle->tendon_length >= 0.0 && json_object_get(object, "start_normalized_length") != NULL) {
        mu_json_push_key(reader, "tendon_length");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given with start_normalized_length, expected one of the two (the tendon's length, or "
                            "the belly's start length that derives it)");
    }
    if (muscle->tendon_length >= 0.0 && muscle->tendon_fraction >= 0.0) {
        mu_json_push_key(reader, "tendon_length");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given with tendon_fraction, expected one of the two (the tendon's length, or its "
                            "share of the path that derives it)");
    }
    return RB_OK;
}

/* The rest length, or the tendon fraction that derives it from the path
 * (after parse_muscle_path). */
static rb_status parse_muscle_size(mu_json_reader *reader, const json_t *object, mu_model_muscle *muscle)
{
    const mu_json_bounds fraction = {0.0, 1.0, false, true};
    muscle->tendon_fraction = -1.0;
    MU_JSON_TRY(mu_json_read_number(reader, object, "tendon_fraction", MU_JSON_OPTIONAL, fraction,
                                    "the tendon's share of the path's length at the start", &muscle->tendon_fraction));
    const bool derived = muscle->tendon_fraction >= 0.0;
    if (derived && json_object_get(object, "rest_length") != NULL) {
        mu_json_push_key(reader, "tendon_fraction");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "given with rest_length, expected one of the two (the rest length, or the tendon's "
                            "share of the path that derives it)");
    }
    return mu_json_read_number(reader, object, "rest_length", derived ? MU_JSON_OPTIONAL : MU_JSON_REQUIRED,
                               rest_length, "the fibres' rest (optimal) length in m", &muscle->rest_length);
}

/* activation_dynamics: {"model": "first_order", "activation_time": ...,
 * "deactivation_time": ...} (the default model), or {"model":
 * "calcium_force", "fibre_type": "fast" or "slow", and any of the four
 * times to override the set's} (mu/calcium_force.h). A time of the other
 * model is refused rather than ignored. */
static const char *const first_order_keys[] = {"activation_time", "deactivation_time", NULL};
static const char *const calcium_force_keys[] = {"fibre_type",      "calcium_rise_time", "calcium_decay_time",
                                                 "force_rise_time", "force_decay_time",  NULL};

/* Fails at the first key of `keys` the object has: it belongs to `other`. */
static rb_status refuse_keys_of(mu_json_reader *reader, const json_t *dynamics, const char *const *keys,
                                const char *model, const char *other)
{
    for (int k = 0; keys[k] != NULL; ++k) {
        if (json_object_get(dynamics, keys[k]) != NULL) {
            mu_json_push_key(reader, keys[k]);
            return mu_json_fail(reader, MU_JSON_AT_KEY,
                                "belongs to the %s dynamics, expected \"model\": \"%s\" or "
                                "the keys of the %s dynamics",
                                other, other, model);
        }
    }
    return RB_OK;
}

static rb_status parse_calcium_force(mu_json_reader *reader, const json_t *dynamics, mu_model_muscle *muscle)
{
    const char *type = "fast";
    const char *type_what = "the fibre type, \"fast\" or \"slow\"";
    MU_JSON_TRY(mu_json_read_string(reader, dynamics, "fibre_type", MU_JSON_OPTIONAL, type_what, &type));
    if (strcmp(type, "fast") != 0 && strcmp(type, "slow") != 0) {
        mu_json_push_key(reader, "fibre_type");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is no fibre type, expected %s", type, type_what);
    }
    mu_calcium_force_times *t = &muscle->calcium_force;
    *t = mu_calcium_force_times_of(strcmp(type, "slow") == 0 ? MU_FIBRE_SLOW : MU_FIBRE_FAST);
    double *const times[] = {&t->calcium_rise_time, &t->calcium_decay_time, &t->force_rise_time, &t->force_decay_time};
    static const char *const whats[] = {"the calcium stage's rise time constant in s",
                                        "the calcium stage's decay time constant in s",
                                        "the force-generating stage's rise time constant in s",
                                        "the force-generating stage's decay time constant in s"};
    for (int k = 0; k < 4; ++k) {
        MU_JSON_TRY(mu_json_read_number(reader, dynamics, calcium_force_keys[k + 1], MU_JSON_OPTIONAL, time_constant,
                                        whats[k], times[k]));
    }
    return refuse_keys_of(reader, dynamics, first_order_keys, "calcium_force", "first_order");
}

static rb_status parse_activation_dynamics(mu_json_reader *reader, const json_t *object, mu_model_muscle *muscle)
{
    const mu_muscle_def defaults = mu_default_muscle_def();
    muscle->activation_time = defaults.activation_time;
    muscle->deactivation_time = defaults.deactivation_time;
    muscle->activation_model = MU_ACTIVATION_FIRST_ORDER;
    muscle->calcium_force = defaults.calcium_force;
    const json_t *dynamics = json_object_get(object, "activation_dynamics");
    if (dynamics == NULL) {
        return RB_OK;
    }
    static const char *const keys[] = {"model",           "activation_time",   "deactivation_time",
                                       "fibre_type",      "calcium_rise_time", "calcium_decay_time",
                                       "force_rise_time", "force_decay_time",  NULL};
    mu_json_push_key(reader, "activation_dynamics");
    MU_JSON_TRY(mu_json_check_object(reader, dynamics, keys));
    const char *model = "first_order";
    const char *model_what = "the dynamics, \"first_order\" or \"calcium_force\"";
    MU_JSON_TRY(mu_json_read_string(reader, dynamics, "model", MU_JSON_OPTIONAL, model_what, &model));
    if (strcmp(model, "calcium_force") == 0) {
        muscle->activation_model = MU_ACTIVATION_CALCIUM_FORCE;
        MU_JSON_TRY(parse_calcium_force(reader, dynamics, muscle));
    } else if (strcmp(model, "first_order") == 0) {
        MU_JSON_TRY(mu_json_read_number(reader, dynamics, "activation_time", MU_JSON_OPTIONAL, time_constant,
                                        "the activation time constant in s", &muscle->activation_time));
        MU_JSON_TRY(mu_json_read_number(reader, dynamics, "deactivation_time", MU_JSON_OPTIONAL, time_constant,
                                        "the deactivation time constant in s", &muscle->deactivation_time));
        MU_JSON_TRY(refuse_keys_of(reader, dynamics, calcium_force_keys, "first_order", "calcium_force"));
    } else {
        mu_json_push_key(reader, "model");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is no activation dynamics, expected %s", model,
                            model_what);
    }
    mu_json_pop(reader);
    muscle->activation_dynamics = true;
    return RB_OK;
}

/* The options beyond the original muscle: pennation, activation dynamics
 * and a compliant tendon, each an object of its parameters. */
static rb_status parse_muscle_physiology(mu_json_reader *reader, const json_t *object, mu_model_muscle *muscle)
{
    const mu_json_bounds angle = {0.0, MAX_PENNATION_DEGREES, false, false};
    MU_JSON_TRY(mu_json_read_number(reader, object, "pennation_angle", MU_JSON_OPTIONAL, angle,
                                    "the pennation angle at the optimal fibre length in degrees",
                                    &muscle->pennation_angle));
    MU_JSON_TRY(parse_activation_dynamics(reader, object, muscle));
    const mu_muscle_def defaults = mu_default_muscle_def();
    muscle->tendon_strain_at_max_force = defaults.tendon_strain_at_max_force;
    muscle->fibre_damping = defaults.fibre_damping;
    const json_t *tendon = json_object_get(object, "compliant_tendon");
    if (tendon != NULL) {
        static const char *const keys[] = {"strain_at_max_force", "fibre_damping", NULL};
        mu_json_push_key(reader, "compliant_tendon");
        MU_JSON_TRY(mu_json_check_object(reader, tendon, keys));
        MU_JSON_TRY(mu_json_read_number(reader, tendon, "strain_at_max_force", MU_JSON_OPTIONAL, tendon_strain,
                                        "the tendon's strain at the maximal isometric force",
                                        &muscle->tendon_strain_at_max_force));
        MU_JSON_TRY(mu_json_read_number(reader, tendon, "fibre_damping", MU_JSON_OPTIONAL, fibre_damping,
                                        "the fibre's damping per unit normalized velocity over Fmax",
                                        &muscle->fibre_damping));
        mu_json_pop(reader);
        muscle->compliant_tendon = true;
    }
    return RB_OK;
}

static double start_path_length(const mu_model_desc *desc, const mu_model_muscle *muscle)
{
    double length = 0.0;
    for (int i = 0; i + 1 < muscle->point_count; ++i) {
        length += rb_distance(start_point(desc, muscle->path[i].body, muscle->path[i].point),
                              start_point(desc, muscle->path[i + 1].body, muscle->path[i + 1].point));
    }
    return length;
}

/* With tendon_fraction, the lengths it derives from the path; with a
 * compliant tendon, a check that its slack length will be > 0. */
static rb_status derive_muscle_lengths(mu_json_reader *reader, const mu_model_desc *desc, mu_model_muscle *muscle)
{
    const double path = start_path_length(desc, muscle);
    const double angle = muscle->pennation_angle / DEGREES;
    if (muscle->tendon_fraction >= 0.0) {
        mu_derived_lengths lengths;
        if (mu_lengths_from_geometry(path, muscle->tendon_fraction, muscle->start_normalized_length, angle, &lengths) !=
            RB_OK) {
            mu_json_push_key(reader, "tendon_fraction");
            return mu_json_fail(reader, MU_JSON_AT_VALUE,
                                "cannot derive the lengths from the path of %g m at the start pose, expected a path "
                                "longer than 0 and a start fibre longer than the pennation allows",
                                path);
        }
        muscle->rest_length = lengths.rest_length;
        muscle->tendon_length = lengths.tendon_length;
        MU_JSON_TRY(check_derived(reader, "tendon_fraction", muscle->rest_length, rest_length,
                                  "the rest length it derives from the path at the start pose, in m,"));
        MU_JSON_TRY(check_derived(reader, "tendon_fraction", muscle->tendon_length, tendon_length,
                                  "the tendon length it derives from the path at the start pose, in m,"));
    }
    if (muscle->compliant_tendon) {
        double slack = muscle->tendon_length;
        if (slack < 0.0) {
            /* As the muscle derives it (mu_muscle_def): path minus the
             * belly's extent √(l² - w²) of the start fibre l. */
            const double fibre = muscle->rest_length * muscle->start_normalized_length;
            const double width = muscle->rest_length * sin(angle);
            slack = path - sqrt(fmax(fibre * fibre - width * width, 0.0));
        }
        if (!(slack > 0.0)) {
            mu_json_push_key(reader, "compliant_tendon");
            return mu_json_fail(reader, MU_JSON_AT_VALUE,
                                "the tendon's slack length would be %g m (path %g m at the start pose), expected a "
                                "compliant tendon longer than 0: give tendon_length or tendon_fraction",
                                slack, path);
        }
    }
    return RB_OK;
}

static rb_status parse_muscle_path(mu_json_reader *reader, const json_t *object, const mu_model_desc *desc,
                                   mu_model_muscle *muscle)
{
    const json_t *path;
    MU_JSON_TRY(mu_json_read_array(reader, object, "path", MU_JSON_REQUIRED, 2, RB_MAX_CABLE_POINTS,
                                   "path points {body, point}: origin, via points, insertion", &path));
    mu_json_push_key(reader, "path");
    for (size_t i = 0; i < json_array_size(path); ++i) {
        mu_json_push_index(reader, i);
        MU_JSON_TRY(parse_path_point(reader, json_array_get(path, i), desc, &muscle->path[i]));
        muscle->point_count = (int)i + 1;
        if (i > 0) {
            /* A segment of no length has no direction to pull along: the
             * engine refuses such a cable (rb_cable_create). */
            const mu_model_path_point *a = &muscle->path[i - 1], *b = &muscle->path[i];
            const double gap = rb_distance(start_point(desc, a->body, a->point), start_point(desc, b->body, b->point));
            if (gap < RB_POLYGON_WELD_DISTANCE) {
                return mu_json_fail(reader, MU_JSON_AT_VALUE,
                                    "is %g m from path[%zu] at the start pose, expected consecutive path points at "
                                    "least %g m apart",
                                    gap, i - 1, RB_POLYGON_WELD_DISTANCE);
            }
        }
        mu_json_pop(reader);
    }
    mu_json_pop(reader);
    return RB_OK;
}

static rb_status parse_muscle(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name",
                                       "rest_length",
                                       "tendon_fraction",
                                       "rest_width",
                                       "specific_tension",
                                       "max_force",
                                       "architecture",
                                       "max_velocity",
                                       "max_velocity_rest_lengths",
                                       "start_normalized_length",
                                       "tendon_length",
                                       "pennation_angle",
                                       "activation_dynamics",
                                       "compliant_tendon",
                                       "symmetry",
                                       "curves",
                                       "path",
                                       NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_muscle *muscle = &desc->muscles[desc->muscle_count++];
    MU_JSON_TRY(
        read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_MUSCLE, desc->muscle_count - 1}, &muscle->name));
    MU_JSON_TRY(parse_muscle_size(reader, object, muscle));
    MU_JSON_TRY(parse_muscle_force(reader, object, muscle));
    double rest_lengths_per_second = 0.0;
    MU_JSON_TRY(parse_muscle_velocity(reader, object, muscle, &rest_lengths_per_second));
    MU_JSON_TRY(parse_muscle_start(reader, object, muscle));
    MU_JSON_TRY(parse_muscle_physiology(reader, object, muscle));
    const mu_json_bounds unit = {0.0, 1.0, false, false};
    muscle->symmetry = DEFAULT_SYMMETRY;
    MU_JSON_TRY(mu_json_read_number(reader, object, "symmetry", MU_JSON_OPTIONAL, unit,
                                    "where the belly sits between the path's ends", &muscle->symmetry));
    const char *curves = "tabulated";
    const char *curves_what = "the curve set, \"tabulated\" or \"analytic\"";
    MU_JSON_TRY(mu_json_read_string(reader, object, "curves", MU_JSON_OPTIONAL, curves_what, &curves));
    if (strcmp(curves, "analytic") == 0) {
        muscle->curves = MU_MODEL_CURVES_ANALYTIC;
    } else if (strcmp(curves, "tabulated") == 0) {
        muscle->curves = MU_MODEL_CURVES_TABULATED;
    } else {
        mu_json_push_key(reader, "curves");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is no curve set, expected %s", curves, curves_what);
    }
    MU_JSON_TRY(parse_muscle_path(reader, object, desc, muscle));
    MU_JSON_TRY(derive_muscle_lengths(reader, desc, muscle));
    MU_JSON_TRY(derive_muscle_force(reader, muscle));
    if (rest_lengths_per_second > 0.0) {
        muscle->max_velocity = rest_lengths_per_second * muscle->rest_length;
        return check_derived(reader, "max_velocity_rest_lengths", muscle->max_velocity, max_velocity,
                             "the maximal shortening speed it gives with the rest length, in m/s,");
    }
    return RB_OK;
}

/* What a model file's "motor_pool" may be, for messages. */
#define POOL_FORMS "{\"image\": PNG}, {\"csv\": CSV} or {neurons, weakest, strongest}"

/* Opens the file `name` that the member `key` (at the current path) names:
 * relative to the model file's folder, or, beside a model built into
 * libmu, the file built in with it. *label names what was opened. */
static rb_status open_pool_file(mu_json_reader *reader, const char *key, const char *name, const char *what, FILE **out,
                                char *label, size_t label_size)
{
    mu_json_push_key(reader, key);
    if (reader->folder == NULL) {
        snprintf(label, label_size, "%s (built into libmu)", name);
        const mu_embedded_file *file = mu_embedded_file_find(name);
        if (file == NULL) {
            return mu_json_fail(reader, MU_JSON_AT_VALUE, "no file named \"%s\" is built into libmu, expected %s", name,
                                what);
        }
        /* fmemopen takes a non-const buffer; in mode "r" it never writes it. */
        *out = fmemopen((void *)file->data, file->size, "r");
        if (*out == NULL) {
            return mu_json_fail(reader, MU_JSON_AT_VALUE, "%s: cannot open: %s, expected %s", label, strerror(errno),
                                what);
        }
    } else {
        const bool absolute = name[0] == '/';
        const int written =
            snprintf(label, label_size, "%s%s%s", absolute ? "" : reader->folder, absolute ? "" : "/", name);
        if (written < 0 || (size_t)written >= label_size) {
            return mu_json_fail(reader, MU_JSON_AT_VALUE, "the path of \"%s\" is too long, expected under %zu bytes",
                                name, label_size);
        }
        char problem[MU_POOL_PROBLEM_SIZE];
        *out = mu_pool_profile_open(label, problem, sizeof problem);
        if (*out == NULL) {
            return mu_json_fail(reader, MU_JSON_AT_VALUE, "%s: %s, expected %s", label, problem, what);
        }
    }
    return RB_OK;
}

/* The motor pool's strengths from the profile image or CSV that `key`
 * ("image" or "csv") names, read now, so that `sinew check` validates
 * them. A failure names the model file, the JSON path and the file. */
static rb_status read_pool_file(mu_json_reader *reader, const json_t *pool, const char *key,
                                mu_model_torque_muscle *muscle)
{
    const bool image = strcmp(key, "image") == 0;
    const char *what = image ? "a profile image: a PNG 1 pixel high, white to red (docs/model-format.md)"
                             : "a CSV of strengths (docs/model-format.md)";
    const char *name;
    MU_JSON_TRY(mu_json_read_string(reader, pool, key, MU_JSON_REQUIRED, what, &name));
    char label[4096];
    FILE *file;
    MU_JSON_TRY(open_pool_file(reader, key, name, what, &file, label, sizeof label));
    char problem[MU_POOL_PROBLEM_SIZE];
    const bool read =
        image ? mu_pool_profile_read_png(file, &muscle->strengths, &muscle->neurons, problem, sizeof problem)
              : mu_pool_profile_read_csv(file, label, &muscle->strengths, &muscle->neurons, problem, sizeof problem);
    fclose(file);
    if (!read) {
        /* A CSV's problem starts with its own "LABEL:LINE:". */
        return image ? mu_json_fail(reader, MU_JSON_AT_VALUE, "%s: %s", label, problem)
                     : mu_json_fail(reader, MU_JSON_AT_VALUE, "%s", problem);
    }
    mu_json_pop(reader);
    muscle->pool_source = image ? MU_MODEL_POOL_IMAGE : MU_MODEL_POOL_CSV;
    MU_JSON_TRY(copy_string(name, &muscle->pool_file));
    return copy_string(label, &muscle->pool_path);
}

/* The torque muscle's motor pool (motor_pool.h), in one of three forms: a
 * profile image, a CSV of strengths, or a generated exponential profile. */
static rb_status parse_motor_pool(mu_json_reader *reader, const json_t *object, mu_model_torque_muscle *muscle)
{
    static const char *const keys[] = {"neurons", "weakest", "strongest", "image", "csv", NULL};
    const json_t *pool = json_object_get(object, "motor_pool");
    if (pool == NULL) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "missing key \"motor_pool\", expected the motor pool " POOL_FORMS);
    }
    mu_json_push_key(reader, "motor_pool");
    MU_JSON_TRY(mu_json_check_object(reader, pool, keys));
    const char *file_key = json_object_get(pool, "image") != NULL ? "image"
                           : json_object_get(pool, "csv") != NULL ? "csv"
                                                                  : NULL;
    if (file_key != NULL) {
        /* One form only: a file's pool has no generated parameters. */
        for (int k = 0; keys[k] != NULL; ++k) {
            if (strcmp(keys[k], file_key) != 0 && json_object_get(pool, keys[k]) != NULL) {
                mu_json_push_key(reader, keys[k]);
                return mu_json_fail(reader, MU_JSON_AT_KEY,
                                    "\"%s\" beside \"%s\", expected one form of motor pool: " POOL_FORMS, keys[k],
                                    file_key);
            }
        }
        MU_JSON_TRY(read_pool_file(reader, pool, file_key, muscle));
        mu_json_pop(reader);
        return RB_OK;
    }
    muscle->pool_source = MU_MODEL_POOL_EXPONENTIAL;
    MU_JSON_TRY(mu_json_read_int(reader, pool, "neurons", MU_JSON_REQUIRED, 1, MU_MAX_MOTOR_NEURONS,
                                 "the number of motor neurons", &muscle->neurons));
    MU_JSON_TRY(mu_json_read_number(reader, pool, "weakest", MU_JSON_REQUIRED, neuron_strength,
                                    "the first (weakest) neuron's strength", &muscle->weakest));
    MU_JSON_TRY(mu_json_read_number(reader, pool, "strongest", MU_JSON_REQUIRED, neuron_strength,
                                    "the last (strongest) neuron's strength", &muscle->strongest));
    if (muscle->strongest < muscle->weakest) {
        mu_json_push_key(reader, "strongest");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "%g is below weakest (%g), expected a strength >= weakest",
                            muscle->strongest, muscle->weakest);
    }
    mu_json_pop(reader);
    return RB_OK;
}

static rb_status parse_torque_muscle(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name", "body", "reaction_body", "peak_torque", "motor_pool", "recruited", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_torque_muscle *muscle = &desc->torque_muscles[desc->torque_muscle_count++];
    MU_JSON_TRY(read_object_name(reader, object, desc,
                                 (mu_model_ref){MU_MODEL_TORQUE_MUSCLE, desc->torque_muscle_count - 1}, &muscle->name));
    MU_JSON_TRY(read_body(reader, object, "body", desc, &muscle->body));
    if (muscle->body.kind != MU_MODEL_BONE) {
        mu_json_push_key(reader, "body");
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is a nail, expected the name of a bone",
                            mu_model_desc_name_of(desc, muscle->body));
    }
    muscle->has_reaction_body = json_object_get(object, "reaction_body") != NULL;
    if (muscle->has_reaction_body) {
        MU_JSON_TRY(read_body(reader, object, "reaction_body", desc, &muscle->reaction_body));
        if (muscle->reaction_body.kind == muscle->body.kind && muscle->reaction_body.index == muscle->body.index) {
            mu_json_push_key(reader, "reaction_body");
            return mu_json_fail(reader, MU_JSON_AT_VALUE, "\"%s\" is body too, expected a different body",
                                mu_model_desc_name_of(desc, muscle->body));
        }
    }
    MU_JSON_TRY(mu_json_read_number(reader, object, "peak_torque", MU_JSON_REQUIRED, peak_torque,
                                    "the torque at full recruitment in N·m", &muscle->peak_torque));
    MU_JSON_TRY(parse_motor_pool(reader, object, muscle));
    return mu_json_read_int(reader, object, "recruited", MU_JSON_OPTIONAL, 0, muscle->neurons,
                            "the neurons recruited at the start", &muscle->recruited);
}

static rb_status parse_group(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name", "muscles", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_group *group = &desc->groups[desc->group_count++];
    MU_JSON_TRY(
        read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_GROUP, desc->group_count - 1}, &group->name));
    return read_name_list(reader, object, "muscles", MU_MODEL_MUSCLE, desc, 1, &group->muscles, &group->muscle_count);
}

static rb_status parse_weight(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name", "body", "position", "masses", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    desc->has_weight = true;
    mu_model_weight *weight = &desc->weight;
    MU_JSON_TRY(read_object_name(reader, object, desc, (mu_model_ref){MU_MODEL_WEIGHT, 0}, &weight->name));
    MU_JSON_TRY(read_body(reader, object, "body", desc, &weight->body));
    MU_JSON_TRY(mu_json_read_vec2(reader, object, "position", MU_JSON_REQUIRED, coordinate, "the weight's centre in m",
                                  &weight->position));
    const json_t *masses;
    MU_JSON_TRY(mu_json_read_array(reader, object, "masses", MU_JSON_REQUIRED, 1, MU_MODEL_MAX_OBJECTS,
                                   "weight choices in kg", &masses));
    weight->masses = calloc(json_array_size(masses), sizeof *weight->masses);
    MU_JSON_TRY(check_allocation(weight->masses, json_array_size(masses)));
    weight->mass_count = (int)json_array_size(masses);
    mu_json_push_key(reader, "masses");
    for (size_t i = 0; i < json_array_size(masses); ++i) {
        mu_json_push_index(reader, i);
        MU_JSON_TRY(mu_json_expect_number(reader, json_array_get(masses, i), weight_mass,
                                          "a mass in kg, 0 for no weight", &weight->masses[i]));
        mu_json_pop(reader);
    }
    mu_json_pop(reader);
    return RB_OK;
}

/* ---- variants ------------------------------------------------------------ */

/* Fails if a muscle of the variant runs over a bone the variant leaves out. */
static rb_status check_variant_bones(mu_json_reader *reader, const mu_model_desc *desc, const mu_model_variant *variant)
{
    /* Flags, not mu_model_variant_has_bone's scan: linear in the variant's size. */
    bool *in_variant = calloc((size_t)desc->bone_count + 1, sizeof *in_variant);
    MU_JSON_TRY(check_allocation(in_variant, 1));
    for (int b = 0; b < variant->bone_count; ++b) {
        in_variant[variant->bones[b]] = true;
    }
    for (int m = 0; m < variant->muscle_count; ++m) {
        const mu_model_muscle *muscle = &desc->muscles[variant->muscles[m]];
        for (int p = 0; p < muscle->point_count; ++p) {
            mu_model_ref body = muscle->path[p].body;
            if (body.kind == MU_MODEL_BONE && !in_variant[body.index]) {
                free(in_variant);
                mu_json_push_key(reader, "muscles");
                mu_json_push_index(reader, (size_t)m);
                return mu_json_fail(reader, MU_JSON_AT_VALUE,
                                    "muscle \"%s\" runs over bone \"%s\", which the variant's bones leave out, "
                                    "expected a muscle whose bones are all in the variant",
                                    muscle->name, desc->bones[body.index].name);
            }
        }
    }
    free(in_variant);
    return RB_OK;
}

/* Every bone, for a variant that does not list its bones. */
static rb_status all_bones(const mu_model_desc *desc, mu_model_variant *variant)
{
    variant->bones = calloc((size_t)desc->bone_count, sizeof *variant->bones);
    MU_JSON_TRY(check_allocation(variant->bones, (size_t)desc->bone_count));
    for (int i = 0; i < desc->bone_count; ++i) {
        variant->bones[variant->bone_count++] = i;
    }
    return RB_OK;
}

static rb_status parse_variant(mu_json_reader *reader, const json_t *object, mu_model_desc *desc)
{
    static const char *const keys[] = {"name", "muscles", "bones", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, object, keys));
    mu_model_variant *variant = &desc->variants[desc->variant_count++];
    const char *name;
    MU_JSON_TRY(read_name(reader, object, "the variant's name", &name));
    int other = mu_model_desc_find_variant(desc, name);
    if (other >= 0) {
        mu_json_push_key(reader, "name");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "\"%s\" is already the name of variants[%d], expected a name that no other variant has",
                            name, other);
    }
    MU_JSON_TRY(copy_string(name, &variant->name));
    MU_JSON_TRY(mu_name_index_add(&desc->variant_names, variant->name, 0, desc->variant_count - 1));
    MU_JSON_TRY(
        read_name_list(reader, object, "muscles", MU_MODEL_MUSCLE, desc, 0, &variant->muscles, &variant->muscle_count));
    if (json_object_get(object, "bones") != NULL) {
        MU_JSON_TRY(
            read_name_list(reader, object, "bones", MU_MODEL_BONE, desc, 0, &variant->bones, &variant->bone_count));
    } else {
        MU_JSON_TRY(all_bones(desc, variant));
    }
    return check_variant_bones(reader, desc, variant);
}

/* Without "variants", the model has one variant with everything in it. */
static rb_status default_variant(mu_model_desc *desc)
{
    desc->variants = calloc(1, sizeof *desc->variants);
    MU_JSON_TRY(check_allocation(desc->variants, 1));
    mu_model_variant *variant = &desc->variants[desc->variant_count++];
    MU_JSON_TRY(copy_string("Default", &variant->name));
    variant->muscles = calloc((size_t)desc->muscle_count, sizeof *variant->muscles);
    MU_JSON_TRY(check_allocation(variant->muscles, (size_t)desc->muscle_count));
    for (int i = 0; i < desc->muscle_count; ++i) {
        variant->muscles[variant->muscle_count++] = i;
    }
    return all_bones(desc, variant);
}

/* ---- the model ------------------------------------------------------------- */

typedef rb_status (*parse_element)(mu_json_reader *reader, const json_t *object, mu_model_desc *desc);

/* Parses each element of the list `key` (NULL: absent) with `parse`,
 * which appends to the array it fills. */
static rb_status for_each(mu_json_reader *reader, const char *key, const json_t *list, mu_model_desc *desc,
                          parse_element parse)
{
    if (list == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    for (size_t i = 0; i < json_array_size(list); ++i) {
        mu_json_push_index(reader, i);
        MU_JSON_TRY(parse(reader, json_array_get(list, i), desc));
        mu_json_pop(reader);
    }
    mu_json_pop(reader);
    return RB_OK;
}

/* The optional list `key` of `what`; *out is NULL when it is absent. */
static rb_status read_list(mu_json_reader *reader, const json_t *root, const char *key, size_t min_count,
                           const char *what, const json_t **out)
{
    return mu_json_read_array(reader, root, key, MU_JSON_OPTIONAL, min_count, MU_MODEL_MAX_OBJECTS, what, out);
}

static rb_status parse_settings(mu_json_reader *reader, const json_t *root, mu_model_desc *desc)
{
    const char *name;
    MU_JSON_TRY(read_name(reader, root, "the model's name", &name));
    MU_JSON_TRY(copy_string(name, &desc->name));
    desc->gravity = rb_v2(0.0, DEFAULT_GRAVITY_Y);
    MU_JSON_TRY(mu_json_read_vec2(reader, root, "gravity", MU_JSON_OPTIONAL, gravity_component, "the gravity in m/s²",
                                  &desc->gravity));
    desc->frame_rate = DEFAULT_FRAME_RATE;
    MU_JSON_TRY(mu_json_read_number(reader, root, "frame_rate", MU_JSON_OPTIONAL, frame_rate, "the frame rate in Hz",
                                    &desc->frame_rate));
    desc->substeps = DEFAULT_SUBSTEPS;
    MU_JSON_TRY(mu_json_read_int(reader, root, "substeps", MU_JSON_OPTIONAL, 1, MAX_SUBSTEPS, "the substeps per frame",
                                 &desc->substeps));
    const double substep_rate = desc->frame_rate * desc->substeps;
    if (substep_rate < MIN_SUBSTEP_RATE || substep_rate > MAX_SUBSTEP_RATE) {
        mu_json_push_key(reader, json_object_get(root, "substeps") != NULL ? "substeps" : "frame_rate");
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "frame_rate × substeps is %g Hz, expected a substep rate in [%g, %g] Hz (a substep of "
                            "1/60 s at most)",
                            substep_rate, MIN_SUBSTEP_RATE, MAX_SUBSTEP_RATE);
    }
    MU_JSON_TRY(mu_json_read_vec2(reader, root, "placement", MU_JSON_OPTIONAL, coordinate, "the model's offset in m",
                                  &desc->placement));
    desc->damping = DEFAULT_BONE_DAMPING;
    return mu_json_read_number(reader, root, "damping", MU_JSON_OPTIONAL, damping, "the bones' damping in 1/s",
                               &desc->damping);
}

rb_status mu_model_parse(mu_json_reader *reader, const json_t *root, mu_model_desc *desc)
{
    static const char *const keys[] = {"name",   "gravity",  "frame_rate",     "substeps", "placement", "damping",
                                       "nails",  "bones",    "hinges",         "glues",    "weight",    "muscles",
                                       "groups", "variants", "torque_muscles", NULL};
    MU_JSON_TRY(mu_json_check_object(reader, root, keys));
    MU_JSON_TRY(parse_settings(reader, root, desc));
    const json_t *list;

    MU_JSON_TRY(read_list(reader, root, "nails", 0, "nails {name, position}", &list));
    desc->nails = calloc(json_array_size(list), sizeof *desc->nails);
    MU_JSON_TRY(check_allocation(desc->nails, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "nails", list, desc, parse_nail));

    MU_JSON_TRY(read_list(reader, root, "bones", 0, "bones {name, centre, size, ...}", &list));
    desc->bones = calloc(json_array_size(list), sizeof *desc->bones);
    MU_JSON_TRY(check_allocation(desc->bones, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "bones", list, desc, parse_bone));

    MU_JSON_TRY(
        read_list(reader, root, "hinges", 0, "hinges {name, body_a, anchor_a, body_b, anchor_b, radius, ...}", &list));
    desc->hinges = calloc(json_array_size(list), sizeof *desc->hinges);
    MU_JSON_TRY(check_allocation(desc->hinges, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "hinges", list, desc, parse_hinge));

    MU_JSON_TRY(read_list(reader, root, "glues", 0, "glues {name, body_a, body_b}", &list));
    desc->glues = calloc(json_array_size(list), sizeof *desc->glues);
    MU_JSON_TRY(check_allocation(desc->glues, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "glues", list, desc, parse_glue));

    const json_t *weight = json_object_get(root, "weight");
    if (weight != NULL) {
        mu_json_push_key(reader, "weight");
        MU_JSON_TRY(parse_weight(reader, weight, desc));
        mu_json_pop(reader);
    }

    MU_JSON_TRY(read_list(reader, root, "muscles", 0, "muscles {name, rest_length, path, ...}", &list));
    desc->muscles = calloc(json_array_size(list), sizeof *desc->muscles);
    MU_JSON_TRY(check_allocation(desc->muscles, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "muscles", list, desc, parse_muscle));

    MU_JSON_TRY(read_list(reader, root, "groups", 0, "groups {name, muscles}", &list));
    desc->groups = calloc(json_array_size(list), sizeof *desc->groups);
    MU_JSON_TRY(check_allocation(desc->groups, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "groups", list, desc, parse_group));

    MU_JSON_TRY(read_list(reader, root, "torque_muscles", 0,
                          "torque muscles {name, body, reaction_body, peak_torque, motor_pool, recruited}", &list));
    desc->torque_muscles = calloc(json_array_size(list), sizeof *desc->torque_muscles);
    MU_JSON_TRY(check_allocation(desc->torque_muscles, json_array_size(list)));
    MU_JSON_TRY(for_each(reader, "torque_muscles", list, desc, parse_torque_muscle));

    MU_JSON_TRY(read_list(reader, root, "variants", 1, "variants {name, muscles, bones}", &list));
    if (list == NULL) {
        return default_variant(desc);
    }
    desc->variants = calloc(json_array_size(list), sizeof *desc->variants);
    MU_JSON_TRY(check_allocation(desc->variants, json_array_size(list)));
    return for_each(reader, "variants", list, desc, parse_variant);
}
