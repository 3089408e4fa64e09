// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_input.h -- what the fuzz targets share: reading numbers and choices
// from the input bytes (past the end every read gives 0), handlers that record
// instead of aborting, and the checks every contact must pass.

#ifndef FUZZ_INPUT_H
#define FUZZ_INPUT_H

#include <ode/ode.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct fz_input {
    const uint8_t *p;
    size_t left;
    int specials;   // how many of fz_real's special values were handed out
} fz_input;

static inline uint8_t fz_u8(fz_input *in)
{
    if (in->left == 0) return 0;
    in->left--;
    return *in->p++;
}

static inline unsigned fz_u16(fz_input *in)
{
    unsigned lo = fz_u8(in);
    return lo | (unsigned)fz_u8(in) << 8;
}

// One of n choices (n >= 1).
static inline unsigned fz_pick(fz_input *in, unsigned n) { return fz_u8(in) % n; }

// A number for a size, a coordinate or a parameter: mostly in [-scale, scale],
// sometimes one of the values that break careless code (zero, signed zero, a
// denormal, huge, infinite, NaN).
static inline dReal fz_real(fz_input *in, dReal scale)
{
    uint8_t kind = fz_u8(in);
    if (kind < 200) return (dReal)(((double)fz_u16(in) / 32767.5 - 1.0) * scale);
    in->specials++;
    switch (kind % 8) {
    case 0: return 0;
    case 1: return -(dReal)0.0;
    case 2: return (dReal)1e-30;
    case 3: return (dReal)1e6;
    case 4: return (dReal)-1e6;
    case 5: return (dReal)INFINITY;
    case 6: return (dReal)NAN;
    default: return (dReal)1e-6;
    }
}

// Uniform in [lo, hi], never special.
static inline dReal fz_range(fz_input *in, dReal lo, dReal hi)
{
    return lo + (hi - lo) * (dReal)((double)fz_u16(in) / 65535.0);
}

// Positive in (0, scale], the specials as above (including non-positive ones).
static inline dReal fz_size(fz_input *in, dReal scale)
{
    dReal v = fz_real(in, scale);
    return isfinite(v) && v != 0 ? (dReal)fabs((double)v) : v;
}

static inline void fz_vec3(fz_input *in, dReal scale, dReal *v)
{
    for (int i = 0; i < 3; i++) v[i] = fz_real(in, scale);
}

// A rotation: usually a normalised random quaternion, sometimes the raw
// (possibly zero or non-finite) one.
static inline void fz_rotation(fz_input *in, dMatrix3 R)
{
    dQuaternion q;
    for (int i = 0; i < 4; i++) q[i] = fz_real(in, 1);
    if (fz_u8(in) < 240) {
        dReal n = (dReal)sqrt((double)(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]));
        if (isfinite(n) && n > (dReal)1e-3) {
            for (int i = 0; i < 4; i++) q[i] /= n;
        } else {
            q[0] = 1;
            q[1] = q[2] = q[3] = 0;
        }
    }
    dRfromQ(R, q);
}

// The recording handlers: errors reported through any of them are counted, the
// last message kept for a failing target to print.
extern int fz_errors;
extern int fz_messages;
void fz_install_handlers(void);
// A property broken: print it and abort (the fuzzer keeps the input).
void fz_fail(const char *fmt, ...);

// 1 if a hull's data describes a closed convex polyhedron: at least 4 planes,
// unit normals, every point on or behind every plane and every face's points
// on its plane (within rounding). Colliders may give any contacts for a hull
// that is not: only the count and g1/g2 are then checked (fz_lenient).
int fz_hull_consistent(const dReal *planes, unsigned planecount, const dReal *points,
                       unsigned pointcount, const unsigned *polygons);
extern int fz_lenient;

// Check n contacts of dCollide(o1, o2, flags, c, skip): at most the count
// asked for, finite positions, unit normals, non-negative finite depths, and
// g1/g2 naming the pair (a transform whose info is 0 names its geom).
void fz_check_contacts(dGeomID o1, dGeomID o2, int flags, const dContactGeom *c,
                       int skip, int n);

#endif
