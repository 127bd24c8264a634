/* Shape geometry and its mass properties.
 *
 * Geometry is given in the body's local frame (metres). Boxes are
 * polygons. A polygon is convex, counter-clockwise, with 3 to
 * RB_MAX_POLYGON_VERTICES vertices and outward unit edge normals.
 */
#ifndef RB_GEOMETRY_H
#define RB_GEOMETRY_H

#include "rb/base.h"
#include "rb/math.h"

#define RB_MAX_POLYGON_VERTICES 8

/* Points closer than this are one point to the hull and polygon
 * builders, and a hull vertex closer than this to the line through its
 * neighbours is dropped as collinear (m). */
#define RB_POLYGON_WELD_DISTANCE 0.5e-3

typedef enum rb_shape_type {
    RB_SHAPE_CIRCLE,
    RB_SHAPE_POLYGON,
} rb_shape_type;

typedef struct rb_circle {
    rb_vec2 center; /* m, offset from the body origin */
    double radius;  /* m, > 0 */
} rb_circle;

typedef struct rb_polygon {
    rb_vec2 vertices[RB_MAX_POLYGON_VERTICES]; /* m, counter-clockwise */
    rb_vec2 normals[RB_MAX_POLYGON_VERTICES];  /* unit, normals[i] is outward normal of edge i -> i+1 */
    rb_vec2 centroid;                          /* m, area centroid */
    int count;                                 /* 3 .. RB_MAX_POLYGON_VERTICES */
} rb_polygon;

/* Mass properties of a shape or a body. */
typedef struct rb_mass_data {
    double mass;               /* kg, >= 0 */
    rb_vec2 center;            /* m, centre of mass in the body frame */
    double rotational_inertia; /* kg·m², about the centre of mass, >= 0 */
} rb_mass_data;

/* A box of half-extents hx, hy (m, > 0) centred on the body origin. */
rb_status rb_make_box(double hx, double hy, rb_polygon *out);

/* A box of half-extents hx, hy centred at `center` and turned by `angle`
 * (rad) in the body frame. */
rb_status rb_make_offset_box(double hx, double hy, rb_vec2 center, double angle, rb_polygon *out);

/* A convex polygon whose vertices are exactly `points` (any order, any
 * winding). Fails with RB_ERR_NOT_CONVEX when a point lies inside the
 * hull of the others or on one of its edges, RB_ERR_DEGENERATE_SHAPE when
 * the points are collinear, coincident or enclose no area, and
 * RB_ERR_INVALID_ARGUMENT for a count outside 3..8 or a non-finite point. */
rb_status rb_make_polygon(const rb_vec2 *points, int count, rb_polygon *out);

/* The convex hull of a point cloud as a polygon: interior and collinear
 * points are dropped, coincident points welded. Fails only when the hull
 * is degenerate (fewer than 3 vertices) or the input invalid. */
rb_status rb_make_polygon_hull(const rb_vec2 *points, int count, rb_polygon *out);

/* Mass properties for an area density (kg/m², > 0). */
rb_mass_data rb_circle_mass(const rb_circle *circle, double density);
rb_mass_data rb_polygon_mass(const rb_polygon *polygon, double density);

/* Area (m²) of a shape. */
double rb_circle_area(const rb_circle *circle);
double rb_polygon_area(const rb_polygon *polygon);

/* The area density (kg/m²) of a plate of thickness `depth` (m, > 0) made
 * of a material of volume density `volume_density` (kg/m³, > 0), so that
 * mass = volume_density · area · depth, as the seed's bones and weights. */
rb_status rb_area_density_from_volume(double volume_density, double depth, double *area_density);

/* Bounding boxes of a shape placed by a transform. */
rb_aabb rb_circle_aabb(const rb_circle *circle, rb_transform xf);
rb_aabb rb_polygon_aabb(const rb_polygon *polygon, rb_transform xf);

#endif
