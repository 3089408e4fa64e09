// SPDX-License-Identifier: BSD-3-Clause
//
// diff_collide_ray.c -- rays and the collision utilities against the
// reference ODE 0.16.
//
// Rays: seeded random shapes of each class (sizes 0.1..2, centres within
// 0.75 of the origin, random rotations; planes with random unit normals)
// and random rays (start in [-1.5, 1.5]^3, a third of them aimed near the
// shape's centre and a third starting within 0.4 of it, length 0.1..3):
// 20..45% hit per class, a quarter start inside. Each scene prints, for
// dCollide(ray, shape): hit or not, depth, pos and normal (zeros without a
// hit), and the same for dCollide(shape, ray) (the normal flipped),
// tolerance 1e-9: both libraries solve the same closed forms (a quadratic
// for the round shapes, slabs for boxes and caps, one division for the
// plane), agreeing to rounding (~1e-15 at these sizes; 1e-9 leaves room for
// the ill-conditioned root of a near-tangent line, ~1e-16 / sqrt(disc)).
//
// One deviation from ODE 0.16, shown (tolerance 10) but not compared: a
// ray starting inside a capsule and leaving it through a cap gets no
// contact from ODE when the ray ends before the line leaves the capsule's
// infinite tube (3 of 300 scenes here, named ..._ode_misses_cap_exit; a
// longer ray gets the same point at the same depth from ODE). Ours reports
// the exit point, as BACKENDS.md section 1 asks.
//
// Ambiguous scenes print only the fact that they are ambiguous (a line
// "<pair>_grazing" without values). A scene is ambiguous, by the rule below
// computed here without calling either library (so both builds agree on
// it), when within 1e-6 of a decision that rounding could flip:
// - the ray's start or end lies within 1e-6 of the surface (inside or
//   outside, hit at depth 0 or at the length, or not at all);
// - the ray's line only grazes the shape: it goes no deeper than 1e-6
//   inside it (tangent lines hit in both libraries, but barely);
// - the hit point lies within 1e-6 of a box edge or a cylinder rim (two
//   faces' normals are equally right);
// - for planes, the ray is within 1e-6 of parallel to the plane.
// The signed distance of each class's surface and the line's span inside
// the shape (ternary search for the deepest point, bisection for the ends:
// these functions are convex along a line) are computed here for this.
//
// (None of these 1500 scenes is ambiguous by this rule; it guards reseeding.)
//
// Utilities: dClosestLineSegmentPoints on random segments (points, 1e-9:
// the closed form, well conditioned away from parallel; scenes within 1e-3
// rad of parallel print only the distance), on exactly parallel and on
// zero-length segments with small integer coordinates (see
// parallel_segment_scenes); and dBoxTouchesBox on random boxes (1 or 0,
// exact; scenes whose separating axis gap is within 1e-6 of 0 print as
// grazing) and on axis-aligned boxes with exactly touching faces, edges and
// corners (parallel edges: zero cross products).

#include "diff_print.h"
#include "diff_random.h"

#include <math.h>

enum { SCENES = 300, UTIL_SCENES = 200 };

static const double AMBIGUOUS = 1e-6;

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void random_unit(double u[3])
{
    double l;
    do {
        for (int i = 0; i < 3; i++) u[i] = rnd(-1, 1);
        l = sqrt(dot3(u, u));
    } while (l < 0.1 || l > 1);
    for (int i = 0; i < 3; i++) u[i] /= l;
}

static dGeomID random_geom(int cls)
{
    dGeomID g;
    switch (cls) {
    case dSphereClass: g = dCreateSphere(0, rnd(0.1, 1)); break;
    case dBoxClass: g = dCreateBox(0, rnd(0.2, 2), rnd(0.2, 2), rnd(0.2, 2)); break;
    case dCapsuleClass: g = dCreateCapsule(0, rnd(0.1, 0.6), rnd(0.05, 2)); break;
    case dCylinderClass: g = dCreateCylinder(0, rnd(0.2, 1), rnd(0.2, 2)); break;
    default: {
        double n[3];
        random_unit(n);
        return dCreatePlane(0, n[0], n[1], n[2], rnd(-0.5, 0.5));
    }
    }
    dGeomSetPosition(g, rnd(-0.75, 0.75), rnd(-0.75, 0.75), rnd(-0.75, 0.75));
    dMatrix3 R;
    random_rotation(R);
    dGeomSetRotation(g, R);
    return g;
}

// ---- the ambiguity rule ---------------------------------------------------------

// p (world) in g's frame.
static void to_local(dGeomID g, const double *p, double q[3])
{
    const dReal *c = dGeomGetPosition(g), *R = dGeomGetRotation(g);
    double d[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
    for (int i = 0; i < 3; i++) q[i] = R[i] * d[0] + R[4 + i] * d[1] + R[8 + i] * d[2];
}

// Signed distance of the world point p from g's surface, negative inside.
static double sdf(dGeomID g, const double *p)
{
    if (dGeomGetClass(g) == dPlaneClass) {
        dVector4 pl;
        dGeomPlaneGetParams(g, pl);
        return pl[0] * p[0] + pl[1] * p[1] + pl[2] * p[2] - pl[3];
    }
    double q[3];
    to_local(g, p, q);
    switch (dGeomGetClass(g)) {
    case dSphereClass: return sqrt(dot3(q, q)) - dGeomSphereGetRadius(g);
    case dBoxClass: {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        double out = 0, in = -INFINITY;
        for (int i = 0; i < 3; i++) {
            double e = fabs(q[i]) - side[i] / 2;
            if (e > 0) out += e * e;
            if (e > in) in = e;
        }
        return out > 0 ? sqrt(out) : in;
    }
    case dCapsuleClass: {
        dReal r, len;
        dGeomCapsuleGetParams(g, &r, &len);
        double z = fabs(q[2]) - len / 2;
        if (z < 0) z = 0;
        return sqrt(q[0] * q[0] + q[1] * q[1] + z * z) - r;
    }
    default: {
        dReal r, len;
        dGeomCylinderGetParams(g, &r, &len);
        double er = sqrt(q[0] * q[0] + q[1] * q[1]) - r, ez = fabs(q[2]) - len / 2;
        if (er <= 0 && ez <= 0) return er > ez ? er : ez;
        double a = er > 0 ? er : 0, b = ez > 0 ? ez : 0;
        return sqrt(a * a + b * b);
    }
    }
}

static double sdf_at(dGeomID g, const double *s, const double *u, double t)
{
    double p[3] = { s[0] + t * u[0], s[1] + t * u[1], s[2] + t * u[2] };
    return sdf(g, p);
}

// The root of sdf along the line between t_out (outside) and t_in (inside).
static double bisect(dGeomID g, const double *s, const double *u, double t_out, double t_in)
{
    for (int k = 0; k < 200; k++) {
        double m = (t_out + t_in) / 2;
        if (sdf_at(g, s, u, m) > 0)
            t_out = m;
        else
            t_in = m;
    }
    return (t_out + t_in) / 2;
}

// 1 if the world point p is within AMBIGUOUS of two faces of a box or of a
// cylinder's rim.
static int near_edge(dGeomID g, const double *p)
{
    double q[3];
    int cls = dGeomGetClass(g);
    if (cls != dBoxClass && cls != dCylinderClass) return 0;
    to_local(g, p, q);
    if (cls == dBoxClass) {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        int faces = 0;
        for (int i = 0; i < 3; i++) faces += fabs(fabs(q[i]) - side[i] / 2) < AMBIGUOUS;
        return faces >= 2;
    }
    dReal r, len;
    dGeomCylinderGetParams(g, &r, &len);
    return fabs(sqrt(q[0] * q[0] + q[1] * q[1]) - r) < AMBIGUOUS &&
           fabs(fabs(q[2]) - len / 2) < AMBIGUOUS;
}

// The rule of the header for the ray (start s, unit direction u, length).
static int ambiguous(dGeomID g, const double *s, const double *u, double length)
{
    if (fabs(sdf_at(g, s, u, 0)) < AMBIGUOUS || fabs(sdf_at(g, s, u, length)) < AMBIGUOUS)
        return 1;
    if (dGeomGetClass(g) == dPlaneClass) {
        dVector4 pl;
        dGeomPlaneGetParams(g, pl);
        return fabs(pl[0] * u[0] + pl[1] * u[1] + pl[2] * u[2]) < AMBIGUOUS;
    }
    // The deepest point of the line (the shapes lie within 4 of the start).
    double lo = -8, hi = 8;
    for (int k = 0; k < 300; k++) {
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (sdf_at(g, s, u, m1) < sdf_at(g, s, u, m2))
            hi = m2;
        else
            lo = m1;
    }
    double tm = (lo + hi) / 2, deepest = sdf_at(g, s, u, tm);
    if (deepest > -AMBIGUOUS) return deepest <= AMBIGUOUS;   // a miss unless grazing
    double t_in = bisect(g, s, u, -8, tm), t_out = bisect(g, s, u, 8, tm);
    double t = t_in >= 0 ? t_in : t_out;
    double p[3] = { s[0] + t * u[0], s[1] + t * u[1], s[2] + t * u[2] };
    return near_edge(g, p);
}

// 1 if the ray starts inside the capsule g, leaves it within its length
// (through a cap), but leaves the capsule's infinite tube only beyond (or
// within 1e-6 of) its end. ODE 0.16 then reports nothing: it rejects the
// tube's exit as too far before checking whether that lies beyond a cap.
static int capsule_exit_beyond_tube(dGeomID g, const double *s, const double *u, double length)
{
    if (dGeomGetClass(g) != dCapsuleClass || sdf_at(g, s, u, 0) >= 0) return 0;
    double t_out = bisect(g, s, u, 8, 0);
    if (t_out >= length) return 0;
    const dReal *R = dGeomGetRotation(g);
    double q[3], v[3];
    to_local(g, s, q);
    for (int i = 0; i < 3; i++) v[i] = R[i] * u[0] + R[4 + i] * u[1] + R[8 + i] * u[2];
    dReal r, len;
    dGeomCapsuleGetParams(g, &r, &len);
    double a = v[0] * v[0] + v[1] * v[1], b = q[0] * v[0] + q[1] * v[1];
    double c = q[0] * q[0] + q[1] * q[1] - r * r;   // < 0: the start is inside the tube
    if (a == 0) return 1;
    return (-b + sqrt(b * b - a * c)) / a > length - AMBIGUOUS;
}

// ---- rays -------------------------------------------------------------------------

static void print_hit(const char *name, dGeomID a, dGeomID b, double tol)
{
    dContactGeom c[4];
    dReal v[8] = { 0 };
    int n = dCollide(a, b, 4, c, sizeof c[0]);
    v[0] = n;
    if (n > 0) {
        v[1] = c[0].depth;
        for (int i = 0; i < 3; i++) {
            v[2 + i] = c[0].pos[i];
            v[5 + i] = c[0].normal[i];
        }
    }
    diff_values(name, tol, v, 8);
}

static void ray_scenes(const char *pair, int cls, unsigned long long seed)
{
    rng_state = seed;
    dGeomID ray = dCreateRay(0, 1);
    for (int k = 0; k < SCENES; k++) {
        dGeomID g = random_geom(cls);
        double s[3] = { rnd(-1.5, 1.5), rnd(-1.5, 1.5), rnd(-1.5, 1.5) }, u[3];
        const dReal *c = cls == dPlaneClass ? NULL : dGeomGetPosition(g);
        if (c && k % 3 == 2)   // starting near the centre, often inside
            for (int i = 0; i < 3; i++) s[i] = c[i] + rnd(-0.4, 0.4);
        if (c && k % 3 == 1) {   // aimed near the centre
            double l = 0;
            for (int i = 0; i < 3; i++) {
                u[i] = c[i] + rnd(-0.5, 0.5) - s[i];
                l += u[i] * u[i];
            }
            l = sqrt(l) + 1e-12;
            for (int i = 0; i < 3; i++) u[i] /= l;
        } else {
            random_unit(u);
        }
        double length = rnd(0.1, 3);
        dGeomRaySetLength(ray, length);
        dGeomRaySet(ray, s[0], s[1], s[2], u[0], u[1], u[2]);
        char name[64];
        if (ambiguous(g, s, u, length)) {
            snprintf(name, sizeof name, "%s_%d_grazing", pair, k);
            diff_values(name, 0, NULL, 0);
        } else {
            int bug = capsule_exit_beyond_tube(g, s, u, length);
            const char *suffix = bug ? "_ode_misses_cap_exit" : "";
            snprintf(name, sizeof name, "%s_%d%s", pair, k, suffix);
            print_hit(name, ray, g, bug ? 10 : 1e-9);
            snprintf(name, sizeof name, "%s_%d_reversed%s", pair, k, suffix);
            print_hit(name, g, ray, bug ? 10 : 1e-9);
        }
        dGeomDestroy(g);
    }
    dGeomDestroy(ray);
}

// ---- dClosestLineSegmentPoints ------------------------------------------------------

static double distance(const dReal *a, const dReal *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static int is_endpoint(const dReal *p, const dReal *e1, const dReal *e2)
{
    return distance(p, e1) < 1e-12 || distance(p, e2) < 1e-12;
}

static void print_segments(const char *name, double tol, const dReal *a1, const dReal *a2,
                           const dReal *b1, const dReal *b2)
{
    dVector3 c1, c2;
    dClosestLineSegmentPoints(a1, a2, b1, b2, c1, c2);
    dReal v[6] = { c1[0], c1[1], c1[2], c2[0], c2[1], c2[2] };
    diff_values(name, tol, v, 6);
}

// Random segments in general position: the points; near-parallel ones
// (sine of the angle below 1e-3): the distance only.
static void segment_scenes(unsigned long long seed)
{
    rng_state = seed;
    for (int k = 0; k < UTIL_SCENES; k++) {
        dVector3 p[4];
        for (int j = 0; j < 4; j++)
            for (int i = 0; i < 3; i++) p[j][i] = rnd(-1, 1);
        if (k % 4 == 3)   // nearly parallel: b along a, slightly turned
            for (int i = 0; i < 3; i++) p[3][i] = p[2][i] + (p[1][i] - p[0][i]) + rnd(-1e-4, 1e-4);
        double da[3], db[3], x[3];
        for (int i = 0; i < 3; i++) {
            da[i] = p[1][i] - p[0][i];
            db[i] = p[3][i] - p[2][i];
        }
        x[0] = da[1] * db[2] - da[2] * db[1];
        x[1] = da[2] * db[0] - da[0] * db[2];
        x[2] = da[0] * db[1] - da[1] * db[0];
        double sin = sqrt(dot3(x, x) / (dot3(da, da) * dot3(db, db)));
        char name[64];
        if (sin > 1e-3) {
            snprintf(name, sizeof name, "segments_%d", k);
            print_segments(name, 1e-9, p[0], p[1], p[2], p[3]);
        } else {
            dVector3 c1, c2;
            dClosestLineSegmentPoints(p[0], p[1], p[2], p[3], c1, c2);
            snprintf(name, sizeof name, "segments_%d_near_parallel_distance", k);
            diff_value(name, 1e-9, distance(c1, c2));
        }
    }
}

static int rnd_int(int lo, int hi)
{
    return lo + (int)floor(rnd(0, hi - lo + 1 - 1e-9));
}

// Exactly parallel segments (b's direction an integer multiple of a's,
// either sign) and zero-length ones, small integer coordinates. Where the
// closest pairs are many, which one is chosen depends in ODE 0.16 on the
// rounding of its projections; with directions along a coordinate axis
// (lengths 1 or 2) that arithmetic is exact and the chosen pair is printed
// (1e-12), otherwise whether the pair involves an endpoint of either segment
// (the guide's promise; exact) and the distance with tolerance 10, that is
// shown but not compared: in some of these scenes (2 of 60 here: 20 and 152)
// ODE 0.16 returns a1 and b1, which are not the closest pair (4.12 apart
// where a1 is 3.58 from B in scene 20), while ours returns a closest pair.
static void parallel_segment_scenes(unsigned long long seed)
{
    rng_state = seed;
    for (int k = 0; k < UTIL_SCENES; k++) {
        dVector3 a1, a2, b1, b2;
        int m = rnd_int(-2, 2), zero = k % 5 == 4, b_zero = k % 5 == 3, axis = k % 2;
        for (int i = 0; i < 3; i++) {
            a1[i] = rnd_int(-3, 3);
            b1[i] = rnd_int(-3, 3);
        }
        int d[3] = { rnd_int(-2, 2), rnd_int(-2, 2), rnd_int(-2, 2) };
        if (axis) {
            int i = rnd_int(0, 2);
            d[(i + 1) % 3] = d[(i + 2) % 3] = 0;
            if (d[i] == 0) d[i] = 1;
        }
        if (m == 0 || (axis && (m < -1 || m > 1))) m = 1;
        for (int i = 0; i < 3; i++) {
            a2[i] = a1[i] + (zero ? 0 : d[i]);
            b2[i] = b1[i] + (b_zero ? 0 : m * d[i]);
        }
        char name[64];
        const char *family = zero || b_zero ? "segments_zero_length"
                             : axis         ? "segments_parallel_axis"
                                            : "segments_parallel";
        snprintf(name, sizeof name, "%s_%d", family, k);
        if (zero || b_zero || axis) {
            print_segments(name, 1e-12, a1, a2, b1, b2);
        } else {
            dVector3 c1, c2;
            dClosestLineSegmentPoints(a1, a2, b1, b2, c1, c2);
            diff_value(name, 0, is_endpoint(c1, a1, a2) || is_endpoint(c2, b1, b2));
            snprintf(name, sizeof name, "%s_%d_distance", family, k);
            diff_value(name, 10, distance(c1, c2));
        }
    }
}

// ---- dBoxTouchesBox ----------------------------------------------------------------

// The largest gap between the boxes' projections over the 15 axes
// (normalised; positive: separated, near 0: grazing).
static double box_gap(const dReal *p1, const dReal *R1, const dReal *s1, const dReal *p2,
                      const dReal *R2, const dReal *s2)
{
    double axes[15][3], A[3][3], B[3][3], d[3];
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            A[i][k] = R1[4 * k + i];
            B[i][k] = R2[4 * k + i];
        }
        d[i] = p2[i] - p1[i];
    }
    int n = 0;
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            axes[n][k] = A[i][k];
            axes[n + 1][k] = B[i][k];
        }
        n += 2;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *m = axes[n];
            m[0] = A[i][1] * B[j][2] - A[i][2] * B[j][1];
            m[1] = A[i][2] * B[j][0] - A[i][0] * B[j][2];
            m[2] = A[i][0] * B[j][1] - A[i][1] * B[j][0];
            double l = sqrt(dot3(m, m));
            if (l < 1e-6) continue;
            for (int k = 0; k < 3; k++) m[k] /= l;
            n++;
        }
    double gap = -INFINITY;
    for (int a = 0; a < n; a++) {
        double r = 0;
        for (int i = 0; i < 3; i++)
            r += s1[i] / 2 * fabs(dot3(A[i], axes[a])) + s2[i] / 2 * fabs(dot3(B[i], axes[a]));
        double g = fabs(dot3(d, axes[a])) - r;
        if (g > gap) gap = g;
    }
    return gap;
}

static void box_touch_scenes(unsigned long long seed)
{
    rng_state = seed;
    for (int k = 0; k < UTIL_SCENES; k++) {
        dVector3 p1, p2, s1, s2;
        dMatrix3 R1, R2;
        for (int i = 0; i < 3; i++) {
            p1[i] = rnd(-1, 1);
            p2[i] = rnd(-1, 1);
            s1[i] = rnd(0.2, 2);
            s2[i] = rnd(0.2, 2);
        }
        random_rotation(R1);
        random_rotation(R2);
        char name[64];
        if (fabs(box_gap(p1, R1, s1, p2, R2, s2)) < AMBIGUOUS) {
            snprintf(name, sizeof name, "boxes_%d_grazing", k);
            diff_values(name, 0, NULL, 0);
        } else {
            snprintf(name, sizeof name, "boxes_%d", k);
            diff_value(name, 0, dBoxTouchesBox(p1, R1, s1, p2, R2, s2));
        }
    }
}

// Axis-aligned boxes with integer sizes and positions (halves exact):
// touching faces, edges and corners count.
static void aligned_box_scenes(unsigned long long seed)
{
    rng_state = seed;
    dMatrix3 I = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
    for (int k = 0; k < UTIL_SCENES; k++) {
        dVector3 p1, p2, s1, s2;
        for (int i = 0; i < 3; i++) {
            s1[i] = rnd_int(1, 3);
            s2[i] = rnd_int(1, 3);
            p1[i] = rnd_int(-2, 2) / 2.0;
            p2[i] = rnd_int(-2, 2) / 2.0;
        }
        char name[64];
        snprintf(name, sizeof name, "boxes_aligned_%d", k);
        diff_value(name, 0, dBoxTouchesBox(p1, I, s1, p2, I, s2));
    }
}

int main(void)
{
    dInitODE();
    ray_scenes("ray_sphere", dSphereClass, 201);
    ray_scenes("ray_box", dBoxClass, 202);
    ray_scenes("ray_capsule", dCapsuleClass, 203);
    ray_scenes("ray_cylinder", dCylinderClass, 204);
    ray_scenes("ray_plane", dPlaneClass, 205);
    segment_scenes(206);
    parallel_segment_scenes(207);
    box_touch_scenes(208);
    aligned_box_scenes(209);
    dCloseODE();
    return 0;
}
