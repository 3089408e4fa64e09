// SPDX-License-Identifier: BSD-3-Clause
//
// shapes.c -- odecontactdiff's shapes: parsing "class:sizes" and scene
// files, making the geoms, and posing pairs at random.

#include "odecontactdiff.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct class_info {
    const char *name;
    int cls, nparams;
    double defaults[4];
} class_info;

static const class_info classes[] = {
    { "sphere", dSphereClass, 1, { 0.5, 0, 0, 0 } },
    { "box", dBoxClass, 3, { 1, 0.6, 0.4, 0 } },
    { "capsule", dCapsuleClass, 2, { 0.3, 0.8, 0, 0 } },
    { "cylinder", dCylinderClass, 2, { 0.4, 0.8, 0, 0 } },
    { "plane", dPlaneClass, 4, { 0, 0, 1, 0 } },
};
enum { NCLASSES = sizeof classes / sizeof classes[0] };

static const class_info *info_by_name(const char *name, size_t len)
{
    for (int i = 0; i < NCLASSES; i++)
        if (strlen(classes[i].name) == len && strncmp(classes[i].name, name, len) == 0)
            return &classes[i];
    return NULL;
}

static const class_info *info_by_class(int cls)
{
    for (int i = 0; i < NCLASSES; i++)
        if (classes[i].cls == cls) return &classes[i];
    return NULL;
}

const char *cd_class_name(int cls)
{
    const class_info *c = info_by_class(cls);
    return c ? c->name : "?";
}

// Sizes must be positive (a plane's normal must not be zero).
static int check_sizes(const class_info *c, const double *p, char *err, size_t size)
{
    if (c->cls == dPlaneClass) {
        if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 0) return 1;
        snprintf(err, size, "plane: the normal (a, b, c) is zero");
        return 0;
    }
    for (int i = 0; i < c->nparams; i++)
        if (!(p[i] > 0) || !isfinite(p[i])) {
            snprintf(err, size, "%s: size %d (%g) is not a positive number", c->name, i + 1, p[i]);
            return 0;
        }
    return 1;
}

int cd_parse_shape(const char *text, cd_shape *out, char *err, size_t size)
{
    const char *colon = strchr(text, ':');
    const class_info *c = info_by_name(text, colon ? (size_t)(colon - text) : strlen(text));
    if (!c) {
        snprintf(err, size, "\"%s\": unknown class (sphere, box, capsule, cylinder, plane)", text);
        return 0;
    }
    out->cls = c->cls;
    memcpy(out->p, c->defaults, sizeof out->p);
    if (!colon) return 1;
    const char *s = colon + 1;
    for (int i = 0; i < c->nparams; i++) {
        char *end;
        out->p[i] = strtod(s, &end);
        if (end == s || (i + 1 < c->nparams ? *end != ',' : *end != 0)) {
            snprintf(err, size, "\"%s\": %s takes %d comma-separated numbers", text, c->name,
                     c->nparams);
            return 0;
        }
        s = end + 1;
    }
    return check_sizes(c, out->p, err, size);
}

// Read up to n numbers from *s into v; returns how many were read.
static int read_numbers(char **s, double *v, int n)
{
    int i = 0;
    for (; i < n; i++) {
        char *end;
        v[i] = strtod(*s, &end);
        if (end == *s) break;
        *s = end;
    }
    return i;
}

// One scene line: "class sizes... [x y z [qw qx qy qz]]".
static int parse_scene_line(char *line, cd_geom *g, char *err, size_t size)
{
    char *s = line + strspn(line, " \t");
    size_t len = strcspn(s, " \t\r\n");
    const class_info *c = info_by_name(s, len);
    if (!c) {
        snprintf(err, size, "unknown class \"%.*s\"", (int)len, s);
        return 0;
    }
    s += len;
    memset(g, 0, sizeof *g);
    g->shape.cls = c->cls;
    g->q[0] = 1;
    if (read_numbers(&s, g->shape.p, c->nparams) != c->nparams) {
        snprintf(err, size, "%s takes %d sizes", c->name, c->nparams);
        return 0;
    }
    if (!check_sizes(c, g->shape.p, err, size)) return 0;
    if (c->cls != dPlaneClass) {
        int n = read_numbers(&s, g->pos, 3);
        if (n != 0 && n != 3) {
            snprintf(err, size, "a position is 3 numbers");
            return 0;
        }
        n = read_numbers(&s, g->q, 4);
        if (n != 0 && n != 4) {
            snprintf(err, size, "a quaternion is 4 numbers (w x y z)");
            return 0;
        }
        if (n == 0) g->q[0] = 1;
    }
    s += strspn(s, " \t\r\n");
    if (*s) {
        snprintf(err, size, "unexpected \"%.20s\"", s);
        return 0;
    }
    return 1;
}

int cd_read_scene(const char *path, cd_geom **out, char *err, size_t size)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, size, "%s: cannot open", path);
        return -1;
    }
    char line[512], why[200];
    int n = 0, cap = 0, lineno = 0;
    cd_geom *geoms = NULL;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *hash = strchr(line, '#');
        if (hash) *hash = 0;
        if (line[strspn(line, " \t\r\n")] == 0) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            cd_geom *grown = realloc(geoms, (size_t)cap * sizeof *geoms);
            if (!grown) break;
            geoms = grown;
        }
        if (!parse_scene_line(line, &geoms[n], why, sizeof why)) {
            snprintf(err, size, "%s:%d: %s", path, lineno, why);
            free(geoms);
            fclose(f);
            return -1;
        }
        n++;
    }
    fclose(f);
    *out = geoms;
    return n;
}

dGeomID cd_make_geom(const cd_geom *g)
{
    const double *p = g->shape.p;
    dGeomID id = NULL;
    switch (g->shape.cls) {
    case dSphereClass: id = dCreateSphere(0, p[0]); break;
    case dBoxClass: id = dCreateBox(0, p[0], p[1], p[2]); break;
    case dCapsuleClass: id = dCreateCapsule(0, p[0], p[1]); break;
    case dCylinderClass: id = dCreateCylinder(0, p[0], p[1]); break;
    default: return dCreatePlane(0, p[0], p[1], p[2], p[3]);
    }
    dGeomSetPosition(id, g->pos[0], g->pos[1], g->pos[2]);
    dQuaternion q = { g->q[0], g->q[1], g->q[2], g->q[3] };
    dGeomSetQuaternion(id, q);
    return id;
}

double cd_bounding_radius(const cd_shape *s)
{
    const double *p = s->p;
    switch (s->cls) {
    case dSphereClass: return p[0];
    case dBoxClass: return sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / 2;
    case dCapsuleClass: return p[0] + p[1] / 2;
    case dCylinderClass: return sqrt(p[0] * p[0] + p[1] * p[1] / 4);
    default: return 0;
    }
}

double cd_uniform(cd_rng *r)
{
    uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

// A rotation uniform over SO(3) (Shoemake's method).
static void random_rotation(cd_rng *r, dGeomID g)
{
    double u1 = cd_uniform(r), u2 = cd_uniform(r), u3 = cd_uniform(r);
    double a = sqrt(1 - u1), b = sqrt(u1), t = 6.283185307179586;
    dQuaternion q = { b * cos(t * u3), a * sin(t * u2), a * cos(t * u2), b * sin(t * u3) };
    dGeomSetQuaternion(g, q);
}

// A unit direction uniform on the sphere.
static void random_direction(cd_rng *r, double d[3])
{
    double z = 2 * cd_uniform(r) - 1, phi = 6.283185307179586 * cd_uniform(r);
    double s = sqrt(1 - z * z);
    d[0] = s * cos(phi);
    d[1] = s * sin(phi);
    d[2] = z;
}

// The shape of a geom made by cd_make_geom.
static cd_shape shape_of(dGeomID g)
{
    cd_shape s;
    memset(&s, 0, sizeof s);
    s.cls = dGeomGetClass(g);
    dVector3 side;
    dVector4 plane;
    dReal r, len;
    switch (s.cls) {
    case dSphereClass: s.p[0] = dGeomSphereGetRadius(g); break;
    case dBoxClass:
        dGeomBoxGetLengths(g, side);
        for (int k = 0; k < 3; k++) s.p[k] = side[k];
        break;
    case dCapsuleClass:
        dGeomCapsuleGetParams(g, &r, &len);
        s.p[0] = r;
        s.p[1] = len;
        break;
    case dCylinderClass:
        dGeomCylinderGetParams(g, &r, &len);
        s.p[0] = r;
        s.p[1] = len;
        break;
    default:
        dGeomPlaneGetParams(g, plane);
        for (int k = 0; k < 4; k++) s.p[k] = plane[k];
        break;
    }
    return s;
}

void cd_random_pose(cd_rng *r, dGeomID g1, dGeomID g2)
{
    cd_shape s1 = shape_of(g1), s2 = shape_of(g2);
    if (s1.cls == dPlaneClass || s2.cls == dPlaneClass) {
        // The other geom's centre from 0.6 of its radius below the plane's
        // surface to 1.3 above it.
        const cd_shape *plane = s1.cls == dPlaneClass ? &s1 : &s2;
        dGeomID other = s1.cls == dPlaneClass ? g2 : g1;
        double R = cd_bounding_radius(s1.cls == dPlaneClass ? &s2 : &s1);
        double n[3] = { plane->p[0], plane->p[1], plane->p[2] };
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double h = plane->p[3] / l + R * (1.9 * cd_uniform(r) - 0.6);
        dGeomSetPosition(other, h * n[0] / l, h * n[1] / l, h * n[2] / l);
        random_rotation(r, other);
        return;
    }
    dGeomSetPosition(g1, 0, 0, 0);
    random_rotation(r, g1);
    random_rotation(r, g2);
    double d[3], dist = 1.1 * (cd_bounding_radius(&s1) + cd_bounding_radius(&s2)) * cd_uniform(r);
    random_direction(r, d);
    dGeomSetPosition(g2, dist * d[0], dist * d[1], dist * d[2]);
}
