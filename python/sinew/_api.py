# SPDX-License-Identifier: MIT
"""The C API as ctypes sees it: the structures of rb/*.h and mu/*.h, field
for field in declaration order, and the argument and result types of every
function the package calls. Private: the classes of the package wrap it.

A structure here must match its header exactly (ctypes lays fields out as
the C compiler does). The tests read values through them that the C side
computed and that they know independently (the solver's documented
defaults, a step's statistics, the arm's frame rate, variants and
weights, every column of a run against sinew run's CSV), which a shifted
field would garble.
"""
import ctypes
from ctypes import POINTER, Structure, c_bool, c_char_p, c_double, c_int, c_int32, c_uint32, c_uint64, c_void_p

c_size_t = ctypes.c_size_t

# ---------------------------------------------------------------- rb/math.h


class Vec2(Structure):
    _fields_ = [("x", c_double), ("y", c_double)]


class Rot(Structure):
    _fields_ = [("c", c_double), ("s", c_double)]


class Transform(Structure):
    _fields_ = [("p", Vec2), ("q", Rot)]


class AABB(Structure):
    _fields_ = [("lower", Vec2), ("upper", Vec2)]


# ------------------------------------------------------------------ rb/id.h


def _id(name):
    return type(name, (Structure,), {"_fields_": [("index", c_int32), ("generation", c_uint32), ("world", c_uint64)]})


BodyId = _id("BodyId")
ShapeId = _id("ShapeId")
JointId = _id("JointId")
CableId = _id("CableId")

# ------------------------------------------------ rb/geometry.h, collision.h

MAX_POLYGON_VERTICES = 8
MAX_MANIFOLD_POINTS = 2
MAX_CABLE_POINTS = 8


class Circle(Structure):
    _fields_ = [("center", Vec2), ("radius", c_double)]


class Polygon(Structure):
    _fields_ = [
        ("vertices", Vec2 * MAX_POLYGON_VERTICES),
        ("normals", Vec2 * MAX_POLYGON_VERTICES),
        ("centroid", Vec2),
        ("count", c_int),
    ]


class Segment(Structure):
    _fields_ = [("point1", Vec2), ("point2", Vec2)]


class ChainSegment(Structure):
    _fields_ = [
        ("segment", Segment),
        ("ghost1", Vec2),
        ("ghost2", Vec2),
        ("has_ghost1", c_bool),
        ("has_ghost2", c_bool),
    ]


class MassData(Structure):
    _fields_ = [("mass", c_double), ("center", Vec2), ("rotational_inertia", c_double)]


class ManifoldPoint(Structure):
    _fields_ = [
        ("point", Vec2),
        ("separation", c_double),
        ("id", c_uint32),
        ("normal_impulse", c_double),
        ("tangent_impulse", c_double),
    ]


class Manifold(Structure):
    _fields_ = [
        ("normal", Vec2),
        ("points", ManifoldPoint * MAX_MANIFOLD_POINTS),
        ("point_count", c_int),
        ("reference_on_b", c_bool),
    ]


# ---------------------------------------------------------------- rb/world.h


class SolverSettings(Structure):
    _fields_ = [
        ("type", c_int),
        ("velocity_iterations", c_int),
        ("position_iterations", c_int),
        ("relax_iterations", c_int),
        ("substeps", c_int),
        ("warm_starting", c_bool),
        ("block_solver", c_bool),
        ("tree_pins", c_bool),
        ("baumgarte", c_double),
        ("linear_slop", c_double),
        ("max_linear_correction", c_double),
        ("restitution_threshold", c_double),
        ("contact_hertz", c_double),
        ("contact_damping_ratio", c_double),
        ("joint_hertz", c_double),
        ("joint_damping_ratio", c_double),
        ("max_push_speed", c_double),
    ]


class WorldDef(Structure):
    _fields_ = [
        ("gravity", Vec2),
        ("solver", SolverSettings),
        ("enable_profile", c_bool),
        ("enable_sleep", c_bool),
        ("internal_value", c_int32),
    ]


PROFILE_FIELDS = (
    "step",
    "pairs",
    "collide",
    "prepare",
    "substep_callback",
    "integrate_velocities",
    "warm_start",
    "solve_velocities",
    "integrate_positions",
    "correct_positions",
    "relax",
    "restitution",
    "store_impulses",
    "islands",
    "sensors",
    "finalize",
)


class Profile(Structure):
    _fields_ = [(name, c_double) for name in PROFILE_FIELDS]


class Statistics(Structure):
    _fields_ = [
        ("body_count", c_int),
        ("awake_body_count", c_int),
        ("island_count", c_int),
        ("shape_count", c_int),
        ("pair_count", c_int),
        ("broad_phase_sweeps", c_int),
        ("broad_phase_requeries", c_int),
        ("broad_phase_moved", c_int),
        ("broad_phase_box_tests", c_int),
        ("broad_phase_boxes", c_int),
        ("broad_phase_new_pairs", c_int),
        ("broad_phase_ended_pairs", c_int),
        ("contact_count", c_int),
        ("manifold_point_count", c_int),
        ("contact_colours", c_int),
        ("velocity_iterations", c_int),
        ("position_iterations", c_int),
        ("relax_iterations", c_int),
        ("max_penetration", c_double),
        ("joint_count", c_int),
        ("max_joint_gap", c_double),
        ("max_joint_angle_error", c_double),
        ("energy", c_double),
    ]


class ContactData(Structure):
    _fields_ = [
        ("shape_a", ShapeId),
        ("shape_b", ShapeId),
        ("body_a", BodyId),
        ("body_b", BodyId),
        ("touching", c_bool),
        ("sensor", c_bool),
        ("manifold", Manifold),
    ]


# --------------------------------------------------------- rb/body.h, shape.h


class BodyDef(Structure):
    _fields_ = [
        ("type", c_int),
        ("position", Vec2),
        ("angle", c_double),
        ("linear_velocity", Vec2),
        ("angular_velocity", c_double),
        ("linear_damping", c_double),
        ("angular_damping", c_double),
        ("gravity_scale", c_double),
        ("fixed_rotation", c_bool),
        ("awake", c_bool),
        ("enable_sleep", c_bool),
        ("bullet", c_bool),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class Filter(Structure):
    _fields_ = [("category_bits", c_uint32), ("mask_bits", c_uint32), ("group_index", c_int32)]


class ShapeDef(Structure):
    _fields_ = [
        ("friction", c_double),
        ("restitution", c_double),
        ("density", c_double),
        ("is_sensor", c_bool),
        ("filter", Filter),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


# ---------------------------------------------------------------- rb/joint.h


class RevoluteJointDef(Structure):
    _fields_ = [
        ("body_a", BodyId),
        ("body_b", BodyId),
        ("local_anchor_a", Vec2),
        ("local_anchor_b", Vec2),
        ("reference_angle", c_double),
        ("enable_lower_limit", c_bool),
        ("enable_upper_limit", c_bool),
        ("lower_angle", c_double),
        ("upper_angle", c_double),
        ("enable_motor", c_bool),
        ("motor_speed", c_double),
        ("max_motor_torque", c_double),
        ("enable_spring", c_bool),
        ("spring_hertz", c_double),
        ("spring_damping_ratio", c_double),
        ("collide_connected", c_bool),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class WeldJointDef(Structure):
    _fields_ = [
        ("body_a", BodyId),
        ("body_b", BodyId),
        ("local_anchor_a", Vec2),
        ("local_anchor_b", Vec2),
        ("reference_angle", c_double),
        ("linear_hertz", c_double),
        ("linear_damping_ratio", c_double),
        ("angular_hertz", c_double),
        ("angular_damping_ratio", c_double),
        ("collide_connected", c_bool),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class DistanceJointDef(Structure):
    _fields_ = [
        ("body_a", BodyId),
        ("body_b", BodyId),
        ("local_anchor_a", Vec2),
        ("local_anchor_b", Vec2),
        ("length", c_double),
        ("enable_spring", c_bool),
        ("spring_hertz", c_double),
        ("spring_damping_ratio", c_double),
        ("enable_limit", c_bool),
        ("min_length", c_double),
        ("max_length", c_double),
        ("collide_connected", c_bool),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class MouseJointDef(Structure):
    _fields_ = [
        ("body", BodyId),
        ("local_anchor", Vec2),
        ("target", Vec2),
        ("max_force", c_double),
        ("hertz", c_double),
        ("damping_ratio", c_double),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class PrismaticJointDef(Structure):
    _fields_ = [
        ("body_a", BodyId),
        ("body_b", BodyId),
        ("local_anchor_a", Vec2),
        ("local_anchor_b", Vec2),
        ("local_axis_a", Vec2),
        ("reference_angle", c_double),
        ("enable_lower_limit", c_bool),
        ("enable_upper_limit", c_bool),
        ("lower_translation", c_double),
        ("upper_translation", c_double),
        ("enable_motor", c_bool),
        ("motor_speed", c_double),
        ("max_motor_force", c_double),
        ("enable_spring", c_bool),
        ("spring_hertz", c_double),
        ("spring_damping_ratio", c_double),
        ("collide_connected", c_bool),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class PulleyJointDef(Structure):
    _fields_ = [
        ("body_a", BodyId),
        ("body_b", BodyId),
        ("ground_anchor_a", Vec2),
        ("ground_anchor_b", Vec2),
        ("local_anchor_a", Vec2),
        ("local_anchor_b", Vec2),
        ("length_a", c_double),
        ("length_b", c_double),
        ("ratio", c_double),
        ("min_length", c_double),
        ("collide_connected", c_bool),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


# ------------------------------------------------------ rb/cable.h, query.h


class CableDef(Structure):
    _fields_ = [
        ("point_count", c_int),
        ("bodies", BodyId * MAX_CABLE_POINTS),
        ("local_points", Vec2 * MAX_CABLE_POINTS),
        ("user_data", c_void_p),
        ("internal_value", c_int32),
    ]


class QueryFilter(Structure):
    _fields_ = [("category_bits", c_uint32), ("mask_bits", c_uint32)]


class RayHit(Structure):
    _fields_ = [("shape", ShapeId), ("body", BodyId), ("point", Vec2), ("normal", Vec2), ("fraction", c_double)]


# --------------------------------------------------------------- rb/events.h


class ContactBeginEvent(Structure):
    _fields_ = [("shape_a", ShapeId), ("shape_b", ShapeId), ("manifold", Manifold)]


class ContactEndEvent(Structure):
    _fields_ = [("shape_a", ShapeId), ("shape_b", ShapeId)]


class ContactEvents(Structure):
    _fields_ = [
        ("begin_events", POINTER(ContactBeginEvent)),
        ("begin_count", c_int),
        ("end_events", POINTER(ContactEndEvent)),
        ("end_count", c_int),
    ]


class SensorEvent(Structure):
    _fields_ = [("sensor_shape", ShapeId), ("visitor_shape", ShapeId)]


class SensorEvents(Structure):
    _fields_ = [
        ("begin_events", POINTER(SensorEvent)),
        ("begin_count", c_int),
        ("end_events", POINTER(SensorEvent)),
        ("end_count", c_int),
    ]


# --------------------------------------------------- mu/model_desc.h (part)


class ModelRef(Structure):
    _fields_ = [("kind", c_int), ("index", c_int)]


class ModelBone(Structure):
    _fields_ = [
        ("name", c_char_p),
        ("centre", Vec2),
        ("size", Vec2),
        ("angle", c_double),
        ("depth", c_double),
        ("is_static", c_bool),
        ("density", c_double),
        ("damping", c_double),
        ("wall_thickness", c_double),
        ("youngs_modulus", c_double),
        ("tensile_strength", c_double),
        ("compressive_strength", c_double),
    ]


class ModelWeight(Structure):
    _fields_ = [
        ("name", c_char_p),
        ("body", ModelRef),
        ("position", Vec2),
        ("mass_count", c_int),
        ("masses", POINTER(c_double)),
    ]


class ModelTorqueMuscle(Structure):
    _fields_ = [
        ("name", c_char_p),
        ("body", ModelRef),
        ("has_reaction_body", c_bool),
        ("reaction_body", ModelRef),
        ("peak_torque", c_double),
        ("pool_source", c_int),
        ("neurons", c_int),
        ("weakest", c_double),
        ("strongest", c_double),
        ("pool_file", c_char_p),
        ("pool_path", c_char_p),
        ("strengths", POINTER(c_double)),
        ("recruited", c_int),
    ]


class ModelGroup(Structure):
    _fields_ = [("name", c_char_p), ("muscle_count", c_int), ("muscles", POINTER(c_int))]


class ModelVariant(Structure):
    _fields_ = [
        ("name", c_char_p),
        ("muscle_count", c_int),
        ("muscles", POINTER(c_int)),
        ("bone_count", c_int),
        ("bones", POINTER(c_int)),
    ]


class ModelDesc(Structure):
    """mu_model_desc: the lists the package reads are typed; the others
    are opaque pointers (their count is all it needs)."""

    _fields_ = [
        ("name", c_char_p),
        ("source", c_char_p),
        ("gravity", Vec2),
        ("frame_rate", c_double),
        ("substeps", c_int),
        ("placement", Vec2),
        ("damping", c_double),
        ("nail_count", c_int),
        ("nails", c_void_p),
        ("bone_count", c_int),
        ("bones", POINTER(ModelBone)),
        ("hinge_count", c_int),
        ("hinges", c_void_p),
        ("glue_count", c_int),
        ("glues", c_void_p),
        ("has_weight", c_bool),
        ("weight", ModelWeight),
        ("muscle_count", c_int),
        ("muscles", c_void_p),
        ("group_count", c_int),
        ("groups", POINTER(ModelGroup)),
        ("torque_muscle_count", c_int),
        ("torque_muscles", POINTER(ModelTorqueMuscle)),
        ("variant_count", c_int),
        ("variants", POINTER(ModelVariant)),
        ("object_names", c_void_p),
        ("variant_names", c_void_p),
    ]


# ---------------------------------------------------------- mu/model.h etc.


class ModelOptions(Structure):
    _fields_ = [("level", c_int), ("variant", c_int), ("weight_index", c_int), ("weld_glues", c_bool)]


READOUT_FIELDS = (
    "activation",
    "target_tension",
    "length",
    "normalized_length",
    "velocity",
    "normalized_velocity",
    "contraction",
    "normalized_contraction",
    "active_force",
    "passive_force",
    "total_force",
    "excitation",
    "fibre_length",
    "tendon_length",
    "pennation_angle",
    "calcium",
)


class MuscleReadout(Structure):
    _fields_ = [(name, c_double) for name in READOUT_FIELDS]


class ModelEnergy(Structure):
    _fields_ = [
        ("mechanical", c_double),
        ("at_start", c_double),
        ("muscle_work", c_double),
        ("muscle_work_gross", c_double),
        ("created", c_double),
    ]


class JointLoad(Structure):
    _fields_ = [
        ("force", Vec2),
        ("along", c_double),
        ("across", c_double),
        ("torque", c_double),
        ("muscle_torque", c_double),
    ]


class StaticOptimizationSettings(Structure):
    _fields_ = [
        ("exponent", c_double),
        ("reserve_scale", c_double),
        ("tolerance", c_double),
        ("max_evaluations", c_int),
    ]


class StaticFrame(Structure):
    _fields_ = [
        ("activations", POINTER(c_double)),
        ("forces", POINTER(c_double)),
        ("net_torques", POINTER(c_double)),
        ("actuator_torques", POINTER(c_double)),
        ("reserves", POINTER(c_double)),
        ("loads", POINTER(JointLoad)),
        ("solver_result", c_int),
        ("solved", c_bool),
    ]


class BoneBeam(Structure):
    _fields_ = [
        ("length", c_double),
        ("outer_diameter", c_double),
        ("wall_thickness", c_double),
        ("area", c_double),
        ("second_moment", c_double),
        ("youngs_modulus", c_double),
        ("tensile_strength", c_double),
        ("compressive_strength", c_double),
    ]


class BoneSection(Structure):
    _fields_ = [
        ("s", c_double),
        ("axial_force", c_double),
        ("shear_force", c_double),
        ("bending_moment", c_double),
        ("stress", c_double),
        ("safety_factor", c_double),
    ]


class BoneStress(Structure):
    _fields_ = [("worst", BoneSection), ("strain", c_double)]


# ------------------------------------------------------------ the functions

W = c_void_p  # rb_world *
M = c_void_p  # mu_model *
D = c_void_p  # mu_model_desc * (opaque; read through ModelDesc)
S = c_int  # rb_status
P = c_void_p  # const mu_motor_pool *, const mu_torque_actuator *

PRE_SOLVE_FN = ctypes.CFUNCTYPE(c_bool, ShapeId, ShapeId, POINTER(Manifold), c_void_p)
SUBSTEP_FN = ctypes.CFUNCTYPE(None, c_void_p, c_int, c_double, c_void_p)

# name: (result type, argument types)
RB_FUNCTIONS = {
    # base.h, version.h
    "rb_status_name": (c_char_p, [c_int]),
    "rb_last_error": (c_char_p, []),
    "rb_last_status": (c_int, []),
    "rb_report_error": (c_int, [c_int, c_char_p]),
    "rb_bytes_in_use": (c_size_t, []),
    "rb_allocation_count": (c_uint64, []),
    "rb_version": (c_char_p, []),
    # geometry.h
    "rb_make_box": (S, [c_double, c_double, POINTER(Polygon)]),
    "rb_make_offset_box": (S, [c_double, c_double, Vec2, c_double, POINTER(Polygon)]),
    "rb_make_polygon": (S, [POINTER(Vec2), c_int, POINTER(Polygon)]),
    "rb_make_polygon_hull": (S, [POINTER(Vec2), c_int, POINTER(Polygon)]),
    "rb_circle_mass": (MassData, [POINTER(Circle), c_double]),
    "rb_polygon_mass": (MassData, [POINTER(Polygon), c_double]),
    "rb_circle_area": (c_double, [POINTER(Circle)]),
    "rb_polygon_area": (c_double, [POINTER(Polygon)]),
    "rb_area_density_from_volume": (S, [c_double, c_double, POINTER(c_double)]),
    # world.h
    "rb_solver_type_name": (c_char_p, [c_int]),
    "rb_solver_type_from_name": (S, [c_char_p, POINTER(c_int)]),
    "rb_default_solver_settings": (SolverSettings, []),
    "rb_default_world_def": (WorldDef, []),
    "rb_world_create": (S, [POINTER(WorldDef), POINTER(c_void_p)]),
    "rb_world_destroy": (None, [W]),
    "rb_world_step": (S, [W, c_double]),
    "rb_world_set_gravity": (S, [W, Vec2]),
    "rb_world_gravity": (Vec2, [W]),
    "rb_world_set_solver_settings": (S, [W, POINTER(SolverSettings)]),
    "rb_world_solver_settings": (SolverSettings, [W]),
    "rb_world_set_substep_callback": (S, [W, SUBSTEP_FN, c_void_p]),
    "rb_world_profile": (Profile, [W]),
    "rb_world_enable_profile": (S, [W, c_bool]),
    "rb_world_statistics": (Statistics, [W]),
    "rb_world_enable_sleep": (S, [W, c_bool]),
    "rb_world_is_sleep_enabled": (c_bool, [W]),
    "rb_world_bytes_in_use": (c_size_t, [W]),
    "rb_world_state_hash": (c_uint64, [W]),
    "rb_world_contact_count": (c_int, [W]),
    "rb_world_contacts": (c_int, [W, POINTER(ContactData), c_int]),
    # body.h
    "rb_default_body_def": (BodyDef, []),
    "rb_body_create": (S, [W, POINTER(BodyDef), POINTER(BodyId)]),
    "rb_body_destroy": (S, [W, BodyId]),
    "rb_body_is_valid": (c_bool, [W, BodyId]),
    "rb_body_type_of": (c_int, [W, BodyId]),
    "rb_body_set_type": (S, [W, BodyId, c_int]),
    "rb_body_position": (Vec2, [W, BodyId]),
    "rb_body_angle": (c_double, [W, BodyId]),
    "rb_body_rotation": (Rot, [W, BodyId]),
    "rb_body_transform": (Transform, [W, BodyId]),
    "rb_body_world_center": (Vec2, [W, BodyId]),
    "rb_body_local_center": (Vec2, [W, BodyId]),
    "rb_body_set_transform": (S, [W, BodyId, Vec2, c_double]),
    "rb_body_linear_velocity": (Vec2, [W, BodyId]),
    "rb_body_angular_velocity": (c_double, [W, BodyId]),
    "rb_body_set_linear_velocity": (S, [W, BodyId, Vec2]),
    "rb_body_set_angular_velocity": (S, [W, BodyId, c_double]),
    "rb_body_point_velocity": (Vec2, [W, BodyId, Vec2]),
    "rb_body_world_point": (Vec2, [W, BodyId, Vec2]),
    "rb_body_local_point": (Vec2, [W, BodyId, Vec2]),
    "rb_body_world_vector": (Vec2, [W, BodyId, Vec2]),
    "rb_body_local_vector": (Vec2, [W, BodyId, Vec2]),
    "rb_body_apply_force": (S, [W, BodyId, Vec2, Vec2]),
    "rb_body_apply_force_to_center": (S, [W, BodyId, Vec2]),
    "rb_body_apply_torque": (S, [W, BodyId, c_double]),
    "rb_body_apply_linear_impulse": (S, [W, BodyId, Vec2, Vec2]),
    "rb_body_apply_linear_impulse_to_center": (S, [W, BodyId, Vec2]),
    "rb_body_apply_angular_impulse": (S, [W, BodyId, c_double]),
    "rb_body_force": (Vec2, [W, BodyId]),
    "rb_body_torque": (c_double, [W, BodyId]),
    "rb_body_mass": (c_double, [W, BodyId]),
    "rb_body_rotational_inertia": (c_double, [W, BodyId]),
    "rb_body_mass_data": (MassData, [W, BodyId]),
    "rb_body_set_mass_data": (S, [W, BodyId, POINTER(MassData)]),
    "rb_body_reset_mass_data": (S, [W, BodyId]),
    "rb_body_set_linear_damping": (S, [W, BodyId, c_double]),
    "rb_body_set_angular_damping": (S, [W, BodyId, c_double]),
    "rb_body_linear_damping": (c_double, [W, BodyId]),
    "rb_body_angular_damping": (c_double, [W, BodyId]),
    "rb_body_set_gravity_scale": (S, [W, BodyId, c_double]),
    "rb_body_gravity_scale": (c_double, [W, BodyId]),
    "rb_body_set_fixed_rotation": (S, [W, BodyId, c_bool]),
    "rb_body_is_fixed_rotation": (c_bool, [W, BodyId]),
    "rb_body_set_awake": (S, [W, BodyId, c_bool]),
    "rb_body_enable_sleep": (S, [W, BodyId, c_bool]),
    "rb_body_is_sleep_enabled": (c_bool, [W, BodyId]),
    "rb_body_is_awake": (c_bool, [W, BodyId]),
    "rb_body_set_bullet": (S, [W, BodyId, c_bool]),
    "rb_body_is_bullet": (c_bool, [W, BodyId]),
    "rb_body_shape_count": (c_int, [W, BodyId]),
    "rb_body_shapes": (c_int, [W, BodyId, POINTER(ShapeId), c_int]),
    # shape.h
    "rb_default_filter": (Filter, []),
    "rb_default_shape_def": (ShapeDef, []),
    "rb_shape_create_circle": (S, [W, BodyId, POINTER(ShapeDef), POINTER(Circle), POINTER(ShapeId)]),
    "rb_shape_create_polygon": (S, [W, BodyId, POINTER(ShapeDef), POINTER(Polygon), POINTER(ShapeId)]),
    "rb_shape_create_segment": (S, [W, BodyId, POINTER(ShapeDef), POINTER(Segment), POINTER(ShapeId)]),
    "rb_shape_create_chain": (
        S,
        [W, BodyId, POINTER(ShapeDef), POINTER(Vec2), c_int, c_bool, POINTER(ShapeId), c_int],
    ),
    "rb_shape_destroy": (S, [W, ShapeId]),
    "rb_shape_is_valid": (c_bool, [W, ShapeId]),
    "rb_shape_type_of": (c_int, [W, ShapeId]),
    "rb_shape_body": (BodyId, [W, ShapeId]),
    "rb_shape_circle": (Circle, [W, ShapeId]),
    "rb_shape_polygon": (Polygon, [W, ShapeId]),
    "rb_shape_segment": (Segment, [W, ShapeId]),
    "rb_shape_chain_segment": (ChainSegment, [W, ShapeId]),
    "rb_shape_aabb": (AABB, [W, ShapeId]),
    "rb_shape_set_friction": (S, [W, ShapeId, c_double]),
    "rb_shape_friction": (c_double, [W, ShapeId]),
    "rb_shape_set_restitution": (S, [W, ShapeId, c_double]),
    "rb_shape_restitution": (c_double, [W, ShapeId]),
    "rb_shape_set_density": (S, [W, ShapeId, c_double]),
    "rb_shape_density": (c_double, [W, ShapeId]),
    "rb_shape_is_sensor": (c_bool, [W, ShapeId]),
    "rb_shape_set_filter": (S, [W, ShapeId, Filter]),
    "rb_shape_filter": (Filter, [W, ShapeId]),
    "rb_shape_sensor_overlaps": (c_int, [W, ShapeId, POINTER(ShapeId), c_int]),
    # joint.h
    "rb_default_revolute_joint_def": (RevoluteJointDef, []),
    "rb_revolute_joint_def_at": (S, [POINTER(RevoluteJointDef), W, BodyId, BodyId, Vec2]),
    "rb_revolute_joint_create": (S, [W, POINTER(RevoluteJointDef), POINTER(JointId)]),
    "rb_revolute_joint_angle": (c_double, [W, JointId]),
    "rb_revolute_joint_speed": (c_double, [W, JointId]),
    "rb_revolute_joint_motor_torque": (c_double, [W, JointId]),
    "rb_revolute_joint_set_motor": (S, [W, JointId, c_bool, c_double, c_double]),
    "rb_revolute_joint_set_limits": (S, [W, JointId, c_bool, c_double, c_bool, c_double]),
    "rb_revolute_joint_set_spring": (S, [W, JointId, c_bool, c_double, c_double]),
    "rb_default_weld_joint_def": (WeldJointDef, []),
    "rb_weld_joint_def_at": (S, [POINTER(WeldJointDef), W, BodyId, BodyId, Vec2]),
    "rb_weld_joint_create": (S, [W, POINTER(WeldJointDef), POINTER(JointId)]),
    "rb_default_distance_joint_def": (DistanceJointDef, []),
    "rb_distance_joint_def_between": (S, [POINTER(DistanceJointDef), W, BodyId, BodyId, Vec2, Vec2]),
    "rb_distance_joint_create": (S, [W, POINTER(DistanceJointDef), POINTER(JointId)]),
    "rb_distance_joint_current_length": (c_double, [W, JointId]),
    "rb_default_mouse_joint_def": (MouseJointDef, []),
    "rb_mouse_joint_create": (S, [W, POINTER(MouseJointDef), POINTER(JointId)]),
    "rb_mouse_joint_set_target": (S, [W, JointId, Vec2]),
    "rb_default_prismatic_joint_def": (PrismaticJointDef, []),
    "rb_prismatic_joint_def_at": (S, [POINTER(PrismaticJointDef), W, BodyId, BodyId, Vec2, Vec2]),
    "rb_prismatic_joint_create": (S, [W, POINTER(PrismaticJointDef), POINTER(JointId)]),
    "rb_prismatic_joint_translation": (c_double, [W, JointId]),
    "rb_prismatic_joint_speed": (c_double, [W, JointId]),
    "rb_prismatic_joint_motor_force": (c_double, [W, JointId]),
    "rb_prismatic_joint_set_motor": (S, [W, JointId, c_bool, c_double, c_double]),
    "rb_prismatic_joint_set_limits": (S, [W, JointId, c_bool, c_double, c_bool, c_double]),
    "rb_prismatic_joint_set_spring": (S, [W, JointId, c_bool, c_double, c_double]),
    "rb_default_pulley_joint_def": (PulleyJointDef, []),
    "rb_pulley_joint_def_between": (S, [POINTER(PulleyJointDef), W, BodyId, BodyId, Vec2, Vec2, Vec2, Vec2]),
    "rb_pulley_joint_create": (S, [W, POINTER(PulleyJointDef), POINTER(JointId)]),
    "rb_pulley_joint_length_a": (c_double, [W, JointId]),
    "rb_pulley_joint_length_b": (c_double, [W, JointId]),
    "rb_joint_destroy": (S, [W, JointId]),
    "rb_joint_is_valid": (c_bool, [W, JointId]),
    "rb_joint_type_of": (c_int, [W, JointId]),
    "rb_joint_body_a": (BodyId, [W, JointId]),
    "rb_joint_body_b": (BodyId, [W, JointId]),
    "rb_joint_world_anchor_a": (Vec2, [W, JointId]),
    "rb_joint_world_anchor_b": (Vec2, [W, JointId]),
    "rb_joint_reaction_force": (Vec2, [W, JointId]),
    "rb_joint_reaction_torque": (c_double, [W, JointId]),
    # cable.h
    "rb_default_cable_def": (CableDef, []),
    "rb_cable_create": (S, [W, POINTER(CableDef), POINTER(CableId)]),
    "rb_cable_destroy": (S, [W, CableId]),
    "rb_cable_is_valid": (c_bool, [W, CableId]),
    "rb_cable_set_tension_law": (S, [W, CableId, c_double, c_double]),
    "rb_cable_state": (S, [W, CableId, POINTER(c_double), POINTER(c_double)]),
    "rb_cable_tension": (c_double, [W, CableId]),
    "rb_cable_points": (c_int, [W, CableId, POINTER(Vec2), c_int]),
    # query.h, events.h
    "rb_default_query_filter": (QueryFilter, []),
    "rb_world_overlap_aabb": (S, [W, AABB, QueryFilter, c_bool, POINTER(ShapeId), c_int, POINTER(c_int)]),
    "rb_world_overlap_point": (S, [W, Vec2, QueryFilter, c_bool, POINTER(ShapeId), c_int, POINTER(c_int)]),
    "rb_world_ray_cast_closest": (S, [W, Vec2, Vec2, QueryFilter, c_bool, POINTER(RayHit), POINTER(c_bool)]),
    "rb_world_ray_cast_all": (S, [W, Vec2, Vec2, QueryFilter, c_bool, POINTER(RayHit), c_int, POINTER(c_int)]),
    "rb_world_contact_events": (ContactEvents, [W]),
    "rb_world_sensor_events": (SensorEvents, [W]),
    "rb_world_set_pre_solve": (S, [W, PRE_SOLVE_FN, c_void_p]),
}

MU_FUNCTIONS = {
    "mu_version": (c_char_p, []),
    # model_desc.h
    "mu_model_desc_load": (S, [c_char_p, POINTER(c_void_p)]),
    "mu_model_desc_load_builtin": (S, [c_char_p, POINTER(c_void_p)]),
    "mu_builtin_model_count": (c_int, []),
    "mu_builtin_model_name": (c_char_p, [c_int]),
    "mu_model_desc_destroy": (None, [D]),
    "mu_model_desc_find_variant": (c_int, [D, c_char_p]),
    "mu_model_desc_find": (c_bool, [D, c_char_p, POINTER(ModelRef)]),
    "mu_model_desc_name_of": (c_char_p, [D, ModelRef]),
    # model.h
    "mu_default_model_options": (ModelOptions, []),
    "mu_model_create": (S, [D, POINTER(ModelOptions), POINTER(c_void_p)]),
    "mu_model_destroy": (None, [M]),
    "mu_model_world": (W, [M]),
    "mu_model_step": (S, [M]),
    "mu_model_substep": (S, [M]),
    "mu_model_time": (c_double, [M]),
    "mu_model_frame_duration": (c_double, [M]),
    "mu_model_substep_duration": (c_double, [M]),
    "mu_model_set_activation": (S, [M, c_char_p, c_double]),
    "mu_model_set_tension": (S, [M, c_char_p, c_double]),
    "mu_model_set_activation_at": (S, [M, c_int, c_double]),
    "mu_model_set_tension_at": (S, [M, c_int, c_double]),
    "mu_model_group_activation": (c_double, [M, c_char_p]),
    "mu_model_set_gravity": (S, [M, Vec2]),
    "mu_model_muscle_count": (c_int, [M]),
    "mu_model_muscle_name": (c_char_p, [M, c_int]),
    "mu_model_muscle_readout": (MuscleReadout, [M, c_int]),
    "mu_model_warnings": (c_char_p, [M]),
    "mu_model_failure": (c_char_p, [M]),
    "mu_model_energy_account": (ModelEnergy, [M]),
    "mu_model_hinge_count": (c_int, [M]),
    "mu_model_hinge_name": (c_char_p, [M, c_int]),
    "mu_model_hinge_angle": (c_double, [M, c_int]),
    "mu_model_part_count": (c_int, [M]),
    "mu_model_part_name": (c_char_p, [M, c_int]),
    "mu_model_part_centre": (Vec2, [M, c_int]),
    "mu_model_part_angle": (c_double, [M, c_int]),
    "mu_model_torque_muscle_count": (c_int, [M]),
    "mu_model_torque_muscle_name": (c_char_p, [M, c_int]),
    "mu_model_recruit": (S, [M, c_char_p, c_int]),
    "mu_model_recruit_at": (S, [M, c_int, c_int]),
    "mu_model_motor_pool": (P, [M, c_int]),
    "mu_model_torque_actuator": (P, [M, c_int]),
    "mu_model_body_count": (c_int, [M]),
    "mu_model_joint_count": (c_int, [M]),
    "mu_model_hinge_joint": (JointId, [M, c_int]),
    "mu_model_glue_count": (c_int, [M]),
    "mu_model_glue_name": (c_char_p, [M, c_int]),
    "mu_model_glue_joint": (JointId, [M, c_int]),
    "mu_model_weight_joint": (JointId, [M]),
    "mu_model_weight_mass": (c_double, [M]),
    "mu_model_body": (BodyId, [M, c_int]),
    "mu_model_part_body": (c_int, [M, c_int]),
    "mu_model_muscle_description_index": (c_int, [M, c_int]),
    # motor_pool.h, torque_actuator.h
    "mu_motor_pool_neuron_count": (c_int, [P]),
    "mu_motor_pool_recruited": (c_int, [P]),
    "mu_motor_pool_exertion": (c_double, [P]),
    "mu_torque_actuator_torque": (c_double, [P]),
    "mu_torque_actuator_peak_torque": (c_double, [P]),
    # joint_loads.h, moment_arms.h, bone_stress.h, inverse_dynamics.h
    "mu_model_hinge_load": (JointLoad, [M, c_int]),
    "mu_model_glue_load": (JointLoad, [M, c_int]),
    "mu_model_hinge_bone_axis": (Vec2, [M, c_int]),
    "mu_model_muscle_crosses": (c_bool, [M, c_int, c_int]),
    "mu_model_moment_arm": (c_double, [M, c_int, c_int]),
    "mu_model_moment_arms": (S, [M, c_int, POINTER(c_double)]),
    "mu_model_muscle_torque": (c_double, [M, c_int, c_int]),
    "mu_model_hinge_muscle_torque": (c_double, [M, c_int]),
    "mu_model_pose_hinge": (S, [M, c_int, c_double]),
    "mu_model_bone_beam": (BoneBeam, [M, c_int]),
    "mu_model_bone_stress": (BoneStress, [M, c_int]),
    "mu_model_bone_stresses": (S, [M, POINTER(BoneStress)]),
    "mu_model_bone_section": (BoneSection, [M, c_int, c_double, c_bool]),
    "mu_model_bone_sections": (S, [M, c_int, c_int, POINTER(BoneSection)]),
    "mu_model_check_tree": (S, [M]),
    "mu_model_inverse_dynamics": (
        S,
        [M, POINTER(c_double), POINTER(c_double), POINTER(c_double), POINTER(c_double)],
    ),
    # static_optimization.h
    "mu_default_static_optimization_settings": (StaticOptimizationSettings, []),
    "mu_static_optimizer_create": (S, [M, POINTER(StaticOptimizationSettings), POINTER(c_void_p)]),
    "mu_static_optimizer_destroy": (None, [c_void_p]),
    "mu_static_optimizer_actuator_count": (c_int, [c_void_p]),
    "mu_static_optimizer_solve": (
        S,
        [c_void_p, POINTER(c_double), POINTER(c_double), POINTER(c_double), POINTER(StaticFrame)],
    ),
    "mu_static_optimizer_result_name": (c_char_p, [c_int]),
}


def declare(rb, mu):
    """Gives every function its result and argument types."""
    for library, table in ((rb, RB_FUNCTIONS), (mu, MU_FUNCTIONS)):
        for name, (restype, argtypes) in table.items():
            function = getattr(library, name)
            function.restype = restype
            function.argtypes = argtypes
