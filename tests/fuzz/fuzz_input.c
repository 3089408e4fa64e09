// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_input.c -- the recording handlers and the contact checks of fuzz_input.h.

#include "fuzz_input.h"

#include <stdarg.h>
#include <stdio.h>

int fz_errors;
int fz_messages;
static char last_message[256];

// Error and debug handler: count and keep the text; return, so the library
// must carry on safely (its checks promise the call then does nothing).
static void record_error(int num, const char *msg, va_list ap)
{
    (void)num;
    fz_errors++;
    vsnprintf(last_message, sizeof last_message, msg, ap);
}

static void record_message(int num, const char *msg, va_list ap)
{
    (void)num;
    fz_messages++;
    vsnprintf(last_message, sizeof last_message, msg, ap);
}

void fz_install_handlers(void)
{
    dSetErrorHandler(record_error);
    dSetDebugHandler(record_error);
    dSetMessageHandler(record_message);
}

void fz_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("fuzz property broken: ", stderr);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n(last reported: %s)\n", last_message);
    abort();
}

// The geom a contact names for o: o itself, or the geom a transform holds
// when the transform's info is 0 (guide: the encapsulated geom is reported).
static dGeomID named(dGeomID o)
{
    if (dGeomGetClass(o) == dGeomTransformClass && dGeomTransformGetInfo(o) == 0 &&
        dGeomTransformGetGeom(o))
        return dGeomTransformGetGeom(o);
    return o;
}

int fz_lenient;

// How far p is outside plane n (n[3] the offset), over the size of the numbers.
static double plane_excess(const dReal *n, const dReal *p)
{
    double out = (double)(n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) - (double)n[3];
    return out / (1 + fabs((double)n[3]) + fabs((double)p[0]) + fabs((double)p[1]) +
                  fabs((double)p[2]));
}

int fz_hull_consistent(const dReal *planes, unsigned planecount, const dReal *points,
                       unsigned pointcount, const unsigned *polygons)
{
#ifdef dSINGLE
    const double tol = 1e-3;
#else
    const double tol = 1e-7;
#endif
    if (planecount < 4) return 0;
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++) {
        const dReal *n = planes + 4 * f;
        double len = sqrt((double)(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
        if (!(fabs(len - 1) <= tol)) return 0;
        for (unsigned i = 0; i < pointcount; i++)
            if (!(plane_excess(n, points + 3 * i) <= tol)) return 0;
        unsigned count = *poly++;
        for (unsigned k = 0; k < count; k++, poly++)
            if (*poly >= pointcount || !(fabs(plane_excess(n, points + 3 * *poly)) <= tol))
                return 0;
    }
    return 1;
}

void fz_check_contacts(dGeomID o1, dGeomID o2, int flags, const dContactGeom *c,
                       int skip, int n)
{
    int asked = flags & 0xffff;
    if (n < 0 || n > asked)
        fz_fail("classes %d, %d: %d contacts for %d asked", dGeomGetClass(o1),
                dGeomGetClass(o2), n, asked);
    for (int i = 0; i < n; i++) {
        const dContactGeom *k = (const dContactGeom *)((const char *)c + (size_t)i * (size_t)skip);
        if (k->g1 != named(o1) || k->g2 != named(o2))
            fz_fail("classes %d, %d: contact %d names geoms %p, %p, not %p, %p",
                    dGeomGetClass(o1), dGeomGetClass(o2), i, (void *)k->g1,
                    (void *)k->g2, (void *)named(o1), (void *)named(o2));
        if (fz_lenient) continue;
        double len = sqrt((double)(k->normal[0] * k->normal[0] + k->normal[1] * k->normal[1] +
                                   k->normal[2] * k->normal[2]));
        int finite = isfinite(k->pos[0]) && isfinite(k->pos[1]) && isfinite(k->pos[2]);
#ifdef dSINGLE
        double tol = 1e-3;
#else
        double tol = 1e-6;
#endif
        if (!finite || !isfinite(k->depth) || k->depth < 0 || !(fabs(len - 1) <= tol))
            fz_fail("classes %d, %d: contact %d of %d: pos (%g %g %g) normal (%g %g %g) "
                    "depth %g", dGeomGetClass(o1), dGeomGetClass(o2), i, n,
                    (double)k->pos[0], (double)k->pos[1], (double)k->pos[2],
                    (double)k->normal[0], (double)k->normal[1], (double)k->normal[2],
                    (double)k->depth);
    }
}
