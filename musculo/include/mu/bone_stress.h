/* SPDX-License-Identifier: MIT */
/** @file
 * Bone stress: each bone read as a beam, from every force on it in the
 * present frame. The engine stays rigid; this is a readout.
 *
 * The beam. A bone's axis is its box's long side (its own x when
 * size.x >= size.y, else y); s is the coordinate along that axis from the
 * bone's centre, -L/2 .. L/2 (L the long extent). Its cross-section is a
 * cortical tube (model_desc.h): outer diameter D the smaller extent, wall
 * t, inner diameter d = D - 2t, so
 *
 *   A = π(D² - d²)/4 (m²),  I = π(D⁴ - d⁴)/64 (m⁴),  c = D/2 (m).
 *
 * The loads on a bone, all in the world frame:
 * - the reactions of the hinges and welds (glues kept as welds, the
 *   weight's weld) at their anchors on it: force and torque, as
 *   joint_loads.h reads them;
 * - the muscles' cable forces at their path points on it (a point is
 *   pulled towards its neighbours on the path with the cable's tension);
 * - the torque muscles' torques on it, and their reactions (couples);
 * - the weight disc, when it is merged into the bone: its m·g at its
 *   centre, and its inertia;
 * - gravity, damping and inertia spread over the bone's box: per unit
 *   mass at a point p, g - a(p) - c·v(p), with a(p) and v(p) the rigid
 *   body's acceleration and velocity at p (c the body's damping, as the
 *   engine applies it);
 * - the loads of the bones glued to it into one rigid body (below).
 * The body's acceleration (a at its centre of mass, α) is not read from
 * the engine, which keeps none: it is Newton's, from the body's loads:
 * m·a = ΣF + m·g - c·m·v, I·α = ΣM - c·I·ω. a is the engine's own
 * (v' - v)/h over the last substep; α differs from the engine's by the
 * turn ω·h of the lever arms (the engine applies the impulses at the
 * substep's starting pose, the readout has the end pose), a relative
 * error of order ω·h in the moments (docs/loads.md).
 *
 * Glued bones. Bones glued into one rigid body (the default, model.h)
 * pass loads to each other through the glue, which the engine does not
 * resolve (how two glued bones share a load is statically indeterminate).
 * Each bone is read as carrying the whole body's loads: its own, and each
 * glued bone's at that bone's points (a glued bone's spread loads as one
 * force and couple at its centre), each placed along the axis at its
 * point's coordinate. So the forearm's ulna and radius each carry the
 * whole forearm, hand and weight: a conservative bound, not a share.
 *
 * The sections. Cut the bone at s: the internal loads are those of every
 * load beyond the cut (on the side of larger s, a point load at its
 * anchor's coordinate along the axis, clamped to the ends):
 * - N (N): the axial force, their resultant along the axis, > 0 tension;
 * - V (N): the shear force, their resultant across it (axis turned +90°);
 * - M (N·m): the bending moment, their moment about the section's centre,
 *   counter-clockwise.
 * The normal stress across the section is N/A ± M·c/I; its extremes
 * σ_t = N/A + |M|·c/I and σ_c = N/A - |M|·c/I, strain ε = σ/E, and the
 * safety factor the smaller of S_t/σ_t (when σ_t > 0) and S_c/(-σ_c)
 * (when σ_c < 0), S the ultimate strengths. Shear stress is not counted.
 * Sections: both sides of every point load's coordinate, the bone's ends
 * and MU_BONE_STRESS_SECTIONS evenly spaced between them. Loads closer
 * than 1e-12 of the bone's length are at one point, with no section
 * between them (a weight on a hinge's pin, a muscle inserted at a
 * joint's anchor: the roundings of their frames must not cut between
 * them). Between point
 * loads the moment from the spread loads is smooth (a cubic in s), and
 * the spacing L/64 puts a maximum between two sections within
 * (L/128)²·|M''|/2 of the sections' value.
 */
#ifndef MU_BONE_STRESS_H
#define MU_BONE_STRESS_H

#include "mu/export.h"
#include "mu/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Evenly spaced sections along a bone, besides the load points. */
#define MU_BONE_STRESS_SECTIONS 64

/** A bone's cross-section and material (model_desc.h gives the defaults). */
typedef struct mu_bone_beam {
    double length;               /**< m, the long extent L */
    double outer_diameter;       /**< m, D */
    double wall_thickness;       /**< m, t, 0 < t <= D/2 */
    double area;                 /**< m², A */
    double second_moment;        /**< m⁴, I */
    double youngs_modulus;       /**< Pa, E */
    double tensile_strength;     /**< Pa */
    double compressive_strength; /**< Pa, > 0 */
} mu_bone_beam;

/** The internal loads at one section. */
typedef struct mu_bone_section {
    double s;              /**< m along the axis from the bone's centre */
    double axial_force;    /**< N, > 0 tension */
    double shear_force;    /**< N */
    double bending_moment; /**< N·m */
    double stress;         /**< Pa: of σ_t and σ_c the one larger in size, signed */
    double safety_factor;  /**< ultimate over actual; +inf unloaded */
} mu_bone_section;

/** A bone's worst section (the lowest safety factor) in the present frame. */
typedef struct mu_bone_stress {
    mu_bone_section worst;
    double strain; /**< worst.stress / E */
} mu_bone_stress;

/** The beam of description bone `bone` (0 .. desc->bone_count - 1).
 * Fields the description leaves at 0 (one made in code) take the
 * defaults. NaN fields for a bad index or a NULL model (the error
 * recorded, model.h). */
MU_API mu_bone_beam mu_model_bone_beam(const mu_model *model, int bone);

/** The bone's worst section now. NaN fields, without an error, for a bone
 * the variant does not build or one fixed to the ground (a static body
 * has no loads to read); with the error for a bad index or NULL model. */
MU_API mu_bone_stress mu_model_bone_stress(const mu_model *model, int bone);

/** Every bone's worst section now, stresses[b] for description bone b in
 * 0 .. desc->bone_count - 1 (stresses must hold that many; NULL only when
 * there are none): the same values, bit for bit, as
 * mu_model_bone_stress(model, b) for each b, NaN fields for the bones it
 * gives NaN, but each rigid body's loads are collected once for all the
 * bones glued into it rather than once per bone, the cost of reading a
 * whole model every frame (`sinew run`). RB_OK, or the error (NULL
 * model or stresses, memory). */
MU_API rb_status mu_model_bone_stresses(const mu_model *model, mu_bone_stress *stresses);

/** The internal loads at section `s` (m, -L/2 .. L/2) counting the point
 * loads at s beyond the cut when `include_at_s`. NaN as above. */
MU_API mu_bone_section mu_model_bone_section(const mu_model *model, int bone, double s, bool include_at_s);

/** `count` sections (1 .. 65535) at the middles of `count` equal pieces
 * of the bone, s_k = L·((k + 1/2)/count - 1/2), for drawing the stress
 * along it. RB_OK, or the error (also for a bone not built or fixed to
 * the ground). */
MU_API rb_status mu_model_bone_sections(const mu_model *model, int bone, int count, mu_bone_section *sections);

/** The free-body balance of the bone: the resultant force (N) and the
 * moment about the bone's centre (N·m) of every load on it, inertia
 * included, which vanish for a rigid body; and, for scale, the sum of
 * the loads' sizes (N) without the inertia. RB_OK, or the error. */
MU_API rb_status mu_model_bone_balance(const mu_model *model, int bone, rb_vec2 *force, double *moment,
                                       double *load_scale);

/** The acceleration of the bone's rigid body as this readout takes it
 * (Newton's, above): of its centre of mass (m/s²) and angular (rad/s²).
 * RB_OK, or the error. */
MU_API rb_status mu_model_bone_acceleration(const mu_model *model, int bone, rb_vec2 *acceleration, double *alpha);

#ifdef __cplusplus
}
#endif

#endif
