// SPDX-License-Identifier: BSD-3-Clause
//
// odecontactdiff.h -- the pieces of the odecontactdiff command: shapes and
// poses (shapes.c), measuring each backend against the ground truth
// (measure.c) and writing the table, CSV and SVG plot (report.c).

#ifndef ODECONTACTDIFF_H
#define ODECONTACTDIFF_H

#include <ode/ode.h>
#include <stdint.h>

#include "contact_truth.h"
#include <stdio.h>

// The contract's tolerances (issue 14; the same as shadow mode's).
#define CD_DEPTH_ABS 0.005   // depth and separation: 5 mm ...
#define CD_DEPTH_REL 0.05    // ... + 5 % of the true depth
#define CD_POINT_ABS 0.01    // a contact point outside a shape: 1 cm ...
#define CD_POINT_REL 0.1     // ... + 10 % of its depth
#define CD_BAND 0.02         // random poses: at least this far from touching ...
#define CD_BAND_REL 0.05     // ... or this fraction of the bounding radii, if less
#define CD_MAX_CONTACTS 16   // contacts asked of each backend

// A shape: class and parameters (sphere r; box lx ly lz; capsule and
// cylinder r, length; plane a b c d).
typedef struct cd_shape {
    int cls;
    double p[4];
} cd_shape;

// A geom of a scene: its shape and pose (ignored for a plane).
typedef struct cd_geom {
    cd_shape shape;
    double pos[3], q[4];   // q: w x y z
} cd_geom;

// Parse "box:1,0.6,0.4" (sizes optional: defaults); returns 1 or 0 with a
// message in err.
int cd_parse_shape(const char *text, cd_shape *out, char *err, size_t size);
// Parse a scene file (see --help); returns the geom count, or -1 with err.
int cd_read_scene(const char *path, cd_geom **out, char *err, size_t size);
const char *cd_class_name(int cls);
// A geom of that shape (space 0), posed.
dGeomID cd_make_geom(const cd_geom *g);
// The radius of a sphere around the shape's centre holding it (0 for a plane).
double cd_bounding_radius(const cd_shape *s);

// Deterministic random numbers (splitmix64).
typedef struct cd_rng {
    uint64_t state;
} cd_rng;
double cd_uniform(cd_rng *r);   // [0, 1)
// Pose g1 at the origin and g2 at random (both turned at random; a plane
// stays as given, the other geom is placed at a random height over it).
void cd_random_pose(cd_rng *r, dGeomID g1, dGeomID g2);

// What one backend (or the truth) gave for one pair class.
typedef struct cd_row {
    char backend[32], pair[40];
    int poses, answered, overlapping;
    int contact_fail, depth_fail, sep_fail, point_fail;
    double worst_depth, worst_sep, worst_normal, worst_point;
    int nsamples, capacity;   // (true depth, depth error) of overlapping answered poses
    double *samples;
} cd_row;

typedef struct cd_results {
    int count, capacity;
    cd_row *rows;
} cd_results;

// Measure one posed pair whose truth is t: the truth row and each
// backend's row for its pair class are updated.
void cd_measure(cd_results *res, const char *const *backends, dGeomID g1, dGeomID g2,
                const contact_truth *t);
// The band of poses too close to touching to be judged, for two shapes.
double cd_grazing_band(const cd_shape *a, const cd_shape *b);
// 1 if the row passes the contract (answered something, no failure).
int cd_row_passes(const cd_row *row);
void cd_free_results(cd_results *res);

void cd_print_table(FILE *f, const cd_results *res);
void cd_print_csv(FILE *f, const cd_results *res);
int cd_write_svg(const char *path, const cd_results *res);

#endif
