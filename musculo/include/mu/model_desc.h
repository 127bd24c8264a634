/* SPDX-License-Identifier: MIT */
/** @file
 * The description of a musculoskeletal model, read from a JSON model file
 * (format: docs/model-format.md): pure data, no engine objects. The model
 * builder turns it into bodies, joints and muscles at a simulation level,
 * a variant and a weight choice (model.h).
 *
 * Positions, centres and anchors are in m; a position is relative to the
 * model's origin (before `placement` moves the model), an anchor or path
 * point is in its body's frame, measured from the body's centre. Angles
 * are in degrees, as in the file.
 *
 * A loaded description has been validated as a whole: every reference is
 * resolved to an index, every value is in its range (docs/model-format.md
 * gives them, and why a model within them runs). A file
 * that fails yields no description and an error (rb_last_error()) naming
 * the file, the line and column, the JSON path and what was expected.
 */
#ifndef MU_MODEL_DESC_H
#define MU_MODEL_DESC_H

#include <stdbool.h>

#include "mu/activation.h"
#include "mu/calcium_force.h"
#include "mu/export.h"
#include "rb/base.h"
#include "rb/cable.h"
#include "rb/math.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Most bytes a model file may have (16 MiB, some 3,000 times the
 * largest built-in model): mu_model_desc_load refuses a longer file, or
 * one that never ends such as /dev/zero, after reading this much. */
#define MU_MODEL_MAX_FILE_BYTES 16777216

/** Most objects one list of a model file may hold. */
#define MU_MODEL_MAX_OBJECTS 65535

/** The kinds of named objects. All of them share one namespace (a name is
 * unique among a model's nails, bones, hinges, glues, weight, muscles and
 * groups), so one name finds one object; variants have their own. */
typedef enum mu_model_kind {
    MU_MODEL_NAIL,
    MU_MODEL_BONE,
    MU_MODEL_HINGE,
    MU_MODEL_GLUE,
    MU_MODEL_WEIGHT,
    MU_MODEL_MUSCLE,
    MU_MODEL_GROUP,
    MU_MODEL_TORQUE_MUSCLE,
} mu_model_kind;

/** One object of the description: desc->nails[index], desc->bones[index],
 * ...; the weight has index 0. A reference to a body is a nail or a bone. */
typedef struct mu_model_ref {
    mu_model_kind kind;
    int index; /**< 0 .. the kind's count - 1 */
} mu_model_ref;

/** A static anchor point. */
typedef struct mu_model_nail {
    char *name;
    rb_vec2 position; /**< m, each coordinate in [-100, 100] */
} mu_model_nail;

/** A box; its mass is density·size.x·size.y·depth. */
typedef struct mu_model_bone {
    char *name;
    rb_vec2 centre; /**< m, each coordinate in [-100, 100] */
    rb_vec2 size;   /**< m, x extent and y extent in the bone's frame, each in [0.001, 100] */
    double angle;   /**< degrees in [-360, 360], counter-clockwise; default 0 */
    double depth;   /**< m in [0.001, 100]; default the smaller extent (the bone's thickness) */
    bool is_static; /**< default false */
    double density; /**< kg/m³ in [1, 100000]; default 1900 */
    /** 1/s, linear and angular, in [0, 1000]; default the model's damping.
     * Bones glued into one body take the first one's (in file order). */
    double damping;
    /** The bone as a beam (bone_stress.h): a cortical tube of outer
     * diameter the smaller extent D and wall wall_thickness (m, in
     * [1e-5, D/2]; default D/4; D/2 is a solid rod), of cortical bone with
     * Young's modulus youngs_modulus (Pa in [1e6, 1e12]; default 17 GPa)
     * and ultimate strengths tensile_strength and compressive_strength
     * (Pa in [1e5, 1e10]; default 133 MPa and 193 MPa). */
    double wall_thickness;
    double youngs_modulus;
    double tensile_strength, compressive_strength;
} mu_model_bone;

/** A revolute joint pinning anchor_a on body A to anchor_b on body B. The
 * joint angle is angle(B) - angle(A); each limit is on only when given. */
typedef struct mu_model_hinge {
    char *name;
    mu_model_ref body_a, body_b; /**< nails or bones, different */
    rb_vec2 anchor_a, anchor_b;  /**< m, in each body's frame, in [-100, 100]; they meet (within 0.01 m) */
    double radius;               /**< m in (0, 100]: drawn size only */
    bool has_lower, has_upper;
    double lower, upper; /**< degrees in [-360, 360]; lower <= upper when both are on */
} mu_model_hinge;

/** A weld freezing the relative pose the two bodies have when it is made. */
typedef struct mu_model_glue {
    char *name;
    mu_model_ref body_a, body_b; /**< nails or bones, different */
} mu_model_glue;

/** The load: an iron disc (7874 kg/m³, 0.10 m deep) at `position`, glued to `body`;
 * the weight choice picks its mass, and no disc is made for 0 kg. */
typedef struct mu_model_weight {
    char *name;
    mu_model_ref body;
    rb_vec2 position; /**< m, the disc's centre, in [-100, 100] */
    int mass_count;   /**< 1 .. MU_MODEL_MAX_OBJECTS: the weight choices */
    double *masses;   /**< kg, each in [0, 1e6] */
} mu_model_weight;

typedef enum mu_model_curve_set {
    MU_MODEL_CURVES_TABULATED, /**< the original report's tables (models/data/hill-curves.csv) */
    MU_MODEL_CURVES_ANALYTIC,  /**< the MATLAB Hill worksheet's analytic curves (curves.h) */
} mu_model_curve_set;

/** One point of a muscle's path: origin, via points, insertion. */
typedef struct mu_model_path_point {
    mu_model_ref body; /**< a nail or a bone */
    rb_vec2 point;     /**< m, in the body's frame, in [-100, 100]; apart from the previous point */
} mu_model_path_point;

/** A muscle's architecture, when the file derives its maximal force from
 * it (Castanyer's report §2.2; muscle_statics.h): Fmax = specific_tension
 * · PCSA, with PCSA = volume / fibre_length, or anatomical_cross_section /
 * cos(pennation_angle). The inputs the file gives are kept (0 when not
 * given) so that they can be shown; max_force holds the derived force. */
typedef struct mu_model_architecture {
    bool given;                      /**< whether the file gave "architecture" */
    double volume;                   /**< m³ in [1e-9, 0.1], or 0 (then anatomical_cross_section) */
    double anatomical_cross_section; /**< m² in [1e-8, 0.1], or 0 (then volume) */
    double sarcomeres;               /**< in [500, 5e6] sarcomeres in series, or 0 when not given */
    double measured_fibre_length;    /**< m in [0.001, 10], or 0 when not given */
    double sarcomere_length;         /**< m in [1e-6, 5e-6], measured with the fibre length, or 0 */
    /** m: the optimal fibre length PCSA divides by (volume only): sarcomeres
     * · 2 µm, the measured fibre length normalized to 2 µm sarcomeres, the
     * fibre length as given, or else the muscle's rest_length. */
    double fibre_length;
    double pcsa; /**< m²: the physiological cross-section derived */
} mu_model_architecture;

/** A Hill muscle (muscle.h); the fields map onto mu_muscle_def. */
typedef struct mu_model_muscle {
    char *name;
    double rest_length; /**< m in [0.001, 10]: the fibres' optimal length */
    /** Maximal isometric force: max_force when > 0 (given, or derived from
     * the architecture), else the circular cross-section π·rest_width²/4
     * times specific_tension. */
    double max_force;        /**< N in [0.001, 1e6], or 0 when not given */
    double rest_width;       /**< m in [1e-4, 1], or 0 when not given (then max_force is given) */
    double specific_tension; /**< N/m² in [1e3, 1e7]; default 1.5e6; unused when max_force is given */
    /** When architecture.given, max_force above is derived from it. */
    mu_model_architecture architecture;
    double max_velocity;            /**< m/s in [0.001, 100]; default 0.25 */
    double start_normalized_length; /**< in [0.5, 1.5]; default 1; unused when tendon_length >= 0 */
    double tendon_length;           /**< m in [0, 100], or -1 when not given (then from start_normalized_length) */
    double symmetry;                /**< in [0, 1]: where the belly sits between the path's ends; default 0.5 */
    mu_model_curve_set curves;      /**< default MU_MODEL_CURVES_TABULATED */
    int point_count;                /**< 2 .. RB_MAX_CABLE_POINTS */
    mu_model_path_point path[RB_MAX_CABLE_POINTS];
    /** Geometry-derived lengths (geometry_lengths.h): the tendon's share of
     * the path's length at the model's start pose, in [0, 1), or -1 when
     * not given. When given, rest_length and tendon_length above hold the
     * lengths derived from it at load. */
    double tendon_fraction;
    double pennation_angle; /**< degrees in [0, 80] at the optimal fibre length; default 0 */
    /** Activation dynamics (activation.h): off by default. */
    bool activation_dynamics;
    double activation_time;   /**< s in [1e-4, 10]; default 0.010 */
    double deactivation_time; /**< s in [1e-4, 10]; default 0.040 */
    /** The dynamics' kind (activation.h); calcium_force holds the two-stage
     * dynamics' times, each s in [1e-4, 10], by default the fast set. */
    mu_activation_model activation_model;
    mu_calcium_force_times calcium_force;
    /** A compliant tendon (tendon.h): off by default (rigid). Its slack
     * length, tendon_length or the one derived at build, is > 0: checked
     * at load against the path's length at the start pose. */
    bool compliant_tendon;
    double tendon_strain_at_max_force; /**< in [0.001, 1]; default 0.049 */
    double fibre_damping;              /**< in [0.001, 10]; default 0.1 */
} mu_model_muscle;

/** Where a torque muscle's motor pool comes from (motor_pool.h). */
typedef enum mu_model_pool_source {
    MU_MODEL_POOL_EXPONENTIAL, /**< generated: neurons strengths from weakest to strongest */
    MU_MODEL_POOL_IMAGE,       /**< a profile image (PNG), one neuron per pixel */
    MU_MODEL_POOL_CSV,         /**< a CSV of strengths */
} mu_model_pool_source;

/** A torque muscle (after McIntyre, "Simulated Muscles"; torque_actuator.h and
 * motor_pool.h): exertion · peak_torque on `body` about the axis out of
 * the plane, its reaction on `reaction_body` (or the world), the exertion
 * set by recruiting neurons of its motor pool: a generated exponential
 * profile, or the strengths of a profile image or a CSV, read when the
 * file is loaded. Built at level 3 and above when its bones are in the
 * variant. */
typedef struct mu_model_torque_muscle {
    char *name;
    mu_model_ref body;          /**< a bone */
    bool has_reaction_body;     /**< default false: the reaction goes to the world */
    mu_model_ref reaction_body; /**< a nail or bone other than body */
    double peak_torque; /**< N·m in [-1000, 1000]: the torque at full recruitment, counter-clockwise when > 0 */
    mu_model_pool_source pool_source;
    int neurons; /**< 1 .. MU_MAX_MOTOR_NEURONS: the pool's size, the image's width or the CSV's count */
    /** MU_MODEL_POOL_EXPONENTIAL only (0 otherwise): strengths of the first
     * and last neuron, 1e-6 <= weakest <= strongest <= 1e6. */
    double weakest, strongest;
    /** MU_MODEL_POOL_IMAGE and _CSV (NULL otherwise): the file as the
     * model file names it, and the path it was read from (relative to the
     * model file's folder; "NAME (built into libmu)" for a built-in
     * model's), and its `neurons` strengths, each >= 0, their sum > 0. */
    char *pool_file;
    char *pool_path;
    double *strengths;
    int recruited; /**< neurons recruited at the start, 0 .. neurons; default 0 */
} mu_model_torque_muscle;

/** Muscles driven together. Each muscle is also a group of its own, which
 * the model provides; these are the groups the file adds. */
typedef struct mu_model_group {
    char *name;
    int muscle_count; /**< 1 .. MU_MODEL_MAX_OBJECTS */
    int *muscles;     /**< indices into desc->muscles, distinct */
} mu_model_group;

/** Which muscles and bones exist when the model is built in this variant.
 * Every muscle's path lies on bones of the variant (or nails). */
typedef struct mu_model_variant {
    char *name;
    int muscle_count; /**< 0 .. desc->muscle_count */
    int *muscles;     /**< indices into desc->muscles, distinct, in file order */
    int bone_count;   /**< 0 .. desc->bone_count; all bones unless the file lists them */
    int *bones;       /**< indices into desc->bones, distinct */
} mu_model_variant;

typedef struct mu_model_desc {
    char *name;
    /** The file it was read from, as given to the loader ("arm.json (built
     * into libmu)" for a built-in one), which the model's messages name;
     * NULL in a description made otherwise. */
    char *source;
    rb_vec2 gravity;   /**< m/s², each component in [-1000, 1000]; default (0, -9.8) */
    double frame_rate; /**< Hz in [1, 1000]; default 60; frame_rate · substeps in [60, 1e5] */
    int substeps;      /**< per frame, in [1, 1000]; default 10 */
    rb_vec2 placement; /**< m, each in [-100, 100], added to every position when the model is built; default (0, 0) */
    double damping;    /**< 1/s, every bone's unless it gives its own, in [0, 1000]; default 8 */
    int nail_count;
    mu_model_nail *nails;
    int bone_count;
    mu_model_bone *bones;
    int hinge_count;
    mu_model_hinge *hinges;
    int glue_count;
    mu_model_glue *glues;
    bool has_weight;
    mu_model_weight weight; /**< all zero without a weight */
    int muscle_count;
    mu_model_muscle *muscles;
    int group_count;
    mu_model_group *groups;
    int torque_muscle_count;
    mu_model_torque_muscle *torque_muscles;
    int variant_count; /**< >= 1: without "variants" in the file, one variant "Default" with everything */
    mu_model_variant *variants;
    /** Private: the loader's indices of the objects' and the variants'
     * names, which make mu_model_desc_find and mu_model_desc_find_variant
     * take constant time (NULL in a description made otherwise: they then
     * scan). They borrow the names: change no name of a loaded description. */
    struct mu_name_index *object_names, *variant_names;
} mu_model_desc;

/** Reads and validates the model file `path`. On success *out owns a new
 * description (free it with mu_model_desc_destroy); on failure *out is
 * NULL and rb_last_error() says what is wrong and where. NULL arguments
 * are refused with RB_ERR_INVALID_ARGUMENT. */
MU_API rb_status mu_model_desc_load(const char *path, mu_model_desc **out);

/** Reads the built-in model `name` ("sample", "arm", "leg", "worm"), which is
 * compiled into the library; when the environment variable SINEW_DATA_DIR
 * names a folder, reads NAME.json from that folder instead. */
MU_API rb_status mu_model_desc_load_builtin(const char *name, mu_model_desc **out);

/** How many models are built in. */
MU_API int mu_builtin_model_count(void);
/** The name of built-in model `index` (0 to mu_builtin_model_count() - 1,
 * in the order `sinew models` lists them); NULL, with the error recorded,
 * out of range. */
MU_API const char *mu_builtin_model_name(int index);

/** Accepts NULL. */
MU_API void mu_model_desc_destroy(mu_model_desc *desc);

/** Finds the object named `name` (any kind but variants): true and *out
 * filled, or false. False, with the error recorded, for a NULL argument. */
MU_API bool mu_model_desc_find(const mu_model_desc *desc, const char *name, mu_model_ref *out);

/** Index of the variant named `name`, or -1 (and, for a NULL argument,
 * the error recorded). */
MU_API int mu_model_desc_find_variant(const mu_model_desc *desc, const char *name);

/** The name of an object; NULL, with the error recorded, for a NULL
 * description or a reference to no object of it. */
MU_API const char *mu_model_desc_name_of(const mu_model_desc *desc, mu_model_ref ref);

/** Whether muscle (or bone) `index` exists in variant `variant`; false,
 * with the error recorded, for a NULL variant. */
MU_API bool mu_model_variant_has_muscle(const mu_model_variant *variant, int index);
MU_API bool mu_model_variant_has_bone(const mu_model_variant *variant, int index);

#ifdef __cplusplus
}
#endif

#endif
